#!/bin/sh
# cli_report_r.sh - R as the referee of the report's participant-level
# statistics (docs/report.md "Participant-level statistics"): a mock 2x2
# study written as log folders (six participants, a practice level, two
# trials a condition, pointing after each; one aborted and one killed
# trial, one participant restarted, one run again into a second folder,
# one without a condition), reported; tests/report_referee.R (Rscript,
# base R only) recomputes the participants' means, both intervals, the
# paired differences, the main effects and d_z from trials.csv and checks
# every figure of participants_stats.csv, paired.csv and effects.csv to
# 1e-9, and from scores.csv the questionnaires' rows of
# participants_stats.csv, paired.csv and effects.csv (an SSQ before the
# study and after each condition, a TLX after it); then a figure made wrong by 1e-6 must fail it. Logs written before
# ids had one spelling (007 and p7 in one folder, 5): read as P07 and P05,
# a line for the merge and one for the rename, p7's run a duplicate named
# in one line (its questionnaires' scores excluded in scores.csv too); 2, then P02 (the one spelling) a restart; --include-restarted counts the duplicate and restarted
# trials (R agrees). The R parts are skipped in one line without Rscript
# (make deps-r).
. "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")

S='session,participant,session_start,version,attempt,study,condition,position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end'
P='session,participant,attempt,level,t,target,pointed,true,flat,error_true,error_flat,time'
# study: practice at position 0; conditions map-q5, map-q6, nomap-q5,
# nomap-q6 (their factors: the cues bits 3/1 standing for the minimap
# on/off, no level files here, x {4,5}/{4,6}) in the order
# the participant's number gives (a rotation here), two levels each.
# gen DIR SESSION PARTICIPANT ROT [SKIP_COND] [ENDS]: rows of one session;
# ENDS "k:END" makes the k-th row (1-based, practice first) end so.
gen() {
    awk -v dir="$1" -v ses="$2" -v p="$3" -v rot="$4" -v skip="${5:-}" -v ends="${6:-}" \
        -v S="$S" -v P="$P" 'BEGIN {
        split("map-q5 map-q6 nomap-q5 nomap-q6", c, " ")
        split(ends, e, ":")
        seed = 0
        for (i = 1; i <= length(p); i++) seed = seed * 31 + index("0123456789P", substr(p, i, 1))
        seed += length(ses) * 7 + rot
        sum = dir "/summary.csv"; pts = dir "/points.csv"
        if ((getline x < sum) <= 0) { print S >> sum; print P >> pts }
        close(sum)
        n = 0; att = 0
        while ((getline x < sum) > 0) att++
        close(sum)
        att = att > 0 ? att - 1 : 0
        for (k = 0; k <= 4; k++) {
            cond = k == 0 ? "practice" : c[(k - 1 + rot) % 4 + 1]
            if (cond == skip) continue
            for (l = 1; l <= (k == 0 ? 1 : 2); l++) {
                n++; att++
                seed = (seed * 1103515245 + 12345) % 2147483648
                q = cond ~ /q6/ ? 6 : 5
                opt = 4 + l + (q == 6)
                steps = opt + int(seed / 7) % 5 + (cond ~ /nomap/ ? 2 : 0)
                t = 8 + steps * 1.37 + (seed % 1000) / 250
                end = (n == e[1]) ? e[2] : "done"
                cues = cond ~ /nomap/ ? 1 : 3
                printf "%s,%s,2026-01-31T14:05:09Z,0.1.0,%d,s2x2,%s,%d,%s%d,sha%s%d,flag,5,%d,\"4,%d\",3x3,1,0,%d,%d,%.3f,%s\n", \
                    ses, p, att, cond, k, cond, l, cond, l, cues, q, steps, opt, t, end >> sum
                err = ((seed % 900) - 450) / 10 + (cond ~ /nomap/ ? 12.5 : 0)
                flat = (seed % 3 == 0) ? "" : sprintf("%.1f", err / 2 - 3)
                printf "%s,%s,%d,%s%d,%.3f,start,10,0,0,%.1f,%s,2.5\n", ses, p, att, cond, l, \
                    t, err, flat >> pts
                if (k == 0) ask("ssq", "before_study")
                if (k > 0 && l == 2) ask("ssq", "condition")
            }
        }
        ask("tlx", "study")
    }
    # the answers of questionnaire q at attempt att (SSQ 0..3, TLX 0..100 in 5s)
    function ask(q, when,    items, n, i, v) {
        if (q == "ssq")
            n = split("general_discomfort fatigue headache eye_strain difficulty_focusing " \
                      "salivation_increasing sweating nausea difficulty_concentrating " \
                      "fullness_of_head blurred_vision dizziness_eyes_open " \
                      "dizziness_eyes_closed vertigo stomach_awareness burping", items, " ")
        else
            n = split("mental physical temporal performance effort frustration", items, " ")
        ans = dir "/answers.csv"
        if (!answered++ && (getline x < ans) <= 0)
            print "session,participant,attempt,questionnaire,when,item,kind,value,time" >> ans
        for (i = 1; i <= n; i++) {
            seed = (seed * 1103515245 + 12345) % 2147483648
            v = q == "ssq" ? int(seed / 13) % 4 : 5 * (int(seed / 13) % 21)
            printf "%s,%s,%d,%s,%s,%s,likert,%d,1.0\n", ses, p, att, q, when, items[i], v >> ans
        }
    }'
}
mkdir "$T/l1" "$T/l2"
gen "$T/l1" sa1 P01 0
gen "$T/l1" sa2 P02 1 "" "4:aborted"
gen "$T/l1" sa3 P03 2
gen "$T/l1" sa3b P03 2 "" "7:killed"      # restarted: sa3's rows played again
gen "$T/l1" sa4 P04 3 nomap-q6            # no nomap-q6: not in the within CI
gen "$T/l1" sa5 P05 0
gen "$T/l2" sb2 P02 1                     # P02 again in another folder: duplicate
gen "$T/l2" sb6 P06 1

