/* report_bids.h - `holonomy report --bids DIR`: the head and hand tracks
 * of every attempt (track-NNN.csv) as a BIDS-Motion dataset (BIDS 1.9,
 * BEP029; docs/report.md, "BIDS-Motion export").
 *
 * Contract
 * - report_bids_check(cmd, dir): DIR is a new name in an existing folder or
 *   an empty folder (an export is never merged into an older one): 0, or
 *   CLI_EXIT_USAGE after one line naming --bids. Called before anything is
 *   read or written.
 * - report_bids_write(r, dir) writes, for every attempt of r->att with a
 *   track file of at least two samples, two tracking systems of one run:
 *   `room` (the poses as logged, room metres) and `tile` (the same samples
 *   turned into the frame of the tile the room stood on at that sample),
 *   each as sub-L/ses-S/motion/sub-L_ses-S_task-T_tracksys-K_run-N_
 *   {motion.tsv,channels.tsv,motion.json}; and dataset_description.json,
 *   README, participants.tsv and participants.json at the top. Every file
 *   is written atomically (platform/file). An attempt without a track file
 *   is a warning, not an error; a malformed track or steps file is bad
 *   input (2) after one line naming the file and line. 0, or the exit
 *   status after one line on stderr.
 * - Labels are the letters and digits of the participant id (empty:
 *   "anon"), of `session_no` (else the session id) and of the condition
 *   (else the level); two ids with one label get "n2", "n3", ... after it;
 *   participants.tsv gives each label's id.
 */
#ifndef REPORT_BIDS_H
#define REPORT_BIDS_H

#include "report.h"

int report_bids_check(const char *cmd, const char *dir);
int report_bids_write(report_run *r, const char *dir);

#endif
