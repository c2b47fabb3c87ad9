#!/bin/sh
# cli_report_chart.sh - two things of `holonomy report`'s statistics
# (docs/research.md "Report"): the learning curves' 95 % CI bars end in a
# cap, or in an arrow where the plot (0..1.05) cuts them, and the legends
# say n; conditions are listed in the study file's order (study-HASH.txt
# in the log folder), practice first, those no study file names after by
# name, the same in conditions.csv, stats.csv, learning.csv,
# participants.csv and the page, whatever order participants played.
. "$(dirname "$0")/lib.sh"

S='session,participant,session_start,version,attempt,study,condition,position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end'
# row SESSION PARTICIPANT ATTEMPT STUDY CONDITION POSITION STEPS OPTIMUM
row() {
    printf '%s,%s,2026-01-31T14:05:09Z,0.1.0,%s,%s,%s,%s,lvl,,flag,5,,"4,5",3x3,1,2026-01-31T14:05:09Z,%s,%s,10,done\n' "$@"
}

# ---- CI bars: the plot is 300 px high, efficiency 0 at y 320, 1.05 at y 5 ----
mkdir "$T/c"
{
    echo "$S"
    # wide: efficiencies 1 and 0.5 at position 1 (n 2): t(.975, 1) = 12.706, [-2.427, 3.927], both ends cut
    row sa P01 1 s1 wide 1 4 4; row sb P02 1 s1 wide 1 8 4
    # narrow: 0.5, 0.5, 0.6 (n 3): [0.390, 0.677], two caps
    row sa P01 2 s1 narrow 2 8 4; row sb P02 2 s1 narrow 2 8 4; row sc P03 1 s1 narrow 2 10 6
    # high: 1, 1, 0.8 (n 3): [0.646, 1.220], a cap below, an arrow above
    row sa P01 3 s1 high 3 4 4; row sb P02 3 s1 high 3 4 4; row sc P03 2 s1 high 3 5 4
} >"$T/c/summary.csv"
run "report" 0 "$H" report "$T/c" --out "$T/cr"
grep -qx 's1,wide,1,2,0.7500,0.3536,-2.4266,3.9266' "$T/cr/learning.csv" &&
    grep -qx 's1,narrow,2,3,0.5333,0.0577,0.3899,0.6768' "$T/cr/learning.csv" &&
    grep -qx 's1,high,3,3,0.9333,0.1155,0.6465,1.2202' "$T/cr/learning.csv" && ok ||
    bad "learning.csv: $(cat "$T/cr/learning.csv")"
svg() { sed -n '/aria-label="learning curves"/,/<\/svg>/p' "$T/cr/index.html"; }
[ "$(svg | grep -o 'class="ci-cut"' | wc -l)" = 3 ] && ok ||
    bad "cut ends: $(svg | grep -o 'class="ci-cut"' | wc -l), want 3"
[ "$(svg | grep -o 'class="ci-cap"' | wc -l)" = 3 ] && ok ||
    bad "caps: $(svg | grep -o 'class="ci-cap"' | wc -l), want 3"
