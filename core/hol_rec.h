/* hol_rec.h - the recording format: a session's metadata and levels, then
 * one input record per frame. Written by the session (hol_session.h), read
 * by `holonomy replay` and `play --input` line by line.
 *
 * Contract
 * - Text, one item per line (LF; a CR before the LF is ignored on reading):
 *
 *     holonomy-rec 2        (3 for a study's session, 4 with the lines below,
 *                           5 when a ready screen can show: below)
 *     session ID            the session's id          (version 2)
 *     participant ID        optional                  (version 2)
 *     start ISO             start, UTC: 2025-01-31T12:00:00Z (version 2)
 *     version V             the app version that played (version 2)
 *     study NAME            the study (version 3; optional in 4)
 *     session_no N          --session N, 1..999       (version 4, optional)
 *     study_sha256 HEX      the study file's SHA-256, 64 lowercase hex
 *                           digits                    (version 4, optional)
 *     meta KEY=VALUE        each --meta, in order     (version 4, optional,
 *                           up to HOL_REC_META_MAX; KEY 1..32 of a-z 0-9 _,
 *                           VALUE as hol_text_escape writes it: no ';',
 *                           no control byte, at most 800 bytes)
 *     ask ID ATTEMPT ITEM   a resumed participant's unanswered questions:
 *                           the first level is not played, its questions
 *                           are asked from ITEM (1..255), the answers on
 *                           attempt ATTEMPT (1..999999) of session ID
 *                           (version 4, optional; meta.ask_*)
 *     ready                 a resumed session: its first level begins on
 *                           the ready screen (version 5, optional, once;
 *                           meta.ready)
 *     level NAME            each level of the session, in order:
 *     condition NAME POS    its study condition and position (version 3)
 *     L LINE                its text's lines (hol_level.h), then
 *     end
 *     TIME f=... ...        one input line per frame (core/hol_input_io.h)
 *     end aborted           last, when the session was aborted (a signal,
 *                           the window closed: HOL_REC_ABORTED_LINE), so a
 *                           replay ends it the same way
 *
 *   Versions 1 (no metadata lines), 2 (no study), 3 and 4 are read too; the
 *   writer writes version 2 unless the session is a study's (3) or has a
 *   session number, a study hash or meta (4), so a recording without them
 *   reads in a build that knows only version 2 (or 3); it writes 5 when a
 *   level has instructions or is a tutorial, or the line `ready` is
 *   written: the sessions issue 35's flow (the ready screen, the
 *   tutorial's lessons) changed. A recording of version 1 to 4 was played
 *   before that flow: its reader sets meta.flow_v4, the session then
 *   gives the app hol_app_desc.flow_v4, so it replays as it was played;
 *   the writer writes no version 5 for such a meta (a replay's recording
 *   keeps its version).
 *   The metadata lines come before the first level, each at most once
 *   (meta: once per KEY, up to HOL_REC_META_MAX);
 *   session, start and version are required from version 2, study in
 *   version 3. IDs (and condition names) are 1..63 bytes of letters,
 *   digits and '.', '_', '-' (hol_rec_id_ok); a version 1..31 bytes of
 *   those and '+'. A condition line comes right after its level line,
 *   POS 0..HOL_REC_MAX_LEVELS, in a recording with a study line (the
 *   writer writes "study -" for conditions without a study's name, so
 *   what it writes reads back the same); a level without one has no
 *   labels.
 * - hol_rec_write_header emits the header through fn in pieces whose
 *   concatenation is the text above (levels given with LF-ended text, as
 *   hol_level_make keeps it), so the header of a recording that play wrote
 *   reads back to the same metadata and levels, and the same hashes.
 * - hol_rec_reader takes the file a line at a time (without its LF):
 *   hol_rec_read_line returns HOL_OK with *out_done 0 while the header goes
 *   on, and *out_done 1 when this line is the first input line (it is not
 *   consumed: the caller parses it and the rest as input records). At the
 *   end of the file call hol_rec_read_end (a recording may hold no input
 *   lines). Errors: HOL_EPARSE / HOL_EVERSION / HOL_ENOMEM / HOL_EARG (a bad
 *   level) with r->msg "line N: ..." naming the file's line. At most
 *   HOL_REC_MAX_LEVELS levels.
 * - Lines are at most HOL_REC_LINE_MAX bytes: readers refuse a longer one at
 *   once (no recording line is longer).
 * - Pure: no allocation, no I/O; the caller gives the levels array.
 */
