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
# and blank lines, are left out; a backslash or a double quote is refused.
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
        function emit(file,   line, n) {
            while ((n = (getline line < file)) > 0) {
                if (line ~ /^@include /) { emit(dir "/" substr(line, 10)); continue }
                if (line ~ /^[ \t]*\/\// || line ~ /^[ \t]*$/) continue
                if (line ~ /["\\]/) {
                    print "glsl_c.sh: " file ": a quote or backslash: " line > "/dev/stderr"
                    exit 1
                }
                print "    \"" line "\\n\""
            }
            if (n < 0) { print "glsl_c.sh: cannot read " file > "/dev/stderr"; exit 1 }
            close(file)
        }
        BEGIN { emit(ARGV[1]); print "    ;" }' "$f"
    done
} >"$out.tmp"
mv "$out.tmp" "$out"
