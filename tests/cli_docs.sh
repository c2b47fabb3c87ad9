#!/bin/sh
# cli_docs.sh - every example in README.md and docs/*.md is true: the
# shell examples run against the binary and print what the page shows, and
# every relative link reaches its file and heading. $HOLONOMY is the binary.
#
# The format (docs/testing.md, "The examples in these pages"):
# - A fenced block opens with ```console (run) or ```text (not run: file
#   formats, usage synopses); any other opening fence fails this test.
# - In a console block a line "$ COMMAND" is a command, run by sh in a
#   scratch folder of the block's own (build/holonomy is the binary under
#   test, tests/ and the other top-level folders are the repository's), so
#   the commands of a block share their files. The lines after it, up to the
#   next "$ " line or the end of the block, are its standard output followed
#   by its standard error; a line "..." stands for any number of lines.
# - The exit status must be 0, or N where the command ends with "# exit N".
# - A command ending with "# skip: REASON" (a window, a device, the network,
#   root, make itself) is not run; this test prints each one it skips.
. "$(dirname "$0")/lib.sh"

R=$(cd "$(dirname "$0")/.." && pwd)
case $H in /*) HA=$H ;; *) HA=$(pwd)/$H ;; esac
# the pages' commands see the block's build/ (the binary under test), not
# the build a make named (make san-all exports BUILD=build/san, which
# docs/pictures.sh would read)
unset BUILD
PAGES=$(cd "$R" && ls README.md docs/*.md)

# ---- 1. extract: one record a line, fields separated by a tab ------------
#   B FILE:LINE           a console block starts
#   C LINE COMMAND        a command (C LINE, skip: REASON form kept as is)
#   O TEXT                a line of shown output
#   X FILE:LINE: MESSAGE  a fence that breaks the format
(cd "$R" && awk '
    FNR == 1 { fence = 0 }
    {
        line = $0
        sub(/^ +/, "", line)
    }
    fence == 0 && line ~ /^```/ {
        info = substr(line, 4)
        if (info == "console") { fence = 2; printf "B\t%s:%d\n", FILENAME, FNR }
        else if (info == "text") fence = 1
        else printf "X\t%s:%d: a block opens with ```console or ```text, not \"%s\"\n", FILENAME, FNR, line
        ind = index($0, "`") - 1
        next
    }
    fence != 0 && line == "```" { fence = 0; next }
    fence == 2 {
        t = substr($0, ind + 1)
        if (substr(t, 1, 2) == "$ ") printf "C\t%d\t%s\n", FNR, substr(t, 3)
        else printf "O\t%s\n", t
    }
    END { if (fence != 0) printf "X\t%s: a block is not closed\n", FILENAME }
' $PAGES) >"$T/records"

# ---- 2. run ---------------------------------------------------------------
# matches EXPECTED ACTUAL...: the actual lines (the files' lines one after
# the other) match the expected ones ("..." any number of lines)
matches() {
    awk -v want="$1" '
        function m(i, j) {
            if (i > ne) return j > na
            if (e[i] == "...") return m(i + 1, j) || (j <= na && m(i, j + 1))
            return j <= na && e[i] == a[j] && m(i + 1, j + 1)
        }
        FILENAME == want { e[++ne] = $0; next }
        { a[++na] = $0 }
        END { exit m(1, 1) ? 0 : 1 }
    ' "$@"
}

nblock=0 nrun=0 nskip=0 cmd=""
: >"$T/skips"
# the command in $cmd (from FILE line $cline) against the output in $T/want
check_cmd() {
    [ -n "$cmd" ] || return 0
    case $cmd in
    *"# skip: "*)
        nskip=$((nskip + 1))
        printf '  skipped %s:%s: %s\n' "$file" "$cline" "$cmd" >>"$T/skips"
        [ -s "$T/want" ] && bad "$file:$cline: a skipped example shows output"
        cmd=""
        return 0 ;;
    esac
    want_st=0
    case $cmd in *"# exit "[0-9]*) want_st=${cmd##*# exit }; want_st=${want_st%%[!0-9]*} ;; esac
    nrun=$((nrun + 1))
    (cd "$B" && timeout 120 sh -c "$cmd" >"$T/out" 2>"$T/err" </dev/null)
    st=$?
    if [ "$st" != "$want_st" ]; then
        bad "$file:$cline: exit status $st, the page says $want_st"
        printf '  $ %s\n' "$cmd"; head -c 300 "$T/err"
    elif ! matches "$T/want" "$T/out" "$T/err"; then
        bad "$file:$cline: the output differs from the page (< page, > binary)"
        printf '  $ %s\n' "$cmd"
        cat "$T/out" "$T/err" | diff "$T/want" - | head -10
    else
        ok
    fi
    cmd=""
}

new_block() {
    nblock=$((nblock + 1))
    B=$T/block$nblock
    mkdir -p "$B/build"
    ln -s "$HA" "$B/build/holonomy"
    # the top-level entries but build/, in one ln (not one ln an entry)
    set --
    for f in "$R"/*; do
        [ "${f##*/}" = build ] || set -- "$@" "$f"
    done
    ln -s "$@" "$B/"
}

