#!/bin/sh
# cli_replay.sh - `holonomy replay`: a recording through the same app step
# as `play`: scores (optimal walk = optimum, detour of k = optimum + k),
# logs byte for byte on every run, PNG frames, bad recordings.
. "$(dirname "$0")/lib.sh"

# rec LEVELTEXT WALK: a recording of one level whose input walks the room
# steps WALK (lib.sh walk_input)
rec() {
    printf 'holonomy-rec 1\nlevel lv\n'
    printf '%s\n' "$1" | sed 's/^/L /'
    printf 'end\n'
    walk_input "$2"
}

run "--help" 0 "$H" replay --help
grep -q -- "--png-frames" "$T/out" && ok || bad "--help does not describe --png-frames"

# the navigator's walk scores exactly the optimum; a detour of 2 adds 2
LEVEL='mode flag
seed 5
flag Wrf'
printf -- '- Wrf\n' | "$H" nav >"$T/nav" || bad "nav"
K=$(cut -d' ' -f1 "$T/nav") WALK=$(cut -d' ' -f2 "$T/nav")
rec "$LEVEL" "$WALK" >"$T/opt.rec"
mkdir "$T/l1" "$T/l2" "$T/l3" "$T/png" "$T/png2"
run "optimal walk" 0 "$H" replay "$T/opt.rec" --log "$T/l1"
grep -q "^level lv done steps $K optimum $K " "$T/out" && ok ||
    bad "optimal walk: $(cat "$T/out"), want done $K $K"
grep -q ",1,,,,lv,[0-9a-f]\{64\},flag,5,15,\"4,5\",3x3,1,[0-9.]*,$K,$K,[0-9.]*,done,,,\$" "$T/l1/summary.csv" && ok ||
    bad "summary: $(cat "$T/l1/summary.csv")"
[ "$(($(wc -l <"$T/l1/steps-001.csv") - 1))" = "$K" ] && ok || bad "one steps row per room step"
tail -1 "$T/l1/steps-001.csv" | grep -q ',Wrf,[0-3],0,15,[0-9]*$' && ok ||
    bad "last step row: $(tail -1 "$T/l1/steps-001.csv")"
rec "$LEVEL" "SN$WALK" >"$T/detour.rec"
run "detour" 0 "$H" replay "$T/detour.rec"
grep -q "^level lv done steps $((K + 2)) optimum $K " "$T/out" && ok ||
    bad "detour: $(cat "$T/out"), want done $((K + 2)) $K"

# byte for byte: the same recording twice gives the same logs; frames render
run "again" 0 "$H" replay "$T/opt.rec" --log "$T/l2" --png-frames 0,3 --out-dir "$T/png" --size 64x48
diff -r "$T/l1" "$T/l2" >/dev/null && ok || bad "replay logs differ between runs"
for f in 000000 000003; do
    head -c 8 "$T/png/frame-$f.png" | od -An -c | grep -q 'P   N   G' && ok || bad "frame $f is not a PNG"
done
# --lang (issue 37): the frames' text in German, the logs byte for byte the same
mkdir "$T/l2de" "$T/pngde"
run "german" 0 "$H" replay "$T/opt.rec" --log "$T/l2de" --png-frames 0,3 --out-dir "$T/pngde" \
    --size 64x48 --lang de
diff -r "$T/l1" "$T/l2de" >/dev/null && ok || bad "replay --lang de: the logs differ"
cmp -s "$T/png/frame-000003.png" "$T/pngde/frame-000003.png" && bad "--lang de: the same frame" || ok
run "lang bad" 2 "$H" replay "$T/opt.rec" --lang xx && one_line "lang bad" "not en, de or nl"
# a frame the recording never reaches: one line, exit 2, the others written
run "frame beyond" 2 "$H" replay "$T/opt.rec" --png-frames 2,99999 --out-dir "$T/png2" \
    --size 64x48
one_line "frame beyond" "frame 99999 is beyond the recording"
[ -f "$T/png2/frame-000002.png" ] && ok || bad "frame beyond: frame 2 was not written"

# keys and chest: both keys, then the chest
LEVEL='mode keys
seed 3
keys Nf Wr
chest Sf'
"$H" tour - Nf Wr Sf >"$T/tour" || bad "tour"
K=$(cut -d' ' -f1 "$T/tour") WALK=$(cut -d' ' -f2 "$T/tour")
rec "$LEVEL" "$WALK" >"$T/keys.rec"
run "keys" 0 "$H" replay "$T/keys.rec" --log "$T/l3"
grep -q "^level lv done steps $K optimum $K " "$T/out" && ok || bad "keys: $(cat "$T/out")"

