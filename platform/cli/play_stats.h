/* play_stats.h - frame time for `holonomy play`: fps and process CPU ms a
 * frame (the software rasterizer's threads included) over the last second,
 * for the F2 overlay and --stats.
 *
 * Contract: play_stats_add after each frame renews the figures every
 * second (printed to stderr with print); text holds the overlay's line;
 * play_stats_end prints the whole run's figures. Clocks: CLOCK_MONOTONIC
 * and CLOCK_PROCESS_CPUTIME_ID.
 */
#ifndef HOL_PLAY_STATS_H
#define HOL_PLAY_STATS_H

typedef struct frame_stats {
    double wall0, cpu0;      /* this second's start */
    double last_cpu;         /* CPU at the frame's start */
    long frames;             /* in this second */
    double fps, cpu_ms;      /* of the last full second */
    long total;              /* every frame */
    double total_cpu_ms, max_cpu_ms, first_wall;
    char text[48];           /* "FPS 19.8 CPU 41.2 MS" */
} frame_stats;

void play_stats_add(frame_stats *fs, int print);
void play_stats_end(const frame_stats *fs);
double play_now_s(void);

#endif
