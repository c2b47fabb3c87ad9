#!/bin/sh
# cli_lesson.sh - the lessons (issue 37; docs/teaching.md): a scripted
# pupil completes every lesson, in {4,5} and in the flat {4,4}, once with
# the right prediction and once with a wrong one: the prediction is logged
# in answers.csv (questionnaire predict, item lessonN), the walk ends done,
# lesson 3's pointing lands in points.csv, and the recording replays to the
# same logs. Refusals: a lesson beside a line it sets, a lesson out of
# range, --lesson beside a LEVEL.
. tests/lib.sh

# lesson_input ROUTE PRESSES POINT: frames of a pupil: the predict item
# (PRESSES right, or left when negative, from the middle mark; confirm), the
# instructions' and the ready screen's confirms, the hint asked for (HINT 1:
# the menu's button, twice), the route's room steps, the pointing's confirm
# (POINT 1), the end screen's and the closing screen's confirms
lesson_input() {
    awk -v route="$1" -v presses="$2" -v point="$3" -v hint="${4:-0}" 'BEGIN {
        t = 0; c = 1; r = 1
        f(""); f("")
        n = presses < 0 ? -presses : presses; m = presses < 0 ? -1 : 1
        for (i = 0; i < n; i++) { f(" m=" m ",0"); f("") }
        f(" p=1"); f(""); f(" p=1"); f(""); f(" p=1"); f("")
        if (hint) { f(" p=4"); f(""); f(" p=4"); f("") }
        for (i = 1; i <= length(route); i++) {
            s = substr(route, i, 1)
            if (s == "N") r--; else if (s == "S") r++; else if (s == "E") c++; else c--
            f("")
        }
        f(""); if (point) { f(" p=1"); f("") }
        f(" p=1"); f(""); f(" p=1"); f("")
    }
    function f(extra) { printf "%g f=9%s h=%d.5,1.6,%d.5,0,0,0,1\n", t, extra, c, r; t += 0.5 }'
}

# the scale's marks from the middle to a value: (value - lo) / step - middle
presses() { echo $(( ($1 - $2) / $3 - ($4 - 1) / 2 )); }

start_xvfb 53 || { echo "cli_lesson: no Xvfb, skipped"; exit 0; }

