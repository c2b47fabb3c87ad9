#!/bin/sh
# cli_light.sh - dusk and night (issue 27) through the binary: render's
# --lighting and repeatable --lantern, their refusals (one line, exit 2),
# a level's `lighting`, `place lantern` and cue `lantern` lines in game and
# replay (the replay renders its frames with the level's sky: the path play
# and xr share), day untouched by lanterns.
. "$(dirname "$0")/lib.sh"
P=${PNG_PROBE:-build/tests/png_probe}

run "--help" 0 "$H" render --help
grep -q -- "--lighting SKY" "$T/out" && grep -q -- "--lantern ADDR" "$T/out" && ok ||
    bad "render --help does not describe --lighting and --lantern"

V="--walk SW --eye 0.15,1.6,2.85 --yaw -30 --pitch -22 --size 96x72"
run "day" 0 "$H" render $V --out "$T/day.png"
run "day with lanterns" 0 "$H" render $V --lighting day --lantern O --lantern W --out "$T/day2.png"
cmp -s "$T/day.png" "$T/day2.png" && ok || bad "lanterns changed the day picture"
run "dusk" 0 "$H" render $V --lighting dusk --lantern O --lantern W --out "$T/dusk.png"
run "night" 0 "$H" render $V --lighting night --lantern O --lantern W --out "$T/night.png"
run "night, no lanterns" 0 "$H" render $V --lighting night --out "$T/dark.png"
for a in dusk night; do
    n=$("$P" "$T/day.png" --vs "$T/$a.png")
    [ "$n" -gt 5000 ] && ok || bad "$a differs from day in only $n of 6912 pixels"
done
n=$("$P" "$T/dark.png" --vs "$T/night.png")
[ "$n" -gt 300 ] && ok || bad "the lanterns light only $n pixels at night"

run "bad sky" 2 "$H" render $V --lighting noon --out "$T/x.png" &&
    one_line "bad sky" "--lighting 'noon' is not day, dusk or night"
run "sky twice" 2 "$H" render $V --lighting dusk --lighting=night --out "$T/x.png" &&
    one_line "sky twice" "--lighting is given twice"
run "bad lantern" 2 "$H" render $V --lantern Nx --out "$T/x.png" &&
    one_line "bad lantern" "--lantern 'Nx' is not a canonical address of {4,5}"
run "lantern in {4,8}" 0 "$H" render --tiling 4,8 --lighting night --lantern Nrr --size 32x24 \
    --out "$T/q8.png"
set -- render $V --lighting night
for a in N E S W Nf Ef Sf Wf Nl El Sl Wl Nr Er Sr Wr Nff; do set -- "$@" --lantern "$a"; done
run "17 lanterns" 2 "$H" "$@" --out "$T/x.png" && one_line "17" "more than 16 --lantern options"
[ ! -e "$T/x.png" ] && ok || bad "a refused render wrote its file"

# levels: the lines parse in game; a bad one is named
printf 'mode flag\nseed 5\nflag Wrf\nlighting night\nplace lantern Wrf\nplace lantern N\ncues lantern poles\n' >"$T/n.lvl"
printf 'WNESWNEE\n' >"$T/in"
expect "night level" 0 "done 8 8
" "$H" game "$T/n.lvl"
printf 'mode flag\nflag Wrf\nlighting noon\n' >"$T/b.lvl"
expect_status "bad sky line" 2 "$H" game "$T/b.lvl" &&
    one_line "bad sky line" "line 3: lighting 'noon' is not day, dusk or night"
printf 'mode flag\nflag Wrf\nplace lantern N\nplace lantern N\n' >"$T/b2.lvl"
expect_status "lantern twice" 2 "$H" game "$T/b2.lvl" &&
    one_line "lantern twice" "line 4: a lantern on N is already placed on line 3"

# replay renders with the level's sky and lanterns (as play and xr do)
rec() {
    printf 'holonomy-rec 1\nlevel lv\n'
    printf '%s\n' "$1" | sed 's/^/L /'
    printf 'end\n'
    walk_input "$2"
}
rec 'mode flag
seed 5
flag Wrf' "W" >"$T/day.rec"
rec 'mode flag
seed 5
flag Wrf
lighting night
place lantern W
cues lantern' "W" >"$T/night.rec"
mkdir "$T/pd" "$T/pn"
run "replay day" 0 "$H" replay "$T/day.rec" --png-frames 1 --out-dir "$T/pd" --size 96x72
run "replay night" 0 "$H" replay "$T/night.rec" --png-frames 1 --out-dir "$T/pn" --size 96x72
n=$("$P" "$T/pd/frame-000001.png" --vs "$T/pn/frame-000001.png")
[ "$n" -gt 5000 ] && ok || bad "the night level's replay frame differs from day in only $n pixels"

finish cli_light