# two levels: the first done, confirm, the second done; then a restart
# (the summary has a row per attempt)
{
    printf 'holonomy-rec 1\nlevel a\nL mode flag\nL seed 5\nL flag Wrf\nend\n'
    printf 'level b\nL mode keys\nL seed 3\nL keys Nf Wr\nL chest Sf\nend\n'
    walk_input "$(cut -d' ' -f2 "$T/nav")"
    walk_input - 50 1
    walk_input "$WALK" 60
    walk_input - 80 1
} >"$T/two.rec"
mkdir "$T/l4"
run "two levels" 0 "$H" replay "$T/two.rec" --log "$T/l4"
grep -q "^level b done steps $K optimum $K " "$T/out" && ok || bad "two levels: $(cat "$T/out")"
[ "$(grep -c ',done,,,$' "$T/l4/summary.csv")" = 2 ] && ok || bad "two levels: $(cat "$T/l4/summary.csv")"
grep -q ',2,,,,b,[0-9a-f]*,keys,3,' "$T/l4/summary.csv" && ok || bad "attempt 2 is level b"
{
    printf 'holonomy-rec 1\nlevel a\nL mode flag\nL seed 5\nL flag Wrf\nend\n'
    walk_input SN
    walk_input "$(cut -d' ' -f2 "$T/nav")" 10 20
} >"$T/restart.rec"
mkdir "$T/l5"
run "restart" 0 "$H" replay "$T/restart.rec" --log "$T/l5"
sed -n 2p "$T/l5/summary.csv" | grep -q ',1,,,,a,[0-9a-f]*,flag,5,15,"4,5",3x3,1,[0-9.]*,2,[0-9]*,[0-9.]*,restart,,,$' && ok ||
    bad "restart row: $(cat "$T/l5/summary.csv")"
sed -n 3p "$T/l5/summary.csv" | grep -q ',2,,,,a,[0-9a-f]*,flag,5,15,"4,5",3x3,1,[0-9.]*,\([0-9]*\),\1,[0-9.]*,done,,,$' && ok ||
    bad "done after restart: $(cat "$T/l5/summary.csv")"
[ "$(($(wc -l <"$T/l5/steps-001.csv") - 1))" = 2 ] && ok || bad "2 steps before the restart"

# the tutorial's lessons in order: a step ahead (N); round a tree back to
# the cell (ESWN); a marker 2 tiles away in a straight line the room allows
# (SS: the north row has the hedge ahead); a flag ahead, ahead, left:
# targets from `tile walk`, walks from `nav`
P=NESWN
A2=$(printf '%sSS\n' "$P" | "$H" tile walk | cut -d' ' -f1)
W2=$(printf '%s %s\n' "$P" "$A2" | "$H" nav | cut -d' ' -f2)
A3=$(printf '%s%sNNW\n' "$P" "$W2" | "$H" tile walk | cut -d' ' -f1)
W3=$(printf '%s%s %s\n' "$P" "$W2" "$A3" | "$H" nav | cut -d' ' -f2)
{
    printf 'holonomy-rec 1\nlevel tut\nL mode tutorial\nend\n'
    walk_input "$P$W2$W3"
} >"$T/tut.rec"
N=$(printf '%s%s%s' "$P" "$W2" "$W3" | wc -c)
run "tutorial" 0 "$H" replay "$T/tut.rec"
grep -q "^level tut done steps $N optimum -1 " "$T/out" && ok || bad "tutorial: $(cat "$T/out")"
{
    printf 'holonomy-rec 1\nlevel tut\nL mode tutorial\nend\n'
    walk_input "N$W2$W3"
} >"$T/tut2.rec"
run "tutorial out of order" 0 "$H" replay "$T/tut2.rec"
grep -q "^level tut playing " "$T/out" && ok || bad "lessons out of order: $(cat "$T/out")"

# bad recordings: exit 2, one line naming the line
printf 'hello\n' >"$T/bad1"
run "no header" 2 "$H" replay "$T/bad1" && one_line "no header" "line 1"
printf 'holonomy-rec 6\n' >"$T/bad2"
run "version" 2 "$H" replay "$T/bad2" && one_line "version" "version 1 to 5"
{ rec "$LEVEL" "N"; printf '9 m=4,0\n'; } >"$T/bad3"
run "bad input line" 2 "$H" replay "$T/bad3" && one_line "bad input line" "line 10"
printf 'holonomy-rec 1\nlevel x\nL mode flag\nL flug Nf\nend\n0\n' >"$T/bad4"
run "bad level line" 2 "$H" replay "$T/bad4" && one_line "bad level line" "line 4"
printf 'holonomy-rec 1\nlevel x\nL mode flag\nL flag O\nend\n0\n' >"$T/bad5"
run "objective on the start" 2 "$H" replay "$T/bad5" && one_line "start" "start tile"
{ rec "$LEVEL" "N"; printf '0 f=8\n'; } >"$T/bad6"
run "time going back" 2 "$H" replay "$T/bad6" && one_line "time going back" "line 10"
run "missing" 2 "$H" replay "$T/nonexistent"
run "no args" 2 "$H" replay
run "png without dir" 2 "$H" replay "$T/opt.rec" --png-frames 1
# ---- geometry: a recording's level lines give the tiling, room and cell -----
{ printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nstart 2026-01-31T14:05:09Z\n'
  printf 'version 0.1.0\nlevel g\nL tiling 4 6\nL room 4 4\nL cell 0.75\nL mode flag\n'
  printf 'L seed 5\nL flag Wrf\nend\n'
  awk 'BEGIN { for (k = 0; k < 60; k++) printf "%.17g f=8 m=0,1\n", k / 60 }'; } >"$T/geo.rec"
