#!/bin/sh
# suite.sh LOGDIR NAME CMD...: runs CMD as one suite of make test (timed by
# tests/timed.sh) with its output kept in LOGDIR/NAME.log, then prints
# "== NAME" and that output whole, so suites that make -j2 runs side by side
# never interleave their lines; exits with CMD's status.
dir=$1
name=$2
shift 2
mkdir -p "$dir" || exit 1
log="$dir/$(printf '%s' "$name" | tr -c 'A-Za-z0-9_.-' '_').log"
sh "$(dirname "$0")/timed.sh" "$name" "$@" >"$log" 2>&1
st=$?
echo "== $name"
cat "$log"
exit "$st"
