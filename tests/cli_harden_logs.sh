#!/bin/sh
# cli_harden_logs.sh - hardening of the logs and recordings (issue 24,
# findings 1, 2, 4, 8, 10, 13 and 15). Each check failed before its change:
# - a recording whose time jumps (0, then 1e9 s) replayed with --log wrote
#   head rows at 100 MB/s and ignored SIGTERM; now a gap of more than 2 s is
#   one `gap` row, and a replay of a hostile recording ends on SIGTERM
#   within 1 s (the same through `play --input`, under Xvfb);
# - a refused --log folder was named after closedir() freed its entry (a
#   use after free: seen by the sanitizer build, `make san-cli`);
# - a kill before an attempt's header reached the disk left 0-byte live
#   files that --append renamed into 0-byte steps files `report` refused;
#   a summary.csv killed before its header made --append refuse the folder;
#   now recovery gives each its header or drops the attempt with one line,
#   and `report` reads the folder after kills at random moments;
# - a recording cut in its last record replayed the cut record; now it is
#   dropped with one warning line;
# - --append with summary.csv a folder or a FIFO: exit 1 "Invalid
#   argument"; now exit 2, one line;
# - a version 2 recording's `study` line: "holds no level"; now named;
# - a refused study or a failed window left an empty --log folder;
# - (issue 26) a play ended by SIGINT, SIGTERM, SIGHUP or the close button
#   replayed with end `open`; now its recording ends "end aborted" and the
#   replay's summary equals the play's byte for byte (quit and timeout too).
. "$(dirname "$0")/lib.sh"
H=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
[ -n "${X11_CLOSE:-}" ] && X11_CLOSE=$(cd "$(dirname "$X11_CLOSE")" && pwd)/$(basename "$X11_CLOSE")
cd "$T" || exit 1

rec_header() {
    printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nparticipant P01\n'
    printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\n'
}
level_lines() {
    printf 'level f\nL mode flag\nL seed 5\nL flag Nf\nend\n'
}
# gone_within PID TENTHS: 0 when PID has ended within TENTHS x 0.1 s
gone_within() {
    for i in $(seq 1 "$2"); do kill -0 "$1" 2>/dev/null || return 0; sleep 0.1; done
    ! kill -0 "$1" 2>/dev/null
}

# ---- finding 1: a time gap is one row ---------------------------------------------
{ rec_header; level_lines; printf '0 f=9\n1e9 f=9\n'; } >jump.rec
( ulimit -f 65536; exec timeout -s KILL 20 "$H" replay jump.rec --log jump ) >out 2>err
st=$?
[ "$st" = 0 ] && ok || bad "jump replay: status $st ($(head -c 200 err))"
want='session,attempt,level,t,frame_t,x,y,z,yaw,pitch,col,row,tile
20260131T140509Z-5f3a9c01,1,f,0.0,0.0000,0.1500,0.0000,0.1500,0.00,-30.00,0,0,O
20260131T140509Z-5f3a9c01,1,f,0.1,1000000000.0000,,,,,,,,gap'
[ "$(cat jump/head-001.csv 2>/dev/null)" = "$want" ] && ok ||
    bad "jump head rows: $(head -c 300 jump/head-001.csv 2>/dev/null)"
grep -q ',1000000000.0000,open,,,$' jump/summary.csv && ok || bad "jump summary: $(cat jump/summary.csv)"

# a gap of 2 s is interpolated (20 rows); of 2.5 s one gap row, then rows go on
{ rec_header; level_lines
  printf '0 f=9 h=1.5,1.6,1.5,0,0,0,1\n2 f=9 h=1.5,1.6,1.5,0,0,0,1\n'
  printf '4.5 f=9 h=1.5,1.6,1.5,0,0,0,1\n4.7 f=9 h=1.5,1.6,1.5,0,0,0,1\n'; } >gaps.rec
run "gaps replay" 0 "$H" replay gaps.rec --log gaps
got=$(cut -d, -f4,5,13 gaps/head-001.csv | tr '\n' ' ')
want="t,frame_t,tile 0.0,0.0000,O"
for k in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19; do
    want="$want $((k / 10)).$((k % 10)),2.0000,O"; done
want="$want 2.0,2.0000,O 2.1,4.5000,gap 4.6,4.7000,O 4.7,4.7000,O "
[ "$got" = "$want" ] && ok || bad "gap rows: $got"

