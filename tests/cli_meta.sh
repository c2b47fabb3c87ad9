#!/bin/sh
# cli_meta.sh - a session's metadata (issue 26 item 5): play's --session N
# and repeatable --meta KEY=VALUE (checked: exit 2, one line; they need
# --log), one row per session start appended to the log folder's
# environment.csv (header once, RFC 4180, the session id of summary.csv),
# and with --study the study's text kept as study-HASH.txt with its hash in
# the row. summary.csv has them too (tests/cli_meta_summary.sh). replay
# writes no environment row.
. "$(dirname "$0")/lib.sh"
case $H in /*) ;; *) H=$PWD/$H ;; esac
cd "$T" || exit 1
mkdir s
printf 'mode flag\nseed 5\nflag Wrf\n' >s/f.lvl
printf 'study mt\ncondition a\nlevel f.lvl\nset minimap hud\n' >s/mt.study

# the options' own rules (before any window)
for bad_arg in "--session 0" "--session 1000" "--session x" "--meta K=v" "--meta =v" \
               "--meta nokey" "--meta a;b=1" "--meta k=a;b" \
               "--meta abcdefghijabcdefghijabcdefghijabc=1" "--meta k=1 --meta k=2"; do
  # shellcheck disable=SC2086
  run "bad: $bad_arg" 2 env DISPLAY= "$H" play --mode flag --log l0 $bad_arg
  [ "$(wc -l <"$T/err")" -eq 1 ] && ok || bad "$bad_arg: not one line: $(cat "$T/err")"
done
# shellcheck disable=SC2046
run "17 metas" 2 env DISPLAY= "$H" play --mode flag --log l0 $(for i in 0 1 2 3 4 5 6 7 8 9 a b c d e f g; do printf -- '--meta k%s=1 ' $i; done)
one_line "17 metas" "more than 16"
run "session without log" 2 env DISPLAY= "$H" play --mode flag --session 2
one_line "session without log" "--session goes with --log"
run "meta without log" 2 env DISPLAY= "$H" play --mode flag --meta a=1
one_line "meta without log" "--meta goes with --log"
[ ! -e l0 ] && ok || bad "a refused play made l0"
run "xr: bad session" 2 "$H" xr --log l0 --session 1000
one_line "xr: bad session" "--session '1000' is not a session number"
run "xr: meta without log" 2 "$H" xr --meta a=1
one_line "xr: meta without log" "--meta goes with --log"
run "xr: twice the key" 2 "$H" xr --log l0 --meta a=1 --meta a=2
one_line "xr: twice the key" "--meta key 'a' is given twice"
"$H" xr --help | grep -q -- "--session N" && ok || bad "xr --help lacks --session"
"$H" play --help | grep -q -- "--meta KEY=VALUE" && ok || bad "play --help lacks --meta"

start_xvfb 37 || { bad "Xvfb did not start"; finish cli_meta; exit $?; }
walk_input WNESE >in1
run "session 1" 0 "$H" play --study s/mt.study --participant P01 --size 64x48 --log logs \
    --input in1 --session 1 --meta room=lab_2 --meta 'note=a, "quoted" value' --record r.rec
SUM=$(sha256sum s/mt.study | cut -d' ' -f1)
[ -f "logs/study-$SUM.txt" ] && cmp -s s/mt.study "logs/study-$SUM.txt" && ok ||
    bad "no study-$SUM.txt: $(ls logs)"
head -1 logs/environment.csv | grep -qx "session,participant,session_no,study_sha256,platform,os,runtime,gl_renderer,controller,refresh_hz,width,height,meta,options" &&
    ok || bad "header: $(head -1 logs/environment.csv)"
SID=$(sed -n 2p logs/summary.csv | cut -d, -f1)
ROW=$(sed -n 2p logs/environment.csv)
case "$ROW" in
  "$SID,P01,1,$SUM,desktop,$(uname -srm),,"*",64,48,\"room=lab_2;note=a, \"\"quoted\"\" value\",\"play --study s/mt.study "*) ok ;;
  *) bad "row: $ROW (session $SID)" ;;
esac
[ "$(head -1 logs/summary.csv | cut -d, -f1-5)" = "session,participant,session_start,version,attempt" ] &&
    head -1 logs/summary.csv | grep -q ',end,session_no,study_sha256,meta$' && ok ||
    bad "summary.csv's columns: $(head -1 logs/summary.csv)"
# a second session appends one row, no second header, the study file kept once
run "session 2" 0 "$H" play --study s/mt.study --participant P02 --size 64x48 --log logs \
    --input in1 --append --session 2
[ "$(wc -l <logs/environment.csv)" = 3 ] && [ "$(grep -c '^session,' logs/environment.csv)" = 1 ] &&
    sed -n 3p logs/environment.csv | grep -q "^[^,]*,P02,2,$SUM," && ok ||
    bad "second row: $(cat logs/environment.csv)"
[ "$(ls logs | grep -c '^study-')" = 1 ] && ok || bad "study files: $(ls logs)"
# a level without a study: empty study_sha256 and session_no
run "level" 0 "$H" play s/f.lvl --size 64x48 --log l2 --input in1
sed -n 2p l2/environment.csv | grep -q "^[^,]*,,,,desktop," && ok || bad "level row: $(cat l2/environment.csv)"
# replay: no environment row (the environment is the live one)
run "replay" 0 "$H" replay r.rec --log rl
[ ! -e rl/environment.csv ] && ok || bad "replay wrote environment.csv"
# issue 39 finding 5: 16 valid values of 200 bytes that escaping makes
# 4 times longer keep their row (the row is sized for the worst case), and
# the options column holds the whole command line (13,000 bytes escaped)
B=$(printf '%200s' '' | tr ' ' '\\'); C=$(printf '%200s' '' | tr ' ' '\001')
set --
for i in 0 1 2 3 4 5 6 7; do set -- "$@" --meta "b$i=$B" --meta "c$i=$C"; done
run "16 escaped metas" 0 "$H" play s/f.lvl --size 64x48 --log l3 --input in1 "$@"
[ "$(wc -l <l3/environment.csv 2>/dev/null)" = 2 ] &&
    sed -n 2p l3/environment.csv | grep -q 'c7=\(\\x01\)\{200\}$' &&
    ok || bad "16 escaped metas: no whole environment row ($(cat "$T/err"))"
# a command line the options column cannot hold is refused before play,
# never cut: exit 2, one line
run "long command line" 2 "$H" play "$(printf '%8500s' '' | sed 's| |./|g')s/f.lvl" \
    --size 64x48 --log l4 --input in1
one_line "long command line" "environment.csv's options column holds at most"
[ ! -e l4 ] && ok || bad "a refused play made l4"
finish cli_meta
