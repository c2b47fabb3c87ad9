#!/bin/sh
# cli_play.sh - `holonomy play`: usage errors; under Xvfb (when installed)
# a scripted playthrough from a recorded input file scores the optimum, a
# detour adds its steps, and the recording it writes replays to the same
# logs byte for byte.
. "$(dirname "$0")/lib.sh"

run "--help" 0 "$H" play --help
grep -q -- "--record" "$T/out" && ok || bad "--help does not describe --record"
printf 'mode flag\nseed 5\nflag Wrf\n' >"$T/f.lvl"
printf 'mode flag\nseed 5\nflag Wrr\n' >"$T/bad.lvl"
run "unknown option" 2 "$H" play --bogus && one_line "unknown option" "bogus"
run "bad mode" 2 "$H" play --mode chess && one_line "bad mode" "chess"
run "level and mode" 2 "$H" play "$T/f.lvl" --mode flag && one_line "level and mode" "one of a LEVEL file, --mode or --study"
run "missing level" 2 "$H" play "$T/nope.lvl" && one_line "missing level" "nope.lvl"
run "bad level" 2 "$H" play "$T/bad.lvl" && one_line "bad level" "line 3"
run "bad seed" 2 "$H" play --seed -1 && one_line "bad seed" "seed"
run "log not a folder" 2 "$H" play --log "$T/f.lvl" && one_line "log" "not a folder"
# a level file whose name a recording cannot carry (a newline) is refused
# when it is read, before any play: play never records what replay refuses
cp "$T/f.lvl" "$T/a
b.lvl"
run "newline in the level's name" 2 "$H" play "$T/a
b.lvl" && one_line "newline in the name" "which a recording cannot carry"
PAD=$(dirname "$0")/hid/asus_play.pad
printf '0 plug 0001:0002 05 01\n1 report 01\n0.5 report 02\n' >"$T/back.pad"
run "pad script time back" 2 "$H" play --gamepad-replay "$T/back.pad" && one_line "time back" "line 3"
printf '# no pad yet\n\n1 unplug\n' >"$T/unplugged.pad"
run "pad script unplug first" 2 "$H" play --gamepad-replay "$T/unplugged.pad" &&
    one_line "unplug first" "line 3"
run "pad script missing" 2 "$H" play --gamepad-replay "$T/nope.pad" && one_line "missing" "nope.pad"
run "pad script and no pad" 2 "$H" play --gamepad-replay "$PAD" --no-gamepad &&
    one_line "both" "not both"
run "pad script no value" 2 "$H" play --gamepad-replay && one_line "no value" "needs a value"
run "bad snap turn" 2 "$H" play --snap-turn 7 && one_line "bad snap" "divisor of 360"
run "snap turn zero" 2 "$H" play --snap-turn 0 && one_line "snap zero" "snap-turn"
run "bad tiling" 2 "$H" play --tiling 4,3 && one_line "bad tiling" "--tiling needs 4,Q"
run "bad room" 2 "$H" play --room 3x2 && one_line "bad room" "--room needs CxR"
run "bad cell" 2 "$H" play --cell 0.4 && one_line "bad cell" "--cell needs metres"

if ! start_xvfb 0; then
    echo "note: no Xvfb here: the window is not tested"
    finish cli_play
    exit $?
fi

printf -- '- Wrf\n' | "$H" nav >"$T/nav" || bad "nav"
K=$(cut -d' ' -f1 "$T/nav") WALK=$(cut -d' ' -f2 "$T/nav")
walk_input "$WALK" >"$T/opt.in"
walk_input "NS$WALK" >"$T/detour.in"
mkdir "$T/l1" "$T/l2"
run "play optimal" 0 "$H" play "$T/f.lvl" --input "$T/opt.in" --size 64x48 --log "$T/l1" \
    --record "$T/r.rec"
grep -q "^level f done steps $K optimum $K " "$T/out" && ok || bad "optimal: $(cat "$T/out")"
run "play detour" 0 "$H" play "$T/f.lvl" --input "$T/detour.in" --size 64x48
grep -q "^level f done steps $((K + 2)) optimum $K " "$T/out" && ok || bad "detour: $(cat "$T/out")"
# the recording replays to the same logs, byte for byte
run "replay" 0 "$H" replay "$T/r.rec" --log "$T/l2"
logs_diff "$T/l1" "$T/l2" >/dev/null && ok || bad "replayed logs differ: $(logs_diff "$T/l1" "$T/l2" | head -3)"
# a recording is also a play's --input
run "recording as input" 0 "$H" play "$T/f.lvl" --input "$T/r.rec" --size 64x48
grep -q "^level f done steps $K " "$T/out" && ok || bad "recording as input: $(cat "$T/out")"
# pancake: walking forward 1 s crosses one edge north
awk 'BEGIN { for (k = 0; k < 60; k++) printf "%.17g f=8 m=0,1\n", k / 60 }' >"$T/fwd.in"
run "pancake" 0 "$H" play --mode explore --input "$T/fwd.in" --size 64x48
grep -q "^level explore-1 playing steps 1 optimum -1 tile N cell 1,0\$" "$T/out" && ok ||
    bad "pancake: $(cat "$T/out")"
