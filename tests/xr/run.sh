#!/bin/sh
# tests/xr/run.sh - `make xr-test`: the headset layer against a real OpenXR
# runtime. Builds (or reuses) the Debian trixie chroot with Monado
# (tests/xr/chroot.sh), copies the source tree into it, builds
# `holonomy` with XR=1 (and the test's API layer, tests/xr/inject_layer.c)
# there with the chroot's compiler, and runs
# tests/xr/inside.sh (Xvfb, monado-service, holonomy xr under the core
# validation layer, the checks). Binds /proc and /dev for the run and always
# unbinds them. Needs root.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
# One run at a time on a machine: the chroot's /src and /tmp/xr-test are
# shared by every checkout (flock waits for another run to finish).
# -o: the run's children (Xvfb, monado-service) do not inherit the lock, so
# one left behind by a killed run cannot hold it for ever; only flock does.
if [ -z "${HOL_XR_LOCKED:-}" ] && command -v flock >/dev/null 2>&1; then
    mkdir -p /var/cache/holonomy
    lock=/var/cache/holonomy/xr-test.lock
    flock -n -o "$lock" true || echo "xr-test: another xr-test holds $lock: waiting for it"
    HOL_XR_LOCKED=1 exec flock -o "$lock" sh "$0" "$@"
fi
start=$(date +%s)
CHROOT=$(sh "$root/tests/xr/chroot.sh")
echo "xr-test: chroot ready at $CHROOT ($(( $(date +%s) - start )) s)"
cleanup() {
    umount "$CHROOT/dev" 2>/dev/null || true
    umount "$CHROOT/proc" 2>/dev/null || true
}
trap cleanup EXIT
mountpoint -q "$CHROOT/proc" || mount --bind /proc "$CHROOT/proc"
mountpoint -q "$CHROOT/dev" || mount --bind /dev "$CHROOT/dev"
rm -rf "$CHROOT/src"
mkdir -p "$CHROOT/src"
(cd "$root" && git ls-files -z --cached --others --exclude-standard | xargs -0 tar -cf - 2>/dev/null) | tar -C "$CHROOT/src" -xf -
chroot "$CHROOT" sh -c 'cd /src && make -s -j2 BUILD=build/xr XR=1 build/xr/holonomy' || {
    echo "xr-test: FAIL: building holonomy with XR=1 in the chroot" >&2; exit 1; }
# the test's API layer (tests/xr/inject_layer.c; trixie's loader headers)
chroot "$CHROOT" sh -c 'cd /src && cc -std=c11 -O2 -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -shared -fPIC -o build/xr/libhol_inject_layer.so tests/xr/inject_layer.c' || {
    echo "xr-test: FAIL: building the test's API layer in the chroot" >&2; exit 1; }
echo "xr-test: built in the chroot ($(( $(date +%s) - start )) s)"
rc=0
# every check's line is kept too, so the end can repeat the failed ones
# (CI shows only the last lines of a long run)
log=${OUT:-$root/build/xr-test}/checks.txt
mkdir -p "$(dirname "$log")" && : >"$log" && rm -f "$log.rc"
done_in() {
    grep "^xr-test: FAIL" "$log" | sed 's/^xr-test: FAIL/xr-test: failed earlier/'
    [ ! -e "$log.rc" ] || echo "xr-test: failed earlier: $(tr '\n' ' ' <"$log.rc")exited non-zero (tests/xr/inside.sh, lighting.sh)"
    echo "xr-test: done in $(( $(date +%s) - start )) s, $(grep -c '^xr-test: ok' "$log") checks passed, $(grep -c '^xr-test: FAIL' "$log") failed"
}
{ chroot "$CHROOT" env XR_ONLY="${XR_ONLY:-}" sh -c 'cd /src && timeout 600 sh tests/xr/inside.sh build/xr/holonomy' || echo inside >>"$log.rc"; } | tee -a "$log"
# the lit eyes, measured here and kept in the build folder (tests/xr/lighting.sh)
{ sh "$root/tests/xr/lighting.sh" "$CHROOT/tmp/xr-test/light" "${OUT:-$root/build/xr-test}/lighting" || echo lighting >>"$log.rc"; } | tee -a "$log"
if grep -q "^xr-test: FAIL" "$log" || [ -e "$log.rc" ]; then rc=1; fi
if [ "${XR_ONLY:-}" = lighting ]; then done_in; exit $rc; fi
# The host's half: the eye read back from the swapchain in the chroot
# against the host build's `holonomy render` of the same eye pose (another
# process, another Mesa, the CLI's pose arguments), within png_diff's
# tolerance (tests/xr/png_diff.c: the render goldens').
out="$CHROOT/tmp/xr-test"
args=$(sed -n 's/^xr: check eye 0 render //p' "$out/xr.out")
walk=$(awk -F, 'NR > 1 { printf "%s", $8 }' "$out/logs/steps-001.csv" 2>/dev/null)
seed=$(sed -n 's/^seed //p' "$out/level.txt")
if [ -n "$args" ] && [ -n "${HOLONOMY:-}" ] && [ -n "${PNG_DIFF:-}" ] &&
   # shellcheck disable=SC2086
   "$HOLONOMY" render --walk "${walk:--}" --seed "$seed" $args --out "$out/check/host-eye0.png" &&
   d=$("$PNG_DIFF" "$out/check/xr-eye0.png" "$out/check/host-eye0.png"); then
    echo "xr-test: ok: swapchain read back equals the host's holonomy render --walk ${walk:--} (same eye): $d" | tee -a "$log"
else
    echo "xr-test: FAIL: swapchain read back against the host's holonomy render: ${d:-no comparison}" | tee -a "$log"
    rc=1
fi
done_in
exit $rc
