#!/bin/sh
# check_quest.sh - what CI can check of the Quest build without the NDK:
# 1. the manifest packages with Debian's aapt against the Android framework
#    resources, and the package says what the Quest needs (badging) and
#    what the Khronos loader needs to find the runtime (the broker
#    providers, the runtime and layer services in <queries>);
# 2. `make quest` without NDK/OPENXR_LOADER stops with exit status 2 and
#    one line naming both.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "check_quest: FAIL: $*" >&2; exit 1; }

aapt package -f -M "$here/platform/android/AndroidManifest.xml" \
    -I /usr/share/android-framework-res/framework-res.apk -F "$tmp/m.apk" ||
    fail "aapt cannot package the manifest"
aapt dump badging "$tmp/m.apk" >"$tmp/badging"
want() { grep -q "$1" "$tmp/badging" || fail "badging lacks: $1"; }
want "package: name='org.holonomy.app'"
want "sdkVersion:'29'"
want "targetSdkVersion:'32'"
want "uses-feature: name='android.hardware.vr.headtracking'"
want "uses-gl-es: '0x30002'"
want "uses-permission: name='org.khronos.openxr.permission.OPENXR'"
want "uses-permission: name='org.khronos.openxr.permission.OPENXR_SYSTEM'"
want "launchable-activity: name='android.app.NativeActivity'"
aapt dump xmltree "$tmp/m.apk" AndroidManifest.xml >"$tmp/tree"
for s in com.oculus.intent.category.VR org.khronos.openxr.intent.category.IMMERSIVE_HMD \
         org.khronos.openxr.OpenXRRuntimeService org.khronos.openxr.OpenXRApiLayerService \
         "org.khronos.openxr.runtime_broker;org.khronos.openxr.system_runtime_broker" \
         com.oculus.vr.focusaware android.app.lib_name; do
    grep -q "$s" "$tmp/tree" || fail "manifest tree lacks $s"
done
grep -q '"holonomy"' "$tmp/tree" || fail "lib_name is not holonomy"

# make quest without the NDK: exit 2, one line naming what it needs.
set +e
env -u NDK -u OPENXR_LOADER -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make -s --no-print-directory -C "$here" quest BUILD="$tmp/build" >"$tmp/out" 2>"$tmp/err"
rc=$?
set -e
[ "$rc" = 2 ] || fail "make quest without NDK exited $rc, not 2"
grep -v '^make\(\[[0-9]*\]\)\{0,1\}: \*\*\*' "$tmp/err" >"$tmp/err1" || true
[ "$(wc -l <"$tmp/err1")" = 1 ] || fail "make quest printed $(wc -l <"$tmp/err1") lines, not 1"
grep -q 'NDK=' "$tmp/err1" && grep -q 'OPENXR_LOADER=' "$tmp/err1" ||
    fail "make quest does not name NDK= and OPENXR_LOADER=: $(cat "$tmp/err1")"
[ ! -e "$tmp/build/holonomy.apk" ] || fail "make quest left an APK behind"
echo "check_quest: manifest packaged by aapt; make quest without NDK: exit 2, one line"
