#!/bin/sh
# cli_onset.sh - a trial's onset (issue 35 item 6): one level_sha256 per
# level of a condition, whether or not it is the participant's last level
# (its closing and questionnaires `after study` are outside the hash), the
# level-HASH.txt of that hash holding the text its name is the sha256sum
# of; a resumed session begins on the ready screen (the clock waits for a
# confirm); a baseline questionnaire (`before study`, no practice) outside
# the first level's hash too. Under Xvfb (when installed).
. "$(dirname "$0")/lib.sh"

mkdir "$T/s"
printf 'mode flag\nseed 5\nflag Nf\n' >"$T/s/f.lvl"
printf 'study on\nclosing Thank you.\nquestionnaire ssq after study\ncondition a\nlevel f.lvl\nset minimap hud\ncondition b\nlevel f.lvl\nset minimap hand\n' >"$T/s/on.study"
S=$T/s/on.study

# Recordings made before the ready screen and the tutorial's new lessons
# (versions 4 and 2; kept in tests/onset/, played by the build before
# them, 7378889: flow.study's P1 whole, P2 quitting at condition one's
# instructions, then resumed with --resume; a tutorial walked with the
# pancake keys, tut.rec) replay as they were played: no ready screen after
# the instructions, the lessons as they were, the play's logs byte for
# byte (whole/, resumed/, tutorial/)
K=$(cd "$(dirname "$0")" && pwd)/onset
same() { # same DIR WANT: every file of WANT, byte for byte in DIR
    for f in "$2"/*; do
        cmp -s "$f" "$1/${f##*/}" || { bad "$1/${f##*/} differs from the play's"; return; }
    done
    ok
}
run "replay a version 4 recording" 0 "$H" replay "$K/whole.rec" --log "$T/o1"
same "$T/o1" "$K/whole"
run "replay a version 4 quit" 0 "$H" replay "$K/quit.rec" --log "$T/o2"
run "replay a version 4 resume" 0 "$H" replay "$K/resume.rec" --log "$T/o2" --append
same "$T/o2" "$K/resumed"
# a pancake tutorial (version 2, the same build): its lessons as they were
# (no turn to face a lesson's thing, no tutorial.csv)
run "replay a version 2 tutorial" 0 "$H" replay "$K/tut.rec" --log "$T/o3"
same "$T/o3" "$K/tutorial"
[ ! -e "$T/o3/tutorial.csv" ] && ok || bad "a version 2 tutorial's replay wrote tutorial.csv"
sed '1s/.*/holonomy-rec 5/' "$K/tut.rec" >"$T/tut5.rec"
run "replay it as version 5" 0 "$H" replay "$T/tut5.rec" --log "$T/o4"
cmp -s "$K/tutorial/steps-001.csv" "$T/o4/steps-001.csv" && bad "version 5 replayed the old lessons" || ok
[ -s "$T/o4/tutorial.csv" ] && ok || bad "version 5's tutorial wrote no tutorial.csv"
# the gate is the version: the same input as version 5 waits on the ready
# screen (condition one's attempt starts a confirm later, at 4.0, not 3.5)
sed '1s/.*/holonomy-rec 5/' "$K/whole.rec" >"$T/five.rec"
run "replay it as version 5" 0 "$H" replay "$T/five.rec" --log "$T/o5"
awk -F, 'NR == 3 { print $17 }' "$T/o5/summary.csv" >"$T/got5"
[ "$(cat "$T/got5")" != "3.5000" ] && ok || bad "version 5 replayed without the ready screen"

if ! command -v Xvfb >/dev/null 2>&1; then
    echo "note: no Xvfb here: the onset is not played"
    finish cli_onset
    exit $?
