#!/bin/sh
# build_id.sh OUT - write OUT, a C header naming the build: HOL_BUILD_COMMIT
# (`git describe --always --dirty` where the source is a git checkout, else
# "unknown") and HOL_BUILD_DATE (ISO 8601 UTC: SOURCE_DATE_EPOCH when set,
# else the commit's date, else "unknown"; never the clock, so that a build
# is reproducible). OUT is rewritten only when its text changes, so the one
# file that includes it (platform/shell/hol_shell_build.c) is recompiled only then.
set -eu
out=$1
commit=unknown
epoch=${SOURCE_DATE_EPOCH:-}
if git rev-parse --git-dir >/dev/null 2>&1; then
    commit=$(git describe --always --dirty 2>/dev/null || git rev-parse --short HEAD 2>/dev/null || echo unknown)
    [ -n "$epoch" ] || epoch=$(git log -1 --format=%ct 2>/dev/null || true)
fi
date=unknown
if [ -n "$epoch" ]; then
    date=$(date -u -d "@$epoch" +%Y-%m-%dT%H:%M:%SZ 2>/dev/null || echo unknown)
fi
# only letters, digits and . _ - + : in either (a C string, a CSV field)
commit=$(printf '%s' "$commit" | tr -c 'A-Za-z0-9._+:-' '_')
mkdir -p "$(dirname "$out")"
tmp=$out.tmp.$$
printf '/* made by platform/shell/build_id.sh: do not edit */\n#define HOL_BUILD_COMMIT "%s"\n#define HOL_BUILD_DATE "%s"\n' \
    "$commit" "$date" >"$tmp"
if cmp -s "$tmp" "$out"; then rm -f "$tmp"; else mv "$tmp" "$out"; fi