run "report" 0 "$H" report "$T/l1" "$T/l2" --out "$T/r"
for f in trials.csv participants_stats.csv paired.csv; do
    [ -f "$T/r/$f" ] && ok || bad "no $f"
done
# the exclusions: practice, the aborted and killed rows by their end, P03's
# first session restarted, P02's second folder a duplicate
ex() { awk -F, -v s="$1" -v a="$2" '$2 == s && $4 == a { print $(NF - 1) }' "$T/r/trials.csv"; }
[ "$(ex sa1 1)" = practice ] && ok || bad "practice: '$(ex sa1 1)'"
[ "$(ex sa1 2)" = "" ] && ok || bad "included: '$(ex sa1 2)'"
[ "$(ex sa2 13)" = aborted ] && ok || bad "aborted: '$(ex sa2 13)'"
[ "$(ex sa3 20)" = restarted ] && ok || bad "restarted: '$(ex sa3 20)'"
[ "$(ex sa3b 34)" = killed ] && ok || bad "killed: '$(ex sa3b 34)'"
[ "$(ex sa3b 35)" = "" ] && ok || bad "after the restart: '$(ex sa3b 35)'"
[ "$(ex sb2 2)" = duplicate ] && ok || bad "duplicate: '$(ex sb2 2)'"
# trial numbers run on within the participant (P03: 1..18 over two sessions)
[ "$(awk -F, '$1 == "P03" { t = $8 } END { print t }' "$T/r/trials.csv")" = 18 ] && ok ||
    bad "P03's last trial is not 18"
# six participants in map-q5 (P02's second folder left out; 11 trials: P03's
# second is killed), five within
# (P04 has no nomap-q6) of the study's four conditions
grep -q '^s2x2,map-q5,steps,6,11,' "$T/r/participants_stats.csv" && ok ||
    bad "map-q5 steps: $(grep '^s2x2,map-q5,steps' "$T/r/participants_stats.csv")"
grep -q '^s2x2,map-q5,steps,.*,4,5,' "$T/r/participants_stats.csv" && ok ||
    bad "map-q5 steps within: $(grep '^s2x2,map-q5,steps' "$T/r/participants_stats.csv")"
# the main effects: q (5, 6) and cues (3, 1) over the five complete participants
grep -q '^s2x2,steps,q,5,6,5,' "$T/r/effects.csv" && grep -q '^s2x2,steps,cues,3,1,5,' "$T/r/effects.csv" &&
    ok || bad "effects.csv: $(sed -n 2,3p "$T/r/effects.csv")"
# the factors a pair differs in
grep -q '^s2x2,steps,map-q5,map-q6,q,6,' "$T/r/paired.csv" && grep -q '^s2x2,steps,map-q5,nomap-q5,cues,6,' "$T/r/paired.csv" &&
    grep -q '^s2x2,steps,map-q5,nomap-q6,q cues,5,' "$T/r/paired.csv" && ok ||
    bad "paired.csv differ: $(sed -n 2,4p "$T/r/paired.csv")"
