/* hol_hid_script.h - a game controller played back from a text script: the
 * device layer's backend (hol_hid_dev.h) for tests and
 * `holonomy play --gamepad-replay FILE`, where no real device is at hand.
 *
 * Contract
 * - A script is lines of text (LF or CR LF). Blank lines and lines starting
 *   with '#' are ignored; every other line is one event:
 *
 *     TIME plug VID:PID HEX   a controller is plugged in (VID:PID four hex
 *                             digits each; HEX its report descriptor)
 *     TIME plug               the last plugged controller is plugged back
 *     TIME report HEX         the controller sends this input report
 *     TIME unplug             the controller goes away
 *
 *   TIME is seconds (digits, optional '.' and digits) on the clock of the
 *   polls (hol_input.time_s), never going back. HEX is hex digit pairs, in
 *   groups separated by single spaces (at most HOL_HID_DESC_MAX bytes of
 *   descriptor, HOL_HID_REPORT_MAX_BYTES of report). plug only while
 *   unplugged, report and unplug only while plugged. Fields are separated
 *   by single spaces.
 * - hol_hid_script_parse checks the whole script into caller memory
 *   (struct hol_hid_script, no allocation); an error is HOL_EPARSE (or
 *   HOL_ENOMEM: more than HOL_HID_SCRIPT_MAX_EVENTS events or
 *   HOL_HID_SCRIPT_MAX_BYTES bytes of hex, or a line, comments included,
 *   longer than HOL_HID_SCRIPT_LINE_MAX bytes) with the 1-based line in
 *   *out_line. The same a line at a time, for a script streamed from a
 *   file: hol_hid_script_begin, then hol_hid_script_line for each line
 *   (without its LF; s->line is the line's number), stopping at the first
 *   error (the script is then empty).
 * - Played back (hol_hid_script_backend), an event happens at the first
 *   poll whose time is at or past its TIME: the device layer's enumeration
 *   finds the controller while it is plugged in; reads return the reports
 *   due, in order, then 0; a read that reaches an unplug fails (< 0), as a
 *   real read does. A report is read by the first read at or past
 *   its TIME (while the layer waits to re-enumerate, they wait too).
 * - hol_hid_script_done tells when the playback has nothing left: `hid
 *   watch --replay` ends there (a script need not unplug its pad).
 * - No I/O, no allocation, no globals.
 */
#ifndef HOL_HID_SCRIPT_H
#define HOL_HID_SCRIPT_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_err.h"
#include "hol_hid_dev.h"

#define HOL_HID_SCRIPT_MAX_EVENTS 16384
#define HOL_HID_SCRIPT_MAX_BYTES (1u << 18)
/* The longest line: a plug with the largest descriptor (3 characters a
 * byte) and room for the time and the VID:PID. */
#define HOL_HID_SCRIPT_LINE_MAX (64 + 3 * HOL_HID_DESC_MAX)

enum { HOL_HID_SCRIPT_PLUG = 1, HOL_HID_SCRIPT_REPORT, HOL_HID_SCRIPT_UNPLUG };

typedef struct hol_hid_script_event {
    double t;
    int kind;          /* HOL_HID_SCRIPT_* */
    uint16_t vid, pid; /* plug */
    uint32_t off, len; /* plug: descriptor; report: the report (in bytes[]) */
} hol_hid_script_event;

typedef struct hol_hid_script {
    hol_hid_script_event ev[HOL_HID_SCRIPT_MAX_EVENTS];
    size_t n;
    uint8_t bytes[HOL_HID_SCRIPT_MAX_BYTES];
    size_t used;
    /* parsing */
    long line;      /* lines given so far */
    long last_plug; /* the last plug event, or -1 */
    int in_plug;    /* plugged at the end of the lines so far */
    double prev_t;
    /* playback */
    size_t next;    /* the first event not yet happened */
    long plugged;   /* the plug event of the controller present, or -1 */
    int open;       /* the device layer holds it open */
    hol_hid_backend be;
} hol_hid_script;

/* Parse len bytes of script text into *s (ready to play from time 0). */
hol_err hol_hid_script_parse(hol_hid_script *s, const char *text, size_t len, long *out_line);

/* The same a line at a time: begin, then each line (without its LF). */
void hol_hid_script_begin(hol_hid_script *s);
hol_err hol_hid_script_line(hol_hid_script *s, const char *line, size_t len);

/* The backend playing *s (valid while *s is). */
const hol_hid_backend *hol_hid_script_backend(hol_hid_script *s);

/* 1 once every event of *s has happened in playback (the last report read,
 * the last plug or unplug seen): nothing more can change, so a watcher of
 * the script may stop. */
int hol_hid_script_done(const hol_hid_script *s);

#endif
