#!/bin/sh
# cli_resume.sh - `play --resume` / `xr --resume` (issue 26 item 4): a
# participant continues at the first level of their order that has no
# finished attempt (end done or timeout) in the log folder; `position`
# keeps its meaning; a practice block already done is not played again.
# Refused with one line (exit 2): nothing to resume (no rows, or every
# level finished), a study other than the one the folder's rows were
# played with, --resume with --restart-participant, without --study or
# --log. Under Xvfb (when installed) three sessions of one participant,
# each driven by an --input file, one killed with SIGKILL, and a replay
# of a resumed session's recording.
. "$(dirname "$0")/lib.sh"

mkdir "$T/s" "$T/hand"
printf 'mode flag\nseed 5\nflag Nf\n' >"$T/s/f.lvl"
printf 'study rs\npractice f.lvl\ncondition a\nlevel f.lvl\nset minimap hud\ncondition b\nlevel f.lvl\nset minimap hand\n' >"$T/s/rs.study"
S=$T/s/rs.study

# ---- the option's rules (no window needed: refused before one opens) ----
run "resume and restart" 2 env DISPLAY= "$H" play --study "$S" --participant P01 --log "$T/l0" \
    --resume --restart-participant
one_line "resume and restart" "give --resume or --restart-participant, not both"
run "xr resume and restart" 2 "$H" xr --study "$S" --participant P01 --log "$T/l0" \
    --resume --restart-participant
one_line "xr resume and restart" "give --resume or --restart-participant, not both"
run "resume without study" 2 "$H" play --mode flag --log "$T/l0" --resume
one_line "resume without study" "--resume goes with --study"
run "resume without log" 2 "$H" play --study "$S" --participant P01 --resume
one_line "resume without log" "--resume goes with --log"
run "xr resume without log" 2 "$H" xr --study "$S" --participant P01 --resume
one_line "xr resume without log" "--resume goes with --log"
run "resume twice" 2 "$H" play --study "$S" --participant P01 --log "$T/l0" --resume --resume
run "help" 0 "$H" play --help
grep -q -- "--resume" "$T/out" && ok || bad "play --help names --resume"
run "xr help" 0 "$H" xr --help
grep -q -- "--resume" "$T/out" && ok || bad "xr --help names --resume"

# ---- nothing to resume, another study: hand-made folders, no window ----
H_ROW='session,participant,session_start,version,attempt,study,condition,position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end'
{ echo "$H_ROW"
  echo 'S1,P01,2026-01-01T00:00:00Z,1.0,1,rs,practice,0,f,00,flag,5,15,"4,5",3x3,1,0.0000,8,8,9.5000,done'
} >"$T/hand/summary.csv"
run "no rows of P02" 2 env DISPLAY= "$H" play --study "$S" --participant P02 --log "$T/hand" --resume
one_line "no rows of P02" "participant P02 has no data for study rs in '.*hand': nothing to resume"
sed 's/^study rs/study other/' "$S" >"$T/s/other.study"
run "no rows in study other" 2 env DISPLAY= "$H" play --study "$T/s/other.study" --participant P01 \
    --log "$T/hand" --resume
one_line "no rows in study other" "no data for study other"
run "empty folder" 2 env DISPLAY= "$H" play --study "$S" --participant P01 --log "$T/l0" --resume
one_line "empty folder" "nothing to resume"
[ ! -e "$T/l0" ] && ok || bad "a refused resume left the folder it made"
run "another level text" 2 env DISPLAY= "$H" play --study "$S" --participant P01 --log "$T/hand" --resume
one_line "another level text" "the study given is not the one participant P01 played in '.*hand': their attempt 1 (condition practice, position 0, level f)"
[ "$(ls "$T/hand")" = summary.csv ] && ok || bad "a refused resume made files: $(ls "$T/hand")"
# the participant check names --resume
run "P01 has data" 2 env DISPLAY= "$H" play --study "$S" --participant P01 --log "$T/hand" --append
one_line "P01 has data" "already has data for study rs .*--resume continues it"

if ! command -v Xvfb >/dev/null 2>&1; then
    echo "note: no Xvfb here: resumed sessions are not played"
    finish cli_resume
    exit $?
