#!/bin/sh
# glsl_c.sh - the renderer's GLSL as C: `sh render/shaders/glsl_c.sh OUT`
# writes OUT, a header of one string per shader of render/shaders/
# (NAME.vert.glsl and NAME.frag.glsl: hol__glsl_NAME_vert, _frag), for
# render/hol_program.c to include. Run by the Makefile (into the build
# folder, never committed), platform/android/build_apk.sh and
# tests/quest_link_check.sh; plain sh and awk.
#
# In a shader: "@include FILE" (a line of its own) is replaced by the file
# of render/shaders/ (the same rules); lines that are only a // comment,
# and blank lines, are left out; a line's indentation, its trailing //
# comment and its runs of blanks are cut to nothing, nothing and one space,
# and a blank beside an operator or a bracket is left out (the text is in
# the web's wasm: GLSL has no string literals, so a // is always a
# comment); a backslash or a double quote is refused.
set -eu
[ $# = 1 ] || { echo "usage: glsl_c.sh OUT" >&2; exit 2; }
dir=$(dirname "$0")
out=$1
mkdir -p "$(dirname "$out")"
trap 'rm -f "$out.tmp"' EXIT
{
    echo "/* Made by render/shaders/glsl_c.sh from the .glsl files of render/shaders: not to edit. */"
    for f in "$dir"/*.vert.glsl "$dir"/*.frag.glsl; do
        name=$(basename "$f" .glsl | tr . _)
        echo "static const char hol__glsl_$name[] ="
        awk -v dir="$dir" '
        # a blank beside an operator or a bracket goes, but for one between
        # two of + and - ("a - -b" must not become "a--b"); never in a
        # #define ("#define F (x)" is not "#define F(x)")
        function tight(s,   out, i, c, a, b) {
            out = ""
            for (i = 1; i <= length(s); i++) {
                c = substr(s, i, 1)
                if (c == " ") {
                    a = substr(out, length(out), 1); b = substr(s, i + 1, 1)
                    if ((a ~ /[-+=*\/<>(),;{}?:&|!\[\]]/ || b ~ /[-+=*\/<>(),;{}?:&|!\[\]]/) &&
                        !(a ~ /[-+]/ && b ~ /[-+]/)) continue
                }
                out = out c
            }
            return out
        }
        function emit(file,   line, n) {
            while ((n = (getline line < file)) > 0) {
                if (line ~ /^@include /) { emit(dir "/" substr(line, 10)); continue }
                if (line ~ /^[ \t]*\/\// || line ~ /^[ \t]*$/) continue
                if (line ~ /["\\]/) {
                    print "glsl_c.sh: " file ": a quote or backslash: " line > "/dev/stderr"
                    exit 1
                }
                sub(/[ \t]*\/\/.*$/, "", line)
                gsub(/[ \t]+/, " ", line)
                sub(/^ /, "", line)
                sub(/ $/, "", line)
                if (line !~ /^#define /) line = tight(line)
                print "    \"" line "\\n\""
            }
            if (n < 0) { print "glsl_c.sh: cannot read " file > "/dev/stderr"; exit 1 }
            close(file)
        }
        BEGIN { emit(ARGV[1]); print "    ;" }' "$f"
    done
} >"$out.tmp"
mv "$out.tmp" "$out"
