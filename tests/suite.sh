#!/bin/sh
# suite.sh LOGDIR NAME CMD...: runs CMD as one suite of make test (timed by
# tests/timed.sh) with its output kept in LOGDIR/NAME.log, then prints
# "== NAME" and that output whole, so suites that make -j2 runs side by side
# never interleave their lines; exits with CMD's status.
# Every suite runs with HOME and the XDG folders in LOGDIR/home, so nothing a
# test starts (Mesa's shader cache, PulseAudio's cookie, dconf) writes into
# the machine's own home folder; Mesa's cache there is shared by the suites
# of one build folder.
dir=$1
name=$2
shift 2
# (Mesa does not make its cache folder's parents, and says so on stderr.)
mkdir -p "$dir/home/.cache/mesa" "$dir/home/.config" "$dir/home/.local/share" || exit 1
home=$(cd "$dir/home" && pwd) || exit 1
export HOME="$home" XDG_CACHE_HOME="$home/.cache" XDG_CONFIG_HOME="$home/.config" \
    XDG_DATA_HOME="$home/.local/share" MESA_SHADER_CACHE_DIR="$home/.cache/mesa"
log="$dir/$(printf '%s' "$name" | tr -c 'A-Za-z0-9_.-' '_').log"
sh "$(dirname "$0")/timed.sh" "$name" "$@" >"$log" 2>&1
st=$?
echo "== $name"
cat "$log"
exit "$st"
