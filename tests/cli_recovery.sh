#!/bin/sh
# cli_recovery.sh - recovery of a log folder a kill (or a power loss) left
# torn, and the one summary reader (issue 39, findings 7, 14 and 15):
# - 7: every append-only log (events.csv, points.csv, answers.csv,
#   environment.csv, each finished steps-NNN.csv) is cut to its whole rows
#   before the next session appends, with one line naming what was cut
#   (the next row was glued onto the torn one);
# - 14: a summary row cut by recovery takes its attempt's files with it
#   (steps-NNN.csv was left with no row), said in the same line;
# - 15: `report`, `play --resume` and the participant check read
#   summary.csv one way (platform/cli/summary_read.h): a symbolic link,
#   a NUL byte, a garbage row, a 70 KB line are refused by each with the
#   same line; a byte order mark and CR LF line ends are read by each (and
#   appended to); the last row a kill cut is left out by each.
# Sessions under Xvfb (when installed) for the resumed plays.
. "$(dirname "$0")/lib.sh"
H=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
cd "$T" || exit 1

{ printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nparticipant P01\n'
  printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\n'
  printf 'level f\nL mode flag\nL seed 5\nL flag Nf\nend\n'
  printf '0 f=9 h=1.5,1.6,1.5,0,0,0,1\n1 f=9 h=0.5,1.6,1.5,0,0,0,1\n2 f=9 h=0.5,1.6,1.5,0,0,0,1\n'
} >r.rec
# ends_lf FILE: FILE's last byte is a newline
ends_lf() { [ "$(tail -c 1 "$1" | od -An -c | tr -d ' ')" = '\n' ]; }