# another geometry: the options go into the level's text (the recording's L
# lines, the summary's columns), and the recording replays with no options
mkdir "$T/g1" "$T/g2"
# (1 s forward from z = 1.875 m in 0.75 m cells crosses two cell edges)
run "play {4,6} 4x4 0.75 m" 0 "$H" play "$T/f.lvl" --tiling 4,6 --room 4x4 --cell 0.75 \
    --input "$T/fwd.in" --size 64x48 --log "$T/g1" --record "$T/g.rec"
grep -q "^level f playing steps 2 optimum 3 tile Nf cell 2,0\$" "$T/out" && ok ||
    bad "{4,6} 4x4: $(cat "$T/out")"
grep -q '^L tiling 4 6$' "$T/g.rec" && grep -q '^L room 4 4$' "$T/g.rec" &&
    grep -q '^L cell 0.75$' "$T/g.rec" && ok || bad "the recording's level has no geometry lines"
grep -q ',flag,5,15,"4,6",4x4,0.75,' "$T/g1/summary.csv" && ok ||
    bad "geometry columns: $(cat "$T/g1/summary.csv")"
run "replay {4,6} 4x4 0.75 m" 0 "$H" replay "$T/g.rec" --log "$T/g2"
logs_diff "$T/g1" "$T/g2" >/dev/null && ok || bad "replayed {4,6} logs differ"
# the campaign with --tiling: the tutorial stays {4,5} 3x3 (it takes --cell
# only), the other five levels get the line
run "campaign in {4,6}" 0 "$H" play --tiling 4,6 --cell 0.8 --frames 3 --size 64x48 --record "$T/c6.rec"
[ "$(grep -c '^L tiling 4 6$' "$T/c6.rec")" = 5 ] && [ "$(grep -c '^L cell 0.8$' "$T/c6.rec")" = 6 ] &&
    ! sed -n '/^level tutorial$/,/^level /p' "$T/c6.rec" | grep -q '^L tiling' && ok ||
    bad "campaign geometry lines: $(grep '^L \(tiling\|cell\)' "$T/c6.rec" | tr '\n' ' ')"
# the campaign and --mode levels are made for the geometry asked for: the
# flat {4,4} plays (flags within its nine tiles), {4,8} 5x5 plays (its
# keys levels within the folded reach), each level holding its lines
run "campaign in {4,4}" 0 "$H" play --tiling 4,4 --frames 3 --size 64x48 --record "$T/c4.rec"
[ "$(grep -c '^L tiling 4 4$' "$T/c4.rec")" = 5 ] && ok || bad "{4,4} campaign: no tiling lines"
run "campaign in {4,8} 5x5" 0 "$H" play --tiling 4,8 --room 5x5 --frames 3 --size 64x48 \
    --record "$T/c8.rec"
[ "$(grep -c '^L room 5 5$' "$T/c8.rec")" = 5 ] && ok || bad "{4,8} 5x5 campaign: no room lines"
run "--mode keys in {4,4} 4x3" 0 "$H" play --mode keys --tiling 4,4 --room 4x3 --frames 3 \
    --size 64x48
run "play a conflict" 2 "$H" play "$T/f.lvl" --tiling 4,4 --frames 2 --size 64x48 &&
    one_line "flat play" "line 3: no walk inside the room reaches the flag's tile Wrf"
# keyboard mode runs and stops after --frames; no LEVEL: the default
# campaign (the tutorial, three flags, two keys levels), carried by the
# recording
run "campaign" 0 "$H" play --frames 3 --size 64x48 --record "$T/c.rec"
grep -q "^level tutorial playing steps 0 optimum -1 tile O cell 1,1\$" "$T/out" && ok ||
    bad "campaign: $(cat "$T/out")"
