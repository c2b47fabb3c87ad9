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
#   Debian's aapt, zipalign, apksigner, android-framework-res and cmake
#                       (`make deps-quest`)
#   OpenAL Soft 1.19.1 (the sound): built here for arm64-v8a with the NDK's
#                       CMake toolchain, its OpenSL ES backend, from
#                       Debian's source tarball openal-soft_1.19.1.orig.tar.gz
#                       (sha256-pinned): OPENAL_SOURCE=FILE, else fetched
#                       from deb.debian.org with curl
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
APK_SRC="core/*.c render/*.c platform/shell/*.c platform/openxr/*.c platform/file/hol_sink_posix.c
  platform/audio/hol_audio.c platform/android/quest_shell.c"
# render/hol_program.c includes hol_glsl.h, the shaders as C strings that
# this script makes (render/shaders/glsl_c.sh) in a folder it adds to -I
APK_GEN="render/shaders/glsl_c.sh"
# with the OpenXR loader; zlib: render/hol_png.c; openal: OpenAL Soft
# (platform/audio/hol_audio.c links it on Android; built below, packed)
APK_LIBS="-lopenal -llog -lEGL -lz -lm"
NDK_SRC="platform/android/android_main.c"
NDK_LIBS="-landroid"

# OpenAL Soft for the APK, pinned: Debian bookworm's source tarball (its
# .dsc's Checksums-Sha256), the version Debian's libopenal-dev has, which
# `make quest-link-check` links against. Only the library: no utilities,
# examples or tests; OpenSL ES required (Android's output; 1.19.1 has no
# AAudio or Oboe backend); the default HRTF data embedded. 1.19.1 defines
# some tables in headers (FuMa2N3DScale, ...): compilers that default to
# -fno-common (GCC 10+, clang 11+, so every NDK this script accepts) fail
# its link with "multiple definition" unless CFLAGS has -fcommon
# (OPENAL_CFLAGS; CMake adds the environment's CFLAGS to the toolchain's).
OPENAL_VERSION=1.19.1
OPENAL_TARBALL=openal-soft_$OPENAL_VERSION.orig.tar.gz
OPENAL_SHA256=9f3536ab2bb7781dbafabc6a61e0b34b17edd16bd6c2eaf2ae71bc63078f98c7
OPENAL_URL=http://deb.debian.org/debian/pool/main/o/openal-soft/$OPENAL_TARBALL
OPENAL_OPTIONS="-DCMAKE_BUILD_TYPE=Release -DLIBTYPE=SHARED -DALSOFT_UTILS=OFF
  -DALSOFT_NO_CONFIG_UTIL=ON -DALSOFT_EXAMPLES=OFF -DALSOFT_TESTS=OFF -DALSOFT_CONFIG=OFF
  -DALSOFT_HRTF_DEFS=OFF -DALSOFT_AMBDEC_PRESETS=OFF -DALSOFT_INSTALL=OFF
  -DALSOFT_EMBED_HRTF_DATA=ON -DALSOFT_REQUIRE_OPENSL=ON"
OPENAL_CFLAGS="-fcommon"

case "${1:-}" in
-h|--help)
    sed -n '2,25p' "$0" | sed 's/^# \{0,1\}//'
    exit 0 ;;
--link-list)
    # for tests/quest_link_check.sh: the sources (relative to the top of the
    # tree) and the libraries, the OpenXR loader first
    (cd "$root" && echo "src" $APK_SRC)
    echo "gen $APK_GEN"
    echo "libs -lopenxr_loader $APK_LIBS"
    exit 0 ;;
--openal)
    # the pinned OpenAL Soft and its CMake options (docs/sound.md)
    echo "version $OPENAL_VERSION"
    echo "tarball $OPENAL_TARBALL $OPENAL_SHA256 $OPENAL_URL"
    echo "options" $OPENAL_OPTIONS
    echo "cflags $OPENAL_CFLAGS"
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
for t in aapt zipalign apksigner keytool cmake sha256sum; do
    command -v "$t" >/dev/null 2>&1 || missing="$missing $t"
done
[ -f "$FRAMEWORK_RES" ] || missing="$missing android-framework-res"
if [ -n "${OPENAL_SOURCE:-}" ]; then
    [ -f "$OPENAL_SOURCE" ] || missing="$missing OPENAL_SOURCE=<$OPENAL_TARBALL; '$OPENAL_SOURCE' does not exist>"
