/* play_track.c - `--track-hz N` (play_track.h). */
#include "play_track.h"

#include <stddef.h>

#include "../../core/hol_session.h"
#include "cli.h"

int play_track_value(const char *cmd, const char *val, int *out_hz)
{
    size_t n = 0;
    int digits = val[0] != 0;
    for (const char *p = val; *p && digits; p++)
        digits = *p >= '0' && *p <= '9';
    if (digits)
        n = cli_parse_count(val);
    if (!digits || n < HOL_SESSION_TRACK_HZ_MIN || n > HOL_SESSION_TRACK_HZ_MAX) {
        cli_error(cmd, 0, "--track-hz '%.40s' is not a whole number in %d..%d", val,
                  HOL_SESSION_TRACK_HZ_MIN, HOL_SESSION_TRACK_HZ_MAX);
        return 1;
    }
    *out_hz = (int)n;
    return 0;
}

int play_track_check(const char *cmd, int hz, const char *log_dir)
{
    if (hz && !log_dir) {
        cli_error(cmd, 0, "--track-hz goes with --log");
        return 1;
    }
    return 0;
}