fi
start_xvfb 31 || { bad "Xvfb did not start"; finish cli_resume; exit $?; }
case $H in /*) ;; *) H=$PWD/$H ;; esac
cd "$T" || exit 1

# in1: the level done (5 steps, optimal), confirm (the next level starts),
# and the input ends: that next attempt ends `open`, unfinished
{ walk_input WNESE; printf '1.5 f=9 p=1 h=2.5,1.6,1.5,0,0,0,1\n1.75 f=9 h=2.5,1.6,1.5,0,0,0,1\n'; } >in1
# in1r: in1 after a resumed session's ready screen, confirmed at once
{ printf '0 f=9 p=1 h=1.5,1.6,1.5,0,0,0,1\n'; walk_input WNESE 0.25
  printf '1.75 f=9 p=1 h=2.5,1.6,1.5,0,0,0,1\n2 f=9 h=2.5,1.6,1.5,0,0,0,1\n'; } >in1r
P="$H play --study $S --participant P01 --size 64x48 --log logs"
# rows: "attempt condition position end" of the summary
rows() { awk -F, 'NR > 1 { print $5, $7, $8, $(NF-3) }' logs/summary.csv | tr '\n' ';'; } # end: before session_no, study_sha256, meta

# session 1: practice done, condition 1 left open
run "session 1" 0 $P --input in1
[ "$(rows)" = "1 practice 0 done;2 a 1 open;" ] && ok || bad "session 1: $(rows)"
cp -r logs pre2
# session 2 resumes at position 1 (the practice done is not played again)
run "session 2" 0 $P --input in1r --resume --record s2.rec
grep -q "practice, a, b; resumed at a (position 1), level 2 of 3\$" err && ok ||
    bad "session 2's order line: $(cat err)"
[ "$(rows)" = "1 practice 0 done;2 a 1 open;3 a 1 done;4 b 2 open;" ] && ok || bad "session 2: $(rows)"
# its recording replays (appended to the folder as it was) to the same summary
run "replay session 2" 0 "$H" replay s2.rec --log pre2 --append
cmp -s logs/summary.csv pre2/summary.csv && ok ||
    bad "the resumed session's replay: $(cat pre2/summary.csv)"
# a study whose condition a has another set line: its rows were not played with it
sed 's/set minimap hud/set minimap off/' "$S" >s/changed.study
run "changed study" 2 "$H" play --study s/changed.study --participant P01 --size 64x48 --log logs \
    --input in1r --resume
one_line "changed study" "is not the one participant P01 played in 'logs': their attempt 2 (condition a, position 1"

# session 3 killed (SIGKILL) in condition b: that attempt is unfinished
awk 'BEGIN { for (k = 0; k < 20000; k++) printf "%.2f f=9%s h=1.5,1.6,1.5,0,0,0,1\n", k * 0.05, k ? "" : " p=1" }' >slow.in # far more than 0.3 s of frames
$P --input slow.in --resume >/dev/null 2>&1 &
pid=$!
wait_for 60 -e logs/attempt-005.live
sleep 0.3
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
[ -f logs/attempt-005.live ] && ok || bad "session 3 left no attempt-005.live: $(ls logs)"
# session 4 resumes at b (position 2) again and finishes the study
run "session 4" 0 $P --input in1r --resume
grep -q "resumed at b (position 2), level 3 of 3\$" err && ok || bad "session 4's order line: $(cat err)"
[ "$(rows)" = "1 practice 0 done;2 a 1 open;3 a 1 done;4 b 2 open;5 b 2 killed;6 b 2 done;" ] && ok ||
    bad "session 4: $(rows)"
# every level finished: nothing to resume, nothing written
cp logs/summary.csv before.csv
run "finished" 2 $P --input in1r --resume
one_line "finished" "participant P01 has finished study rs in 'logs': nothing to resume"
cmp -s before.csv logs/summary.csv && ok || bad "a refused resume changed the summary"
# a timeout finishes a level too: participant 2 (order b, a) times out in practice
printf 'study rs\npractice t.lvl\ncondition a\nlevel f.lvl\nset minimap hud\ncondition b\nlevel f.lvl\nset minimap hand\n' >"$T/s/t.study"
printf 'mode flag\nseed 5\nflag Nf\ntime-limit 1\n' >"$T/s/t.lvl"
walk_input WNESWNEE >tl.in
run "P02 timeout" 0 "$H" play --study "$T/s/t.study" --participant P02 --size 64x48 --log tlogs --input tl.in
run "P02 resumes" 0 "$H" play --study "$T/s/t.study" --participant P02 --size 64x48 --log tlogs --input in1r --resume
grep -q "practice, b, a; resumed at b (position 1), level 2 of 3\$" err && ok ||
    bad "a practice ended by its time limit is played again: $(cat err) $(cat tlogs/summary.csv)"
# one level file twice in a condition: the one attempt done finishes the first only
printf 'study tw\ncondition a\nlevel f.lvl\nlevel f.lvl\nset minimap hud\ncondition b\nlevel f.lvl\n' >"$T/s/tw.study"
run "twice: session 1" 0 "$H" play --study "$T/s/tw.study" --participant P01 --size 64x48 --log twl --input in1
run "twice: resumed" 0 "$H" play --study "$T/s/tw.study" --participant P01 --size 64x48 --log twl --input in1r --resume
grep -q "a, b; resumed at a (position 1), level 2 of 3\$" err && ok || bad "twice: $(cat err)"
finish cli_resume