# SIGTERM within 1 s: a long recording of frames 2000 s apart (a million
# of them: several seconds of replay even on a quiet machine, so the signal
# lands mid-replay; below 2^31 s, where the level's clock saturates)
{ rec_header; level_lines
  awk 'BEGIN { for (k = 0; k < 1000000; k++) printf "%d f=9\n", k * 2000 }'; } >hostile.rec
( ulimit -f 262144; exec "$H" replay hostile.rec --log term ) >/dev/null 2>&1 &
pid=$!
wait_for 60 -e term/head-001.csv.live
sleep 0.2
kill -TERM $pid 2>/dev/null
if gone_within $pid 10; then
    wait $pid; st=$?
    [ "$st" = 143 ] && ok || bad "SIGTERM: status $st, want 143"
    tail -1 term/summary.csv | grep -q ',aborted,,,$' && ok || bad "SIGTERM: $(tail -1 term/summary.csv)"
else
    bad "a replay of a hostile recording still runs 1 s after SIGTERM"
    kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
fi
rm -rf term hostile.rec

# ---- finding 2: the refused folder's file is named (ASan: no use after free) ----
mkdir held && : >held/summary.csv
run "a folder with logs" 2 "$H" replay jump.rec --log held
one_line "a folder with logs" "holds earlier logs ('summary.csv')"

# ---- finding 8: a record cut by the file's end is dropped ---------------------------
{ rec_header; level_lines
  printf '0 f=9 h=1.5,1.6,1.5,0,0,0,1\n1 f=9 h=0.5,1.6,1.5,0,0,0,1\n'
  printf '2 f=9 h=0.5,1.6,0.5,0,0,0,1\n2.5 f=9 h=0.5,1.6,0.5,0,0,0,1\n'; } >whole.rec
n=$(wc -c <whole.rec)
head -c $((n - 23)) whole.rec >cut.rec # "2.5 f=9": a record cut before its pose
head -n -1 whole.rec >two.rec
run "a cut record" 0 "$H" replay cut.rec --log cutlogs
one_line "a cut record" "line 14: 'cut.rec' ends inside this record (no newline): it is dropped"
cp out cut.out
run "the whole records" 0 "$H" replay two.rec --log twologs
cmp -s out cut.out && cmp -s cutlogs/head-001.csv twologs/head-001.csv && ok ||
    bad "the cut record was replayed: $(cat cut.out) vs $(cat out)"
printf '0 f=9 h=1.5,1.6,1.5,0,0,0,1\n1 f=9 h=0.5,1.6,1.5,0,0,0,1\n2 f=9' >cut.in

# ---- finding 13: a v2 recording's study line ------------------------------------------
{ rec_header; printf 'study cues\n'; level_lines; printf '0 f=9\n'; } >v2study.rec
run "v2 study line" 2 "$H" replay v2study.rec
one_line "v2 study line" "line 6: a 'study' line needs a version 3 recording"

# ---- a version 4 recording's condition without its study line (the fuzz
# smoke's find: what the writer made of it, "study -", read back otherwise)
{ rec_header | sed 's/holonomy-rec 2/holonomy-rec 4/'
  printf 'level f\ncondition hand 1\nL mode flag\nL seed 5\nL flag Nf\nend\n0 f=9\n'; } >v4cond.rec
run "v4 condition without study" 2 "$H" replay v4cond.rec
one_line "v4 condition without study" "line 7: a 'condition' line needs the recording's 'study' line"

# ---- finding 10: --append with summary.csv a folder or a FIFO -------------------------
mkdir -p sumdir/summary.csv
run "summary.csv a folder" 2 "$H" replay whole.rec --log sumdir --append
one_line "summary.csv a folder" "'summary.csv' is a folder, not a log file"
mkdir sumfifo && mkfifo sumfifo/summary.csv
run "summary.csv a FIFO" 2 timeout 10 "$H" replay whole.rec --log sumfifo --append
one_line "summary.csv a FIFO" "'summary.csv' is a FIFO, not a log file"

