#!/bin/sh
# cli_render.sh - `holonomy render`: usage errors, outputs, atomic writes.
. "$(dirname "$0")/lib.sh"
fail() { echo "FAIL: $*"; exit 1; }

# expect_usage ARGS...: exit 2, exactly one line on stderr, nothing on stdout
expect_usage() {
    "$H" render "$@" >"$T/out" 2>"$T/err"
    st=$?
    [ $st -eq 2 ] || fail "render $* exited $st, expected 2"
    [ "$(wc -l <"$T/err")" -eq 1 ] || fail "render $*: stderr is not one line"
    [ ! -s "$T/out" ] || fail "render $*: wrote to stdout"
}

"$H" render --help >"$T/help" || fail "--help"
grep -q -- "--tile-ids" "$T/help" || fail "--help does not describe --tile-ids"

expect_usage
expect_usage --walk NX --out "$T/a.png"
expect_usage --walk NN --out "$T/a.png"
expect_usage --eye 0.5,1.6,0.5 --out "$T/a.png"
expect_usage --eye 1.0,1.6,1.5 --out "$T/a.png"
expect_usage --eye 1.5,1.6 --out "$T/a.png"
expect_usage --eye 1.5,-1,1.5 --out "$T/a.png"
expect_usage --walk N --eye 1.5,1.6,1.5 --out "$T/a.png"
expect_usage --size 0x10 --out "$T/a.png"
expect_usage --size 64 --out "$T/a.png"
expect_usage --pitch 91 --out "$T/a.png"
expect_usage --yaw abc --out "$T/a.png"
expect_usage --bogus --out "$T/a.png"
expect_usage --out
expect_usage --gl vulkan --out "$T/a.png"
expect_usage --stereo 0.5 --out "$T/a.png"
expect_usage --stereo 0.064 --tile-ids "$T/a.ids"
expect_usage --hand 1,2 --out "$T/a.png"
expect_usage --hand 1.5,1.2,1.5 --out "$T/a.png"
expect_usage --hand 4,1.2,4 --out "$T/a.png"
[ ! -e "$T/a.png" ] || fail "a usage error left an output file"

# a view, its tile ids, stats
"$H" render --walk NE --eye 2.4,1.6,0.6 --yaw 135 --pitch -40 --size 64x48 \
    --out "$T/v.png" --tile-ids "$T/ids" --stats >"$T/stats" || fail "render"
head -c 8 "$T/v.png" | od -An -c | grep -q "P   N   G" || fail "not a PNG"
grep -q '^draw_calls [0-9]' "$T/stats" || fail "no draw_calls in --stats"
grep -q '^stencil_passes [0-9]' "$T/stats" || fail "no stencil_passes in --stats"
grep -q '^cpu_ms [0-9]' "$T/stats" || fail "no cpu_ms in --stats"
[ -s "$T/ids" ] || fail "no tile ids"
# every line: PX PY ADDRESS with PX < 64, PY < 48; the user's tile (walk NE
# ends on Nr) is among them
awk 'NF != 3 || $1 !~ /^[0-9]+$/ || $2 !~ /^[0-9]+$/ || $1 >= 64 || $2 >= 48 ||
     $3 !~ /^(O|[NESW][flr]*)$/ { bad = 1 } END { exit bad }' "$T/ids" ||
    fail "malformed tile-id line"
grep -q ' Nr$' "$T/ids" || fail "the user's tile Nr is not in view"
ls -A "$T" | grep -q holonomy-tmp && fail "a temporary file was left behind"

# two eyes side by side, one render queue each
"$H" render --stereo 0.064 --eye 1.98,1.6,1.5 --size 64x24 --out "$T/st.png" \
    --stats >"$T/stats2" || fail "--stereo"
grep -q '^eyes 2$' "$T/stats2" || fail "--stereo stats do not report two eyes"
grep -q '^right_draw_calls [0-9]' "$T/stats2" || fail "no right eye stats"

