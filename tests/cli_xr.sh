#!/bin/sh
# cli_xr.sh - `holonomy xr`'s command line on any build: --help, bad input
# (exit 2, one line, before anything else happens), and what each build
# does without a headset: a build without OpenXR says how to get one (exit
# 1, one line); an XR=1 build with no runtime fails in one line naming the
# missing runtime (exit 1). The headset itself is `make xr-test`'s.
. "$(dirname "$0")/lib.sh"

run "--help" 0 "$H" xr --help
grep -q "^usage: holonomy xr" "$T/out" && ok || bad "--help lacks the usage line"
grep -q "Exit status" "$T/out" && ok || bad "--help lacks the exit statuses"

run "unknown option" 2 "$H" xr --bogus
one_line "unknown option" "unknown option '--bogus'"
run "bad --frames" 2 "$H" xr --frames x
one_line "bad --frames" "frames"
run "--frames without a value" 2 "$H" xr --frames
one_line "--frames without a value" "needs a value"
run "bad --space" 2 "$H" xr --space floor
one_line "bad --space" "--space 'floor' is neither stage nor local"
run "bad --play-area" 2 "$H" xr --play-area 2x
one_line "bad --play-area" "--play-area '2x' is not WxD in metres, 0.5 to 100 each (2.6x2.6)"
run "missing level" 2 "$H" xr "$T/none.lvl"
one_line "missing level" "none.lvl"
printf 'mode flag\nseed 5\nbogus 1\n' >"$T/bad.lvl"
run "bad level" 2 "$H" xr "$T/bad.lvl"
one_line "bad level" "line 3"

# no headset here (no runtime; XR_RUNTIME_JSON points nowhere)
printf 'mode explore\nseed 1\n' >"$T/ok.lvl"
XR_RUNTIME_JSON="$T/none.json" DISPLAY= run "no runtime" 1 "$H" xr "$T/ok.lvl" --frames 2
if grep -q "this build has no OpenXR" "$T/err"; then
    one_line "a build without OpenXR" "make xr"
else
    # the loader says its own lines first; ours is the last, one line
    tail -n 1 "$T/err" | grep -q "^holonomy xr: cannot start the OpenXR instance: no OpenXR runtime is installed or active;.*monado-service.*(XR_ERROR_RUNTIME_UNAVAILABLE)$" && ok ||
        bad "no runtime: $(cat "$T/err")"
fi
finish cli_xr
