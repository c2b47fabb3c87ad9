#!/bin/sh
# cli_harden_values.sh - `holonomy report` against torn rows and impossible
# values, its own 10,000th picture, formulas in its CSVs (issue 39,
# findings 7 (the report's side), 11, 12 and 13): a row of another field
# count than its header's refused with its file and line; SSQ, TLX and
# Likert values outside their marks, an item twice or unknown, pointing
# errors and bearings that are no finite number of their range refused;
# attempt-10000.png a report's own name; text cells a spreadsheet would
# take for formulas written as text, numbers as they are, the logs
# untouched; a participant starting with '-' refused by play. The
# reproductions are also in tests/hostile/ (report-*-torn-row,
# report-likert-inf, report-ssq-*, report-tlx-101, report-points-inf,
# report-attempt-10000, report-formula-cells, participant-starts-minus).
. "$(dirname "$0")/lib.sh"

# a log folder made by replay: the flag level at Nf, walked WNESE (optimal)
{ printf 'holonomy-rec 3\nsession 20260131T140509Z-00000001\nparticipant P01\n'
  printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\nstudy s1\nlevel flag-a\n'
  printf 'condition map 1\nL mode flag\nL seed 5\nL flag Nf\nend\n'
  walk_input WNESE; } >"$T/a.rec"
run "replay" 0 "$H" replay "$T/a.rec" --log "$T/la"
L=$T/la
S=20260131T140509Z-00000001
AH='session,participant,attempt,questionnaire,when,item,kind,value,time'
PH='session,participant,attempt,level,t,target,pointed,true,flat,error_true,error_flat,time'
SSQ='general_discomfort fatigue headache eye_strain difficulty_focusing salivation_increasing
sweating nausea difficulty_concentrating fullness_of_head blurred_vision dizziness_eyes_open
dizziness_eyes_closed vertigo stomach_awareness burping'
# ssq VALUE_OF_NAUSEA: a whole SSQ after attempt 1, every other item 0
ssq() {
    for i in $SSQ; do
        v=0; [ "$i" = nausea ] && v=$1
        echo "$S,P01,1,ssq,condition,$i,likert,$v,1.0"
    done
}
n=0
# refused NAME FILE TEXT: the log folder $T/l with FILE as $T/f (written
# before: a pipe into a function would count in a subshell) is refused:
# exit 2, one line with TEXT, nothing written
refused() {
    n=$((n + 1))
    rm -rf "$T/l" && cp -r "$L" "$T/l" && cp "$T/f" "$T/l/$2"
    run "$1" 2 "$H" report "$T/l" --out "$T/o$n" && one_line "$1" "$3"
    [ ! -e "$T/o$n" ] && ok || bad "$1: a report was written"
}
# taken NAME FILE: the same folder is reported (exit 0)
taken() {
    n=$((n + 1))
    rm -rf "$T/l" && cp -r "$L" "$T/l" && cp "$T/f" "$T/l/$2"
    run "$1" 0 "$H" report "$T/l" --out "$T/o$n"
}

# finding 7: torn rows (the next row glued on, or the file's end cut
# inside one): refused naming the file and line, never read short
{ echo "$AH"; ssq 1 | sed '8s/likert.*/lik/;8N;s/\n//'; } >"$T/f"
    refused "answers torn" answers.csv "answers.csv: line 9: 15 fields where the header has 9"
{ echo "$AH"; echo "$S,P01,1,fun,level,enjoy,likert,4,1.0"; printf '%s' "$S,P01,1,fun,le"; } >"$T/f"
    refused "answers cut" answers.csv "answers.csv: line 3: 5 fields where the header has 9"
{ echo "$PH"; echo "$S,P01,1,flag-a,1.2,start,10.0,0.0,20.0,10.0,-1$S,P01,1,flag-a,1.2,start,10.0,0.0,20.0,10.0,-10.0,2.5"; } >"$T/f"
    refused "points torn" points.csv "points.csv: line 2: 22 fields where the header has 12"
{ echo "$PH"; echo "$S,P01,1,flag-a,1.2,start,10.0,0.0,20.0,10.0,-10.0,2.5,x"; } >"$T/f"
    refused "points long" points.csv "points.csv: line 2: 13 fields where the header has 12"
