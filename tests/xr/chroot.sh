#!/bin/sh
# tests/xr/chroot.sh: build, or reuse, the Debian trixie chroot in which
# `make xr-test` runs a real OpenXR runtime (Monado 25, null compositor,
# simulated headset and controllers, Khronos core validation layer).
#
#   sh tests/xr/chroot.sh            build it if absent; print its path
#   XR_CHROOT=DIR sh tests/xr/chroot.sh
#
# The chroot is cached at $XR_CHROOT (default /var/cache/holonomy/xr-trixie)
# between runs on one machine; a new machine builds it from nothing
# (debootstrap about 40 s, packages about 50 s, 1.4 GB). It is complete only
# when its stamp file holds the current package list, so an interrupted
# build is redone, never used, and a changed list is installed on top.
# Needs root and debootstrap (make deps-xr).
set -eu
CHROOT=${XR_CHROOT:-/var/cache/holonomy/xr-trixie}
MIRROR=${XR_MIRROR:-http://deb.debian.org/debian}
STAMP="$CHROOT/.holonomy-xr-ready"
PKGS="monado-service libopenxr1-monado libopenxr-loader1 libopenxr-dev
  openxr-layer-corevalidation mesa-vulkan-drivers libgl-dev libegl-dev
  libgles-dev libx11-dev libgl1-mesa-dri xvfb xauth gcc make libc6-dev
  zlib1g-dev libosmesa6-dev libhidapi-dev ca-certificates"

# The stamp records the package list it was completed with: the same list,
# nothing to do; another, only the packages are installed again.
want=$(echo $PKGS)
if [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$want" ]; then echo "$CHROOT"; exit 0; fi
if [ "$(id -u)" != 0 ]; then
    echo "tests/xr/chroot.sh: needs root (debootstrap, chroot)" >&2; exit 1
fi
if [ ! -f "$CHROOT/.holonomy-debootstrap-done" ]; then
    command -v debootstrap >/dev/null 2>&1 || {
        echo "tests/xr/chroot.sh: debootstrap not installed (make deps-xr)" >&2; exit 1; }
    # A half-built chroot from an interrupted run: unmount what it bound, start over.
    for m in proc dev/pts dev; do umount "$CHROOT/$m" 2>/dev/null || true; done
    rm -rf "$CHROOT"
    mkdir -p "$(dirname "$CHROOT")"
    debootstrap --variant=minbase trixie "$CHROOT" "$MIRROR" >"$CHROOT.log" 2>&1 || {
        echo "tests/xr/chroot.sh: debootstrap failed; see $CHROOT.log" >&2; exit 1; }
    touch "$CHROOT/.holonomy-debootstrap-done"
fi
rm -f "$STAMP"
mount --bind /proc "$CHROOT/proc"
mount --bind /dev "$CHROOT/dev"
trap 'umount "$CHROOT/dev" "$CHROOT/proc" 2>/dev/null || true' EXIT
chroot "$CHROOT" env DEBIAN_FRONTEND=noninteractive apt-get update >>"$CHROOT.log" 2>&1
# shellcheck disable=SC2086
chroot "$CHROOT" env DEBIAN_FRONTEND=noninteractive apt-get install -y \
    --no-install-recommends $PKGS >>"$CHROOT.log" 2>&1 || {
    echo "tests/xr/chroot.sh: apt-get install in the chroot failed; see $CHROOT.log" >&2; exit 1; }
chroot "$CHROOT" apt-get clean
echo "$want" >"$STAMP"
echo "$CHROOT"