# the arrows' tips are on the plot's edges: two at the top (y 5), one at 0 (y 320)
[ "$(svg | grep -o 'class="ci-cut" points="[^"]*,5\.0"' | wc -l)" = 2 ] && ok || bad "top arrows"
[ "$(svg | grep -o 'class="ci-cut" points="[^"]*,320\.0"' | wc -l)" = 1 ] && ok || bad "bottom arrow"
# and point out of the plot: the base below the top tip, above the bottom one
svg | grep -q 'class="ci-cut" points="[0-9.]*,12\.0 [0-9.]*,12\.0 [0-9.]*,5\.0"' &&
    svg | grep -q 'class="ci-cut" points="[0-9.]*,313\.0 [0-9.]*,313\.0 [0-9.]*,320\.0"' && ok ||
    bad "arrow directions: $(svg | grep -o 'class="ci-cut" points="[^"]*"')"
# the narrow bar's caps at 0.6768 and 0.3899: y 320 - 300 v
svg | grep -q 'class="ci-cap" x1="[0-9.]*" y1="117\.0"' && svg | grep -q 'class="ci-cap" x1="[0-9.]*" y1="203\.0"' &&
    ok || bad "caps' places: $(svg | grep -o 'class="ci-cap"[^/]*')"
grep -q "bars cut at the plot's edge (0 and 1.05) end in an arrow" "$T/cr/index.html" && ok || bad "caption"
# n in the legends: a range per condition (learning curves), a count (scatter)
svg | grep -q '>s1 / wide (n = 2)</text>' && ok || bad "learning legend: $(svg | grep -o '>s1 / [^<]*<')"
svg | grep -q '<title>position 1: mean 0.750, n = 2</title>' && ok || bad "a point's title"
sed -n '/aria-label="steps against optimum"/,/<\/svg>/p' "$T/cr/index.html" |
    grep -q '>s1 / narrow (n = 3)</text>' && ok || bad "scatter legend"
mkdir "$T/c2"
{
    echo "$S"
    row sa P01 1 s1 a 1 4 4; row sb P02 1 s1 a 2 4 4; row sc P03 1 s1 a 2 5 4
} >"$T/c2/summary.csv"
run "report n range" 0 "$H" report "$T/c2" --out "$T/cr2"
grep -q '>s1 / a (n = 1&#8211;2)</text>' "$T/cr2/index.html" && ok || bad "n range in the legend"

# ---- order: the study file's, not the first participant's ----
mkdir "$T/l1" "$T/l2"
{
    echo "$S"
    row sa P01 1 s1 practice 0 3 3
    row sa P01 2 s1 mid 1 4 4
    row sa P01 3 s1 extra 2 4 4   # in no study file: after the file's, by name
    row sa P01 4 s1 alpha 3 5 4
    row sa P01 5 s1 zeta 4 6 4
    row sb P02 1 s1 zeta 1 4 4
} >"$T/l1/summary.csv"
cat >"$T/l1/study-0123abcd.txt" <<'E'
# the study file as play --study keeps it
study s1
counterbalance williams
practice p.txt
condition zeta
level z.txt
condition alpha
level a.txt
condition mid
level m.txt
E
# not study files, or not readable as one: left alone (a fifo is not opened)
printf 'study s1\ncondition mid\nlevel m.txt\ncondition alpha\nlevel a.txt\ncondition\n' >"$T/l1/study-0000bad.txt"
mkfifo "$T/l1/study-fifo.txt"
{
    echo "$S"
    row sc P03 1 s2 bb 1 4 4    # no study file for s2: by name
    row sc P03 2 s2 aa 2 4 4
    row sc P03 3 s2 c10 3 4 4   # numbers in names by value: c2 before c10
    row sc P03 4 s2 c2 4 4 4
} >"$T/l2/summary.csv"
run "report in order" 0 "$H" report "$T/l1" "$T/l2" --out "$T/or"
want='s1,practice s1,zeta s1,alpha s1,mid s1,extra s2,aa s2,bb s2,c2 s2,c10'
got=$(tail -n +2 "$T/or/conditions.csv" | cut -d, -f1,2 | tr '\n' ' ' | sed 's/ $//')
[ "$got" = "$want" ] && ok || bad "conditions.csv order: $got, want $want"
got=$(tail -n +2 "$T/or/stats.csv" | cut -d, -f1,2 | uniq | tr '\n' ' ' | sed 's/ $//')
[ "$got" = "${want#s1,practice }" ] && ok || bad "stats.csv order: $got"
got=$(tail -n +2 "$T/or/learning.csv" | cut -d, -f1,2 | uniq | tr '\n' ' ' | sed 's/ $//')
[ "$got" = "${want#s1,practice }" ] && ok || bad "learning.csv order: $got"
got=$(grep '^P01,' "$T/or/participants.csv" | cut -d, -f3 | tr '\n' ' ' | sed 's/ $//')
[ "$got" = 'practice zeta alpha mid extra' ] && ok || bad "participants.csv order: $got"
# the page: the means table and the legend in the same order
got=$(sed -n '/<h2>Statistics/,/<\/table>/p' "$T/or/index.html" | grep -o '<tr><td>s[12] / [a-z0-9]*' |
    sed 's/.*\/ //' | uniq | tr '\n' ' ' | sed 's/ $//')
[ "$got" = 'zeta alpha mid extra aa bb c2 c10' ] && ok || bad "the page's table: $got"
got=$(sed -n '/aria-label="learning curves"/,/<\/svg>/p' "$T/or/index.html" | grep -o '>s[12] / [a-z0-9]*' |
    sed 's/.*\/ //' | tr '\n' ' ' | sed 's/ $//')
[ "$got" = 'zeta alpha mid extra aa bb c2 c10' ] && ok || bad "the legend: $got"
# the per-condition table of the page follows conditions.csv
got=$(sed -n '/conditions.csv/,/<\/table>/p' "$T/or/index.html" | grep -o '<tr><td>s[12]</td><td>[a-z0-9]*' |
    sed 's/.*<td>//' | tr '\n' ' ' | sed 's/ $//')
[ "$got" = 'practice zeta alpha mid extra aa bb c2 c10' ] && ok || bad "the page's conditions: $got"

finish cli_report_chart
