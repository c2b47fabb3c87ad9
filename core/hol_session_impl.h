/* hol_session_impl.h - the session's insides, shared by its files:
 * hol_session_run.c (create, the frame, the level sequence, the end),
 * hol_session_recover.c (a log folder's earlier files: refusal, recovery),
 * hol_session_log.c (rows, attempts begun and ended; it also holds
 * hol_session_cues_visible), hol_session_track.c (the track rows) and
 * hol_session_out.c (the buffered outputs, the end names, the first sink
 * failure, the attempt's file names). Calls go one way, down:
 * hol_session_run.c -> hol_session_recover.c -> hol_session_log.c ->
 * hol_session_track.c -> hol_session_out.c, each file calling only files
 * after it in this list. */
#ifndef HOL_SESSION_IMPL_H
#define HOL_SESSION_IMPL_H

#include "hol_session.h"

/* A summary row's fixed part, then its tail: ",N,HEX,META" with META
 * CSV-quoted (each byte at most doubled). */
#define HOL__TAIL_MAX (2 * HOL_REC_META_TEXT + 96)
#define HOL__ROW_MAX (1024 + HOL__TAIL_MAX)

/* A buffered output stream of a sink. */
typedef struct hol__out {
    const hol_sink *sink;
    int h; /* -1: closed */
    char *buf;
    size_t n, cap;
    char name[HOL_SINK_NAME_MAX];
} hol__out;

/* The previous frame of the attempt, for head rows between frames. */
typedef struct hol__head_frame {
    int valid;
    double t; /* level time */
    double pos[3], yaw, pitch;
    hol_room room;
} hol__head_frame;

/* The previous frame of the attempt, for track rows between frames: the
 * head (0), left (1) and right (2) hands, x y z qx qy qz qw each, and
 * which are tracked. */
typedef struct hol__track_frame {
    int valid;
    double t; /* level time */
    double pose[3][7];
    int ok[3];
    uint32_t device;
} hol__track_frame;

/* Row ends: the app's (hol_app_end) and the session's own. */
enum { HOL__END_ABORTED = 5, HOL__END_KILLED = 6 };

struct hol_session {
    hol_alloc alloc;
    hol_app *app;
    hol_level *levels;
    int nlevels, cur;
    hol_rec_meta meta;
    const hol_sink *log, *rec;
    char rec_name[HOL_SINK_NAME_MAX];
    hol__out rec_out, steps, head, track;
    int attempt, attempt_open;
    int ask_pending;     /* meta.ask_item: answers go on meta.ask_attempt
                            until this session's first attempt begins */
    int level_end;       /* hol_app_end of the level in play's attempt once
                            it ended (its questions may follow); 0 */
    double attempt_started;  /* session time at the attempt's start */
    double next_sample;      /* the next head row's time, in 0.1 s (whole) */
    hol__head_frame prev;
    int track_hz;            /* track rows per second of level time */
    double track_next;       /* the next track row's sample (whole) */
    hol__track_frame track_prev;
    double flush_s, next_flush, now;
    long frames;
    int over, finished, recovered, dropped;
    int events_known;        /* events.csv is known to have its header */
    int points_known;        /* points.csv likewise */
    int lessons_known;       /* tutorial.csv likewise */
    int answers_known;       /* answers.csv likewise */
    char *row;               /* a summary row being made (HOL__ROW_MAX) */
    char *scratch;           /* recovery's copy of a row (HOL__ROW_MAX) */
    char *tail;              /* the summary rows' last three fields */
    size_t tail_len;
    int old_cols;            /* summary.csv has HOL_SESSION_SUMMARY_COLUMNS_OLD */
    char cut[160];           /* recovery: the logs cut to whole rows ("a, b") */
    char gone[160];          /* recovery: the files of a cut row removed */
    char repaired[512];      /* hol_session_repaired's line */
    hol_err failed;          /* the first sink failure (sticky) */
    int failed_told;
    char msg[256];
};

/* hol_session_out.c */
extern const char *const hol__end_names[7];
void hol__out_init(hol__out *o, const hol_sink *sink, char *buf, size_t cap);
hol_err hol__out_open(hol_session *s, hol__out *o, const char *name, int append);
void hol__out_put(hol_session *s, hol__out *o, const char *data, size_t n);
void hol__out_printf(hol_session *s, hol__out *o, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void hol__out_flush(hol_session *s, hol__out *o, int durable);
void hol__out_close(hol_session *s, hol__out *o);
hol_err hol__fail_sink(hol_session *s, const hol_sink *k, hol_err e, const char *what,
                       const char *name);
void hol__attempt_name(char *out, size_t cap, const char *what, int attempt);

/* hol_session_log.c */
size_t hol__summary_row(const hol_session *s, const hol_app_summary *sum, int end, char *out,
                        size_t cap);
/* The summary rows' tail from m: ",session_no,study_sha256,meta". */
void hol__summary_tail(const hol_rec_meta *m, char *out, size_t cap, size_t *out_len);
void hol__log_frame(hol_session *s, const hol_app_events *ev, const hol_app_view *v,
                    const hol_input *in);
void hol__attempt_end(hol_session *s, const hol_app_summary *sum, int end);
void hol__log_levels(hol_session *s);
/* The study's text as study-HASH.txt, HASH meta.study_sha256. */
void hol__log_study(hol_session *s, const char *text, size_t len);

/* hol_session_track.c: the last sample k / hz at or before t; the track
 * rows of a frame (name: the level's CSV field). */
double hol__last_sample_hz(double t, int hz);
void hol__track_rows(hol_session *s, const hol_app_view *v, const hol_input *in,
                     const char *name);

/* hol_session_recover.c */
hol_err hol__log_open(hol_session *s, int append);
/* Attempt a's live files (their rows flushed and closed) finished as a
 * later session's recovery finishes a killed one. */
void hol__recover_killed(hol_session *s, int a);

#endif
