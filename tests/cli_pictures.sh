#!/bin/sh
# cli_pictures.sh - docs/pictures.sh, the commands of the pictures the docs
# show: its list is exactly the PNGs in render/doc and docs (no picture
# without a command, no command without its picture), every one has a
# command, its lanterns are holonomy tile walk's, three quick ones (two
# day views at 400 x 300, the German tutorial's frame; well under a second
# each) are remade byte for byte, it writes
# only under the folder it is given, the pictures it cannot make here are
# skipped with a line naming what is missing, and its refusals.
# Rendering them all takes half a minute: make doc-pictures, not make test.
# (docs/rendering.md shows the script's --print for the forest, light,
# shadow and keys-level pictures, which tests/cli_docs.sh compares.)
. "$(dirname "$0")/lib.sh"
R=$(cd "$(dirname "$0")/.." && pwd)
P=$R/docs/pictures.sh
# the tool under test, as pictures.sh finds it: $BUILD/holonomy
case $H in
*/holonomy) BUILD=${H%/holonomy} ;;
*) case $H in /*) HA=$H ;; *) HA=$(pwd)/$H ;; esac
   mkdir -p "$T/b" && ln -s "$HA" "$T/b/holonomy" && BUILD=$T/b ;;
esac
export BUILD

# the list against the folders, both ways
(cd "$R" && ls render/doc/*.png docs/*.png) | sort >"$T/files"
if run list 0 sh "$P" --list; then
    sort "$T/out" >"$T/listed"
    if cmp -s "$T/files" "$T/listed"; then ok; else
        bad "docs/pictures.sh --list is not the PNGs in render/doc and docs (< the folders, > the list):"
        diff "$T/files" "$T/listed" | grep '^[<>]'
    fi
    [ "$(sort -u "$T/listed" | wc -l)" -eq "$(wc -l <"$T/out")" ] && ok || bad "a picture listed twice"
fi
[ "$(wc -l <"$T/files")" -ge 30 ] && ok || bad "render/doc and docs hold only $(wc -l <"$T/files") PNGs"

# every listed picture has a command that writes its file
if run print 0 sh "$P" --print; then
    [ "$(wc -l <"$T/out")" -eq "$(wc -l <"$T/files")" ] && ok || bad "--print: not one command a picture"
    while IFS= read -r f; do
        grep -q "^${f##*/}[: ].*\"\\\$O\"" "$T/out" && ok || bad "--print: no command writes $f"
    done <"$T/files"
fi

# the corner view's lanterns, written out in the script, are the tiles
# that holonomy tile walk says the room walks reach
for q in 5 6; do
    want=$(printf 'SWN\nSWEN\nSWNE\nSWNNE\n' | "$H" tile walk --tiling "4,$q" | cut -d' ' -f1 |
        sed 's/^/--lantern /' | tr '\n' ' ')
    got=$(sed -n "s/^LANTERNS_$q=\"\\(.*\\)\"\$/\\1/p" "$P")
    [ -n "$got" ] && [ "$got " = "$want" ] && ok || bad "LANTERNS_$q in docs/pictures.sh is '$got', tile walk says '$want'"
done

# three remade byte for byte (two of render/doc, one of docs), into a
# folder of their own, nothing else left there
if run remake 0 sh "$P" --only view_corner_bare --only view_hud.png --only docs/teaching_de.png "$T/out-dir"; then
    for f in render/doc/view_corner_bare.png render/doc/view_hud.png docs/teaching_de.png; do
        cmp -s "$T/out-dir/${f##*/}" "$R/$f" && ok ||
            bad "${f##*/} remade differs from $f (a rendering change: make doc-pictures, look, commit)"
    done
    [ "$(ls -A "$T/out-dir" | wc -l)" -eq 3 ] && ok || bad "left in the output folder: $(ls -A "$T/out-dir")"
    grep -q '^pictures.sh: 3 picture(s) written to' "$T/out" && ok || bad "remake: no closing line"
fi

# a "before" picture is skipped with a line naming its commit unless --before
if run before 0 sh "$P" --only light8_q5_night_before "$T/before"; then
    grep -q "^light8_q5_night_before.png: skipped: .* commit [0-9a-f]\{7,\}" "$T/out" && ok ||
        bad "a before picture: no skip line ($(cat "$T/out"))"
    [ -z "$(ls -A "$T/before")" ] && ok || bad "a skipped picture left files"
fi

# what is missing here: a line naming it, the rest made, nothing left
mkdir -p "$T/nx" && ln -s "$(cd "$BUILD" && pwd)/holonomy" "$T/nx/holonomy"
if run needs 0 env BUILD="$T/nx" CHROMIUM=no-such-browser sh "$P" --only 'teaching_sheet*' \
    --only headset_night_eyes --only view_hud "$T/needs"; then
    for f in teaching_sheet teaching_sheet_de; do
        grep -q "^$f.png: skipped: needs a browser .*(no-such-browser" "$T/out" && ok || bad "$f: no skip line naming the browser"
    done
    grep -q "^headset_night_eyes.png: skipped: needs make xr-test's night eyes" "$T/out" && ok ||
        bad "headset_night_eyes: no skip line naming make xr-test"
    [ "$(ls -A "$T/needs")" = view_hud.png ] && ok || bad "left in the output folder: $(ls -A "$T/needs")"
fi

# refusals: exit 2, one line on stderr, nothing written
run unknown 2 sh "$P" --only no_such_picture "$T/x" && one_line unknown "no picture 'no_such_picture'"
run option 2 sh "$P" --bogus && one_line option "unknown option '--bogus'"
run two-dirs 2 sh "$P" "$T/x" "$T/y" && one_line two-dirs "one OUTDIR only"
[ ! -e "$T/x" ] && [ ! -e "$T/y" ] && ok || bad "a refusal created a folder"
# a missing program: exit 1, a line naming it and make doc-pictures
run missing 1 env BUILD="$T/nobuild" sh "$P" --only view_hud "$T/x" &&
    one_line missing "make doc-pictures builds it"

finish cli_pictures
