# tests/xr/lib.sh - what every xr-test script shares, sourced by each
# (`. "$(dirname "$0")/lib.sh"`): check prints one line per check and sets
# fail=1 on a failure; inject_manifest writes the manifest of the test
# API layer (tests/xr/inject_layer.c, library $LAYER) into a folder.

# check DESCRIPTION SHELL-CONDITION
check() { if eval "$2"; then echo "xr-test: ok: $1"; else echo "xr-test: FAIL: $1"; fail=1; fi; }

# inject_manifest DIR DESCRIPTION: DIR/XrApiLayer_holonomy_inject.json,
# naming $LAYER (a relative path taken from the current folder)
inject_manifest() {
    cat >"$1/XrApiLayer_holonomy_inject.json" <<JSON
{ "file_format_version": "1.0.0",
  "api_layer": { "name": "XR_APILAYER_HOLONOMY_inject",
    "library_path": "$(case $LAYER in /*) echo "$LAYER";; *) echo "$(pwd)/$LAYER";; esac)",
    "api_version": "1.0", "implementation_version": "1",
    "description": "holonomy xr-test: $2" } }
JSON
}
