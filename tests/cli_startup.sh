#!/bin/sh
# cli_startup.sh - what every command pays at start: the binary does not
# load OSMesa (and LLVM behind it) unless it renders headless
# (platform/osmesa/hol_osmesa.h loads it then), and rendering still works.
. "$(dirname "$0")/lib.sh"

if command -v readelf >/dev/null 2>&1; then
  readelf -d "$H" >"$T/dyn" 2>/dev/null || bad "readelf -d $H"
  if grep -q 'NEEDED.*libOSMesa' "$T/dyn"; then bad "the binary links libOSMesa"; else ok; fi
fi
# a command that draws nothing never maps the library
if [ -r /proc/self/maps ]; then
  # the maps of a running command: `tile` reads stdin, so it waits on a fifo
  mkfifo "$T/fifo"
  "$H" tile walk <"$T/fifo" >/dev/null 2>&1 &
  pid=$!
  exec 3>"$T/fifo"
  # until the child has become the binary (the shell opens the fifo first)
  i=0
  while [ $i -lt 50 ] && ! grep -q 'walk' "/proc/$pid/cmdline" 2>/dev/null; do
    sleep 0.1
    i=$((i + 1))
  done
  sleep 0.1
  if grep -q 'libOSMesa\|libLLVM' "/proc/$pid/maps" 2>/dev/null; then
    bad "a command that does not render maps libOSMesa"
  else ok; fi
  exec 3>&-
  wait "$pid"
fi
# and headless rendering loads it when needed
run "render loads OSMesa" 0 "$H" render --size 64x48 --out "$T/o.png" &&
  { [ -s "$T/o.png" ] && ok || bad "render wrote no PNG"; }
finish cli_startup
