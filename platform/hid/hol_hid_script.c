/* hol_hid_script.c - a game controller played back from a text script (see
 * hol_hid_script.h). */
#include "hol_hid_script.h"

#include <string.h>

static int hexval(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

/* "12.5" (digits, optional '.' and digits) into *out; the end, or NULL. */
static const char *parse_time(const char *p, const char *end, double *out)
{
    double v = 0, scale = 1;
    const char *start = p;
    while (p < end && *p >= '0' && *p <= '9' && p - start < 12)
        v = v * 10 + (*p++ - '0');
    if (p == start)
        return NULL;
    if (p < end && *p == '.') {
        const char *f = ++p;
        while (p < end && *p >= '0' && *p <= '9' && p - f < 9) {
            scale /= 10;
            v += (*p++ - '0') * scale;
        }
        if (p == f)
            return NULL;
    }
    *out = v;
    return p;
}

/* Hex pairs in groups separated by single spaces, up to end, appended to
 * s->bytes (at most max). 0 ok, else the error. */
static hol_err parse_hex(hol_hid_script *s, const char *p, const char *end, size_t max,
                         uint32_t *out_off, uint32_t *out_len)
{
    size_t n = 0;
    if (p >= end)
        return HOL_EPARSE;
    while (p < end) {
        if (*p == ' ') {
            if (p + 1 >= end || p[1] == ' ' || n == 0)
                return HOL_EPARSE;
            p++;
            continue;
        }
        int hi = hexval(p[0]), lo = p + 1 < end ? hexval(p[1]) : -1;
        if (hi < 0 || lo < 0)
            return HOL_EPARSE;
        if (n >= max)
            return HOL_EPARSE;
        if (s->used + n >= HOL_HID_SCRIPT_MAX_BYTES)
            return HOL_ENOMEM;
        s->bytes[s->used + n++] = (uint8_t)(hi << 4 | lo);
        p += 2;
    }
    *out_off = (uint32_t)s->used;
    *out_len = (uint32_t)n;
    s->used += n;
    return HOL_OK;
}

static int word(const char *p, const char *end, const char *w)
{
    size_t n = strlen(w);
    return (size_t)(end - p) >= n && !memcmp(p, w, n) && (p + n == end || p[n] == ' ');
}

/* One event line [p, end) into *e. */
static hol_err parse_event(hol_hid_script *s, const char *p, const char *end, int plugged,
                           long last_plug, hol_hid_script_event *e)
{
    memset(e, 0, sizeof *e);
    p = parse_time(p, end, &e->t);
    if (!p || p >= end || *p != ' ')
        return HOL_EPARSE;
    p++;
    if (word(p, end, "plug")) {
        if (plugged)
            return HOL_EPARSE;
        e->kind = HOL_HID_SCRIPT_PLUG;
        p += 4;
        if (p == end) { /* the last controller again */
            if (last_plug < 0)
                return HOL_EPARSE;
            *e = s->ev[last_plug];
            return HOL_OK; /* the caller sets the time */
        }
        p++;
        int v[8];
        if (end - p < 10 || p[4] != ':' || p[9] != ' ')
            return HOL_EPARSE;
        for (int i = 0; i < 8; i++)
            if ((v[i] = hexval(p[i < 4 ? i : i + 1])) < 0)
                return HOL_EPARSE;
        e->vid = (uint16_t)(v[0] << 12 | v[1] << 8 | v[2] << 4 | v[3]);
        e->pid = (uint16_t)(v[4] << 12 | v[5] << 8 | v[6] << 4 | v[7]);
        return parse_hex(s, p + 10, end, HOL_HID_DESC_MAX, &e->off, &e->len);
    }
    if (!plugged)
        return HOL_EPARSE;
    if (word(p, end, "unplug")) {
        e->kind = HOL_HID_SCRIPT_UNPLUG;
        return p + 6 == end ? HOL_OK : HOL_EPARSE;
    }
    if (word(p, end, "report") && p + 6 < end) {
        e->kind = HOL_HID_SCRIPT_REPORT;
        return parse_hex(s, p + 7, end, HOL_HID_REPORT_MAX_BYTES, &e->off, &e->len);
    }
    return HOL_EPARSE;
}

static hol_err script_open_first(void *ctx, double now_s, hol_hid_dev_info *out_info,
                                 uint8_t *desc, size_t cap, size_t *out_len);
static int script_read(void *ctx, double now_s, uint8_t *buf, size_t cap);
static void script_close(void *ctx);

void hol_hid_script_begin(hol_hid_script *s)
{
    s->n = s->used = s->next = 0;
    s->plugged = -1;
    s->open = 0;
    s->be.open_first = script_open_first;
    s->be.read = script_read;
    s->be.close = script_close;
    s->be.ctx = s;
    s->line = 0;
    s->last_plug = -1;
    s->in_plug = 0;
    s->prev_t = 0;
}

hol_err hol_hid_script_line(hol_hid_script *s, const char *p, size_t len)
{
    const char *le = p + len;
    s->line++;
    if (le > p && le[-1] == '\r')
        le--;
    if (le == p || *p == '#')
        return len > HOL_HID_SCRIPT_LINE_MAX ? HOL_ENOMEM : HOL_OK;
    hol_hid_script_event e;
    hol_err err = s->n >= HOL_HID_SCRIPT_MAX_EVENTS || len > HOL_HID_SCRIPT_LINE_MAX ? HOL_ENOMEM
                                                                                    : HOL_OK;
    double t = 0;
    if (!err && parse_time(p, le, &t) && t < s->prev_t)
        err = HOL_EPARSE; /* time going back */
    if (!err)
        err = parse_event(s, p, le, s->in_plug, s->last_plug, &e);
    if (err) {
        s->n = s->used = 0;
        return err;
    }
    e.t = s->prev_t = t;
    if (e.kind == HOL_HID_SCRIPT_PLUG)
        s->last_plug = (long)s->n, s->in_plug = 1;
    else if (e.kind == HOL_HID_SCRIPT_UNPLUG)
        s->in_plug = 0;
    s->ev[s->n++] = e;
    return HOL_OK;
}

hol_err hol_hid_script_parse(hol_hid_script *s, const char *text, size_t len, long *out_line)
{
    hol_hid_script_begin(s);
    const char *p = text, *end = text + len;
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        const char *le = nl ? nl : end;
        hol_err err = hol_hid_script_line(s, p, (size_t)(le - p));
        if (err) {
            if (out_line)
                *out_line = s->line;
            return err;
        }
        p = nl ? nl + 1 : end;
    }
    return HOL_OK;
}

