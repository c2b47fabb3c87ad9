/* test_session_study.c - the study's text kept by the session
 * (core/hol_session.h, "Studies"): every platform hands the session the
 * study file's bytes (hol_session_desc's study_text) and the session alone
 * writes study-HASH.txt in the log folder, as it writes level-HASH.txt.
 *
 * Against the in-memory folder of tests/mem_sink.h, watched by a spy that
 * logs every sink call: the file is written once a session (a restart and
 * a second attempt write nothing more), as study-HASH.txt.live flushed
 * durably, closed, then renamed (the final name never holds fewer bytes
 * than the text), with HASH the text's SHA-256 and the exact bytes (not
 * NUL-terminated, CR LF kept); a replay (no text) and a session without
 * logs write none; a text whose hash is not meta.study_sha256 is refused
 * before anything is written; another session's file of the same name is
 * replaced by the same bytes; a failed rename fails the create naming it.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_level.h"
#include "../core/hol_session.h"
#include "../core/hol_sha256.h"

#include "app_fixture.h" /* the navigator, a tracked head */
#include "mem_sink.h"    /* a folder in memory */

static hol_level g_flag; /* mode flag, seed 5, flag Wrf: 8 steps by WNESWNEE */

/* A study file's bytes: CR LF kept, a NUL-free text whose last bytes
 * (after STUDY_LEN) are not part of it. */
static const char g_study[] = "study s1\r\ncondition hand\nlevel f.lvl\nset minimap hand\n"
                              "NOT PART OF THE TEXT";
#define STUDY_LEN (sizeof g_study - 1 - 20)
static char g_hex[HOL_SHA256_HEX], g_name[96], g_live[104];

/* The group's navigator (app_fixture.h's setup), the level, the names. */
static int study_setup(void **state)
{
    const char *t = "mode flag\nseed 5\nflag Wrf\n";
    uint8_t dig[32];
    hol_sha256(g_study, STUDY_LEN, dig);
    hol_sha256_hex(dig, g_hex);
    snprintf(g_name, sizeof g_name, "study-%s.txt", g_hex);
    snprintf(g_live, sizeof g_live, "%s.live", g_name);
    if (setup(state) || hol_level_make("lv", 2, t, strlen(t), &g_flag, NULL) != HOL_OK)
        return -1;
    snprintf(g_flag.condition, sizeof g_flag.condition, "hand"); /* the study's */
    g_flag.position = 1;
    return 0;
}

/* ---- a spy on the folder: every call on a study file logged ---------------- */

typedef struct spy {
    hol_sink sink;
    mem_sink *m;
    char ops[32][256];
    int nops;
    size_t kept_at_rename; /* the live file's flushed bytes when renamed */
} spy;

static spy g_spy;

static const char *spy_name(int h)
{
    return g_spy.m->s[g_spy.m->open[h] - 1].name;
}

static void spy_log(const char *verb, const char *name, const char *more)
{
    if (strncmp(name, "study-", 6))
        return;
    assert_true(g_spy.nops < 32);
    snprintf(g_spy.ops[g_spy.nops++], sizeof g_spy.ops[0], "%s %s%s", verb, name, more);
}

static hol_err spy_open(void *user, const char *name, int append, int *out_h)
{
    (void)user;
    spy_log(append ? "append" : "open", name, "");
    return g_spy.m->sink.open(g_spy.m, name, append, out_h);
}

static hol_err spy_write(void *user, int h, const void *data, size_t n)
{
    (void)user;
    char more[32];
    snprintf(more, sizeof more, " %zu", n);
    spy_log("write", spy_name(h), more);
    return g_spy.m->sink.write(g_spy.m, h, data, n);
}

static hol_err spy_flush(void *user, int h, int durable)
{
    (void)user;
    spy_log(durable ? "sync" : "flush", spy_name(h), "");
    return g_spy.m->sink.flush(g_spy.m, h, durable);
}

static hol_err spy_close(void *user, int h)
{
    (void)user;
    spy_log("close", spy_name(h), "");
    return g_spy.m->sink.close(g_spy.m, h);
}

