#!/bin/sh
# cli_class.sh - a class's results (issue 37; docs/teaching.md "A class's
# results"): two pupils take the pre-test and the post-test in the app
# (`quiz pre`, `quiz post`, one log folder each, --append), their answers
# logged under pretest and posttest; twelve more pupils' files as the web
# page downloads them (NAME.csv, some without a participant), one pupil who
# answered an item twice, one with the pre-test only, lessons' predictions
# (judged in {4,5} without a summary.csv, in {4,4} where a pupil's folder
# says so), a questionnaire's answer (left out); `holonomy report --class`
# writes the items' rates, the pupils' scores, the gain and the wrong
# answers, with the keys in {4,5} the core gives; tests/class_referee.R (R, base only) recomputes
# every figure to 1e-9, and a figure made wrong by 1e-6 fails it.
# Refusals: no folder, a file that is not an answers file, no test answers.
. "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")

A='session,participant,attempt,questionnaire,when,item,kind,value,time'
# quiz_input "P1 P2 P3 P4": the four items answered P presses right (left
# when negative) from the middle mark, the screen confirmed, the level's
# end screen confirmed
quiz_input() {
    awk -v presses="$1" 'BEGIN { t = 0; f(""); f("")
      n = split(presses, P, " ")
      for (i = 1; i <= n; i++) { k = P[i] < 0 ? -P[i] : P[i]; m = P[i] < 0 ? -1 : 1
        for (j = 0; j < k; j++) { f(" m=" m ",0"); f("") }
        f(" p=1"); f("") }
      f(" p=1"); f(""); f(""); f(""); f(" p=1"); f(""); f(" p=1"); f("") }
    function f(extra) { printf "%g f=8%s\n", t, extra; t += 0.5 }'
}

mkdir -p "$T/class"
printf 'tiling 4 5\nquiz pre\n' >"$T/pre.lvl"
printf 'tiling 4 5\nquiz post\n' >"$T/post.lvl"
if start_xvfb 59; then
    # p01: pre No, 5, 12, 5 (3 right); post No, less than 360, 28, 3 (all right)
    quiz_input "1 -1 2 0" >"$T/in1"
    quiz_input "1 0 1 -2" >"$T/in2"
    # p02: pre Yes, 6, 10, 5 (none right); post Yes, less, 24, 5 (1 right)
    quiz_input "0 0 0 0" >"$T/in3"
    quiz_input "0 0 0 0" >"$T/in4"
    for p in 1 2; do
        a=$((2 * p - 1)); b=$((2 * p))
        run "p0$p pre" 0 "$H" play "$T/pre.lvl" --input "$T/in$a" --size 64x48 --participant P0$p \
            --log "$T/class/p0$p"
        run "p0$p post" 0 "$H" play "$T/post.lvl" --input "$T/in$b" --size 64x48 --participant P0$p \
            --log "$T/class/p0$p" --append
    done
    grep -q ',P01,1,pretest,before_level,growth_q5,likert,12,' "$T/class/p01/answers.csv" &&
        grep -q ',P01,2,posttest,before_level,corner_q5,choice,less than 360,' "$T/class/p01/answers.csv" &&
        ok || bad "p01's answers: $(cat "$T/class/p01/answers.csv")"
else
    echo "cli_class: no Xvfb, the played pupils skipped"
fi
# twelve downloaded files: pupil k answers right with a chance rising from
# pre to post (a fixed generator), wrong answers from a few common ones
awk -v A="$A" -v dir="$T/class" 'BEGIN {
    split("No 5 12 3", pre, " "); split("No|less than 360|28|3", post, "|")
    split("Yes 4 8 4", wpre, " "); split("Yes|360 degrees|12|4", wpost, "|")
    split("Yes 6 16 2", wpre2, " "); split("Yes|more than 360|36|2", wpost2, "|")
    split("square corner growth home", c, " ")
    s = 7
    for (k = 3; k <= 14; k++) {
        f = sprintf("%s/w%02d.csv", dir, k)
        print A > f
        who = k % 4 == 0 ? "" : sprintf("P%02d", k)
        for (ph = 0; ph < 2; ph++) {
            if (k == 14 && ph == 1) continue
            for (i = 1; i <= 4; i++) {
                s = (s * 1103515245 + 12345) % 2147483648
                r = (s / 2147483648) < (ph ? 0.75 : 0.4)
                alt = (s % 7) < 4
                v = ph ? (r ? post[i] : alt ? wpost[i] : wpost2[i]) : (r ? pre[i] : alt ? wpre[i] : wpre2[i])
                kind = (i == 1 || (ph && i == 2)) ? "choice" : "likert"
                q = ph ? "posttest" : "pretest"
                printf "s%d,%s,%d,%s,before_level,%s_q5,%s,%s,%d.0000\n", k, who, ph + 1, q, c[i], kind, (v ~ / / ? v : v), i >> f
            }
        }
        if (k == 5) printf "s5,P05,3,posttest,before_level,home_q5,likert,3,9.0000\n" >> f
        if (k == 6) printf "s6,P06,3,predict,before_level,lesson1,choice,No,1.0000\n" >> f
        if (k == 7) printf "s7,P07,3,predict,before_level,lesson4,likert,28,1.0000\n" >> f
        if (k == 8) printf "s8,,3,predict,before_level,lesson2,likert,6,1.0000\n" >> f
        if (k == 9) printf "s9,P09,3,ssq,after_level,nausea,likert,2,1.0000\n" >> f
        close(f)
    }
}'
# a pupil's log folder whose lessons were played in {4,4} (summary.csv says
# so): lesson 1's Yes and lesson 4's 12 are right there
mkdir "$T/class/p20"
printf '%s\ns20,P20,1,predict,before_level,lesson1,choice,Yes,1.0\ns20,P20,2,predict,before_level,lesson4,likert,12,1.0\n' "$A" >"$T/class/p20/answers.csv"
printf 'session,participant,attempt,tiling\ns20,P20,1,"4,4"\ns20,P20,2,"4,4"\n' >"$T/class/p20/summary.csv"
run "report --class" 0 "$H" report --class "$T/class" --out "$T/rep"
grep -q "^report --class: 15 pupils, 13 with both tests; gain " "$T/out" && ok ||
    bad "report --class: $(cat "$T/out")"
