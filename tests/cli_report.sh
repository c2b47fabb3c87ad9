#!/bin/sh
# cli_report.sh - `holonomy report LOGDIR... --out DIR` through the binary:
# logs made by `replay` of hand-written recordings (two participants, two
# conditions of a study, a killed attempt), the aggregate CSV against the
# summary rows and `nav`'s optima, efficiency, per-condition means, the
# page links every picture and escapes names, the pictures decode with the
# walked and optimal paths drawn (a golden reviewed by eye), refusals.
. "$(dirname "$0")/lib.sh"
P=${PNG_PROBE:-build/tests/png_probe}
G=$(dirname "$0")/golden

# rec PARTICIPANT CONDITION LEVELNAME WALK: a study's recording (version 3)
# of the flag level at Nf, walking the room steps WALK (lib.sh walk_input)
rec() {
    printf 'holonomy-rec 3\nsession 20260131T140509Z-0000000%s\nparticipant %s\n' "${1#P0}" "$1"
    printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\nstudy s1\nlevel %s\n' "$3"
    printf 'condition %s 1\nL mode flag\nL seed 5\nL flag Nf\nend\n' "$2"
    walk_input "$4"
}

run "--help" 0 "$H" report --help
grep -q -- "--out DIR" "$T/out" && grep -q "attempts.csv" "$T/out" && ok ||
    bad "--help does not describe --out and the files"
"$H" --help | grep -q "^  report " && ok || bad "holonomy --help does not list report"

printf -- '- Nf\n' | "$H" nav >"$T/nav" || bad "nav"
K=$(cut -d' ' -f1 "$T/nav") WALK=$(cut -d' ' -f2 "$T/nav")
[ "$K" = 5 ] && ok || bad "nav's optimum for Nf: $K"
rec P01 map flag-a "$WALK" >"$T/a.rec"
rec P02 nomap '<b>&"x' "SN$WALK" >"$T/b.rec"
rec P03 nomap flag-c "W" >"$T/c.rec"
for p in a b c; do
    run "replay $p" 0 "$H" replay "$T/$p.rec" --log "$T/l$p"
done
# a killed attempt: its end as a later --append session writes it
sed -i '2s/,open,,,$/,killed,,,/' "$T/lc/summary.csv"
grep -q ',killed,,,$' "$T/lc/summary.csv" && ok || bad "the killed row was not made"

run "report" 0 "$H" report "$T/la" "$T/lb" "$T/lc" --out "$T/out1"
[ "$(cat "$T/out")" = "report: 3 attempts from 3 log folders" ] && ok || bad "stdout: $(cat "$T/out")"
[ ! -s "$T/err" ] && ok || bad "warnings on good logs: $(cat "$T/err")"
ls "$T/out1" | tr '\n' ' ' >"$T/ls"
[ "$(cat "$T/ls")" = "attempt-0001.png attempt-0002.png attempt-0003.png attempts.csv build.csv codebook.csv conditions.csv effects.csv index.html learning.csv paired.csv participants.csv participants_stats.csv scores.csv stats.csv trials.csv " ] &&
    ok || bad "files: $(cat "$T/ls")"

# the CSV: one row per attempt, values from the summaries
C="$T/out1/attempts.csv"
head -1 "$C" | grep -qx 'participant,session,attempt,study,condition,position,level,mode,steps,optimum,efficiency,time,end,tiling,room,cell,logdir,picture,q,cues,minimap,logdir_relative,session_no' &&
    ok || bad "header: $(head -1 "$C")"
[ "$(wc -l <"$C")" = 4 ] && ok || bad "rows: $(wc -l <"$C")"
sed -n 2p "$C" | grep -q "^P01,20260131T140509Z-00000001,1,s1,map,1,flag-a,flag,$K,$K,1.0000,[0-9.]*,done,\"4,5\",3x3,1,.*,attempt-0001.png,5,15,hud,\.\./la,\$" &&
    ok || bad "row 1: $(sed -n 2p "$C")"