# the euclidean baseline and a bare view render too
"$H" render --euclidean --size 32x24 --out "$T/e.png" || fail "--euclidean"
"$H" render --bare --size 32x24 --tile-ids "$T/b" || fail "--bare"

# the same view through OpenGL ES 3 on EGL (surfaceless) is the same image
if "$H" render --gl egl --walk NE --eye 2.4,1.6,0.6 --yaw 135 --pitch -40 \
    --size 64x48 --out "$T/v_egl.png" 2>"$T/err"; then
    cmp -s "$T/v.png" "$T/v_egl.png" || echo "note: EGL and OSMesa images differ (goldens decide)"
else
    echo "note: no EGL surfaceless platform here: $(cat "$T/err")"
fi

# the desktop build: a window through EGL on X11, here under Xvfb
if command -v Xvfb >/dev/null 2>&1; then
    # (lib.sh's Xvfb, ready when it returns; DISPLAY as it was for the rest)
    xd_old=${DISPLAY-}
    start_xvfb 0
    D=$DISPLAY
    if [ -n "$xd_old" ]; then DISPLAY=$xd_old; else unset DISPLAY; fi
    DISPLAY=$D "$H" render --window --frames 2 --size 64x48 --seed 2 \
        --out "$T/w.png" >/dev/null 2>&1 || fail "--window under Xvfb"
    # the window shows what the headless build shows (HUD on in both)
    "$H" render --hud --size 64x48 --seed 2 --out "$T/w_osm.png" || fail "render --hud"
    cmp -s "$T/w.png" "$T/w_osm.png" || echo "note: window and OSMesa images differ"
    # walking 40 frames north crosses the edge z = 1: one room step to N
    KEYS=wwwwwwwwwwwwwwwwwwwwwwwwwwwwwwwwwwwwwwww
    DISPLAY=$D "$H" render --window --size 64x48 --keys "$KEYS" >"$T/walk" ||
        fail "--keys"
    grep -q '^tile N cell 1,0 steps 1 ' "$T/walk" || fail "walking north: $(cat "$T/walk")"
    kill $XPID 2>/dev/null
    wait $XPID 2>/dev/null
else
    echo "note: no Xvfb here: --window not tested"
fi
expect_usage --window --stereo 0.064
expect_usage --keys www --out "$T/a.png"

# a failed write: exit 1, the old file untouched, no temp file
echo old >"$T/keep.png"
chmod 0555 "$T" 2>/dev/null
if [ "$(id -u)" != 0 ]; then
    "$H" render --size 16x16 --out "$T/keep.png" 2>/dev/null && fail "write into read-only dir"
fi
chmod 0755 "$T"
"$H" render --size 16x16 --out "$T/nodir/x.png" 2>"$T/err"
[ $? -eq 2 ] || fail "a missing folder is bad usage, refused before rendering (exit 2)"
[ "$(cat "$T/keep.png")" = old ] || fail "old file changed"
# the minimap in the hand (its picture is the golden minimap_hand)
"$H" render --walk NE --eye 2.4,1.6,0.6 --yaw 135 --size 64x48 --hand 2.2,1.3,0.8 \
    --target Nrfl --out "$T/hand.png" || fail "--hand"
[ -s "$T/hand.png" ] || fail "--hand wrote no picture"
# the headset's form of the eye (--orient, --tan, as holonomy xr prints
# it): yaw 20 and pitch -30 as a quaternion with the 90 degree field of
# view's tangents give the same picture, byte for byte
"$H" render --eye 1.4,1.6,1.3 --yaw 20 --pitch -30 --size 64x48 --out "$T/yp.png" ||
    fail "render yaw/pitch"
Q=$(awk 'BEGIN { y = 10 * atan2(0, -1) / 180; p = -15 * atan2(0, -1) / 180;
    printf "%.17g,%.17g,%.17g,%.17g", cos(y) * sin(p), sin(y) * cos(p), -sin(y) * sin(p),
    cos(y) * cos(p) }')
"$H" render --eye 1.4,1.6,1.3 --orient "$Q" --tan -1.3333333333333333,1.3333333333333333,-1,1 \
    --size 64x48 --out "$T/q.png" || fail "render --orient --tan"