[ "$(grep -c '^level ' "$T/c.rec")" = 6 ] && ok || bad "the campaign has not 6 levels"
[ "$(grep -c '^L mode flag' "$T/c.rec")" = 3 ] && ok || bad "the campaign has not 3 flag levels"
[ "$(grep -c '^L mode keys' "$T/c.rec")" = 2 ] && ok || bad "the campaign has not 2 keys levels"
run "mode keys" 0 "$H" play --mode keys --seed 0x10 --frames 2 --size 64x48
grep -q "^level keys-16 playing steps 0 optimum [1-9]" "$T/out" && ok || bad "--mode keys: $(cat "$T/out")"

# a scripted game controller: the stick held left 1 s walks a cell west as
# the keyboard's strafe would; unplugged at 2 s the game pauses (the input
# carries HOL_INPUT_DEVICE_LOST: f=18 with focus) until the pad is found
# again at 3 s; the recording replays to the same end
awk 'BEGIN { for (k = 0; k < 240; k++) printf "%.17g f=8\n", k / 60 }' >"$T/idle.in"
run "gamepad walks" 0 "$H" play --mode explore --input "$T/idle.in" --gamepad-replay "$PAD" \
    --size 64x48 --record "$T/pad.rec"
grep -q "^level explore-1 playing steps 1 optimum -1 tile W cell 0,1\$" "$T/out" && ok ||
    bad "gamepad walk: $(cat "$T/out")"
awk 'BEGIN { for (k = 0; k < 240; k++) printf "%.17g f=8%s\n", k / 60, (k < 60 ? " m=-1,0" : "") }' \
    >"$T/strafe.in"
run "keyboard strafe" 0 "$H" play --mode explore --input "$T/strafe.in" --size 64x48 --no-gamepad
grep -q "^level explore-1 playing steps 1 optimum -1 tile W cell 0,1\$" "$T/out" && ok ||
    bad "keyboard strafe: $(cat "$T/out")"
# held left (merged: the pad's axes in the recorded lines) for the first
# second, then centred; paused exactly from 2 s to the re-enumeration at 3 s
[ "$(grep -c ' m=-0.99' "$T/pad.rec")" = 60 ] && ok || bad "the stick is not in 60 recorded lines"
[ "$(grep -c ' f=18' "$T/pad.rec")" = 60 ] && ok || bad "not 60 paused lines"
grep ' f=18' "$T/pad.rec" | sed -n '1p;$p' | cut -d' ' -f1 | tr '\n' ' ' | grep -q '^2 2.98' && ok ||
    bad "the pause is not 2 .. 3 s: $(grep ' f=18' "$T/pad.rec" | sed -n '1p;$p')"
run "gamepad replay" 0 "$H" replay "$T/pad.rec"
grep -q "^level explore-1 playing steps 1 optimum -1 tile W cell 0,1\$" "$T/out" && ok ||
    bad "the pad's recording replays: $(cat "$T/out")"
# unplugged for good: a key resumes (and walks north from 3 s)
head -n 9 "$PAD" >"$T/gone.pad"
awk 'BEGIN { for (k = 0; k < 300; k++) printf "%.17g f=8%s\n", k / 60, (k >= 180 ? " m=0,1" : "") }' \
    >"$T/key.in"
run "key resumes" 0 "$H" play --mode explore --input "$T/key.in" --gamepad-replay "$T/gone.pad" \
    --size 64x48 --record "$T/gone.rec"
[ "$(grep -c ' f=18' "$T/gone.rec")" = 60 ] && ok || bad "key: not 60 paused lines"
grep -q "^level explore-1 playing steps 2 optimum -1 tile Wr cell 0,0\$" "$T/out" && ok ||
    bad "key resumes: $(cat "$T/out")"