# ---- finding 15: no empty --log folder after a refusal ---------------------------------
printf 'study s\nbogus line\n' >bad.study
run "refused study" 2 env DISPLAY= "$H" play --study bad.study --participant P1 --log nolog1
[ ! -e nolog1 ] && ok || bad "a refused study left $(ls -ld nolog1)"
run "no window" 1 env DISPLAY= "$H" play --mode flag --log nolog2
[ ! -e nolog2 ] && ok || bad "a failed window left $(ls -ld nolog2)"
run "bad recording" 2 "$H" replay v2study.rec --log nolog3
[ ! -e nolog3 ] && ok || bad "a refused recording left $(ls -ld nolog3)"
mkdir keep
run "refused in a folder of its own" 2 "$H" replay v2study.rec --log keep
[ -d keep ] && ok || bad "a folder that was there was removed"

# ---- finding 4: recovery leaves a folder report and replay accept -----------------------
# by hand: the files a kill before the first flush leaves
run "logs to break" 0 "$H" replay whole.rec --log k0
row=$(sed -n 2p k0/summary.csv | sed 's/,open,,,$/,killed,,,/')
mkdir k1
sed -n 1p k0/summary.csv >k1/summary.csv
for a in 001 002; do printf '%s\n' "$row" | sed "s/,P01,\([^,]*\),\([^,]*\),1,/,P01,\1,\2,${a#00},/" \
    >k1/attempt-$a.live; done
: >k1/steps-001.csv.live; : >k1/head-001.csv.live          # 0 bytes: no header
printf 'session,attempt,le' >k1/steps-002.csv.live          # a cut header
: >k1/attempt-003.live; : >k1/steps-003.csv.live            # killed before it all
cp k0/level-*.txt k1/
run "recovery of headerless files" 0 "$H" replay whole.rec --log k1 --append
grep -q "2 unfinished attempt(s)" err && grep -q "1 attempt(s) of a killed session dropped" err &&
    ok || bad "recovery lines: $(cat err)"
[ "$(head -1 k1/steps-001.csv)" = "$(head -1 k0/steps-001.csv)" ] &&
    [ "$(head -1 k1/head-002.csv)" = "$(head -1 k0/head-001.csv)" ] && ok ||
    bad "headers not made: $(ls -l k1)"
ls k1 | grep -q -e '-003' -e 'live$' && bad "attempt 3 left: $(ls k1)" || ok
run "report after recovery" 0 "$H" report k1 --out r1
[ "$(grep -c '' r1/attempts.csv)" = 4 ] && ok || bad "report rows: $(cat r1/attempts.csv)"
# a summary.csv killed before its header, and one cut in a row
mkdir k2 && printf 'session,participant,sess' >k2/summary.csv
run "a cut summary header" 0 "$H" replay whole.rec --log k2 --append
[ "$(head -1 k2/summary.csv)" = "$(head -1 k0/summary.csv)" ] && ok || bad "k2: $(cat k2/summary.csv)"
printf '20260131T140509Z-5f3a9c01,P01,2026-01' >>k2/summary.csv
run "a cut summary row" 0 "$H" replay whole.rec --log k2 --append
run "report of k2" 0 "$H" report k2 --out r2
[ "$(grep -c '' k2/summary.csv)" = 3 ] && ok || bad "k2 rows: $(cat k2/summary.csv)"

# kills at random moments, from the very start (before the first flush) on
{ rec_header; printf 'level lv\nL mode flag\nL seed 5\nL flag Wrf\nend\n'
  awk 'BEGIN { for (k = 0; k < 3600; k++) { t = k / 60; x = 1.5 + 0.9 * sin(t);
       printf "%.17g f=9%s h=%.4f,1.6,1.5,0,0,0,1\n", t, (k % 30 == 29 ? " p=20" : ""), x } }'
} >long.rec
mkdir kr
# until_new DIR N PID: until DIR holds other than N entries or PID has ended
# (at most 5 s; tests/wait_for.c polls every 5 ms in one process: a `sleep`
# a poll cost more CPU than the replays it waits for)
until_new() { wait_for 5 -c "$1" "$2" -p "$3"; }
# each kill falls a moment after the replay's first new file (its level, its
# first attempt's files: before their first flush), or later
for d in 0 0 0.002 0.01 0.05 0.2; do
    before=$(ls kr | wc -l)
    "$H" replay long.rec --log kr --append >/dev/null 2>&1 &
    pid=$!
    until_new kr "$before" $pid
    sleep $d
    kill -9 $pid 2>/dev/null
    wait $pid 2>/dev/null
done
run "recovery after random kills" 0 "$H" replay whole.rec --log kr --append
ls kr | grep -q 'live$' && bad "live files left: $(ls kr | grep live)" || ok
run "report after random kills" 0 "$H" report kr --out rr
run "replay after random kills" 0 "$H" replay whole.rec --log kr --append