sed '3s/,[^,]*$//;3N;s/\n//' "$L/steps-001.csv" >"$T/f"
    refused "steps torn" steps-001.csv "steps-001.csv: line 3: 26 fields where the header has 14"
sed '2s/,[^,]*,[^,]*$//' "$L/summary.csv" >"$T/f"
    refused "summary cut" summary.csv "summary.csv: line 2: 22 fields where the header has 24"

# finding 12: values outside their documented ranges
{ echo "$AH"; echo "$S,P01,1,fun,level,enjoy,likert,inf,1.0"; } >"$T/f"
    refused "likert inf" answers.csv "answers.csv: line 2: column value: 'inf' is not a whole number in 0..100"
{ echo "$AH"; echo "$S,P01,1,fun,level,enjoy,likert,101,1.0"; } >"$T/f"
    refused "likert 101" answers.csv "column value: '101' is not a whole number in 0..100"
{ echo "$AH"; echo "$S,P01,1,fun,level,enjoy,likert,2.5,1.0"; } >"$T/f"
    refused "likert 2.5" answers.csv "column value: '2.5' is not a whole number in 0..100"
{ echo "$AH"; ssq 4; } >"$T/f"
    refused "ssq 4" answers.csv "answers.csv: line 9: column value: '4' is not one of ssq's marks 0..3"
{ echo "$AH"; ssq 1; echo "$S,P01,1,ssq,condition,nausea,likert,3,1.0"; } >"$T/f"
    refused "ssq 17 rows" answers.csv "answers.csv: line 18: item 'nausea' answered twice in one ssq"
{ echo "$AH"; ssq 1 | sed 's/,burping,/,happiness,/'; } >"$T/f"
    refused "ssq unknown item" answers.csv "line 17: column item: 'happiness' is not one of ssq's 16 items"
{ echo "$AH"; echo "$S,P01,1,ssq,condition,nausea,choice,3,1.0"; } >"$T/f"
    refused "ssq a choice" answers.csv "column kind: ssq's items are likert"
{ echo "$AH"; echo "$S,P01,1,tlx,condition,mental,likert,101,1.0"; } >"$T/f"
    refused "tlx 101" answers.csv "column value: '101' is not one of tlx's marks 0..100 in steps of 5"
{ echo "$AH"; echo "$S,P01,1,tlx,condition,mental,likert,37,1.0"; } >"$T/f"
    refused "tlx 37" answers.csv "column value: '37' is not one of tlx's marks 0..100 in steps of 5"
{ echo "$AH"; echo "$S,P01,1,fun,later,enjoy,likert,3,1.0"; } >"$T/f"
    refused "when later" answers.csv "column when: 'later' is not level, condition, study, before_level, before_condition or before_study"
{ echo "$AH"; echo "$S,P01,1,fun,level,enjoy,lickert,3,1.0"; } >"$T/f"
    refused "kind lickert" answers.csv "column kind: 'lickert' is not likert or choice"
{ echo "$AH"; echo "$S,P01,1.5,fun,level,enjoy,likert,3,1.0"; } >"$T/f"
    refused "attempt 1.5" answers.csv "attempt is not a whole number (0 or more)"
{ echo "$AH"; echo "$S,P01,1,fun,level,hand,choice,left,1.0"; echo "$S,P01,1,fun,level,hand,choice,right,1.0"; } >"$T/f"
    refused "choice twice" answers.csv "line 3: item 'hand' answered twice in one fun"
for e in inf nan -inf 1e3 0x10 180.1 -180 ' 10'; do
    { echo "$PH"; echo "$S,P01,1,flag-a,1.2,start,10.0,0.0,20.0,$e,-10.0,2.5"; } >"$T/f"
        refused "error_true $e" points.csv "points.csv: line 2: column error_true: '$e' is not a number in (-180, 180]"
