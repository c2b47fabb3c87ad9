#!/bin/sh
# cli_meta_summary.sh - the session's metadata in summary.csv (issue 26
# item 5): the columns session_no, study_sha256 and meta after `end`,
# escaped and quoted as the other CSV writers do; carried by the recording
# (version 4), so a replay writes the same summary byte for byte; kept by
# the recovery of a killed session (its own metadata, not the recovering
# session's); by --resume; a folder whose summary.csv has the columns
# before these is appended to in its own columns; report reads old and
# new summaries and gives attempts.csv a session_no column.
. "$(dirname "$0")/lib.sh"
case $H in /*) ;; *) H=$PWD/$H ;; esac
cd "$T" || exit 1
OLD='session,participant,session_start,version,attempt,study,condition,position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end'
NEW="$OLD,session_no,study_sha256,meta"

# a version 4 recording made by hand: replay writes its metadata in every
# row (no window needed)
rec4() {
  printf 'holonomy-rec 4\nsession 20260131T140509Z-5f3a9c01\nparticipant P01\nstart 2026-01-31T14:05:09Z\nversion 0.1.0\n'
  printf 'session_no 2\nstudy_sha256 %s\nmeta room=lab_2\nmeta note=a, "quoted" \\\\ \\x1b value\n' \
    "$(printf x | sha256sum | cut -d' ' -f1)"
  printf 'level f\nL mode flag\nL seed 5\nL flag Wrf\nend\n0 f=8 m=0,1\n0.5 f=8 m=0,1\n1 f=8\n'
}
rec4 >v4.rec
run "replay v4" 0 "$H" replay v4.rec --log l4
[ "$(head -1 l4/summary.csv)" = "$NEW" ] && ok || bad "header: $(head -1 l4/summary.csv)"
XS=$(printf x | sha256sum | cut -d' ' -f1)
case "$(sed -n 2p l4/summary.csv)" in
  *",open,2,$XS,\"room=lab_2;note=a, \"\"quoted\"\" \\\\ \\x1b value\"") ok ;;
  *) bad "v4 row: $(sed -n 2p l4/summary.csv)" ;;
esac
# an old recording (version 2) still replays: the three fields empty
printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nstart 2026-01-31T14:05:09Z\nversion 0.1.0\nlevel f\nL mode flag\nL seed 5\nL flag Wrf\nend\n0 f=8 m=0,1\n1 f=8\n' >v2.rec
run "replay v2" 0 "$H" replay v2.rec --log l2
sed -n 2p l2/summary.csv | grep -q ',open,,,$' && ok || bad "v2 row: $(sed -n 2p l2/summary.csv)"
# version 4 lines are checked, naming the line
for badl in 'session_no 0' 'session_no 1000' 'session_no 01' 'study_sha256 abc' \
            'meta K=v' 'meta k=a;b' 'meta k=\q' 'meta k=\x1' 'meta k=\x41'; do
  rec4 | BADL=$badl awk 'NR == 6 { print ENVIRON["BADL"] } { print }' >bad.rec
  run "bad v4 line: $badl" 2 "$H" replay bad.rec
  one_line "bad v4 line: $badl" "line 6:"
done
rec4 | awk 'NR == 9 { print "meta room=again" } { print }' >bad.rec
run "meta key twice" 2 "$H" replay bad.rec
one_line "meta key twice" "line 9: not a valid 'meta KEY=VALUE' line"
rec4 | sed 's/^holonomy-rec 4/holonomy-rec 3/' | sed '/^study_sha256\|^session_no\|^meta/d' |
  sed '6i session_no 2' >bad.rec
run "v4 line in v3" 2 "$H" replay bad.rec
one_line "v4 line in v3" "line 6:"

# report: old (21 columns) and new summaries side by side; session_no
# carried into attempts.csv
mkdir old
{ echo "$OLD"
  echo '20260131T140509Z-5f3a9c01,P09,2026-01-31T14:05:09Z,0.1.0,1,,,,f,00,flag,5,15,"4,5",3x3,1,0.0000,1,8,1.0000,open'
} >old/summary.csv
run "report old and new" 0 "$H" report old l4 --out rep
head -1 rep/attempts.csv | grep -q ',logdir_relative,session_no$' && ok ||
  bad "attempts.csv header: $(head -1 rep/attempts.csv)"
[ "$(sed -n 2p rep/attempts.csv | awk -F, '{print $NF}')" = "" ] &&
  [ "$(sed -n 3p rep/attempts.csv | awk -F, '{print $NF}')" = 2 ] && ok ||
  bad "session_no in attempts.csv: $(cat rep/attempts.csv)"

if ! command -v Xvfb >/dev/null 2>&1; then
  echo "note: no Xvfb here: play's summary not checked"
  finish cli_meta_summary
  exit $?
fi
start_xvfb 61 || { bad "Xvfb did not start"; finish cli_meta_summary; exit $?; }
mkdir s
printf 'mode flag\nseed 5\nflag Wrf\n' >s/f.lvl
printf 'study mt\ncondition a\nlevel f.lvl\nset minimap hud\ncondition b\nlevel f.lvl\nset minimap hand\n' >s/mt.study
SUM=$(sha256sum s/mt.study | cut -d' ' -f1)
walk_input WNESE >in1

# play: the three columns in every row; the replay writes the same summary
run "play" 0 "$H" play --study s/mt.study --participant P01 --size 64x48 --log logs \
    --input in1 --session 3 --meta room=lab_2 --meta "note=a, \"q\" $(printf '\033')x" --record r.rec
[ "$(head -1 logs/summary.csv)" = "$NEW" ] && ok || bad "play header: $(head -1 logs/summary.csv)"
case "$(sed -n 2p logs/summary.csv)" in
  *",3,$SUM,\"room=lab_2;note=a, \"\"q\"\" \\x1bx\"") ok ;;
  *) bad "play row: $(sed -n 2p logs/summary.csv)" ;;
esac
head -1 r.rec | grep -qx 'holonomy-rec 4' && grep -qx 'session_no 3' r.rec &&
  grep -qx "study_sha256 $SUM" r.rec && grep -qx 'meta room=lab_2' r.rec && ok ||
  bad "the recording's header: $(head -12 r.rec)"
run "replay" 0 "$H" replay r.rec --log rl
cmp -s logs/summary.csv rl/summary.csv && ok || bad "replay's summary differs: $(cat rl/summary.csv)"
# refresh_hz: Xvfb's XRandR mode has no rate, so the present rate is
# measured (a number with three decimals, written at the session's end
# when it presented fewer than 60 frames)
sed -n 2p logs/environment.csv | grep -q ',[0-9][0-9]*\.[0-9][0-9][0-9],64,48,' && ok ||
  bad "refresh_hz: $(sed -n 2p logs/environment.csv)"
# the meta column of environment.csv is the summary's
E=$(sed -n 2p logs/environment.csv | sed 's/^.*,64,48,//' | sed 's/,"play --study.*//')
case "$(sed -n 2p logs/summary.csv)" in *",$E") ok ;; *) bad "environment's meta $E" ;; esac