# ---- finding 1 and 8 through play --input (a window under Xvfb) --------------------------
if start_xvfb 317; then
    printf '0 f=9\n1e9 f=9\n' >jump.in
    ( ulimit -f 65536; exec timeout -s KILL 20 "$H" play --size 64x48 --mode flag --input jump.in \
        --log pjump ) >out 2>err
    st=$?
    [ "$st" = 0 ] && ok || bad "play --input jump: status $st ($(head -c 200 err))"
    [ "$(grep -c ',gap$' pjump/head-001.csv 2>/dev/null)" = 1 ] && ok ||
        bad "play --input jump: $(head -c 300 pjump/head-001.csv 2>/dev/null)"
    awk 'BEGIN { for (k = 0; k < 400000; k++) printf "%d f=9\n", k * 1000000 }' >hostile.in
    ( ulimit -f 262144; exec "$H" play --size 64x48 --mode flag --input hostile.in --log pterm ) \
        >/dev/null 2>&1 &
    pid=$!
    wait_for 60 -e pterm/head-001.csv.live
    sleep 0.3
    kill -TERM $pid 2>/dev/null
    if gone_within $pid 10; then
        wait $pid; st=$?
        [ "$st" = 143 ] && ok || bad "play SIGTERM: status $st, want 143"
    else
        bad "play --input of a hostile input still runs 1 s after SIGTERM"
        kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
    fi
    rm -rf pterm hostile.in
    run "play --input cut" 0 "$H" play --size 64x48 --mode flag --input cut.in
    one_line "play --input cut" "line 3: 'cut.in' ends inside this record"

    # ---- issue 26 item 2: replay reproduces every end, the summary byte for byte ----
    # same_end NAME END: the play's logs in $T/NAME/logs and recording
    # $T/NAME/s.rec; the replay's summary equals the play's, which ends END
    same_end() {
        if ! "$H" replay "$1/s.rec" --log "$1/re" >/dev/null 2>"$1/re.err"; then
            bad "$1: the replay failed: $(cat "$1/re.err")"; return; fi
        tail -1 "$1/logs/summary.csv" | grep -q ",$2,,,\$" || {
            bad "$1: the play ended $(tail -1 "$1/logs/summary.csv" | sed 's/,,,$//; s/.*,//'), want $2"; return; }
        cmp -s "$1/logs/summary.csv" "$1/re/summary.csv" && ok ||
            bad "$1: the replay's summary differs: $(tail -1 "$1/re/summary.csv")"
    }
    mkdir quit timeout
    { walk_input WN; printf '0.75 f=9 p=40 h=0.5,1.6,0.5,0,0,0,1\n'; } >quit.in
    run "play to quit" 0 "$H" play --size 64x48 --mode flag --input quit.in --log quit/logs \
        --record quit/s.rec
    same_end quit quit
    printf 'mode flag\nseed 5\nflag Wrf\ntime-limit 1\n' >tl.lvl
    walk_input WNESWNEE >timeout.in
    run "play to timeout" 0 "$H" play --size 64x48 tl.lvl --input timeout.in --log timeout/logs \
        --record timeout/s.rec
    same_end timeout timeout
    # live plays, ended by a signal or the close button
    ends="INT:130 TERM:143 HUP:129"
    [ -n "${X11_CLOSE:-}" ] && ends="$ends close:0" || echo "note: no X11_CLOSE: the close button is not tested"
    for s in $ends; do
        d=end-${s%:*}; mkdir "$d"
        "$H" play --size 64x48 --mode flag --log "$d/logs" --record "$d/s.rec" >/dev/null 2>&1 &
        pid=$!
        wait_for 60 -e "$d/logs/head-001.csv.live"
        sleep 0.2 # the attempt under way (0.5 s before: frames no check reads)
        if [ "${s%:*}" = close ]; then "$X11_CLOSE" holonomy || bad "close: no window"
        else kill -"${s%:*}" $pid; fi
        if gone_within $pid 100; then
            wait $pid; st=$?
            [ "$st" = "${s#*:}" ] && ok || bad "$d: status $st, want ${s#*:}"
            same_end "$d" aborted
        else
            bad "$d: still running"; kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
        fi
    done
else
    echo "note: no Xvfb here: play --input and the ends of a live play are not tested"
fi

finish cli_harden_logs
