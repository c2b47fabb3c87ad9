#!/bin/sh
# cli_ask_before.sh - a baseline questionnaire (issue 35): `questionnaire
# ssq before study` is asked when the first level starts, before its clock,
# logged in answers.csv with `when` before_study and the attempt that level
# begins; `tlx after study` after it; scores.csv scores the baseline with
# placement `before` and the TLX under the condition `study`, checked
# against values computed by hand; the recording replays byte for byte.
. tests/lib.sh

start_xvfb 41 || { echo "cli_ask_before: no Xvfb, skipped"; exit 0; }

printf 'mode flag\nseed 7\nflag N\n' >"$T/a.lvl"
cat >"$T/s.study" <<'S'
study base
questionnaire ssq before study
questionnaire tlx after study
condition one
level a.lvl
S
# R T [PRESSED]: a head in cell (1, R) at time T
f() { printf '%s f=9%s h=1.5,1.6,%s.5,0,0,0,1\n' "$2" "${3:+ p=$3}" "$1"; }
{ f 1 0
  t=1
  while [ $t -le 16 ]; do                  # the SSQ: each item its middle mark, 1
    f 1 $t 1; t=$((t + 1))
  done
  f 1 17; f 0 17.5                         # the level begins, done
  f 0 18 1                                 # confirm: the TLX
  t=19
  while [ $t -le 24 ]; do                  # each item its middle mark, 50
    f 0 $t 1; t=$((t + 1))
  done
  f 0 25; } >"$T/in"
run "play" 0 "$H" play --study "$T/s.study" --participant P01 --input "$T/in" --size 64x48 \
    --log "$T/l" --record "$T/r.rec"
a="$T/l/answers.csv"
[ "$(grep -c ',ssq,before_study,' "$a")" = 16 ] && ok || bad "baseline rows: $(cat "$a")"
sed -n 2p "$a" | cut -d, -f2-8 | grep -qx 'P01,1,ssq,before_study,general_discomfort,likert,1' &&
    ok || bad "first answer: $(sed -n 2p "$a")"
[ "$(grep -c ',1,tlx,study,[a-z]*,likert,50,' "$a")" = 6 ] && ok || bad "tlx rows: $(cat "$a")"
# the level's clock starts after the baseline: its attempt starts at 17 s
# (one step, optimum 1, time 0.5)
grep -q ',17.0000,1,1,0.5000,done,' "$T/l/summary.csv" && ok || bad "summary: $(cat "$T/l/summary.csv")"
mkdir "$T/l2"
run "replay" 0 "$H" replay "$T/r.rec" --log "$T/l2"
logs_diff "$T/l" "$T/l2" >/dev/null && ok || bad "the replay's logs differ"

# scores.csv: every SSQ item 1: each subscale's raw sum 7 (7 items each,
# Kennedy et al. 1993), N 7 x 9.54, O 7 x 7.58, D 7 x 13.92, total 21 x 3.74;
# raw TLX 50
run "report" 0 "$H" report "$T/l" --out "$T/rep"
s=$(sed -n 2p "$T/l/summary.csv" | cut -d, -f1)
for want in "P01,$s,1,base,study,before,study,ssq,total,78.5400,1," \
    "P01,$s,1,base,study,before,study,ssq,nausea,66.7800,1," \
    "P01,$s,1,base,study,before,study,ssq,oculomotor,53.0600,1," \
    "P01,$s,1,base,study,before,study,ssq,disorientation,97.4400,1," \
    "P01,$s,1,base,study,after,study,tlx,raw,50.0000,1," \
    "P01,$s,1,base,study,after,study,tlx,mental,50.0000,1,"; do
    grep -qx "$want" "$T/rep/scores.csv" && ok || bad "scores.csv: no $want: $(cat "$T/rep/scores.csv")"
done
# stats.csv: the TLX asked `after study` under the condition `study` (not
# the participant's last condition), listed after the study's conditions
grep -qx 'base,study,tlx_raw,,1,50.0000,,,' "$T/rep/stats.csv" && ok ||
    bad "stats.csv: after-study TLX: $(grep tlx_raw "$T/rep/stats.csv")"
[ "$(grep -c ',tlx_raw,' "$T/rep/stats.csv")" = 1 ] && [ "$(tail -1 "$T/rep/stats.csv" | cut -d, -f2)" = study ] &&
    ok || bad "stats.csv: $(cat "$T/rep/stats.csv")"

# cut in the baseline: its end line says the level was not played (not
# `done`); its answers so far are a partial questionnaire, in scores.csv
# with complete 0, never dropped
head -5 "$T/in" >"$T/in-cut"
run "play cut in the baseline" 0 "$H" play --study "$T/s.study" --participant P02 \
    --input "$T/in-cut" --size 64x48 --log "$T/l3"
grep -q '^level a playing steps 0 ' "$T/out" && ok || bad "cut in the baseline: $(cat "$T/out")"
[ "$(grep -c ',P02,1,ssq,before_study,' "$T/l3/answers.csv")" = 4 ] && ok ||
    bad "cut baseline: $(cat "$T/l3/answers.csv")"
run "report of a partial baseline" 0 "$H" report "$T/l3" --out "$T/rep3"
grep -q '^P02,[^,]*,1,,study,before,study,ssq,total,,0,$' "$T/rep3/scores.csv" && ok ||
    bad "partial baseline: $(cat "$T/rep3/scores.csv")"

# started again (--resume: nothing to resume, no attempt began): the level
# starts with its baseline asked whole (a new session, the same attempt
# number); the partial one stays in scores.csv beside the complete one
run "started again" 0 "$H" play --study "$T/s.study" --participant P02 --input "$T/in" --size 64x48 \
    --log "$T/l3" --append
[ "$(grep -c ',P02,1,ssq,before_study,' "$T/l3/answers.csv")" = 20 ] && ok ||
    bad "baseline again: $(cat "$T/l3/answers.csv")"
run "report of a baseline again" 0 "$H" report "$T/l3" --out "$T/rep4"
[ "$(grep -c '^P02,[^,]*,1,base,study,before,study,ssq,total,78.5400,1,$' "$T/rep4/scores.csv")" = 1 ] &&
    ok || bad "baseline again scores: $(cat "$T/rep4/scores.csv")"
grep -q '^P02,[^,]*,1,,study,before,study,ssq,total,,0,$' "$T/rep4/scores.csv" && ok ||
    bad "the partial baseline dropped: $(cat "$T/rep4/scores.csv")"

# the study file: before level|condition|study only
printf 'study s\nquestionnaire ssq before session\ncondition a\nlevel a.lvl\n' >"$T/b.study"
run "before session" 2 "$H" play --study "$T/b.study" --participant 1 --frames 1 --size 64x48 &&
    one_line "before session" "line 2: questionnaire ssq before 'session': level, condition or study"
finish cli_ask_before
