#!/bin/sh
# cli_harden.sh - files and command lines that must not hang, bloat or
# echo raw bytes (issue: hardening). Each check failed before its fix:
# a FIFO given to --load blocked in open; a 1 GB sparse file was read
# whole (7 s, 1.1 GB) before "not a world image"; a directory was exit 1;
# a save killed mid-write left its temporary file for ever; --capacity 1
# was raised silently; option values echoed escape bytes raw; a bare
# `holonomy` printed 13 lines. Issue 19: a save replaced device nodes and
# FIFOs with exit 0; stdin readers had no line limit (tile walk < /dev/zero
# grew to 1.2 GB); gamepad scripts were read whole; hid watch --replay never
# ended; repeated options were taken (the last won); --budget 2147483648
# was taken against its help; numbers took blanks, signs and hex; --out and
# --tile-ids could name one file; a level without its objective blamed the
# start tile.
. "$(dirname "$0")/lib.sh"

cd "$T" || exit 1
H=$(cd "$OLDPWD" && cd "$(dirname "$H")" && pwd)/$(basename "$H")

# --- reads: only regular files, header before body ------------------------
mkfifo fifo
run "FIFO load" 2 timeout 10 "$H" world --load fifo
one_line "FIFO load" "not a regular file"
run "directory load" 2 "$H" world --load .
one_line "directory load" "is a directory"
run "/dev/zero load" 2 timeout 10 "$H" world --load /dev/zero
one_line "/dev/zero load" "not a regular file"
truncate -s 1G sparse
# memory and CPU, not wall time (a loaded machine, a sanitizer build)
run "1 GB sparse file" 2 /usr/bin/time -f '%M %U %S' -o mem "$H" world --load sparse
one_line "1 GB sparse file" "not a holonomy world image"
read -r kb cu cs <<EOT
$(tail -n 1 mem)
EOT
[ "${kb:-999999}" -lt 200000 ] && ok || bad "1 GB sparse file: $kb KB resident (the file was read)"
awk "BEGIN { exit !(${cu:-99} + ${cs:-99} < 3) }" && ok || bad "1 GB sparse file took $cu s user, $cs s system"
# a real image made 1 GB long: refused from its header, before the rest
run "save" 0 "$H" world --seed 3 --walk NE --quiet --save w.img
cp w.img long.img && truncate -s 1G long.img
run "1 GB world image" 2 "$H" world --load long.img --quiet
one_line "1 GB world image" "but the header promises"
run "the image itself" 0 "$H" world --load w.img --quiet
# the other readers of files: levels, descriptors, recordings
printf 'mode flag\n' >/dev/null
run "game FIFO" 2 timeout 10 "$H" game fifo
one_line "game FIFO" "not a regular file"
run "hid parse directory" 2 "$H" hid parse .
one_line "hid parse directory" "is a directory"
run "replay FIFO" 2 timeout 10 "$H" replay fifo
one_line "replay FIFO" "not a regular file"

# --- stdin readers: a line limit, streamed (tile walk < /dev/zero grew to
# 1.2 GB in 10 s; a 1 GB line of N was refused after 14 s at 1 GB) ---------
printf 'mode flag\nflag Nr\n' >flag.lvl
for c in "tile walk" "tile dist" "nav" "game flag.lvl"; do
  run "$c < /dev/zero" 2 /usr/bin/time -f '%M' -o mem timeout 5 "$H" $c </dev/zero
  one_line "$c < /dev/zero" "line 1: longer than 1048576 bytes"
  kb=$(tail -n 1 mem)
  [ "${kb:-999999}" -lt 200000 ] && ok || bad "$c < /dev/zero: $kb KB resident"
