#!/bin/sh
# cli_harden_opts.sh - issue 24 (Hardening 3), the option grammar and the
# inputs a command reads, through the binary; each check failed before its
# fix:
# - finding 16: one grammar for every command (cli_opts_next): --opt VALUE
#   and --opt=VALUE, "--" ends the options, -h/--help only as an option
#   (never as a value), a flag takes no value, each option once; ids
#   -1, 1e3, 0x10 are not participants 1, 3, 10;
# - finding 7: no output may name a file that the same command reads
#   (device and inode compared: a link to the input is the input);
# - finding 11: a refused study prints one stderr line, not the order too;
# - findings 9, 10, 13: level files (a repeated key names both lines; a
#   tile beyond the reach less one names its line; a UTF-8 BOM is skipped).
. "$(dirname "$0")/lib.sh"
cd "$T" || exit 1
case $H in /*) ;; *) H=$OLDPWD/$H ;; esac

printf 'mode flag\nflag Nf\n' >fl.lvl
walk_input NE >walk.in
: >in

# --- --opt=VALUE is --opt VALUE, in every command -------------------------
printf 'NE\nNN\n' >in
expect "tile walk --tiling=4,6" 0 "$("$H" tile walk --tiling 4,6 <in)
" "$H" tile walk --tiling=4,6
printf -- '- Nf\n' >in
expect "nav --room=4x4" 0 "$("$H" nav --room 4x4 <in)
" "$H" nav --room=4x4
run "world --seed=7 equals --seed 7" 0 "$H" world --seed=7 --radius=1
cp "$T/out" w1
run "world --seed 7" 0 "$H" world --seed 7 --radius 1
cmp -s w1 "$T/out" && ok || bad "world --seed=7 differs from --seed 7"
printf 'N\nNESW\n' >in
expect "game --tiling=4,6" 0 "$("$H" game fl.lvl --tiling 4,6 <in)
" "$H" game fl.lvl --tiling=4,6
run "render --size=16x16 --target=Nf" 0 "$H" render --size=16x16 --stats --target=Nf
run "replay --size=WxH parses" 2 "$H" replay missing.rec --size=32x32
one_line "replay --size=" "missing.rec"

# --- "--" ends the options: what follows is an operand ---------------------
printf 'mode flag\nflag Nf\n' >./-x.lvl
expect "game -- -x.lvl" 0 "$("$H" game fl.lvl <in)
" "$H" game -- -x.lvl
expect "game -- --help is a file" 2 "" "$H" game -- --help
one_line "game -- --help" "'--help'"
run "tile -- walk" 0 "$H" tile -- walk </dev/null

# --- -h / --help only as an option, never as a value -----------------------
run "world --walk -h" 2 "$H" world --walk -h
one_line "world --walk -h" "character 1"
run "world --seed --help" 2 "$H" world --seed --help
one_line "world --seed --help" "--seed '--help'"
run "world -h" 0 "$H" world -h
grep -q "usage" "$T/out" && ok || bad "world -h prints no usage"
run "render --stats -h" 0 "$H" render --stats -h
run "nav --budget -h is a value" 2 "$H" nav --budget -h </dev/null
one_line "nav --budget -h" "--budget needs a node count"
for c in tile world nav tour render game play replay xr hid report; do
  run "$c --help" 0 "$H" $c --help
done

# --- a flag takes no value; each option once, both spellings ---------------
run "nav --stats=1" 2 "$H" nav --stats=1 </dev/null
one_line "nav --stats=1" "--stats takes no value"
run "world --seed 1 --seed=2" 2 "$H" world --seed 1 --seed=2
one_line "world twice" "--seed is given twice"
run "report --out=a --out b" 2 "$H" report . --out=a --out b
one_line "report twice" "--out is given twice"
run "hid watch --frames=1 --frames 2" 2 "$H" hid watch --frames=1 --frames 2
one_line "hid twice" "--frames is given twice"
run "render --target twice still" 0 "$H" render --size 8x8 --stats --target Nf --target=Ef

# --- participants: a sign, an exponent, hex are not numbers ----------------
cat >s.study <<'EOF'
study s
counterbalance latin
condition a
set mode flag
set flag Nf
condition b
set mode flag
set flag Sf
EOF
for p in -1 1e3 0x10; do
  run "participant $p" 2 "$H" play --study s.study --participant "$p" --frames 1
  one_line "participant $p" "participant"
done

# --- finding 11: a refused study session is one stderr line ----------------
printf 'tiling 4 5\nmode flag\nflag Nf\n' >t5.lvl
printf 'study s\ncondition a\nlevel t5.lvl\n' >t.study
run "study level's tiling differs" 2 "$H" play --study t.study --participant P1 --tiling 4,6 --frames 1
one_line "study tiling" "tiling 4 5"

# --- finding 7: no output names an input ------------------------------------
cp fl.lvl keep.lvl
run "play LEVEL --record LEVEL" 2 "$H" play fl.lvl --record fl.lvl --frames 1
one_line "record over level" "--record 'fl.lvl' is LEVEL 'fl.lvl'"
cmp -s fl.lvl keep.lvl && ok || bad "play --record clobbered the level"
cp walk.in keep.in
run "play --input --record same" 2 "$H" play fl.lvl --input walk.in --record walk.in
one_line "record over input" "--record 'walk.in' is --input 'walk.in'"
cmp -s walk.in keep.in && ok || bad "play --record clobbered the input"
ln -s fl.lvl link.lvl; ln fl.lvl hard.lvl
run "record over a link to the level" 2 "$H" play fl.lvl --record link.lvl --frames 1
one_line "symlink" "is LEVEL 'fl.lvl'"
run "record over a hard link" 2 "$H" play hard.lvl --record fl.lvl --frames 1
one_line "hard link" "is LEVEL 'hard.lvl'"
run "xr --record LEVEL" 2 "$H" xr fl.lvl --record fl.lvl --frames 1
one_line "xr" "is LEVEL 'fl.lvl'"
run "play --record the study" 2 "$H" play --study s.study --participant P1 --record s.study
one_line "study" "is --study 's.study'"
"$H" world --radius 1 --save w.hw >/dev/null 2>&1
cp w.hw keep.hw
run "world --load f --save f" 2 "$H" world --load w.hw --save w.hw
one_line "world" "--save 'w.hw' is --load 'w.hw'"
cmp -s w.hw keep.hw && ok || bad "world --save clobbered --load"
mkdir logs
run "report --out a log folder" 2 "$H" report logs --out logs
one_line "report" "--out 'logs' is the log folder 'logs'"
cmp -s fl.lvl keep.lvl && ok || bad "the level changed"

# --- findings 9, 10, 13: level files ----------------------------------------
printf 'tiling 4 8\nmode flag\nflag Nrr\ntiling 4 5\n' >two.lvl
run "two tiling lines" 2 "$H" game two.lvl </dev/null
one_line "two tilings" "line 4: 'tiling' is given twice; give each key once (line 1)"
printf 'mode flag\nflag Nf\nflag Sf\n' >twoflag.lvl
run "two flag lines" 2 "$H" game twoflag.lvl </dev/null
one_line "two flags" "line 3: 'flag' is given twice"
a=N$(printf 'f%.0s' $(seq 58))
for q in 6 7; do
  printf 'mode flag\ntiling 4 %s\nflag %s\n' $q "$a" >far$q.lvl
  run "59 letters in {4,$q}" 2 "$H" game far$q.lvl </dev/null
  one_line "59 letters {4,$q}" "line 3: '"
done
printf '\357\273\277mode flag\nflag Nf\n' >bom.lvl
expect "level with a BOM" 0 "$("$H" game fl.lvl <in)
" "$H" game bom.lvl
printf '\357\273\277study s\ncondition a\nlevel t5.lvl\n' >bom.study
run "study with a BOM: read (then refused for its level's tiling)" 2 "$H" play --study bom.study \
    --participant P1 --tiling 4,6 --frames 1
one_line "bom study" "tiling 4 5"

# finding 13: a level that cannot start names its objective's line (the
# file's line, not counting the lines --tiling adds)
printf 'mode flag\ntiling 4 8\nseed 2\nflag-distance 2\n' >f8.lvl
run "{4,8} flag-distance 2 seed 2" 2 "$H" game f8.lvl </dev/null
one_line "f8" "f8.lvl: line 4: no walk inside the room reaches an objective"
printf 'mode flag\nseed 2\nflag-distance 2\n' >f8b.lvl
run "{4,8} by --tiling" 2 "$H" game f8b.lvl --tiling 4,8 </dev/null
one_line "f8b" "f8b.lvl: line 3: no walk inside the room reaches an objective"
{ printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nstart 2026-01-31T14:05:09Z\n'
  printf 'version 0.1.0\nlevel f8\n'; sed 's/^/L /' f8.lvl; printf 'end\n'
  walk_input N; } >f8.rec
run "replay names the line" 2 "$H" replay f8.rec
one_line "replay f8" "level 'f8' cannot start: line 4: no walk inside its room"

# --- replay never replays a recording in another geometry ------------------
# (a level without a tiling line was recorded in {4,5}: --tiling 4,6 replayed
# it silently in {4,6})
{ printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nstart 2026-01-31T14:05:09Z\n'
  printf 'version 0.1.0\nlevel f\nL mode flag\nL flag Nf\nend\n'
  walk_input NE; } >p.rec
run "replay" 0 "$H" replay p.rec
run "replay --tiling 4,5: the same" 0 "$H" replay p.rec --tiling 4,5 --room=3x3 --cell 1
run "replay --tiling 4,6" 2 "$H" replay p.rec --tiling 4,6
one_line "replay --tiling" "level 'f' was recorded in {4,5}; --tiling 4,6 would replay it"
run "replay --room 4x4" 2 "$H" replay p.rec --room 4x4
one_line "replay --room" "recorded in a 3x3 room"
run "replay --cell 0.75" 2 "$H" replay p.rec --cell=0.75
one_line "replay --cell" "recorded in cells of 1 m"

finish cli_harden_opts