# resume: the resumed session's rows carry its own metadata
run "play stops" 0 "$H" play --study s/mt.study --participant P02 --size 64x48 --log logs \
    --frames 1 --append --session 1 --meta day=one
# (a resumed session begins on the ready screen: confirmed first)
{ printf '0 f=9 p=1 h=1.5,1.6,1.5,0,0,0,1\n'; awk '{ $1 += 0.25; print }' in1; } >in1r
run "resume" 0 "$H" play --study s/mt.study --participant P02 --size 64x48 --log logs \
    --input in1r --resume --session 2 --meta day=two
grep ',P02,' logs/summary.csv | tail -1 | grep -q ",2,$SUM,day=two$" && ok ||
  bad "resumed row: $(grep ',P02,' logs/summary.csv)"

# kill -9 mid-walk: the recovered row keeps the killed session's metadata,
# not the recovering session's; the replay of REC.live writes the same row
awk 'BEGIN { for (k = 0; k < 60000; k++) { c = (int(k / 25) % 2) ? 2.5 : 1.5
             printf "%.2f f=9 h=%.1f,1.6,1.5,0,0,0,1\n", k * 0.01, c } }' >walk.in
"$H" play --size 64x48 --mode explore --input walk.in --log lk --record k.rec \
    --session 7 --meta who=killed >/dev/null 2>&1 &
pid=$!
wait_for 120 -l lk/steps-001.csv.live 4
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
[ -f lk/attempt-001.live ] && ok || bad "no killed attempt: $(ls lk)"
run "recovery" 0 "$H" play --size 64x48 --mode explore --log lk --append --frames 1 \
    --session 8 --meta who=recovery
sed -n 2p lk/summary.csv | grep -q ',killed,7,,who=killed$' && ok ||
  bad "recovered row: $(sed -n 2p lk/summary.csv)"
sed -n 3p lk/summary.csv | grep -q ',open,8,,who=recovery$' && ok ||
  bad "recovering session's row: $(sed -n 3p lk/summary.csv)"
run "replay killed" 0 "$H" replay k.rec.live --log rk
[ "$(sed -n 1,2p lk/summary.csv)" = "$(cat rk/summary.csv)" ] && ok ||
  bad "the killed replay's summary: $(cat rk/summary.csv)"

# --append to a folder of the columns before these: rows in its columns
mkdir lo
{ echo "$OLD"
  echo '20260131T140509Z-5f3a9c01,P09,2026-01-31T14:05:09Z,0.1.0,1,,,,f,00,flag,5,15,"4,5",3x3,1,0.0000,1,8,1.0000,open'
} >lo/summary.csv
run "append old" 0 "$H" play s/f.lvl --size 64x48 --log lo --append --input in1 --session 4
[ "$(head -1 lo/summary.csv)" = "$OLD" ] && [ "$(sed -n 3p lo/summary.csv | awk -F, '{print $NF}')" = open ] &&
  [ "$(wc -l <lo/summary.csv)" = 3 ] && ok || bad "old folder: $(cat lo/summary.csv)"
finish cli_meta_summary