TAB=$(printf '\t')
while IFS= read -r rec; do
    kind=${rec%%"$TAB"*}
    rest=${rec#*"$TAB"}
    case $kind in
    X) bad "$rest" ;;
    B) check_cmd; file=${rest%:*}; new_block ;;
    C) check_cmd; cline=${rest%%"$TAB"*}; cmd=${rest#*"$TAB"}; : >"$T/want" ;;
    O) if [ -n "$cmd" ]; then printf '%s\n' "$rest" >>"$T/want"
       else bad "$file: output before the block's first command: $rest"; fi ;;
    esac
done <"$T/records"
check_cmd

[ "$nrun" -gt 20 ] || bad "only $nrun examples found in README.md and docs/"
echo "examples: $nrun run, $nskip skipped (a window, a device, the network, root or make):"
cat "$T/skips"

# ---- 3. links: every relative link reaches its file and its heading -------
(cd "$R" && awk '
    function slug(s) {
        s = tolower(s)
        gsub(/[^a-z0-9 _-]/, "", s)
        gsub(/ /, "-", s)
        return s
    }
    function dir(f) { return f ~ /\// ? substr(f, 1, match(f, /[^\/]*$/) - 1) : "" }
    FNR == 1 { fence = 0; files[FILENAME] = 1 }
    /^ *```/ { fence = !fence; next }
    fence { next }
    /^#/ { h = $0; sub(/^#+ */, "", h); anchor[FILENAME "#" slug(h)] = 1 }
    {
        s = $0
        while (match(s, /\]\([^) ]+\)/)) {
            t = substr(s, RSTART + 2, RLENGTH - 3)
            s = substr(s, RSTART + RLENGTH)
            if (t ~ /^[a-z]+:/) continue
            n++; src[n] = FILENAME ":" FNR; tgt[n] = t; base[n] = dir(FILENAME)
        }
    }
    END {
        for (i = 1; i <= n; i++) {
            t = tgt[i]; a = ""
            if (index(t, "#")) { a = substr(t, index(t, "#") + 1); t = substr(t, 1, index(t, "#") - 1) }
            p = t == "" ? substr(src[i], 1, index(src[i], ":") - 1) : base[i] t
            while (p ~ /[^\/]+\/\.\.\//) sub(/[^\/]+\/\.\.\//, "", p)
            # a file named: checked by the shell below (a `test` a link
            # spawned by system() before), then its heading if named
            if (t != "") print "F\t" p "\t" src[i] ": no file " tgt[i] "\t" \
                (a != "" && !((p "#" a) in anchor) ? src[i] ": no heading for " tgt[i] : "")
            else if (a != "" && !((p "#" a) in anchor)) print "H\t" src[i] ": no heading for " tgt[i]
        }
        printf "links: %d checked\n", n > "/dev/stderr"
    }
' $PAGES) >"$T/links_raw" 2>"$T/links_n"
(cd "$R" && while IFS="$TAB" read -r kind p nofile nohead; do
    case $kind in
    F) if [ ! -e "$p" ]; then echo "$nofile"
       elif [ -n "$nohead" ]; then echo "$nohead"; fi ;;
    H) echo "$p" ;;
    esac
done) <"$T/links_raw" >"$T/links"
if [ -s "$T/links" ]; then
    while IFS= read -r l; do bad "$l"; done <"$T/links"
else
    ok
fi
cat "$T/links_n"

finish "cli_docs"
