#!/bin/sh
# bench_sound.sh BINARY - `holonomy replay REC --wav F` on a 60 s recording
# (5400 frames at 90 Hz, a flag level with `sound all` and the beacon cue,
# the head swaying through the room and turning) against the same replay
# without --wav: the CPU seconds of each and of the sound alone (target:
# under 2 s; make bench, docs/performance.md). Not a test: no pass or fail.
set -eu
H=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
{ printf 'holonomy-rec 2\nsession 20261126T000000Z-00000000\nstart 2026-11-26T00:00:00Z\n'
  printf 'version 0.1.0\nlevel walk\nL mode flag\nL seed 5\nL flag Wrf\nL cues sound poles\n'
  printf 'L sound all\nend\n'
  awk 'BEGIN { for (i = 0; i <= 5400; i++) { t = i / 90
      printf "%.4f f=9 h=%.3f,1.6,%.3f,0,%.4f,0,%.4f\n", t, 1.5 + 0.9 * sin(t * 0.3),
          1.5 + 0.9 * sin(t * 0.21), sin(t * 0.2), cos(t * 0.2) } }'; } >"$T/walk.rec"
cpu() { # CMD...: user + system CPU seconds
    /usr/bin/time -f '%U %S' -o "$T/time" "$@" >/dev/null 2>&1
    awk '{ printf "%.2f", $1 + $2 }' "$T/time"
}
if ! [ -x /usr/bin/time ]; then echo "bench_sound: no /usr/bin/time: skipped"; exit 0; fi
a=$(cpu "$H" replay "$T/walk.rec")
b=$(cpu "$H" replay "$T/walk.rec" --wav "$T/walk.wav")
if [ ! -s "$T/walk.wav" ]; then echo "bench_sound: no WAV (no libopenal.so.1?): skipped"; exit 0; fi
awk -v a="$a" -v b="$b" 'BEGIN { printf "sound: 60 s recording: replay %.2f s CPU, with --wav %.2f s, the sound %.2f s (target < 2 s)\n", a, b, b - a }'
