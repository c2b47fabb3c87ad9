/* play_stats.c - frame time for `holonomy play` (see play_stats.h). */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE
#endif
#include "play_stats.h"

#include <stdio.h>
#include <time.h>

double play_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

void play_stats_add(frame_stats *fs, int print)
{
    double w = play_now_s(), c = cpu_s();
    if (!fs->total) {
        fs->wall0 = fs->first_wall = w;
        fs->cpu0 = fs->last_cpu = c;
        snprintf(fs->text, sizeof fs->text, "FPS - CPU - MS");
    }
    double ms = (c - fs->last_cpu) * 1e3;
    fs->last_cpu = c;
    fs->total++;
    fs->frames++;
    fs->total_cpu_ms += ms;
    fs->max_cpu_ms = ms > fs->max_cpu_ms ? ms : fs->max_cpu_ms;
    if (w - fs->wall0 < 1.0)
        return;
    fs->fps = fs->frames / (w - fs->wall0);
    fs->cpu_ms = (c - fs->cpu0) * 1e3 / fs->frames;
    snprintf(fs->text, sizeof fs->text, "FPS %.1f CPU %.1f MS", fs->fps, fs->cpu_ms);
    if (print)
        fprintf(stderr, "stats: %.0f s: %.1f fps, CPU %.1f ms a frame\n", w - fs->first_wall,
                fs->fps, fs->cpu_ms);
    fs->wall0 = w;
    fs->cpu0 = c;
    fs->frames = 0;
}

void play_stats_end(const frame_stats *fs)
{
    if (!fs->total)
        return;
    double secs = play_now_s() - fs->first_wall;
    fprintf(stderr, "stats: %ld frames in %.1f s: %.1f fps, CPU %.1f ms a frame (max %.1f)\n",
            fs->total, secs, secs > 0 ? fs->total / secs : 0.0, fs->total_cpu_ms / fs->total,
            fs->max_cpu_ms);
}
