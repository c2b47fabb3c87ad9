#!/bin/sh
# cli_harden_writers.sh - the writers (issue 39, findings 2, 8, 9, 10). Each
# check failed before its change:
# - two sessions in one --log folder at once mixed their rows and numbered
#   attempts twice; now the folder has one writer (a lock, .holonomy-lock):
#   the second is refused with exit 2 and one line naming the holder, a lock
#   a killed writer left is taken over with one line, and the lock file is
#   no log (report reads past it);
# - a file size limit (ulimit -f) killed every writer by SIGXFSZ (exit 153,
#   no line, its hidden temporary file left); now EFBIG takes the usual
#   failure path: exit 1, one line in errno's own words, nothing left;
# - a temporary file of a killed writer (kill -9 in `replay --wav`,
#   `report`) stayed for good unless the same target was saved again; now
#   the next save into that folder, or a session into that log folder,
#   removes those of writers that no longer run, with one line;
# - an error said twice (the session's at the step, again at its end), and
#   --wav said "input/output error" for every cause.
. "$(dirname "$0")/lib.sh"
H=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
cd "$T" || exit 1

rec_header() {
    printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c0%s\nparticipant P01\n' "$1"
    printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\nlevel f\nL mode flag\nL seed 5\nL flag Nf\nend\n'
}
{ rec_header 1; printf '0 f=9 h=1.5,1.6,1.5,0,0,0,1\n0.25 f=9 h=0.5,1.6,1.5,0,0,0,1\n'; } >a.rec
# 4000 records (40 s): a steps file of some KB, a session of some ms
{ rec_header 2
  awk 'BEGIN { for (i = 0; i < 4000; i++) printf "%d.%02d f=9 h=1.5,1.6,1.5,0,0,0,1\n", i / 100, i % 100 }'
} >long.rec
# a process id that no longer runs
true & dead=$!
wait $dead

# ---- one writer per log folder ---------------------------------------------------
mkdir L
run "first" 0 "$H" replay a.rec --log L
[ ! -e L/.holonomy-lock ] && ok || bad "the lock stays after the session"
if command -v flock >/dev/null 2>&1; then
    # another process holds the folder's lock (flock(1) on its descriptor,
    # which the sleep keeps: killing it frees the lock), as a session does
    sh -c 'exec 9>>L/.holonomy-lock && flock 9 && exec sleep 30' &
    fl=$!
    while flock -n L/.holonomy-lock true; do sleep 0.01; done
    printf 'pid 4242 on station-2\n' >L/.holonomy-lock
    run "second, held" 2 "$H" replay a.rec --log L --append &&
        one_line "second, held" "in use by another session (pid 4242 on station-2)"
    kill $fl 2>/dev/null
    wait $fl 2>/dev/null
    [ "$(sed 1d L/summary.csv | wc -l)" = 1 ] && ok ||
        bad "the refused session wrote: $(cat L/summary.csv)"
else
    echo "cli_harden_writers: no flock(1), the held-lock checks skipped"
fi
# a lock file a killed session left: taken over, one line; gone after
printf 'pid %s on %s\n' "$dead" "$(hostname)" >L/.holonomy-lock
run "stale lock" 0 "$H" replay a.rec --log L --append &&
    one_line "stale lock" "took over the lock of a session that no longer runs (pid $dead on"
[ ! -e L/.holonomy-lock ] && ok || bad "the taken-over lock stays"
# the lock file is no log: report reads past it (a session running, or killed)
printf 'pid %s on %s\n' "$dead" "$(hostname)" >L/.holonomy-lock
run "report past the lock" 0 "$H" report L --out R && ok
rm -f L/.holonomy-lock
# two sessions at once, three times: one runs, the other one runs after it
# or is refused (exit 2); never two attempts with one number
i=0
while [ $i -lt 3 ]; do
    "$H" replay long.rec --log M --append >/dev/null 2>"m1.err" &
    p1=$!
    "$H" replay long.rec --log M --append >/dev/null 2>"m2.err" &
    p2=$!
    wait $p1; s1=$?
    wait $p2; s2=$?
    case "$s1 $s2" in
    "0 0" | "0 2" | "2 0") ok ;;
    *) bad "two at once: status $s1 and $s2 ($(cat m1.err m2.err))" ;;
    esac
    i=$((i + 1))
done
cut -d, -f5 M/summary.csv | sed 1d | sort | uniq -d >dup
[ ! -s dup ] && ok || bad "attempt numbers twice: $(cat dup)"
run "report two at once" 0 "$H" report M --out RM

# ---- a file size limit: EFBIG, not SIGXFSZ -----------------------------------------
# (sh's ulimit -f counts blocks of 512 bytes)
# tmp_left DIR: a temporary file is left in DIR
tmp_left() { ls -A "$1" | grep -q 'holonomy-tmp'; }
mkdir F
( ulimit -f 1; exec "$H" render --size 256x256 --out F/o.png ) >out 2>err
st=$?
[ $st = 1 ] && ok || bad "render over the limit: status $st"
one_line "render over the limit" "cannot write 'F/o.png': File too large"
tmp_left F && bad "render left: $(ls -A F)" || ok
# (OpenAL Soft's null driver: its PulseAudio probe would say a line of its
# own when its shared memory passes the limit)
( ulimit -f 1; ALSOFT_DRIVERS=null exec "$H" replay a.rec --wav F/o.wav ) >out 2>err
st=$?
[ $st = 1 ] && ok || bad "--wav over the limit: status $st"
one_line "--wav over the limit" "cannot write 'F/o.wav': File too large"
tmp_left F && bad "--wav left: $(ls -A F)" || ok
( ulimit -f 8; exec "$H" replay long.rec --log FL ) >out 2>err
st=$?
[ $st = 1 ] && ok || bad "a log over the limit: status $st"
one_line "a log over the limit" "File too large"
# the folder it left is a killed session's: the next session recovers it
run "after the limit" 0 "$H" replay a.rec --log FL --append

# ---- temporary files of writers that no longer run ---------------------------------
mkdir W
: >W/.o.wav.holonomy-tmp.$dead.AbCdEf
: >W/.other.png.holonomy-tmp.$dead.AbCdEf
: >W/.mine.png.holonomy-tmp.$$.AbCdEf # its writer runs: kept
: >W/.not.ours.AbCdEf
run "--wav into the folder" 0 "$H" replay a.rec --wav W/o.wav &&
    one_line "--wav into the folder" "removed 2 temporary file(s) left in 'W' by writers that no"
ls -A W | tr '\n' ' ' >got
[ "$(cat got)" = ".mine.png.holonomy-tmp.$$.AbCdEf .not.ours.AbCdEf o.wav " ] && ok ||
    bad "after --wav: $(cat got)"
: >L/.attempts.csv.holonomy-tmp.$dead.AbCdEf
run "a session into the folder" 0 "$H" replay a.rec --log L --append &&
    one_line "a session into the folder" "removed 1 temporary file(s) left in 'L'"
ls -A L | grep -q holonomy-tmp && bad "a session left: $(ls -A L)" || ok
# a report killed mid-write (kill -9): its next run into --out removes them
: >R/.attempts.csv.holonomy-tmp.$dead.AbCdEf
: >R/.attempt-0001.png.holonomy-tmp.$dead.AbCdEf
run "report again" 0 "$H" report L --out R &&
    one_line "report again" "removed 2 temporary file(s) left in 'R'"
ls -A R | grep -q holonomy-tmp && bad "report left: $(ls -A R)" || ok
finish cli_harden_writers
