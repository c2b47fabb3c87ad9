#!/bin/sh
# apt_get.sh WAIT ARGS... - apt-get ARGS, waiting up to WAIT seconds for
# another apt or dpkg to finish (make deps and the other deps targets).
# apt-get's DPkg::Lock::Timeout waits for dpkg's lock only: `apt-get update`
# fails at once ("Could not get lock /var/lib/apt/lists/lock") while
# another apt holds its lists, and so does an install holding the archives'
# lock. So: while apt-get fails for a lock, say so once and try again every
# 2 seconds until WAIT seconds have passed; any other failure is final.
# APT_GET_CMD names the program (default apt-get; the tests give a fake),
# APT_GET_PAUSE the seconds between tries (default 2; the tests' 0.1).
set -u
wait=${1:?usage: apt_get.sh WAIT ARGS...}
shift
cmd=${APT_GET_CMD:-apt-get}
pause=${APT_GET_PAUSE:-2}
out=$(mktemp) || exit 1
trap 'rm -f "$out"' EXIT
start=$(date +%s) told=0
while :; do
    "$cmd" -o DPkg::Lock::Timeout="$wait" "$@" >"$out" 2>&1
    st=$?
    if [ "$st" = 0 ] || ! grep -q -e 'Could not get lock' -e 'Unable to lock' -e 'Unable to acquire' "$out" ||
        [ $(($(date +%s) - start)) -ge "$wait" ]; then
        cat "$out"
        exit "$st"
    fi
    if [ "$told" = 0 ]; then
        echo "apt-get $1: another apt holds its lock; waiting up to $wait s"
        told=1
    fi
    sleep "$pause"
done
