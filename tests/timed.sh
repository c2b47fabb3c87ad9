#!/bin/sh
# timed.sh NAME CMD...: runs CMD and then prints "-- NAME: S.S s" (how make
# test shows each suite's time); exits with CMD's status.
name=$1
shift
start=$(date +%s%N)
"$@"
st=$?
ms=$((($(date +%s%N) - start) / 1000000))
if [ "$st" = 0 ]; then note=""; else note=" (failed, status $st)"; fi
printf -- '-- %s: %d.%d s%s\n' "$name" $((ms / 1000)) $((ms % 1000 / 100)) "$note"
exit "$st"