done
{ echo "$PH"; echo "$S,P01,1,flag-a,1.2,start,10.0,0.0,20.0,10.0,inf,2.5"; } >"$T/f"
    refused "error_flat inf" points.csv "column error_flat: 'inf' is not a number in (-180, 180]"
{ echo "$PH"; echo "$S,P01,1,flag-a,1.2,start,360.0,0.0,20.0,10.0,10.0,2.5"; } >"$T/f"
    refused "pointed 360" points.csv "column pointed: '360.0' is not a bearing in"
{ echo "$PH"; echo "$S,P01,1,flag-a,1.2,start,10.0,nan,20.0,10.0,10.0,2.5"; } >"$T/f"
    refused "true nan" points.csv "column true: 'nan' is not a bearing in"
# a questionnaire of the study's own: its marks and kind are those of the
# question its attempt's level asks (level-HASH.txt), when that file is there
lq="$T/lq"; mkdir "$lq"
printf 'mode flag\nseed 5\nflag Nf\nquestion fun likert 1 7 "Fun?" "no" "yes"\nquestion hand choice "Hand?" "left" "right"\nask mine level fun hand\n' >"$lq/level-abc.txt"
printf 'session,participant,attempt,level,level_sha256,mode,steps,optimum,time,end\n%s,P01,1,lv,abc,flag,5,5,1.0,done\n' "$S" >"$lq/summary.csv"
for a in 'fun,likert,9:2:is not one of fun'"'"'s marks 1..7' 'fun,likert,0:2:marks 1..7' \
    'hand,likert,1:2:its level asks mine'"'"'s hand as a choice' 'fun,choice,x:2:asks mine'"'"'s fun as a likert' \
    'fun,likert,7:0:' 'hand,choice,left:0:' 'other,likert,50:0:'; do
    printf '%s\n%s,P01,1,mine,level,%s,1.0\n' "$AH" "$S" "${a%%:*}" >"$lq/answers.csv"
    rest=${a#*:}; rm -rf "$T/oq"
    run "level's question ${a%%:*}" "${rest%%:*}" "$H" report "$lq" --out "$T/oq" &&
        { [ -z "${rest#*:}" ] || one_line "level's question ${a%%:*}" "answers.csv: line 2: .*${rest#*:}"; }
done

# the ranges' ends and empty values are taken: SSQ 0 and 3, TLX 0 and 100,
# Likert 0 and 100, errors 180 and -179.9, bearings 0 and 359.9, an
# undefined bearing and error empty; a file without the bearings' columns
{ echo "$AH"; ssq 3; echo "$S,P01,1,fun,level,enjoy,likert,0,1.0"
  echo "$S,P01,1,fun,level,more,likert,100,1.0"
  for i in mental physical temporal performance effort frustration; do
      echo "$S,P01,1,tlx,study,$i,likert,100,1.0"; done; } >"$T/f"
taken "answers at the ends" answers.csv
grep -q '^s1,map,ssq_total,,1,' "$T/o$n/stats.csv" && grep -qx 's1,map,tlx_raw,,1,100.0000,,,' "$T/o$n/stats.csv" &&
    ok || bad "answers at the ends: $(cat "$T/o$n/stats.csv")"
{ echo "$PH"; echo "$S,P01,1,flag-a,1.2,start,0.0,359.9,,180.0,,2.5"
  echo "$S,P01,1,flag-a,1.2,start,0,0.1,0.0,-179.9,-0.1,2.5"; } >"$T/f"
taken "points at the ends" points.csv
grep -qx 's1,map,error_true,,2,179.9500,0.0707,179.3147,180.5853' "$T/o$n/stats.csv" && ok ||
    bad "points at the ends: $(grep error "$T/o$n/stats.csv")"
{ echo 'session,attempt,error_true,error_flat'; echo "$S,1,10.0,"; } >"$T/f"
taken "points without bearings" points.csv

# finding 11: a report of exactly 10,000 attempts is made again in its own
# folder (attempt-10000.png is its name); one steps file, the rest warned
mkdir "$T/big" && cp "$L"/level-*.txt "$T/big/"
{ head -1 "$L/summary.csv"
  sed -n 2p "$L/summary.csv" | awk -F, -v OFS=, '{ for (i = 1; i <= 10000; i++) { $5 = i; print } }'
} >"$T/big/summary.csv"
awk -F, -v OFS=, 'NR > 1 { $2 = 10000 } { print }' "$L/steps-001.csv" >"$T/big/steps-10000.csv"
run "10,000 attempts" 0 "$H" report "$T/big" --out "$T/ob"
[ -f "$T/ob/attempt-10000.png" ] && ok || bad "10,000 attempts: no attempt-10000.png"
run "10,000 attempts again" 0 "$H" report "$T/big" --out "$T/ob"
[ "$(cat "$T/out")" = 'report: 10000 attempts from 1 log folder' ] && [ -f "$T/ob/attempt-10000.png" ] &&
    ok || bad "10,000 attempts again: $(cat "$T/out" "$T/err" | head -3)"
# not every five-digit name: attempt-10001.png and attempt-01000.png are not a report's
for f in attempt-10001.png attempt-01000.png attempt-100000.png; do
    mkdir -p "$T/o5/$f.d" && : >"$T/o5/$f.d/$f"
    run "$f" 2 "$H" report "$L" --out "$T/o5/$f.d" && one_line "$f" "holds '$f', not a report's file"
done

# finding 13: text cells a spreadsheet would read as formulas are quoted
# with a ' before them in every CSV of the report; numbers stay numbers;
# the page and the logs keep the texts as they are
cp -r "$L" "$T/lf"
awk -F, -v OFS=, 'NR == 2 { $2 = "-A1"; $6 = "=1+1"; $7 = "@SUM(A1)"; $9 = "-h.lvl" } { print }' \
    "$L/summary.csv" >"$T/lf/summary.csv"
{ echo "$AH"; echo "$S,-A1,1,fun,level,enjoy,likert,4,1.0"
  echo "$S,-A1,1,fun,level,hand,choice,=cmd|' /C calc'!A0,1.0"; } >"$T/lf/answers.csv"
cp "$T/lf/summary.csv" "$T/lf/answers.csv" "$T/"
run "formulas" 0 "$H" report "$T/lf" --out "$T/of"
row=$(sed -n 2p "$T/of/attempts.csv")
case $row in
"\"'-A1\",$S,1,\"'=1+1\",\"'@SUM(A1)\",1,\"'-h.lvl\",flag,5,5,1.0000,"*) ok ;;
*) bad "formulas: attempts.csv row $row" ;;
esac
for f in attempts.csv conditions.csv stats.csv learning.csv participants.csv; do
    grep -qE '(^|,)([=+@]|-[^0-9.])' "$T/of/$f" && bad "$f holds a formula: $(cat "$T/of/$f")" || ok
    grep -qF "\"'@SUM(A1)\"" "$T/of/$f" && ok || bad "$f: the condition is not quoted"