# ---- finding 7: every append-only log cut to its whole rows -------------------------
run "two attempts" 0 "$H" replay r.rec --log k
run "two attempts" 0 "$H" replay r.rec --log k --append
A='session,participant,attempt,questionnaire,when,item,kind,value,time'
P='session,participant,attempt,level,t,target,pointed,true,flat,error_true,error_flat,time'
printf '%s\nS,P01,1,q,level,a,likert,3,1.0000\nS,P01,1,q,lev' "$A" >k/answers.csv
printf '%s\nS,P01,1,f,2.0000,start,90.0,90.0,90.0,0.0,0.0,1.0000\nS,P01,1,f,2.0' "$P" >k/points.csv
printf 'session,attempt,level,t,event,value\nS,1,f,1.0000,minimap,hud\nS,1,f,1.5' >k/events.csv
printf 'session,platform\nS,desktop\nS,desk' >k/environment.csv
n=$(wc -c <k/steps-001.csv)
head -c $((n - 5)) k/steps-001.csv >x && mv x k/steps-001.csv
run "recovery cuts the logs" 0 "$H" replay r.rec --log k --append
for f in answers:2 points:2 events:2 environment:2 steps-001:1; do # name:its whole lines
    n=${f#*:}; f=${f%:*}
    ends_lf "k/$f.csv" && [ "$(grep -c '' "k/$f.csv")" = "$n" ] && ok ||
        bad "$f.csv not cut to its whole rows: $(tail -c 80 "k/$f.csv")"
done
grep -q "the log folder's rows a kill cut removed (events.csv, points.csv, answers.csv, environment.csv, steps-001.csv)" err &&
    [ "$(grep -c 'cut removed' err)" = 1 ] && ok || bad "the line of what was cut: $(cat err)"
run "report after the cut" 0 "$H" report k --out r1
grep -q warning err && bad "report warned: $(cat err)" || ok
# nothing torn: nothing said, nothing changed
cp -r k k2
run "a whole folder" 0 "$H" replay r.rec --log k2 --append
grep -q "cut" err && bad "a whole folder: $(cat err)" || ok
cmp -s k/answers.csv k2/answers.csv && cmp -s k/steps-001.csv k2/steps-001.csv && ok ||
    bad "a whole folder's logs changed"

# ---- finding 14: a cut summary row takes its attempt's files ------------------------
run "three attempts" 0 "$H" replay r.rec --log o
run "three attempts" 0 "$H" replay r.rec --log o --append
run "three attempts" 0 "$H" replay r.rec --log o --append
n=$(wc -c <o/summary.csv)
head -c $((n - 30)) o/summary.csv >x && mv x o/summary.csv # attempt 3's row cut
run "report of a cut row" 0 "$H" report o --out r2
one_line "report of a cut row" "warning: .*summary.csv: line 4: a row a kill cut (no newline at the file's end): left out"
run "recovery of a cut row" 0 "$H" replay r.rec --log o --append
one_line "recovery of a cut row" "rows a kill cut removed (summary.csv); the files of the attempt whose summary row was cut removed with it: .*steps-003.csv"
ls o | grep -q -e '-003\.' && bad "attempt 3's files kept without its row: $(ls o)" || ok
[ "$(cut -d, -f5 o/summary.csv | tr '\n' ' ')" = "attempt 1 2 4 " ] && ok ||
    bad "the attempts after recovery: $(cut -d, -f5 o/summary.csv)"
for a in 001 002 004; do [ -f o/steps-$a.csv ] || bad "steps-$a.csv missing"; done
run "report after a cut row" 0 "$H" report o --out r3
[ ! -s err ] && ok || bad "report after a cut row: $(cat err)"
# a cut row whose attempt is still live is finished by recovery (kept, killed)
run "live attempt" 0 "$H" replay r.rec --log lv
sed -n 2p lv/summary.csv | sed 's/,1,,,,f,/,2,,,,f,/' >lv/attempt-002.live
printf '%s' "$(sed -n 2p lv/summary.csv | sed 's/,1,,,,f,/,2,,,,f,/' | cut -c1-60)" >>lv/summary.csv
: >lv/steps-002.csv.live
run "recovery of a live attempt" 0 "$H" replay r.rec --log lv --append
[ "$(cut -d, -f5 lv/summary.csv | tr '\n' ' ')" = "attempt 1 2 3 " ] && [ -f lv/steps-002.csv ] &&
    ok || bad "a live attempt's cut row: $(cat lv/summary.csv; ls lv)"

# ---- finding 15: one summary reader ------------------------------------------------
mkdir s
printf 'mode flag\nseed 5\nflag Nf\n' >s/f.lvl
printf 'study rs\npractice f.lvl\ncondition a\nlevel f.lvl\nset minimap hud\ncondition b\nlevel f.lvl\nset minimap hand\n' >s/rs.study
S=$T/s/rs.study
HR='session,participant,session_start,version,attempt,study,condition,position,level,level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end'
ROW='S1,P01,2026-01-01T00:00:00Z,1.0,1,rs,practice,0,f,00,flag,5,15,"4,5",3x3,1,0.0000,8,8,9.5000,done'
# same NAME STATUS TEXT: report, --resume and the participant check of
# --append on folder h end STATUS with one line holding TEXT
same() {
    run "$1: report" "$2" "$H" report h --out "rep-$1"
    one_line "$1: report" "$3"
    run "$1: resume" "$2" env DISPLAY= "$H" play --study "$S" --participant P01 --log h --resume
    one_line "$1: resume" "$3"
    run "$1: append" "$2" env DISPLAY= "$H" play --study "$S" --participant P01 --log h --append
    one_line "$1: append" "$3"
}
mkdir h
{ echo "$HR"; echo "$ROW"; } >real.csv
ln -s ../real.csv h/summary.csv
same "a symbolic link" 2 "summary.csv' is a symbolic link, not a log file"
run "a symbolic link: replay" 2 "$H" replay r.rec --log h --append
one_line "a symbolic link: replay" "'summary.csv' is a symbolic link, not a log file"
[ "$(grep -c '' real.csv)" = 2 ] && ok || bad "the link's file was written: $(cat real.csv)"
rm h/summary.csv
{ echo "$HR"; printf '%s\n' "$ROW" | tr 'f' '\000'; } >h/summary.csv
same "a NUL byte" 2 "summary.csv: line 2: a NUL byte"
{ echo "$HR"; echo "$ROW"; echo 'garbage'; } >h/summary.csv
same "a garbage row" 2 "summary.csv: line 3: 1 fields where the header has 21"
{ echo "$HR"; echo "$ROW"; awk 'BEGIN { for (i = 0; i < 7000; i++) printf "xxxxxxxxxx"; print "" }'; } >h/summary.csv
same "a 70 KB line" 2 "summary.csv': longer than 65536 bytes"
# read alike: the participant has data (a byte order mark, CR LF, a cut last row)
{ printf '\357\273\277'; echo "$HR"; echo "$ROW"; } >h/summary.csv
run "a byte order mark: report" 0 "$H" report h --out rep-bom
run "a byte order mark: append" 2 env DISPLAY= "$H" play --study "$S" --participant P01 --log h --append
one_line "a byte order mark: append" "participant P01 already has data for study rs"
run "a byte order mark: resume" 2 env DISPLAY= "$H" play --study "$S" --participant P01 --log h --resume
one_line "a byte order mark: resume" "the study given is not the one participant P01 played"
{ echo "$HR"; echo "$ROW"; } | sed 's/$/\r/' >h/summary.csv
run "CR LF: report" 0 "$H" report h --out rep-crlf
run "CR LF: append" 2 env DISPLAY= "$H" play --study "$S" --participant P01 --log h --append
one_line "CR LF: append" "participant P01 already has data for study rs"
run "CR LF: resume" 2 env DISPLAY= "$H" play --study "$S" --participant P01 --log h --resume
one_line "CR LF: resume" "the study given is not the one participant P01 played"

if ! start_xvfb; then
    echo "note: no Xvfb here: resumed sessions are not played"
    finish cli_recovery
    exit $?
fi
# a real folder: practice done, condition a left open; then its summary
# saved by another program (a byte order mark, CR LF): resumed alike, and
# a NUL byte in it refused (it restarted the participant at the practice)
walk_input WNESE >in1
printf '1.5 f=9 p=1 h=2.5,1.6,1.5,0,0,0,1\n1.75 f=9 h=2.5,1.6,1.5,0,0,0,1\n' >>in1
PL="$H play --study $S --participant P01 --size 64x48 --input in1"
# a resume: the ready screen confirmed first (issue 35)
{ printf '0 f=9 p=1 h=1.5,1.6,1.5,0,0,0,1\n'; awk '{ $1 += 0.25; print }' in1; } >in1r
PR="$H play --study $S --participant P01 --size 64x48 --input in1r"
run "session 1" 0 $PL --log logs
for v in bom crlf; do
    cp -r logs "$v"
    case $v in
    bom) { printf '\357\273\277'; cat logs/summary.csv; } >"$v/summary.csv" ;;
    crlf) sed 's/$/\r/' logs/summary.csv >"$v/summary.csv" ;;
    esac
    run "$v: resumed" 0 $PR --log "$v" --resume
    grep -q "resumed at a (position 1), level 2 of 3\$" err && ok || bad "$v: $(cat err)"
    [ "$(grep -c '' "$v/summary.csv")" = 5 ] && ok || bad "$v: rows $(cat "$v/summary.csv")"
    run "$v: report" 0 "$H" report "$v" --out "rep-$v-2"
done
# a live play's environment row is not glued onto a torn one
cp -r logs env
printf 'S,desk' >>env/environment.csv
run "environment: resumed" 0 $PR --log env --resume
grep -q "rows a kill cut removed (environment.csv)" err && ok || bad "environment: $(cat err)"
[ "$(grep -c '' env/environment.csv)" = 3 ] && ! grep -q '^S,desk' env/environment.csv && ok ||
    bad "the environment row was glued on: $(cut -c1-40 env/environment.csv)"
cp -r logs nul
sed '2s/practice/pr\x00ctice/' logs/summary.csv >nul/summary.csv
run "a NUL byte: resumed" 2 $PR --log nul --resume
one_line "a NUL byte: resumed" "summary.csv: line 2: a NUL byte"
finish cli_recovery
