#!/bin/sh
# cli_replay_killed.sh - a session killed with SIGKILL and recovered
# replays to the same end (issue 26 item 2): the replay of its recording
# (REC.live, never renamed) ends the attempt in play as the recovery of
# the play's folder did, `killed` with the steps and time of the rows that
# reached the disk, so the summary and the attempt's files are the same
# byte for byte. Under Xvfb (when installed): `play --input` of a long
# walk in explore, killed mid-walk.
. "$(dirname "$0")/lib.sh"

if ! command -v Xvfb >/dev/null 2>&1; then
    echo "note: no Xvfb here: a killed play is not replayed"
    finish cli_replay_killed
    exit $?
fi
start_xvfb 53 || { bad "Xvfb did not start"; finish cli_replay_killed; exit $?; }
case $H in /*) ;; *) H=$PWD/$H ;; esac
cd "$T" || exit 1

# 60,000 frames, 10 ms apart: walking E and W a cell every 0.25 s
awk 'BEGIN { for (k = 0; k < 60000; k++) { c = (int(k / 25) % 2) ? 2.5 : 1.5
             printf "%.2f f=9 h=%.1f,1.6,1.5,0,0,0,1\n", k * 0.01, c } }' >walk.in
"$H" play --size 64x48 --mode explore --input walk.in --log logs --record s.rec >/dev/null 2>&1 &
pid=$!
# killed once rows of a few seconds and steps reached the disk
wait_for 120 -l logs/steps-001.csv.live 8
sleep 0.3
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
[ -f s.rec.live ] && [ -f logs/attempt-001.live ] && ok || bad "no killed session: $(ls . logs)"
# the replay of the killed recording, then the play's folder recovered by
# the next --append session (one frame)
run "replay" 0 "$H" replay s.rec.live --log re
run "recovery" 0 "$H" play --size 64x48 --mode explore --log logs --append --frames 1
grep -q "1 unfinished attempt(s) of a killed session finished" err && ok || bad "recovery: $(cat err)"
sed -n 2p logs/summary.csv | grep -q ',killed,,,$' && ok || bad "the play's folder: $(cat logs/summary.csv)"
[ "$(sed -n 1,2p logs/summary.csv)" = "$(cat re/summary.csv)" ] && ok ||
    bad "the replay's summary differs: $(cat re/summary.csv) / $(sed -n 2p logs/summary.csv)"
cmp -s logs/steps-001.csv re/steps-001.csv && cmp -s logs/head-001.csv re/head-001.csv && ok ||
    bad "the replay's attempt files differ"
[ "$(ls re)" = "$(ls re | grep -v '\.live$')" ] && ok || bad "live files left: $(ls re)"
sed -n 2p re/summary.csv | awk -F, '$19 >= 7 && $21 > 1' | grep -q . && ok ||
    bad "the killed attempt has too few rows to tell: $(sed -n 2p re/summary.csv)"
finish cli_replay_killed
