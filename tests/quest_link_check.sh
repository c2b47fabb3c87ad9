#!/bin/sh
# quest_link_check.sh - `make quest-link-check`: the Quest APK's native
# library as far as this machine can build it, with no NDK and no stand-in
# headers. Every source that platform/android/build_apk.sh links into
# libholonomy.so (its APK_SRC, from `build_apk.sh --link-list`; all but the
# NDK's native_app_glue and the NativeActivity entry that needs its header)
# is compiled for this machine with the Android branches on (__ANDROID__, as
# the NDK's compiler defines it), against Debian's copies of the NDK's
# headers: EGL, JNI (android-libnativehelper-dev), android/log.h
# (android-liblog-dev), OpenXR (libopenxr-dev) and OpenAL (libopenal-dev:
# OpenAL Soft 1.19.1, the version build_apk.sh builds for the APK). Then
# the objects are linked into a shared library with --no-undefined against
# exactly the libraries build_apk.sh names (APK_LIBS and the OpenXR
# loader), Debian's builds of each: a library missing from build_apk.sh
# leaves a symbol undefined and fails here (the sound player dropped from
# APK_SRC leaves quest_shell.c's calls undefined; -lopenal dropped, the
# player's). With --as-needed, every named library must also be needed (a
# stale one fails too), and the sound is linked, not loaded: OpenAL's
# alcOpenDevice is an undefined symbol of the library, from libopenal.
# For tests/quest_link_neg.sh: QUEST_APK_SH, the build_apk.sh to read the
# lists from (default the tree's); QUEST_LINK_OBJS, a folder keeping the
# objects from run to run (the same tree only).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
apk_sh=${QUEST_APK_SH:-$root/platform/android/build_apk.sh}
CC=${CC:-gcc}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "quest-link-check: FAIL: $*" >&2; exit 1; }

list=$(sh "$apk_sh" --link-list) || fail "build_apk.sh --link-list"
srcs=$(echo "$list" | sed -n 's/^src //p')
libs=$(echo "$list" | sed -n 's/^libs //p')
gen=$(echo "$list" | sed -n 's/^gen //p')
[ -n "$srcs" ] && [ -n "$libs" ] || fail "build_apk.sh --link-list printed no sources or libraries"
# the shaders as C (render/hol_program.c includes hol_glsl.h), as build_apk.sh makes them
[ -n "$gen" ] || fail "build_apk.sh --link-list names no generator of the shaders' C"
sh "$root/$gen" "$tmp/gen/hol_glsl.h" || fail "$gen"
# the build's commit and date (platform/shell/hol_shell_build.h), as build_apk.sh makes them
(cd "$root" && sh platform/shell/build_id.sh "$tmp/gen/hol_build_id.h") || fail "build_id.sh"

# Debian's builds of the named libraries (liblog lives in its own folder)
ma=$($CC -print-multiarch)
hostlibs=""
for l in $libs; do
    case "$l" in
    -llog) hostlibs="$hostlibs -L/usr/lib/$ma/android -llog" ;;
    -l*) hostlibs="$hostlibs $l" ;;
    *) fail "build_apk.sh names '$l', not a -l library" ;;
    esac
done
for h in /usr/include/android/android/log.h /usr/include/android/nativehelper/jni.h \
         /usr/include/EGL/egl.h /usr/include/openxr/openxr_platform.h /usr/include/AL/alc.h; do
    [ -f "$h" ] || fail "$h missing (make deps-quest-link)"
done

flags="-std=c11 -O2 -g -fPIC -D_DEFAULT_SOURCE -DHOL_GLES=1 -D__ANDROID__
  -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wvla
  -isystem /usr/include/android -isystem /usr/include/android/nativehelper -I$root -I$tmp/gen"
n=0
objs=""
# objects in QUEST_LINK_OBJS when given (kept and reused: a source whose
# object is there is not compiled again), else in the scratch folder
odir=${QUEST_LINK_OBJS:-$tmp}
reuse=${QUEST_LINK_OBJS:+1}
for f in $srcs; do
    objs="$objs $odir/$(echo "$f" | tr / _).o"
    n=$((n + 1))
done
# two compilers at once (QUEST_LINK_JOBS; CI's two cores); the first source
# that does not compile stops the rest (xargs stops at a status of 255)
export CC flags root odir reuse
# shellcheck disable=SC2016
printf '%s\n' $srcs | xargs -P "${QUEST_LINK_JOBS:-2}" -n 1 sh -c '
    o="$odir/$(echo "$1" | tr / _).o"
    [ -n "$reuse" ] && [ -f "$o" ] && exit 0
    # shellcheck disable=SC2086
    $CC $flags -c "$root/$1" -o "$o" && exit 0
    echo "quest-link-check: FAIL: $1 does not compile with __ANDROID__" >&2
    exit 255' sh || exit 1
# shellcheck disable=SC2086
$CC -shared -Wl,--no-undefined -Wl,--as-needed -o "$tmp/libholonomy.so" $objs $hostlibs \
    2>"$tmp/link.err" || {
    sed 's/^/  /' "$tmp/link.err" | grep -v "^  collect2" | head -20 >&2
    fail "libholonomy.so does not link with --no-undefined against $libs (build_apk.sh)"
}
# every named library is needed (--as-needed keeps only those)
needed=$(readelf -d "$tmp/libholonomy.so" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
for l in $libs; do
    name=${l#-l}
    echo "$needed" | grep -q "^lib$name\.so" ||
        fail "build_apk.sh links $l, which nothing in the library needs"
done
# the entry android_main.c calls is there
nm -D --defined-only "$tmp/libholonomy.so" | grep -q " T quest_run$" || fail "no quest_run"
# the sound: OpenAL linked (not loaded at run time), from libopenal
nm -D --undefined-only "$tmp/libholonomy.so" | grep -q " U alcOpenDevice$" &&
    echo "$needed" | grep -q "^libopenal\.so" ||
    fail "libholonomy.so does not link OpenAL (alcOpenDevice from libopenal): no sound on the Quest"
echo "quest-link-check: $n sources compiled with __ANDROID__; libholonomy.so linked with" \
     "--no-undefined against $libs (Debian's); needs" $(echo "$needed" | tr '\n' ' ')
