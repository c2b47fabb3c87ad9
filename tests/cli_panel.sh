#!/bin/sh
# cli_panel.sh - the world panel's composition layer (issue 25): holonomy
# xr's --panel option (quad or scene; anything else is bad input: one
# line, exit 2), and the web glue's choice between an XRQuadLayer and the
# panel in the scene (tests/web/quad_check.mjs, on stubs, where node is
# installed). The headset's quad layer itself: make xr-test (tests/xr/quad.sh).
. "$(dirname "$0")/lib.sh"

run "xr --help" 0 "$H" xr --help
grep -q -- "\[--panel quad|scene\]" "$T/out" && grep -q -- "--panel P " "$T/out" && ok ||
    bad "xr --help does not describe --panel"
run "xr --panel sky" 2 "$H" xr --panel sky
err_line "--panel 'sky' is neither quad nor scene"
run "xr --panel (no value)" 2 "$H" xr --panel
err_line "--panel"
run "xr --panel QUAD (case matters)" 2 "$H" xr --panel QUAD
err_line "neither quad nor scene"

if command -v node >/dev/null 2>&1; then
    if node "$(dirname "$0")/web/quad_check.mjs" >"$T/node" 2>&1; then ok; else
        bad "web quad layer choice (tests/web/quad_check.mjs):"; sed 's/^/  /' "$T/node"; fi
else
    echo "cli_panel: node not installed: the web glue's check skipped"
fi
finish cli_panel
