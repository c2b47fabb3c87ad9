#!/bin/sh
# cli_report_scatter.sh - the steps-against-optimum plot of `holonomy
# report`'s page (docs/research.md "Report"): attempts of a condition with
# the same optimum and steps are one circle whose area is their number,
# the number written in it (or beside it) and in its tooltip; conditions
# at one place side by side in the legend's order; a key in the legend
# says what the size means. Before issue 26's fix every attempt was a
# circle of its own, so n equal attempts looked like one.
. "$(dirname "$0")/lib.sh"

S='session,participant,session_start,version,attempt,study,condition,position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end'
# row SESSION PARTICIPANT ATTEMPT CONDITION POSITION STEPS OPTIMUM [END]
row() {
    printf '%s,%s,2026-01-31T14:05:09Z,0.1.0,%s,s1,%s,%s,lvl,,flag,5,,"4,5",3x3,1,2026-01-31T14:05:09Z,%s,%s,10,%s\n' \
        "$1" "$2" "$3" "$4" "$5" "$6" "$7" "${8:-done}"
}
svg() { sed -n '/aria-label="steps against optimum"/,/<\/svg>/p' "$1/index.html"; }
# attr FILE TITLE NAME: attribute NAME of the circle whose tooltip is TITLE
attr() {
    svg "$1" | grep -F "<title>$2</title>" | sed -n "s/.*<circle[^>]* $3=\"\([0-9.]*\)\".*/\1/p"
}

mkdir "$T/a"
{
    echo "$S"
    row sa P01 1 practice 0 4 4              # practice: not plotted
    row sa P01 2 a 1 4 4; row sb P02 1 a 1 4 4; row sc P03 1 a 1 4 4
    row sd P04 1 a 1 6 4                     # one attempt: no number
    row sa P01 3 b 2 4 4; row sb P02 2 b 2 4 4
    row sc P03 2 b 2 9 4 timeout             # not completed: not plotted
} >"$T/a/summary.csv"
run "report" 0 "$H" report "$T/a" --out "$T/ra"
n=$(svg "$T/ra" | grep -c '<g class="pt">')
[ "$n" = 3 ] && ok || bad "points: $n, want 3 (a at 4,4; a at 4,6; b at 4,4)"
svg "$T/ra" | grep -F '<title>s1 / a: optimum 4, steps 4, 3 attempts</title></circle><text class="count"' |
    grep -q '>3</text></g>' && ok || bad "a at 4,4: 3 attempts, the count written: $(svg "$T/ra" | grep -F 'optimum 4, steps 4')"
svg "$T/ra" | grep -F '<title>s1 / b: optimum 4, steps 4, 2 attempts</title></circle><text class="count"' |
    grep -q '>2</text></g>' && ok || bad "b at 4,4: 2 attempts"
svg "$T/ra" | grep -qF '<title>s1 / a: optimum 4, steps 6, 1 attempt</title></circle></g>' && ok ||
    bad "a at 4,6: one attempt, no count"
# the counts add up to the legend's n
svg "$T/ra" | grep -qF '>s1 / a (n = 4)</text>' && svg "$T/ra" | grep -qF '>s1 / b (n = 2)</text>' &&
    ok || bad "legend n: $(svg "$T/ra" | grep -o '>s1 / [^<]*<')"
# the area is the number of attempts: r^2 of 3 attempts = 3 r^2 of one
r3=$(attr "$T/ra" 's1 / a: optimum 4, steps 4, 3 attempts' r)
r2=$(attr "$T/ra" 's1 / b: optimum 4, steps 4, 2 attempts' r)
r1=$(attr "$T/ra" 's1 / a: optimum 4, steps 6, 1 attempt' r)
awk -v a="$r3" -v b="$r2" -v c="$r1" 'BEGIN { e = 0.01
    exit !(c > 0 && (a * a) / (c * c) > 3 - e && (a * a) / (c * c) < 3 + e &&
           (b * b) / (c * c) > 2 - e && (b * b) / (c * c) < 2 + e) }' && ok ||
    bad "radii $r3 $r2 $r1: areas not 3 : 2 : 1"
# a and b at the same place: side by side (a first, as in the legend), apart
xa=$(attr "$T/ra" 's1 / a: optimum 4, steps 4, 3 attempts' cx)
xb=$(attr "$T/ra" 's1 / b: optimum 4, steps 4, 2 attempts' cx)
ya=$(attr "$T/ra" 's1 / a: optimum 4, steps 4, 3 attempts' cy)
yb=$(attr "$T/ra" 's1 / b: optimum 4, steps 4, 2 attempts' cy)
awk -v xa="$xa" -v xb="$xb" -v ra="$r3" -v rb="$r2" -v ya="$ya" -v yb="$yb" \
    'BEGIN { exit !(ya == yb && xb - xa >= ra + rb) }' && ok ||
    bad "a ($xa,$ya r $r3) and b ($xb,$yb r $r2) overlap or are out of order"
# the legend's key to the size, and the caption
svg "$T/ra" | grep -qF '>circle area: attempts</text>' && svg "$T/ra" | grep -qF '>1 attempt</text>' &&
    svg "$T/ra" | grep -qF '>3 attempts</text>' && ok || bad "size key: $(svg "$T/ra" | grep size-key)"
grep -q 'one circle, its area their number' "$T/ra/index.html" && ok || bad "caption"

# ---- 300 equal attempts: one circle, not larger than the plot allows ----
mkdir "$T/b"
{
    echo "$S"
    i=1
    while [ $i -le 300 ]; do row "s$i" "P$i" 1 a 1 5 5; i=$((i + 1)); done
    row s0 P0 1 a 1 7 5
} >"$T/b/summary.csv"
run "report 301" 0 "$H" report "$T/b" --out "$T/rb"
n=$(svg "$T/rb" | grep -c '<g class="pt">')
[ "$n" = 2 ] && ok || bad "points: $n, want 2"
svg "$T/rb" | grep -F '<title>s1 / a: optimum 5, steps 5, 300 attempts</title>' | grep -q '>300</text>' &&
    ok || bad "300 attempts written"
r=$(attr "$T/rb" 's1 / a: optimum 5, steps 5, 300 attempts' r)
r1=$(attr "$T/rb" 's1 / a: optimum 5, steps 7, 1 attempt' r)
awk -v r="$r" -v c="$r1" 'BEGIN { exit !(r <= 18 && c >= 1.5 && c < r) }' && ok ||
    bad "radii $r (300) and $r1 (1): want at most 18 and at least 1.5"
svg "$T/rb" | grep -qF '>300 attempts</text>' && ok || bad "size key 300"

finish cli_report_scatter
