#!/bin/sh
# cli_harden_report.sh - `holonomy report` against hostile logs and output
# folders (issue 24, findings 3, 5, 6, 10, 12 and 13): a stale picture
# numbered 0, more conditions than the old table held, control bytes and
# bad UTF-8 in summary fields, --out as a dangling link or '', a report's
# name in DIR that is a folder or a FIFO, messages escaped once, a UTF-8
# byte order mark, long lines, blank lines. The reproductions are also in
# tests/hostile/report-*.
. "$(dirname "$0")/lib.sh"

# a log folder made by replay: the flag level at Nf, walked WNESE (optimal)
{ printf 'holonomy-rec 3\nsession 20260131T140509Z-00000001\nparticipant P01\n'
  printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\nstudy s1\nlevel flag-a\n'
  printf 'condition map 1\nL mode flag\nL seed 5\nL flag Nf\nend\n'
  walk_input WNESE; } >"$T/a.rec"
run "replay" 0 "$H" replay "$T/a.rec" --log "$T/la"
L=$T/la

# finding 3: attempt-0000.png in DIR (read r->att[-1]): removed as stale
mkdir "$T/o3" && : >"$T/o3/attempt-0000.png"
run "attempt-0000.png" 0 "$H" report "$L" --out "$T/o3"
[ ! -e "$T/o3/attempt-0000.png" ] && [ -f "$T/o3/attempt-0001.png" ] && ok ||
    bad "attempt-0000.png: $(ls "$T/o3" | tr '\n' ' ')"

# finding 5: 70 conditions give 70 rows (64 before, silently)
mkdir "$T/l70"
{ head -1 "$L/summary.csv"
  for i in $(seq 1 70); do
      sed -n 2p "$L/summary.csv" | awk -F, -v OFS=, -v i="$i" '{ $5 = i; $7 = "c" i; print }'
  done; } >"$T/l70/summary.csv"
run "70 conditions" 0 "$H" report "$T/l70" --out "$T/o70"
[ "$(wc -l <"$T/o70/conditions.csv")" = 71 ] && grep -q '^s1,c70,1,' "$T/o70/conditions.csv" &&
    ok || bad "70 conditions: $(($(wc -l <"$T/o70/conditions.csv") - 1)) rows"
[ "$(grep -c '<tr><td>s1</td><td>c' "$T/o70/index.html")" = 70 ] && ok ||
    bad "70 conditions on the page: $(grep -c '<tr><td>s1</td><td>c' "$T/o70/index.html")"

# finding 6: ESC, BEL, DEL, C1 (U+009B), bidi (U+202E), bad UTF-8 in fields
# come out as \xHH in every file; valid UTF-8 and the logs' own backslash
# escapes are kept as they are
cp -r "$L" "$T/lc"
ctl=$(printf 'x\033]0;T\007\177\302\233\342\200\256\377y')
awk -F, -v OFS=, -v c="$ctl" 'NR == 2 { $2 = "P" c; $7 = "m" c; $9 = "f\\\\\303\251" c } { print }' \
    "$L/summary.csv" >"$T/lc/summary.csv"
run "control bytes" 0 "$H" report "$T/lc" --out "$T/oc"
esc='x\x1b]0;T\x07\x7f\xc2\x9b\xe2\x80\xae\xffy'
for f in attempts.csv conditions.csv index.html; do
    n=$(LC_ALL=C tr -d '\n\040-\176' <"$T/oc/$f" | LC_ALL=C tr -d '\303\251' | wc -c)
    [ "$n" = 0 ] && ok || bad "$f: $n raw control or non-ASCII bytes"
    grep -qF "m$esc" "$T/oc/$f" && ok || bad "$f: the condition is not escaped as m$esc"
done
grep -qF "P$esc,20260131T140509Z-00000001," "$T/oc/attempts.csv" && ok ||
    bad "the participant: $(sed -n 2p "$T/oc/attempts.csv")"
grep -qF "f\\\\$(printf '\303\251')$esc" "$T/oc/attempts.csv" && ok ||
    bad "the level (backslash kept, é kept): $(sed -n 2p "$T/oc/attempts.csv")"

