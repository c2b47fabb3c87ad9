#!/bin/sh
# cli_kills.sh - kills in a study with pointing and the SSQ (issue 39 item
# 3): a two-condition study (a pointing question after every level, the
# SSQ after each condition, instructions and a closing screen). Before the
# fix a kill, quit or close in a questionnaire or the pointing question
# lost the answers for good (--resume went on to the next level, or
# refused after the last), `report` dropped a cut SSQ silently, and a quit
# there printed `quit` for an attempt logged `done`.
# - At chosen moments (the session held there by frames 30 us apart, killed
#   once the file that shows it has its rows): the pointing question (the
#   level is played again), an SSQ's item 11 (asked from item 11 on the same
#   attempt, none twice; the resumed session's recording replays to the
#   same rows), the last SSQ, an SSQ with another participant's whole study
#   between the kill and the resume (scored whole by `report`); a quit in
#   an SSQ (printed `done`; asked again on resume).
# - At random moments: participants killed with SIGKILL after random
#   delays and resumed with --resume until their study is over; then every
#   level has its pointing answer, every condition its 16 SSQ items (none
#   twice), `report` takes the folder and scores every SSQ.
# HOL_KILLS: the random kills (default 12, as make test and make san-cli
# run it; make kill-test runs 60); HOL_KILL_SEED: the delays' seed
# (default: this shell's pid; printed with a failure).
# The play is scripted (--input): a cycle of frames that, whatever the
# state, walks the level's one step, answers the pointing question, the end
# screen, a screen or an item (the middle mark), so a resumed session takes
# the same input whatever it resumes at.
. "$(dirname "$0")/lib.sh"

if ! command -v Xvfb >/dev/null 2>&1; then
    echo "note: no Xvfb here: no study is killed"
    finish cli_kills
    exit $?
