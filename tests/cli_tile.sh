#!/bin/sh
# cli_tile.sh - `holonomy tile walk|dist`, --help, --version and the exit
# status contract of SPEC section 4. $HOLONOMY is the binary under test.
. "$(dirname "$0")/lib.sh"

printf 'NESW\nNE\n\n-\nNWSEN\nNENWNWSWWS\nEEENNNWWWSSS\n' >"$T/in"
expect "walk examples" 0 'E 1
Nr 2
O 0
O 0
O 0
Nfrlrffl 8
Efflfflfflff 12
' "$H" tile walk

printf 'NE\nNX\nN\n' >"$T/in"
expect "walk bad step" 2 'Nr 2
' "$H" tile walk
err_line "line 2"

printf 'NE\r\n' >"$T/in"
expect "walk CRLF" 0 'Nr 2
' "$H" tile walk

# 61 steps north leave the reach of tile words
printf '%061d\n' 0 | tr 0 N >"$T/in"
expect "walk beyond reach" 2 '' "$H" tile walk
err_line "line 1"

printf 'Nr El\nO Nlffl\nO O\nN  S\nWrfr O\n' >"$T/in"
expect "dist examples" 0 '1
5
0
2
4
' "$H" tile dist

for input in 'Nrr O' 'O' 'O O O' 'Nq O' 'Nlfl O' 'x y'; do
  printf 'O N\n%s\n' "$input" >"$T/in"
  expect "dist bad '$input'" 2 '1
' "$H" tile dist
  err_line "line 2"
done
printf 'Nrr O\n' >"$T/in"
"$H" tile dist <"$T/in" 2>"$T/err" >/dev/null
grep -q "reaches El" "$T/err" && ok || bad "non-canonical message names the canonical address"

# walk -> address -> distance from O agrees
printf 'NNEESSWWN\nWWSENNESW\nSSSSWWNNNEEE\n' >"$T/in"
"$H" tile walk <"$T/in" >"$T/addr" || bad "walk failed"
awk '{print "O", $1}' "$T/addr" >"$T/in"
"$H" tile dist <"$T/in" >"$T/d" || bad "dist failed"
if [ "$(awk '{print $2}' "$T/addr")" = "$(cat "$T/d")" ]; then ok; else bad "walk distance != dist from O"; fi

: >"$T/in"
expect "help" 0 "$("$H" --help)
" "$H" --help
"$H" --help | grep -q "usage: holonomy" && ok || bad "--help text"
"$H" tile --help | grep -q "tile walk" && ok || bad "tile --help text"
"$H" --version | grep -q "^holonomy [0-9]" && ok || bad "--version"
"$H" nosuch >/dev/null 2>"$T/err"; [ $? = 2 ] && ok || bad "unknown command status"
err_line "unknown command"
"$H" >/dev/null 2>&1; [ $? = 2 ] && ok || bad "no command status"
"$H" tile >/dev/null 2>&1; [ $? = 2 ] && ok || bad "tile without subcommand"
"$H" tile walk extra >/dev/null 2>&1; [ $? = 2 ] && ok || bad "tile walk with arguments"

finish cli_tile
