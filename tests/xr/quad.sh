#!/bin/sh
# tests/xr/quad.sh - the world panel as an OpenXR quad layer (issue 25),
# run by tests/xr/inside.sh while monado-service runs (Xvfb :77,
# XDG_RUNTIME_DIR set). Monado's null compositor shows nothing and its
# composited picture cannot be read back, so the checks are: the run is
# clean under the core validation layer; the quad layer reaches the
# runtime as submitted (the test's API layer, tests/xr/inject_layer.c,
# prints the layers of one xrEndFrame): after the projection layer, both
# eyes, the panel's size and a pose up to 1.5 m ahead (nearer scenery); the eyes' own swapchains
# no longer contain the panel (the check frame drawn with and without the
# HUD is the same); the quad's image holds the panel (read back); it is
# drawn again only when the panel's content changes; and where the quad's
# swapchain cannot be made (the layer fails it) the run goes on with the
# panel in the scene; and with a trunk nearer than the panel can come, the
# panel in the scene for those frames. Prints one line per check; exit 0
# when all pass.
set -u
BIN=${1:-build/xr/holonomy}
LAYER=${2:-build/xr/libhol_inject_layer.so}
out=/tmp/xr-test/quad
rm -rf "$out" && mkdir -p "$out/check" "$out/layers"
fail=0
. "$(dirname "$0")/lib.sh"
inject_manifest "$out/layers" "the submitted layers"
printf 'mode flag\nseed 5\nflag Wrf\nminimap off\ncues none\n' >"$out/level.txt"
xrl="$out/layers:/usr/share/openxr/1/api_layers/explicit.d"
xre=XR_APILAYER_LUNARG_core_validation:XR_APILAYER_HOLONOMY_inject
env DISPLAY=:77 HOL_INJECT_AT=1000000 HOL_INJECT_LAYERS_AT=60 XR_API_LAYER_PATH="$xrl" \
    XR_ENABLE_API_LAYERS="$xre" \
    "$BIN" xr "$out/level.txt" --frames 120 --check-frame 60 --check-dir "$out/check" \
    >"$out/xr.out" 2>"$out/xr.err"
rc=$?
grep "quad\|panel" "$out/xr.out" | sed 's/^/  | /'
grep "^inject:" "$out/xr.err" | sed 's/^/  | /'
all="$out/xr.out $out/xr.err"
check "quad: exit 0 ($rc), the core validation layer ran, no VALID_ERROR or VALID_WARNING" \
    '[ "$rc" = 0 ] && grep -q "Core Validation" $all && ! grep -q "VALID_ERROR\|VALID_WARNING" $all'
check "quad: its swapchain made once (824x372, the eyes' format)" \
    '[ "$(grep -c "^xr: panel as a quad layer: 824x372 image, format" "$out/xr.out")" = 1 ]'
# as the runtime receives it: projection first, then the quad over it
l=$(grep "^inject: frame 60:" "$out/xr.err")
# The panel stands 1.5 m ahead, or in front of the nearest hedge or trunk
# in its direction (down to 0.5 m), scaled with its distance so that its
# angular size is kept (docs/headset.md, "Nearer scenery"): at 1.5 m it is
# 0.585 x 0.400 m (136 x 93 font pixels of 4.3 mm).
size=$(echo "$l" | sed -n 's/.*quad(eyes both, size \([0-9.]*\) \([0-9.]*\), position .*, rect 544x372, source alpha yes)$/\1 \2/p')
check "quad: the runtime receives projection then quad: both eyes, 0.585 x 0.400 m at 1.5 m scaled by one factor ($size), 544x372 texels, source alpha" \
    'echo "$l" | grep -q "2 layers: projection(2 views) quad(" &&
     echo "$size" | awk "{ a = \$1 / 0.585; b = \$2 / 0.400; exit !(NF == 2 && a <= 1.001 && a >= 0.33 && a - b < 0.005 && b - a < 0.005) }"'
# Monado's simulated head stands near the stage origin looking along -z:
# the panel 0.5 to 1.5 m ahead, below the eyes (the box's centre a little
# lower), its size in proportion to its distance
pos=$(echo "$l" | sed -n 's/.*position \([-0-9.]*\) \([-0-9.]*\) \([-0-9.]*\),.*/\1 \2 \3/p')
check "quad: its centre 0.5 to 1.6 m ahead of the stage origin (-z), within 0.3 m of the middle, its scale its distance / 1.5 within 0.06 ($pos; $size)" \
    'echo "$pos $size" | awk "{ d = -\$3 / 1.5; a = \$4 / 0.585; exit !(NF == 5 && \$3 <= -0.5 && \$3 >= -1.6 && \$1 <= 0.3 && \$1 >= -0.3 && d - a < 0.06 && a - d < 0.06) }"'
fe=$(echo "$size" | awk '{ printf "%.3f x %.3f", $1, $2 }')
check "quad: the frame-end line of the check frame names the same submission ($fe m)" \
    'grep -q "^xr: frame 60 ends with the quad layer after the projection layer: eye visibility BOTH, pose .*, size $fe m, image 544x372 of 824x372$" "$out/xr.out"'
