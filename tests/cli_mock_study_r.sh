#!/bin/sh
# cli_mock_study_r.sh - issue 35's "Done when": a mock 2 x 2 study played
# through the CLI by six participants (tiling {4,5} or {4,6} x minimap on
# the HUD or in the hand, Williams order, practice, pointing after each
# level, the SSQ after each condition, the TLX after the study), with
#   - P02 run a second time, as `--participant 002`, into another folder
#     (the id read as P02, the same order; the report flags the second
#     run `duplicate` and names it in one line);
#   - P03 killed (SIGKILL) in the SSQ of their second condition and
#     resumed (--resume asks it from item 6);
#   - P04 aborting a trial (SIGTERM in a level: `aborted`) and resumed;
# then `report` on both folders: trials.csv's exclusions, the duplicate's
# line, the TLX under the condition `study` in stats.csv, each SSQ scored,
# six participants in participants_stats.csv, and R
# (tests/report_referee.R) reproducing every participant-level figure, also
# under --include-restarted (the duplicate run counted).
# KEEP=DIR keeps the logs and the report in DIR.
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
GEN=$HERE/mock_study_gen.awk

if ! command -v Xvfb >/dev/null 2>&1; then
    echo "note: no Xvfb here: the mock study is not played"
    finish cli_mock_study_r
    exit $?
