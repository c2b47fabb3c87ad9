#!/bin/sh
# cli_study.sh - study designs through the binary (`play --study`, README:
# Study designs): refusals with the file and line they blame; under Xvfb
# (when installed) participants 1..4 of a four-condition study get the rows
# of a balanced Latin square (each condition once in each position, each
# ordered pair adjacent once), the logs and the recording name the study,
# condition and position, the log folder keeps every level's text, and the
# recording replays to the same logs.
. "$(dirname "$0")/lib.sh"

mkdir "$T/s" "$T/s/lv"
printf 'mode flag\nseed 5\nflag Wrf\n' >"$T/s/lv/flag.lvl"
printf 'mode tutorial\nstages 1\n' >"$T/s/tut.lvl"
cat >"$T/s/four.study" <<'END'
# four conditions, Williams by default
study four
practice tut.lvl
set time-limit 600
condition hud
level lv/flag.lvl
set minimap hud
condition hand
level lv/flag.lvl
set minimap hand
condition off
level lv/flag.lvl
set minimap off
condition nocue
level lv/flag.lvl
set cues none
END

run "--help" 0 "$H" play --help
grep -q -- "--study FILE" "$T/out" && ok || bad "play --help does not describe --study"
run "xr --help" 0 "$H" xr --help
grep -q -- "--study FILE" "$T/out" && ok || bad "xr --help does not describe --study"
S="$T/s/four.study"
run "no participant" 2 "$H" play --study "$S" && one_line "no participant" "participant's number"
run "no number" 2 "$H" play --study "$S" --participant Pam && one_line "no number" "P07"
run "zero" 2 "$H" play --study "$S" --participant P0 && one_line "zero" "P07"
run "study and level" 2 "$H" play --study "$S" "$T/s/tut.lvl" --participant 1 &&
    one_line "study and level" "one of a LEVEL file, --mode or --study"
run "study and mode" 2 "$H" play --study "$S" --mode flag --participant 1 &&
    one_line "study and mode" "one of a LEVEL file, --mode or --study"
run "xr study and level" 2 "$H" xr --study "$S" "$T/s/tut.lvl" --participant 1 &&
    one_line "xr study and level" "not both"
run "missing study" 2 "$H" play --study "$T/nope.study" --participant 1 &&
    one_line "missing study" "cannot open study '.*nope.study'"
run "study a folder" 2 "$H" play --study "$T/s" --participant 1 && one_line "folder" "not a regular"
# a bad study line: the study file and its line
sed 's/set minimap hand/set minimap wrist/' "$S" >"$T/s/bad1.study"
run "bad set line" 2 "$H" play --study "$T/s/bad1.study" --participant 1 &&
    one_line "bad set line" "bad1.study: line 10: set: minimap 'wrist' is not hud, hand or off"
sed 's/^condition off/condition hud/' "$S" >"$T/s/bad2.study"
run "condition twice" 2 "$H" play --study "$T/s/bad2.study" --participant 1 &&
    one_line "condition twice" "bad2.study: line 11: condition 'hud' is given twice (line 5)"
# a level file's line, with the condition it serves; a missing level file
printf 'mode flag\nseed 5\nflag Wrr\n' >"$T/s/lv/bad.lvl"
sed 's|^level lv/flag.lvl|level lv/bad.lvl|' "$S" >"$T/s/bad3.study"
run "bad level line" 2 "$H" play --study "$T/s/bad3.study" --participant 1 &&
    one_line "bad level line" "lv/bad.lvl: line 3: .*(condition hud of .*bad3.study)"
sed 's|^level lv/flag.lvl|level lv/gone.lvl|' "$S" >"$T/s/bad4.study"
run "missing level" 2 "$H" play --study "$T/s/bad4.study" --participant 1 &&
    one_line "missing level" "cannot open level '.*/s/lv/gone.lvl'"