for e in 0 1; do
    check "quad: eye $e's swapchain no longer contains the panel (drawn with and without the HUD: 0 pixels differ)" \
        'grep -q "^xr: check panel eye '$e': 0 pixels" "$out/xr.out"'
done
img=$(sed -n 's/^xr: check quad image: \([0-9]*\) opaque, \([0-9]*\) transparent of 544x372 texels$/\1 \2/p' "$out/xr.out")
check "quad: its image read back holds the panel: opaque texels and a transparent rest (${img:-none})" \
    'echo "$img" | awk "{ exit !(NF == 2 && \$1 > 20000 && \$2 > 1000 && \$1 + \$2 == 544 * 372) }"'
sub=$(sed -n 's/^xr: panel quad layer submitted in \([0-9]*\) frames, its image drawn \([0-9]*\) times.*/\1 \2/p' "$out/xr.out")
check "quad: submitted every frame, its image drawn again only when the panel changed (frames, draws: ${sub:-none})" \
    'echo "$sub" | awk "{ exit !(NF == 2 && \$1 >= 100 && \$2 >= 1 && \$2 * 4 <= \$1) }"'

# Nearer scenery than the panel can come (issue 36): the scripted head
# 0.3 m south of the trunk at (1, 1) and 0.15 m west of it, looking north:
# the panel stays at 0.5 m with the trunk's bark nearer, so the quad (no
# depth) would show over it. The quad is not submitted and the eyes draw
# the panel, depth-tested (its left part shows, the trunk hides its right:
# straight behind the trunk it would hide it all), said when it changes;
# the figures count those frames.
awk 'BEGIN { for (k = 0; k < 60; k++) printf "%.4f f=9 h=0.85,1.6,1.3,0,0,0,1\n", k / 72.0 }' \
    >"$out/trunk.txt"
env DISPLAY=:77 HOL_INJECT_AT=1000000 HOL_INJECT_LAYERS_AT=40 XR_API_LAYER_PATH="$xrl" \
    XR_ENABLE_API_LAYERS="$xre" \
    "$BIN" xr "$out/level.txt" --frames 60 --check-frame 40 --check-dir "$out/check" \
    --input "$out/trunk.txt" >"$out/trunk.out" 2>"$out/trunk.err"
rc=$?
grep "panel\|check panel" "$out/trunk.out" | sed 's/^/  | /'
grep "^inject:" "$out/trunk.err" | sed 's/^/  | /'
check "quad behind a trunk nearer than 0.55 m: exit 0 ($rc), said once: the panel in the scene, depth-tested" \
    '[ "$rc" = 0 ] && [ "$(grep -c "^xr: frame [0-9]*: panel in the scene (depth-tested): a hedge or trunk is nearer than the panel can come" "$out/trunk.out")" = 1 ]'
tf=$(sed -n 's/^xr: panel quad layer submitted in \([0-9]*\) frames, .*in the scene behind nearer scenery in \([0-9]*\)$/\1 \2/p' "$out/trunk.out")
check "quad behind a trunk: the projection layer alone, the panel in the eyes; the quad in at most the first 2 frames (quad, in the scene: ${tf:-none})" \
    'grep -q "^inject: frame 40: 1 layers: projection(2 views)$" "$out/trunk.err" &&
     grep "^xr: check panel eye 0:" "$out/trunk.out" | awk "{ exit !(\$6 > 100) }" &&
     echo "$tf" | awk "{ exit !(NF == 2 && \$1 <= 2 && \$2 >= 55) }"'
check "quad behind a trunk: no VALID_ERROR or VALID_WARNING" \
    'grep -q "Core Validation" "$out/trunk.out" "$out/trunk.err" && ! grep -q "VALID_ERROR\|VALID_WARNING" "$out/trunk.out" "$out/trunk.err"'

# no quad swapchain (the third xrCreateSwapchain fails: after both eyes'):
# the panel in the scene, said in one line, and the run goes on (exit 0)
env DISPLAY=:77 HOL_INJECT_AT=1000000 HOL_INJECT_SWAPCHAIN_FAIL=3 HOL_INJECT_LAYERS_AT=40 \
    XR_API_LAYER_PATH="$xrl" XR_ENABLE_API_LAYERS="$xre" \
    "$BIN" xr "$out/level.txt" --frames 60 --check-frame 40 --check-dir "$out/check" \
    >"$out/fb.out" 2>"$out/fb.err"
rc=$?
grep "panel in the scene" "$out/fb.out" | sed 's/^/  | /'
check "quad unavailable: exit 0 ($rc), said once: the panel in the scene, the fallback" \
    '[ "$rc" = 0 ] && [ "$(grep -c "^xr: panel in the scene: the quad layer.s swapchain failed (XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED): the fallback$" "$out/fb.out")" = 1 ]'
check "quad unavailable: the projection layer alone, and the panel in the eyes" \
    'grep -q "^inject: frame 40: 1 layers: projection(2 views)$" "$out/fb.err" && grep "^xr: check panel eye 0:" "$out/fb.out" | awk "{ exit !(\$6 > 100) }"'
check "quad unavailable: no VALID_ERROR or VALID_WARNING" \
    'grep -q "Core Validation" "$out/fb.out" "$out/fb.err" && ! grep -q "VALID_ERROR\|VALID_WARNING" "$out/fb.out" "$out/fb.err"'
exit $fail
