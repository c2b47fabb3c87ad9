#!/bin/sh
# cli_fireflies.sh - render's --fireflies (issue 27): at dusk and night the
# fireflies are drawn by default at time 0 (as the app draws them, at the
# level's clock), --fireflies T places them at time T (what the xr and web
# check lines print for an eye), 'off' leaves them out; day ignores it;
# bad values are refused with one line (exit 2) and no file.
. "$(dirname "$0")/lib.sh"
P=${PNG_PROBE:-build/tests/png_probe}

run "--help" 0 "$H" render --help
grep -q -- "--fireflies T" "$T/out" && ok || bad "render --help does not describe --fireflies"

# seed 3 from the south-west corner: flower and creek tiles in view
V="--seed 3 --walk SW --eye 0.15,1.6,2.85 --yaw -30 --pitch -22 --size 160x120"
run "night" 0 "$H" render $V --lighting night --out "$T/n.png"
run "night at 0" 0 "$H" render $V --lighting night --fireflies 0 --out "$T/n0.png"
run "night at 3.25" 0 "$H" render $V --lighting night --fireflies 3.25 --out "$T/n3.png"
run "night at 3.25 again" 0 "$H" render $V --lighting night --fireflies=3.25 --out "$T/n3b.png"
run "night off" 0 "$H" render $V --lighting night --fireflies off --out "$T/off.png"
cmp -s "$T/n.png" "$T/n0.png" && ok || bad "the default is not --fireflies 0"
cmp -s "$T/n3.png" "$T/n3b.png" && ok || bad "the same time drew two pictures"
n=$("$P" "$T/n0.png" --vs "$T/n3.png")
[ "$n" -gt 0 ] && ok || bad "the fireflies did not move between 0 and 3.25 s"
n=$("$P" "$T/off.png" --vs "$T/n.png")
[ "$n" -gt 100 ] && ok || bad "the fireflies change only $n pixels at night"
run "dusk" 0 "$H" render $V --lighting dusk --fireflies 1.5 --out "$T/d.png"
run "dusk off" 0 "$H" render $V --lighting dusk --fireflies off --out "$T/doff.png"
n=$("$P" "$T/doff.png" --vs "$T/d.png")
[ "$n" -gt 100 ] && ok || bad "the fireflies change only $n pixels at dusk"
run "day" 0 "$H" render $V --out "$T/day.png"
run "day at 7" 0 "$H" render $V --lighting day --fireflies 7 --out "$T/day7.png"
cmp -s "$T/day.png" "$T/day7.png" && ok || bad "--fireflies changed the day picture"

for v in x -1 1e10 nan inf "" 1,2 "0x10" " 1"; do
    run "bad '$v'" 2 "$H" render $V --lighting night --fireflies "$v" --out "$T/x.png" &&
        one_line "bad '$v'" "--fireflies '$v' is not a time in seconds in 0..1e9 (or off)"
done
run "twice" 2 "$H" render $V --fireflies 1 --fireflies 2 --out "$T/x.png" &&
    one_line "twice" "--fireflies is given twice"
run "no value" 2 "$H" render $V --fireflies
[ "$(wc -l <"$T/err")" -eq 1 ] && ok || bad "no value: stderr is not one line"
[ ! -e "$T/x.png" ] && ok || bad "a refused render wrote its file"

finish cli_fireflies
