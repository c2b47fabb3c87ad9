#!/bin/sh
# cli_report_stats.sh - the statistics of `holonomy report` (stats.csv,
# learning.csv, participants.csv, the page's section) on hand-made log
# folders (docs/research.md, /work formats of points.csv and answers.csv):
# means over completed attempts only with practice left out, SD, the 95 %
# t interval and n against values computed by hand; learning curves by
# position; pointing errors |true| and |flat|; SSQ with Kennedy's weights,
# raw TLX and Likert means per condition; malformed instrument files.
. "$(dirname "$0")/lib.sh"

S='session,participant,session_start,version,attempt,study,condition,position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end'
# row SESSION PARTICIPANT ATTEMPT CONDITION POSITION STEPS OPTIMUM TIME END
row() {
    printf '%s,%s,2026-01-31T14:05:09Z,0.1.0,%s,s1,%s,%s,lvl,,flag,5,,"4,5",3x3,1,2026-01-31T14:05:09Z,%s,%s,%s,%s\n' "$@"
}
mkdir "$T/l1" "$T/l2"
{
    echo "$S"
    row sa P01 1 practice 0 9 3 30 done      # practice: left out
    row sa P01 2 map 1 5 5 10 done           # map: steps 5, eff 1.0, time 10
    row sa P01 3 map 2 10 5 20 done          # map: steps 10, eff 0.5, time 20
    row sa P01 4 nomap 3 8 4 40 done         # nomap: steps 8, eff 0.5
    row sa P01 5 nomap 4 3 4 99 killed       # not completed: left out
} >"$T/l1/summary.csv"
{
    echo "$S"
    row sb P02 1 map 1 6 5 12 done           # map: steps 6, eff 5/6, time 12
    row sb P02 2 nomap 2 4 4 30 done         # nomap: steps 4, eff 1
    row sb P02 3 nomap 3 20 4 50 aborted
} >"$T/l2/summary.csv"
# points: attempt 2 and 3 (map), 4 (nomap); one flat bearing undefined
cat >"$T/l1/points.csv" <<'P'
session,participant,attempt,level,t,target,pointed,true,flat,error_true,error_flat,time
sa,P01,2,lvl,10.0,start,10.0,0.0,20.0,10.0,-10.0,2.5
sa,P01,3,lvl,20.0,start,350.0,10.0,,-20.0,,3.0
sa,P01,4,lvl,40.0,objective,90.0,60.0,45.0,30.0,45.0,1.0
P
# answers: SSQ after map (P01, attempt 3) complete: nausea 3, burping 1,
# difficulty_focusing 2, the rest 0; TLX after nomap (attempt 4); a
# likert item of the study's own; an SSQ at attempt 0 (condition none)
{
    echo 'session,participant,attempt,questionnaire,when,item,kind,value,time'
    for i in general_discomfort fatigue headache eye_strain difficulty_focusing \
        salivation_increasing sweating nausea difficulty_concentrating fullness_of_head \
        blurred_vision dizziness_eyes_open dizziness_eyes_closed vertigo stomach_awareness burping; do
        v=0; [ $i = nausea ] && v=3; [ $i = burping ] && v=1; [ $i = difficulty_focusing ] && v=2
        echo "sa,P01,3,ssq,condition,$i,likert,$v,1.0"
    done
    for i in mental physical temporal performance effort frustration; do
        echo "sa,P01,4,tlx,condition,$i,likert,60,1.0"
    done
    echo 'sa,P01,0,ssq,study,nausea,likert,1,1.0'
    echo 'sa,P01,2,fun,level,enjoy,likert,4,1.0'
    echo 'sa,P01,3,fun,level,enjoy,likert,5,1.0'
    echo 'sa,P01,3,fun,level,colour,choice,red,1.0'
} >"$T/l1/answers.csv"

run "report" 0 "$H" report "$T/l1" "$T/l2" --out "$T/r"
for f in stats.csv learning.csv participants.csv; do
    [ -f "$T/r/$f" ] && ok || bad "no $f"