# finding 10: --out a dangling link, '', a report's name that is a folder or
# a FIFO: bad input (2), one line, nothing written
ln -s "$T/nowhere" "$T/dangle"
run "--out dangling" 2 "$H" report "$L" --out "$T/dangle" && one_line "--out dangling" "symbolic link"
[ ! -e "$T/nowhere" ] && ok || bad "--out dangling: the link's target was made"
run "--out ''" 2 "$H" report "$L" --out '' && one_line "--out ''" "empty"
mkdir -p "$T/of/attempt-0001.png"
run "png a folder" 2 "$H" report "$L" --out "$T/of" && one_line "png a folder" "attempt-0001.png"
[ -d "$T/of/attempt-0001.png" ] && [ ! -e "$T/of/index.html" ] && ok || bad "png a folder: written"
mkdir "$T/op" && mkfifo "$T/op/attempt-0001.png"
run "png a FIFO" 2 "$H" report "$L" --out "$T/op" && one_line "png a FIFO" "attempt-0001.png"
[ -p "$T/op/attempt-0001.png" ] && [ ! -e "$T/op/index.html" ] && ok || bad "png a FIFO: written"
mkdir "$T/oh" && mkfifo "$T/oh/index.html"
run "index a FIFO" 2 "$H" report "$L" --out "$T/oh" && one_line "index a FIFO" "index.html"

# finding 12: a name escaped once in a message (e\x1bx, not e\\x1bx)
e="$T/e$(printf '\033')x"
mkdir "$e" && printf 'session,attempt\n' >"$e/summary.csv"
run "escaped once" 2 "$H" report "$e" --out "$T/oe" && one_line "escaped once" 'e\\x1bx/summary.csv: line 1'
grep -qF 'e\\x1bx' "$T/err" && bad "escaped twice: $(cat "$T/err")" || ok

# finding 13: a UTF-8 byte order mark (summary and steps), lines up to
# 65,536 bytes, blank lines (at the end, and inside): accepted
cp -r "$L" "$T/lb"
{ printf '\357\273\277'; cat "$L/summary.csv"; printf '\n\n'; } >"$T/lb/summary.csv"
{ printf '\357\273\277'; sed '3{p;s/.*//}' "$L/steps-001.csv"; printf '\r\n \n'; } >"$T/lb/steps-001.csv"
run "BOM, blank lines" 0 "$H" report "$T/lb" --out "$T/ob"
[ ! -s "$T/err" ] && sed -n 2p "$T/ob/attempts.csv" |
    grep -q '^P01,20260131T140509Z-00000001,1,s1,map,1,flag-a,flag,5,5,1.0000,' && ok ||
    bad "BOM, blank lines: $(cat "$T/err") $(sed -n 2p "$T/ob/attempts.csv")"
[ -f "$T/ob/attempt-0001.png" ] && ok || bad "BOM: no picture (the steps file was not read)"
pad=$(head -c 60000 /dev/zero | tr '\0' 'p')
cp -r "$L" "$T/ll"
awk -F, -v OFS=, -v p="$pad" '{ print $0, (NR == 1 ? "note" : p) }' "$L/summary.csv" >"$T/ll/summary.csv"
awk -F, -v OFS=, -v p="$pad" '{ print $0, (NR == 1 ? "note" : p) }' "$L/steps-001.csv" >"$T/ll/steps-001.csv"
run "60 KB lines" 0 "$H" report "$T/ll" --out "$T/ol"
[ -f "$T/ol/attempt-0001.png" ] && ok || bad "60 KB lines: no picture"
awk -F, -v OFS=, -v p="$pad$pad" '{ print $0, (NR == 1 ? "note" : p) }' "$L/summary.csv" >"$T/ll/summary.csv"
run "120 KB line" 2 "$H" report "$T/ll" --out "$T/ol2" && one_line "120 KB line" "line 2: summary .*longer than 65536 bytes"
printf '\357\273\277' >"$T/lb/summary.csv"
run "only a BOM" 2 "$H" report "$T/lb" --out "$T/ob2" && one_line "only a BOM" "no header"

finish cli_harden_report