fi
start_xvfb 47 || { bad "Xvfb did not start"; finish cli_mock_study_r; exit $?; }
case $H in /*) ;; *) H=$PWD/$H ;; esac
KEEP=${KEEP:-}
case $KEEP in ''|/*) ;; *) KEEP=$PWD/$KEEP ;; esac
cd "$T" || exit 1

printf 'mode flag\nseed 3\nflag N\ntime-limit 3\n' >p.lvl
printf 'mode flag\nseed 3\nflag N\ntime-limit 3\n' >a.lvl   # optimal walk N
printf 'mode flag\nseed 4\nflag Wl\ntime-limit 3\n' >b.lvl  # optimal walk WS
cat >mock.study <<'S'
study mock2
counterbalance williams
practice p.lvl
closing Thank you, the study is over.
set point start
questionnaire ssq after condition
questionnaire tlx after study
condition q5-hud
level a.lvl
level b.lvl
set minimap hud
condition q5-hand
level a.lvl
level b.lvl
set minimap hand
condition q6-hud
level a.lvl
level b.lvl
set tiling 4 6
set minimap hud
condition q6-hand
level a.lvl
level b.lvl
set tiling 4 6
set minimap hand
S
# the plans (tests/mock_study_gen.awk: D done, L long, T timeout, R restart)
plan1=DDLTDDRD plan2=DTDLTDDD plan3=DDDTLDDD plan4=DDLDDTDD plan5=DLDDTDDD plan6=LDDDDRDT
for p in 1 2 5 6; do
    awk -v plan="$(eval echo \$plan$p)" -v p=$p -v tlx=1 -f "$GEN" >p$p.in
done
awk -v plan=$plan3 -v p=3 -v tlx=1 -v killq=3 -f "$GEN" >p3a.in
awk -v plan=$plan3 -v p=3 -v tlx=1 -v from=4 -v ssqfrom=6 -f "$GEN" >p3b.in
awk -v plan=$plan4 -v p=4 -v tlx=1 -v kill=5 -f "$GEN" >p4a.in
awk -v plan=$plan4 -v p=4 -v tlx=1 -v from=5 -f "$GEN" >p4b.in
P="$H play --study mock.study --size 64x48"

run "P01" 0 $P --log logs --participant P01 --input p1.in
run "P02" 0 $P --log logs --participant P02 --input p2.in --append
# P03 killed once the fifth item of their second SSQ is in answers.csv
n=$(($(wc -l <logs/answers.csv) + 16 + 5))
$P --log logs --participant P03 --input p3a.in --append >/dev/null 2>&1 &
pid=$!
wait_for 120 -l logs/answers.csv $n
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
[ "$(grep -c ',P03,.*,ssq,' logs/answers.csv)" = 21 ] && ok ||
    bad "P03 not killed in their second SSQ: $(grep -c ',P03,' logs/answers.csv) answers"
run "P03 resumed" 0 $P --log logs --participant P03 --input p3b.in --resume
grep -q "its questions from item 6" err && ok || bad "P03's resume: $(cat err)"
# P04 aborts (SIGTERM) 2 s into their sixth level (slot 5), then resumes
nnn=$(printf %03d $(($(wc -l <logs/summary.csv) + 6)))
$P --log logs --participant P04 --input p4a.in --append >/dev/null 2>&1 &
pid=$!
wait_for 120 -l logs/steps-$nnn.csv.live 2 && wait_for 120 -e logs/attempt-$nnn.live
kill -TERM $pid 2>/dev/null; wait $pid; st=$?
[ $st = 143 ] && grep -q ",P04,.*,aborted,[^,]*,[0-9a-f]*,\$" logs/summary.csv && ok ||
    bad "P04's abort: status $st, $(grep -c aborted logs/summary.csv) aborted rows"
run "P04 resumed" 0 $P --log logs --participant P04 --input p4b.in --resume
run "P05" 0 $P --log logs --participant P05 --input p5.in --append
run "P06" 0 $P --log logs --participant P06 --input p6.in --append
# P02 again, into another folder, spelled 002: the same participant and order
run "P02 again" 0 $P --log logs2 --participant 002 --input p2.in
grep -q "participant P02 (number 2, order 2 of 4)" err && ok || bad "002's order: $(cat err)"
[ "$(sed 1d logs2/summary.csv | cut -d, -f2 | sort -u)" = P02 ] && ok ||
    bad "002 logged as: $(sed 1d logs2/summary.csv | cut -d, -f2 | sort -u)"
for p in P01 P02 P03 P04 P05 P06; do
    [ "$(grep -c ",$p,[0-9]*,tlx,study," logs/answers.csv)" = 6 ] &&
        [ "$(grep -c ",$p,[0-9]*,ssq,condition," logs/answers.csv)" = 64 ] || bad "$p's answers"
done

# ---- the report ----------------------------------------------------------------------------
run "report" 0 "$H" report logs logs2 --out rep
grep -q "^holonomy report: participant P02 of study mock2 ran twice ('logs' session .* as P02, then 'logs2' session .* as P02): 6 trial(s) of the second run are excluded as duplicate" err &&
    [ "$(grep -c 'ran twice' err)" = 1 ] && ok || bad "the duplicate's line: $(cat err)"
# excluded: every completed trial of logs2 (practice aside) duplicate (its
# timeouts by their end), P04's aborted one
ex() { awk -F, -v w="$1" 'NR > 1 && $NF ~ w { print $1, $(NF - 1) }' rep/trials.csv | sort | uniq -c |
       awk '{ printf "%s %s %s;", $2, $3, $1 }'; }
[ "$(ex logs2)" = "P02 duplicate 6;P02 practice 1;P02 timeout 2;" ] && ok || bad "logs2's trials: $(ex logs2)"
[ "$(awk -F, '$1 == "P04" && $(NF - 1) == "aborted"' rep/trials.csv | wc -l)" = 1 ] && ok ||
    bad "P04's aborted trial: $(grep aborted rep/trials.csv)"
# the TLX after the study under `study`: seven (six participants and the
# second run), none under a condition; every SSQ scored (P03's in two runs)
grep -q '^mock2,study,tlx_raw,,7,' rep/stats.csv && [ "$(grep -c ',tlx_raw,' rep/stats.csv)" = 1 ] &&
    ok || bad "stats.csv's TLX: $(grep tlx rep/stats.csv)"
grep -q "answered in part" err && bad "report: $(cat err)" || ok
[ "$(grep -c '^P03,.*,ssq,total,[0-9.]*,1,$' rep/scores.csv)" = 4 ] && ok ||
    bad "P03's SSQ scores: $(grep '^P03,.*,ssq,total' rep/scores.csv)"
# six participants in each condition, their trials
for c in q5-hud q5-hand q6-hud q6-hand; do
    grep -q "^mock2,$c,steps,6," rep/participants_stats.csv || bad "$c: $(grep "^mock2,$c,steps" rep/participants_stats.csv)"
done
[ "$(cut -d, -f1 rep/participants.csv | sed 1d | sort -u | tr '\n' ' ')" = "P01 P02 P03 P04 P05 P06 " ] &&
    ok || bad "participants: $(cut -d, -f1 rep/participants.csv | sort -u | tr '\n' ' ')"

# ---- R reproduces every participant-level figure --------------------------------------------
run "report --include-restarted" 0 "$H" report logs logs2 --out repi --include-restarted
grep -q "ran twice" err && ok || bad "--include-restarted: the line: $(cat err)"
cmp -s rep/trials.csv repi/trials.csv && ok || bad "--include-restarted changed trials.csv"
cmp -s rep/participants_stats.csv repi/participants_stats.csv && bad "--include-restarted counted nothing" || ok
grep -q 'duplicate and restarted runs counted (--include-restarted)' repi/index.html &&
    ! grep -q 'counted (--include-restarted)' rep/index.html && ok || bad "the page does not say what it counts"
grep -q "^mock2,q5-hud,steps,6,1[0-9]," repi/participants_stats.csv && ok ||
    bad "--include-restarted: $(grep '^mock2,q5-hud,steps' repi/participants_stats.csv)"
if command -v Rscript >/dev/null 2>&1; then
    Rscript "$HERE/report_referee.R" rep >rout 2>&1 && grep -q '^R referee: [0-9]* figures agree' rout &&
        ok || bad "R disagrees: $(cat rout)"
    Rscript "$HERE/report_referee.R" repi --include-restarted >rout 2>&1 && ok ||
        bad "R disagrees (--include-restarted): $(cat rout)"
    Rscript "$HERE/report_referee.R" repi >rout 2>&1 && bad "R agreed without --include-restarted" || ok
else
    echo "cli_mock_study_r: Rscript not found (make deps-r): R referee skipped"
fi
if [ -n "$KEEP" ]; then
    mkdir -p "$KEEP" && rm -rf "$KEEP/logs" "$KEEP/logs2" "$KEEP/report" &&
        cp -r logs logs2 "$KEEP/" && cp -r rep "$KEEP/report" &&
        echo "cli_mock_study_r: kept the logs and the report in $KEEP"
fi
finish cli_mock_study_r
