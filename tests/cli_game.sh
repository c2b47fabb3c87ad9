#!/bin/sh
# cli_game.sh - `holonomy game LEVEL` (SPEC section 5): the navigator's
# optimal walk scores exactly the optimum, a detour of k steps the optimum
# plus k, for flag and keys levels and with a start walk; open plays; bad
# plays and bad levels named by line.
. "$(dirname "$0")/lib.sh"

run "--help" 0 "$H" game --help
grep -q "done STEPS OPTIMUM" "$T/out" && ok || bad "--help lacks the output format"

# flag
printf 'mode flag   # find the flag\nseed 5\n\nflag Wrf\n' >"$T/f.lvl"
printf -- '- Wrf\n' | "$H" nav >"$T/nav"
K=$(cut -d' ' -f1 "$T/nav") W=$(cut -d' ' -f2 "$T/nav")
# (steps after completion are ignored: W ends in a north cell, so S N fits)
printf '%s\nSN%s\nEWEW%s\n-\n\n%sSN\n' "$W" "$W" "$W" "$W" >"$T/in"
expect "flag" 0 "done $K $K
done $((K + 2)) $K
done $((K + 4)) $K
open 0 $K
open 0 $K
done $K $K
" "$H" game "$T/f.lvl"

# keys and chest, from a start walk
printf 'mode keys\nseed 0x3\nstart NE\nkeys Nf Wr\nchest Sf\n' >"$T/k.lvl"
"$H" tour NE Nf Wr Sf >"$T/tour"
K=$(cut -d' ' -f1 "$T/tour") W=$(cut -d' ' -f2 "$T/tour")
printf '%s\nWE%s\n' "$W" "$W" >"$T/in"
expect "keys" 0 "done $K $K
done $((K + 2)) $K
" "$H" game "$T/k.lvl"
# the chest before the keys does not count
printf 'mode keys\nseed 1\nkeys Nf\nchest N\n' >"$T/k2.lvl"
"$H" tour - Nf N >"$T/tour"
K=$(cut -d' ' -f1 "$T/tour") W=$(cut -d' ' -f2 "$T/tour")
printf 'N\n%s\n' "$W" >"$T/in"
expect "chest last" 0 "open 1 $K
done $K $K
" "$H" game "$T/k2.lvl"

# bad plays: exit 2, one line naming the line
printf 'N\nNN\n' >"$T/in"
expect_status "leaves the room" 2 "$H" game "$T/f.lvl"
one_line "leaves the room" "line 2: step 2"
printf 'N\nNX\n' >"$T/in"
expect_status "bad step" 2 "$H" game "$T/f.lvl"
one_line "bad step" "line 2: character 2"

# bad levels: exit 2, one line naming the file's line
: >"$T/in"
printf 'mode flag\nseed 5\nflug Wrf\n' >"$T/b1.lvl"
run "unknown key" 2 "$H" game "$T/b1.lvl" && one_line "unknown key" "line 3"
printf 'mode flag\nseed -5\n' >"$T/b2.lvl"
run "bad seed" 2 "$H" game "$T/b2.lvl" && one_line "bad seed" "line 2"
printf 'mode chess\n' >"$T/b3.lvl"
run "bad mode" 2 "$H" game "$T/b3.lvl" && one_line "bad mode" "line 1"
printf 'mode flag\nflag O\n' >"$T/b4.lvl"
run "flag on the start" 2 "$H" game "$T/b4.lvl" && one_line "flag on the start" "where the level begins"
printf 'mode flag\nflag\n' >"$T/b5.lvl"
run "missing value" 2 "$H" game "$T/b5.lvl" && one_line "missing value" "line 2"
printf 'mode flag\nflag N\ncues path arrow\nminimap hand\n' >"$T/c.lvl"
printf 'N\n' >"$T/in"
expect "cues and minimap keys" 0 "done 1 1
" "$H" game "$T/c.lvl"
: >"$T/in"
printf 'mode flag\nflag N\ncues path smell\n' >"$T/b6.lvl"
run "bad cue" 2 "$H" game "$T/b6.lvl" && one_line "bad cue" "line 3"
printf 'mode flag\nflag N\nminimap wrist\n' >"$T/b7.lvl"
run "bad minimap" 2 "$H" game "$T/b7.lvl" && one_line "bad minimap" "line 3"
run "no level" 2 "$H" game
run "missing file" 2 "$H" game "$T/nope.lvl"
# ---- geometry (SPEC 7): options and level lines ----------------------------------
printf 'mode flag\nseed 5\nflag Wrf\n' >"$T/g.lvl"
printf -- '- Wrf\n' | "$H" nav --tiling 4,6 --room 4x4 >"$T/nav6" || bad "nav {4,6} 4x4"
K6=$(cut -d' ' -f1 "$T/nav6") W6=$(cut -d' ' -f2 "$T/nav6")
printf '%s\nN\n' "$W6" >"$T/in"
expect "game --tiling 4,6 --room 4x4" 0 "done $K6 $K6
open 1 $K6
" "$H" game "$T/g.lvl" --tiling 4,6 --room 4x4
expect "the same in 0.5 m cells" 0 "done $K6 $K6
open 1 $K6
" "$H" game "$T/g.lvl" --tiling 4,6 --room 4x4 --cell 0.5
printf 'tiling 4 6\nroom 4 4\ncell 1.25\nmode flag\nseed 5\nflag Wrf\n' >"$T/g6.lvl"
expect "the same from level lines" 0 "done $K6 $K6
open 1 $K6
" "$H" game "$T/g6.lvl"
expect "level lines and the same options" 0 "done $K6 $K6
open 1 $K6
" "$H" game "$T/g6.lvl" --tiling 4,6 --room 4x4 --cell 1.25
run "an option against a level line" 2 "$H" game "$T/g6.lvl" --room 5x5 &&
    one_line "conflict" "level 'g6': its own line 'room 4 4' differs from the 5x5 asked for"
# 4x4: the start is cell (2,2), so EE leaves the room and W, WW do not
printf 'WW\nEE\n' >"$T/in"
run "4x4 bounds" 2 "$H" game "$T/g.lvl" --tiling 4,6 --room 4x4 <"$T/in" &&
    one_line "4x4 bounds" "line 2: step 2 (E from cell (3,2)) leaves the room"
# the flat {4,4}: a walk round the room comes back to O; a flag off the
# nine tiles is refused with its line
printf 'tiling 4 4\nmode flag\nflag Nr\n' >"$T/flat.lvl"
printf 'NE\nWNES\n' >"$T/in"
expect "flat flag" 0 "done 2 2
open 4 2
" "$H" game "$T/flat.lvl"
run "flat out of reach" 2 "$H" game "$T/g.lvl" --tiling 4,4 &&
    one_line "flat out of reach" "line 3: no walk inside the room reaches the flag's tile Wrf"
run "bad --tiling" 2 "$H" game "$T/g.lvl" --tiling 5,4 && one_line "bad tiling" "--tiling needs 4,Q"
run "bad --room" 2 "$H" game "$T/g.lvl" --room 3 && one_line "bad room" "--room needs CxR"
run "bad --cell" 2 "$H" game "$T/g.lvl" --cell 0.5.1 && one_line "bad cell" "--cell needs metres"
printf 'mode explore\ntiling 4 9\n' >"$T/b8.lvl"
run "bad tiling line" 2 "$H" game "$T/b8.lvl" && one_line "bad tiling line" "line 2: tiling needs 4 Q"
: >"$T/in"
finish cli_game
