#!/bin/sh
# cli_ask.sh - questionnaires in a study (docs/research.md "Questionnaires"):
# a session played headless from an --input file answers its own items and
# the SSQ after the level's end screen with the keys' axes and confirm;
# answers.csv holds one row per answer (questionnaire, when, item, kind,
# value, time taken); the recording replays it byte for byte; a folder
# holding answers.csv is refused without --append; bad lines one line.
. tests/lib.sh

start_xvfb 37 || { echo "cli_ask: no Xvfb, skipped"; exit 0; }

printf 'mode flag\nseed 7\nflag N\n' >"$T/a.lvl"
cat >"$T/s.study" <<'S'
study asks
question fun likert 1 7 "How much fun was it?" "none" "a lot"
question hand choice "Which hand did you use?" "left" "right, mostly" "both"
questionnaire mine fun hand
questionnaire mine after level
questionnaire ssq after study
condition one
level a.lvl
S
# R T [PRESSED] [MORE]: a head in cell (1, R) at time T
f() { printf '%s f=9%s h=1.5,1.6,%s.5,0,0,0,1%s\n' "$2" "${3:+ p=$3}" "$1" "${4:+ $4}"; }
{ f 1 0; f 0 0.5; f 0 1 1                        # done; confirm: the questionnaires
  f 0 1.5 "" m=1,0; f 0 2 "" m=1,0; f 0 2.5; f 0 3 "" m=1,0; f 0 3.5 1  # fun 4 -> 6
  f 0 4 "" t=1,0; f 0 4.5 1                       # hand: right, mostly -> left
  i=0; t=5
  while [ $i -lt 16 ]; do                         # the SSQ: 1 - 1 = 0 each ...
    f 0 $t "" t=1,0; f 0 $t.5 1; t=$((t + 1)); i=$((i + 1))
  done
  f 0 $t 1; f 0 $((t + 1)); } >"$T/in"            # the closing screen; the end
run "play" 0 "$H" play --study "$T/s.study" --participant P03 --input "$T/in" --size 64x48 \
    --log "$T/l" --record "$T/r.rec"
head -1 "$T/l/answers.csv" | grep -qx 'session,participant,attempt,questionnaire,when,item,kind,value,time,shown_ms,answered_ms' &&
  ok || bad "answers.csv header: $(head -1 "$T/l/answers.csv")"
cut -d, -f2- "$T/l/answers.csv" | sed -n '2,5p' >"$T/got"
cat >"$T/want" <<'W'
P03,1,mine,level,fun,likert,6,2.5000,1000,3500
P03,1,mine,level,hand,choice,left,1.0000,3500,4500
P03,1,ssq,study,general_discomfort,likert,0,1.0000,4500,5500
P03,1,ssq,study,fatigue,likert,0,1.0000,5500,6500
W
cmp -s "$T/got" "$T/want" && ok || { bad "answers.csv rows:"; diff "$T/want" "$T/got"; }
[ "$(wc -l <"$T/l/answers.csv")" = 19 ] && ok || bad "answers.csv: $(wc -l <"$T/l/answers.csv") lines, want 19"
tail -1 "$T/l/answers.csv" | cut -d, -f4-8 | grep -qx 'ssq,study,burping,likert,0' && ok ||
  bad "last answer: $(tail -1 "$T/l/answers.csv")"
tail -1 "$T/r.rec" | grep -q "^21 " && ok || bad "the session ended at $(tail -1 "$T/r.rec")"
mkdir "$T/l2"
run "replay" 0 "$H" replay "$T/r.rec" --log "$T/l2"
logs_diff "$T/l" "$T/l2" >/dev/null && ok || bad "the replay's logs differ"
# a folder whose answers.csv has the header of the build before the
# timestamps (shown_ms, answered_ms) is appended to in its own columns
mkdir "$T/l4"
printf 'session,participant,attempt,questionnaire,when,item,kind,value,time\n' >"$T/l4/answers.csv"
run "replay into an old answers.csv" 0 "$H" replay "$T/r.rec" --log "$T/l4" --append
[ "$(cut -d, -f1-9 "$T/l/answers.csv")" = "$(cat "$T/l4/answers.csv")" ] && ok ||
    bad "old answers.csv: $(head -3 "$T/l4/answers.csv")"

# a play whose input ends with a questionnaire's item on screen: its end
# line says done (it printed bytes past the end of the state names' table:
# issue 39; tests/hostile/replay-ends-on-question replays one)
{ f 1 0; f 0 0.5; f 0 1 1; f 0 1.5; } >"$T/in-ask"
run "play ends on a question" 0 "$H" play --study "$T/s.study" --participant P04 \
    --input "$T/in-ask" --size 64x48
grep -qx 'level a done steps 1 optimum 1 tile N cell 1,0' "$T/out" && ok ||
    bad "play ends on a question: $(cat "$T/out")"

mkdir "$T/l3" && cp "$T/l/answers.csv" "$T/l3/"
run "folder with answers" 2 "$H" play "$T/a.lvl" --frames 1 --size 64x48 --log "$T/l3" &&
  one_line "folder with answers" "l3"

printf 'study s\nquestionnaire sus after level\ncondition a\nset mode explore\n' >"$T/b.study"
run "unknown questionnaire" 2 "$H" play --study "$T/b.study" --participant 1 --frames 1 --size 64x48 &&
  one_line "unknown questionnaire" "line 2: questionnaire sus is neither given"
printf 'mode flag\nflag N\nquestion q likert 1 7 "x" "y"\n' >"$T/b.lvl"
run "bad question" 2 "$H" play "$T/b.lvl" --frames 1 --size 64x48 &&
  one_line "bad question" "line 3: question q likert needs"
finish cli_ask