fi
start_xvfb 61 || { bad "Xvfb did not start"; finish cli_kills; exit $?; }
case $H in /*) ;; *) H=$PWD/$H ;; esac
KILLS=${HOL_KILLS:-12}
SEED=${HOL_KILL_SEED:-$$}
cd "$T" || exit 1

printf 'mode flag\nseed 3\nflag N\n' >a.lvl
cat >k.study <<'S'
study kills
counterbalance williams
closing Thank you.
set point start
questionnaire ssq after condition
condition one
instructions First block.
level a.lvl
level a.lvl
condition two
instructions Second block.
level a.lvl
set minimap hand
S
# gen CYCLES [LAST]: the cycle CYCLES times: standing in cell (1,1), a step
# north (the flag), back, confirm, confirm; every press in (1,1), so a
# level begins there. Then the line LAST (its flags) if given.
gen() {
    awk -v cycles="$1" -v last="${2:-}" '
     function line(extra, c, r) { printf "%.5f f=9%s h=%.1f,1.6,%.1f,0,0,0,1\n", t, extra, c + 0.5, r + 0.5; t += 0.05 }
     function hold(c, r,   k) { for (k = 0; k < 12; k++) line("", c, r) }
     BEGIN { for (n = 0; n < cycles; n++) {
         hold(1, 1); hold(1, 0); line(" p=1", 1, 1); hold(1, 1); line(" p=1", 1, 1); hold(1, 1) }
       if (last != "") line(last, 1, 1) }'
}
gen 30 >in.txt
# held: cycle 1 confirms the instructions and the ready screen (level 1
# begins; a resumed session: the ready screen), cycle 2 walks
# it, points and confirms its end screen; cycle 3 the same for level 2,
# whose end brings the SSQ (two items a cycle); cycles 4..11 its 16 items,
# 12 the next instructions, 13 level 3 and its end, 14.. its SSQ.
# held CYCLES FILE LINES WHAT: P1 into folder held/, its input CYCLES
# cycles, a step north and back, then 30,000 frames 30 us apart standing,
# killed once held/FILE has LINES lines (WHAT names the moment)
held() {
    rm -rf held
    gen "$1" >h.in
    awk 'END { t = $1 + 0.05
               for (k = 0; k < 12; k++) printf "%.5f f=9 h=1.5,1.6,1.5,0,0,0,1\n", t + k * 0.05
               for (k = 0; k < 12; k++) printf "%.5f f=9 h=1.5,1.6,0.5,0,0,0,1\n", t + 0.6 + k * 0.05
               for (k = 1; k <= 30000; k++) printf "%.5f f=9 h=1.5,1.6,0.5,0,0,0,1\n", t + 1.2 + k * 0.00003 }' \
        h.in >h.tail
    cat h.tail >>h.in
    $H play --study k.study --size 64x48 --log held --input h.in --participant P1 >/dev/null 2>&1 &
    pid=$!
    wait_for 60 -l "held/$2" "$3"
    kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
    [ "$(wc -l <"held/$2")" = "$3" ] && ok || bad "$4: not held there: $(wc -l <"held/$2") lines in $2"
}
# ---- kills at chosen moments -------------------------------------------------------------
# resumed NAME WANT [REC]: P1 resumed in held/ with the whole input, to the
# end (recorded to REC if given); stderr's order line ends with WANT
resumed() {
    run "$1" 0 $H play --study k.study --size 64x48 --log held --input in.txt --participant P1 \
        --resume ${3:+--record "$3"} && { grep -q "$2\$" err && ok || bad "$1: $(cat err), want '$2'"; }
}
# answered ATTEMPT N: held/answers.csv has N rows of attempt ATTEMPT, each
# item once
answered() {
    got=$(awk -F, -v a="$1" 'NR > 1 && $3 == a && !seen[$6]++ { n++ } NR > 1 && $3 == a { all++ }
                             END { print n + 0, all + 0 }' held/answers.csv)
    [ "$got" = "$2 $2" ] && ok || bad "attempt $1's answers: $got (distinct, all), want $2"
}
# the pointing question of level 1: its attempt is `done`, its answer lost;
# the level is played again (the question is about the walk just made)
held 1 summary.csv 2 "level 1's pointing question"
resumed "pointing lost" "resumed at one (position 1), level 1 of 3"
[ "$(awk -F, 'NR > 1 { print $3 }' held/points.csv | tr '\n' ' ')" = "2 3 4 " ] && ok ||
    bad "points after the resume: $(cat held/points.csv)"
# the first SSQ, 10 items answered: asked from item 11 on attempt 2
held 8 answers.csv 11 "the first SSQ's item 11"
cp -R held pre
resumed "SSQ cut" "resumed at one (position 1), level 2 of 3, its questions from item 11 (attempt 2)" r.rec
answered 2 16
answered 3 16
# its recording (an `ask` line) replayed into the folder as it was: the
# same answers and rows, byte for byte
grep -q "^ask [^ ]* 2 11\$" r.rec && ok || bad "the recording's ask line: $(grep -v '^[0-9L]' r.rec)"
run "replay of the resumed" 0 "$H" replay r.rec --log pre --append
for f in answers.csv points.csv summary.csv; do
    cmp -s held/$f pre/$f && ok || bad "the replay's $f differs"
done
rm -rf pre r.rec
# the last level's SSQ (6 answered): asked again, not "nothing to resume"
held 16 answers.csv 23 "the last SSQ's item 7"
resumed "last SSQ cut" "resumed at two (position 2), level 3 of 3, its questions from item 7 (attempt 3)"
answered 3 16
run "report of the resumed" 0 "$H" report held --out rep-held
# P1 killed in the first SSQ, P2 plays to the end, P1 resumed: P1's SSQ is
# in two runs of rows with P2's between, and scored whole
held 8 answers.csv 11 "the first SSQ's item 11, again"
t0=$(date +%s%N)
run "P2 between" 0 $H play --study k.study --size 64x48 --log held --input in.txt --participant P2 --append
full=$(( ($(date +%s%N) - t0) / 1000000 )) # ms: a whole play on this machine, now
resumed "SSQ cut, P2 between" "its questions from item 11 (attempt 2)"
run "report: SSQ in two runs" 0 "$H" report held --out rep-held2
grep -q "answered in part" err && bad "report: $(cat err)" || ok
[ "$(grep -c '^kills,[a-z]*,ssq_total,,2,' rep-held2/stats.csv)" = 2 ] && ok ||
    bad "SSQ scores: $(grep ssq_total rep-held2/stats.csv)"
# a quit in a questionnaire ends the line as the attempt was logged: done
rm -rf held
gen 8 " p=40" >q.in
run "quit in the SSQ" 0 $H play --study k.study --size 64x48 --log held --input q.in --participant P1
grep -q "^level a done steps 1 " out && ok || bad "quit in the SSQ printed: $(cat out)"
[ "$(awk -F, 'NR > 1 { print $(NF-3) }' held/summary.csv | tr '\n' ' ')" = "done done " ] && ok ||
    bad "quit in the SSQ: $(cat held/summary.csv)"
# and the level is not finished: --resume asks the rest
resumed "resumed after a quit" "its questions from item 11 (attempt 2)"
answered 2 16
# input that ends with an item on screen: done, not garbage
gen 5 >e.in
run "ends in the SSQ" 0 $H play --study k.study --size 64x48 --input e.in --participant P2
grep -q "^level a done steps 1 " out && ok || bad "ended in the SSQ printed: $(cat out)"

# ---- random kills --------------------------------------------------------------------------
# the delays: uniform over 5 % to 60 % of a whole play's time (as measured
# above: a sanitizer build or a loaded machine is slower), so that a
# resumed session, which has less to play, is killed again too
awk -v s="$SEED" -v n=$((KILLS * 3)) -v f="$full" \
    'BEGIN { srand(s); for (i = 0; i < n; i++) printf "%.3f\n", f / 1000 * (0.05 + 0.55 * rand()) }' >delays
P="$H play --study k.study --size 64x48 --log logs --input in.txt"

kills=0 asked=0 d=0 p=0
# one run of participant $1 (--resume unless $2 is "fresh"), killed after the
# next delay unless $3 is "last"; sets st
one_run() {
    how=--resume
    [ "$2" = fresh ] && how=--append
    $P --participant "$1" $how >out 2>err &
    pid=$!
    if [ "$3" != last ]; then
        d=$((d + 1))
        wait_for "$(sed -n ${d}p delays)" -p $pid
        kill -9 $pid 2>/dev/null
    fi
    wait $pid 2>/dev/null; st=$?
    grep -q "its questions from item" err && asked=$((asked + 1))
    [ $st = 137 ] && kills=$((kills + 1))
    return 0
}
while [ $kills -lt "$KILLS" ]; do
    p=$((p + 1)); fresh=fresh
    for k in 1 2 3 4 last; do
        one_run "$(printf P%02d $p)" "$fresh" "$k"
        fresh=
        if [ $st = 2 ] && grep -q "nothing to resume (start them" err; then
            one_run "$(printf P%02d $p)" fresh "$k" # killed before a row reached the disk
        fi
        [ $st = 0 ] && break
        [ $st = 2 ] && grep -q "has finished study" err && break
        [ $st = 137 ] || { bad "P$p: status $st: $(cat err)"; break; }
    done
    [ $st = 0 ] || { [ $st = 2 ] && grep -q "has finished study" err; } ||
        bad "P$p did not finish: status $st: $(cat err)"
done
[ $kills -ge "$KILLS" ] && ok || bad "$kills kills, want $KILLS"
# a run of kills that never fell in a question would test nothing
[ $asked -gt 0 ] && ok || bad "no kill fell in a questionnaire (seed $SEED)"
echo "cli_kills: $kills kills of $p participants, $asked resumed in a questionnaire"

# ---- every answer kept or asked again ------------------------------------------------
# levels with a done attempt and its pointing answer, per participant and
# condition: one 2, two 1
awk -F, 'FNR == 1 { next }
         FILENAME ~ /points/ { pt[$1 "," $3] = 1; next }
         $(NF-3) == "done" && pt[$1 "," $5] { n[$2 " " $7]++ }
         END { for (k in n) print k, n[k] }' logs/points.csv logs/summary.csv | sort >got.levels
for i in $(seq 1 $p); do printf 'P%02d one 2\nP%02d two 1\n' $i $i; done | sort >want.levels
cmp -s want.levels got.levels && ok || { bad "levels with their pointing answer:"; diff want.levels got.levels | head -5; }
# the SSQ's 16 items per participant and condition (by the attempt's row),
# none answered twice for one attempt
awk -F, 'FNR == 1 { next }
         FILENAME ~ /summary/ { cond[$1 "," $5] = $7; next }
         { k = $1 "," $3 "," $6; if (seen[k]++) print "twice", k
           items[$2 " " cond[$1 "," $3]]++ }
         END { for (k in items) print k, items[k] }' logs/summary.csv logs/answers.csv | sort >got.ssq
for i in $(seq 1 $p); do printf 'P%02d one 16\nP%02d two 16\n' $i $i; done | sort >want.ssq
cmp -s want.ssq got.ssq && ok || { bad "SSQ answers (seed $SEED):"; diff want.ssq got.ssq | head -8; }
run "report" 0 "$H" report logs --out rep
# every participant's SSQ scored under both conditions, none left in part
grep -q "answered in part" err && bad "report: $(cat err)" || ok
[ "$(grep -c "^kills,[a-z]*,ssq_total,,$p," rep/stats.csv)" = 2 ] && ok ||
    bad "SSQ scores of $p participants: $(grep ssq_total rep/stats.csv)"
cd logs && ls attempt-*.live *.csv.live 2>/dev/null | grep -q . && bad "live files left: $(ls)"; cd ..
finish cli_kills
