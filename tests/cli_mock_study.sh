#!/bin/sh
# cli_mock_study.sh - a mock study end to end (issue 26 "Done when"): a
# 2 x 2 study (tiling {4,5} or {4,6}, minimap on the HUD or in the hand,
# Williams order), practice, instructions, two levels a condition with the
# pointing question after each (`set point start`), the SSQ after each
# condition, a closing screen. Four participants play it headless from
# --input files this script generates (done, long walks, timeouts,
# restarts; varied pointing and SSQ answers), all into one log folder;
# participant 3 is killed with SIGKILL in the middle of a level and
# resumed with --resume. `report` on the folder: n per condition in
# stats.csv, the learning curve's positions, one points.csv row for every
# level finished, 16 SSQ answers per condition and participant with the
# values given, the SSQ scores against Kennedy's weights computed here,
# the killed level counted once, the factor columns (q, minimap, room,
# cell). Participant 1's recording replays to the same logs.
# KEEP=DIR keeps the logs and the report in DIR (made; printed) to look at.
. "$(dirname "$0")/lib.sh"
REFEREE=$(cd "$(dirname "$0")" && pwd)/report_referee.R

if ! command -v Xvfb >/dev/null 2>&1; then
    echo "note: no Xvfb here: the mock study is not played"
    finish cli_mock_study
    exit $?