EFF=$(awk -v k="$K" 'BEGIN { printf "%.4f", k / (k + 2) }')
sed -n 3p "$C" | grep -qF "P02,20260131T140509Z-00000002,1,s1,nomap,1,\"<b>&\"\"x\",flag,$((K + 2)),$K,$EFF," &&
    ok || bad "row 2 (efficiency $EFF, the name quoted): $(sed -n 3p "$C")"
sed -n 4p "$C" | grep -q "^P03,.*,flag-c,flag,1,$K,,[0-9.]*,killed," && ok ||
    bad "row 3 (killed, no efficiency): $(sed -n 4p "$C")"
for p in a b c; do # steps, optimum, time and end as in each summary
    s=$(tail -1 "$T/l$p/summary.csv" | awk -F, '{ print $(NF-6) "," $(NF-5) ",[0-9.]*," $(NF-4) "," $(NF-3) }')
    grep -q ",$s," "$C" && ok || bad "summary of $p ($s) not in the CSV"
done
grep -qx 'study,condition,attempts,done,mean_steps,mean_efficiency,mean_time' "$T/out1/conditions.csv" &&
    grep -qx "s1,map,1,1,$K.00,1.0000,[0-9.]*" "$T/out1/conditions.csv" &&
    grep -qx "s1,nomap,2,1,$(awk -v k="$K" 'BEGIN { printf "%.2f", (k + 3) / 2 }'),$EFF,[0-9.]*" "$T/out1/conditions.csv" &&
    ok || bad "conditions: $(cat "$T/out1/conditions.csv")"

# the page: every picture linked, names escaped, the killed row marked
I="$T/out1/index.html"
for f in "$T/out1"/attempt-*.png; do
    b=$(basename "$f")
    grep -q "<img src=\"$b\"" "$I" && ok || bad "index.html does not show $b"
done
grep -qF '&lt;b&gt;&amp;&quot;x' "$I" && ! grep -qF '<b>&' "$I" && ok || bad "the level's name is not escaped"
grep -q '<tr class="killed">' "$I" && ok || bad "the killed attempt is not marked"
grep -q 'href="attempts.csv"' "$I" && ok || bad "index.html does not link attempts.csv"

# the pictures decode (render/hol_png.c), with both paths drawn
for n in 1 2 3; do
    "$P" "$T/out1/attempt-000$n.png" dc5014 78aaf0 >"$T/probe" || bad "picture $n does not decode"
    [ "$(sed -n 1p "$T/probe")" = "480 480" ] && ok || bad "picture $n size $(sed -n 1p "$T/probe")"
    [ "$(sed -n 2p "$T/probe")" -gt 100 ] && [ "$(sed -n 3p "$T/probe")" -gt 100 ] && ok ||
        bad "picture $n: walked/optimal pixels $(sed -n 2,3p "$T/probe" | tr '\n' ' ')"
done
# the detour (S, N, then the optimal walk), reviewed by eye: tests/golden/report_detour.png
d=$("$P" "$T/out1/attempt-0002.png" --vs "$G/report_detour.png")
[ "${d:-99999}" -lt 200 ] && ok || bad "picture 2 differs from the golden in ${d:-?} pixels"

# another geometry: {4,6} in a 4 x 4 room (the summary's columns), walked N, E, W, N
{ printf 'holonomy-rec 2\nsession 20260131T140509Z-00000009\nstart 2026-01-31T14:05:09Z\n'
  printf 'version 0.1.0\nlevel q6\nL mode flag\nL seed 5\nL tiling 4 6\nL room 4 4\nL flag Nf\nend\n'
  printf '%s f=9 h=%s,1.6,%s,0,0,0,1\n' 0 2.5 2.5 1 2.5 1.5 2 3.5 1.5 3 2.5 1.5 4 2.5 0.5 5 2.5 0.5
} >"$T/q6.rec"
run "replay q6" 0 "$H" replay "$T/q6.rec" --log "$T/lq6"
K6=$(printf -- '- Nf\n' | "$H" nav --tiling 4,6 --room 4x4 | cut -d' ' -f1)
run "report q6" 0 "$H" report "$T/lq6" --out "$T/out6"
sed -n 2p "$T/out6/attempts.csv" | grep -q ",q6,flag,4,$K6,[0-9.]*,[0-9.]*,done,\"4,6\",4x4,1," && ok ||
    bad "{4,6} 4x4 row (optimum $K6): $(sed -n 2p "$T/out6/attempts.csv")"
