/* test_codebook.c - the codebook's tables (platform/cli/codebook.h,
 * platform/shell/hol_shell_codebook.h) against the headers the writers
 * write:
 * - each log file's columns, joined with commas, are its writer's header
 *   byte for byte (both are made from one table: this checks the making):
 *   the session's HOL_SESSION_*_COLUMNS (summary, steps, head, track,
 *   events, points, answers), the shell's HOL_SHELL_ENV_COLUMNS
 *   (environment.csv), HOL_SHELL_PROV_COLUMNS, HOL_SHELL_ORDER_COLUMNS,
 *   CODEBOOK_COLUMNS; the headers are those of the build before the tables
 *   (the literals here), and points.csv and answers.csv the earlier ones
 *   and the two timestamps; the report's build.csv and codebook.csv
 *   likewise (its other files' headers are string literals in its writers:
 *   tests/cli_codebook.sh parses them from the files);
 * - every row of every table has a type of the listed ones and a meaning,
 *   no column is listed twice for a file, and no field starts with = + - @
 *   (a spreadsheet's formula);
 * - both codebooks fit CODEBOOK_TEXT_MAX, start with their header, and a
 *   report's names no "report:" file.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_session.h"
#include "../platform/cli/codebook.h"
#include "../platform/cli/codebook_table.h"
#include "../platform/cli/report/report.h"
#include "../platform/shell/hol_shell_env.h"
#include "../platform/shell/hol_shell_prov.h"

static void header_is(const char *file, const char *want)
{
    char got[4096];
    int n = codebook_header(file, got, sizeof got);
    if (n == 0 || strcmp(got, want)) {
        print_error("%s: codebook columns\n  %s\nwriter's header\n  %s\n", file, got, want);
        fail();
    }
}

static void headers_match(void **state)
{
    (void)state;
    header_is("summary.csv", HOL_SESSION_SUMMARY_COLUMNS);
    header_is("steps-NNN.csv", HOL_SESSION_STEP_COLUMNS);
    header_is("head-NNN.csv", HOL_SESSION_HEAD_COLUMNS);
    header_is("track-NNN.csv", HOL_SESSION_TRACK_COLUMNS);
    header_is("events.csv", HOL_SESSION_EVENT_COLUMNS);
    header_is("points.csv", HOL_SESSION_POINT_COLUMNS);
    header_is("answers.csv", HOL_SESSION_ANSWER_COLUMNS);
    header_is("environment.csv", HOL_SHELL_ENV_COLUMNS);
    header_is("provenance.csv", HOL_SHELL_PROV_COLUMNS);
    header_is("order.csv", HOL_SHELL_ORDER_COLUMNS);
    header_is("codebook.csv", CODEBOOK_COLUMNS);
    header_is("report:codebook.csv", CODEBOOK_COLUMNS);
    /* the report's headers, which its writers print from the table, as
     * the build before the table wrote them (byte for byte) */
    header_is("report:build.csv", "program,version,commit,build_date");
    header_is("report:attempts.csv",
              "participant,session,attempt,study,condition,position,level,mode,steps,optimum,"
              "efficiency,time,end,tiling,room,cell,logdir,picture,q,cues,minimap,"
              "logdir_relative,session_no");
    header_is("report:conditions.csv",
              "study,condition,attempts,done,mean_steps,mean_efficiency,mean_time");
    header_is("report:stats.csv", "study,condition,measure,item,n,mean,sd,ci_low,ci_high");
    header_is("report:learning.csv",
              "study,condition,position,n,mean_efficiency,sd,ci_low,ci_high");
    header_is("report:participants.csv",
              "participant,study,condition,attempts,done,mean_steps,mean_efficiency,mean_time");
    header_is("report:scores.csv", "participant,session,attempt,study,condition,placement,"
                                   "scope,instrument,subscale,score,complete,excluded");
    header_is("report:trials.csv",
              "participant,session,session_no,attempt,study,condition,block,trial,practice,"
              "level,level_sha256,mode,tiling,q,room,cell,cues,minimap,end,steps,optimum,"
              "efficiency,time,points_true,error_true,points_flat,error_flat,excluded,logdir");
    header_is("report:participants_stats.csv",
              "study,condition,measure,participants,trials,mean,sd,ci_low,ci_high,conditions,"
              "n_within,mean_within,ci_within_low,ci_within_high");
    header_is("report:paired.csv", "study,measure,condition_a,condition_b,differ,n,mean_diff,"
                                   "sd_diff,ci_low,ci_high,dz");
    header_is("report:effects.csv", "study,measure,factor,level_a,level_b,n,mean_diff,"
                                    "sd_diff,ci_low,ci_high,dz");
    /* the headers as the build before the tables wrote them */
    assert_string_equal(HOL_SESSION_SUMMARY_COLUMNS,
                        "session,participant,session_start,version,attempt,study,condition,"
                        "position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,"
                        "steps,optimum,time,end,session_no,study_sha256,meta");
    assert_string_equal(HOL_SESSION_SUMMARY_COLUMNS_OLD,
                        "session,participant,session_start,version,attempt,study,condition,"
                        "position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,"
                        "steps,optimum,time,end");
    assert_string_equal(HOL_SESSION_STEP_COLUMNS, "session,attempt,level,t,step,col,row,dir,yaw,"
                                                  "tile,orient,remaining,cues,visible");
    assert_string_equal(HOL_SESSION_HEAD_COLUMNS,
                        "session,attempt,level,t,frame_t,x,y,z,yaw,pitch,col,row,tile");
    assert_string_equal(HOL_SESSION_TRACK_COLUMNS,
                        "session,attempt,level,sample,t,frame_t,device,"
                        "head_x,head_y,head_z,head_qx,head_qy,head_qz,head_qw,"
                        "left_x,left_y,left_z,left_qx,left_qy,left_qz,left_qw,"
                        "right_x,right_y,right_z,right_qx,right_qy,right_qz,right_qw");
    assert_string_equal(HOL_SESSION_EVENT_COLUMNS, "session,attempt,level,t,event,value");
    assert_string_equal(HOL_SESSION_POINT_COLUMNS_OLD,
                        "session,participant,attempt,level,t,target,pointed,true,flat,"
                        "error_true,error_flat,time");
    assert_string_equal(HOL_SESSION_POINT_COLUMNS,
                        HOL_SESSION_POINT_COLUMNS_OLD ",shown_ms,answered_ms");
    assert_string_equal(HOL_SESSION_ANSWER_COLUMNS_OLD,
                        "session,participant,attempt,questionnaire,when,item,kind,value,time");
    assert_string_equal(HOL_SESSION_ANSWER_COLUMNS,
                        HOL_SESSION_ANSWER_COLUMNS_OLD ",shown_ms,answered_ms");
    assert_string_equal(HOL_SHELL_ENV_COLUMNS,
                        "session,participant,session_no,study_sha256,platform,os,runtime,"
                        "gl_renderer,controller,refresh_hz,width,height,meta,options");
    assert_string_equal(HOL_SHELL_PROV_COLUMNS, "session,participant,version,commit,build_date");
    assert_string_equal(HOL_SHELL_ORDER_COLUMNS, "session,participant,study,position,condition,"
                                                 "level,level_file,level_sha256");
    assert_string_equal(CODEBOOK_COLUMNS, "file,column,type,unit,allowed,meaning");
    char none[8];
    assert_int_equal(codebook_header("nothing.csv", none, sizeof none), 0);
}

