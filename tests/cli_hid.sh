#!/bin/sh
# cli_hid.sh - `holonomy hid parse|list|watch` (SPEC section 6).
# Goldens: tests/hid/NAME.golden is hid-tools' own parse of the real
# descriptor tests/hid/NAME.hex (tests/hid/SOURCES). Checked by hand
# against the bytes: saitek.hex has Report ID 1 (85 01), X 8 bits 0..255
# at bit 0 (09 30 15 00 26 ff 00 75 08 95 01 81 02) -> "1 0 8 0001:0030 0 255",
# 12 buttons at 32..43, a 0-bit constant, then the hat (09 39 25 07 75 04
# 81 42) -> "1 44 4 0001:0039 0 7"; asus.hex declares buttons with 2-byte
# usages (0a 01 00) on the Button page and then switches to Consumer (05 0c)
# before its main item: the buttons keep page 0009 ("1 0 1 0009:0001 0 1").
. "$(dirname "$0")/lib.sh"
D=$(dirname "$0")/hid

for g in "$D"/*.golden; do
  n=$(basename "$g" .golden)
  run "parse $n" 0 "$H" hid parse "$D/$n.hex" && {
    cmp -s "$T/out" "$g" && ok || { bad "parse $n differs from its golden"; diff "$g" "$T/out" | head -5; }
  }
done
grep -qx "1 0 8 0001:0030 0 255" "$D/saitek.golden" && ok || bad "saitek X by hand"
grep -qx "1 44 4 0001:0039 0 7" "$D/saitek.golden" && ok || bad "saitek hat by hand"
grep -qx "1 0 1 0009:0001 0 1" "$D/asus.golden" && ok || bad "asus button page by hand"

# raw bytes give the same map as hex text
xxd -r -p "$D/ps4_usb.hex" >"$T/ps4.bin" 2>/dev/null ||
  python3 -c "import sys;sys.stdout.buffer.write(bytes.fromhex(open(sys.argv[1]).read()))" "$D/ps4_usb.hex" >"$T/ps4.bin"
run "parse binary" 0 "$H" hid parse "$T/ps4.bin" && { cmp -s "$T/out" "$D/ps4_usb.golden" && ok || bad "binary differs from hex"; }

# hex text forms: 0x prefixes, commas, newlines; signed ranges; arrays
printf '0x05, 0x01, 0x09, 0x05,\n0xa1, 0x01, 0x09, 0x30, 0x09, 0x31, 0x15, 0x81, 0x25, 0x7f,\n0x75, 0x08, 0x95, 0x02, 0x81, 0x02,\n0x05, 0x07, 0x19, 0x00, 0x29, 0x65, 0x15, 0x00, 0x25, 0x65, 0x95, 0x02, 0x81, 0x00, 0xc0\n' >"$T/in"
expect "parse stdin hex" 0 '0 0 8 0001:0030 -127 127
0 8 8 0001:0031 -127 127
0 16 8 0007:0000-0065 0 101
0 24 8 0007:0000-0065 0 101
' "$H" hid parse -

# logical max read unsigned when the minimum is not negative; fewer usages
# than elements: the last repeats; a 4-byte usage carries its own page
printf '05 01 09 05 a1 01 0b 30 00 02 00 09 31 15 00 25 ff 75 08 95 03 81 02 c0' >"$T/d"
run "parse ranges" 0 "$H" hid parse "$T/d"
printf '0 0 8 0002:0030 0 255\n0 8 8 0001:0031 0 255\n0 16 8 0001:0031 0 255\n' >"$T/want"
cmp -s "$T/out" "$T/want" && ok || { bad "unsigned max, repeat, 4-byte usage"; cat "$T/out"; }

# bad descriptors: exit 2 and one line
for bad in '05' '05 01 a1 01' 'c0' '85 00' 'b4' '75 ff 01' 'zz' '05 1'; do
  printf '%s' "$bad" >"$T/d"
  run "bad '$bad'" 2 "$H" hid parse "$T/d" && one_line "bad '$bad'" "hid parse"
  [ -s "$T/out" ] && bad "bad '$bad' printed output" || ok
done
: >"$T/d"
run "empty file" 2 "$H" hid parse "$T/d" && one_line "empty" "not a valid"
run "missing file" 2 "$H" hid parse "$T/nonexistent" && one_line "missing" "nonexistent"
run "parse no file" 2 "$H" hid parse
run "unknown sub" 2 "$H" hid frobnicate && one_line "unknown" "unknown subcommand"
run "help" 0 "$H" hid --help && grep -q "hid parse FILE" "$T/out" && ok || bad "hid --help text"

# no device on this machine: list says so (0), watch fails (1) with one line
if ls /dev/hidraw* >/dev/null 2>&1; then
  echo "cli_hid: /dev/hidraw* present, skipping the no-device checks"
else
  run "list no device" 0 "$H" hid list && grep -q "no game controllers found" "$T/out" && ok || bad "list message"
  run "watch no device" 1 "$H" hid watch --frames 2 && one_line "watch" "no game controller found"
fi
run "watch bad frames" 2 "$H" hid watch --frames 0 && one_line "frames" "--frames"
# watch on a scripted controller (the recorded Asus pad, tests/hid_samples.h
# states: report 1 = left stick full left and button 1 (south: confirm,
# 0x01), report 0 = centred), 10 ms a read: a line a change, then the
# unplug at 2 s ends it
run "watch replay" 0 "$H" hid watch --replay "$D/asus_play.pad"
printf '%s\n' "# 18d1:2c40 scripted controller" \
    "buttons 0x01 move -1.000 0.004 turn 0.000 0.000" \
    "buttons 0x00 move 0.000 0.000 turn 0.000 0.000" "# controller lost" >"$T/want"
cmp -s "$T/out" "$T/want" && ok || bad "watch replay: $(cat "$T/out")"
run "watch replay frames" 0 "$H" hid watch --replay "$D/asus_play.pad" --frames 100
[ "$(wc -l <"$T/out")" = 2 ] && ok || bad "watch --frames 100 (1 s): $(cat "$T/out")"
printf '1 plug 0001:0002 05 01\n' >"$T/late.pad"
run "watch replay late" 1 "$H" hid watch --replay "$T/late.pad" && one_line "late" "no game controller"
printf '0 plug 0001:0002 05 01\n0 jump\n' >"$T/bad.pad"
run "watch replay bad" 2 "$H" hid watch --replay "$T/bad.pad" && one_line "bad script" "line 2"
run "watch help" 0 "$H" hid watch --help && grep -q -- "--replay FILE" "$T/out" && ok ||
    bad "hid watch --help lacks --replay"

finish cli_hid
