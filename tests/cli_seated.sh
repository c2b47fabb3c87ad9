#!/bin/sh
# cli_seated.sh - seated play (issue 37; docs/teaching.md): play --seated
# turns the move axes (keys, a stick, a script's m=) into one room step a
# push; lesson 1 stepped seated ends as the walked lesson does (done in 4
# steps on the same tile and cell), the recording carries the seated flag
# and the step buttons, and replays to the same logs byte for byte.
. tests/lib.sh

# lesson1_input SEATED: the right prediction ({4,5}: No, one press right),
# the instructions' confirm, the square N, E, S, W (walked by a tracked
# head, or seated: pushes of the move axes with a rest between), the end
# screen's and the closing screen's confirms
lesson1_input() {
    awk -v seated="$1" 'BEGIN {
        t = 0; c = 1; r = 1
        f(""); f(""); f(" m=1,0"); f(""); f(" p=1"); f(""); f(" p=1"); f("")
        split("0,1 1,0 0,-1 -1,0", push, " "); split("0 1 0 -1", dc, " "); split("-1 0 1 0", dr, " ")
        for (i = 1; i <= 4; i++) {
            if (seated) { f(" m=" push[i]); f("") } else { c += dc[i]; r += dr[i]; f("") }
        }
        f(""); f(" p=1"); f(""); f(" p=1"); f("")
    }
    function f(extra) {
        if (seated) printf "%g f=8%s\n", t, extra
        else printf "%g f=9%s h=%d.5,1.6,%d.5,0,0,0,1\n", t, extra, c, r
        t += 0.5
    }'
}

start_xvfb 57 || { echo "cli_seated: no Xvfb, skipped"; exit 0; }

lesson1_input 0 >"$T/walk.in"
lesson1_input 1 >"$T/seat.in"
run "lesson 1 walked" 0 "$H" play --lesson 1 --input "$T/walk.in" --size 64x48 --log "$T/w"
cp "$T/out" "$T/walk.out"
run "lesson 1 seated" 0 "$H" play --lesson 1 --seated --input "$T/seat.in" --size 64x48 \
    --log "$T/s" --record "$T/s.rec"
grep -q "^level lesson-1 done steps 4 optimum -1 " "$T/out" && ok || bad "seated: $(cat "$T/out")"
[ "$(cut -d' ' -f1-11 "$T/out")" = "$(cut -d' ' -f1-11 "$T/walk.out")" ] && ok ||
    bad "seated and walked differ: $(cat "$T/out") / $(cat "$T/walk.out")"
col() { awk -F, -v n="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) k = i } NR > 1 { print $k }' "$1"; }
for c in steps optimum; do
    [ "$(col "$T/s/summary.csv" $c)" = "$(col "$T/w/summary.csv" $c)" ] && ok ||
        bad "summary's $c: seated $(col "$T/s/summary.csv" $c), walked $(col "$T/w/summary.csv" $c)"
done
grep -q ",predict,before_level,lesson1,choice,No," "$T/s/answers.csv" && ok ||
    bad "seated answer: $(cat "$T/s/answers.csv")"
# the record holds the seated flag (1000) and the step buttons (100..800)
grep -q ' f=1008 ' "$T/s.rec" && grep -q ' p=100 ' "$T/s.rec" && grep -q ' p=800 ' "$T/s.rec" && ok ||
    bad "seated recording: $(grep -c f=1008 "$T/s.rec") seated records"
mkdir "$T/s-replay"
run "replay seated" 0 "$H" replay "$T/s.rec" --log "$T/s-replay"
logs_diff "$T/s" "$T/s-replay" >/dev/null && ok || bad "seated replay's logs differ"
# a held push is one step; the hedge takes none
printf '0 f=8\n0.5 f=8 m=0,1\n1 f=8 m=0,1\n1.5 f=8 m=0,1\n2 f=8\n2.5 f=8 m=0,1\n3 f=8\n' >"$T/held.in"
run "held push" 0 "$H" play --mode explore --seated --input "$T/held.in" --size 64x48
grep -q " steps 1 " "$T/out" && ok || bad "held push then the hedge: $(cat "$T/out")"
run "--help names --seated" 0 "$H" play --help
grep -q -- "--seated " "$T/out" && ok || bad "play --help: no --seated"

finish cli_seated
