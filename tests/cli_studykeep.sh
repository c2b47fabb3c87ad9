#!/bin/sh
# cli_studykeep.sh - the study's text kept by the session alone (core's
# hol_session: study-HASH.txt written at the session's start as
# study-HASH.txt.live, made durable, renamed; docs/research.md): through
# the binary, play --study keeps the file's exact bytes under its hash's
# name, no .live file stays; a second session on the folder (--append)
# leaves one file, and one cut by hand is made whole again; a replay of the
# recording writes every level-HASH.txt (the recording carries the
# levels' text) but no study-HASH.txt (it carries the study's hash only);
# a session without --log writes nowhere.
. "$(dirname "$0")/lib.sh"
case $H in /*) ;; *) H=$PWD/$H ;; esac
cd "$T" || exit 1
mkdir s
printf 'mode flag\nseed 5\nflag Wrf\n' >s/f.lvl
# CR LF and no last newline: kept as they are
printf 'study keep\r\ncondition a\nlevel f.lvl\nset minimap hud\ncondition b\nlevel f.lvl' >s/k.study
SUM=$(sha256sum s/k.study | cut -d' ' -f1)
# count DIR GLOB: how many names in DIR match GLOB
count() { n=0; for f in "$1"/$2; do [ -e "$f" ] && n=$((n + 1)); done; echo "$n"; }

start_xvfb || { bad "Xvfb did not start"; finish cli_studykeep; exit $?; }
walk_input WNESWNEE >in1
run "play --study" 0 "$H" play --study s/k.study --participant P01 --size 64x48 --log logs \
    --input in1 --record r.rec
[ -f "logs/study-$SUM.txt" ] && cmp -s s/k.study "logs/study-$SUM.txt" && ok ||
    bad "study-$SUM.txt: $(ls logs)"
[ "$(count logs 'study-*')" = 1 ] && ok || bad "study files: $(ls logs)"
[ "$(count logs '*.live')" = 0 ] && ok || bad "live files left: $(ls logs)"
grep -q ",$SUM," logs/summary.csv && ok || bad "summary without the hash: $(cat logs/summary.csv)"

# a second session: the file cut by hand is made whole, still one file
printf 'study ke' >"logs/study-$SUM.txt"
run "play --append" 0 "$H" play --study s/k.study --participant P02 --size 64x48 --log logs \
    --input in1 --append
cmp -s s/k.study "logs/study-$SUM.txt" && ok || bad "not made whole: $(od -c "logs/study-$SUM.txt" | head -3)"
[ "$(count logs 'study-*')" = 1 ] && ok || bad "study files: $(ls logs)"

# replay: the levels' files (from the recording), no study file
run "replay" 0 "$H" replay r.rec --log rl
[ "$(count rl 'study-*')" = 0 ] && ok || bad "replay wrote a study file: $(ls rl)"
[ "$(count logs 'level-*')" -ge 1 ] && ok || bad "level files: $(ls logs)"
for f in logs/level-*; do
  cmp -s "$f" "rl/${f#logs/}" && ok || bad "replay's ${f#logs/} differs"
done
grep -q ",$SUM," rl/summary.csv && ok || bad "replay's summary without the hash"

# no --log: nothing written anywhere
mkdir quiet && cd quiet || exit 1
run "no log" 0 "$H" play --study ../s/k.study --participant P03 --size 64x48 --input ../in1
[ "$(count . '*')" = 0 ] && ok || bad "a session without --log wrote: $(ls)"
cd .. || exit 1
finish cli_studykeep
