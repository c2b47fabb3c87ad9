#!/bin/sh
# cli_codebook.sh - provenance and the codebook (issue 35; docs/logs.md,
# "Provenance and codebook"; docs/report.md, "Outputs"):
# - `--version` names the release, the commit and the build date;
# - every log folder (replay, play, a study's play) holds codebook.csv and
#   provenance.csv (its row naming --version's commit), a study's order.csv
#   (every position, level_sha256 a level-HASH.txt of the folder), and
#   every report codebook.csv, build.csv and a footer naming the build;
# - every column of every CSV written in those folders (parsed from each
#   file's header line) is in the codebook.csv written beside it, and the
#   check fails when one row is taken out of a codebook; each report CSV's
#   header is its codebook rows' columns in order, from the writers' table
#   (no writer has its header as a literal).
. "$(dirname "$0")/lib.sh"
SRC=$(cd "$(dirname "$0")" && pwd)
H=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
cd "$T" || exit 1

"$H" --version >v || bad "--version failed"
grep -Eq '^holonomy [0-9]+\.[0-9]+\.[0-9]+ \(commit [A-Za-z0-9._+:-]+, built ([0-9T:Z-]+|unknown)\)$' v &&
    ok || bad "--version: $(cat v)"
commit=$(sed 's/.*(commit \([^,]*\),.*/\1/' v)