#ifndef HOL_REC_H
#define HOL_REC_H

#include <stddef.h>

#include "hol_err.h"

/* The recording's last line when its session was aborted (no LF). */
#define HOL_REC_ABORTED_LINE "end aborted"
#include "hol_level.h"

#define HOL_REC_VERSION 5
#define HOL_REC_MAX_LEVELS 16
#define HOL_REC_LINE_MAX 1024
#define HOL_REC_ID_MAX 64 /* with the NUL */
#define HOL_REC_META_MAX 16 /* meta lines (--meta options) */
#define HOL_REC_META_VALUE 800 /* bytes of an escaped value (4 x 200) */
/* the meta text: KEY=VALUE items joined with ';', with its NUL */
#define HOL_REC_META_TEXT (HOL_REC_META_MAX * (32 + 1 + HOL_REC_META_VALUE + 1))

typedef struct hol_rec_meta {
    char session[HOL_REC_ID_MAX];     /* "" in version 1 */
    char participant[HOL_REC_ID_MAX]; /* "": none */
    char start[HOL_REC_ID_MAX];       /* ISO 8601 UTC, "" in version 1 */
    char version[32];                 /* "" in version 1 */
    char study[HOL_REC_ID_MAX];       /* "": not a study's session */
    int session_no;                   /* --session N, 1..999; 0: none */
    char study_sha256[65];            /* "" or 64 lowercase hex digits */
    /* the --meta options, KEY=VALUE joined with ';', each VALUE escaped
     * (hol_text_escape: no control byte); "": none */
    char meta[HOL_REC_META_TEXT];
    /* a resumed participant's questions (issue 39): ask_item > 0 when the
     * session's first level is not played but its questions are asked,
     * from its item ask_item (1-based, counted over the level's
     * questionnaires in order), the answers on the attempt that played it:
     * ask_attempt (1..999999) of session ask_session; 0, 0, "": none */
    char ask_session[HOL_REC_ID_MAX];
    int ask_attempt, ask_item;
    /* 1: a resumed session: its first level begins on the ready screen
     * (hol_app_ready; issue 35); 0: none */
    int ready;
    /* 1: read from a recording of version 1 to 4, played before issue
     * 35's flow: its session's app plays that flow (hol_app_desc.flow_v4);
     * 0 (live play, version 5) */
    int flow_v4;
} hol_rec_meta;

/* 1 when k (n bytes) is a meta KEY: 1..32 of a-z, 0-9, '_'. */
int hol_rec_meta_key_ok(const char *k, size_t n);

/* 1 when s is a meta text as above: 0..HOL_REC_META_MAX items, distinct
 * keys, values escaped (hol_text_escape's own output) of at most
 * HOL_REC_META_VALUE bytes; 1 for "". */
int hol_rec_meta_ok(const char *s);

/* 1 when s is an id: 1..63 bytes of [A-Za-z0-9._-]. */
int hol_rec_id_ok(const char *s);
/* 1 when s is YYYY-MM-DDTHH:MM:SSZ. */
int hol_rec_time_ok(const char *s);

typedef void (*hol_rec_emit)(void *ctx, const char *data, size_t n);
void hol_rec_write_header(const hol_rec_meta *meta, const hol_level *levels, int nlevels,
                          hol_rec_emit fn, void *ctx);

typedef struct hol_rec_reader {
    hol_level *levels; /* cap HOL_REC_MAX_LEVELS, given */
    int nlevels;
    int version;       /* 1 or 2 once line 1 is read */
    hol_rec_meta meta;
    long line;         /* lines read */
    char msg[256];
    /* private: where the reader is, metadata seen, the level being read */
    int state, seen;
    long level_first;
    char name[HOL_LEVEL_NAME_MAX];
    char cond[HOL_LEVEL_NAME_MAX]; /* the level's condition line */
    int cond_pos;
    size_t name_len, len;
    char text[HOL_LEVEL_TEXT_MAX + 1];
} hol_rec_reader;

void hol_rec_reader_init(hol_rec_reader *r, hol_level *levels);
hol_err hol_rec_read_line(hol_rec_reader *r, const char *s, size_t len, int *out_done);
hol_err hol_rec_read_end(hol_rec_reader *r);

#endif
