#!/bin/sh
# cli_pictures.sh - docs/pictures.sh, the commands of the pictures in
# render/doc: its list is exactly the PNGs there (no picture without a
# command, no command without its picture), every one has a command, two
# quick ones (day, 400 x 300, well under a second each) are remade byte for
# byte, it writes only under the folder it is given, and its refusals.
# Rendering them all takes a minute: make doc-pictures, not make test.
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

# the list against the folder, both ways
(cd "$R/render/doc" && ls) | grep '\.png$' | sort >"$T/files"
if run list 0 sh "$P" --list; then
    sort "$T/out" >"$T/listed"
    if cmp -s "$T/files" "$T/listed"; then ok; else
        bad "docs/pictures.sh --list is not render/doc's PNGs (< render/doc, > the list):"
        diff "$T/files" "$T/listed" | grep '^[<>]'
    fi
    [ "$(sort -u "$T/listed" | wc -l)" -eq "$(wc -l <"$T/out")" ] && ok || bad "a picture listed twice"
fi
[ "$(wc -l <"$T/files")" -ge 20 ] && ok || bad "render/doc holds only $(wc -l <"$T/files") PNGs"

# every listed picture has a command that writes its file
if run print 0 sh "$P" --print; then
    [ "$(wc -l <"$T/out")" -eq "$(wc -l <"$T/files")" ] && ok || bad "--print: not one command a picture"
    while IFS= read -r f; do
        grep -q "^${f}[: ].*\"\\\$O\"" "$T/out" && ok || bad "--print: no command writes $f"
    done <"$T/files"
fi

# two remade byte for byte, into a folder of their own, nothing else left there
if run remake 0 sh "$P" --only view_corner_bare --only view_hud.png "$T/out-dir"; then
    for f in view_corner_bare.png view_hud.png; do
        cmp -s "$T/out-dir/$f" "$R/render/doc/$f" && ok ||
            bad "$f remade differs from render/doc/$f (a rendering change: make doc-pictures, look, commit)"
    done
    [ "$(ls -A "$T/out-dir" | wc -l)" -eq 2 ] && ok || bad "left in the output folder: $(ls -A "$T/out-dir")"
    grep -q '^pictures.sh: 2 picture(s) written to' "$T/out" && ok || bad "remake: no closing line"
fi

# a "before" picture is skipped with a line naming its commit unless --before
if run before 0 sh "$P" --only light8_q5_night_before "$T/before"; then
    grep -q "^light8_q5_night_before.png: skipped: .* commit [0-9a-f]\{7,\}" "$T/out" && ok ||
        bad "a before picture: no skip line ($(cat "$T/out"))"
    [ -z "$(ls -A "$T/before")" ] && ok || bad "a skipped picture left files"
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
