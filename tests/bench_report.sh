#!/bin/sh
# bench_report.sh BINARY [N] - `holonomy report` on N attempts (default
# 10,000, the documented maximum) in one log folder: a replayed flag level
# (the optimal walk at Nf) copied N times, each attempt with its steps file
# and a picture; 20 conditions. Prints the wall and CPU seconds (make bench;
# docs/performance.md). Not a test: no pass or fail.
set -eu
H=$1 N=${2:-10000}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
{ printf 'holonomy-rec 3\nsession 20260131T140509Z-00000001\nparticipant P01\n'
  printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\nstudy s1\nlevel flag-a\n'
  printf 'condition map 1\nL mode flag\nL seed 5\nL flag Nf\nend\n'
  printf '%s f=9 h=%s,1.6,%s,0,0,0,1\n' 0 1.5 1.5 0.25 0.5 1.5 0.5 0.5 0.5 0.75 1.5 0.5 \
      1 1.5 1.5 1.25 2.5 1.5; } >"$T/a.rec"
"$H" replay "$T/a.rec" --log "$T/one" >/dev/null
mkdir "$T/logs"
cp "$T"/one/level-*.txt "$T/logs/"
awk -F, -v OFS=, -v n="$N" 'NR == 1 { print; next }
    { for (i = 1; i <= n; i++) { $5 = i; $7 = "c" (i % 20); print } }' \
    "$T/one/summary.csv" >"$T/logs/summary.csv"
awk -v n="$N" -v dir="$T/logs" 'NR == 1 { head = $0; next } { rows[NR] = $0; last = NR }
    END {
        for (i = 1; i <= n; i++) {
            f = sprintf("%s/steps-%03d.csv", dir, i)
            print head >f
            for (r = 2; r <= last; r++) { s = rows[r]; sub(/,1,/, "," i ",", s); print s >f }
            close(f)
        }
    }' "$T/one/steps-001.csv"
s=$(date +%s.%N)
/usr/bin/env time -f '%U %S' -o "$T/cpu" "$H" report "$T/logs" --out "$T/out" >/dev/null
e=$(date +%s.%N)
awk -v s="$s" -v e="$e" -v n="$N" -v cpu="$(cat "$T/cpu")" 'BEGIN {
    split(cpu, c, " ")
    printf "== report: %d attempts (pictures, 20 conditions): %.1f s wall, %.1f s CPU (%.1f user, %.1f system)\n",
        n, e - s, c[1] + c[2], c[1], c[2] }'