done
grep -q ',-[0-9]' "$T/of/stats.csv" && bad "a number quoted" || ok # no negative here: see test_report_escape
grep -qF '<td>-A1</td>' "$T/of/index.html" && grep -qF '<td>=1+1</td>' "$T/of/index.html" && ok ||
    bad "the page: $(grep -o '<td>[^<]*A1[^<]*</td>' "$T/of/index.html" | head -3)"
cmp -s "$T/summary.csv" "$T/lf/summary.csv" && cmp -s "$T/answers.csv" "$T/lf/answers.csv" && ok ||
    bad "the logs were changed"
# the participant: play refuses an id starting with '-' (either form)
printf 'mode flag\nseed 5\nflag Nf\n' >"$T/a.lvl"
for p in "-A1" "-" "--"; do
    run "participant $p" 2 "$H" play "$T/a.lvl" --participant="$p" --frames 1 &&
        one_line "participant $p" "--participant '$p' starts with '-'"
done
run "participant -A1 apart" 2 "$H" play "$T/a.lvl" --participant -A1 --frames 1 &&
    one_line "participant -A1 apart" "starts with '-'"
run "xr participant -A1" 2 "$H" xr "$T/a.lvl" --participant=-A1 --frames 1 &&
    one_line "xr participant -A1" "starts with '-'"

finish cli_harden_values
