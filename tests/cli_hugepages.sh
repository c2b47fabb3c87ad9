#!/bin/sh
# cli_hugepages.sh - a command with big blocks (nav, tour, render, play,
# ...) starts itself once more with glibc's tunable glibc.malloc.hugetlb=1
# (platform/cli/main.c), so malloc's big blocks are advised onto
# transparent huge pages: the navigator's block (32 MB) of a waiting `nav`
# carries the flag `hg` (MADV_HUGEPAGE) in /proc/PID/smaps, also beside
# other tunables of the user's; a GLIBC_TUNABLES naming the tunable is
# kept as it is (=0: no flag); the answers are the same; --help works.
. "$(dirname "$0")/lib.sh"

# big_flags PID: the VmFlags of the process's mappings of 16 MB or more
big_flags() {
  awk '/^Size:/ { size = $2 } /^VmFlags:/ { if (size >= 16384) print }' "/proc/$1/smaps" 2>/dev/null
}

# probe NAME WANT CMD...: CMD (a `nav`) run with its stdin on a FIFO, so it
# waits for a line once its navigator is made; WANT 1: its big mapping
# advised (hg), 0: not. Then the line "- Nff" is written; stdout in $T/pout.
probe() {
  name=$1 want=$2; shift 2
  rm -f "$T/fifo"
  mkfifo "$T/fifo"
  "$@" <"$T/fifo" >"$T/pout" 2>"$T/perr" &
  pid=$!
  exec 3>"$T/fifo"
  # until the navigator's block is mapped (and advised, when wanted)
  i=0 got=
  while [ $i -lt 100 ]; do
    got=$(big_flags "$pid")
    if [ -n "$got" ]; then
      echo "$got" | grep -qw hg && break
      [ "$want" = 0 ] && [ $i -ge 5 ] && break
    fi
    sleep 0.1
    i=$((i + 1))
  done
  printf -- '- Nff\n' >&3
  exec 3>&-
  wait "$pid" || bad "$name: status $?"
  if [ -z "$got" ]; then bad "$name: no mapping of 16 MB or more seen"; return; fi
  if echo "$got" | grep -qw hg; then has=1; else has=0; fi
  [ "$has" = "$want" ] && ok || bad "$name: huge pages advised $has, want $want ($got)"
  [ "$(cat "$T/pout")" = "7 WNEESWS" ] && ok || bad "$name: answered $(cat "$T/pout")"
}

# (a sanitizer build's malloc is not glibc's: nothing to check there)
if [ "$(uname -s)" != Linux ] || [ ! -r /proc/self/smaps ] ||
   ! ldd "$H" 2>/dev/null | grep -q 'libc.so.6' || ldd "$H" 2>/dev/null | grep -q 'libasan'; then
  echo "cli_hugepages: not Linux with glibc's malloc: skipped"
  finish cli_hugepages
  exit
fi

unset GLIBC_TUNABLES
probe "nav" 1 "$H" nav
probe "nav beside another tunable" 1 env GLIBC_TUNABLES=glibc.malloc.check=0 "$H" nav
probe "nav, hugetlb=0" 0 env GLIBC_TUNABLES=glibc.malloc.hugetlb=0 "$H" nav

# commands that finish the tables or render run as before
printf 'mode keys\nseed 5\nkeys Wr Nf\nchest Ef\n' >"$T/k.lvl"
echo NSWE >"$T/in"
expect "game keys" 0 "open 4 12
" "$H" game "$T/k.lvl"
run "render" 0 "$H" render --size 64x48 --out "$T/o.png" &&
  { [ -s "$T/o.png" ] && ok || bad "render wrote no PNG"; }
run "render --help" 0 "$H" render --help
finish cli_hugepages