# scores.csv's excluded: the scores of P02's second folder and of P03's
# restarted session (its baseline at the practice level too), as their
# trials; they are left out of the participant-level rows (the baseline:
# six participants, one score each)
sx() { awk -F, -v s="$1" 'NR > 1 && $2 == s { print $NF }' "$T/r/scores.csv" | sort -u | tr '\n' ' '; }
[ "$(head -1 "$T/r/scores.csv" | awk -F, '{ print $NF }')" = excluded ] && [ "$(sx sb2)" = "duplicate " ] &&
    [ "$(sx sa3)" = "restarted " ] && [ "$(sx sa3b)" = " " ] && [ "$(sx sa1)" = " " ] && ok ||
    bad "scores.csv's excluded: '$(sx sb2)' '$(sx sa3)' '$(sx sa3b)' '$(sx sa1)'"
grep -q '^s2x2,study,ssq_total_before,6,6,' "$T/r/participants_stats.csv" && ok ||
    bad "the baseline's counts: $(grep ssq_total_before "$T/r/participants_stats.csv")"
# the questionnaires' pairs and main effects too (the SSQ after each
# condition; the baseline and the TLX, once a study, have none)
grep -q '^s2x2,ssq_total,map-q5,map-q6,q,' "$T/r/paired.csv" &&
    grep -q '^s2x2,ssq_nausea,q,5,6,' "$T/r/effects.csv" &&
    ! grep -q '^s2x2,\(tlx_raw\|ssq_total_before\),' "$T/r/paired.csv" "$T/r/effects.csv" && ok ||
    bad "the questionnaires' pairs: $(grep ssq "$T/r/paired.csv" "$T/r/effects.csv" | head -3)"
grep -q 'Participant-level statistics' "$T/r/index.html" && grep -q 'within-subjects' "$T/r/index.html" &&
    grep -q 'Paired differences' "$T/r/index.html" && ok || bad "the page has no participant-level section"

# ---- ids of logs written before ids had one spelling ----------------------------------------
# P07 logged as 007, then run again in the same folder as p7 (no
# --restart-participant: the app took them for two people); 5 alone
mkdir "$T/l3"
gen "$T/l3" sc7 007 2
gen "$T/l3" sc7b p7 2
gen "$T/l3" sc5 5 0
run "report of old ids" 0 "$H" report "$T/l3" --out "$T/r3"
grep -qx "holonomy report: participant P07 is spelled '007', 'p7' in the logs: read as one participant, P07" \
    "$T/err" && ok || bad "the merge's line: $(cat "$T/err")"
grep -qx "holonomy report: 1 participant id(s) read in their one spelling: '5' as P05" "$T/err" && ok ||
    bad "the rename's line: $(cat "$T/err")"
grep -q "^holonomy report: participant P07 of study s2x2 ran twice ('$T/l3' session sc7 as 007, then '$T/l3' session sc7b as p7): 8 trial(s)" \
    "$T/err" && ok || bad "the duplicate's line: $(cat "$T/err")"
[ "$(sed 1d "$T/r3/trials.csv" | cut -d, -f1 | sort -u | tr '\n' ' ')" = "P05 P07 " ] && ok ||
    bad "ids in trials.csv: $(cut -d, -f1 "$T/r3/trials.csv" | sort -u | tr '\n' ' ')"
ex3() { awk -F, -v s="$1" -v a="$2" '$2 == s && $4 == a { print $(NF - 1) }' "$T/r3/trials.csv"; }
[ "$(ex3 sc7 2)" = "" ] && [ "$(ex3 sc7b 11)" = duplicate ] && ok ||
    bad "the second spelling's run: '$(ex3 sc7 2)' '$(ex3 sc7b 11)'"
grep -q '^s2x2,map-q5,steps,2,4,' "$T/r3/participants_stats.csv" && ok ||
    bad "old ids' participants: $(grep '^s2x2,map-q5,steps' "$T/r3/participants_stats.csv")"
# 2 in old logs, then P02 (its one spelling: a build with the rule starts
# them again only with --restart-participant): restarted, not a duplicate
mkdir "$T/l4"
gen "$T/l4" sd2 2 1
gen "$T/l4" sd2b P02 1
run "report of a restart in the new spelling" 0 "$H" report "$T/l4" --out "$T/r4"
ex4() { awk -F, -v s="$1" -v a="$2" '$2 == s && $4 == a { print $(NF - 1) }' "$T/r4/trials.csv"; }
[ "$(ex4 sd2 2)" = restarted ] && [ "$(ex4 sd2b 11)" = "" ] && ! grep -q "ran twice" "$T/err" && ok ||
    bad "2, then P02: '$(ex4 sd2 2)' '$(ex4 sd2b 11)': $(cat "$T/err")"
