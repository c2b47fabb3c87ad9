#!/bin/sh
# cli_report_bids.sh - `holonomy report --bids DIR` (issue 35): each
# attempt's head and hand tracks as BIDS-Motion (BIDS 1.9, BEP029). From a
# log folder replayed here (two participants, hands tracked in part, a gap):
# - the option's refusals (an input, --out itself, a folder not empty, a
#   malformed track file): one line, exit 2, nothing written; --out's files
#   the same with --bids beside it;
# - the dataset against the BIDS-Motion rules this test names (bids_rules,
#   below), and by npm's bids-validator (tests/bids, `make deps-web`) with
#   0 errors when it is installed (else one line says it is skipped);
# - both fail on a broken copy: a channels.tsv row fewer than the motion
#   columns (the rules), a motion.json key BIDS does not define (the
#   validator);
# - values: the room frame is the track file's, n/a where it is empty and
#   for the samples a gap hid; the tile frame is turned by the steps'
#   orient about the room's centre.
. "$(dirname "$0")/lib.sh"
H=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
V=$(cd "$(dirname "$0")" && pwd)/bids/node_modules/.bin/bids-validator
cd "$T" || exit 1

# bids_rules DIR: 0 when DIR keeps these rules of BIDS 1.9 (common
# principles and the motion modality), else a line naming the first broken:
# R1 dataset_description.json with Name and BIDSVersion;
# R2 participants.tsv starting with participant_id, naming every sub- folder;
# R3 motion files named sub-L/[ses-S/]motion/sub-L[_ses-S]_task-T
#    [_acq-A]_tracksys-K[_run-N]_motion.tsv, labels letters and digits, the
#    folders' labels the name's;
# R4 beside each: _channels.tsv (the same entities) with the columns name,
#    component, type, tracked_point, units first, a type of the motion
#    types and a component of x, y, z, quat_x..quat_w or n/a; and
#    _motion.json with TaskName and a numeric SamplingFrequency;
# R5 motion.tsv has no header: every row has as many values as
#    channels.tsv has rows, each a number or n/a.
bids_rules() {
    d=$1
    grep -q '"Name"' "$d/dataset_description.json" && grep -q '"BIDSVersion"' \
        "$d/dataset_description.json" || { echo "R1 dataset_description.json"; return 1; }
    [ "$(head -1 "$d/participants.tsv" | cut -f1)" = participant_id ] ||
        { echo "R2 participants.tsv header"; return 1; }
    for s in "$d"/sub-*; do
        cut -f1 "$d/participants.tsv" | grep -qx "$(basename "$s")" ||
            { echo "R2 $(basename "$s") not in participants.tsv"; return 1; }
    done
    n=0
    for m in "$d"/sub-*/*/motion/*_motion.tsv "$d"/sub-*/motion/*_motion.tsv; do
        [ -e "$m" ] || continue
        n=$((n + 1))
        rel=${m#"$d"/}
        echo "$rel" | grep -Eq '^sub-([A-Za-z0-9]+)/(ses-([A-Za-z0-9]+)/)?motion/sub-\1(_ses-\3)?_task-[A-Za-z0-9]+(_acq-[A-Za-z0-9]+)?_tracksys-[A-Za-z0-9]+(_run-[0-9]+)?_motion\.tsv$' ||
            { echo "R3 $rel"; return 1; }
        c=${m%_motion.tsv}_channels.tsv j=${m%.tsv}.json
        [ -f "$c" ] && [ -f "$j" ] || { echo "R4 no channels.tsv or motion.json for $rel"; return 1; }
        awk -F'\t' 'NR == 1 { if ($1 != "name" || $2 != "component" || $3 != "type" ||
                $4 != "tracked_point" || $5 != "units") exit 1; next }
            $3 !~ /^(ACCEL|ANGACCEL|GYRO|JNTANG|LATENCY|MAGN|MISC|ORNT|POS|VEL)$/ { exit 1 }
            $2 !~ /^(x|y|z|quat_x|quat_y|quat_z|quat_w|n\/a)$/ { exit 1 }' "$c" ||
            { echo "R4 $c"; return 1; }
        grep -q '"TaskName": "' "$j" && grep -Eq '"SamplingFrequency": [0-9.]+,?$' "$j" ||
            { echo "R4 $j"; return 1; }
        nc=$(($(wc -l <"$c") - 1))
        awk -F'\t' -v nc="$nc" 'NF != nc { exit 1 }
            { for (i = 1; i <= NF; i++) if ($i != "n/a" && $i !~ /^-?[0-9]+(\.[0-9]+)?$/) exit 1 }' \
            "$m" || { echo "R5 $rel: rows of other than $nc numbers or n/a"; return 1; }
    done
    [ "$n" -gt 0 ] || { echo "R3 no motion files"; return 1; }
}

# validate DIR: the validator's error count (its summary's "N: [ERR]" lines)
validate() {
    "$V" "$1" >val.out 2>&1
    grep -c '\[ERR\]' val.out
}

rec_header() { # rec_header PARTICIPANT
    printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c0%s\nparticipant %s\n' "${#1}" "$1"
    printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\n'
    printf 'level f\nL mode flag\nL seed 5\nL flag Wrf\nend\n'
}
# hands N: N records at 72 Hz walking north; the left hand untracked in
# records 30..59; a 3 s gap after record 100
hands() {
    awk -v n="$1" 'BEGIN { for (i = 0; i < n; i++) { t = i / 72 + (i > 100 ? 3 : 0)
        f = (i >= 30 && i < 60) ? "d" : "f"
        printf "%.17g f=%s h=1.5,1.6,%.4f,0,0,0,1 l=1.2,1.1,1.4,0,0,0,1 r=1.8,1.2,1.3,0,0.2,0,0.9797959 d=xr-touch\n", t, f, 1.5 - t / 10 } }'
}
{ rec_header P-01; hands 200; } >a.rec
{ rec_header 7; hands 40; } >b.rec
"$H" replay a.rec --log logs --track-hz 45 >/dev/null 2>&1 &&
    "$H" replay b.rec --log logs --track-hz 45 --append >/dev/null 2>&1 && ok ||
    bad "the log folder: $(cat "$T/err" 2>/dev/null)"

# ---- refusals -------------------------------------------------------------------
run "--bids the log folder" 2 "$H" report logs --bids logs && one_line "bids=log" "--bids"
mkdir full && : >full/x
run "--bids not empty" 2 "$H" report logs --bids full && one_line "not empty" "not empty"
run "--bids = --out" 2 "$H" report logs --out same --bids same && one_line "same" "--bids"
[ ! -e same ] && ok || bad "--bids = --out made a folder"
run "--bids in a missing folder" 2 "$H" report logs --bids no/such && one_line "missing" "--bids"

# ---- the export -----------------------------------------------------------------
run "report --out --bids" 0 "$H" report logs --out rep --bids ds &&
    grep -q '^report: 2 runs of head and hand tracks into --bids$' "$T/out" && ok ||
    bad "report --bids said: $(cat "$T/out")"
[ -f rep/attempts.csv ] && ok || bad "--out without its tables beside --bids"
run "report --out alone" 0 "$H" report logs --out rep0 && diff -r rep rep0 >/dev/null && ok ||
    bad "--out's files differ with --bids beside it"
run "report --bids alone" 0 "$H" report logs --bids ds2 && diff -r ds ds2 >/dev/null && ok ||
    bad "--bids alone differs from --bids with --out"
out=$(bids_rules ds) && ok || bad "the export breaks $out"
[ "$(cat ds/participants.tsv)" = "$(printf 'participant_id\tholonomy_id\nsub-P01\tP-01\nsub-P07\tP07')" ] &&
    ok || bad "participants.tsv: $(cat ds/participants.tsv)"
m=$(ls ds/sub-P01/ses-*/motion/*tracksys-room_run-1_motion.tsv)
t=$(ls ds/sub-P01/ses-*/motion/*tracksys-tile_run-1_motion.tsv)
tr=logs/track-001.csv
# every sample a row: the last sample's index + 1 rows, n/a for the gap's
[ "$(wc -l <"$m")" = "$(($(tail -1 $tr | cut -d, -f4) + 1))" ] && ok ||
    bad "room rows $(wc -l <"$m") for samples 0..$(tail -1 $tr | cut -d, -f4)"
awk -F, 'NR > 1 && $7 != "gap" { s = $8; for (i = 9; i <= 28; i++) s = s "\t" $i
        gsub(/\t\t/, "\tn/a\t", s); gsub(/\t\t/, "\tn/a\t", s); sub(/\t$/, "\tn/a", s)
        print $4 "\t" s }' $tr >want
awk '{ print NR - 1 "\t" $0 }' "$m" | grep -Fxf want | wc -l >got
[ "$(cat got)" = "$(wc -l <want)" ] && ok || bad "room rows not the track's: $(cat got) of $(wc -l <want)"
[ "$(grep -c '^n/a	n/a	n/a	n/a' "$m")" -gt 100 ] && ok || bad "the gap's samples not n/a"
grep -q 'n/a' "$m" && awk -F'\t' '$8 == "n/a" && $15 != "n/a" { f = 1 } END { exit !f }' "$m" && ok ||
    bad "the untracked left hand not n/a beside a tracked right"
grep -q '"SamplingFrequency": 45,' "${m%.tsv}.json" && ok || bad "SamplingFrequency not 45"
# the tile frame: orient 0 here, so the room's poses about its centre (1.5, 1.5)
awk -F'\t' 'NR == FNR { x[FNR] = $1; z[FNR] = $3; next }
    $1 != "n/a" && ($1 != sprintf("%.4f", x[FNR] - 1.5) || $3 != sprintf("%.4f", z[FNR] - 1.5)) { f = 1 }
    END { exit f }' "$m" "$t" && ok || bad "tile frame at orient 0 not the room's about its centre"
# ... and a steps file turned by a quarter (orient 1 from t = 0): x_tile = z - 1.5, z_tile = 0
# for the head (on x = 1.5), its quaternion (0, .70711, 0, .70711) times the room's
cp -r logs logs1
printf 'session,attempt,level,t,step,col,row,dir,yaw,tile,orient,remaining,cues,visible\n20260131T140509Z-5f3a9c05,1,f,0.0000,1,1,0,N,0.00,N,1,8,15,5\n' >logs1/steps-001.csv
run "report --bids orient 1" 0 "$H" report logs1 --bids ds1 &&
    awk -F'\t' 'NR == FNR { z[FNR] = $3; next } $1 != "n/a" && ($1 != sprintf("%.4f", z[FNR] - 1.5) ||
        $3 != "0.0000" || $5 != "0.70711" || $7 != "0.70711") { f = 1 } END { exit f }' "$m" \
        ds1/sub-P01/ses-*/motion/*tracksys-tile_run-1_motion.tsv && ok ||
    bad "tile frame at orient 1: $(head -1 ds1/sub-P01/ses-*/motion/*tracksys-tile_run-1_motion.tsv)"

# ---- a malformed track file: one line naming it and its line, exit 2 ------------
cp -r logs logs2
sed -i '5s/,f,3,/,f,x3,/' logs2/track-001.csv
run "a malformed track row" 2 "$H" report logs2 --bids ds3 && one_line "bad track" "track-001.csv: line 5"
[ ! -e ds3 ] && ok || bad "a malformed track file made --bids"

# ---- a broken copy fails the rules -----------------------------------------------
cp -r ds broken
c=$(ls broken/sub-P01/ses-*/motion/*tracksys-room_run-1_channels.tsv)
sed -i '$d' "$c"
out=$(bids_rules broken) && bad "a channels.tsv a row short passed the rules" ||
    { case $out in R5*) ok ;; *) bad "a channels.tsv a row short: $out" ;; esac; }

# ---- npm's bids-validator ---------------------------------------------------------
if ! command -v node >/dev/null 2>&1 || [ ! -x "$V" ]; then
    echo "cli_report_bids: bids-validator skipped (no node or tests/bids/node_modules: make deps-web)"
else
    [ "$(validate ds)" = 0 ] && ok || bad "bids-validator: $(grep -A3 ERR val.out | head -8)"
    cp -r ds broken2
    j=$(ls broken2/sub-P07/ses-*/motion/*tracksys-tile_run-1_motion.json)
    sed -i 's/^{$/{\n  "NotABidsKey": 1,/' "$j"
    [ "$(validate broken2)" -gt 0 ] && ok || bad "bids-validator took a motion.json with an unknown key"
fi
finish cli_report_bids