cmp -s "$T/yp.png" "$T/q.png" || fail "--orient/--tan differs from the same yaw and pitch"
expect_usage --out "$T/q.png" --orient 0,0,0,1
expect_usage --out "$T/q.png" --tan -1,1,-1,1
expect_usage --out "$T/q.png" --orient 0,0,0,2 --tan -1,1,-1,1
expect_usage --out "$T/q.png" --orient 0,0,1 --tan -1,1,-1,1
expect_usage --out "$T/q.png" --orient 0,0,0,1 --tan 1,-1,-1,1
expect_usage --out "$T/q.png" --orient 0,0,0,1 --tan -1,1,-1,1,0

# geometries (SPEC 7): bad values one line, exit 2, no output
for bad in "--tiling 4,3" "--tiling 4,9" "--tiling 5,5" "--tiling 4" "--room 2x3" \
    "--room 6x6" "--room 3x" "--cell 0.4" "--cell 1.6" "--cell abc" "--cell 1,0" "--cell 0.7501" \
    "--tiling 4,5 --tiling 4,6" "--room 4x4 --walk NNN" "--cell 0.5 --eye 1.5,1.6,1.5" \
    "--room 4x4 --cell 0.7 --eye 1.1,1.6,1.1"; do
    # shellcheck disable=SC2086
    expect_usage $bad --out "$T/g.png"
done
[ ! -e "$T/g.png" ] || fail "a geometry usage error left an output file"
# {4,4} in the 3 x 3 room: the floor shows only the room's nine tiles
"$H" render --tiling 4,4 --walk NE --eye 2.4,1.6,0.6 --yaw 135 --pitch -40 --size 64x48 \
    --tile-ids "$T/ids4" || fail "render --tiling 4,4"
awk '{ print $3 }' "$T/ids4" | sort -u >"$T/tiles4"
[ "$(wc -l <"$T/tiles4")" -ge 4 ] || fail "{4,4}: fewer than 4 tiles in view"
[ "$(wc -l <"$T/tiles4")" -le 9 ] || fail "{4,4}: more than the room's nine tiles"
awk 'length($0) > 2 { bad = 1 } END { exit bad }' "$T/tiles4" ||
    fail "{4,4}: a tile farther than 2 steps from O in a 3 x 3 room"
# {4,8}, a 5 x 5 room of 0.6 m cells: the default eye is the start cell's
# centre (1.5, 1.6, 1.5) and the user's tile O is in view
"$H" render --tiling 4,8 --room 5x5 --cell 0.6 --pitch -60 --size 64x48 \
    --tile-ids "$T/ids8" --out "$T/g8.png" || fail "render --tiling 4,8 --room 5x5 --cell 0.6"
grep -q ' O$' "$T/ids8" || fail "{4,8} 5x5: the user's tile O is not in view"
[ "$(awk '{ print $3 }' "$T/ids8" | sort -u | wc -l)" -ge 9 ] ||
    fail "{4,8} 5x5: fewer than 9 tiles in view"
"$H" render --help | grep -q -- "--cell M" || fail "--help does not describe --cell"
echo "cli_render: ok"

# --lang (issue 37): the --hud text in the language; en is the default
expect_usage --lang fr --out "$T/a.png"
expect_usage --lang DE --out "$T/a.png"
expect_usage --lang de-DE --out "$T/a.png"
"$H" render --hud --target N --size 160x120 --out "$T/l0.png" || fail "render --hud"
"$H" render --hud --target N --size 160x120 --lang en --out "$T/len.png" || fail "--lang en"
"$H" render --hud --target N --size 160x120 --lang de --out "$T/lde.png" || fail "--lang de"
cmp -s "$T/l0.png" "$T/len.png" || fail "--lang en is not the default's picture"
cmp -s "$T/l0.png" "$T/lde.png" && fail "--lang de draws the English text"
"$H" render --help | grep -q -- "--lang L" || fail "--help does not describe --lang"
echo "cli_render: --lang ok"
