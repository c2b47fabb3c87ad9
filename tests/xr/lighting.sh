#!/bin/sh
# tests/xr/lighting.sh - make xr-test's host half for lighting (issue 27):
# the eyes that tests/xr/inside.sh read back from Monado's swapchains for
# day, dusk and night levels with a lantern on N, in {4,5} and {4,6}.
#
#   sh tests/xr/lighting.sh IN OUT   (HOLONOMY, PNG_DIFF, LIGHT_PROBE set)
#
# IN holds q5_day ... q6_night, each with xr.out and xr-world-eye0/1.png
# (the world without the HUD) and xr-shown-eye0/1.png (as shown); OUT (the
# build folder) gets the pictures, the host's renders and lighting.txt.
# Per tiling and eye it checks, with tests/xr/light_probe.c (a pinhole of
# the printed pose and tangents, independent of the renderer):
# - night darker than dusk darker than day (night's mean luma below half
#   of day's: the trunks, hedges and crowns take the lantern's light by the
#   floor's law since issue 38, tone-mapped (docs/lighting.md#tone-map):
#   0.37 to 0.38 of day; 0.2 when only the floor was lit, 0.54 to 0.57 with the
#   lanterns' sum unbounded);
# - at dusk and night the lantern's glass glows where the pinhole puts it
#   (pixels of luma 200 or more within 16 px, their mean x within 2 px of
#   the projection), and at day there is no glass;
# - at night the floor by the lantern's foot (0.15 m beyond it, under the
#   glass) is more than 1.2 times the frame's mean (a lit region in the
#   dark: 1.37 to 1.64; more than 3 when only the floor was lit: the trunks
#   0.7 m from the lantern take more light than the floor 1.3 m under
#   it, so they raise the mean), and at day not above twice it (the
#   control: no glare);
# - the glass's offset between the eyes: eye 0 (the left) sees it further
#   right, by the projections' difference within 1 px;
# - each eye equals the host's `holonomy render` of the same pose, tiling,
#   sky and lantern (png_diff's tolerance), and the night eye does not
#   equal the host's day render (the control: the checks can fail).
set -u
IN=$1 OUT=$2
fail=0
. "$(dirname "$0")/lib.sh"
rm -rf "$OUT" && mkdir -p "$OUT"
GLASS=1.5,1.3,0.5 FOOT=1.5,0,0.35
# field F of a probe line "mean M at PX,PY disc D bright N centroid CX"
f() { echo "$1" | awk -v k="$2" '{ split($4, p, ","); v["mean"] = $2; v["px"] = p[1]; v["disc"] = $6;
      v["bright"] = $8; v["cx"] = $10; print v[k] }'; }
for q in 5 6; do
    for s in day dusk night; do
        d="$IN/q${q}_$s"
        for e in 0 1; do
            for k in world shown; do cp "$d/xr-$k-eye$e.png" "$OUT/q${q}_${s}_${k}_eye$e.png" 2>/dev/null; done
            args=$(sed -n "s/^xr: check eye $e render //p" "$d/xr.out" 2>/dev/null)
            echo "$args" >"$OUT/q${q}_${s}_eye$e.args"
            # shellcheck disable=SC2086
            g=$("$LIGHT_PROBE" "$d/xr-world-eye$e.png" --point $GLASS $args 2>&1)
            # shellcheck disable=SC2086
            ft=$("$LIGHT_PROBE" "$d/xr-world-eye$e.png" --point $FOOT $args 2>&1)
            eval "g_${q}_${s}_$e=\$g ft_${q}_${s}_$e=\$ft"
            echo "{4,$q} $s eye $e: glass: $g; foot: $ft" >>"$OUT/lighting.txt"
            # shellcheck disable=SC2086
            "$HOLONOMY" render --walk - --seed 5 --tiling "4,$q" --lighting "$s" --lantern N $args \
                --out "$OUT/q${q}_${s}_host_eye$e.png" 2>>"$OUT/lighting.txt"
            r=$("$PNG_DIFF" "$d/xr-world-eye$e.png" "$OUT/q${q}_${s}_host_eye$e.png" 2>&1)
            check "lighting {4,$q} $s eye $e: the swapchain's eye equals the host's holonomy render --lighting $s --lantern N of its pose: $r" \
                '"$PNG_DIFF" "$d/xr-world-eye$e.png" "$OUT/q${q}_${s}_host_eye$e.png" >/dev/null'
        done
    done
    for e in 0 1; do
        eval "gd=\$g_${q}_day_$e gu=\$g_${q}_dusk_$e gn=\$g_${q}_night_$e fn=\$ft_${q}_night_$e fd=\$ft_${q}_day_$e"
        md=$(f "$gd" mean) mu=$(f "$gu" mean) mn=$(f "$gn" mean)
        check "lighting {4,$q} eye $e: night darker than dusk darker than day, night below half of day (mean luma $mn, $mu, $md)" \
            'awk "BEGIN { exit !($mn < $mu && $mu < $md && $mn < 0.5 * $md) }"'
        for s in dusk night; do
            eval "gs=\$g_${q}_${s}_$e"
            check "lighting {4,$q} $s eye $e: the lantern's glass glows where its pose projects ($(f "$gs" bright) bright pixels at x $(f "$gs" cx), projected $(f "$gs" px))" \
                'awk "BEGIN { exit !($(f "$gs" bright) >= 5 && $(f "$gs" cx) - $(f "$gs" px) <= 2 && $(f "$gs" px) - $(f "$gs" cx) <= 2) }"'
        done
        check "lighting {4,$q} day eye $e: no glass ($(f "$gd" bright) bright pixels)" '[ "$(f "$gd" bright)" = 0 ]'
        check "lighting {4,$q} night eye $e: the floor by the lantern's foot lit (luma $(f "$fn" disc)) above 1.2 times the frame's mean ($mn)" \
            'awk "BEGIN { exit !($(f "$fn" disc) > 1.2 * $mn) }"'
        check "lighting {4,$q} day eye $e: the same floor not above twice the frame's mean (luma $(f "$fd" disc), mean $md)" \
            'awk "BEGIN { exit !($(f "$fd" disc) <= 2 * $md) }"'
    done
    for s in dusk night; do
        eval "a=\$g_${q}_${s}_0 b=\$g_${q}_${s}_1"
        m=$(awk "BEGIN { print $(f "$a" cx) - $(f "$b" cx) }") p=$(awk "BEGIN { print $(f "$a" px) - $(f "$b" px) }")
        check "lighting {4,$q} $s: the glass's offset between the eyes, left minus right, $m px (projected $p)" \
            'awk "BEGIN { exit !($p > 0.5 && $m > 0 && $m - $p <= 1 && $p - $m <= 1) }"'
    done
    # the control: the night eye against the host's day render of its pose
    args=$(cat "$OUT/q${q}_night_eye0.args")
    # shellcheck disable=SC2086
    "$HOLONOMY" render --walk - --seed 5 --tiling "4,$q" --lighting day $args --out "$OUT/q${q}_control_day.png" 2>/dev/null
    r=$("$PNG_DIFF" "$IN/q${q}_night/xr-world-eye0.png" "$OUT/q${q}_control_day.png" 2>&1)
    check "lighting {4,$q}: the night eye is not the host's day render (the control: $r)" \
        '! "$PNG_DIFF" "$IN/q${q}_night/xr-world-eye0.png" "$OUT/q${q}_control_day.png" >/dev/null 2>&1'
done
grep -q '^{4,' "$OUT/lighting.txt" 2>/dev/null && sed 's/^/  | /' "$OUT/lighting.txt"
exit $fail