# --include-restarted counts the second run (and P03's restarted one)
run "report --include-restarted" 0 "$H" report "$T/l3" --out "$T/r3i" --include-restarted
grep -q '^s2x2,map-q5,steps,2,6,' "$T/r3i/participants_stats.csv" && ok ||
    bad "--include-restarted: $(grep '^s2x2,map-q5,steps' "$T/r3i/participants_stats.csv")"
run "report l1 --include-restarted" 0 "$H" report "$T/l1" --out "$T/r1i" --include-restarted
grep -q '^s2x2,map-q5,steps,5,11,' "$T/r1i/participants_stats.csv" && ok ||
    bad "--include-restarted, P03: $(grep '^s2x2,map-q5,steps' "$T/r1i/participants_stats.csv")"
# ... and counted under --include-restarted (P03's two baselines)
grep -q '^s2x2,study,ssq_total_before,5,6,' "$T/r1i/participants_stats.csv" && ok ||
    bad "--include-restarted, the baseline: $(grep ssq_total_before "$T/r1i/participants_stats.csv")"
if command -v Rscript >/dev/null 2>&1; then
    Rscript "$HERE/report_referee.R" "$T/r3" >"$T/rout" 2>&1 && ok || bad "R on old ids: $(cat "$T/rout")"
    Rscript "$HERE/report_referee.R" "$T/r1i" --include-restarted >"$T/rout" 2>&1 && ok ||
        bad "R under --include-restarted: $(cat "$T/rout")"
fi

if ! command -v Rscript >/dev/null 2>&1; then
    echo "cli_report_r: Rscript not found (make deps-r): R referee skipped"
    finish cli_report_r
    exit $?
fi
if Rscript "$HERE/report_referee.R" "$T/r" >"$T/rout" 2>&1; then ok; else
    bad "R disagrees: $(cat "$T/rout")"
fi
grep -q '^R referee: [0-9]* figures agree' "$T/rout" && ok || bad "R said: $(cat "$T/rout")"
# a figure made wrong by 1e-6 fails it
mkdir "$T/w"
cp "$T/r/trials.csv" "$T/r/paired.csv" "$T/r/effects.csv" "$T/r/scores.csv" "$T/w/"
awk -F, 'BEGIN { OFS = "," } NR == 3 { $6 = sprintf("%.15g", $6 + 1e-6) } { print }' "$T/r/participants_stats.csv" \
    >"$T/w/participants_stats.csv"
if Rscript "$HERE/report_referee.R" "$T/w" >"$T/rout" 2>&1; then bad "a wrong mean passed"; else
    grep -q 'mean' "$T/rout" && ok || bad "R's failure names no figure: $(cat "$T/rout")"
fi
# so does a questionnaire's figure (the TLX after the study's mean)
awk -F, 'BEGIN { OFS = "," } $3 == "tlx_raw" { $6 = sprintf("%.15g", $6 + 1e-6) } { print }' \
    "$T/r/participants_stats.csv" >"$T/w/participants_stats.csv"
if Rscript "$HERE/report_referee.R" "$T/w" >"$T/rout" 2>&1; then bad "a wrong TLX mean passed"; else
    grep -q 'study tlx_raw mean' "$T/rout" && ok || bad "R's failure: $(cat "$T/rout")"
fi
cp "$T/r/participants_stats.csv" "$T/w/"
awk -F, 'BEGIN { OFS = "," } NR == 2 { $11 = sprintf("%.15g", $11 * 1.000001) } { print }' "$T/r/paired.csv" \
    >"$T/w/paired.csv"
if Rscript "$HERE/report_referee.R" "$T/w" >"$T/rout" 2>&1; then bad "a wrong d_z passed"; else ok; fi
# so does a questionnaire's pair's (their rows follow the trials')
awk -F, 'BEGIN { OFS = "," } $2 == "ssq_oculomotor" { $7 = sprintf("%.15g", $7 + 1e-6) } { print }' \
    "$T/r/paired.csv" >"$T/w/paired.csv"
if Rscript "$HERE/report_referee.R" "$T/w" >"$T/rout" 2>&1; then bad "a wrong SSQ pair passed"; else
    grep -q 'ssq_oculomotor .* mean_diff' "$T/rout" && ok || bad "R's failure: $(cat "$T/rout")"
fi
cp "$T/r/paired.csv" "$T/w/"
awk -F, 'BEGIN { OFS = "," } NR == 2 { $7 = sprintf("%.15g", $7 + 1e-6) } { print }' "$T/r/effects.csv" \
    >"$T/w/effects.csv"
if Rscript "$HERE/report_referee.R" "$T/w" >"$T/rout" 2>&1; then bad "a wrong main effect passed"; else
    grep -q 'q=5 - 6 mean_diff' "$T/rout" && ok || bad "R's failure: $(cat "$T/rout")"
fi
finish cli_report_r
