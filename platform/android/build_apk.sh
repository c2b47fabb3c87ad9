#!/bin/sh
# build_apk.sh - `make quest`: the sideloadable Quest APK (arm64-v8a,
# NativeActivity, no Java code).
#
# Needs (all named in one line, exit 2, when missing):
#   NDK=DIR             the Android NDK (r23 or later): its clang for
#                       aarch64-linux-android29, sysroot with bionic, EGL,
#                       GLESv3, android and log libraries
#   OPENXR_LOADER=FILE  libopenxr_loader.so for arm64-v8a, from the Khronos
#                       OpenXR loader for Android (Maven
#                       org.khronos.openxr:openxr_loader_for_android, the
#                       .aar's prebuiltLibs/android.arm64-v8a/)
#   Debian's aapt, zipalign, apksigner and android-framework-res
#                       (`make deps-quest`)
# Optional: OPENXR_INCLUDE (default /usr/include, Debian's libopenxr-dev
# headers), KEYSTORE (default: a debug key made with keytool under
# BUILD/quest), OUT (default BUILD/holonomy.apk), BUILD (default build).
#
# The APK is assembled under BUILD/quest and renamed into OUT only when it
# is complete, aligned and signed: no half-written APK is ever left at OUT.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)

# What libholonomy.so is made of, named once. APK_SRC and APK_LIBS are
# what `make quest-link-check` compiles and links for this machine
# (--link-list prints them); NDK_SRC and NDK_LIBS only the NDK can build:
# the NativeActivity entry needs the NDK's native_app_glue header, and the
# glue and the entry are the only users of libandroid (ALooper, AInputQueue,
# AConfiguration, ANativeActivity_finish).
APK_SRC="core/*.c render/*.c platform/openxr/*.c platform/file/hol_sink_posix.c
  platform/android/quest_shell.c"
APK_LIBS="-llog -lEGL -lz -lm" # with the OpenXR loader; zlib: render/hol_png.c
NDK_SRC="platform/android/android_main.c"
NDK_LIBS="-landroid"

case "${1:-}" in
-h|--help)
    sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'
    exit 0 ;;
--link-list)
    # for tests/quest_link_check.sh: the sources (relative to the top of the
    # tree) and the libraries, the OpenXR loader first
    (cd "$root" && echo "src" $APK_SRC)
    echo "libs -lopenxr_loader $APK_LIBS"
    exit 0 ;;
"") ;;
*)
    echo "make quest: unknown argument '$1'; see 'make quest-help'" >&2
    exit 2 ;;
esac

BUILD=${BUILD:-build}
OUT=${OUT:-$BUILD/holonomy.apk}
OPENXR_INCLUDE=${OPENXR_INCLUDE:-/usr/include}
FRAMEWORK_RES=${FRAMEWORK_RES:-/usr/share/android-framework-res/framework-res.apk}
API=29

missing=""
cc=""
if [ -z "${NDK:-}" ]; then
    missing="$missing NDK=<Android NDK r23+ directory>"
else
    cc=$(ls "$NDK"/toolchains/llvm/prebuilt/*/bin/aarch64-linux-android$API-clang 2>/dev/null | head -n 1 || true)
    [ -n "$cc" ] || missing="$missing NDK=<Android NDK r23+ directory; '$NDK' has no aarch64-linux-android$API-clang>"
fi
if [ -z "${OPENXR_LOADER:-}" ]; then
    missing="$missing OPENXR_LOADER=<libopenxr_loader.so for arm64-v8a>"
elif [ ! -f "$OPENXR_LOADER" ]; then
    missing="$missing OPENXR_LOADER=<libopenxr_loader.so for arm64-v8a; '$OPENXR_LOADER' does not exist>"
fi
[ -f "$OPENXR_INCLUDE/openxr/openxr.h" ] || missing="$missing OPENXR_INCLUDE=<directory with openxr/openxr.h>"
for t in aapt zipalign apksigner keytool; do
    command -v "$t" >/dev/null 2>&1 || missing="$missing $t"
done
[ -f "$FRAMEWORK_RES" ] || missing="$missing android-framework-res"
if [ -n "$missing" ]; then
    echo "make quest: needs$missing (Debian: apt-get install aapt zipalign apksigner android-framework-res; see README 'Quest build')" >&2
    exit 2
fi

stage="$BUILD/quest"
rm -rf "$stage"
mkdir -p "$stage/apk/lib/arm64-v8a"

# The native library: core (with the session), renderer, OpenXR layer (GLES
# binding), the session's POSIX sink (logs and recordings in the app's files
# directory), the Quest shell (all compiled and linked for this machine by
# `make quest-link-check`) and the NativeActivity entry with the NDK's glue.
glue="$NDK/sources/android/native_app_glue"
srcs=$(cd "$root" && ls $APK_SRC $NDK_SRC | sed "s|^|$root/|")
# -ffp-contract=off: no fused multiply-add where the desktop has none, so
# the core's results (and a recording's replay) are the same bits as on the
# desktop and the web (README: "The same results on every platform").
# shellcheck disable=SC2086
"$cc" -std=c11 -O2 -g -ffp-contract=off -fPIC -shared -D_DEFAULT_SOURCE -DHOL_GLES=1 \
    -I"$OPENXR_INCLUDE" -I"$root" -I"$glue" \
    -Wl,--no-undefined -Wl,-z,max-page-size=16384 -u ANativeActivity_onCreate \
    -o "$stage/apk/lib/arm64-v8a/libholonomy.so" $srcs "$glue"/android_native_app_glue.c \
    "$OPENXR_LOADER" $NDK_LIBS $APK_LIBS
cp "$OPENXR_LOADER" "$stage/apk/lib/arm64-v8a/libopenxr_loader.so"

aapt package -f -M "$here/AndroidManifest.xml" -I "$FRAMEWORK_RES" \
    -F "$stage/unaligned.apk"
(cd "$stage/apk" && aapt add -0 so ../unaligned.apk lib/arm64-v8a/libholonomy.so \
    lib/arm64-v8a/libopenxr_loader.so >/dev/null)
zipalign -f -p 4 "$stage/unaligned.apk" "$stage/aligned.apk"

key=${KEYSTORE:-$stage/debug.keystore}
if [ ! -f "$key" ]; then
    keytool -genkeypair -keystore "$key" -storepass android -keypass android \
        -alias holonomy -keyalg RSA -keysize 2048 -validity 10000 \
        -dname "CN=Holonomy debug" >/dev/null 2>&1
fi
apksigner sign --ks "$key" --ks-pass pass:android --key-pass pass:android \
    --out "$stage/signed.apk" "$stage/aligned.apk"
apksigner verify "$stage/signed.apk"
mv -f "$stage/signed.apk" "$OUT"
echo "make quest: wrote $OUT"