static int formula(const char *s) { return s[0] && strchr("=+-@", s[0]) != NULL; }

/* A row complete and no formula; 0 or 1 after a message. */
static int row_bad(const char *file, const hol_codebook_col *r)
{
    static const char *const types[] = {"string", "integer", "number", "hex", "id", "timestamp"};
    int typed = 0;
    for (size_t k = 0; k < sizeof types / sizeof types[0]; k++)
        typed |= !strcmp(r->type, types[k]);
    if (!typed || !r->column[0] || formula(r->unit) || formula(r->allowed) ||
        formula(r->meaning) || formula(r->column)) {
        print_error("%s %s incomplete or a formula\n", file, r->column);
        return 1;
    }
    return 0;
}

/* No double quote or line break in a field, no comma in the unquoted ones
 * (codebook.csv's text is made by the preprocessor: hol_shell_codebook.h);
 * 1 when so. */
static int csv_safe(const char *file, const hol_codebook_col *r)
{
    const char *f[6] = {file, r->column, r->type, r->unit, r->allowed, r->meaning};
    for (int k = 0; k < 6; k++)
        if (strpbrk(f[k], k < 4 ? "\",\r\n" : "\"\r\n")) {
            print_error("%s %s: a quote, line break or comma in field %d\n", file, r->column, k);
            return 0;
        }
    return 1;
}