done
st() { grep "^s1,$1,$2," "$T/r/stats.csv"; }
# map steps 5, 10, 6: mean 7, sd sqrt(7) = 2.6458, t(.975,2) = 4.302653:
# half 4.302653 * 2.6458 / sqrt(3) = 6.5724 (Python's statistics.stdev agrees)
want='s1,map,steps,,3,7.0000,2.6458,0.4276,13.5724'
[ "$(st map steps)" = "$want" ] && ok || bad "map steps: $(st map steps), want $want"
# map efficiency 1, 0.5, 0.8333: mean 0.7778, sd 0.2546, half 0.6325
want='s1,map,efficiency,,3,0.7778,0.2546,0.1453,1.4102'
[ "$(st map efficiency)" = "$want" ] && ok || bad "map eff: $(st map efficiency), want $want"
# nomap: 2 completed (8 and 4; the killed and aborted rows left out)
want='s1,nomap,steps,,2,6.0000,2.8284,-19.4124,31.4124'
[ "$(st nomap steps)" = "$want" ] && ok || bad "nomap steps: $(st nomap steps), want $want"
grep -q '^s1,practice,steps' "$T/r/stats.csv" && bad "practice has means" || ok
# pointing: map |true| 10, 20 (mean 15, sd 7.0711); |flat| 10 only (n 1: no sd)
want='s1,map,error_true,,2,15.0000,7.0711,-48.5310,78.5310'
[ "$(st map error_true)" = "$want" ] && ok || bad "map error_true: $(st map error_true)"
want='s1,map,error_flat,,1,10.0000,,,'
[ "$(st map error_flat)" = "$want" ] && ok || bad "map error_flat: $(st map error_flat)"
want='s1,nomap,error_flat,,1,45.0000,,,'
[ "$(st nomap error_flat)" = "$want" ] && ok || bad "nomap error_flat: $(st nomap error_flat)"
# SSQ: N raw 4 (nausea 3 + burping 1), O raw 2, D raw 5 (nausea 3 + focusing 2)
want='s1,map,ssq_total,,1,41.1400,,,'
[ "$(st map ssq_total)" = "$want" ] && ok || bad "ssq_total: $(st map ssq_total)"
[ "$(st map ssq_nausea)" = 's1,map,ssq_nausea,,1,38.1600,,,' ] && ok || bad "ssq_nausea: $(st map ssq_nausea)"
[ "$(st map ssq_oculomotor)" = 's1,map,ssq_oculomotor,,1,15.1600,,,' ] && ok || bad "ssq_oculomotor"
[ "$(st map ssq_disorientation)" = 's1,map,ssq_disorientation,,1,69.6000,,,' ] && ok || bad "ssq_disorientation"
[ "$(st nomap tlx_raw)" = 's1,nomap,tlx_raw,,1,60.0000,,,' ] && ok || bad "tlx_raw: $(st nomap tlx_raw)"
# an incomplete SSQ (attempt 0: condition none) is no score, its item a likert mean
grep -q '^,none,ssq_total' "$T/r/stats.csv" && bad "an incomplete ssq scored" || ok
grep -q '^,none,likert,ssq/nausea,1,1.0000,,,$' "$T/r/stats.csv" && ok || bad "the none row: $(grep none "$T/r/stats.csv")"
want='s1,map,likert,fun/enjoy,2,4.5000,0.7071,-1.8531,10.8531'
grep -qx "$want" "$T/r/stats.csv" && ok || bad "likert fun/enjoy: $(grep enjoy "$T/r/stats.csv")"
grep -q colour "$T/r/stats.csv" && bad "a choice item has a mean" || ok