mkdir "$T/geo1" "$T/geo2"
run "replay {4,6} 4x4 0.75 m" 0 "$H" replay "$T/geo.rec" --log "$T/geo1"
# 1 s at 1.4 m/s from z = 2.5 * 0.75 = 1.875 m crosses z = 1.5 and 0.75: two steps
grep -q '^level g playing steps 2 optimum 3 tile Nf cell 2,0$' "$T/out" && ok ||
    bad "geometry replay: $(cat "$T/out")"
grep -q ',flag,5,15,"4,6",4x4,0.75,0.0000,2,3,' "$T/geo1/summary.csv" && ok ||
    bad "geometry columns: $(cat "$T/geo1/summary.csv")"
awk -F, 'NR == 2 { exit !($6 == "1.8750" && $7 == "1.6000" && $8 == "1.8750") }' \
    "$T/geo1/head-001.csv" && ok || bad "the head does not start at (1.875, 1.6, 1.875)"
run "replay with the same options" 0 "$H" replay "$T/geo.rec" --log "$T/geo2" --tiling 4,6 \
    --room 4x4 --cell 0.75
diff -r "$T/geo1" "$T/geo2" >/dev/null && ok || bad "the same options changed the replay"
run "replay with another tiling" 2 "$H" replay "$T/geo.rec" --tiling 4,7 &&
    one_line "conflict" "level 'g' was recorded in {4,6}; --tiling 4,7 would replay it in another geometry"
run "replay with a bad cell" 2 "$H" replay "$T/geo.rec" --cell 1.55 &&
    one_line "bad cell" "--cell needs metres from 0.5 to 1.5"
# a {4,8} level no walk completes is refused before the replay
sed 's/^L tiling 4 6$/L tiling 4 8/; s/^L flag Wrf$/L flag Nf/; /^L room/d' "$T/geo.rec" >"$T/geo8.rec"
run "replay {4,8} out of reach" 2 "$H" replay "$T/geo8.rec" &&
    one_line "out of reach" "level 'g' cannot start: line 5: no walk inside its room reaches an objective"

# steps only from a worn headset (core/hol_input.h): a headset's head walks
# 1.2 m east with the headset off (flag 200) and stands there worn again:
# no room step, one relocated row; the same lines without the state walk one
# step east; the state is in the records, so the replay reproduces it
worn_rec() {
    printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nstart 2026-01-31T14:05:09Z\n'
    printf 'version 0.1.0\nlevel e\nL mode explore\nL seed 3\nL minimap off\nend\n'
    awk -v off="$1" 'BEGIN { for (k = 0; k < 150; k++) { x = 1.5 + (k < 30 ? 0 : k > 90 ? 1.2 : (k - 30) * 0.02);
        printf "%.4f f=%s h=%.4f,1.6,1.5,0,0,0,1\n", k / 72.0, (k >= 30 && k <= 90) ? off : "109", x } }'
}
worn_rec 309 >"$T/off.rec"
worn_rec 109 >"$T/on.rec"
mkdir "$T/off1" "$T/off2" "$T/on1"
run "headset off: replay" 0 "$H" replay "$T/off.rec" --log "$T/off1"
[ "$(wc -l <"$T/off1/steps-001.csv")" = 1 ] && ok || bad "headset off: steps $(cat "$T/off1/steps-001.csv")"
[ "$(grep -c ',relocated,1.200$' "$T/off1/events.csv")" = 1 ] && ok ||
    bad "headset off: events $(cat "$T/off1/events.csv" 2>&1)"
run "headset off: replay again" 0 "$H" replay "$T/off.rec" --log "$T/off2"
diff -r "$T/off1" "$T/off2" >/dev/null && ok || bad "headset off: the replays differ"
run "headset worn: replay" 0 "$H" replay "$T/on.rec" --log "$T/on1"
[ "$(grep -c ',E,' "$T/on1/steps-001.csv")" = 1 ] && [ ! -e "$T/on1/events.csv" ] && ok ||
    bad "headset worn: steps $(cat "$T/on1/steps-001.csv")"

finish cli_replay
