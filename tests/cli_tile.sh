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

# ---- tilings {4,Q} (SPEC 7) ----
# every walk of up to 5 steps: the tiles at distance 0..5 and their counts
awk 'BEGIN { split("N E S W", d, " "); n = 1; w[1] = ""; print "-";
  for (len = 1; len <= 5; len++) { m = 0;
    for (i = 1; i <= n; i++) for (k = 1; k <= 4; k++) { m++; v[m] = w[i] d[k]; print v[m] }
    n = m; for (i = 1; i <= n; i++) w[i] = v[i] } }' >"$T/walks"
for qc in "4:1 4 8 12 16 20" "5:1 4 12 28 64 148" "6:1 4 12 32 84 220" \
          "7:1 4 12 36 100 284" "8:1 4 12 36 104 300"; do
  q=${qc%%:*} want=${qc#*:}
  "$H" tile walk --tiling "4,$q" <"$T/walks" >"$T/addr" 2>"$T/err" || bad "{4,$q} walks failed"
  got=$(sort -u "$T/addr" | awk '{ c[$2]++ } END { for (i = 0; i <= 5; i++) printf "%s%d", i ? " " : "", c[i] }')
  [ "$got" = "$want" ] && ok || bad "{4,$q} tiles by distance: $got, want $want"
done
# ---- tile count (SPEC 9): the same counts as every walk of up to 5 steps ----
for qc in "4:1 4 8 12 16 20" "5:1 4 12 28 64 148" "6:1 4 12 32 84 220" \
          "7:1 4 12 36 100 284" "8:1 4 12 36 104 300"; do
  q=${qc%%:*} want=${qc#*:}
  got=$("$H" tile count --radius 5 --tiling "4,$q" </dev/null 2>"$T/err" |
        awk '$1 == NR - 1 { printf "%s%s", (NR > 1 ? " " : ""), $2 } END { if (NR != 6) print " rows " NR }')
  [ "$got" = "$want" ] && ok || bad "tile count {4,$q}: $got, want $want"
done
: >"$T/in"
expect "tile count radius 0" 0 '0 1
' "$H" tile count --radius 0
expect "tile count --radius=3 before count, {4,4}" 0 '0 1
1 4
2 8
3 12
' "$H" tile --radius=3 --tiling 4,4 count
"$H" tile count --radius 12 --tiling 4,8 >"$T/out" 2>"$T/err"; st=$?
[ $st = 0 ] && [ "$(wc -l <"$T/out")" = 13 ] && [ "$(tail -1 "$T/out")" = "12 505656" ] && ok ||
  bad "tile count radius 12 in {4,8}: status $st, $(tail -1 "$T/out")"
for v in 13 -1 x 0x3 "" 1.0 " 3" 3x 012345; do
  expect "tile count --radius '$v'" 2 '' "$H" tile count --radius "$v"
  err_line "radius"
done
expect "tile count without --radius" 2 '' "$H" tile count
err_line "required"
expect "tile count with an argument" 2 '' "$H" tile count --radius 2 extra
err_line "takes no arguments"
expect "--radius on tile walk" 2 '' "$H" tile walk --radius 2
err_line "tile count"
expect "--radius twice" 2 '' "$H" tile count --radius 2 --radius 3
# the option's forms and places, and the default
printf 'NESW\n' >"$T/in"
expect "flat NESW closes" 0 'O 0
' "$H" tile walk --tiling 4,4
expect "--tiling=4,4 before walk" 0 'O 0
' "$H" tile --tiling=4,4 walk
expect "{4,6} NESW" 0 'El 2
' "$H" tile walk --tiling 4,6
expect "default is {4,5}" 0 'E 1
' "$H" tile walk
for v in 4,9 4,3 5,4 x 4, "" "{4,5"; do
  printf '\n' >"$T/in"
  expect "bad --tiling '$v'" 2 '' "$H" tile walk --tiling "$v"
  err_line "tiling"
done
expect "--tiling without a value" 2 '' "$H" tile walk --tiling
"$H" tile walk --room 3x3 </dev/null >/dev/null 2>"$T/err"
[ $? = 2 ] && ok || bad "tile walk takes no --room"
# the reach is 59 letters beside {4,5}'s 60
printf '%059d\n' 0 | tr 0 N >"$T/in"
expect_status "{4,7} walk to the reach" 0 "$H" tile walk --tiling 4,7
printf '%060d\n' 0 | tr 0 N >"$T/in"
expect "{4,7} walk beyond the reach" 2 '' "$H" tile walk --tiling 4,7
err_line "distance 59"
# flat distances are Manhattan distances of the walks' end points
awk 'BEGIN { srand(7); split("N E S W", d, " ");
  for (i = 0; i < 40; i++) { w = ""; n = int(rand() * 14);
    for (k = 0; k < n; k++) w = w d[int(rand() * 4) + 1]; print (w == "" ? "-" : w) } }' >"$T/walks"
"$H" tile walk --tiling 4,4 <"$T/walks" >"$T/addr" || bad "flat walks"
paste -d' ' "$T/walks" "$T/addr" | awk '{ x = 0; y = 0; n = length($1); if ($1 == "-") n = 0
  for (i = 1; i <= n; i++) { c = substr($1, i, 1); if (c == "N") y++; if (c == "S") y--;
    if (c == "E") x++; if (c == "W") x-- }
  X[NR] = x; Y[NR] = y; A[NR] = $2 }
  END { for (i = 1; i < NR; i++) { j = i + 1; dx = X[i] - X[j]; dy = Y[i] - Y[j];
    print A[i], A[j] > "'"$T"'/pairs"; print (dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy) } }' >"$T/want"
"$H" tile dist --tiling 4,4 <"$T/pairs" >"$T/got" || bad "flat dist"
cmp -s "$T/got" "$T/want" && ok || bad "flat distances are not Manhattan distances"
printf 'Nl O\n' >"$T/in"
expect "flat tie between branches" 2 '' "$H" tile dist --tiling 4,4
err_line "reaches Wr"
# Nrr: three of the eight tiles round a vertex: canonical in {4,8}, not in {4,5}
printf 'Nrr O\n' >"$T/in"
expect "an address of {4,8}" 0 '3
' "$H" tile dist --tiling 4,8

finish cli_tile