fi
start_xvfb 43 || { bad "Xvfb did not start"; finish cli_mock_study; exit $?; }
case $H in /*) ;; *) H=$PWD/$H ;; esac
KEEP=${KEEP:-}
case $KEEP in ''|/*) ;; *) KEEP=$PWD/$KEEP ;; esac
cd "$T" || exit 1

printf 'mode flag\nseed 3\nflag N\ntime-limit 3\n' >p.lvl
printf 'mode flag\nseed 3\nflag N\ntime-limit 3\n' >a.lvl   # optimal walk N
printf 'mode flag\nseed 4\nflag Wl\ntime-limit 3\n' >b.lvl  # optimal walk WS
cat >mock.study <<'S'
study mock
counterbalance williams
practice p.lvl
instructions Practice: walk one step north to the flag.
closing Thank you, the study is over.
set point start
questionnaire ssq after condition
condition q5-hud
instructions The map is on the HUD.
level a.lvl
level b.lvl
set minimap hud
condition q5-hand
instructions The map is in your hand.
level a.lvl
level b.lvl
set minimap hand
condition q6-hud
instructions The map is on the HUD; the forest has six trees a corner.
level a.lvl
level b.lvl
set tiling 4 6
set minimap hud
condition q6-hand
instructions The map is in your hand; the forest has six trees a corner.
level a.lvl
level b.lvl
set tiling 4 6
set minimap hand
S

# One participant's --input lines. plan: a letter per condition level in
# play order: D the optimal walk (done), L a longer walk (done), T a wrong
# step then the time limit (3 s), R a wrong step, restart, the optimal
# walk. Lines 0.25 s apart (a line a second while standing); after a
# level, the head back in cell (1,1) turned to a yaw of its own, confirm
# (the pointing), confirm (the end screen); instructions: confirm, then
# confirm (the ready screen). SSQ item i of the condition at
# position k answered (3i + 5p + 7k + p int(i/4)) mod 4: the middle mark
# is 1, t= moves one mark down, m= one up, confirm answers. -v kill=K:
# the lines end 2 s into slot K (a step east, then 30,000 frames 30 us
# apart, so that the session is killed there); -v from=K starts at slot K
# (a resumed session: no practice).
cat >gen.awk <<'A'
function line(extra, c, r) {
    printf "%.2f f=9%s h=%.1f,1.6,%.1f,%s\n", t, extra, c + 0.5, r + 0.5, q
    t += 0.25
}
function quat(y,   h) { h = y * 3.14159265358979 / 360; return sprintf("0,%.7f,0,%.7f", sin(h), cos(h)) }
function level(w, c0, r0, y, point,   i, c, r, d, L) {
    L = t; c = c0; r = r0; q = quat(0)
    line("", c, r)
    for (i = 1; i <= length(w); i++) {
        d = substr(w, i, 1)
        if (d == "N") r--; if (d == "S") r++; if (d == "E") c++; if (d == "W") c--
        line("", c, r)
    }
    if (t < L + 1) t = L + 1
    while (t <= L + 3.01) { line("", c, r); t += 0.75 }
    t = L + 3.25; q = quat(y)
    line("", 1, 1)
    if (point) { line(" p=1", 1, 1); line("", 1, 1) }  # the pointing's confirm
    line(" p=1", 1, 1)                                  # the end screen's
}
function screen(ready) { q = quat(0); line("", 1, 1); line(" p=1", 1, 1); if (ready) line(" p=1", 1, 1) }
function ssq(k,   i, v) {
    q = quat(0)
    for (i = 1; i <= 16; i++) {
        v = (i * 3 + p * 5 + k * 7 + int(i / 4) * p) % 4
        if (v == 0) line(" t=1,0", 1, 1)
        if (v >= 2) line(" m=1,0", 1, 1)
        if (v == 3) { line("", 1, 1); line(" m=1,0", 1, 1) }
        line(" p=1", 1, 1)
    }
}
BEGIN {
    t = 0; if (kill == "") kill = -1; if (from == "") from = 0
    if (from == 0) { screen(1); q = quat(0); level("N", 1, 1, 0, 0) }
    for (s = from; s < 8; s++) {
        if (s % 2 == 0) screen(1)           # the condition's instructions, the ready screen
        a = substr(plan, s + 1, 1); y = (37 * s + 61 * p) % 360
        if (s == kill) {
            q = quat(0); line("", 1, 1); line("", 2, 1); t += 0.5; line("", 2, 1)
            t += 0.75; line("", 2, 1)
            for (i = 1; i <= 30000; i++)
                printf "%.5f f=9 h=2.5,1.6,1.5,%s\n", t - 0.25 + i * 0.00003, q
            exit
        }
        best = s % 2 ? "WS" : "N"; long = s % 2 ? "EWWS" : "EWN"
        if (a == "D") level(best, 1, 1, y, 1)
        if (a == "L") level(long, 1, 1, y, 1)
        if (a == "T") level("E", 1, 1, y, 1)
        if (a == "R") {
            q = quat(0); line("", 1, 1); line("", 2, 1); line(" p=20", 2, 1)
            level(best, 2, 1, y, 1)
        }
        if (s % 2 == 1) ssq(int(s / 2) + 1)
    }
    screen(); line("", 1, 1)                # the closing screen
}
A

# the plans (slots 0..7: two levels a condition, in the participant's
# order) and the Williams orders of the four conditions (1 q5-hud,
# 2 q5-hand, 3 q6-hud, 4 q6-hand: rows 1, 2, 4, 3 and +1, +2, +3)
plan1=DDLTDDRD plan2=DTDLTDDD plan3=DDDTLDDD plan4=RDDDLTDD
order1='q5-hud q5-hand q6-hand q6-hud'
order2='q5-hand q6-hud q5-hud q6-hand'
order3='q6-hud q6-hand q5-hand q5-hud'
order4='q6-hand q5-hud q6-hud q5-hand'
for p in 1 2 4; do
    awk -v plan="$(eval echo \$plan$p)" -v p=$p -f gen.awk >p$p.in
done
awk -v plan=$plan3 -v p=3 -v kill=4 -f gen.awk >p3a.in
awk -v plan=$plan3 -v p=3 -v from=4 -f gen.awk >p3b.in
P="$H play --study mock.study --size 64x48 --log logs"
order_ok() { # P: the order line on stderr names the Williams row
    want="practice, $(eval echo \$order$1 | sed 's/ /, /g')"
    grep -q "participant P$1 (number $1, order $1 of 4): $want" err && ok ||
        bad "P$1's order: $(cat err), want $want"
}

run "P1" 0 $P --participant P1 --input p1.in --record p1.rec && order_ok 1
cp -r logs p1logs
run "P2" 0 $P --participant P2 --input p2.in --append && order_ok 2
# P3 killed 2 s into the fifth level (position 3, level a; attempt NNN,
# the practice and four levels after the summary's rows): its steps row
# and the attempt's live file on the disk, then SIGKILL
nnn=$(printf %03d $(($(wc -l <logs/summary.csv) + 5)))
$P --participant P3 --input p3a.in --append >/dev/null 2>&1 &
pid=$!
wait_for 120 -l logs/steps-$nnn.csv.live 2 && wait_for 120 -e logs/attempt-$nnn.live
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
[ -f logs/attempt-$nnn.live ] && ok || bad "P3 was not killed in attempt $nnn: $(ls logs | grep live)"
run "P3 resumed" 0 $P --participant P3 --input p3b.in --resume
grep -q "1 unfinished attempt(s) of a killed session finished" err && ok || bad "P3's recovery: $(cat err)"
grep -q "resumed at q5-hand (position 3), level 6 of 9\$" err && ok || bad "P3's resume: $(cat err)"
run "P4" 0 $P --participant P4 --input p4.in --append && order_ok 4
cd logs && ls attempt-*.live *.csv.live 2>/dev/null | grep -q . && bad "live files left: $(ls)"; cd ..

# ---- the summary against the plans --------------------------------------------------------
# expected rows "participant condition position level steps end", the
# killed attempt and the restarts included, from the plans and the orders
expect_rows() {
    for p in 1 2 3 4; do
        echo "P$p practice 0 p 1 done"
        eval "set -- \$order$p"; eval "pl=\$plan$p"
        s=0
        for c in "$@"; do
            for l in a b; do
                # the plan's next letter, peeled off in the shell
                a=${pl%"${pl#?}"}; pl=${pl#?}; k=$((s / 2 + 1))
                best=1 long=3; [ $l = b ] && best=2 long=4
                [ $p = 3 ] && [ $s = 4 ] && echo "P3 $c $k $l 1 killed"
                case $a in
                D) echo "P$p $c $k $l $best done" ;;
                L) echo "P$p $c $k $l $long done" ;;
                T) echo "P$p $c $k $l 1 timeout" ;;
                R) echo "P$p $c $k $l 1 restart"; echo "P$p $c $k $l $best done" ;;
                esac
                s=$((s + 1))
            done
        done
    done
}
expect_rows >want.rows
awk -F, 'NR > 1 { print $2, $7, $8, $9, $19, $(NF-3) }  # "4,5" is two fields here' logs/summary.csv >got.rows
cmp -s want.rows got.rows && ok || { bad "summary rows:"; diff want.rows got.rows | head -10; }
[ "$(grep -c ',killed,[^,]*,[0-9a-f]*,$' logs/summary.csv)" = 1 ] && ok || bad "killed rows: $(grep -c ',killed,' logs/summary.csv)"

# ---- points.csv: one answer for every level finished (done or timeout) -------------------
awk -F, 'NR > 1 && $7 != "practice" && ($(NF-3) == "done" || $(NF-3) == "timeout") { print $5 }' \
    logs/summary.csv >want.pts
awk -F, 'NR > 1 && $6 == "start" && $8 != "" && $10 != "" && $11 != "" { print $3 }' \
    logs/points.csv >got.pts
[ "$(wc -l <want.pts)" = 32 ] && cmp -s want.pts got.pts && ok ||
    bad "points.csv answers: $(tr '\n' ' ' <got.pts), want $(tr '\n' ' ' <want.pts)"

# ---- answers.csv: the SSQ after each condition, the values given ----------------------------
# "participant condition item value" expected, from the generator's rule
items='general_discomfort fatigue headache eye_strain difficulty_focusing salivation_increasing
sweating nausea difficulty_concentrating fullness_of_head blurred_vision dizziness_eyes_open
dizziness_eyes_closed vertigo stomach_awareness burping'
# (one awk: the conditions of participant p in order, k from 1)
for p in 1 2 3 4; do
    eval "echo $p \$order$p"
done | awk -v items="$items" '{
    n = split(items, it, /[ \n]+/); p = $1
    for (k = 1; k < NF; k++)
        for (i = 1; i <= n; i++) print "P" p, $(k + 1), it[i], (i * 3 + p * 5 + k * 7 + int(i / 4) * p) % 4
}' >want.ssq
# the condition of each answer: its attempt's row in the summary
awk -F, 'FNR == 1 { next } FILENAME ~ /summary/ { cond[$2 "," $5] = $7; next }
         $4 == "ssq" && $5 == "condition" && $7 == "likert" { print $2, cond[$2 "," $3], $6, $8 }' \
    logs/summary.csv logs/answers.csv >got.ssq
cmp -s want.ssq got.ssq && ok || { bad "SSQ answers:"; diff want.ssq got.ssq | head -10; }
[ "$(wc -l <got.ssq)" = 256 ] && [ "$(wc -l <logs/answers.csv)" = 257 ] && ok ||
    bad "answers.csv: $(wc -l <logs/answers.csv) lines"

# ---- participant 1's recording replays to the same logs ----------------------------------------
run "replay P1" 0 "$H" replay p1.rec --log re1
logs_diff p1logs re1 >/dev/null && ok || { bad "P1's replay differs"; logs_diff p1logs re1 | head -5; }

# ---- the report -----------------------------------------------------------------------------
run "report" 0 "$H" report logs --out rep
grep -qx "report: $(($(wc -l <logs/summary.csv) - 1)) attempts from 1 log folder" out && ok ||
    bad "report said: $(cat out)"
# SSQ scores (Kennedy et al. 1993) per participant and condition, from the
# answers given: "participant condition nausea oculomotor disorientation total"
awk 'BEGIN { split("1 6 7 8 9 15 16", a); for (j in a) N[a[j]] = 1
             split("1 2 3 4 5 9 11", a); for (j in a) O[a[j]] = 1
             split("5 8 10 11 12 13 14", a); for (j in a) D[a[j]] = 1 }
     { key = $1 " " $2; i = ++item[key]; n[key] += N[i] * $4; o[key] += O[i] * $4; d[key] += D[i] * $4
       if (i == 16) print key, n[key] * 9.54, o[key] * 7.58, d[key] * 13.92, (n[key] + o[key] + d[key]) * 3.74 }' \
    want.ssq >ssq.scores
# expected "condition measure n mean" for stats.csv: steps, efficiency
# over the levels done (practice left out), pointing n, SSQ means
{ awk '$2 != "practice" && $6 == "done" { opt = $4 == "a" ? 1 : 2
        n[$2]++; st[$2] += $5; ef[$2] += opt / $5 }
       END { for (c in n) { printf "%s steps %d %.4f\n", c, n[c], st[c] / n[c]
                            printf "%s efficiency %d %.4f\n", c, n[c], ef[c] / n[c] } }' want.rows
  awk '{ n[$2]++; t[$2] += $6; na[$2] += $3; oc[$2] += $4; di[$2] += $5 }
       END { for (c in n) { printf "%s ssq_total %d %.4f\n", c, n[c], t[c] / n[c]
                            printf "%s ssq_nausea %d %.4f\n", c, n[c], na[c] / n[c]
                            printf "%s ssq_oculomotor %d %.4f\n", c, n[c], oc[c] / n[c]
                            printf "%s ssq_disorientation %d %.4f\n", c, n[c], di[c] / n[c] } }' ssq.scores
} | sort >want.stats
awk -F, '$1 == "mock" && $3 ~ /^(steps|efficiency|ssq_)/ { print $2, $3, $5, $6 }' rep/stats.csv | sort >got.stats
cmp -s want.stats got.stats && ok || { bad "stats.csv:"; diff want.stats got.stats | head -10; }
# the pointing errors: 8 answers a condition (4 participants, 2 levels),
# the mean of |error| of points.csv's rows of its attempts
awk -F, 'FNR == 1 { next } FILENAME ~ /summary/ { cond[$2 "," $5] = $7; next }
         { c = cond[$2 "," $3]; n[c]++; et[c] += $10 < 0 ? -$10 : $10; ef[c] += $11 < 0 ? -$11 : $11 }
         END { for (c in n) printf "%s error_true %d %.4f\n%s error_flat %d %.4f\n",
                                   c, n[c], et[c] / n[c], c, n[c], ef[c] / n[c] }' \
    logs/summary.csv logs/points.csv | sort >want.err
awk -F, '$3 ~ /^error_/ { print $2, $3, $5, $6 }' rep/stats.csv | sort >got.err
[ "$(grep -c ' 8 ' want.err)" = 8 ] && cmp -s want.err got.err && ok ||
    { bad "pointing errors in stats.csv:"; diff want.err got.err | head; }
# the learning curve: a row per condition and position it was played at
awk '$2 != "practice" && $6 == "done" { k = $2 " " $3; n[k]++; ef[k] += ($4 == "a" ? 1 : 2) / $5 }
     END { for (k in n) printf "%s %d %.4f\n", k, n[k], ef[k] / n[k] }' want.rows | sort >want.learn
awk -F, 'NR > 1 { print $2, $3, $4, $5 }' rep/learning.csv | sort >got.learn
cmp -s want.learn got.learn && ok || { bad "learning.csv:"; diff want.learn got.learn | head -10; }
# participants.csv: 4 participants, a row per condition (practice too);
# the killed attempt is an attempt, not a level done: P3's q5-hand has 3
# attempts, 2 done (the level killed counted once, when resumed)
awk '{ k = $1 " " $2; a[k]++; if ($6 == "done") d[k]++ } END { for (k in a) print k, a[k], d[k] + 0 }' \
    want.rows | sort >want.part
awk -F, 'NR > 1 { print $1, $3, $4, $5 }' rep/participants.csv | sort >got.part
cmp -s want.part got.part && ok || { bad "participants.csv:"; diff want.part got.part | head -10; }
[ "$(cut -d, -f1 rep/participants.csv | sed 1d | sort -u | tr '\n' ' ')" = "P1 P2 P3 P4 " ] && ok ||
    bad "participants: $(cut -d, -f1 rep/participants.csv | sort -u | tr '\n' ' ')"
grep -qx 'P3,mock,q5-hand,3,2,2.5000,0.6667,0.6250' rep/participants.csv && ok ||
    bad "P3's q5-hand: $(grep '^P3,mock,q5-hand' rep/participants.csv)"
# the participant-level statistics: the killed attempt excluded as killed,
# and R (when installed) recomputes every figure from trials.csv
[ "$(awk -F, '$NF != "" && $(NF - 1) == "killed"' rep/trials.csv | wc -l)" = 1 ] && ok ||
    bad "trials.csv: killed rows: $(grep -c killed rep/trials.csv)"
if command -v Rscript >/dev/null 2>&1; then
    Rscript "$REFEREE" rep >rout 2>&1 && ok || bad "R disagrees: $(cat rout)"
fi
# the factor columns of attempts.csv (the quoted tiling is two fields here)
awk -F, 'NR > 1 && $5 != "practice" {
        q = substr($5, 2, 1); m = substr($5, 4)
        if ($14 $15 != "\"4" q "\"" || $16 != "3x3" || $17 != "1" || $20 != q || $22 != m) print }' \
    rep/attempts.csv >bad.rows
[ ! -s bad.rows ] && [ "$(sed 1d rep/attempts.csv | wc -l)" = "$(sed 1d logs/summary.csv | wc -l)" ] && ok ||
    bad "attempts.csv factor columns: $(head -3 bad.rows)"
[ "$(ls rep/attempt-*.png | wc -l)" = "$(sed 1d logs/summary.csv | wc -l)" ] && ok ||
    bad "pictures: $(ls rep | grep -c png)"
# index.html's learning curves: q5-hud and q6-hand have the same means at
# every position; each curve is drawn apart from the others (dodged)
sed -n '/aria-label="learning curves"/,/<\/svg>/p' rep/index.html | grep -o '<polyline[^>]*>' |
    sed 's/.* points="\([^"]*\)".*/\1/' >curves
