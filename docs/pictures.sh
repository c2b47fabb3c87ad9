#!/bin/sh
# pictures.sh - every picture in render/doc (README.md's and docs/*.md's),
# each made by the one command written in cmd_of below, from the built tree.
#
#   sh docs/pictures.sh [OUTDIR]        remake them all into OUTDIR (default
#                                       render/doc); writes only under OUTDIR
#   sh docs/pictures.sh --only NAME ... [OUTDIR]   just NAME.png (repeatable)
#   sh docs/pictures.sh --before ...    also the two "before" pictures: each
#                                       from a build of its older commit (git
#                                       archive into OUTDIR, make, removed)
#   sh docs/pictures.sh --list          every picture's file name, one a line
#   sh docs/pictures.sh --print         every picture's command, not run
#
# It needs build/holonomy and, for three pictures, a render test's program
# (make doc-pictures builds them, then runs this); BUILD names another build
# folder. Every picture renders headless (OSMesa): none needs Xvfb or the
# web build.
# holonomy's PNGs are kept as it writes them (deflate, no further
# optimisation), so a picture remade from the same tree is the same bytes
# (tests/cli_pictures.sh checks that this list covers every PNG in
# render/doc and remakes two of them byte for byte).
#
# In a command: $H is holonomy, $BT the tests' programs' folder, $O the
# picture's file, $S a scratch folder (both under OUTDIR).
set -u
BUILD=${BUILD:-build}
H=$BUILD/holonomy
BT=$BUILD/tests

PICTURES="view_game view_corner view_corner_euclidean view_corner_bare view_hud view_hand
forest_q4 forest_q5 forest_q6 forest_q8 forest_q6_room5x5_cell06
light_q5_dusk light_q5_night light_q6_dusk light_q6_night shadow_q6_night
light8_q5_dusk light8_q5_night
panel_stereo panel_hedge body_hands
shadow_q6_night_before light8_q5_night_before"

# The views the commands share.
CORNER="--walk NW --eye 0.3,1.6,0.3 --yaw -135 --seed 2 --size 400x300"
FOREST="--seed 3 --walk SW --eye 0.15,1.6,2.85 --yaw -30 --size 400x300"
EIGHT="--tiling 4,5 --seed 3 --walk SE --eye 2.8,1.6,2.8 --yaw 45 --pitch -28 --size 400x300 --fireflies off"
EIGHT_L="--lantern O --lantern N --lantern W --lantern Nl --lantern Wr --lantern E --lantern S --lantern Nr"
GAME_REC='holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nstart 2026-01-31T14:05:09Z\nversion 0.1.0\nlevel keys-1\nL mode keys\nL seed 4\nL keys Nf Nlr\nL chest N\nend\n0 f=9 h=1.5,1.6,2.9,-0.2588,0,0,0.9659\n0.1 f=9 h=1.5,1.6,2.9,-0.2588,0,0,0.9659\n'

# lanterns Q: the four lanterns of the corner view in {4,Q} (the tiles the
# room walks SW+N, SW+EN, SW+NE and SW+NNE reach) as --lantern options
# (called by the commands, through eval)
# shellcheck disable=SC2317
lanterns() {
    printf 'SWN\nSWEN\nSWNE\nSWNNE\n' | "$H" tile walk --tiling "4,$1" | cut -d' ' -f1 |
        sed 's/^/--lantern /' | tr '\n' ' '
}

# cmd_of NAME: C, the command that writes NAME's picture to $O (run by
# eval), and B, empty or the commit whose build makes it (a "before"
# picture: the behaviour it shows is gone from today's tree). Fails for a
# name without a command.
cmd_of() {
    B=
    case $1 in
    view_game) # README: a keys level's first frame as replay renders it (docs/rendering.md)
        C="printf '$GAME_REC' >\"\$S/game.rec\" && \$H replay \"\$S/game.rec\" --png-frames 1 --size 800x450 --out-dir \"\$S\" && mv \"\$S/frame-000001.png\" \"\$O\"" ;;
    view_corner) # rendering.md: the corner view across the room's vertices
        C="\$H render $CORNER --pitch -30 --out \"\$O\"" ;;
    view_corner_euclidean) # the same cells as a flat room
        C="\$H render $CORNER --pitch -30 --euclidean --out \"\$O\"" ;;
    view_corner_bare) # floors only, 15 degrees further down: the seams
        C="\$H render $CORNER --pitch -45 --bare --out \"\$O\"" ;;
    view_hud)
        C="\$H render --hud --target Nrfl --seed 2 --size 400x300 --out \"\$O\"" ;;
    view_hand)
        C="\$H render --walk NE --eye 2.4,1.6,0.6 --yaw 135 --target Nrfl --hand 2.2,1.3,0.8 --seed 2 --size 480x360 --out \"\$O\"" ;;
    forest_q[4568]) # README and rendering.md: the same forest in four tilings
        C="\$H render --tiling 4,${1#forest_q} $FOREST --pitch -22 --hud --out \"\$O\"" ;;
    forest_q6_room5x5_cell06)
        C="\$H render --tiling 4,6 --room 5x5 --cell 0.6 --seed 3 --walk SSWW --eye 0.1,1.6,2.9 --yaw -30 --pitch -22 --hud --size 400x300 --out \"\$O\"" ;;
    light_q[56]_dusk | light_q[56]_night) # README and rendering.md#lighting
        q=${1#light_q}
        C="\$H render --tiling 4,${q%%_*} $FOREST --pitch -22 --lighting ${q#*_} \$(lanterns ${q%%_*}) --out \"\$O\"" ;;
    shadow_q6_night) # rendering.md: every lantern's shadows
        C="\$H render --tiling 4,6 $FOREST --pitch -35 --lighting night \$(lanterns 6) --out \"\$O\"" ;;
    shadow_q6_night_before) # each trunk its nearest lantern's shadow
        B=666df01; C="\$H render --tiling 4,6 $FOREST --pitch -35 --lighting night \$(lanterns 6) --out \"\$O\"" ;;
    light8_q5_dusk | light8_q5_night) # rendering.md: eight lanterns round a vertex
        C="\$H render $EIGHT --lighting ${1#light8_q5_} $EIGHT_L --out \"\$O\"" ;;
    light8_q5_night_before) # seams on the tile edges past four lanterns
        B=bb85c07; C="\$H render $EIGHT --lighting night $EIGHT_L --out \"\$O\"" ;;
    panel_stereo) # headset.md: both eyes with the world panel, 800 px an eye
        C="HOL_PANEL_SIZE=800 HOL_PANEL_SHOT=\"\$O\" \$BT/test_render_panel" ;;
    panel_hedge) # headset.md: both eyes 0.9 m from a hedge, the panel in front of it
        C="HOL_DEPTH_SHOT=\"\$O\" \$BT/test_render_depth" ;;
    body_hands) # headset.md: the same with both tracked hands
        C="HOL_BODY_SHOT=\"\$O\" \$BT/test_render_body" ;;
    *) return 1 ;;
    esac
}

