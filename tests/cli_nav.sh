#!/bin/sh
# cli_nav.sh - `holonomy nav` and `holonomy tour`: output format, walks that
# stay in the room and end on the target (checked with `holonomy tile walk`
# and a room simulation in awk), the exit status contract of SPEC section 4.
# $HOLONOMY is the binary under test.
. "$(dirname "$0")/lib.sh"

# in_room WALK: the walk (letters N/E/S/W, '-' none) stays in the room from (1,1)
in_room() {
  printf '%s\n' "$1" | awk '{ c = 1; r = 1; s = $0; if (s == "-") s = "";
    for (i = 1; i <= length(s); i++) { x = substr(s, i, 1);
      if (x == "N") r--; else if (x == "S") r++; else if (x == "E") c++;
      else if (x == "W") c--; else exit 1;
      if (c < 0 || c > 2 || r < 0 || r > 2) exit 1 } }'
}
# walk_checks Q C R: $T/in holds 'PREFIX TARGET' lines and $T/out 'K WALK'
# lines; writes $T/checks, a line for each: PREFIX TARGET K WALK ROOM GOT,
# ROOM 1 when PREFIX+WALK stays in a C x R room from (C/2, R/2) (as
# in_room_cr), GOT the tile `tile walk --tiling 4,Q` reaches (one awk and
# one tile walk for all the lines, not a few processes a line)
walk_checks() {
  paste -d ' ' "$T/in" "$T/out" >"$T/pairs"
  awk '{ p = $1 == "-" ? "" : $1; w = $4 == "-" ? "" : $4; s = p w
         print s == "" ? "-" : s }' "$T/pairs" >"$T/walks"
  awk -v C="$2" -v R="$3" '{ c = int(C / 2); r = int(R / 2); s = $0; in_r = 1
    if (s == "-") s = ""
    for (i = 1; i <= length(s) && in_r; i++) { x = substr(s, i, 1)
      if (x == "N") r--; else if (x == "S") r++; else if (x == "E") c++
      else if (x == "W") c--; else in_r = 0
      if (c < 0 || c >= C || r < 0 || r >= R) in_r = 0 }
    print in_r }' "$T/walks" >"$T/inroom"
  "$H" tile walk --tiling "4,$1" <"$T/walks" 2>/dev/null | cut -d ' ' -f 1 >"$T/got"
  paste -d ' ' "$T/pairs" "$T/inroom" "$T/got" >"$T/checks"
}
# check_lines: each walk has K steps, PREFIX+WALK stays in the room, and
# ends on TARGET.
check_lines() {
  walk_checks 5 3 3
  while read -r prefix target k walk room got; do
    w=$walk; [ "$w" = "-" ] && w=""
    if [ "${#w}" != "$k" ]; then bad "K $k but walk '$walk' for $prefix $target"; continue; fi
    if [ "$room" != 1 ]; then bad "walk $prefix+$walk leaves the room"; continue; fi
    if [ "$got" != "$target" ]; then bad "$prefix+$walk ends on $got, not $target"; continue; fi
    ok
  done <"$T/checks"
}

# examples; K values checked against brute force in tests/test_nav.c
printf -- '- O\n- N\n- Nr\n- Nff\n' >"$T/in"
"$H" nav <"$T/in" >"$T/out" 2>"$T/err"
[ $? = 0 ] && ok || bad "nav examples status"
cut -d ' ' -f 1 "$T/out" | tr '\n' ' ' >"$T/ks"
[ "$(cat "$T/ks")" = "0 1 2 7 " ] && ok || bad "nav example K: $(cat "$T/ks")"
head -1 "$T/out" | grep -qx '0 -' && ok || bad "K 0 prints '0 -'"
check_lines

# straight ahead from the start: 3, 5 and 8 tiles (brute force: 7 11 17)
printf -- '- Nff\n- Nffff\n- Nfffffff\n' >"$T/in"
"$H" nav <"$T/in" >"$T/out" 2>"$T/err"
k=$(cut -d ' ' -f 1 "$T/out" | tr '\n' ' ')
[ "$k" = "7 11 17 " ] && ok || bad "straight targets: K $k, want 7 11 17"
check_lines

# prefixes, blanks, CRLF, targets near and far (anytime beyond 12 tiles)
printf 'NE Nr\nWSEN Elf\nSN Sff\nEWEW Nlfrf\nNESW Wfffff\n- Nffffrffflffff\n- Sfffffffffffffffff\n' >"$T/in"
"$H" nav --budget 5000 <"$T/in" >"$T/out" 2>"$T/err"
[ $? = 0 ] && ok || bad "nav mixed status"
[ ! -s "$T/err" ] && ok || bad "nav mixed: stderr $(cat "$T/err")"
check_lines
printf ' \tNE\t Nr \r\n' >"$T/in"
expect "blanks and CRLF" 0 '0 -
' "$H" nav