fi
start_xvfb 37 || { bad "Xvfb did not start"; finish cli_onset; exit $?; }
case $H in /*) ;; *) H=$PWD/$H ;; esac
cd "$T" || exit 1

# the first level done (5 steps), confirm: the second (the last) starts
# and the input ends (its attempt open)
{ walk_input WNESE; printf '1.5 f=9 p=1 h=2.5,1.6,1.5,0,0,0,1\n1.75 f=9 h=2.5,1.6,1.5,0,0,0,1\n'; } >in1
# "condition position level_sha256" of each row
rows() { awk -F, 'NR > 1 { print $7, $8, $10 }' "$1/summary.csv"; }
run "P01 (a, b)" 0 "$H" play --study "$S" --participant P01 --size 64x48 --log l1 --input in1 --record r1.rec
run "P02 (b, a)" 0 "$H" play --study "$S" --participant P02 --size 64x48 --log l2 --input in1
[ "$(rows l1 | awk '{ print $1, $2 }' | tr '\n' ';')" = "a 1;b 2;" ] && ok || bad "P01: $(rows l1)"
[ "$(rows l2 | awk '{ print $1, $2 }' | tr '\n' ';')" = "b 1;a 2;" ] && ok || bad "P02: $(rows l2)"
# condition b: P01's last level, P02's first; a: the other way round
for c in a b; do
    h1=$(rows l1 | awk -v c=$c '$1 == c { print $3 }')
    h2=$(rows l2 | awk -v c=$c '$1 == c { print $3 }')
    [ -n "$h1" ] && [ "$h1" = "$h2" ] && ok || bad "condition $c: two level_sha256, $h1 and $h2"
done
# each level file's name is its sha256sum
for f in l1/level-*.txt l2/level-*.txt; do
    [ "$(sha256sum <"$f" | cut -c1-64)" = "$(basename "$f" .txt | cut -c7-)" ] && ok ||
        bad "$f: its sha256sum is not its name"
done
[ "$(ls l1/level-*.txt | wc -l)" = 2 ] && ok || bad "l1: $(ls l1)"
# the recording (the last level's text with its closing) replays to the
# same rows and level files
run "replay P01" 0 "$H" replay r1.rec --log l1r
cmp -s l1/summary.csv l1r/summary.csv && ok || bad "replay: $(cat l1r/summary.csv)"
[ "$(cd l1 && ls level-*)" = "$(cd l1r && ls level-*)" ] && ok || bad "replay's levels: $(ls l1r)"

# a resume (P01 at b, position 2) begins on the ready screen: the walk
# before its confirm is no step, the clock starts at the confirm (4.0 s)
{ walk_input WNESE; printf '2 f=9 p=1 h=1.5,1.6,1.5,0,0,0,1\n'; walk_input WNESE 4; } >in2
cp -r l1 l1s
run "P01 resumed" 0 "$H" play --study "$S" --participant P01 --size 64x48 --log l1 --input in2 \
    --resume --record r2.rec
grep -q '^ready$' r2.rec && ok || bad "the resumed recording has no ready line"
last=$(tail -n 1 l1/summary.csv | cut -d, -f7,8,18-22)
case $last in "b,2,4.0000,5,5,1.2500,done") ok ;; *) bad "the resumed attempt: $last" ;; esac
# its replay begins on the ready screen too
run "replay resumed" 0 "$H" replay r2.rec --log l1s --append
cmp -s l1/summary.csv l1s/summary.csv && ok || bad "the resumed replay: $(diff l1/summary.csv l1s/summary.csv)"

# a questionnaire `before study` (a baseline) with no practice is asked on
# the participant's first level: its lines are between the first level's
# marks, outside the hash, so two participants in two orders get one
# level file a condition (the shared question `calm` before the marks)
printf 'study base\nquestion calm likert 1 5 "How calm are you?" "not" "very"\nquestionnaire mood calm\nquestionnaire mood before study\nquestionnaire mood after condition\nquestionnaire ssq before study\ncondition a\nlevel f.lvl\nset minimap hud\ncondition b\nlevel f.lvl\nset minimap hand\n' >s/base.study
printf '0 f=9 h=1.5,1.6,1.5,0,0,0,1\n0.25 f=9 h=1.5,1.6,1.5,0,0,0,1\n' >in3
run "base P01 (a, b)" 0 "$H" play --study s/base.study --participant P01 --size 64x48 --log b1 \
    --input in3 --record b1.rec
run "base P02 (b, a)" 0 "$H" play --study s/base.study --participant P02 --size 64x48 --log b2 \
    --input in3
[ "$(cd b1 && ls level-*)" = "$(cd b2 && ls level-*)" ] && ok || bad "two orders' levels: $(ls b1 b2)"
[ "$(ls b1/level-*.txt | wc -l)" = 2 ] && ok || bad "b1: $(ls b1)"
for f in b1/level-*.txt; do
    [ "$(sha256sum <"$f" | cut -c1-64)" = "$(basename "$f" .txt | cut -c7-)" ] && ok ||
        bad "$f: its sha256sum is not its name"
done
# the recording carries them, in the order asked; its replay the same files
grep -c 'before_study' b1.rec | grep -qx 2 && ok || bad "the recording's baseline: $(grep before b1.rec)"
run "replay base P01" 0 "$H" replay b1.rec --log b1r
[ "$(cd b1 && ls level-*)" = "$(cd b1r && ls level-*)" ] && ok || bad "replay's levels: $(ls b1r)"
finish cli_onset