[ "$(wc -l <curves)" = 4 ] && [ "$(sort -u curves | wc -l)" = 4 ] && ok ||
    bad "learning curves drawn on top of each other: $(cat curves)"
# conditions in the study file's order (study-HASH.txt), not P1's (q6-hand
# before q6-hud): conditions.csv and stats.csv alike
[ "$(sed 1d rep/conditions.csv | cut -d, -f2 | tr '\n' ' ')" = 'practice q5-hud q5-hand q6-hud q6-hand ' ] &&
    [ "$(sed 1d rep/stats.csv | cut -d, -f2 | uniq | tr '\n' ' ')" = 'q5-hud q5-hand q6-hud q6-hand ' ] && ok ||
    bad "conditions' order: $(cut -d, -f2 rep/conditions.csv | tr '\n' ' ')"
# participant 1 alone (the replay's folder): the SSQ scores are theirs
run "report P1" 0 "$H" report re1 --out rep1
grep '^P1 ' ssq.scores | while read -r pp c na oc di tot; do
    printf '%s ssq_nausea 1 %.4f\n%s ssq_oculomotor 1 %.4f\n%s ssq_disorientation 1 %.4f\n%s ssq_total 1 %.4f\n' \
        "$c" "$na" "$c" "$oc" "$c" "$di" "$c" "$tot"
done | sort >want.p1
awk -F, '$3 ~ /^ssq_/ { print $2, $3, $5, $6 }' rep1/stats.csv | sort >got.p1
[ "$(wc -l <want.p1)" = 16 ] && cmp -s want.p1 got.p1 && ok || { bad "P1's SSQ scores:"; diff want.p1 got.p1 | head; }

if [ -n "$KEEP" ]; then
    mkdir -p "$KEEP" && rm -rf "$KEEP/logs" "$KEEP/report" && cp -r logs "$KEEP/logs" &&
        cp -r rep "$KEEP/report" && echo "cli_mock_study: kept the logs and the report in $KEEP"
fi
finish cli_mock_study