# a set line in conflict with the level file: the study's line
printf 'study c\ncondition a\nlevel lv/flag.lvl\nset place rock Wrf\n' >"$T/s/bad5.study"
run "set conflict" 2 "$H" play --study "$T/s/bad5.study" --participant 1 &&
    one_line "set conflict" "bad5.study: line 4: set: the placement on Wrf conflicts with the flag"

if ! command -v Xvfb >/dev/null 2>&1; then
    echo "note: no Xvfb here: the study's sessions are not played"
    finish cli_study
    exit $?
fi
start_xvfb 7

# participants 1..4: the orders the recordings and the stderr line name
: >"$T/orders"
for p in 1 2 3 4; do
    run "participant $p" 0 "$H" play --study "$S" --participant "P0$p" --frames 3 --size 64x48 \
        --record "$T/p$p.rec" --log "$T/l$p"
    grep -q "study four, participant P0$p (number $p, order $p of 4): practice, " "$T/err" && ok ||
        bad "participant $p: $(cat "$T/err")"
    # condition lines in play order: practice 0, then positions 1..4
    grep '^condition ' "$T/p$p.rec" | awk '{ printf "%s%s", (NR > 1 ? " " : ""), $2 ":" $3 }
        END { print "" }' >>"$T/orders"
done
awk '{ if ($1 != "practice:0") bad = 1
       for (k = 2; k <= 5; k++) { split($k, a, ":"); if (a[2] != k - 1) bad = 1
           pos[a[1] "@" a[2]]++; if (k > 2) pair[prev ">" a[1]]++; prev = a[1] } }
     END { n = 0; for (x in pos) { n++; if (pos[x] != 1) bad = 1 }
           m = 0; for (x in pair) { m++; if (pair[x] != 1) bad = 1 }
           exit !(n == 16 && m == 12 && !bad) }' "$T/orders" && ok ||
    bad "participants 1..4 do not get a balanced Latin square: $(cat "$T/orders")"
# version 5: its practice is a tutorial (issue 35's lessons; docs/logs.md)
grep -q '^holonomy-rec 5$' "$T/p1.rec" && grep -q '^study four$' "$T/p1.rec" && ok ||
    bad "the recording names no study: $(head -8 "$T/p1.rec")"
# participant 5 plays participant 1's order
run "participant 5" 0 "$H" play --study "$S" --participant 5 --frames 3 --size 64x48 \
    --record "$T/p5.rec"
[ "$(grep '^condition ' "$T/p5.rec")" = "$(grep '^condition ' "$T/p1.rec")" ] && ok ||
    bad "participant 5 differs from participant 1"

# the logs: the summary's study, condition and position; the levels' texts
sed -n 2p "$T/l2/summary.csv" | grep -q '^[^,]*,P02,[^,]*,[^,]*,1,four,practice,0,tut,' && ok ||
    bad "summary: $(cat "$T/l2/summary.csv")"
n=0
for f in "$T"/l2/level-*.txt; do
    h=$(basename "$f" .txt | sed 's/^level-//')
    [ "$(sha256sum <"$f" | cut -d' ' -f1)" = "$h" ] && n=$((n + 1))
done
[ "$n" = 5 ] && ok || bad "level files: $n of 5 named by their SHA-256: $(ls "$T/l2")"
grep -q '^# study four, condition hand:$' "$T"/l2/level-*.txt && grep -q '^minimap hand$' "$T"/l2/level-*.txt &&
    ok || bad "no level file holds condition hand's set lines"
# a study session's recording replays to the same logs
walk_input - >"$T/in"
printf '0.5 f=9 p=1 h=1.5,1.6,1.5,0,0,0,1\n' >>"$T/in"
printf '1 f=9 h=1.5,1.6,1.5,0,0,0,1\n' >>"$T/in"
run "walk" 0 "$H" play --study "$S" --participant 3 --input "$T/in" --size 64x48 --log "$T/w" \
    --record "$T/w.rec"
mkdir "$T/w2"
run "replay" 0 "$H" replay "$T/w.rec" --log "$T/w2"
logs_diff "$T/w" "$T/w2" >/dev/null && ok || bad "a study session's replay writes other logs"
finish cli_study
