#!/bin/sh
# cli_props.sh - `holonomy props`: the printable plan of where real hedges
# and trees stand (docs/headset.md, "Props"). The SVG's elements are counted
# and their page coordinates checked against the room's maths: a trunk on
# every vertex (i*M, j*M) of the C x R grid, at 1000*x/N mm from the floor's
# corner at 1:N; a hedge piece on every boundary cell edge. Then the
# command-line contract: --help, one line and exit 2 for bad input, no file
# written for it, atomic output, an output that is the level refused.
. "$(dirname "$0")/lib.sh"

# Debian's python3 when there (a python3 on PATH may be a slow shim)
PY=python3
[ -x /usr/bin/python3 ] && PY=/usr/bin/python3
command -v "$PY" >/dev/null 2>&1 || echo "cli_props: no python3: the SVG's XML is not parsed"
svg_ok() { # FILE: well-formed XML (when python3 is there)
    command -v "$PY" >/dev/null 2>&1 || return 0
    "$PY" -c 'import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])' "$1" 2>/dev/null
}
count() { grep -c "class=\"$1\"" "$2"; }

# plan NAME C R M N FILE: FILE holds the plan of a C x R room of M m cells at
# 1:N: counts of trees by kind and hedges, the floor's size, and every
# trunk and hedge where the room's maths puts it
plan() {
    name=$1 c=$2 r=$3 m=$4 n=$5 f=$6
    if ! svg_ok "$f"; then bad "$name: not well-formed XML"; return; fi
    if ! grep -q "data-scale=\"$n\"" "$f"; then bad "$name: not at 1:$n"; return; fi
    got=$(printf '%s %s %s %s' "$(count tree-inner "$f")" "$(count tree-side "$f")" \
        "$(count tree-corner "$f")" "$(count hedge "$f")")
    want="$(((c - 1) * (r - 1))) $((2 * (c - 1) + 2 * (r - 1))) 4 $((2 * (c + r)))"
    if [ "$got" != "$want" ]; then bad "$name: inner side corner hedges $got, want $want"; return; fi
    # the independent model: every vertex and boundary edge, page mm from the floor
    awk -v c="$c" -v r="$r" -v m="$m" -v n="$n" '
        function attr(s, k,   i, t) { i = index(s, " " k "=\""); if (!i) return ""
            t = substr(s, i + length(k) + 3); return substr(t, 1, index(t, "\"") - 1) }
        function near(a, b) { return a - b < 0.006 && b - a < 0.006 }
        function die(msg) { print msg; dead = 1; exit 1 }
        /class="floor"/ { fx = attr($0, "x"); fy = attr($0, "y"); fw = attr($0, "width"); fh = attr($0, "height") }
        /class="tree-/ { nt++; x = attr($0, "cx") - fx; y = attr($0, "cy") - fy
            i = x * n / 1000 / m; j = y * n / 1000 / m; ii = int(i + 0.5); jj = int(j + 0.5)
            if (!near(x, ii * m * 1000 / n) || !near(y, jj * m * 1000 / n)) { die("trunk off the grid: " $0) }
            if (ii < 0 || ii > c || jj < 0 || jj > r || seen[ii "," jj]++) { die("trunk twice or outside: " $0) }
            kind = (ii == 0 || ii == c) && (jj == 0 || jj == r) ? "corner" : (ii == 0 || ii == c || jj == 0 || jj == r) ? "side" : "inner"
            if (attr($0, "class") != "tree-" kind) { die("wrong kind: " $0) }
            if (!near(attr($0, "r"), 110 / n)) { die("trunk not 0.22 m across: " $0) } }
        /class="hedge"/ { x1 = (attr($0, "x1") - fx) * n / 1000 / m; y1 = (attr($0, "y1") - fy) * n / 1000 / m
            x2 = (attr($0, "x2") - fx) * n / 1000 / m; y2 = (attr($0, "y2") - fy) * n / 1000 / m
            len = (x1 - x2) * (x1 - x2) + (y1 - y2) * (y1 - y2)
            onb = (near(x1, 0) && near(x2, 0)) || (near(x1, c) && near(x2, c)) || (near(y1, 0) && near(y2, 0)) || (near(y1, r) && near(y2, r))
            if (!near(len, 1) || !onb) { die("hedge not a boundary cell edge: " $0) }
            k = int(x1 + x2 + 0.5) "," int(y1 + y2 + 0.5); if (hs[k]++) { die("hedge twice: " $0) } }
        END { if (dead) exit 1
              if (!near(fw, c * m * 1000 / n) || !near(fh, r * m * 1000 / n)) { die("floor " fw " x " fh) }
              if (nt != (c + 1) * (r + 1)) { die(nt " trunks") } }
    ' "$f" >"$T/why" || { bad "$name: $(cat "$T/why")"; return; }
    ok
}