static void rows_complete(void **state)
{
    (void)state;
    size_t n = sizeof codebook_rows / sizeof codebook_rows[0];
    for (size_t i = 0; i < n; i++) {
        const codebook_row *r = &codebook_rows[i];
        const hol_codebook_col c = {r->column, r->type, r->unit, r->allowed, r->meaning};
        if (row_bad(r->file, &c) || !csv_safe(r->file, &c))
            fail();
        for (size_t j = 0; j < i; j++)
            if (!strcmp(codebook_rows[j].file, r->file) &&
                !strcmp(codebook_rows[j].column, r->column)) {
                print_error("%s %s listed twice\n", r->file, r->column);
                fail();
            }
    }
    int nf;
    const hol_codebook_file *f = hol_shell_codebook_logs(&nf);
    for (int i = 0; i < nf; i++)
        for (int c = 0; c < f[i].n; c++) {
            if (row_bad(f[i].name, &f[i].cols[c]) || !csv_safe(f[i].name, &f[i].cols[c]) ||
                !f[i].cols[c].meaning[0])
                fail();
            for (int d = 0; d < c; d++)
                if (!strcmp(f[i].cols[d].column, f[i].cols[c].column)) {
                    print_error("%s %s listed twice\n", f[i].name, f[i].cols[c].column);
                    fail();
                }
        }
}

static void texts(void **state)
{
    (void)state;
    static char text[CODEBOOK_TEXT_MAX];
    for (int which = CODEBOOK_LOGS; which <= CODEBOOK_REPORT; which++) {
        size_t n = codebook_csv(which, text, sizeof text);
        assert_true(n > 0 && n == strlen(text) && text[n - 1] == '\n');
        assert_memory_equal(text, CODEBOOK_COLUMNS "\n", sizeof CODEBOOK_COLUMNS);
        assert_null(strstr(text, "report:"));
        /* every meaning filled (a report's from the log column's) */
        assert_null(strstr(text, ",\"\"\n"));
    }
    assert_non_null(strstr(text, "\nattempts.csv,steps,"));
    /* the log folder's text (made by the preprocessor) is the rows as
     * hol_shell_codebook_put writes them from the tables */
    static char rows[CODEBOOK_TEXT_MAX];
    size_t at = 0;
    int nf;
    const hol_codebook_file *f = hol_shell_codebook_logs(&nf);
    at = (size_t)snprintf(rows, sizeof rows, "%s\n", CODEBOOK_COLUMNS);
    for (int i = 0; i < nf; i++)
        for (int c = 0; c < f[i].n; c++)
            assert_int_equal(hol_shell_codebook_put(f[i].name, &f[i].cols[c], rows, sizeof rows, &at),
                             0);
    assert_int_equal(codebook_csv(CODEBOOK_LOGS, text, sizeof text), at);
    assert_string_equal(text, rows);
    assert_non_null(strstr(text, "\nanswers.csv,answered_ms,integer,ms,\"0..\",\"the session's"));
    assert_int_equal(codebook_csv(CODEBOOK_LOGS, text, 100), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(headers_match),
        cmocka_unit_test(rows_complete),
        cmocka_unit_test(texts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
