#!/bin/sh
# pictures.sh - every picture that README.md and docs/*.md show from
# render/doc and docs/, each made by the one command written in cmd_of
# below, from the built tree.
#
#   sh docs/pictures.sh [OUTDIR]        remake them all: each into its own
#                                       folder (render/doc or docs), or all
#                                       into OUTDIR; writes only there
#   sh docs/pictures.sh --only NAME ... [OUTDIR]   just NAME.png (repeatable;
#                                       NAME may be a pattern: 'forest_*')
#   sh docs/pictures.sh --before ...    also the two "before" pictures: each
#                                       from a build of its older commit (git
#                                       archive into the output folder, make,
#                                       removed)
#   sh docs/pictures.sh --list          every picture's file, one a line
#   sh docs/pictures.sh --print         every picture's command, not run
#
# It needs build/holonomy and, for some pictures, a test's program (make
# doc-pictures builds them, then runs this); BUILD names another build
# folder. Most pictures render headless (OSMesa). Three need more, and are
# skipped with a line saying what when it is missing: the worksheets are
# drawn by a browser (chromium, headless; CHROMIUM names another), and the
# headset's eyes are make xr-test's (the OpenXR chroot's Monado), which
# it keeps in BUILD/xr-test: make xr-test first. None needs Xvfb.
# holonomy's PNGs are kept as it writes them (deflate, no further
# optimisation), so a picture remade from the same tree is the same bytes
# (tests/cli_pictures.sh checks that this list covers every PNG in
# render/doc and docs/ and remakes three of them byte for byte). The
# browser's pictures are its own PNGs: the same bytes from the same
# chromium and fonts.
#
# In a command: $H is holonomy, $BT the tests' programs' folder, $X the
# folder where make xr-test keeps its lighting eyes, $CHROMIUM the browser,
# $O the picture's file, $S a scratch folder (both under the output
# folder, absolute).
set -u
BUILD=${BUILD:-build}
H=$BUILD/holonomy
BT=$BUILD/tests
X=$BUILD/xr-test/lighting
CHROMIUM=${CHROMIUM:-chromium}

PICTURES="view_game view_corner view_corner_euclidean view_corner_bare view_hud view_hand
forest_q4 forest_q5 forest_q6 forest_q8 forest_q6_room5x5_cell06
light_q5_dusk light_q5_night light_q6_dusk light_q6_night shadow_q6_night
light8_q5_dusk light8_q5_night
panel_stereo panel_hedge body_hands
shadow_q6_night_before light8_q5_night_before
teaching_de teaching_lesson_de teaching_walk_de teaching_sheet teaching_sheet_de
font_sheet headset_night_eyes"

# The views the commands share.
CORNER="--walk NW --eye 0.3,1.6,0.3 --yaw -135 --seed 2 --size 400x300"
FOREST="--seed 3 --walk SW --eye 0.15,1.6,2.85 --yaw -30 --size 400x300"
EIGHT="--tiling 4,5 --seed 3 --walk SE --eye 2.8,1.6,2.8 --yaw 45 --pitch -28 --size 400x300 --fireflies off"
EIGHT_L="--lantern O --lantern N --lantern W --lantern Nl --lantern Wr --lantern E --lantern S --lantern Nr"
GAME_REC='holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nstart 2026-01-31T14:05:09Z\nversion 0.1.0\nlevel keys-1\nL mode keys\nL seed 4\nL keys Nf Nlr\nL chest N\nend\n0 f=9 h=1.5,1.6,2.9,-0.2588,0,0,0.9659\n0.1 f=9 h=1.5,1.6,2.9,-0.2588,0,0,0.9659\n'

TUT_REC='holonomy-rec 1\nlevel tutorial\nL mode tutorial\nend\n0 f=9 d=keyboard h=1.5,1.6,1.5,0,0,0,1\n'
L2_REC='holonomy-rec 1\nlevel lesson-2\nL lesson 2\nend\n0 f=9 d=keyboard h=1.5,1.6,1.5,0,0,0,1\n0.5 f=9 d=keyboard p=1 h=1.5,1.6,1.5,0,0,0,1\n1 f=9 d=keyboard h=1.5,1.6,1.5,0,0,0,1\n'
# The four lanterns of the corner view in {4,Q}: the tiles the room walks
# SW+N, SW+EN, SW+NE and SW+NNE reach (tests/cli_pictures.sh checks them
# against holonomy tile walk, whose first column they are).
LANTERNS_5="--lantern Wl --lantern O --lantern W --lantern Wfl"
LANTERNS_6="--lantern Srr --lantern O --lantern Wl --lantern Srrfr"
# a worksheet's SVG as a browser draws it at A4 (96 dpi), its own profile
SHEET_PNG="\"\$CHROMIUM\" --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir=\"\$S/chromium\" --window-size=794,1123 --screenshot=\"\$O\""