else
    command -v curl >/dev/null 2>&1 || missing="$missing curl"
fi
if [ -n "$missing" ]; then
    echo "make quest: needs$missing (Debian: apt-get install aapt zipalign apksigner android-framework-res cmake curl; see README 'Quest build')" >&2
    exit 2
fi

stage="$BUILD/quest"
rm -rf "$stage"
mkdir -p "$stage/apk/lib/arm64-v8a"

# OpenAL Soft: the pinned tarball (given, or fetched), checked, built with
# the NDK's CMake toolchain for the APK's ABI and API level.
oal="$stage/openal"
mkdir -p "$oal/src"
if [ -n "${OPENAL_SOURCE:-}" ]; then
    cp "$OPENAL_SOURCE" "$oal/$OPENAL_TARBALL"
else
    curl -fsSL -o "$oal/$OPENAL_TARBALL" "$OPENAL_URL" || {
        echo "make quest: cannot fetch $OPENAL_URL; give it as OPENAL_SOURCE=FILE" >&2
        exit 1
    }
fi
echo "$OPENAL_SHA256  $oal/$OPENAL_TARBALL" | sha256sum -c --status || {
    echo "make quest: $OPENAL_TARBALL is not the pinned one (sha256 $OPENAL_SHA256)" >&2
    exit 1
}
tar -xzf "$oal/$OPENAL_TARBALL" -C "$oal/src" --strip-components=1
# shellcheck disable=SC2086
CFLAGS="$OPENAL_CFLAGS" cmake -S "$oal/src" -B "$oal/build" -DCMAKE_TOOLCHAIN_FILE="$NDK/build/cmake/android.toolchain.cmake" \
    -DANDROID_ABI=arm64-v8a -DANDROID_PLATFORM=android-$API \
    -DCMAKE_SHARED_LINKER_FLAGS="-Wl,-z,max-page-size=16384" $OPENAL_OPTIONS >"$oal/cmake.log"
cmake --build "$oal/build" --target OpenAL -j 2 >"$oal/build.log"
[ -f "$oal/build/libopenal.so" ] || {
    echo "make quest: OpenAL Soft built no libopenal.so (see $oal/build.log)" >&2
    exit 1
}

# The native library: core (with the session), renderer, OpenXR layer (GLES
# binding), the session's POSIX sink (logs and recordings in the app's files
# directory), the sound player (against OpenAL Soft, just built), the Quest
# shell (all compiled and linked for this machine by `make
# quest-link-check`) and the NativeActivity entry with the NDK's glue.
glue="$NDK/sources/android/native_app_glue"
sh "$root/$APK_GEN" "$stage/gen/hol_glsl.h"
# the build's commit and date (platform/shell/hol_shell_build.h: provenance.csv)
(cd "$root" && sh platform/shell/build_id.sh "$stage/gen/hol_build_id.h")
srcs=$(cd "$root" && ls $APK_SRC $NDK_SRC | sed "s|^|$root/|")
# -ffp-contract=off: no fused multiply-add where the desktop has none, so
# the core's results (and a recording's replay) are the same bits as on the
# desktop and the web (README: "The same results on every platform").
# shellcheck disable=SC2086
"$cc" -std=c11 -O2 -g -ffp-contract=off -fPIC -shared -D_DEFAULT_SOURCE -DHOL_GLES=1 \
    -I"$OPENXR_INCLUDE" -I"$root" -I"$stage/gen" -I"$glue" -I"$oal/src/include" -L"$oal/build" \
    -Wl,--no-undefined -Wl,-z,max-page-size=16384 -u ANativeActivity_onCreate \
    -o "$stage/apk/lib/arm64-v8a/libholonomy.so" $srcs "$glue"/android_native_app_glue.c \
    "$OPENXR_LOADER" $NDK_LIBS $APK_LIBS
cp "$OPENXR_LOADER" "$stage/apk/lib/arm64-v8a/libopenxr_loader.so"
cp "$oal/build/libopenal.so" "$stage/apk/lib/arm64-v8a/libopenal.so"

aapt package -f -M "$here/AndroidManifest.xml" -I "$FRAMEWORK_RES" \
    -F "$stage/unaligned.apk"
(cd "$stage/apk" && aapt add -0 so ../unaligned.apk lib/arm64-v8a/libholonomy.so \
    lib/arm64-v8a/libopenxr_loader.so lib/arm64-v8a/libopenal.so >/dev/null)
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