# bad input: exit 2, one stderr line naming the line, earlier lines printed
printf -- '- N\nNN O\n- O\n' >"$T/in"
expect "prefix leaves the room" 2 '1 N
' "$H" nav
err_line "line 2: prefix step 2"
printf -- '- Nrr\n' >"$T/in"
expect "non-canonical target" 2 '' "$H" nav
err_line "line 1: .*canonical.*El"
printf -- 'NX O\n' >"$T/in"
expect "bad step" 2 '' "$H" nav
err_line "line 1: prefix character 2"
printf -- '- Q\n' >"$T/in"
expect "bad address" 2 '' "$H" nav
err_line "line 1: target"
printf -- '-\n' >"$T/in"
expect "missing target" 2 '' "$H" nav
err_line "line 1"
printf -- '- O O\n' >"$T/in"
expect "extra field" 2 '' "$H" nav
err_line "line 1"
printf -- '- O\n\n' >"$T/in"
expect "empty line" 2 '0 -
' "$H" nav
err_line "line 2"
printf -- '- Nfffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff\n' >"$T/in"
expect "beyond reach" 2 '' "$H" nav
err_line "line 1"

# --stats: one stderr line per input line, exact within 12 tiles
printf -- '- Nff\n- Nffffffffffffff\n' >"$T/in"
"$H" nav --stats --budget 3000 <"$T/in" >"$T/out" 2>"$T/err"
[ $? = 0 ] && ok || bad "nav --stats status"
if grep -q '^1 exact 0$' "$T/err" && grep -q '^2 anytime [0-9]*$' "$T/err"; then ok; else bad "nav --stats: $(cat "$T/err")"; fi
check_lines

# options
: >"$T/in"
expect_status "help" 0 "$H" nav --help
grep -q "PREFIX TARGET" "$T/out" && ok || bad "nav --help text"
expect_status "unknown option" 2 "$H" nav --fast
err_line "unknown option"
expect_status "budget 0" 2 "$H" nav --budget 0
err_line "budget"
expect_status "budget missing" 2 "$H" nav --budget
expect_status "budget junk" 2 "$H" nav --budget=12x
expect "empty input" 0 '' "$H" nav --budget=100

# tour: K WALK; the walk ends on the chest, stays in the room, visits keys
: >"$T/in"
"$H" tour - Nf Wr Sf Nff <"$T/in" >"$T/out" 2>"$T/err"
[ $? = 0 ] && ok || bad "tour status"
read -r k walk <"$T/out"
[ "${#walk}" = "$k" ] && ok || bad "tour K $k vs walk $walk"
in_room "$walk" && ok || bad "tour walk leaves the room"
[ "$(printf '%s\n' "$walk" | "$H" tile walk | cut -d ' ' -f 1)" = Nff ] && ok || bad "tour ends off the chest"
# each key is on the walk: some prefix of it ends on the key (every prefix
# through one tile walk)
printf '%s\n' "$walk" | awk '{ print "-"; for (i = 1; i <= length($0); i++) print substr($0, 1, i) }' |
  "$H" tile walk | cut -d ' ' -f 1 >"$T/stops"
for key in Nf Wr Sf; do
  grep -qx "$key" "$T/stops" && ok || bad "tour misses key $key"
done
expect "tour no keys, chest here" 0 '0 -
' "$H" tour NE Nr
expect "tour key here" 0 '1 N
' "$H" tour - O N
expect_status "tour too many keys" 2 "$H" tour - N N N N N N O
err_line "at most 5 keys"
expect_status "tour bad key" 2 "$H" tour - Nrr O
err_line "key 'Nrr'"
expect_status "tour bad chest" 2 "$H" tour - N Q
err_line "chest 'Q'"
expect_status "tour bad prefix" 2 "$H" tour NN O
err_line "prefix step 2"
expect_status "tour missing chest" 2 "$H" tour -
expect_status "tour help" 0 "$H" tour --help
grep -q "PREFIX KEY... CHEST" "$T/out" && ok || bad "tour --help text"

