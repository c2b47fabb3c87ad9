#!/bin/sh
# check_fn_length.sh [MAX] - no C function in core/, render/ or platform/
# longer than MAX lines (120 by default: the house's rule), from the first
# line of its declaration to its closing brace. The code's style makes a
# function's body a "{" ... "}" pair at column 0 (or a declaration line
# ending in "{"); one-line functions are short by themselves. Prints each
# function over the limit and exits 1, else one line and 0.
max=${1:-120}
cd "$(dirname "$0")/.." || exit 2
find core render platform -name '*.[ch]' | sort | xargs awk -v max="$max" '
FNR == 1 { sig = 0; start = 0 }
/^[A-Za-z_]/ && !/^(typedef|struct|enum|union)[ \t]/ && !/=/ && !/;[ \t]*$/ {
    if (!start) sig = FNR
    if (/\)[ \t]*\{[ \t]*$/ && !/\}/) start = sig
}
/^\{/ { if (sig) start = sig }
/^\}[ \t]*$/ {
    if (start && FNR - start + 1 > max) {
        printf "%s:%d: a function of %d lines (at most %d)\n", FILENAME, start, FNR - start + 1, max
        bad = 1
    }
    start = 0; sig = 0
}
END { exit bad }' || exit 1
echo "functions: none over $max lines in core/, render/, platform/"
