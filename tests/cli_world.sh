#!/bin/sh
# cli_world.sh - `holonomy world`: output format, determinism, --check,
# atomic --save, --load (round trip, continuing walks), bad files and bad
# usage (exit 2, one line on stderr, files untouched). $HOLONOMY is the
# binary under test.
. "$(dirname "$0")/lib.sh"

same() { if cmp -s "$2" "$3"; then ok; else bad "$1: $2 and $3 differ"; fi; }
lines() { n=$(wc -l <"$T/out"); if [ "$n" -eq "$2" ]; then ok; else bad "$1: $n lines, want $2"; fi; }

run "help" 0 "$H" world --help
grep -q "ADDRESS BIOME OBJECT ROTATION CONNECTORS" "$T/out" && ok || bad "help lacks the format"

# format and ball sizes (1, 5, 17, 45, 109 tiles within 0..4)
run "radius 0" 0 "$H" world --seed 3 --walk NE --radius 0
lines "radius 0" 1
grep -q '^Nr ' "$T/out" && ok || bad "radius 0: the end tile of NE is Nr, got $(cat "$T/out")"
for r in 1:5 2:17 3:45 4:109 6:597; do
  run "radius ${r%:*}" 0 "$H" world --seed 3 --walk NE --radius "${r%:*}"
  lines "radius ${r%:*}" "${r#*:}"
done
run "default radius" 0 "$H" world --seed 3 --walk NE
lines "default radius" 109
if grep -Evq '^(O|[NESW][flr]*) (meadow|pine|wetland|autumn) (none|grass|flowers|log|creek|spring|pool|rock|mushroom) [0-3] [-cl]{4}$' "$T/out"; then
  bad "format: $(grep -Ev '^(O|[NESW][flr]*) (meadow|pine|wetland|autumn) (none|grass|flowers|log|creek|spring|pool|rock|mushroom) [0-3] [-cl]{4}$' "$T/out" | head -2)"
else ok; fi
# object and connectors agree: logs have exactly one 'l', creeks 2..4 'c'
awk '$3=="log" && gsub(/l/,"l",$5)!=1 {print; bad=1}
     $3=="creek" && gsub(/c/,"c",$5)<2 {print; bad=1}
     $3!="log" && $5 ~ /l/ {print; bad=1}
     END {exit bad}' "$T/out" >"$T/shape" && ok || bad "shapes: $(head -2 "$T/shape")"
# sorted by distance from the end tile: O is one step from Nr
head -1 "$T/out" | grep -q '^Nr ' && ok || bad "first line is not the end tile"

# seeds: decimal (a leading 0 is not octal) or 0x hex
"$H" world --seed 10 >"$T/s10"; "$H" world --seed 010 >"$T/s010"; "$H" world --seed 0xa >"$T/sxa"
same "seed 010 is ten" "$T/s10" "$T/s010"
same "seed 0xa is ten" "$T/s10" "$T/sxa"
run "seed 18446744073709551615" 0 "$H" world --seed 18446744073709551615 --radius 0
run "seed too big" 2 "$H" world --seed 18446744073709551616
one_line "seed too big" "seed"
run "seed 0x" 2 "$H" world --seed 0x
one_line "seed 0x" "seed"

# determinism, and another seed gives another world
"$H" world --seed 42 --walk NWSEENWW --radius 5 >"$T/a"
"$H" world --seed 42 --walk NWSEENWW --radius 5 >"$T/b"
"$H" world --seed 43 --walk NWSEENWW --radius 5 >"$T/c"
same "determinism" "$T/a" "$T/b"
if cmp -s "$T/a" "$T/c"; then bad "seeds 42 and 43 give the same world"; else ok; fi
# a world wide enough to show creeks, logs and all biomes somewhere
"$H" world --seed 1 --radius 8 >"$T/wide"
for o in log creek spring pool rock mushroom flowers grass; do
  grep -q " $o " "$T/wide" && ok || bad "radius 8 of seed 1 shows no $o"