# scores.csv (issue 35): one row per score, subscale or Likert item, by hand:
# the SSQ after map (N 4 x 9.54, O 2 x 7.58, D 5 x 13.92, T 11 x 3.74), the
# TLX after nomap (raw and items), a Likert item its value, the partial SSQ
# after study (attempt 0) under `study` with no scores and complete 0, and
# P02's TLX after study (10..60: raw 35) under `study`
{
    echo 'session,participant,attempt,questionnaire,when,item,kind,value,time'
    v=10
    for i in mental physical temporal performance effort frustration; do
        echo "sb,P02,0,tlx,study,$i,likert,$v,1.0"
        v=$((v + 10))
    done
} >"$T/l2/answers.csv"
run "report with a TLX after study" 0 "$H" report "$T/l1" "$T/l2" --out "$T/rs"
sc="$T/rs/scores.csv"
head -1 "$sc" | grep -qx 'participant,session,attempt,study,condition,placement,scope,instrument,subscale,score,complete,excluded' &&
    ok || bad "scores.csv header: $(head -1 "$sc")"
for want in P01,sa,3,s1,map,after,condition,ssq,total,41.1400,1, \
    P01,sa,3,s1,map,after,condition,ssq,nausea,38.1600,1, \
    P01,sa,3,s1,map,after,condition,ssq,oculomotor,15.1600,1, \
    P01,sa,3,s1,map,after,condition,ssq,disorientation,69.6000,1, \
    P01,sa,4,s1,nomap,after,condition,tlx,raw,60.0000,1, \
    P01,sa,4,s1,nomap,after,condition,tlx,effort,60.0000,1, \
    P01,sa,2,s1,map,after,level,fun,enjoy,4.0000,1, \
    P01,sa,3,s1,map,after,level,fun,enjoy,5.0000,1, \
    P01,sa,0,,study,after,study,ssq,total,,0, \
    P01,sa,0,,study,after,study,ssq,nausea,,0, \
    P02,sb,0,,study,after,study,tlx,raw,35.0000,1, \
    P02,sb,0,,study,after,study,tlx,mental,10.0000,1, \
    P02,sb,0,,study,after,study,tlx,frustration,60.0000,1,; do
    grep -qx "$want" "$sc" && ok || bad "scores.csv: no $want"
done
[ "$(grep -c ',ssq,' "$sc")" = 8 ] && ok || bad "ssq rows: $(grep ',ssq,' "$sc")"
[ "$(grep -c ',tlx,' "$sc")" = 14 ] && ok || bad "tlx rows: $(grep -c ',tlx,' "$sc")"
grep -q colour "$sc" && bad "a choice item scored" || ok

# learning curve: map at positions 1 (P01 1.0, P02 0.8333) and 2 (0.5)
grep -qx 's1,map,1,2,0.9167,0.1179,-0.1422,1.9755' "$T/r/learning.csv" && ok ||
    bad "learning map 1: $(cat "$T/r/learning.csv")"
grep -qx 's1,map,2,1,0.5000,,,' "$T/r/learning.csv" && ok || bad "learning map 2"
grep -q ',practice,' "$T/r/learning.csv" && bad "practice in the learning curve" || ok

# per participant: P01 nomap 2 attempts, 1 done (steps 8); P02 nomap 2, 1 done
grep -qx 'P01,s1,nomap,2,1,8.0000,0.5000,40.0000' "$T/r/participants.csv" && ok ||
    bad "participants: $(cat "$T/r/participants.csv")"
grep -qx 'P01,s1,practice,1,1,9.0000,0.3333,30.0000' "$T/r/participants.csv" && ok ||
    bad "participants practice row"
[ "$(wc -l <"$T/r/participants.csv")" = 6 ] && ok || bad "participants rows: $(wc -l <"$T/r/participants.csv")"

# the page: the section, both plots, the t interval stated
for s in '<h2>Statistics</h2>' 'aria-label="learning curves"' 'aria-label="steps against optimum"' \
    "Student's t" '<h3>Participants</h3>'; do
    grep -q "$s" "$T/r/index.html" && ok || bad "index.html lacks $s"
done
# the old tables keep their meaning (all attempts)
grep -qx 's1,map,3,3,7.00,0.7778,14.0000' "$T/r/conditions.csv" && ok || bad "conditions.csv changed: $(cat "$T/r/conditions.csv")"
# a second report over the first replaces the new files too
run "report again" 0 "$H" report "$T/l1" --out "$T/r"

