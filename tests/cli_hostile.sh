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
n=0
for c in "$root"/*/; do
    [ -f "$c/cmd" ] || continue
    name=${c%/}; name=${name##*/}; n=$((n + 1))
    w="$T/case-$name"; cp -R "$c". "$w/"
    read -r want <"$c/status"
    (cd "$w" && timeout -s KILL 20 sh ./cmd >"$T/out" 2>"$T/err"); st=$?
    if [ "$st" != "$want" ]; then
        bad "$name: status $st, want $want ($(head -c 200 "$T/err"))"; continue; fi
    if [ "$st" != 0 ] && { [ "$st" -lt 129 ] || [ "$st" -gt 143 ]; } &&
       [ "$(wc -l <"$T/err")" != 1 ]; then
        bad "$name: status $st with $(wc -l <"$T/err") stderr lines: $(head -c 300 "$T/err")"; continue; fi
    if [ -f "$c/out" ] && ! cmp -s "$c/out" "$T/out"; then
        bad "$name: stdout differs"; diff "$c/out" "$T/out" | head -5; continue; fi
    if [ -f "$c/err" ] && ! grep -qF -- "$(cat "$c/err")" "$T/err"; then
        bad "$name: stderr lacks '$(cat "$c/err")': $(head -c 300 "$T/err")"; continue; fi
    big=$(find "$w" -type f -size +16M | head -1)
    if [ -n "$big" ]; then bad "$name: wrote a file over 16 MB: ${big#"$w"/}"; continue; fi
    ok
done
[ "$n" -gt 0 ] || bad "no case in tests/hostile"
finish cli_hostile
