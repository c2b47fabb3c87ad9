#!/bin/sh
# cli_harden_inputs.sh - issue 39 (Hardening 4), the inputs a command reads
# and the option grammar, through the binary; each check failed before its
# fix (findings 5 and 6 are in cli_meta.sh and test_study.c, and the
# hostile corpus has a case of each):
# - finding 1: every file a command reads, a study's levels included, is
#   never one it writes: --record over a study's level, an input that is a
#   file of the --log folder (also through a link), xr as play;
# - finding 16: one number grammar (decimal: no hex but seeds', no '+',
#   no ".5" or "5.", finite, no underflow, no sign on a value that cannot
#   be negative), --restart-participant with --append, repeated keys
#   refused in studies and levels (allow, a questionnaire's item, a choice),
#   render --lantern as a level's place lantern, uniform "set: " prefixes
#   and the real reason for `questionnaire ssq before level`.
. "$(dirname "$0")/lib.sh"
cd "$T" || exit 1
case $H in /*) ;; *) H=$OLDPWD/$H ;; esac

printf 'mode flag\nflag Nf\n' >a.lvl
cp a.lvl keep.lvl
printf 'study s\ncondition c\nlevel a.lvl\n' >s.study
printf '0 f=9\n' >in.txt

# --- finding 1: the study's levels and the log folder's files -------------
for c in play xr; do
  run "$c: --record over the study's level" 2 env DISPLAY= "$H" $c --study s.study \
      --participant P1 --record a.lvl --input in.txt
  one_line "$c: --record over the study's level" \
      "--record 'a.lvl' is the study's level 'a.lvl', which this command reads"
  cmp -s a.lvl keep.lvl && ok || bad "$c: the study's level changed"
  ln -sf a.lvl link.lvl
  run "$c: --record over a link to the study's level" 2 env DISPLAY= "$H" $c --study s.study \
      --participant P1 --record link.lvl --input in.txt
  one_line "$c: --record link" "the study's level 'a.lvl'"
done
mkdir logs
printf 'mode flag\nflag Nf\n' >logs/summary.csv
printf '0 f=9\n' >logs/environment.csv
run "LEVEL is the log folder's summary.csv" 2 env DISPLAY= "$H" play logs/summary.csv \
    --log logs --append --input in.txt
one_line "LEVEL summary.csv" "LEVEL 'logs/summary.csv' is 'summary.csv' of --log 'logs', which this command writes"
ln -s logs/environment.csv env.in
run "--input links to environment.csv" 2 env DISPLAY= "$H" play a.lvl --log logs --append \
    --input env.in
one_line "--input environment.csv" "--input 'env.in' is 'environment.csv' of --log 'logs'"
run "xr: --input is summary.csv" 2 "$H" xr a.lvl --log logs --append --input logs/summary.csv
one_line "xr --input summary.csv" "--input 'logs/summary.csv' is 'summary.csv' of --log"
printf 'study s\ncondition c\nlevel logs/summary.csv\n' >t.study
run "a study's level in the log folder" 2 env DISPLAY= "$H" play --study t.study \
    --participant P1 --log logs --append --input in.txt
one_line "a study's level in the log folder" "the study's level 'logs/summary.csv' is 'summary.csv' of --log 'logs'"
# replay: a recording under a log file's name in its --log folder (the
# folder's recovery removed it)
printf '%s\n' "holonomy-rec 2" "session 20260131T140509Z-5f3a9c01" "participant P01" \
    "start 2026-01-31T14:05:09Z" "version 0.1.0" "level f" "L mode flag" "L seed 5" \
    "L flag Nf" "end" "0 f=9" >logs/attempt-009.live
run "replay: the recording is a live log file" 2 "$H" replay logs/attempt-009.live --log logs --append
one_line "replay live" "the recording 'logs/attempt-009.live' is 'attempt-009.live' of --log 'logs'"
[ -f logs/attempt-009.live ] && ok || bad "replay removed its own recording"
rm -f logs/attempt-009.live
# a level beside the logs, under another name, is no log file
cp a.lvl logs/mine.lvl
"$H" play logs/mine.lvl --log logs --append --input in.txt >"$T/out" 2>"$T/err"
grep -q "which this command writes" "$T/err" && bad "logs/mine.lvl refused" || ok

# --- finding 16: one number grammar -----------------------------------------
for v in 0x1 1e-400 -0 .5 5. +0.5 " 0.5" inf nan 1.5 ""; do
  run "--volume '$v'" 2 env DISPLAY= "$H" play a.lvl --volume "$v"
  one_line "--volume '$v'" "--volume '$v' is not a number in 0..1"
done
for v in 0 1 0.5 1e0 5e-1; do
  "$H" play a.lvl --volume "$v" --frames 1 >"$T/out" 2>"$T/err"
  grep -q -- "--volume" "$T/err" && bad "--volume '$v' refused: $(cat "$T/err")" || ok
done
for v in "--fireflies|-0" "--fireflies|.5" "--stereo|-0" "--yaw|-.5e-1" "--yaw|5." \
         "--pitch|+5" "--fov|0x5A"; do
  run "render ${v%%|*} '${v#*|}'" 2 "$H" render --bare --stats "${v%%|*}" "${v#*|}"
  one_line "render ${v%%|*} '${v#*|}'" "${v%%|*} '"
done
run "render --yaw -0.5e-1" 0 "$H" render --bare --stats --yaw -0.5e-1 --fireflies 0
run "xr --play-area 0x2x2" 2 "$H" xr --play-area 0x2x2
one_line "xr --play-area 0x2x2" "--play-area '0x2x2' is not WxD"
run "xr --play-area .5x2" 2 "$H" xr --play-area .5x2
run "world --radius 0x3" 2 "$H" world --radius 0x3 --quiet
one_line "world --radius 0x3" "--radius '0x3' is not a number"
run "world --capacity 0x100" 2 "$H" world --capacity 0x100 --quiet
run "props --scale 1:0x10" 2 "$H" props --level a.lvl --scale 1:0x10 --out p.svg
one_line "props --scale" "--scale needs 1:N"
run "replay --png-frames +3" 2 "$H" replay nothing.rec --png-frames +3 --out-dir .
run "seeds keep 0x (SPEC 7)" 0 "$H" world --seed 0x10 --quiet

# --- finding 16: the options' and the files' repeats and reasons ------------
run "--restart-participant without --append" 2 env DISPLAY= "$H" play --study s.study \
    --participant P1 --log l2 --restart-participant
one_line "restart without append" "--restart-participant goes with --append"
run "xr: --restart-participant without --append" 2 "$H" xr --study s.study \
    --participant P1 --log l2 --restart-participant
one_line "xr: restart without append" "--restart-participant goes with --append"
study_refused() { # NAME WANT LINES...: a study of LINES then one condition
  sr_name=$1 sr_want=$2; shift 2
  printf '%b\n' "study s" "$@" "condition a" "set mode explore" >r.study
  run "$sr_name" 2 env DISPLAY= "$H" play --study r.study --participant P1
  one_line "$sr_name" "$sr_want"
}
study_refused "allow twice" "line 3: allow minimap-toggle is given twice (line 2)" \
    "allow minimap-toggle" "allow minimap-toggle"
study_refused "an item twice" "line 3: questionnaire mine lists 'fun' twice" \
    'question fun likert 1 7 "Fun?" "a" "b"' "questionnaire mine fun fun"
study_refused "a choice twice" "line 2: question hand: choice 3 is choice 1 again ('left')" \
    'question hand choice "Which?" "left" "right" "left"'
study_refused "ssq during level" \
    "line 2: questionnaire ssq during level: a questionnaire is placed with 'after|before level|condition|study'" \
    "questionnaire ssq during level"
study_refused "ssq before before_level" \
    "line 2: questionnaire ssq before 'before_level': level, condition or study" \
    "questionnaire ssq before before_level"
study_refused "set place lantern: not canonical" "line 3: set: 'Nrr' is not a canonical address" \
    "set lighting night" "set place lantern Nrr"
study_refused "set place lantern twice" "line 4: set: a lantern on Nf is already placed on line 3" \
    "set lighting night" "set place lantern Nf" "set place lantern Nf"
study_refused "a placement twice" "line 3: questionnaire ssq after level is given twice (line 2)" \
    "questionnaire ssq after level" "questionnaire ssq after level"
printf 'mode explore\nask ssq level\nask ssq level\n' >q2.lvl
run "a level's ask twice" 2 "$H" game q2.lvl </dev/null
one_line "a level's ask twice" "line 3: ask ssq level is given twice"
printf 'mode explore\nquestion fun likert 1 7 "Fun?" "a" "b"\nask mine level fun fun\n' >q.lvl
run "a level's ask lists an item twice" 2 "$H" game q.lvl </dev/null
one_line "a level's ask twice" "line 3: ask mine lists 'fun' twice"
run "render --lantern Nrr" 2 "$H" render --bare --stats --lighting night --lantern Nrr
one_line "render --lantern Nrr" "--lantern 'Nrr' is not a canonical address of {4,5}"
printf 'mode flag\nflag Nf\nlighting night\nplace lantern Nrr\n' >nrr.lvl
run "a level's place lantern Nrr (the same rule)" 2 "$H" game nrr.lvl </dev/null
run "render --lantern twice" 2 "$H" render --bare --stats --lighting night --lantern Nf \
    --lantern Nf
one_line "render --lantern twice" "--lantern 'Nf' is given twice"
run "render --lantern Nf" 0 "$H" render --bare --stats --lighting night --lantern Nf

finish cli_harden_inputs