# cmd_of NAME: C, the command that writes NAME's picture to $O (run by
# eval); D, the picture's folder; B, empty or the commit whose build makes
# it (a "before" picture: the behaviour it shows is gone from today's
# tree); and Q, empty or a test (run by eval) of what the command needs
# beyond the build, with W, what Q found missing. Fails for a name
# without a command.
cmd_of() {
    B='' D=render/doc Q='' W=''
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
    light_q[56]_dusk | light_q[56]_night) # README and lighting.md
        q=${1#light_q}
        case $q in 5_*) l=$LANTERNS_5 ;; *) l=$LANTERNS_6 ;; esac
        C="\$H render --tiling 4,${q%%_*} $FOREST --pitch -22 --lighting ${q#*_} $l --out \"\$O\"" ;;
    shadow_q6_night) # rendering.md: every lantern's shadows
        C="\$H render --tiling 4,6 $FOREST --pitch -35 --lighting night $LANTERNS_6 --out \"\$O\"" ;;
    shadow_q6_night_before) # each trunk its nearest lantern's shadow
        B=666df01; C="\$H render --tiling 4,6 $FOREST --pitch -35 --lighting night $LANTERNS_6 --out \"\$O\"" ;;
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
    teaching_de) # teaching.md: the German tutorial's first frame
        D=docs; C="printf '$TUT_REC' >\"\$S/tut.rec\" && \$H replay \"\$S/tut.rec\" --lang de --png-frames 0 --out-dir \"\$S\" --size 640x480 && mv \"\$S/frame-000000.png\" \"\$O\"" ;;
    teaching_lesson_de | teaching_walk_de) # teaching.md: lesson 2 in German, its question (frame 0) and walk (2)
        f=0; [ "$1" = teaching_walk_de ] && f=2
        D=docs; C="printf '$L2_REC' >\"\$S/l2.rec\" && \$H replay \"\$S/l2.rec\" --lang de --png-frames $f --out-dir \"\$S\" --size 640x480 && mv \"\$S/frame-00000$f.png\" \"\$O\"" ;;
    teaching_sheet | teaching_sheet_de) # teaching.md: lesson 2's worksheet in {4,5}, English and German
        l=en; [ "$1" = teaching_sheet_de ] && l=de
        D=docs Q="command -v \"\$CHROMIUM\" >/dev/null" W="needs a browser to draw the sheet's SVG ($CHROMIUM, headless; CHROMIUM names another)"
        C="\$H lesson sheet 2 --lang $l --out \"\$S/sheet.svg\" && $SHEET_PNG \"file://\$S/sheet.svg\"" ;;
    font_sheet) # rendering.md: the text face's sample sheet, drawn by the CPU rasteriser
        D=docs; C="HOL_FONT_SHEET=\"\$O\" \$BT/test_font" ;;
    headset_night_eyes) # headset.md: both eyes at night in {4,5} read back from Monado's swapchain
        D=docs Q="[ -s \"\$X/q5_night_shown_eye0.png\" ] && [ -s \"\$X/q5_night_shown_eye1.png\" ]"
        W="needs make xr-test's night eyes in $X (make xr-test, in its OpenXR chroot, keeps them)"
        C="\$BT/png_probe \"\$X/q5_night_shown_eye0.png\" --beside \"\$X/q5_night_shown_eye1.png\" \"\$O\"" ;;
    *) return 1 ;;
    esac
}

usage() { echo "pictures.sh: $1 (usage: [--only NAME]... [--before] [OUTDIR] | --list | --print)" >&2; exit 2; }

ONLY='' BEFORE=0 MODE=make OUT=''
while [ $# -gt 0 ]; do
    case $1 in
    --only) [ $# -ge 2 ] || usage "--only needs a picture's name"
        p=${2##*/}; p=${p%.png} m=''
        for n in $PICTURES; do
            # shellcheck disable=SC2254
            case $n in $p) m="$m $n" ;; esac
        done
        [ -n "$m" ] || usage "no picture '$2' (--list lists them)"
        for n in $m; do case " $ONLY " in *" $n "*) ;; *) ONLY="$ONLY $n" ;; esac; done
        shift ;;
    --before) BEFORE=1 ;;
    --list) MODE=list ;;
    --print) MODE=print ;;
    -*) usage "unknown option '$1'" ;;
    *) [ -z "$OUT" ] || usage "one OUTDIR only"; OUT=$1 ;;
    esac
    shift
done
[ -n "$ONLY" ] && PICTURES=$ONLY

case $MODE in
list)
    for n in $PICTURES; do cmd_of "$n" && echo "$D/$n.png"; done
    exit 0 ;;
print)
    for n in $PICTURES; do
        cmd_of "$n" || { echo "pictures.sh: $n has no command" >&2; exit 1; }
        printf '%s%s: %s\n' "$n.png" "${B:+ (the build of $B)}" "$C"
    done
    exit 0 ;;
esac

# every program the chosen pictures' commands run, built (but for a
# picture that will be skipped: a before picture, a need missing)
for n in $PICTURES; do
    cmd_of "$n" || { echo "pictures.sh: $n has no command" >&2; exit 1; }
    [ -z "$Q" ] || eval "$Q" || continue
    case $C in *"\$BT/"*) p=${C##*\$BT/}; p=$BT/${p%% *} ;; *) p=$H ;; esac
    [ -n "$B" ] || [ -x "$p" ] || { echo "pictures.sh: $p is missing (make doc-pictures builds it)" >&2; exit 1; }
done
# the scratch folder: in OUTDIR, or in render/doc when each goes home
mkdir -p "${OUT:-render/doc}" || exit 1
S=$(mktemp -d "${OUT:-render/doc}/.pictures.XXXXXX") || exit 1
trap 'rm -rf "$S"' EXIT
trap 'exit 1' INT TERM HUP
S=$(cd "$S" && pwd) || exit 1

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
    if [ -n "$Q" ] && ! eval "$Q"; then
        echo "$n.png: skipped: $W"
        continue
    fi
    echo "$n.png${B:+ (the build of $B)}"
    H0=$H
    if [ -n "$B" ] && ! before_build "$B"; then continue; fi
    O=$S/$n.png
    if (eval "$C") >"$S/log" 2>&1 && [ -s "$O" ]; then
        mv "$O" "${OUT:-$D}/$n.png" && made=$((made + 1))
    else
        echo "pictures.sh: $n.png failed:" >&2; tail -n 20 "$S/log" >&2; st=1
    fi
    H=$H0
done
echo "pictures.sh: $made picture(s) written to ${OUT:-their folders (render/doc, docs)}"
exit $st