const hol_hid_backend *hol_hid_script_backend(hol_hid_script *s)
{
    return &s->be;
}

int hol_hid_script_done(const hol_hid_script *s)
{
    return s->next >= s->n;
}

/* Let the plugs and unplugs due by now_s happen, up to the first report
 * (reports are the reads'). */
static void settle(hol_hid_script *s, double now_s)
{
    while (s->next < s->n && s->ev[s->next].t <= now_s &&
           s->ev[s->next].kind != HOL_HID_SCRIPT_REPORT) {
        const hol_hid_script_event *e = &s->ev[s->next++];
        if (e->kind == HOL_HID_SCRIPT_PLUG)
            s->plugged = (long)(e - s->ev);
        else if (e->kind == HOL_HID_SCRIPT_UNPLUG)
            s->plugged = -1;
    }
}

static hol_err script_open_first(void *ctx, double now_s, hol_hid_dev_info *out_info,
                                 uint8_t *desc, size_t cap, size_t *out_len)
{
    hol_hid_script *s = ctx;
    settle(s, now_s);
    if (s->plugged < 0)
        return HOL_EOPEN;
    const hol_hid_script_event *e = &s->ev[s->plugged];
    if (e->len > cap)
        return HOL_EOPEN;
    memset(out_info, 0, sizeof *out_info);
    out_info->vid = e->vid;
    out_info->pid = e->pid;
    out_info->usage_page = 0x01;
    out_info->usage = 0x05;
    memcpy(out_info->path, "script", 7);
    memcpy(out_info->name, "scripted controller", 20);
    memcpy(desc, s->bytes + e->off, e->len);
    *out_len = e->len;
    s->open = 1;
    return HOL_OK;
}

static int script_read(void *ctx, double now_s, uint8_t *buf, size_t cap)
{
    hol_hid_script *s = ctx;
    if (!s->open || s->plugged < 0)
        return -1;
    if (s->next >= s->n || s->ev[s->next].t > now_s)
        return 0;
    const hol_hid_script_event *e = &s->ev[s->next++];
    if (e->kind == HOL_HID_SCRIPT_UNPLUG) {
        s->plugged = -1;
        return -1;
    }
    /* only reports follow a plug until its unplug */
    size_t n = e->len < cap ? e->len : cap;
    memcpy(buf, s->bytes + e->off, n);
    return (int)n;
}

static void script_close(void *ctx)
{
    hol_hid_script *s = ctx;
    s->open = 0;
}
