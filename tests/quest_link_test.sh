#!/bin/sh
# quest_link_test.sh - `make quest-link-check`: tests/quest_link_check.sh
# on the tree (it must pass), then on two copies of build_apk.sh each
# missing part of the sound, where it must fail (exit 1, one FAIL line
# naming what is undefined): the sound player (platform/audio/hol_audio.c)
# dropped from APK_SRC, and OpenAL Soft (-lopenal) dropped from APK_LIBS.
# The objects are compiled once (QUEST_LINK_OBJS) and the copies relink
# them: the copies differ only in their lists.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "quest-link-check: FAIL: $*" >&2; exit 1; }
mkdir "$tmp/objs"
export QUEST_LINK_OBJS="$tmp/objs"
sh "$root/tests/quest_link_check.sh"

# a copy of build_apk.sh with one sed edit; its root stays the tree's
variant() { # NAME SED
    sed -e "s|^root=.*|root='$root'|" -e "$2" "$root/platform/android/build_apk.sh" >"$tmp/$1.sh"
    cmp -s "$tmp/$1.sh" "$root/platform/android/build_apk.sh" && fail "variant $1 changed nothing"
    sh "$tmp/$1.sh" --link-list >"$tmp/$1.list"
}
# must_fail NAME WHAT: the check on the variant fails, its last line says
# FAIL, and the linker's lines name WHAT undefined
must_fail() {
    set +e
    QUEST_APK_SH="$tmp/$1.sh" sh "$root/tests/quest_link_check.sh" >"$tmp/$1.out" 2>"$tmp/$1.err"
    rc=$?
    set -e
    [ "$rc" = 1 ] || fail "without $1 the check exited $rc, not 1"
    tail -n 1 "$tmp/$1.err" | grep -q "^quest-link-check: FAIL: libholonomy.so does not link" ||
        fail "without $1 the check's last line is: $(tail -n 1 "$tmp/$1.err")"
    grep -q "undefined reference to \`$2" "$tmp/$1.err" ||
        fail "without $1 the link does not name $2 undefined: $(head -n 3 "$tmp/$1.err")"
    echo "quest-link-check: without $1: FAIL as it must ($2... undefined):"
    grep -m 1 "undefined reference to \`$2" "$tmp/$1.err" | sed 's/^ */  /'
    tail -n 1 "$tmp/$1.err" | sed 's/^/  /'
}
variant player 's|platform/audio/hol_audio\.c ||'
grep -q "hol_audio" "$tmp/player.list" && fail "the player variant still lists hol_audio.c"
must_fail player hol_audio_feed_
variant openal 's|^APK_LIBS="-lopenal |APK_LIBS="|'
grep -q -- "-lopenal" "$tmp/openal.list" && fail "the openal variant still names -lopenal"
must_fail openal alc
