#!/bin/sh
# cli_point.sh - the pointing question (level line `point start|objective`,
# SPEC 8; docs/levels.md, docs/research.md "points.csv"): a level played
# headless from an --input file asks at its end, the head turned to a known
# yaw confirms, and points.csv holds the row whose true and flat bearings are
# what `holonomy tile bearing` prints for the walk; the recording replays it
# byte for byte; bad `point` lines are refused with one line.
. tests/lib.sh

start_xvfb 23 || { echo "cli_point: no Xvfb, skipped"; exit 0; }

# yaw Y degrees (SPEC 1: positive towards the west) as a head quaternion
quat() { awk -v y="$1" 'BEGIN { h = y * 3.14159265358979 / 360; printf "0,%.7f,0,%.7f", sin(h), cos(h) }'; }

printf 'mode flag\nseed 7\nflag El\npoint start\n' >"$T/start.lvl"
walk_input EN >"$T/in"
q=$(quat 135) # bearing 225
{ echo "0.75 f=9 h=2.5,1.6,0.5,$q"
  echo "1.25 f=9 b=1 h=2.5,1.6,0.5,$q"
  echo "1.5 f=9 h=2.5,1.6,0.5,$q"; } >>"$T/in"
run "play start" 0 "$H" play "$T/start.lvl" --input "$T/in" --size 64x48 --log "$T/l1" \
    --participant P01 --record "$T/r1.rec"
grep -q "^level start done steps 2 " "$T/out" && ok || bad "play start: $(cat "$T/out")"
want=$(printf 'EN O\n' | "$H" tile bearing)  # "211.7 225.0"
[ "$want" = "211.7 225.0" ] && ok || bad "tile bearing EN O: $want"
head -1 "$T/l1/points.csv" | grep -qx \
  'session,participant,attempt,level,t,target,pointed,true,flat,error_true,error_flat,time,shown_ms,answered_ms' \
  && ok || bad "points.csv header: $(head -1 "$T/l1/points.csv")"
# the row less its session id: pointed 225, true 211.7 (13.3 off), flat 225 (0 off)
row=$(sed -n 2p "$T/l1/points.csv" | cut -d, -f2-)
[ "$row" = "P01,1,start,0.5000,start,225.0,211.7,225.0,13.3,0.0,0.7500,500,1250" ] && ok || bad "points row: $row"
[ "$(wc -l <"$T/l1/points.csv")" -eq 2 ] && ok || bad "points.csv rows: $(wc -l <"$T/l1/points.csv")"

# the recording replays the answer: the same logs byte for byte
run "replay" 0 "$H" replay "$T/r1.rec" --log "$T/l2"
cmp -s "$T/l1/points.csv" "$T/l2/points.csv" && ok || bad "replayed points.csv differs"
cmp -s "$T/l1/summary.csv" "$T/l2/summary.csv" && ok || bad "replayed summary.csv differs"

# the objective, never reached (time limit): flat empty, true from the
# start; the first confirm answers, the second finishes
printf 'mode flag\nseed 7\nflag Nfl\ntime-limit 1\npoint objective\n' >"$T/obj.lvl"
q=$(quat -90) # bearing 90
{ echo "0 f=9 h=1.5,1.6,1.5,0,0,0,1"
  echo "1 f=9 h=1.5,1.6,1.5,$q"
  echo "1.5 f=9 b=1 h=1.5,1.6,1.5,$q"
  echo "2 f=9 h=1.5,1.6,1.5,$q"
  echo "2.5 f=9 b=1 h=1.5,1.6,1.5,$q"; } >"$T/in2"
run "play objective" 0 "$H" play "$T/obj.lvl" --input "$T/in2" --size 64x48 --log "$T/l3"
grep -q "^level obj timeout " "$T/out" && ok || bad "play objective: $(cat "$T/out")"
tb=$(printf -- '- Nfl\n' | "$H" tile bearing | cut -d' ' -f1)
row=$(sed -n 2p "$T/l3/points.csv" | cut -d, -f3-)
err=$(awk -v p=90 -v t="$tb" 'BEGIN { e = p - t; while (e > 180) e -= 360; while (e <= -180) e += 360; printf "%.1f", e }')
[ "$row" = "1,obj,1.0000,objective,90.0,$tb,,$err,,0.5000,1000,1500" ] && ok || bad "objective row: $row (true $tb)"

# a log folder holding points.csv holds logs: refused without --append
mkdir "$T/l4" && cp "$T/l1/points.csv" "$T/l4/"
run "folder with points" 2 "$H" play "$T/start.lvl" --input "$T/in" --size 64x48 --log "$T/l4" &&
  one_line "folder with points" "l4"

# bad lines: one line naming it
printf 'mode flag\nflag El\npoint north\n' >"$T/bad1.lvl"
run "point north" 2 "$H" play "$T/bad1.lvl" --frames 1 --size 64x48 && one_line "point north" "line 3"
printf 'mode explore\npoint objective\n' >"$T/bad2.lvl"
run "explore objective" 2 "$H" play "$T/bad2.lvl" --frames 1 --size 64x48 &&
  one_line "explore objective" "point objective needs a mode with an objective"

finish cli_point