# route, then per tiling q (4, 5): the right answer as "choice:INDEX" or
# "scale:VALUE:LO:STEP:MARKS", and a wrong one's presses
for q in 4 5; do
    for n in 1 2 3 4 5 6; do
        case $n in
        1) route=NESW; marks=2; [ $q = 4 ] && right=0 || right=1; expect=$([ $q = 4 ] && echo Yes || echo No) ;;
        2) route=$(echo NWSENWSE | cut -c1-$q); lo=3; step=1; marks=7; right=$q ;;
        3) route=NWSE; marks=5; [ $q = 4 ] && right=0 || right=1; expect=$([ $q = 4 ] && echo "Under my feet" || echo North) ;;
        4) route=NESSWWNN; lo=4; step=4; marks=11; right=$([ $q = 4 ] && echo 12 || echo 28) ;;
        5) route=NESWSWNN; lo=0; step=1; marks=11; right=$([ $q = 4 ] && echo 2 || echo 4) ;;
        6) route=NESW; lo=1; step=1; marks=8; right=$([ $q = 4 ] && echo 1 || echo 5)
           [ $q = 5 ] && route=NESWNESWNESWNESWNESW ;;
        esac
        if [ $n = 1 ] || [ $n = 3 ]; then
            p=$(( right - (marks - 1) / 2 ))
        else
            p=$(presses "$right" $lo $step $marks); expect=$right
        fi
        for kind in right wrong; do
            d=$p
            [ $kind = wrong ] && { [ $p -lt $(( marks - 1 - (marks - 1) / 2 )) ] && d=$((p + 1)) || d=$((p - 1)); }
            lesson_input $route $d $([ $n = 3 ] && echo 1 || echo 0) >"$T/in"
            L="$T/l$q-$n-$kind"
            run "lesson $n {4,$q} $kind" 0 "$H" play --lesson $n --tiling 4,$q --input "$T/in" \
                --size 64x48 --log "$L" --record "$L.rec"
            grep -q "^level lesson-$n done steps ${#route} optimum -1 " "$T/out" && ok ||
                bad "lesson $n {4,$q} $kind: $(cat "$T/out")"
            row=$(grep ",predict,before_level,lesson$n," "$L/answers.csv" | cut -d, -f7-8)
            case $n in 1|3) got=${row#choice,} ;; *) got=${row#likert,} ;; esac
            if [ $kind = right ]; then
                [ "$got" = "$expect" ] && ok || bad "lesson $n {4,$q}: answer '$row', want $expect"
            else
                [ -n "$got" ] && [ "$got" != "$expect" ] && ok ||
                    bad "lesson $n {4,$q} wrong: answer '$row'"
            fi
            if [ $n = 3 ]; then
                [ "$(wc -l <"$L/points.csv")" = 2 ] && ok || bad "lesson 3 points: $(cat "$L/points.csv")"
            fi
            mkdir "$L-replay"
            run "replay lesson $n {4,$q} $kind" 0 "$H" replay "$L.rec" --log "$L-replay"
            logs_diff "$L" "$L-replay" >/dev/null && ok || bad "lesson $n {4,$q}: the replay's logs differ"
        done
    done
done

# in German: the same logs (the choice logged is the English one), and
# lesson 6's hint on request (the menu's button) is an event
lesson_input NESW 1 0 >"$T/in"
run "lesson 1 de" 0 "$H" play --lesson 1 --lang de --input "$T/in" --size 64x48 --log "$T/de1"
[ "$(grep ',predict,before_level,lesson1,' "$T/de1/answers.csv" | cut -d, -f7-8)" = "choice,No" ] &&
    ok || bad "lesson 1 de: $(cat "$T/de1/answers.csv")"
lesson_input NESWNESWNESWNESWNESW 0 0 1 >"$T/in"
run "lesson 6 de hint" 0 "$H" play --lesson 6 --lang de --input "$T/in" --size 64x48 --log "$T/de6"
grep -q "^level lesson-6 done steps 20 optimum -1 " "$T/out" && ok || bad "lesson 6 de: $(cat "$T/out")"
[ "$(grep -c ',hint,lesson6$' "$T/de6/events.csv")" = 1 ] && ok ||
    bad "lesson 6 hint: $(cat "$T/de6/events.csv")"

# the headless game plays a lesson's walk (its route's steps done, not scored)
printf 'tiling 4 5\nlesson 6\n' >"$T/l6.lvl"
printf 'NESWNESWNESWNESWNESW\nNESW\n' >"$T/plays"
run "game lesson 6" 0 "$H" game "$T/l6.lvl" <"$T/plays"
[ "$(cat "$T/out")" = "done 20 -1
open 4 -1" ] && ok || bad "game lesson 6: $(cat "$T/out")"

# refusals: one line naming the line
printf 'lesson 2\nmode flag\n' >"$T/b1.lvl"
run "lesson beside mode" 2 "$H" game "$T/b1.lvl" </dev/null
grep -q "line 2: a lesson level sets its own 'mode': drop this line (line 1)" "$T/err" && ok ||
    bad "lesson beside mode: $(cat "$T/err")"
printf 'lesson 7\n' >"$T/b2.lvl"
run "lesson 7" 2 "$H" game "$T/b2.lvl" </dev/null
grep -q "line 1: lesson '7' is not a lesson 1..6" "$T/err" && ok || bad "lesson 7: $(cat "$T/err")"
run "--lesson 0" 2 "$H" play --lesson 0 --frames 1
grep -q "\-\-lesson '0' is not a lesson 1..6" "$T/err" && ok || bad "--lesson 0: $(cat "$T/err")"
run "--lesson with a level" 2 "$H" play --lesson 1 "$T/l6.lvl" --frames 1
grep -q "give no LEVEL" "$T/err" && ok || bad "--lesson with a level: $(cat "$T/err")"

# worksheets and keys: every lesson in {4,4} and {4,5}, SVG and HTML; the
# sheet asks and never answers, the key answers with the core's number
for q in 4 5; do
    for n in 1 2 3 4 5 6; do
        run "sheet $n {4,$q}" 0 "$H" lesson sheet $n --tiling 4,$q --out "$T/s$n-$q.svg"
        run "key $n {4,$q}" 0 "$H" lesson sheet $n --tiling 4,$q --key --out "$T/k$n-$q.html"
        grep -q '^<svg .*width="210mm" height="297mm"' "$T/s$n-$q.svg" && ok || bad "sheet $n: no A4 svg"
        grep -q 'href="data:image/png;base64,iVBORw0KGgo' "$T/s$n-$q.svg" && ok || bad "sheet $n: no picture"
        grep -q 'Answer' "$T/s$n-$q.svg" && bad "sheet $n answers" || ok
        grep -q "^<!doctype html>" "$T/k$n-$q.html" && grep -q '>Answer: ' "$T/k$n-$q.html" && ok ||
            bad "key $n {4,$q}: $(head -c 300 "$T/k$n-$q.html")"
    done
done
# the German sheet and key: the sheet's words and the lesson's, the same numbers
run "sheet 4 de" 0 "$H" lesson sheet 4 --lang de --out "$T/s4-de.svg"
grep -q '1. Sag voraus, bevor du gehst:' "$T/s4-de.svg" && grep -q 'Wie viele Kacheln liegen genau 3' "$T/s4-de.svg" &&
    ok || bad "sheet 4 de: $(head -c 600 "$T/s4-de.svg")"
grep -q 'Antwort' "$T/s4-de.svg" && bad "sheet 4 de answers" || ok
run "key 4 de" 0 "$H" lesson sheet 4 --lang de --key --out "$T/k4-de.html"
tr -d '\n' <"$T/k4-de.html" | sed 's/<[^>]*>/ /g; s/  */ /g' >"$T/k4de.txt"
grep -q 'Antwort: 28. In 1, 2, 3 Schritten liegen 4, 12, 28 Kacheln; im flachen Gitter 4, 8, 12' "$T/k4de.txt" &&
    grep -q '<title>Lektion 4</title>' "$T/k4-de.html" && ok || bad "key 4 de: $(cat "$T/k4de.txt")"
run "sheet --lang fr" 2 "$H" lesson sheet 4 --lang fr --out "$T/s4-fr.svg"
[ ! -e "$T/s4-fr.svg" ] && ok || bad "sheet --lang fr wrote a file"
tr -d '\n' <"$T/k4-5.html" | sed 's/<[^>]*>/ /g; s/  */ /g' >"$T/k4.txt"
grep -q 'Answer: 28. At 1, 2, 3 steps lie 4, 12, 28 tiles; on a flat grid 4, 8, 12; in {4,5} 4, 12, 28.' "$T/k4.txt" &&
    ok || bad "key 4 {4,5}: $(cat "$T/k4.txt")"
tr -d '\n' <"$T/k5-5.html" | sed 's/<[^>]*>/ /g; s/  */ /g' >"$T/k5.txt"
grep -q 'Answer: 4. You stand 2 cells from your start cell but 4 steps from the start tile (you are on Erlr).' "$T/k5.txt" &&
    ok || bad "key 5 {4,5}: $(cat "$T/k5.txt")"
if command -v xmllint >/dev/null 2>&1; then
    for f in "$T"/s*-*.svg; do xmllint --noout "$f" && ok || bad "$f is not well-formed"; done
fi
run "sheet --help" 0 "$H" lesson --help
grep -q '^usage: holonomy lesson sheet N --out' "$T/out" && ok || bad "lesson --help: $(cat "$T/out")"
run "sheet 7" 2 "$H" lesson sheet 7 --out "$T/x.svg"
run "sheet .png" 2 "$H" lesson sheet 1 --out "$T/x.png"
grep -q 'ending in .svg or .html' "$T/err" && ok || bad "sheet .png: $(cat "$T/err")"
run "sheet without --out" 2 "$H" lesson sheet 1
run "lesson list" 2 "$H" lesson list --out "$T/x.svg"

finish cli_lesson