# one live play (xdotool, when installed), keys tapped as a player taps
# them (each had a play of its own: three windows' start-up and first
# second of frames, about 5 s of CPU more; the checks are the same):
# - F2: the frame time appears at the top right of the window (that box
#   changes, the middle of the view does not), and F2 again hides it (the
#   box is as before); first, on the view as the play opens it;
# - R and M pressed and let go at once, most likely between two frames,
#   still act: the first attempt ends by restart, the recording carries the
#   presses (p=20, p=10) and replays to the same logs; Q quits;
# - snap turn: a tapped Left turns the look to 90 degrees exactly (the
#   recording carries the snap: f=48 y=90), a tapped Right back to 0;
# - --stats prints the frame rate and CPU ms a frame at the end.
# wait_frames ERRFILE: until play --stats has run frames for a second (its
# first stats line; at most 60 s), then focus its window
wait_frames() {
    for i in $(seq 1 120); do
        grep -q '^stats: ' "$1" 2>/dev/null && break
        sleep 0.5
    done
    WID=$(timeout 20 xdotool search --sync --name '^holonomy$' | head -n 1)
    [ -n "$WID" ] && xdotool windowfocus --sync "$WID" 2>/dev/null
    sleep 0.3
}
if command -v xdotool >/dev/null 2>&1; then
    mkdir "$T/tap" "$T/tap2"
    "$H" play --mode explore --size 320x240 --snap-turn 90 --log "$T/tap" --record "$T/tap.rec" \
        --stats >"$T/tap.out" 2>"$T/tap.err" &
    PPID_PLAY=$!
    wait_frames "$T/tap.err"
    if [ -n "$WID" ]; then
        # each look polls (at most 1.5 s, the wait it had) for the change
        c0=$("$X11_SHOT" holonomy 55 0 100 12) m0=$("$X11_SHOT" holonomy 20 20 80 80)
        xdotool key F2
        for i in $(seq 1 15); do
            sleep 0.1
            c1=$("$X11_SHOT" holonomy 55 0 100 12)
            [ "$c1" != "$c0" ] && break
        done
        m1=$("$X11_SHOT" holonomy 20 20 80 80)
        xdotool key F2
        for i in $(seq 1 15); do
            sleep 0.1
            c2=$("$X11_SHOT" holonomy 55 0 100 12)
            [ "$c2" = "$c0" ] && break
        done
        [ -n "$c0" ] && [ "$c1" != "$c0" ] && ok || bad "F2 drew nothing at the top right ($c0, $c1)"
        [ -n "$m0" ] && [ "$m1" = "$m0" ] && ok || bad "F2 changed the middle of the view"
        [ "$c2" = "$c0" ] && ok || bad "F2 again did not hide the frame time ($c0, $c2)"
        xdotool key r
        sleep 0.5
        xdotool key m
        sleep 0.5
        xdotool key Left
        sleep 0.5
        xdotool key Right
        sleep 0.5
        xdotool key q
    fi
    wait_for 10 -p $PPID_PLAY
    kill $PPID_PLAY 2>/dev/null
    wait $PPID_PLAY 2>/dev/null
    grep -q ',1,,,,explore-1,[0-9a-f]*,explore,1,15,"4,5",3x3,1,[0-9.]*,0,-1,[0-9.]*,restart,,,$' "$T/tap/summary.csv" && ok ||
        bad "a tapped R did not restart: $(cat "$T/tap/summary.csv" "$T/tap.err" 2>&1)"
    grep -q ' p=20 .*d=keyboard$' "$T/tap.rec" && ok || bad "no pressed R (p=20) in the recording"
    grep -q ' p=10 .*d=keyboard$' "$T/tap.rec" && ok || bad "no pressed M (p=10) in the recording"
    grep -q '^level explore-1 quit ' "$T/tap.out" && ok || bad "Q did not quit: $(cat "$T/tap.out")"
    run "taps replay" 0 "$H" replay "$T/tap.rec" --log "$T/tap2"
    logs_diff "$T/tap" "$T/tap2" >/dev/null && ok || bad "the taps' logs differ in the replay"
    grep -q ' f=48 y=90 d=keyboard$' "$T/tap.rec" && ok || bad "a tapped Left did not snap to 90"
    [ "$(grep -c ' f=48 d=keyboard$' "$T/tap.rec")" = 1 ] && ok || bad "a tapped Right did not snap to 0"
    grep -q '^stats: [0-9]* frames in [0-9.]* s: [0-9.]* fps, CPU [0-9.]* ms a frame' "$T/tap.err" &&
        ok || bad "--stats printed no summary: $(cat "$T/tap.err")"
else
    echo "note: no xdotool here: taps are tested through recorded lines only"
fi
# a tap in a recorded line (pressed, not held) restarts as a held press does
awk 'BEGIN { for (k = 0; k < 20; k++) printf "%.17g f=8%s\n", k / 10, (k == 5 ? " p=20" : "") }' \
    >"$T/ptap.in"
mkdir "$T/ptap"
run "pressed line" 0 "$H" play --mode explore --input "$T/ptap.in" --size 64x48 --log "$T/ptap"
grep -q ',1,,,,explore-1,[0-9a-f]*,explore,1,15,"4,5",3x3,1,[0-9.]*,0,-1,0.4000,restart,,,$' "$T/ptap/summary.csv" && ok ||
    bad "a pressed-only line did not restart: $(cat "$T/ptap/summary.csv")"
kill $XPID 2>/dev/null
wait $XPID 2>/dev/null
finish cli_play
