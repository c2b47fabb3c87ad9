#!/bin/sh
# cli_level.sh - the level keys added to SPEC section 5 for studies, through
# the binary: flag-distance, keys-distance, chest-distance, time-limit,
# stages, place. Each good line plays (`holonomy game`), each bad line is
# exit 2 with one stderr line naming the file's line; placements that
# conflict name both lines; the time limit through `holonomy replay`
# (state, summary, logs byte for byte) and through `game` on every play.
. "$(dirname "$0")/lib.sh"

# lvl TEXT: the level file $T/l.lvl
lvl() { printf '%s\n' "$1" >"$T/l.lvl"; }
# refused NAME LINE TEXT LEVEL: exit 2, one stderr line naming line LINE and TEXT
refused() {
    lvl "$4"
    : >"$T/in"
    expect_status "$1" 2 "$H" game "$T/l.lvl" && one_line "$1" "l.lvl: line $2: .*$3"
    [ -s "$T/out" ] && bad "$1: printed on stdout: $(cat "$T/out")" || ok
}

# ---- flag-distance: drawn from the seed, the same file the same tile -------
printf -- '-\n-\n' >"$T/in"
lvl 'mode flag
seed 5
flag-distance 4 6'
"$H" game "$T/l.lvl" <"$T/in" >"$T/a" 2>"$T/err" && ok || bad "flag-distance: $(cat "$T/err")"
K=$(head -1 "$T/a" | cut -d' ' -f3)
[ "$(cat "$T/a")" = "open 0 $K
open 0 $K" ] && [ "$K" -ge 4 ] && ok || bad "flag-distance: $(cat "$T/a")"
"$H" game "$T/l.lvl" <"$T/in" >"$T/b" && cmp -s "$T/a" "$T/b" && ok || bad "flag-distance not deterministic"
# a tile at distance 4..6 is 4..6 room steps away at least; the optimum
# differs across seeds (the tile is drawn, not fixed)
for s in 1 2 3 4 5 6 7 8; do
    printf 'mode flag\nseed %s\nflag-distance 4 6\n' "$s" >"$T/s.lvl"
    printf -- '-\n' | "$H" game "$T/s.lvl"
done >"$T/opts"
[ "$(sort -u "$T/opts" | wc -l)" -gt 1 ] && ok || bad "flag-distance: one optimum over 8 seeds"
awk '$3 < 4 { exit 1 }' "$T/opts" && ok || bad "flag-distance: an optimum under 4: $(cat "$T/opts")"
refused "flag-distance 0" 3 "flag-distance needs MIN" 'mode flag
seed 5
flag-distance 0'
refused "flag-distance MIN > MAX" 2 "flag-distance needs MIN" 'mode flag
flag-distance 5 3'
refused "flag-distance 11" 4 "MAX <= 10" 'mode flag
# far

flag-distance 11'
refused "flag-distance x" 2 "flag-distance needs" 'mode flag
flag-distance x'

# ---- keys-distance, chest-distance ---------------------------------------------
lvl 'mode keys
seed 9
keys-distance 3 2 3
chest-distance 4'
printf -- '-\n' >"$T/in"
"$H" game "$T/l.lvl" <"$T/in" >"$T/a" && grep -q '^open 0 [0-9][0-9]*$' "$T/a" && ok ||
    bad "keys-distance: $(cat "$T/a")"
refused "keys-distance 6 keys" 2 "keys-distance needs COUNT (1..5)" 'mode keys
keys-distance 6 2
chest-distance 3'
refused "keys-distance 0 keys" 2 "keys-distance needs COUNT" 'mode keys
keys-distance 0 2'
refused "keys-distance no range" 3 "wrong value count: 'keys-distance'" 'mode keys
chest N
keys-distance 2'
refused "chest-distance 3 2" 3 "chest-distance needs MIN" 'mode keys
keys N
chest-distance 3 2'

# ---- time-limit ------------------------------------------------------------------
# `game` steps every 0.25 s: 2 s allow 8 steps; every play has its own clock
printf -- '- Wrf\n' | "$H" nav >"$T/nav" || bad "nav"
W=$(cut -d' ' -f2 "$T/nav") K=$(cut -d' ' -f1 "$T/nav")
[ "$K" = 8 ] && ok || bad "the walk to Wrf is not 8 steps: $K"
lvl 'mode flag
seed 5
flag Wrf
time-limit 2'
printf '%s\nSN%s\n%s\nEWEW%s\n' "$W" "$W" "$W" "$W" >"$T/in"
expect "time-limit game" 0 "done 8 8
open 8 8
done 8 8
open 8 8
" "$H" game "$T/l.lvl"
refused "time-limit 0" 4 "time-limit '0' is not seconds in 1..86400" 'mode flag
seed 5
flag Wrf
time-limit 0'
refused "time-limit 86401" 2 "time-limit '86401'" 'mode flag
time-limit 86401'
refused "time-limit 1.5" 2 "time-limit '1.5'" 'mode flag
time-limit 1.5'
refused "time-limit no value" 2 "'time-limit' needs a value" 'mode flag
time-limit'

# through replay: walking at 0.25 s a step, a 1 s limit ends the level after
# 4 steps; the state, the summary and the logs say timeout, byte for byte
{
    printf 'holonomy-rec 1\nlevel lv\n'
    printf 'L mode flag\nL seed 5\nL flag Wrf\nL time-limit 1\nend\n'
    walk_input "$W"
} >"$T/t.rec"
mkdir "$T/g1" "$T/g2"
run "time-limit replay" 0 "$H" replay "$T/t.rec" --log "$T/g1"
grep -q '^level lv timeout steps 4 optimum 8 ' "$T/out" && ok ||
    bad "time-limit replay: $(cat "$T/out")"
grep -q ',1,,,,lv,[0-9a-f]\{64\},flag,5,15,"4,5",3x3,1,[0-9.]*,4,8,1.0000,timeout,,,$' "$T/g1/summary.csv" && ok ||
    bad "time-limit summary: $(cat "$T/g1/summary.csv")"
[ "$(($(wc -l <"$T/g1/steps-001.csv") - 1))" = 4 ] && ok || bad "time-limit: not 4 step rows"
run "time-limit replay again" 0 "$H" replay "$T/t.rec" --log "$T/g2"
diff -r "$T/g1" "$T/g2" >/dev/null && ok || bad "time-limit replay logs differ"
# without the limit the same input completes
sed '/^L time-limit/d' "$T/t.rec" >"$T/n.rec"
run "no time-limit replay" 0 "$H" replay "$T/n.rec"
grep -q '^level lv done steps 8 optimum 8 ' "$T/out" && ok || bad "no limit: $(cat "$T/out")"

# a recording's level names the recording's lines, both of them
printf 'holonomy-rec 1\nlevel c\nL mode flag\nL flag Wrf\nL place rock Wrf\nend\n0 f=8\n' >"$T/c.rec"
run "conflict in a recording" 2 "$H" replay "$T/c.rec"
one_line "conflict in a recording" "line 5: level 'c': the placement on Wrf conflicts with the flag (line 4)$"
printf 'holonomy-rec 1\nlevel c\nL mode explore\nL place rock Nf\nL place grass Nf\nend\n0 f=8\n' >"$T/c.rec"
run "placed twice in a recording" 2 "$H" replay "$T/c.rec"
one_line "placed twice in a recording" "line 5: level 'c': Nf is already placed on line 4$"

# ---- stages (the tutorial's lessons) ---------------------------------------------
lvl 'mode tutorial
stages 1'
printf 'N\n-\n' >"$T/in"
expect "stages 1" 0 "done 1 -1
open 0 -1
" "$H" game "$T/l.lvl"
lvl 'mode tutorial
stages 2 4'
printf 'N\n' >"$T/in"
expect "stages 2 4: the first lesson is not played" 0 "open 1 -1
" "$H" game "$T/l.lvl"
lvl 'mode tutorial'
expect "all lessons" 0 "open 1 -1
" "$H" game "$T/l.lvl"
refused "stages 5" 2 "stages are lesson numbers 1..4" 'mode tutorial
stages 1 5'
refused "stages 0" 2 "stages are lesson numbers" 'mode tutorial
stages 0'
refused "stages no value" 3 "'stages' needs a value" 'mode tutorial

stages'

# ---- place: designer placements ----------------------------------------------------
# a landmark beside the route does not change the score
lvl 'mode flag
seed 5
place rock Nf
place flowers Wr
place pond Sf
place clearing E
place grass Nr
place mushroom W
flag Wrf'
printf '%s\n' "$W" >"$T/in"
expect "placements" 0 "done 8 8
" "$H" game "$T/l.lvl"
refused "place on the flag" 3 "the placement on Wrf conflicts with the flag (line 2)" 'mode flag
flag Wrf
place rock Wrf'
refused "place on a key" 4 "the placement on Nf conflicts with a key (line 2)" 'mode keys
keys Wr Nf
chest Sf
place flowers Nf'
refused "place on the chest" 2 "conflicts with the chest (line 4)" 'mode keys
place pond Sf
keys Wr
chest Sf'
refused "placed twice" 3 "Nf is already placed on line 2" 'mode explore
place rock Nf
place grass Nf'
refused "place a tree" 2 "place 'tree' is not clearing, grass, flowers, rock, mushroom, pond or lantern" 'mode explore
place tree Nf'
refused "place bad address" 2 "'Nx' is not a canonical address" 'mode explore
place rock Nx'
refused "place no tile" 2 "wrong value count: 'place'" 'mode explore
place rock'
# at most 32; the 33rd line is named
printf 'mode explore\n' >"$T/many.lvl"
printf 'NN\nNE\nNNN\nWW\nWN\nSS\nES\nEEN\nWSS\nNNE\nSW\nNEN\nN\nE\nS\nW\nNW\nEN\nEE\nSE\nWS\nSSE\nSSW\nEES\nEEN\nWWN\nWWS\nNNW\nNWW\nNEE\nSEE\nSWW\nSWS\nNWN\n' |
    "$H" tile walk | cut -d' ' -f1 | sort -u | head -33 | sed 's/^/place rock /' >>"$T/many.lvl"
[ "$(wc -l <"$T/many.lvl")" = 34 ] && ok || bad "need 33 distinct tiles for the placement limit"
: >"$T/in"
expect_status "33 placements" 2 "$H" game "$T/many.lvl" && one_line "33 placements" "line 34: more than 32 placements"
sed -i '$d' "$T/many.lvl"
printf -- '-\n' >"$T/in"
expect "32 placements" 0 "open 0 -1
" "$H" game "$T/many.lvl"

# a drawn objective never lands on a placement: place rocks on every tile
# at distance 1 but one; flag-distance 1 must take that one
lvl 'mode flag
seed 3
place rock N
place rock E
place rock S
flag-distance 1'
printf 'W\n' >"$T/in"
expect "drawn around placements" 0 "done 1 1
" "$H" game "$T/l.lvl"
lvl 'mode flag
seed 3
place rock N
place rock E
place rock S
place rock W
flag-distance 1'
: >"$T/in"
expect_status "no free tile" 2 "$H" game "$T/l.lvl" && one_line "no free tile" "line 7: no free tile for the flag at that distance"

finish cli_level