grep -q "w06.csv: 1 lesson answer(s) of attempts without a known tiling (no summary.csv beside it) judged in {4,5}" "$T/err" &&
    ok || bad "the lessons' tiling: $(cat "$T/err")"
[ "$(grep '^predict,' "$T/rep/class_items.csv" | cut -d, -f1-7 | tr '\n' ' ')" = "predict,lesson1_q4,lesson 1,Yes,1,1,1.0000000000 predict,lesson4_q4,lesson 4,12,1,1,1.0000000000 predict,lesson1_q5,lesson 1,No,1,1,1.0000000000 predict,lesson4_q5,lesson 4,28,1,1,1.0000000000 predict,lesson2_q5,lesson 2,5,1,0,0.0000000000 " ] &&
    ok || bad "the lessons' items: $(grep '^predict' "$T/rep/class_items.csv")"
# the keys in {4,5} (docs/teaching.md names them)
[ "$(grep -v "^predict," "$T/rep/class_items.csv" | cut -d, -f1,2,4 | tr '\n' ' ')" = "phase,item,right_answer pretest,square_q5,No pretest,corner_q5,5 pretest,growth_q5,12 pretest,home_q5,3 posttest,square_q5,No posttest,corner_q5,less than 360 posttest,growth_q5,28 posttest,home_q5,3 " ] &&
    ok || bad "the keys: $(cat "$T/rep/class_items.csv")"
grep -q '^P05,' "$T/rep/class_pupils.csv" && grep -q '^w04,' "$T/rep/class_pupils.csv" &&
    grep -q '^P14,[0-9.]*,,$' "$T/rep/class_pupils.csv" && ok ||
    bad "class_pupils.csv: $(cat "$T/rep/class_pupils.csv")"
if command -v Rscript >/dev/null 2>&1; then
    run "R referee" 0 Rscript "$HERE/class_referee.R" "$T/class" "$T/rep/"
    grep -q "^R referee: [0-9]* figures agree" "$T/out" && ok || bad "R: $(cat "$T/out" "$T/err")"
    cp -r "$T/rep" "$T/rep2"
    awk -F, -v OFS=, 'NR == 2 { $6 = $6 + 1e-6 } { print }' "$T/rep/class_gain.csv" >"$T/rep2/class_gain.csv"
    run "R referee, a wrong figure" 1 Rscript "$HERE/class_referee.R" "$T/class" "$T/rep2/"
    grep -q "gain gain_mean" "$T/out" && ok || bad "R missed the wrong figure: $(cat "$T/out")"
else
    echo "cli_class: no Rscript, the R referee skipped (make deps-r)"
fi
# refusals
run "--class without --out" 2 "$H" report --class "$T/class"
run "--class, no folder" 2 "$H" report --class "$T/nothere" --out "$T/o3"
mkdir "$T/empty"
printf 'a,b\n1,2\n' >"$T/empty/x.csv"
run "--class, not answers" 2 "$H" report --class "$T/empty" --out "$T/o4"
grep -q "is not an answers file" "$T/err" && ok || bad "not answers: $(cat "$T/err")"
rm "$T/empty/x.csv"
run "--class, no test answers" 2 "$H" report --class "$T/empty" --out "$T/o5"
grep -q "holds no pre-test, post-test or lesson answers" "$T/err" && ok || bad "no answers: $(cat "$T/err")"

finish cli_class