# missing_columns DIR: "FILE COLUMN" for each column of DIR/*.csv's header
# lines that DIR/codebook.csv does not list (steps-001.csv is steps-NNN.csv)
missing_columns() {
    for f in "$1"/*.csv; do
        b=$(basename "$f")
        key=$(printf '%s\n' "$b" | sed 's/-[0-9][0-9]*\.csv$/-NNN.csv/')
        head -1 "$f" | tr -d '\r' | tr ',' '\n' | while IFS= read -r col; do
            grep -q "^$key,$col," "$1/codebook.csv" || echo "$b $col"
        done
    done
}
# check_folder DIR FILE...: codebook.csv and FILE... are there, and every
# column written in DIR is in its codebook
check_folder() {
    d=$1
    shift
    for f in codebook.csv "$@"; do
        [ -s "$d/$f" ] && ok || bad "$d: no $f ($(ls "$d" | tr '\n' ' '))"
    done
    head -1 "$d/codebook.csv" | grep -qx 'file,column,type,unit,allowed,meaning' && ok ||
        bad "$d/codebook.csv header: $(head -1 "$d/codebook.csv")"
    m=$(missing_columns "$d")
    [ -z "$m" ] && ok || bad "$d: columns not in codebook.csv: $m"
}

# ---- a replay: questionnaire answers, no study ------------------------------------
{ cat "$SRC/hostile/replay-ends-on-question/ask.rec"
  echo "2 f=9 b=1 h=1.5,1.6,0.5,0,0,0,1"
  echo "2.5 f=9 h=1.5,1.6,0.5,0,0,0,1"; } >ask.rec
run "replay with answers" 0 "$H" replay ask.rec --log L1
check_folder L1 summary.csv steps-001.csv head-001.csv track-001.csv answers.csv provenance.csv
grep -q "^20261128T164958Z-3850947c,P1,0\.1\.0,$commit," L1/provenance.csv &&
    ok || bad "provenance row: $(cat L1/provenance.csv)"

# ---- a tutorial's replay (version 5): tutorial.csv ----------------------------------
sed '1s/.*/holonomy-rec 5/' "$SRC/onset/tut.rec" >tut.rec
run "replay a tutorial" 0 "$H" replay tut.rec --log Lt
check_folder Lt summary.csv steps-001.csv tutorial.csv provenance.csv

# ---- the check fails when a column is missing from the codebook ------------------
cp -r L1 L1x
grep -v '^answers.csv,kind,' L1/codebook.csv >L1x/codebook.csv
[ "$(missing_columns L1x)" = "answers.csv kind" ] && ok ||
    bad "a missing row not found: $(missing_columns L1x)"

if start_xvfb; then
    # ---- a play: pointing and the minimap key (points.csv, events.csv) -----------
    printf 'mode flag\nseed 7\nflag El\npoint start\n' >start.lvl
    q=0,0.9238795,0,0.3826834 # yaw 135: bearing 225
    { walk_input EN | sed '2s/f=9/f=9 p=10/'
      echo "0.75 f=9 h=2.5,1.6,0.5,$q"
      echo "1.25 f=9 b=1 h=2.5,1.6,0.5,$q"
      echo "1.5 f=9 h=2.5,1.6,0.5,$q"; } >in
    run "play with pointing" 0 "$H" play start.lvl --input in --size 64x48 --log L2 --participant P01
    check_folder L2 summary.csv points.csv events.csv environment.csv provenance.csv

    # ---- a study's play: order.csv -----------------------------------------------
    mkdir -p s/lv
    printf 'mode flag\nseed 5\nflag Wrf\n' >s/lv/flag.lvl
    printf 'mode tutorial\nstages 1\n' >s/tut.lvl
    printf 'study two\npractice tut.lvl\ncondition hud\nlevel lv/flag.lvl\nset minimap hud\n' >s/two.study
    printf 'condition off\nlevel lv/flag.lvl\nset minimap off\n' >>s/two.study
    run "study play" 0 "$H" play --study s/two.study --participant P02 --frames 3 --size 64x48 --log L3
    check_folder L3 summary.csv environment.csv provenance.csv order.csv
    head -1 L3/order.csv | grep -qx 'session,participant,study,position,condition,level,level_file,level_sha256' &&
        ok || bad "order.csv header: $(head -1 L3/order.csv)"
    [ "$(cut -d, -f2-7 L3/order.csv | sed 1d | tr '\n' ' ')" = \
      "P02,two,0,practice,tut,tut.lvl P02,two,1,off,flag,lv/flag.lvl P02,two,2,hud,flag,lv/flag.lvl " ] &&
        ok || bad "order.csv rows: $(cat L3/order.csv)"
    for h in $(cut -d, -f8 L3/order.csv | sed 1d); do
        [ -e "L3/level-$h.txt" ] && ok || bad "order.csv's $h is no level-HASH.txt of the folder"
    done
    # the practice attempt's summary row has order.csv's hash
    [ "$(sed -n 2p L3/summary.csv | cut -d, -f10)" = "$(sed -n 2p L3/order.csv | cut -d, -f8)" ] &&
        ok || bad "summary and order.csv hashes differ"
    dirs="L1 L2 L3"
else
    echo "cli_codebook: no Xvfb, the plays skipped"
    dirs="L1"
fi

# ---- a report of them ------------------------------------------------------------
run "report" 0 "$H" report $dirs --out R
check_folder R attempts.csv conditions.csv stats.csv learning.csv participants.csv build.csv
[ "$(sed -n 2p R/build.csv)" = "holonomy,$(sed 's/^holonomy \([^ ]*\) (commit \([^,]*\), built \(.*\))$/\1,\2,\3/' v)" ] &&
    ok || bad "build.csv: $(cat R/build.csv)"
grep -q "<footer><p>Made by holonomy .*commit $commit" R/index.html && ok || bad "index.html has no footer"
# each of the report's CSVs has its codebook rows' columns as its header,
# in their order (the writers print the header from the codebook's table,
# platform/cli/codebook_table.h), and no writer has it as a literal of its own
for f in R/*.csv; do
    n=${f#R/}
    [ "$n" = codebook.csv ] && continue
    want=$(awk -F, -v n="$n" 'NR > 1 && $1 == n { printf "%s%s", c, $2; c = "," }' R/codebook.csv)
    [ "$(head -n 1 "$f")" = "$want" ] && ok || bad "$n: header $(head -n 1 "$f"), codebook $want"
    lit=$(printf '%s' "$want" | cut -c1-40)
    grep -rqF "\"$lit" "$SRC/../platform/cli/report" && bad "$n: its header a literal in the writers" || ok
done

finish cli_codebook
