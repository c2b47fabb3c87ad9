#!/bin/sh
# timed.sh NAME CMD...: runs CMD and then prints "-- NAME: S.S s, cpu C.C s"
# (how make test shows each suite's time: wall time, then the CPU time, user +
# system, of CMD and all its children, which a loaded machine does not
# inflate); exits with CMD's status.
name=$1
shift
start=$(date +%s%N)
"$@"
st=$?
ms=$((($(date +%s%N) - start) / 1000000))
# `times` prints the shell's user and system times, then its children's
# ("1m2.345s 0m0.100s"); the children's line is the suite's CPU time.
# It must run in this shell (not in a pipe or $(...), whose fork has no
# children yet), so it goes through a scratch file.
tf=$(mktemp) || exit 1
times >"$tf"
cpu=$(awk 'NR == 2 {
  t = 0
  for (i = 1; i <= 2; i++) { split($i, a, "m"); sub("s", "", a[2]); t += a[1] * 60 + a[2] }
  printf "%.1f", t }' "$tf")
rm -f "$tf"
if [ "$st" = 0 ]; then note=""; else note=" (failed, status $st)"; fi
printf -- '-- %s: %d.%d s, cpu %s s%s\n' "$name" $((ms / 1000)) $((ms % 1000 / 100)) "${cpu:-?}" "$note"
exit "$st"