done
for b in meadow pine wetland autumn; do
  grep -q " $b " "$T/wide" && ok || bad "radius 8 of seed 1 shows no $b"
done

run "check" 0 "$H" world --seed 9 --walk NWSSEENWN --check --quiet
[ -s "$T/out" ] && bad "--quiet printed tiles" || ok

# a small store: eviction keeps it under its capacity, constraints hold
W=$(awk 'BEGIN { srand(7); c = 1; r = 1; s = ""; n = 0
  while (n < 1100) { d = int(rand() * 4); nc = c; nr = r
    if (d == 0) nr--; if (d == 1) nc--; if (d == 2) nr++; if (d == 3) nc++
    if (nc < 0 || nc > 2 || nr < 0 || nr > 2) continue
    c = nc; r = nr; s = s substr("NWSE", d + 1, 1); n++ }
  print s }')
run "small store" 0 "$H" world --seed 2 --walk "$W" --capacity 4096 --check --quiet --stats
if awk '$1 == "#" && $2 == "tiles" { ok = $3 < $5 && $5 == 4096 && $9 > 0 } END { exit !ok }' "$T/out"; then ok
else bad "small store: want tiles < capacity 4096 and evictions, got $(cat "$T/out")"; fi

# save, load, continue
run "save" 0 "$H" world --seed 5 --walk NWS --save "$T/w.hw" --quiet
[ -s "$T/w.hw" ] && ok || bad "save wrote nothing"
ls -A "$T" | grep -q 'holonomy-tmp' && bad "save left a temporary file" || ok
"$H" world --seed 5 --walk NWS >"$T/direct"
run "load" 0 "$H" world --load "$T/w.hw" --check
cp "$T/out" "$T/loaded"
same "load prints the saved world" "$T/direct" "$T/loaded"
"$H" world --seed 5 --walk NWSENE >"$T/direct2"
run "load and walk on" 0 "$H" world load "$T/w.hw" --walk ENE
same "a loaded world walks on like the original" "$T/direct2" "$T/out"
run "save subcommand" 0 "$H" world save "$T/w2.hw" --seed 5 --walk NWS --quiet
same "save subcommand writes the same file" "$T/w.hw" "$T/w2.hw"

# bad files: exit 2, one line, the file untouched, no partial output
cp "$T/w.hw" "$T/orig.hw"
head -c 100 "$T/w.hw" >"$T/trunc.hw"
cp "$T/trunc.hw" "$T/trunc.copy"
run "truncated" 2 "$H" world --load "$T/trunc.hw"
one_line "truncated" "truncated"
[ -s "$T/out" ] && bad "truncated: printed output" || ok
same "truncated file untouched" "$T/trunc.hw" "$T/trunc.copy"
run "truncated, save over it" 2 "$H" world --load "$T/trunc.hw" --save "$T/trunc.hw"
same "failed load does not overwrite the file" "$T/trunc.hw" "$T/trunc.copy"
# one changed byte in a record; the version field set to 2
cp "$T/w.hw" "$T/flip.hw"
printf 'X' | dd of="$T/flip.hw" bs=1 seek=200 conv=notrunc 2>/dev/null
cp "$T/w.hw" "$T/v2.hw"
printf '\002' | dd of="$T/v2.hw" bs=1 seek=8 conv=notrunc 2>/dev/null
run "corrupt" 2 "$H" world --load "$T/flip.hw"
one_line "corrupt" "checksum"
run "wrong version" 2 "$H" world --load "$T/v2.hw"
one_line "wrong version" "version 2"
printf 'hello world, not a world\n' >"$T/text.hw"
run "not an image" 2 "$H" world --load "$T/text.hw"
one_line "not an image" "not a holonomy world"
run "missing file" 2 "$H" world --load "$T/nope.hw"
one_line "missing file" "cannot open"
same "original untouched" "$T/w.hw" "$T/orig.hw"
run "missing folder" 2 "$H" world --seed 1 --quiet --save "$T/no/such/dir/w.hw"
one_line "missing folder" "is in a folder that does not exist"