static hol_err spy_rename(void *user, const char *from, const char *to)
{
    (void)user;
    char more[120];
    snprintf(more, sizeof more, " %s", to);
    spy_log("rename", from, more);
    mem_stream *s = mem_find(g_spy.m, from);
    if (s && !strcmp(to, g_name))
        g_spy.kept_at_rename = s->kept;
    return g_spy.m->sink.rename(g_spy.m, from, to);
}

static hol_err spy_remove(void *user, const char *name)
{
    (void)user;
    spy_log("remove", name, "");
    return g_spy.m->sink.remove(g_spy.m, name);
}

static hol_err spy_read(void *user, const char *name, uint64_t off, void *buf, size_t n,
                        size_t *out_got)
{
    (void)user;
    return g_spy.m->sink.read(g_spy.m, name, off, buf, n, out_got);
}

static hol_err spy_list(void *user, void (*fn)(void *ctx, const char *name), void *ctx)
{
    (void)user;
    return g_spy.m->sink.list(g_spy.m, fn, ctx);
}

static const hol_sink *spy_on(mem_sink *m)
{
    memset(&g_spy, 0, sizeof g_spy);
    g_spy.m = m;
    g_spy.sink = (hol_sink){&g_spy, spy_open, spy_write, spy_flush, spy_close, spy_rename,
                            spy_remove, spy_read, spy_list, NULL};
    return &g_spy.sink;
}

/* ---- sessions ----------------------------------------------------------------- */

static hol_session_desc desc(const hol_sink *log, const char *text, size_t len, const char *hex)
{
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = &g_flag;
    d.nlevels = 1;
    d.app.nav = g_nav;
    d.log = log;
    d.append = 1;
    snprintf(d.meta.session, sizeof d.meta.session, "20260101T000000Z-00000003");
    snprintf(d.meta.start, sizeof d.meta.start, "2026-01-01T00:00:00Z");
    snprintf(d.meta.participant, sizeof d.meta.participant, "P3");
    snprintf(d.meta.study, sizeof d.meta.study, "s1");
    snprintf(d.meta.study_sha256, sizeof d.meta.study_sha256, "%s", hex);
    d.study_text = text;
    d.study_len = len;
    return d;
}

/* The walk from cell (1,1): frame i at t0 + i / 4 s where the first i
 * steps lead; the last frame's time. */
static double walk(hol_session *s, const char *w, double t0)
{
    int c = 1, r = 1, over = 0;
    size_t n = strlen(w);
    for (size_t i = 0; i <= n; i++) {
        hol_input in = tracked_at(t0 + 0.25 * (double)i, c, r);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
        if (i < n) {
            c += w[i] == 'E' ? 1 : w[i] == 'W' ? -1 : 0;
            r += w[i] == 'S' ? 1 : w[i] == 'N' ? -1 : 0;
        }
    }
    return t0 + 0.25 * (double)n;
}

static int study_files(mem_sink *m)
{
    int n = 0;
    for (int i = 0; i < MEM_MAX; i++)
        n += m->s[i].used && !strncmp(m->s[i].name, "study-", 6);
    return n;
}

/* ---- the tests ---------------------------------------------------------------- */

/* Written once, at create, atomically, with its name and bytes; a restart
 * (attempt 2) and the session's end write nothing more. */
