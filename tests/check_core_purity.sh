#!/bin/sh
# check_core_purity.sh - core/ stays pure: its objects may not call file or
# OS functions, clocks, threads or GL. (Allocation happens once, at make
# time, through caller hooks; the unit tests check it with counting hooks.)
# Nor libm's transcendental functions, which differ between C libraries in
# the last bit: the core's own are core/hol_math.h (sqrt, floor, fmod and
# fabs are exact everywhere and allowed).
# Usage: check_core_purity.sh OBJ...
set -u
forbidden='^(fopen|fclose|fread|fwrite|fprintf|printf|puts|fputs|putchar|getline|open|close|read|write|mmap|munmap|clock_gettime|clock|time|gettimeofday|rand|srand|getenv|exit|abort|pthread_.*|gl[A-Z].*|egl[A-Z].*|OSMesa.*|xr[A-Z].*|hid_.*|libusb_.*|rename|unlink|remove|realloc|stderr|stdout|stdin|(sin|cos|tan|asin|acos|atan|atan2|sinh|cosh|tanh|asinh|acosh|atanh|exp|exp2|expm1|log|log2|log10|log1p|pow|cbrt|hypot|erf|erfc|lgamma|tgamma|sincos)[fl]?)$'
bad=0
for o in "$@"; do
  syms=$(nm -u "$o" | awk '{print $2}' | sed 's/@.*//' | grep -E "$forbidden")
  if [ -n "$syms" ]; then
    echo "core purity: $o uses: $(echo $syms)"
    bad=1
  fi
done
if [ $bad = 0 ]; then echo "core purity: $# objects clean"; fi
exit $bad
