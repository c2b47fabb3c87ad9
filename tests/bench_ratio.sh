#!/bin/sh
# bench_ratio.sh - {4,5} in the 3 x 3 room: this build against the build
# before the tilings {4,Q} and room sizes (issue 20), in the same run.
# Builds tests/bench_ratio.c against core/ and against core/ of the pinned
# commit BASE (git archive; skipped with a line when git or the commit is
# not there), runs the two in turns ROUNDS times and prints per figure the
# median thread CPU time of each and the ratio this / before (below 1:
# faster now). Usage: bench_ratio.sh BUILD BASE [ROUNDS] (default 7); CC from the
# environment.
set -u
build=$1 base=$2 rounds=${3:-7}
cc=${CC:-cc}
dir=$build/bench/ratio
mkdir -p "$dir"
flags="-std=c11 -O2 -DNDEBUG -D_DEFAULT_SOURCE"
echo "== bench_ratio: {4,5} 3x3, this build against $base (before issue 20), $rounds rounds"
if ! git cat-file -e "$base^{commit}" 2>/dev/null; then
  echo "   skipped: commit $base is not in this repository (a shallow clone?)"
  exit 0
fi
rm -rf "$dir/base"
mkdir -p "$dir/base/tests"
git archive "$base" core | tar x -C "$dir/base" || exit 1
cp tests/bench_ratio.c tests/bench_util.h "$dir/base/tests/"
$cc $flags -o "$dir/before" "$dir/base/tests/bench_ratio.c" "$dir"/base/core/*.c -lm || exit 1
$cc $flags -o "$dir/now" tests/bench_ratio.c core/*.c -lm || exit 1
: >"$dir/times"
i=0
while [ $i -lt "$rounds" ]; do
  "$dir/before" | sed 's/^/before /' >>"$dir/times" || exit 1
  "$dir/now" | sed 's/^/now /' >>"$dir/times" || exit 1
  i=$((i + 1))
done
awk '
  { v[$1, $2, ++n[$1, $2]] = $3; if (!($2 in seen)) { seen[$2] = 1; order[++k] = $2 } }
  function best(who, f,   m, i, b) {
    m = n[who, f]; b = v[who, f, 1]; for (i = 2; i <= m; i++) if (v[who, f, i] < b) b = v[who, f, i]
    return b }
  END {
    printf "   %-24s %12s %12s %8s\n", "figure (best of rounds)", "before s", "now s", "ratio"
    lg = 0
    for (i = 1; i <= k; i++) { f = order[i]; b = best("before", f); c = best("now", f)
      r = c / b; lg += log(r); printf "   %-24s %12.4f %12.4f %8.3f\n", f, b, c, r }
    printf "   %-24s %12s %12s %8.3f\n", "geometric mean", "", "", exp(lg / k) }' "$dir/times"
