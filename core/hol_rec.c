/* hol_rec.c - the recording's header: written piecewise, read a line at a
 * time (see hol_rec.h). */
#include "hol_rec.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "hol_text.h"

enum { HOL__START, HOL__META, HOL__LEVEL, HOL__LEVELS };
enum { HOL__SEEN_SESSION = 1, HOL__SEEN_PART = 2, HOL__SEEN_START = 4, HOL__SEEN_VERSION = 8,
       HOL__SEEN_STUDY = 16 };

static int hol__idc(int c, int plus)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '.' || c == '_' || c == '-' || (plus && c == '+');
}

static int hol__id(const char *s, size_t max, int plus)
{
    size_t n = strlen(s);
    if (n == 0 || n >= max)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!hol__idc((unsigned char)s[i], plus))
            return 0;
    return 1;
}

int hol_rec_id_ok(const char *s)
{
    return hol__id(s, HOL_REC_ID_MAX, 0);
}

int hol_rec_time_ok(const char *s)
{
    static const char pat[] = "dddd-dd-ddTdd:dd:ddZ";
    if (strlen(s) != sizeof pat - 1)
        return 0;
    for (size_t i = 0; pat[i]; i++)
        if (pat[i] == 'd' ? !(s[i] >= '0' && s[i] <= '9') : s[i] != pat[i])
            return 0;
    return 1;
}

/* ---- the meta text ---------------------------------------------------------- */

int hol_rec_meta_key_ok(const char *k, size_t n)
{
    if (n < 1 || n > 32)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!((k[i] >= 'a' && k[i] <= 'z') || (k[i] >= '0' && k[i] <= '9') || k[i] == '_'))
            return 0;
    return 1;
}

/* 1 when v (n bytes) is hol_text_escape's output for some bytes: read
 * back (\\ and \xHH), escaped again, the same. */
static int hol__escaped_ok(const char *v, size_t n)
{
    char raw[HOL_REC_META_VALUE], again[HOL_REC_META_VALUE + 1];
    size_t m = 0;
    if (n > HOL_REC_META_VALUE)
        return 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)v[i];
        if (c == ';' || c < 0x20 || c == 0x7f)
            return 0;
        if (c != '\\') {
            raw[m++] = (char)c;
            continue;
        }
        if (i + 1 < n && v[i + 1] == '\\') {
            raw[m++] = '\\';
            i++;
            continue;
        }
        static const char hex[] = "0123456789abcdef";
        if (i + 3 >= n || v[i + 1] != 'x')
            return 0;
        const char *a = memchr(hex, v[i + 2], 16), *b = memchr(hex, v[i + 3], 16);
        if (!a || !b)
            return 0;
        raw[m++] = (char)((a - hex) * 16 + (b - hex));
        i += 3;
    }
    size_t e = hol_text_escape(raw, m, again, sizeof again);
    return e == n && !memcmp(again, v, n);
}

int hol_rec_meta_ok(const char *s)
{
    const char *items[HOL_REC_META_MAX];
    size_t lens[HOL_REC_META_MAX];
    int k = 0;
    if (!*s)
        return 1;
    for (const char *p = s;;) {
        const char *semi = strchr(p, ';'), *end = semi ? semi : p + strlen(p);
        const char *eq = memchr(p, '=', (size_t)(end - p));
        if (k == HOL_REC_META_MAX || !eq || !hol_rec_meta_key_ok(p, (size_t)(eq - p)) ||
            !hol__escaped_ok(eq + 1, (size_t)(end - eq - 1)))
            return 0;
        for (int i = 0; i < k; i++)
            if (lens[i] == (size_t)(eq - p) && !memcmp(items[i], p, lens[i]))
                return 0;
        items[k] = p;
        lens[k++] = (size_t)(eq - p);
        if (!semi)
            return 1;
        p = semi + 1;
    }
}

/* ---- writing --------------------------------------------------------------- */