# --help
run "help" 0 "$H" props --help && grep -q -- '--out FILE.svg' "$T/out" && ok || bad "help text"

# the default: 3 x 3 of 1 m at 1:20 on A4; the 4 inner trees at 1 m and 2 m,
# 50 mm apart from the floor's corner
run "default" 0 "$H" props --out "$T/a.svg" && plan "default 3x3" 3 3 1 20 "$T/a.svg"
grep -q 'width="210mm" height="297mm" viewBox="0 0 210 297"' "$T/a.svg" && grep -q 'A4 portrait' "$T/a.svg" \
    && ok || bad "default page: A4 portrait in mm"
fx=$(sed -n 's/.*class="floor" x="\([0-9.]*\)" y="\([0-9.]*\)".*/\1 \2/p' "$T/a.svg")
inner=$(grep 'class="tree-inner"' "$T/a.svg" | sed 's/.*cx="\([0-9.]*\)" cy="\([0-9.]*\)".*data-m="\([^"]*\)".*/\1 \2 \3/' |
    awk -v f="$fx" 'BEGIN { split(f, o, " ") } { printf "%.2f,%.2f=%s ", $1 - o[1], $2 - o[2], $3 }')
[ "$inner" = "50.00,50.00=1,1 100.00,50.00=2,1 50.00,100.00=1,2 100.00,100.00=2,2 " ] && ok ||
    bad "inner trees of 3x3 at 1:20: $inner"
grep -q '1 m = 50 mm at 1:20' "$T/a.svg" && ok || bad "scale bar text"
grep -q 'data-mm="50.00"' "$T/a.svg" && ok || bad "scale bar 50 mm"

# other rooms and cells; the scale that fits
run "4x5 0.75" 0 "$H" props --room 4x5 --cell 0.75 --out "$T/b.svg" && plan "4x5 0.75" 4 5 0.75 20 "$T/b.svg"
run "5x5 1.5 auto scale" 0 "$H" props --room 5x5 --cell 1.5 --out "$T/c.svg" && plan "5x5 1.5" 5 5 1.5 50 "$T/c.svg"
run "1:15 on A3" 0 "$H" props --scale 1:15 --out "$T/d.svg" && plan "1:15" 3 3 1 15 "$T/d.svg"
grep -q 'A3 portrait' "$T/d.svg" && grep -q 'width="297mm" height="420mm"' "$T/d.svg" && ok || bad "1:15 on A3 portrait"
run "3x4 0.5 at 1:10" 0 "$H" props --room 3x4 --cell 0.5 --scale 1:10 --out "$T/e.svg" &&
    plan "3x4 0.5 1:10" 3 4 0.5 10 "$T/e.svg"
run "tiling named" 0 "$H" props --tiling 4,7 --out "$T/g.svg" && grep -q '{4,7}: room 3 x 3' "$T/g.svg" && ok ||
    bad "tiling named on the plan"

# a fitted play area (core/hol_fit.h: 3.2 x 3.2 m gets 5 x 5 cells of 0.6 m),
# drawn centred on the room: 0.1 m (5 mm at 1:20) beyond it on every side
run "play area" 0 "$H" props --play-area 3.2x3.2 --out "$T/p.svg" && plan "play area" 5 5 0.6 20 "$T/p.svg"
pa=$(awk '/class="floor"/ { match($0, /x="[0-9.]*" y="[0-9.]*"/); split(substr($0, RSTART, RLENGTH), a, "\"")
        fx = a[2]; fy = a[4] }
    /class="play-area"/ { match($0, /x="[0-9.]*" y="[0-9.]*" width="[0-9.]*" height="[0-9.]*"/)
        split(substr($0, RSTART, RLENGTH), b, "\""); printf "%.2f %.2f %.2f %.2f", b[2] - fx, b[4] - fy, b[6], b[8] }' "$T/p.svg")
[ "$pa" = "-5.00 -5.00 160.00 160.00" ] && ok || bad "play area rect: $pa"
run "play area 2x2" 0 "$H" props --play-area 2x2 --out "$T/p2.svg" && plan "play area 2x2" 3 3 0.6 20 "$T/p2.svg"