# malformed instrument files: one line naming the file and line, nothing written
cp -r "$T/l1" "$T/l3"
echo 'sa,P01,x,lvl,1,start,1,2,3,4,5,6' >>"$T/l3/points.csv"
run "bad points" 2 "$H" report "$T/l3" --out "$T/r3"
one_line "bad points" "points.csv: line 5: attempt is not a whole number"
[ ! -e "$T/r3" ] && ok || bad "a report was written on bad input"
cp "$T/l1/points.csv" "$T/l3/points.csv"
echo 'sa,P01,2,fun,level,enjoy,likert,lots,1.0' >>"$T/l3/answers.csv"
run "bad answers" 2 "$H" report "$T/l3" --out "$T/r3"
one_line "bad answers" "answers.csv: line 28: column value: 'lots' is not a whole number in 0..100"
printf 'session,attempt\nsa,2\n' >"$T/l3/answers.csv"
run "answers without columns" 2 "$H" report "$T/l3" --out "$T/r3"
one_line "answers without columns" "answers.csv: line 1: no column 'participant'"
# without points.csv and answers.csv: no such rows, no error
rm "$T/l3/points.csv" "$T/l3/answers.csv"
run "no instruments" 0 "$H" report "$T/l3" --out "$T/r3"
grep -q 'error_true\|ssq_\|likert' "$T/r3/stats.csv" && bad "rows from no data" || ok

# factor columns after picture: q (numeric), cues (the summary's), minimap
# (the level's place, read from level-HASH.txt), the log folder from DIR
mkdir -p "$T/f/logs/a" "$T/f/out"
HA=$(cd "$(dirname "$H")" && pwd)/$(basename "$H") # the binary from another folder
{
    echo "$S"
    echo 'sa,P01,x,0.1.0,1,s1,map,1,lvl,abc,flag,5,6,"4,6",3x3,1,x,5,5,10,done'
    echo 'sa,P01,x,0.1.0,2,s1,map,2,lvl,,flag,5,,"4,5",4x4,0.75,x,5,5,10,done'
} >"$T/f/logs/a/summary.csv"
printf 'mode flag\nseed 5\nflag Nf\nminimap hand\n' >"$T/f/logs/a/level-abc.txt"
(cd "$T/f" && "$HA" report logs/a --out out/r >/dev/null 2>&1) && ok || bad "report of factors"
head -1 "$T/f/out/r/attempts.csv" | grep -q ',logdir,picture,q,cues,minimap,logdir_relative,session_no$' && ok ||
    bad "attempts.csv header: $(head -1 "$T/f/out/r/attempts.csv")"
[ "$(sed -n 2p "$T/f/out/r/attempts.csv" | cut -d, -f18-)" = 'logs/a,,6,6,hand,../../logs/a,' ] && ok ||
    bad "factors row 1: $(sed -n 2p "$T/f/out/r/attempts.csv")"
[ "$(sed -n 3p "$T/f/out/r/attempts.csv" | cut -d, -f16-)" = '4x4,0.75,logs/a,,5,,,../../logs/a,' ] && ok ||
    bad "factors row 2: $(sed -n 3p "$T/f/out/r/attempts.csv")"
(cd "$T/f/logs/a" && "$HA" report . --out r >/dev/null 2>&1) && ok || bad "report inside the logs"
[ "$(sed -n 2p "$T/f/logs/a/r/attempts.csv" | cut -d, -f23)" = '..' ] && ok ||
    bad "the logs from inside: $(sed -n 2p "$T/f/logs/a/r/attempts.csv")"
echo 'sa,P01,x,0.1.0,3,s1,map,2,lvl,,flag,5,many,"4,5",3x3,1,x,5,5,10,done' >>"$T/f/logs/a/summary.csv"
run "bad cues" 2 "$H" report "$T/f/logs/a" --out "$T/f/bad"
one_line "bad cues" "line 4: column cues: not a whole number"

finish cli_report_stats