done
# a good line is answered, then the long one is refused naming its line
{ printf 'NE\n'; head -c 3000000 /dev/zero | tr '\0' N; } >long.txt
run "tile walk: a long second line" 2 timeout 5 "$H" tile walk <long.txt
one_line "tile walk: a long second line" "line 2: longer than 1048576 bytes"
[ "$(cat "$T/out")" = "Nr 2" ] && ok || bad "the first line was not answered: $(cat "$T/out")"
# answers stream out as lines come in (a program can talk to it line by line)
# (no clock: the second line is written only once the first answer has
# arrived, or after 30 s without it; a tool that waits for the input's end
# answers only then, and `seen` is never written)
rm -f t1 seen
{ echo NE; i=0; while [ ! -s t1 ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
  [ -s t1 ] && echo yes >seen; echo N; } |
  "$H" tile walk | { read -r first; echo "$first" >t1; cat >/dev/null; }
[ "$(cat t1)" = "Nr 2" ] && [ -s seen ] && ok ||
  bad "the first answer waited for the input's end: $(cat t1)"
# gamepad scripts streamed and bounded too (read whole up to 64 MiB before)
truncate -s 1G sparse.pad
run "1 GB sparse pad script" 2 /usr/bin/time -f '%M' -o mem timeout 5 "$H" hid watch --replay sparse.pad
one_line "1 GB sparse pad script" "line 1: gamepad script 'sparse.pad': longer than 12352 bytes"
[ "$(tail -n 1 mem)" -lt 200000 ] && ok || bad "sparse pad script: $(tail -n 1 mem) KB"
run "sparse pad script in play" 2 timeout 5 "$H" play --gamepad-replay sparse.pad --frames 1
one_line "sparse pad script in play" "longer than 12352 bytes"
rm -f sparse.pad

# --- a level without its objective names what is missing (it said "an
# objective lies on the tile where the level begins": the flag was left on O)
for l in "flag|mode flag|line 1: mode flag needs a 'flag' or 'flag-distance' line" \
         "keys|# keys\nmode keys\nchest Nr|line 2: mode keys needs a 'keys' or 'keys-distance' line" \
         "chest|mode keys\nkeys-distance 2 1 3|line 1: mode keys needs a 'chest' or 'chest-distance' line"; do
  n=${l%%|*} rest=${l#*|}; text=${rest%%|*} msg=${rest#*|}
  printf "$text\n" >"miss-$n.lvl"
  run "level without its $n" 2 "$H" game "miss-$n.lvl" </dev/null
  one_line "level without its $n" "$msg"
done

# --- temporary files: owned names, cleaned by the next save --------------
# a leftover of a killed save of w.img (writer gone), one of another target
# whose writer is gone too (removed by any save into the folder since issue
# 39: a killed `replay --wav` or `report` left its file for good) and
# unrelated files
sh -c 'exit 0' & dead=$!; wait $dead
touch ".w.img.holonomy-tmp.$dead.AbC123" ".x.img.holonomy-tmp.$dead.AbC123" "w.img.tmpQwErTy"
touch ".w.img.holonomy-tmp.$$.LiVe12"   # this shell still runs: not a leftover
run "save again" 0 "$H" world --seed 3 --walk NE --quiet --save w.img
[ ! -e ".w.img.holonomy-tmp.$dead.AbC123" ] && ok || bad "the dead writer's temporary file is still there"
[ ! -e ".x.img.holonomy-tmp.$dead.AbC123" ] && ok || bad "another target's leftover is still there"
[ -e "w.img.tmpQwErTy" ] && ok || bad "an unrelated file was removed"
[ -e ".w.img.holonomy-tmp.$$.LiVe12" ] && ok || bad "a running writer's temporary file was removed"

# --- outputs: a regular file or a new name in an existing folder, else
# exit 2 with one line before any work (a save replaced a device node and a
# FIFO with exit 0; run as root against /dev/null it replaced /dev/null) ----
mkdir outs && cd outs || exit 1
mkfifo fifo; mkdir dir; ln -s fifo lfifo; ln -s nowhere dangling; touch plain
mknod null c 1 3 2>/dev/null || [ "$(id -u)" != 0 ] || bad "mknod failed as root"
# target WHAT: a special file, and the words that name it
for target in "fifo:is a FIFO" "dir:is a directory" "lfifo:is a symbolic link to a FIFO" \
              "dangling:is a symbolic link to nothing" "null:is a character device" \
              "no/such:is in a folder that does not exist" "plain/x:is under a file" \
              "dir/:names a folder"; do
  f=${target%%:*} why=${target#*:}
  [ "$f" = null ] && [ ! -e null ] && continue # not root: no device node
  run "world --save $f" 2 "$H" world --seed 3 --walk NE --save "$f"
  one_line "world --save $f" "--save '$f' $why.*; an output is a regular file or a new name"
  [ -s "$T/out" ] && bad "world --save $f: worked before refusing (tiles printed)" || ok
  run "world save $f" 2 "$H" world save "$f" --quiet
  run "render --out $f" 2 "$H" render --bare --size 8x8 --out "$f"
  one_line "render --out $f" "--out '$f' $why"
  run "render --tile-ids $f" 2 "$H" render --bare --size 8x8 --stats --tile-ids "$f"
  one_line "render --tile-ids $f" "--tile-ids '$f' $why"
  [ -s "$T/out" ] && bad "render --tile-ids $f: rendered before refusing" || ok
done
[ -p fifo ] && [ -d dir ] && [ -L lfifo ] && [ -L dangling ] && ok || bad "a special file was replaced"
[ ! -e null ] || [ -c null ] && ok || bad "the device node was replaced"
[ -z "$(ls -A dir)" ] && ok || bad "something was written into dir"
# the good targets still work: a new name, a regular file, a link to one
ln -s plain lplain
run "world --save new" 0 "$H" world --seed 3 --quiet --save new.img
run "world --save plain" 0 "$H" world --seed 3 --quiet --save plain
run "world --save lplain" 0 "$H" world --seed 3 --quiet --save lplain
run "render --out new" 0 "$H" render --bare --size 8x8 --out new.png --tile-ids ids.txt
[ -s new.png ] && [ -s ids.txt ] && ok || bad "render wrote nothing"
# one file for two outputs: the second would replace the first
run "render --out F --tile-ids F" 2 "$H" render --bare --size 8x8 --out same --tile-ids same
one_line "render --out F --tile-ids F" "name the same file"
ln -s new.png lnew
run "render --out F --tile-ids link to F" 2 "$H" render --bare --size 8x8 --out new.png --tile-ids lnew
[ ! -e same ] && ok || bad "render --out F --tile-ids F wrote F"
# a folder this user cannot write in is refused at the start too (as root:
# run as nobody; the copy of the binary is theirs to run)
mkdir ro && chmod 555 ro && chmod 755 "$T" . && cp "$H" hcopy && chmod 755 hcopy
if [ "$(id -u)" = 0 ]; then as_user="setpriv --reuid=65534 --regid=65534 --clear-groups"; else as_user=""; fi
run "world --save in a read-only folder" 2 $as_user ./hcopy world --seed 3 --save ro/w.img
one_line "read-only folder" "is in a folder this user cannot write"
[ -s "$T/out" ] && bad "read-only folder: worked before refusing" || ok
# replay's frames: every frame's file is checked before the replay runs
{ printf 'holonomy-rec 1\nlevel lv\nL mode explore\nend\n'; walk_input NESW; } >rec.txt
mkdir frames && mkfifo frames/frame-000002.png
run "replay --out-dir with a FIFO frame" 2 timeout 20 "$H" replay rec.txt --png-frames 0,2 --out-dir frames
one_line "replay --out-dir" "frame-000002.png' is a FIFO"
[ -p frames/frame-000002.png ] && [ ! -e frames/frame-000000.png ] && ok || bad "replay wrote frames or replaced the FIFO"
cd "$T" || exit 1

# --- --capacity bounds ------------------------------------------------------
run "capacity 1" 2 "$H" world --capacity 1 --quiet
one_line "capacity 1" "below the minimum of 4096 tiles for radius 4"
run "capacity 4095" 2 "$H" world --capacity 4095 --quiet
one_line "capacity 4095" "below the minimum"
run "capacity 4096" 0 "$H" world --capacity 4096 --quiet --walk NE
run "capacity 2^30" 2 "$H" world --capacity 1073741824 --quiet
one_line "capacity 2^30" "not a number of tiles 1..268435456"

# --- a repeated option is a usage error (the last one won), in every
# command; the options documented as repeatable still repeat -------------
mkfifo rep.fifo # a command that got past its options would block on it
for c in "world --seed 1 --seed 2" "world --save=a.img --save b.img" "world save a.img --save b.img" \
         "world load a.img --load b.img" "nav --stats --stats" "tile walk --tiling 4,5 --tiling=4,6" \
         "nav --budget 9 --budget=10" "tour --stats --stats - O" "render --size 8x8 --size 9x9 --stats" \
         "play --seed 1 --seed 2 --input rep.fifo" "replay rep.fifo --log . --log ." \
         "hid watch --frames 1 --frames 2" "xr --frames 1 --frames 2 --input rep.fifo" \
         "game rep.fifo --tiling 4,5 --tiling=4,6"; do
  opt=$(echo "$c" | awk '{for (i = 2; i <= NF; i++) if ($i ~ /^--/) { sub(/=.*/, "", $i); print $i; exit }}')
  run "repeated: $c" 2 timeout 10 "$H" $c </dev/null
  one_line "repeated: $c" "$opt is given twice; give each option once"
done
run "render --target twice" 0 "$H" render --bare --size 4x4 --stats --target Nr --target El

# --- every documented bound is enforced (--budget 2147483648 was taken
# although the help says 262144 at most) ---------------------------------
for c in "nav --budget 262145" "nav --budget 2147483648" "tour --budget 262145 - O"; do
  run "bound: $c" 2 "$H" $c </dev/null
  one_line "bound: $c" "--budget needs a node count 1..262144"
done
echo '- Nr' | "$H" nav --budget 262144 >/dev/null && ok || bad "nav --budget 262144 refused"
run "tour --budget 262144" 0 "$H" tour --budget 262144 - Nr
for c in "--size 8193x1" "--size 0x4" "--fov 9.9" "--fov 170.1" "--pitch 90.5" "--frames 1001" \
         "--frames 0" "--stereo 0.21" "--stereo 0" "--eye 1.5,0.005,1.5" "--eye 1.5,100.5,1.5" \
         "--hand 1.5,1,1.52" "--hand 3.6,1,1.5"; do
  run "render bound: $c" 2 "$H" render --bare --stats $c
done
run "render at its bounds" 0 "$H" render --bare --stats --size 1x1 --fov 10 --pitch -90 --frames 2 \
  --eye 1.5,0.02,1.5 --hand 1.5,1,1.56
run "render at its other bounds" 0 "$H" render --bare --stats --size 2x1 --fov 170 --pitch 90 \
  --stereo 0.2 --eye 1.5,100,1.5 --hand 3.49,1,1.5
for c in "--radius 9" "--capacity 268435457"; do
  run "world bound: $c" 2 "$H" world --quiet $c
done
run "tour: 5 keys" 0 "$H" tour - Nr El Sr Wl Nl Er
run "tour: 6 keys" 2 "$H" tour - Nr El Sr Wl Nl Er Sl

# --- hid watch --replay ends at the end of its script (it never ended when
# the script did not unplug its pad) ---------------------------------------
printf '0 plug 0001:0002 05 01 09 05 a1 01 15 00 25 01 75 01 95 08 05 09 19 01 29 08 81 02 c0\n0.05 report 01\n' >held.pad
run "watch a script that keeps its pad" 0 timeout 10 "$H" hid watch --replay held.pad
[ "$(tail -n 1 "$T/out")" = "# end of script" ] && [ "$(sed -n 3p "$T/out")" = "buttons 0x01 move 0.000 0.000 turn 0.000 0.000" ] &&
  ok || bad "watch held.pad: $(cat "$T/out")"

# --- option values and messages ---------------------------------------------
esc=$(printf '\033[31mX')
run "escape bytes in --seed" 2 "$H" world --seed "$esc"
one_line "escape bytes" '\\x1b\[31mX'
if LC_ALL=C grep -q "$(printf '\033')" "$T/err"; then bad "a raw escape byte on stderr"; else ok; fi
run "escape bytes in a path" 2 "$H" world --load "$(printf 'a\033b\nc')"
if [ "$(wc -l <"$T/err")" -eq 1 ] && ! LC_ALL=C grep -q "$(printf '\033')" "$T/err"; then ok; else bad "path: $(od -c "$T/err" | head -3)"; fi
# numbers are plain decimals: no blanks, signs on counts, hex or inf (strtol
# and strtod took ' 2', '+8', '0x1p3')
for v in "--size|+8x8" "--size| 8x8" "--frames| 2" "--frames|+2" "--yaw|0x1p3" "--yaw| 5" \
         "--pitch|nan" "--yaw|inf" "--eye|1.5, 1.6,1.5" "--fov|1e" "--fov|90x"; do
  run "render ${v%%|*} '${v#*|}'" 2 "$H" render --bare --stats "${v%%|*}" "${v#*|}"
  one_line "render ${v%%|*} '${v#*|}'" "${v%%|*} '"
done
run "render --yaw -0.5e-1 --eye 1.5,1e0,1.5" 0 "$H" render --bare --stats --yaw -0.5e-1 --eye 1.5,1e0,1.5
run "seed with a leading blank" 2 "$H" world --seed " 5" --quiet
run "seed with a second 0x" 2 "$H" world --seed 0x0x5 --quiet
run "count with a newline" 2 "$H" world --capacity "$(printf '\n8192')" --quiet
run "bare holonomy" 2 "$H"
one_line "bare holonomy" "see 'holonomy --help'"
for c in tile world nav tour render play replay game hid xr; do
  run "$c: unknown option" 2 "$H" $c --no-such-option
  one_line "$c: unknown option" "--help"
done

finish cli_harden
