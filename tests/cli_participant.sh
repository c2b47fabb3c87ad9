#!/bin/sh
# cli_participant.sh - a participant who already has data is not started
# again unasked (issue 26): `play --study` / `xr --study` with --append to a
# log folder whose summary.csv has rows of that study and participant are
# refused with one line (exit 2) before anything opens, unless
# --restart-participant; other participants, other studies and a folder
# without a summary pass the check; ids in their one spelling (1, 001, p1
# are P01, also against logs that spell it 3 for P03; P-01 is refused as
# ambiguous). Runs without a display (the refusal
# comes before the window; the other cases get past it and stop there).
. "$(dirname "$0")/lib.sh"
unset DISPLAY

mkdir "$T/s" "$T/logs" "$T/empty"
printf 'mode flag\nseed 5\nflag Wrf\n' >"$T/s/flag.lvl"
printf 'study four\ncondition hud\nlevel flag.lvl\nset minimap hud\ncondition hand\nlevel flag.lvl\nset minimap hand\n' >"$T/s/four.study"
sed 's/^study four/study other/' "$T/s/four.study" >"$T/s/other.study"
{
  echo "session,participant,session_start,version,attempt,study,condition,position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end"
  echo 'S1,P01,2026-01-01T00:00:00Z,1.0,1,four,hud,1,flag,00,flag,5,15,"4,5",3x3,1,0.0000,8,8,9.5000,done'
  echo 'S1,P01,2026-01-01T00:00:00Z,1.0,2,four,hand,2,flag,00,flag,5,15,"4,5",3x3,1,9.5000,3,8,2.0000,killed'
} >"$T/logs/summary.csv"

run "P01 has data" 2 "$H" play --study "$T/s/four.study" --participant P01 --log "$T/logs" --append
one_line "P01 has data" "participant P01 already has data for study four in '.*logs' (2 attempts); --restart-participant"
# nothing made: no recording, no log file
run "P01 has data, --record" 2 "$H" play --study "$T/s/four.study" --participant P01 --log "$T/logs" --append --record "$T/r.rec"
[ "$(ls "$T/logs")" = summary.csv ] && ! ls "$T"/r.rec* >/dev/null 2>&1 && ok || bad "files made: $(ls "$T" "$T/logs")"
run "xr: P01 has data" 2 "$H" xr --study "$T/s/four.study" --participant P01 --log "$T/logs" --append
one_line "xr: P01 has data" "participant P01 already has data for study four"
# past the check (then no window: not a refusal of the participant)
for args in "--participant P02" "--participant P01 --restart-participant" ; do
  # shellcheck disable=SC2086
  "$H" play --study "$T/s/four.study" $args --log "$T/logs" --append --frames 1 >"$T/out" 2>"$T/err"
  if grep -q "already has data" "$T/err"; then bad "$args: refused"; else ok; fi
done
"$H" play --study "$T/s/other.study" --participant P01 --log "$T/logs" --append --frames 1 >"$T/out" 2>"$T/err"
if grep -q "already has data" "$T/err"; then bad "another study: refused"; else ok; fi
"$H" play --study "$T/s/four.study" --participant P01 --log "$T/empty" --append --frames 1 >"$T/out" 2>"$T/err"
if grep -q "already has data" "$T/err"; then bad "no summary: refused"; else ok; fi
# ids in their one spelling (issue 35): 1, 001 and p1 are P01, who has data
for id in 1 001 p1 P001; do
  run "$id has data" 2 "$H" play --study "$T/s/four.study" --participant $id --log "$T/logs" --append
  one_line "$id has data" "participant P01 already has data for study four"
done
# logs written before the rule name P03 "3": P03 and p3 have data there
echo 'S0,3,2026-01-01T00:00:00Z,1.0,3,four,hud,1,flag,00,flag,5,15,"4,5",3x3,1,0.0000,8,8,9.5000,done' \
  >>"$T/logs/summary.csv"
run "3 logged, P03 has data" 2 "$H" play --study "$T/s/four.study" --participant p3 --log "$T/logs" --append
one_line "3 logged, P03 has data" "participant P03 already has data for study four in '.*logs' (1 attempt)"
# a number spelled otherwise is refused, naming its spelling
for id in P-01 p_1 0.1 P.0.1; do
  run "ambiguous $id" 2 "$H" play --study "$T/s/four.study" --participant $id --log "$T/logs" --append
  one_line "ambiguous $id" "--participant '$id' is ambiguous: participant 1 is written P01 (1 and p1 are read as P01)"
  run "xr: ambiguous $id" 2 "$H" xr --participant $id --frames 1
  one_line "xr: ambiguous $id" "--participant '$id' is ambiguous"
done
# other ids stay as given
for args in "--participant s2-p031" "--participant Pam" ; do
  # shellcheck disable=SC2086
  "$H" play --study "$T/s/four.study" $args --log "$T/logs" --append --frames 1 >"$T/out" 2>"$T/err"
  if grep -q "ambiguous\|already has data" "$T/err"; then bad "$args: refused"; else ok; fi
done
# the option's own rules
run "restart without study" 2 "$H" play --restart-participant --log "$T/logs" --append
one_line "restart without study" "--restart-participant goes with --study"
run "xr restart without study" 2 "$H" xr --restart-participant --log "$T/logs" --append
one_line "xr restart without study" "--restart-participant goes with --study"
run "restart twice" 2 "$H" play --study "$T/s/four.study" --participant P01 --log "$T/logs" --append --restart-participant --restart-participant
run "help" 0 "$H" play --help
grep -q -- "--restart-participant" "$T/out" && ok || bad "play --help names --restart-participant"
run "xr help" 0 "$H" xr --help
grep -q -- "--restart-participant" "$T/out" && ok || bad "xr --help names --restart-participant"

finish "cli_participant"