static void hol__emitf(hol_rec_emit fn, void *ctx, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void hol__emitf(hol_rec_emit fn, void *ctx, const char *fmt, ...)
{
    char line[HOL_REC_LINE_MAX + 2];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (n > 0)
        fn(ctx, line, (size_t)n < sizeof line ? (size_t)n : sizeof line - 1);
}

void hol_rec_write_header(const hol_rec_meta *m, const hol_level *levels, int nlevels,
                          hol_rec_emit fn, void *ctx)
{
    /* version 3 only for a study's session: others stay readable by
     * builds that know version 2 */
    int study = m->study[0] != 0;
    for (int i = 0; i < nlevels; i++)
        study |= levels[i].condition[0] != 0;
    /* version 4 only with a session number, a study's hash, meta or ask */
    int four = m->session_no > 0 || m->study_sha256[0] || m->meta[0] || m->ask_item > 0;
    /* version 5 only where issue 35's flow shows: a ready screen, a tutorial */
    int five = m->ready;
    for (int i = 0; i < nlevels; i++)
        five |= levels[i].lvl.instructions[0] != 0 || levels[i].lvl.mode == HOL_APP_TUTORIAL;
    five &= !m->flow_v4;
    hol__emitf(fn, ctx, "holonomy-rec %d\n", five ? 5 : four ? 4 : study ? 3 : 2);
    hol__emitf(fn, ctx, "session %s\n", m->session);
    if (m->participant[0])
        hol__emitf(fn, ctx, "participant %s\n", m->participant);
    hol__emitf(fn, ctx, "start %s\n", m->start);
    hol__emitf(fn, ctx, "version %s\n", m->version);
    if (study)
        hol__emitf(fn, ctx, "study %s\n", m->study[0] ? m->study : "-");
    if (m->session_no > 0)
        hol__emitf(fn, ctx, "session_no %d\n", m->session_no);
    if (m->study_sha256[0])
        hol__emitf(fn, ctx, "study_sha256 %s\n", m->study_sha256);
    for (const char *p = m->meta; *p;) {
        const char *semi = strchr(p, ';');
        size_t n = semi ? (size_t)(semi - p) : strlen(p);
        hol__emitf(fn, ctx, "meta %.*s\n", (int)n, p);
        p += n + (semi != NULL);
    }
    if (m->ask_item > 0)
        hol__emitf(fn, ctx, "ask %s %d %d\n", m->ask_session, m->ask_attempt, m->ask_item);
    if (m->ready)
        hol__emitf(fn, ctx, "ready\n");
    for (int i = 0; i < nlevels; i++) {
        hol__emitf(fn, ctx, "level %s\n", levels[i].name);
        if (levels[i].condition[0])
            hol__emitf(fn, ctx, "condition %s %d\n", levels[i].condition, levels[i].position);
        const char *p = levels[i].text, *e = p + levels[i].len;
        while (p < e) {
            const char *nl = memchr(p, '\n', (size_t)(e - p));
            size_t n = (size_t)((nl ? nl : e) - p);
            fn(ctx, "L ", 2);
            fn(ctx, p, n);
            fn(ctx, "\n", 1);
            p = nl ? nl + 1 : e;
        }
        fn(ctx, "end\n", 4);
    }
}

/* ---- reading --------------------------------------------------------------- */

static hol_err hol__bad(hol_rec_reader *r, hol_err code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static hol_err hol__bad(hol_rec_reader *r, hol_err code, const char *fmt, ...)
{
    int n = snprintf(r->msg, sizeof r->msg, "line %ld: ", r->line);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->msg + n, sizeof r->msg - (size_t)n, fmt, ap);
    va_end(ap);
    return code;
}

void hol_rec_reader_init(hol_rec_reader *r, hol_level *levels)
{
    memset(r, 0, sizeof *r);
    r->levels = levels;
}

static hol_err hol__first_line(hol_rec_reader *r, const char *s, size_t len)
{
    if (len < 13 || memcmp(s, "holonomy-rec ", 13))
        return hol__bad(r, HOL_EPARSE, "not a recording (no 'holonomy-rec' header)");
    if (len == 14 && s[13] >= '1' && s[13] <= '0' + HOL_REC_VERSION) {
        r->version = s[13] - '0';
        r->state = r->version == 1 ? HOL__LEVELS : HOL__META;
        r->meta.flow_v4 = r->version < 5; /* played before issue 35's flow */
        return HOL_OK;
    }
    return hol__bad(r, HOL_EVERSION, "recording format '%.30s' is not version 1 to %d",
                    len > 13 ? s + 13 : "", HOL_REC_VERSION);
}

/* "session ID", "participant ID", "start ISO", "version V" (version 2, before
 * the first level), "study NAME" (version 3). 1 when the line was one of
 * them (or an error). */
static int hol__meta_line(hol_rec_reader *r, const char *s, size_t len, hol_err *err)
{
    static const char *const keys[5] = {"session ", "participant ", "start ", "version ",
                                         "study "};
    hol_rec_meta *m = &r->meta;
    char *dst[5] = {m->session, m->participant, m->start, m->version, m->study};
    size_t cap[5] = {sizeof m->session, sizeof m->participant, sizeof m->start,
                     sizeof m->version, sizeof m->study};
    for (int k = 0; k < (r->version >= 3 ? 5 : 4); k++) {
        size_t kl = strlen(keys[k]);
        if (len < kl || memcmp(s, keys[k], kl))
            continue;
        *err = HOL_OK;
        char v[HOL_REC_ID_MAX];
        size_t n = len - kl;
        int ok = r->state == HOL__META && !(r->seen & (1 << k)) && n < cap[k] && n < sizeof v;
        if (ok) {
            memcpy(v, s + kl, n);
            v[n] = 0;
            ok = k == 2 ? hol_rec_time_ok(v) : k == 3 ? hol__id(v, cap[k], 1) : hol_rec_id_ok(v);
        }
        if (!ok)
            *err = hol__bad(r, HOL_EPARSE, "'%.*s' is not a %s line (once, before the levels)",
                            (int)(kl - 1), keys[k],
                            k == 2 ? "'start YYYY-MM-DDTHH:MM:SSZ'" : "valid metadata");
        else {
            memcpy(dst[k], v, n + 1);
            r->seen |= 1 << k;
        }
        return 1;
    }
    return 0;
}

/* "session_no N", "study_sha256 HEX", "meta KEY=VALUE" (version 4, before
 * the first level; meta repeated, in order). 1 when the line was one. */
static int hol__meta4_line(hol_rec_reader *r, const char *s, size_t len, hol_err *err)
{
    hol_rec_meta *m = &r->meta;
    int k = len > 11 && !memcmp(s, "session_no ", 11)     ? 1
            : len > 13 && !memcmp(s, "study_sha256 ", 13) ? 2
            : len > 5 && !memcmp(s, "meta ", 5)           ? 3
                                                          : 0;
    if (!k || r->version < 4)
        return 0;
    int ok = r->state == HOL__META;
    if (k == 1) {
        /* 1..999, no leading zero */
        int n = 0;
        ok = ok && len - 11 <= 3 && s[11] != '0';
        for (size_t i = 11; i < len && ok; i++) {
            ok = s[i] >= '0' && s[i] <= '9';
            n = n * 10 + (s[i] - '0');
        }
        ok = ok && !m->session_no && n >= 1 && n <= 999;
        if (ok)
            m->session_no = n;
    } else if (k == 2) {
        ok = ok && !m->study_sha256[0] && len - 13 == 64;
        for (size_t i = 13; i < len && ok; i++)
            ok = (s[i] >= '0' && s[i] <= '9') || (s[i] >= 'a' && s[i] <= 'f');
        if (ok) {
            memcpy(m->study_sha256, s + 13, 64);
            m->study_sha256[64] = 0;
        }
    } else {
        size_t have = strlen(m->meta), n = len - 5;
        ok = ok && have + 1 + n < sizeof m->meta;
        if (ok) {
            if (have)
                m->meta[have++] = ';';
            memcpy(m->meta + have, s + 5, n);
            m->meta[have + n] = 0;
            ok = !memchr(s + 5, ';', n) && hol_rec_meta_ok(m->meta);
            if (!ok)
                m->meta[have ? have - 1 : 0] = 0;
        }
    }
    *err = ok ? HOL_OK
              : hol__bad(r, HOL_EPARSE, "not a valid '%s' line (once, before the levels)",
                         k == 1 ? "session_no 1..999" : k == 2 ? "study_sha256 HEX" : "meta KEY=VALUE");
    return 1;
}

/* A whole number of 1..max digits, no leading zero, in s[*i..len) up to a
 * space or the end; -1 when none. */
static long hol__rec_num(const char *s, size_t len, size_t *i, long max)
{
    long n = 0;
    size_t b = *i;
    while (*i < len && s[*i] >= '0' && s[*i] <= '9' && n <= max)
        n = n * 10 + (s[(*i)++] - '0');
    return *i == b || s[b] == '0' || n > max ? -1 : n;
}

/* "ask ID ATTEMPT ITEM" (version 4) or "ready" (version 5), once each,
 * before the first level. 1 when the line was one. */
static int hol__ask_line(hol_rec_reader *r, const char *s, size_t len, hol_err *err)
{
    if (len == 5 && !memcmp(s, "ready", 5) && r->version >= 5) { /* "ready", once */
        int ok = r->state == HOL__META && !r->meta.ready;
        r->meta.ready = 1;
        *err = ok ? HOL_OK : hol__bad(r, HOL_EPARSE, "not a valid 'ready' line (once, before the levels)");
        return 1;
    }
    if (len < 4 || memcmp(s, "ask ", 4) || r->version < 4)
        return 0;
    const char *sp = memchr(s + 4, ' ', len - 4);
    size_t i = sp ? (size_t)(sp - s) : len, idn = i - 4;
    char id[HOL_REC_ID_MAX] = "";
    if (idn < sizeof id) {
        memcpy(id, s + 4, idn);
        id[idn] = 0;
    }
    i += i < len;
    long a = hol_rec_id_ok(id) ? hol__rec_num(s, len, &i, 999999) : -1, k = -1;
    if (a > 0 && i < len && s[i] == ' ') {
        i++;
        k = hol__rec_num(s, len, &i, 255);
    }
    int ok = r->state == HOL__META && !r->meta.ask_item && a > 0 && k > 0 && i == len;
    if (ok) {
        memcpy(r->meta.ask_session, id, sizeof id);
        r->meta.ask_attempt = (int)a;
        r->meta.ask_item = (int)k;
    }
    *err = ok ? HOL_OK
              : hol__bad(r, HOL_EPARSE, "not a valid 'ask SESSION ATTEMPT ITEM' line (once, "
                                        "before the levels)");
    return 1;
}

static hol_err hol__level_begin(hol_rec_reader *r, const char *s, size_t len)
{
    if (r->state == HOL__META && (r->seen & 0xd) != 0xd)
        return hol__bad(r, HOL_EPARSE, "a version %d recording names its session, start and "
                                       "version before its levels", r->version);
    if (r->state == HOL__META && r->version == 3 && !(r->seen & HOL__SEEN_STUDY))
        return hol__bad(r, HOL_EPARSE, "a version 3 recording names its study before its "
                                       "levels");
    if (r->nlevels >= HOL_REC_MAX_LEVELS)
        return hol__bad(r, HOL_ENOMEM, "more than %d levels", HOL_REC_MAX_LEVELS);
    r->name_len = len - 6;
    if (!hol_level_name_ok(s + 6, r->name_len))
        return hol__bad(r, HOL_EARG, "a level name is 1..%d bytes without a CR",
                        HOL_LEVEL_NAME_MAX - 1);
    memcpy(r->name, s + 6, r->name_len);
    r->name[r->name_len] = 0;
    r->cond[0] = 0;
    r->cond_pos = 0;
    r->len = 0;
    r->level_first = r->line + 1;
    r->state = HOL__LEVEL;
    return HOL_OK;
}

static hol_err hol__level_end(hol_rec_reader *r)
{
    hol_level_err le;
    hol_err e = hol_level_make(r->name, r->name_len, r->text, r->len, &r->levels[r->nlevels], &le);
    if (e) {
        char what[224];
        hol_level_err_format(&le, r->level_first, what, sizeof what);
        /* "line N: MSG" of the recording's lines, said of the level */
        const char *colon = le.line > 0 ? strchr(what, ':') : NULL;
        snprintf(r->msg, sizeof r->msg, "line %ld: level '%.40s'%s%.190s",
                 le.line > 0 ? r->level_first + le.line - 1 : r->line, r->name,
                 colon ? "" : ": ", colon ? colon : what);
        return e;
    }
    memcpy(r->levels[r->nlevels].condition, r->cond, sizeof r->cond);
    r->levels[r->nlevels].position = r->cond_pos;
    r->nlevels++;
    r->state = HOL__LEVELS;
    return HOL_OK;
}

/* "condition NAME POS" right after a level line (version 3), in a
 * recording with a study line (a study's session: the writer writes one,
 * "study -" without a name, wherever a level has a condition). */
static hol_err hol__condition_line(hol_rec_reader *r, const char *s, size_t len)
{
    if (!(r->seen & HOL__SEEN_STUDY))
        return hol__bad(r, HOL_EPARSE, "a 'condition' line needs the recording's 'study' "
                                       "line (a study's session)");
    const char *sp = len > 10 ? memchr(s + 10, ' ', len - 10) : NULL;
    size_t n = sp ? (size_t)(sp - s) - 10 : 0;
    int pos = 0, digits = 0;
    for (const char *p = sp ? sp + 1 : s + len; p < s + len && digits < 3; p++, digits++) {
        if (*p < '0' || *p > '9')
            digits = 9;
        else
            pos = pos * 10 + (*p - '0');
    }
    int ok = sp && n > 0 && n < sizeof r->cond && digits >= 1 && digits <= 2 &&
             (size_t)(sp - s) + 1 + (size_t)digits == len && pos <= HOL_REC_MAX_LEVELS;
    if (ok) {
        memcpy(r->cond, s + 10, n);
        r->cond[n] = 0;
        ok = hol_rec_id_ok(r->cond);
    }
    if (!ok) {
        r->cond[0] = 0;
        return hol__bad(r, HOL_EPARSE, "not a 'condition NAME POSITION' line (POSITION 0..%d)",
                        HOL_REC_MAX_LEVELS);
    }
    r->cond_pos = pos;
    r->level_first++; /* the level's text starts on the next line */
    return HOL_OK;
}

hol_err hol_rec_read_line(hol_rec_reader *r, const char *s, size_t len, int *out_done)
{
    *out_done = 0;
    r->line++;
    if (len && s[len - 1] == '\r')
        len--;
    if (memchr(s, 0, len))
        return hol__bad(r, HOL_EPARSE, "a NUL byte");
    if (r->state == HOL__START)
        return hol__first_line(r, s, len);
    if (r->state == HOL__LEVEL) {
        if (r->version >= 3 && len >= 10 && !memcmp(s, "condition ", 10) && r->len == 0 &&
            !r->cond[0] && r->line == r->level_first)
            return hol__condition_line(r, s, len);
        if (len >= 2 && s[0] == 'L' && s[1] == ' ') {
            if (r->len + len - 2 + 1 > HOL_LEVEL_TEXT_MAX)
                return hol__bad(r, HOL_ENOMEM, "level '%.40s' longer than %d bytes", r->name,
                                HOL_LEVEL_TEXT_MAX);
            memcpy(r->text + r->len, s + 2, len - 2);
            r->len += len - 2;
            r->text[r->len++] = '\n';
            return HOL_OK;
        }
        if (len == 3 && !memcmp(s, "end", 3))
            return hol__level_end(r);
        return hol__bad(r, HOL_EPARSE, "level '%.40s' not closed by 'end'", r->name);
    }
    hol_err err;
    if (hol__meta_line(r, s, len, &err) || hol__meta4_line(r, s, len, &err) ||
        hol__ask_line(r, s, len, &err))
        return err;
    if (len >= 6 && !memcmp(s, "level ", 6))
        return hol__level_begin(r, s, len);
    if (r->nlevels == 0 && r->version < 3 && len >= 6 && !memcmp(s, "study ", 6))
        return hol__bad(r, HOL_EPARSE, "a 'study' line needs a version 3 recording "
                                       "('holonomy-rec 3'), not version %d", r->version);
    if (r->nlevels == 0)
        return hol__bad(r, HOL_EPARSE, "'%.*s' is not a header line (%s'level NAME') and "
                                       "no level came before it",
                        (int)(len < 20 ? len : 20), s,
                        r->version >= 2 ? "session, participant, start, version, " : "");
    r->line--; /* not a header line: the first input line */
    *out_done = 1;
    return HOL_OK;
}

hol_err hol_rec_read_end(hol_rec_reader *r)
{
    r->line++;
    if (r->state == HOL__LEVEL)
        return hol__bad(r, HOL_EPARSE, "level '%.40s' not closed by 'end'", r->name);
    if (r->state == HOL__START)
        return hol__bad(r, HOL_EPARSE, "not a recording (no 'holonomy-rec' header)");
    if (r->nlevels == 0)
        return hol__bad(r, HOL_EPARSE, "the recording holds no level");
    r->line--;
    return HOL_OK;
}