static void test_study_kept_once(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session_desc d = desc(spy_on(&m), g_study, STUDY_LEN, g_hex);
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    /* the calls at create: the live file whole and durable, then renamed */
    char want[5][256];
    snprintf(want[0], sizeof want[0], "open %s", g_live);
    snprintf(want[1], sizeof want[1], "write %s %zu", g_live, STUDY_LEN);
    snprintf(want[2], sizeof want[2], "sync %s", g_live);
    snprintf(want[3], sizeof want[3], "close %s", g_live);
    snprintf(want[4], sizeof want[4], "rename %s %s", g_live, g_name);
    assert_int_equal(g_spy.nops, 5);
    for (int i = 0; i < 5; i++)
        assert_string_equal(g_spy.ops[i], want[i]);
    assert_int_equal(g_spy.kept_at_rename, STUDY_LEN);
    /* attempt 1 restarted, attempt 2 done, the session finished */
    double t = walk(s, "WE", 0);
    int over = 0;
    hol_input in = app_head(t + 0.25, 1, 1, 0, 0, HOL_BTN_RESTART);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    walk(s, "WNESWNEE", t + 1);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    const char *sum = mem_text(&m, "summary.csv");
    assert_non_null(strstr(sum, ",1,s1,hand,1,lv,"));
    assert_non_null(strstr(sum, ",restart,"));
    assert_non_null(strstr(sum, ",2,s1,hand,1,lv,"));
    assert_non_null(strstr(sum, ",done,"));
    assert_int_equal(g_spy.nops, 5); /* nothing more on a study file */
    mem_stream *f = mem_find(&m, g_name);
    assert_non_null(f);
    assert_int_equal(f->len, STUDY_LEN);
    assert_int_equal(f->kept, STUDY_LEN);
    assert_memory_equal(f->data, g_study, STUDY_LEN);
    assert_null(mem_find(&m, g_live));
    assert_int_equal(study_files(&m), 1);
    /* its hash is the summary's study_sha256 */
    assert_non_null(strstr(sum, g_hex));
    /* a second session on the folder: the same file, made again once */
    s = NULL;
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    assert_int_equal(g_spy.nops, 10);
    assert_int_equal(study_files(&m), 1);
    assert_memory_equal(mem_find(&m, g_name)->data, g_study, STUDY_LEN);
    mem_free(&m);
}

/* A replay has no text (its recording carries the hash): no study file,
 * the hash still in the rows; a session without logs writes nothing. */
static void test_study_not_on_replay(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session_desc d = desc(spy_on(&m), NULL, 0, g_hex);
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    walk(s, "WNESWNEE", 0);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    assert_int_equal(g_spy.nops, 0);
    assert_int_equal(study_files(&m), 0);
    assert_non_null(strstr(mem_text(&m, "summary.csv"), g_hex));
    mem_free(&m);
    d = desc(NULL, g_study, STUDY_LEN, g_hex);
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
}

/* A text that is not the one meta.study_sha256 names (another's hash, no
 * hash, a byte more) is refused before anything is written. */
static void test_study_hash_checked(void **state)
{
    (void)state;
    static mem_sink m;
    char other[HOL_SHA256_HEX];
    snprintf(other, sizeof other, "%s", g_hex);
    other[0] = other[0] == '0' ? '1' : '0';
    const hol_session_desc bad[3] = {desc(spy_on(&m), g_study, STUDY_LEN, other),
                                     desc(spy_on(&m), g_study, STUDY_LEN, ""),
                                     desc(spy_on(&m), g_study, STUDY_LEN + 1, g_hex)};
    for (int i = 0; i < 3; i++) {
        mem_init(&m);
        spy_on(&m);
        hol_session *s = NULL;
        char msg[256];
        assert_int_equal(hol_session_create(&bad[i], &s, msg, sizeof msg), HOL_EARG);
        assert_null(s);
        assert_non_null(strstr(msg, "study"));
        for (int k = 0; k < MEM_MAX; k++)
            assert_false(m.s[k].used); /* nothing written */
        mem_free(&m);
    }
}

/* Another session's file of the same name is replaced by the text's bytes
 * (a file cut or edited by hand made whole again); a rename that fails
 * fails the create, naming the file. */
static void test_study_replaced_or_failed(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    mem_stream *old = mem_make(&m, g_name);
    old->data = malloc(8);
    memcpy(old->data, "study s", 7);
    old->len = old->kept = 7;
    old->cap = 8;
    hol_session_desc d = desc(spy_on(&m), g_study, STUDY_LEN, g_hex);
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    mem_stream *f = mem_find(&m, g_name);
    assert_int_equal(f->len, STUDY_LEN);
    assert_memory_equal(f->data, g_study, STUDY_LEN);
    mem_free(&m);
    /* the level's rename first, the study's second */
    mem_init(&m);
    m.fail_rename = 2;
    d = desc(spy_on(&m), g_study, STUDY_LEN, g_hex);
    s = NULL;
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_EIO);
    assert_null(s);
    assert_non_null(strstr(msg, "cannot rename 'study-"));
    assert_null(mem_find(&m, g_name));
    mem_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_study_kept_once),
        cmocka_unit_test(test_study_not_on_replay),
        cmocka_unit_test(test_study_hash_checked),
        cmocka_unit_test(test_study_replaced_or_failed),
    };
    return cmocka_run_group_tests(tests, study_setup, teardown);
}