# ---- tilings and rooms (SPEC 7) ----
# in_room_cr WALK C R: the walk stays in a C x R room from (C/2, R/2)
in_room_cr() {
  printf '%s\n' "$1" | awk -v C="$2" -v R="$3" '{ c = int(C / 2); r = int(R / 2); s = $0;
    if (s == "-") s = "";
    for (i = 1; i <= length(s); i++) { x = substr(s, i, 1);
      if (x == "N") r--; else if (x == "S") r++; else if (x == "E") c++;
      else if (x == "W") c--; else exit 1;
      if (c < 0 || c >= C || r < 0 || r >= R) exit 1 } }'
}
# check_lines_in Q C R: as check_lines, in {4,Q} and a C x R room
check_lines_in() {
  walk_checks "$1" "$2" "$3"
  while read -r prefix target k walk room got; do
    w=$walk; [ "$w" = "-" ] && w=""
    if [ "${#w}" != "$k" ]; then bad "{4,$1} $2x$3: K $k but walk '$walk'"; continue; fi
    if [ "$room" != 1 ]; then bad "{4,$1} $2x$3: $prefix+$walk leaves the room"; continue; fi
    if [ "$got" != "$target" ]; then bad "{4,$1} $2x$3: $prefix+$walk ends on $got, not $target"; continue; fi
    ok
  done <"$T/checks"
}
for cfg in "5 5 5" "6 4 4" "7 3 5" "5 5 3" "6 3 3"; do
  set -- $cfg
  printf -- '- O\n- Nff\nEN Wlf\n- Sfrf\nWS Elff\n' >"$T/in"
  "$H" nav --tiling "4,$1" --room "$2x$3" <"$T/in" >"$T/out" 2>"$T/err"
  [ $? = 0 ] && ok || bad "nav {4,$1} $2x$3 status ($(cat "$T/err"))"
  check_lines_in "$1" "$2" "$3"
done
# a bigger room walks less: Nff from the start of 3x3, 4x4, 5x5 in {4,5}
k3=$(printf -- '- Nffff\n' | "$H" nav | cut -d ' ' -f 1)
k5=$(printf -- '- Nffff\n' | "$H" nav --room 5x5 | cut -d ' ' -f 1)
[ "$k5" -lt "$k3" ] && ok || bad "5x5 room: K $k5, 3x3: $k3"
# the flat grid: the room's own tiles only
printf -- '- Nr\n- Er\n' >"$T/in"
"$H" nav --tiling 4,4 <"$T/in" >"$T/out" 2>"$T/err" && ok || bad "flat nav status"
check_lines_in 4 3 3
printf -- '- N\n- Nf\n- O\n' >"$T/in"
expect "flat: a tile off the room" 2 '1 N
' "$H" nav --tiling 4,4
[ "$(cat "$T/out")" = "" ] || true
err_line "no walk inside the room reaches Nf"
printf -- '- Nf\n' >"$T/in"
expect "flat 5x5 reaches two north" 0 '2 NN
' "$H" nav --tiling 4,4 --room 5x5
# {4,8} folds onto the flat grid: straight two ahead is out of a 3x3 room's reach
printf -- '- Nf\n' >"$T/in"
expect "{4,8}: Nf out of reach" 2 '' "$H" nav --tiling 4,8
err_line "no walk inside the room reaches Nf"
# bad options and prefixes
for v in 2x2 6x3 3x 3by3 ""; do
  printf -- '- O\n' >"$T/in"
  expect "bad --room '$v'" 2 '' "$H" nav --room "$v"
  err_line "room"
done
printf -- 'NNN O\n' >"$T/in"
expect "prefix leaves a 5x5 room" 2 '' "$H" nav --room 5x5
err_line "leaves the room"
printf -- '- Nrr\n' >"$T/in"
expect "address of {4,8} in {4,5}" 2 '' "$H" nav
err_line "canonical"
printf -- '- Nrr\n' >"$T/in"
"$H" nav --tiling 4,8 --room 5x5 <"$T/in" >"$T/out" 2>"$T/err" && ok || bad "Nrr in {4,8} 5x5: $(cat "$T/err")"
check_lines_in 8 5 5
# tours
"$H" tour --tiling 4,6 --room 4x4 - Nf Wr Sf Nff >"$T/out" 2>"$T/err" && ok || bad "tour {4,6} 4x4"
w=$(cut -d ' ' -f 2 "$T/out"); [ "$w" = "-" ] && w=""
in_room_cr "$w" 4 4 && ok || bad "tour {4,6} 4x4 leaves the room"
printf '%s\n' "$w" | "$H" tile walk --tiling 4,6 | grep -q '^Nff ' && ok || bad "tour {4,6} 4x4 ends off the chest"
"$H" tour --tiling 4,4 - N Nf O >/dev/null 2>"$T/err"
[ $? = 2 ] && ok || bad "flat tour to a tile off the room: status"
err_line "no walk inside the room"
"$H" tour --room 9x9 - N O >/dev/null 2>"$T/err"
[ $? = 2 ] && ok || bad "tour --room 9x9 status"

finish cli_nav