"$P" "$T/out6/attempt-0001.png" dc5014 78aaf0 >"$T/probe" &&
    [ "$(sed -n 2p "$T/probe")" -gt 100 ] && [ "$(sed -n 3p "$T/probe")" -gt 100 ] && ok ||
    bad "{4,6} picture: $(cat "$T/probe" | tr '\n' ' ')"

# DIR again: a report's own files are replaced; a foreign file is refused
run "again" 0 "$H" report "$T/la" --out "$T/out1"
[ ! -e "$T/out1/attempt-0002.png" ] && [ "$(wc -l <"$C")" = 2 ] && ok || bad "the rerun left old pictures"
touch "$T/out1/notes.txt"
run "foreign file" 2 "$H" report "$T/la" --out "$T/out1" && one_line "foreign file" "notes.txt"

# refusals: one line, exit 2, nothing written
run "no folder" 2 "$H" report --out "$T/o2" && one_line "no folder" "no log folder"
run "no --out" 2 "$H" report "$T/la" && one_line "no --out" "--out DIR is required"
run "--out twice" 2 "$H" report "$T/la" --out "$T/o2" --out "$T/o3" && one_line "--out twice" "twice"
run "not a folder" 2 "$H" report "$T/a.rec" --out "$T/o2" && one_line "not a folder" "a.rec"
run "--out a file" 2 "$H" report "$T/la" --out "$T/a.rec" && one_line "--out a file" "not a folder"
run "--out parent" 2 "$H" report "$T/la" --out "$T/none/o" && one_line "--out parent" "does not exist"
run "unknown option" 2 "$H" report "$T/la" --out "$T/o2" --fast && one_line "unknown option" "fast"
cp -r "$T/la" "$T/bad1"
sed -i "2s/,$K,$K,\([0-9.]*\),done,,,\$/,${K}x,$K,\1,done,,,/" "$T/bad1/summary.csv"
cp -r "$T/la" "$T/bad2"
awk -F, -v OFS=, 'NR == 3 { $10 = "Q" } { print }' "$T/la/steps-001.csv" >"$T/bad2/steps-001.csv"
run "bad steps" 2 "$H" report "$T/la" "$T/bad2" --out "$T/o2" &&
    one_line "bad steps" "bad2/steps-001.csv: line 3: column tile"
run "bad summary" 2 "$H" report "$T/bad1" --out "$T/o2" &&
    one_line "bad summary" "bad1/summary.csv: line 2: column steps"
[ ! -e "$T/o2" ] && ok || bad "a refused report made its folder"
printf 'session,attempt\n' >"$T/bad1/summary.csv"
run "no columns" 2 "$H" report "$T/bad1" --out "$T/o2" && one_line "no columns" "summary.csv: line 1: column level: missing"
printf 'a,"b\n' >"$T/bad1/summary.csv"
run "open quote" 2 "$H" report "$T/bad1" --out "$T/o2" && one_line "open quote" "closing quote"
run "--out new/" 0 "$H" report "$T/la" --out "$T/o5/" && [ -f "$T/o5/index.html" ] && ok ||
    bad "--out with a trailing slash"
# a missing steps file: a warning, the row without a picture
cp -r "$T/la" "$T/miss" && rm "$T/miss/steps-001.csv"
run "missing steps" 0 "$H" report "$T/miss" --out "$T/o4" && one_line "missing steps" "warning: .*steps-001.csv: missing"
[ ! -e "$T/o4/attempt-0001.png" ] && grep -q ',done,"4,5",3x3,1,.*,,5,15,hud,\.\./miss,$' "$T/o4/attempts.csv" && ok ||
    bad "missing steps: $(cat "$T/o4/attempts.csv")"

finish cli_report