# bad usage
run "radius 9" 2 "$H" world --radius 9
one_line "radius 9" "radius"
run "negative seed" 2 "$H" world --seed -1
one_line "negative seed" "seed"
run "leaves the room" 2 "$H" world --walk NNN
one_line "leaves the room" "step 2"
[ -s "$T/out" ] && bad "leaves the room: printed output" || ok
run "bad step" 2 "$H" world --walk NX
one_line "bad step" "character 2"
run "unknown option" 2 "$H" world --colour
one_line "unknown option" "unknown option"
run "seed and load" 2 "$H" world --seed 1 --load "$T/w.hw"
one_line "seed and load" "exclude"
run "missing value" 2 "$H" world --walk
one_line "missing value" "needs a value"

# one seed parser and one default (1) for every command
run "default seed" 0 "$H" world --walk NE --radius 2
cp "$T/out" "$T/seed_default"
run "seed 1" 0 "$H" world --walk NE --radius 2 --seed 1
same "the default seed is 1" "$T/seed_default" "$T/out"
run "hex seed" 0 "$H" render --seed 0x10 --size 16x12 --out "$T/hex.png"
run "decimal seed" 0 "$H" render --seed 16 --size 16x12 --out "$T/dec.png"
same "render: 0x10 is 16" "$T/hex.png" "$T/dec.png"

# ---- tilings and rooms (SPEC 7) ----
# the ball of radius 2 around the start: 1 + 4 + 12 tiles (8 in the flat grid)
for qn in 4:13 5:17 6:17 7:17 8:17; do
  q=${qn%%:*} n=${qn#*:}
  "$H" world --tiling "4,$q" --radius 2 --check >"$T/out" 2>"$T/err"
  [ $? = 0 ] && ok || bad "world {4,$q}: status ($(cat "$T/err"))"
  [ "$(wc -l <"$T/out")" = "$n" ] && ok || bad "world {4,$q}: $(wc -l <"$T/out") tiles, want $n"
  # every line's address is an address of that tiling
  cut -d ' ' -f 1 "$T/out" | awk '{ print "O", $1 }' >"$T/in"
  "$H" tile dist --tiling "4,$q" <"$T/in" >/dev/null 2>&1 && ok || bad "world {4,$q}: addresses"
done
# a 5x5 room walks farther east than a 3x3 one, and the walk is the room's
run "world 5x5 walk" 0 "$H" world --room 5x5 --walk EE --radius 0 --quiet --check
run "world 3x3 walk off the room" 2 "$H" world --walk EE --radius 0
one_line "world 3x3 walk off the room" "leaves the room"
run "world bad --room" 2 "$H" world --room 6x6
one_line "world bad --room" "room"
run "world bad --tiling" 2 "$H" world --tiling 4,9
one_line "world bad --tiling" "tiling"
# save a {4,7} 4x3 world, load it: the tiling and the room come back
run "world save {4,7}" 0 "$H" world --tiling 4,7 --room 4x3 --walk EN --save "$T/w7" --quiet
run "world load {4,7}" 0 "$H" world --load "$T/w7" --walk W --radius 0
head -1 "$T/out" >"$T/got"
printf 'ENW\n' | "$H" tile walk --tiling 4,7 | cut -d ' ' -f 1 >"$T/want"
[ "$(cut -d ' ' -f 1 "$T/got")" = "$(cat "$T/want")" ] && ok || bad "loaded {4,7} walk ends on $(cat "$T/got"), want $(cat "$T/want")"
run "world load {4,7} walk off its 4x3 room" 2 "$H" world --load "$T/w7" --walk EE --radius 0
run "world load with --tiling" 2 "$H" world --load "$T/w7" --tiling 4,7
one_line "world load with --tiling" "do not go with --load"

finish cli_world
