#!/bin/sh
# cli_track.sh - the tracker rows (issue 26 item 6): track-NNN.csv, the head
# and both hands at exact samples k / hz of level time, `--track-hz N` on
# play, xr and replay (10..90, default 10). Each check failed before the
# change (no track file, no option):
# - the option's refusals: one line, exit 2, nothing made;
# - a replay at 90 Hz of records with hand poses: every sample once, their
#   count against a brute-force count, hands empty where not tracked;
# - a play (--input, under Xvfb) with hand poses at --track-hz 90 and its
#   replay at 90 Hz: every log file byte for byte; environment.csv names
#   the rate; a killed recording (REC.live) replays with its track file;
# - `report` reads a folder with track files.
. "$(dirname "$0")/lib.sh"
H=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
cd "$T" || exit 1

rec_header() {
    printf 'holonomy-rec 2\nsession 20260131T140509Z-5f3a9c01\nparticipant P01\n'
    printf 'start 2026-01-31T14:05:09Z\nversion 0.1.0\n'
    printf 'level f\nL mode flag\nL seed 5\nL flag Nf\nend\n'
}
# hand_input N: N records at 72 Hz, a tracked head walking east slowly; the
# left controller tracked in all but records 30..59, the right in every one
hand_input() {
    awk -v n="$1" 'BEGIN { for (i = 0; i < n; i++) { t = i / 72; x = 1.5 + 0.1 * t
        f = (i >= 30 && i < 60) ? "d" : "f"
        printf "%.17g f=%s h=%.4f,1.6,1.5,0,0,0,1 l=%.4f,1.1,1.4,0,0,0,1 r=%.4f,1.2,1.3,0,0.2,0,0.9797959 d=xr-touch\n", t, f, x, x - 0.3, x + 0.3 } }'
}

# ---- the option ------------------------------------------------------------------
{ rec_header; hand_input 3; } >r.rec
for v in 9 91 0 abc 4.5 '' -10 +20 1e1 0x10 ' 20'; do
    run "replay --track-hz '$v'" 2 "$H" replay r.rec --log bad --track-hz "$v" &&
        one_line "replay --track-hz '$v'" "--track-hz"
    [ ! -e bad ] && ok || bad "--track-hz '$v' made the log folder"
done
run "--track-hz without --log" 2 "$H" replay r.rec --track-hz 20 && one_line "no log" "goes with --log"
run "play --track-hz 91" 2 "$H" play --track-hz 91 --log p && one_line "play 91" "10..90"
run "play --track-hz=abc" 2 "$H" play --track-hz=abc --log p && one_line "play abc" "--track-hz"
run "xr --track-hz 5" 2 "$H" xr --track-hz 5 --log p && one_line "xr 5" "--track-hz"
run "play repeated --track-hz" 2 "$H" play --track-hz 20 --track-hz 30 --log p &&
    one_line "repeated" "--track-hz"
for c in play xr replay; do
    "$H" $c --help 2>&1 | grep -q -- '--track-hz N' && ok || bad "$c --help names no --track-hz"
done

# ---- a replay at 90 Hz: every sample once, against a brute-force count ----------
{ rec_header; hand_input 216; } >h.rec
run "replay 90 Hz" 0 "$H" replay h.rec --log r90 --track-hz 90
f=r90/track-001.csv
[ "$(head -1 $f)" = "session,attempt,level,sample,t,frame_t,device,head_x,head_y,head_z,head_qx,head_qy,head_qz,head_qw,left_x,left_y,left_z,left_qx,left_qy,left_qz,left_qw,right_x,right_y,right_z,right_qx,right_qy,right_qz,right_qw" ] &&
    ok || bad "track columns: $(head -1 $f)"
# the last record at 215/72 s: samples k with k/90 <= 215/72, i.e. 72k <= 215*90
want=$(awk 'BEGIN { k = 0; while (72 * (k + 1) <= 215 * 90) k++; print k + 1 }')
[ "$(($(wc -l <$f) - 1))" = "$want" ] && ok || bad "90 Hz rows: $(($(wc -l <$f) - 1)), want $want"
awk -F, 'NR > 1 && ($4 != NR - 2 || $5 != sprintf("%.4f", (NR - 2) / 90)) { bad = 1 } END { exit bad }' $f &&
    ok || bad "samples not k = 0, 1, 2, ... at k / 90: $(cut -d, -f4,5 $f | head -5 | tr '\n' ' ')"
# left: empty exactly for samples whose nearer record is 30..59 (t in ~[0.41, 0.82])
awk -F, 'NR > 1 { t = $5 + 0; e = ($15 == ""); near = int(t * 72 + 0.5)
    if (e != (near >= 30 && near < 60)) bad = 1; if ($22 == "") bad = 1 } END { exit bad }' $f &&
    ok || bad "left hand fields not empty exactly where untracked"
awk -F, 'NR > 1 && $28 != "" { if ($25 != "0.00000" || $26 != "0.20000") bad = 1 } END { exit bad }' $f &&
    ok || bad "right hand quaternion: $(sed -n 2p $f)"
# the head file keeps its 10 Hz
[ "$(($(wc -l <r90/head-001.csv) - 1))" = 30 ] && ok || bad "head rows: $(wc -l <r90/head-001.csv)"
# the default: 10 Hz, the same samples as the head file's
run "replay default" 0 "$H" replay h.rec --log r10
[ "$(cut -d, -f5 r10/track-001.csv | sed 1d | tr '\n' ' ')" = "$(cut -d, -f4 r10/head-001.csv | sed 1d | sed 's/$/000/' | tr '\n' ' ')" ] &&
    ok || bad "10 Hz track times differ from the head file's"
run "report on track logs" 0 "$H" report r90 --out rep

# a killed session's recording (REC.live): the track file is renamed
cp h.rec k.rec.live
run "replay REC.live" 0 "$H" replay k.rec.live --log rk --track-hz 90
[ -f rk/track-001.csv ] && [ ! -e rk/track-001.csv.live ] && cmp -s rk/track-001.csv r90/track-001.csv &&
    ok || bad "killed replay's track file: $(ls rk)"
# a folder of an older build (no track file) takes --append
mkdir old && cp r10/summary.csv r10/steps-001.csv r10/head-001.csv r10/level-*.txt old/
run "append to an older folder" 0 "$H" replay h.rec --log old --append --track-hz 45
[ -f old/track-002.csv ] && ok || bad "append: $(ls old)"

# ---- a play at 90 Hz and its replay: byte for byte ---------------------------------
if start_xvfb 61; then
    hand_input 150 >in.txt
    printf 'mode flag\nseed 5\nflag Nf\n' >f.lvl
    run "play --track-hz 90" 0 "$H" play f.lvl --input in.txt --size 64x48 --record p.rec \
        --log P --track-hz 90
    run "its replay" 0 "$H" replay p.rec --log R --track-hz 90
    logs_diff P R >d.txt && ok || bad "replay at 90 Hz differs: $(head -5 d.txt)"
    [ "$(($(wc -l <P/track-001.csv) - 1))" -gt 180 ] && ok || bad "play rows: $(wc -l <P/track-001.csv)"
    grep -q -- '--track-hz 90' P/environment.csv && ok || bad "environment.csv: $(cat P/environment.csv)"
    run "replay at another rate" 0 "$H" replay p.rec --log R10
    cmp -s P/track-001.csv R10/track-001.csv && bad "10 Hz replay gave the 90 Hz rows" || ok
else
    echo "cli_track: no Xvfb, the play checks skipped"
fi

finish cli_track