# a level's room and cell (its lines; the options are its defaults)
printf 'mode explore\nseed 3\nroom 4 3\ncell 0.8\n' >"$T/lv.lvl"
run "level" 0 "$H" props --level "$T/lv.lvl" --out "$T/l.svg" && plan "level 4x3 0.8" 4 3 0.8 20 "$T/l.svg"
grep -q '(level lv)' "$T/l.svg" && ok || bad "level named"
printf 'mode explore\nseed 3\n' >"$T/plain.lvl"
run "level + room" 0 "$H" props --level "$T/plain.lvl" --room 5x3 --out "$T/l2.svg" && plan "level+room" 5 3 1 20 "$T/l2.svg"
run "level + play area" 0 "$H" props --level "$T/plain.lvl" --play-area 2.6x2.6 --out "$T/l3.svg" &&
    plan "level+area" 4 4 0.6 20 "$T/l3.svg"
run "level's own room kept" 0 "$H" props --level "$T/lv.lvl" --play-area 2.6x2.6 --out "$T/l4.svg" &&
    plan "level kept" 4 3 0.8 20 "$T/l4.svg"
run "level room differs" 2 "$H" props --level "$T/lv.lvl" --room 3x3 --out "$T/no.svg" && one_line "level room" "differs"
# a name with markup in it stays well-formed
cp "$T/lv.lvl" "$T/a&b<c>.lvl"
run "markup name" 0 "$H" props --level "$T/a&b<c>.lvl" --out "$T/m.svg" && svg_ok "$T/m.svg" &&
    grep -q '(level a&amp;b&lt;c&gt;)' "$T/m.svg" && ok || bad "markup in a level name"

# bad input: exit 2, one line, no file
for args in "--scale 1:0" "--scale 1:201" "--scale 2:20" "--scale 1:2x" "--room 6x3" "--room 3" \
    "--cell 2" "--cell abc" "--tiling 4,9" "--play-area 0x3" "--play-area 3x" "--play-area x" \
    "--play-area 3.2x30" "--play-area nanx3" "--play-area 3x3 --room 3x3" "--play-area 3x3 --cell 1" \
    "--scale 1:10 --room 5x5 --cell 1.5" "--bogus" "operand" "--out"; do
    # shellcheck disable=SC2086
    run "bad '$args'" 2 "$H" props $args --out "$T/bad.svg" && one_line "bad '$args'" "holonomy props"
    [ -e "$T/bad.svg" ] && { bad "bad '$args' wrote a file"; rm -f "$T/bad.svg"; }
done
run "no --out" 2 "$H" props --room 3x3 && one_line "no --out" "--out FILE.svg is required"
run "too big" 2 "$H" props --scale 1:10 --room 5x5 --cell 1.5 --out "$T/bad.svg" && one_line "too big" "fits no A4 or A3 page"
run "missing level" 2 "$H" props --level "$T/none.lvl" --out "$T/bad.svg" && one_line "missing level" "none.lvl"
printf 'mode nope\n' >"$T/badlv.lvl"
run "bad level" 2 "$H" props --level "$T/badlv.lvl" --out "$T/bad.svg" && one_line "bad level" "line 1"
mkdir "$T/dir"
run "out a folder" 2 "$H" props --out "$T/dir" && one_line "out a folder" "is a directory"
mkfifo "$T/fifo"
run "out a FIFO" 2 "$H" props --out "$T/fifo" && one_line "out a FIFO" "FIFO"
[ ! -e "$T/bad.svg" ] && ok || bad "a refused run wrote a file"

# the output is the level: refused, the level untouched (also through a link)
cp "$T/lv.lvl" "$T/keep.lvl"
run "out is the level" 2 "$H" props --level "$T/lv.lvl" --out "$T/lv.lvl" && one_line "out is level" "which this command reads"
ln -s lv.lvl "$T/link.svg"
run "out links to the level" 2 "$H" props --level "$T/lv.lvl" --out "$T/link.svg" && one_line "link" "which this command reads"
cmp -s "$T/lv.lvl" "$T/keep.lvl" && ok || bad "the level was changed"

# atomic: an existing plan is replaced whole, no temporary file left
mkdir "$T/o" && printf 'old\n' >"$T/o/p.svg"
run "replace" 0 "$H" props --out "$T/o/p.svg" && cmp -s "$T/o/p.svg" "$T/a.svg" && ok || bad "replaced plan differs"
[ "$(ls -A "$T/o")" = "p.svg" ] && ok || bad "left over: $(ls -A "$T/o")"

# the plan the README shows is what the command writes today
R=$(cd "$(dirname "$0")/.." && pwd)
cmp -s "$T/a.svg" "$R/docs/props_3x3.svg" && ok ||
    bad "docs/props_3x3.svg is out of date: build/holonomy props --out docs/props_3x3.svg"

finish cli_props