usage() { echo "pictures.sh: $1 (usage: [--only NAME]... [--before] [OUTDIR] | --list | --print)" >&2; exit 2; }

ONLY='' BEFORE=0 MODE=make OUT=''
while [ $# -gt 0 ]; do
    case $1 in
    --only) [ $# -ge 2 ] || usage "--only needs a picture's name"
        n=${2%.png}; cmd_of "$n" || usage "no picture '$2' (--list lists them)"
        ONLY="$ONLY $n"; shift ;;
    --before) BEFORE=1 ;;
    --list) MODE=list ;;
    --print) MODE=print ;;
    -*) usage "unknown option '$1'" ;;
    *) [ -z "$OUT" ] || usage "one OUTDIR only"; OUT=$1 ;;
    esac
    shift
done
OUT=${OUT:-render/doc}
[ -n "$ONLY" ] && PICTURES=$ONLY

case $MODE in
list) for n in $PICTURES; do echo "$n.png"; done; exit 0 ;;
print)
    for n in $PICTURES; do
        cmd_of "$n" || { echo "pictures.sh: $n has no command" >&2; exit 1; }
        printf '%s%s: %s\n' "$n.png" "${B:+ (the build of $B)}" "$C"
    done
    exit 0 ;;
esac

# every program the chosen pictures' commands run, built
for n in $PICTURES; do
    cmd_of "$n" || { echo "pictures.sh: $n has no command" >&2; exit 1; }
    case $C in *"\$BT/"*) p=${C##*\$BT/}; p=$BT/${p%% *} ;; *) p=$H ;; esac
    [ -n "$B" ] || [ -x "$p" ] || { echo "pictures.sh: $p is missing (make doc-pictures builds it)" >&2; exit 1; }
done
mkdir -p "$OUT" || exit 1
S=$(mktemp -d "$OUT/.pictures.XXXXXX") || exit 1
trap 'rm -rf "$S"' EXIT
trap 'exit 1' INT TERM HUP

# before_build COMMIT: H set to a holonomy built from COMMIT in $S, or a
# line saying why not (no git history, the build failed); fails then.
before_build() {
    d=$S/build-$1
    if [ -x "$d/build/holonomy" ]; then H=$d/build/holonomy; return 0; fi
    git cat-file -e "$1^{commit}" 2>/dev/null || { echo "  skipped: commit $1 is not in this clone's history"; return 1; }
    if ! { mkdir -p "$d" && git archive "$1" | tar -x -C "$d" &&
        MAKEFLAGS='' make -C "$d" -j2 BUILD=build build/holonomy >"$S/build-$1.log" 2>&1; }; then
        echo "  skipped: the build of $1 failed:"; tail -n 5 "$S/build-$1.log"; return 1
    fi
    H=$d/build/holonomy
}

st=0 made=0
for n in $PICTURES; do
    cmd_of "$n" || { echo "pictures.sh: $n has no command" >&2; exit 1; }
    if [ -n "$B" ] && [ "$BEFORE" = 0 ]; then
        echo "$n.png: skipped: a 'before' picture, made by the build of commit $B (--before builds it)"
        continue
    fi
    echo "$n.png${B:+ (the build of $B)}"
    H0=$H
    if [ -n "$B" ] && ! before_build "$B"; then continue; fi
    O=$S/$n.png
    if (eval "$C") >"$S/log" 2>&1 && [ -s "$O" ]; then
        mv "$O" "$OUT/$n.png" && made=$((made + 1))
    else
        echo "pictures.sh: $n.png failed:" >&2; tail -n 20 "$S/log" >&2; st=1
    fi
    H=$H0
done
echo "pictures.sh: $made picture(s) written to $OUT"
exit $st
