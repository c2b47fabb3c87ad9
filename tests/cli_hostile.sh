#!/bin/sh
# cli_hostile.sh - replays the hostile corpus (tests/hostile/): every input
# that ever broke something, kept so that it never breaks it again.
#
# A case is a folder tests/hostile/NAME/ holding:
#   cmd     a sh script, run in a scratch copy of the folder (its other files
#           are the case's inputs) with $H the binary; at most 20 s
#   status  the exit status it must end with
#   out     (optional) the exact standard output it must print
#   err     (optional) a text that its one stderr line must contain
# Every case must also keep the command-line contract: a non-zero status
# other than a signal's (129..143) prints exactly one line on stderr, and
# no file in the scratch folder may grow past 16 MB (a disk filler).
. "$(dirname "$0")/lib.sh"
root=$(cd "$(dirname "$0")" && pwd)/hostile
H=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
export H
top=$(pwd)
# The scratch copies in one cp (not one a case), each case in its own
# subfolder of $T/cases; the one-line stderr and the expected text read
# in the shell (a `wc`, a `cat` a case before); every copy searched for files over 16 MB in one find
# at the end (one `cp`, `find` and `head` a case before: the harness's
# processes were a third of the suite's CPU).
cp -R "$root" "$T/cases" || bad "cannot copy $root"
# one_nl FILE: FILE holds exactly one newline (wc -l is 1): a first
# line read whole, then none (a last line without its newline counts as
# none, as for wc)
one_nl() {
    { IFS= read -r _l && ! IFS= read -r _l; } <"$1"
}
n=0
for c in "$root"/*/; do
    [ -f "$c/cmd" ] || continue
    name=${c%/}; name=${name##*/}; n=$((n + 1))
    w="$T/cases/$name"
    read -r want <"$c/status"
    cd "$w" && { timeout -s KILL 20 sh ./cmd >"$T/out" 2>"$T/err"; st=$?; cd "$top"; } ||
        { bad "$name: no copy in $w"; cd "$top"; continue; }
    if [ "$st" != "$want" ]; then
        bad "$name: status $st, want $want ($(head -c 200 "$T/err"))"; continue; fi
    if [ "$st" != 0 ] && { [ "$st" -lt 129 ] || [ "$st" -gt 143 ]; }; then
        if ! one_nl "$T/err"; then
            bad "$name: status $st with $(wc -l <"$T/err") stderr lines: $(head -c 300 "$T/err")"
            continue
        fi
    fi
    if [ -f "$c/out" ] && ! cmp -s "$c/out" "$T/out"; then
        bad "$name: stdout differs"; diff "$c/out" "$T/out" | head -5; continue; fi
    if [ -f "$c/err" ]; then
        # one line (its newline optional)
        { IFS= read -r want_err; ! IFS= read -r _l && [ -z "$_l" ]; } <"$c/err" ||
            { bad "$name: its err file is not one line"; continue; }
        if ! grep -qF -- "$want_err" "$T/err"; then
            bad "$name: stderr lacks '$want_err': $(head -c 300 "$T/err")"; continue; fi
    fi
    ok
done
find "$T/cases" -type f -size +16M >"$T/big"
while IFS= read -r big; do
    big=${big#"$T/cases/"}
    bad "${big%%/*}: wrote a file over 16 MB: ${big#*/}"
done <"$T/big"
[ "$n" -gt 0 ] || bad "no case in tests/hostile"
finish cli_hostile
