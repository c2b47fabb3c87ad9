#!/bin/sh
# cli_sound.sh - holonomy replay --wav (issue 27, docs/sound.md): recordings
# written here by hand (a head standing or stepping at cell centres, facing
# room north), their sound rendered offline through OpenAL Soft's loopback
# device and read back: a beacon due east is louder in the right channel
# and one due west in the left; the beacon's level falls with the true
# distance as core/hol_sound.h documents (an independent model here, in
# awk); footstep onsets fall on the room steps; `sound off` is silent; the
# same recording gives the same bytes; the file is a 16-bit stereo 48 kHz
# WAV; outputs never name an input.
. "$(dirname "$0")/lib.sh"

run "--help" 0 "$H" replay --help && grep -q -- "--wav FILE" "$T/out" && ok ||
    bad "replay --help does not describe --wav"

if [ ! -e /usr/lib/x86_64-linux-gnu/libopenal.so.1 ] && ! ldconfig -p 2>/dev/null | grep -q libopenal.so.1; then
    echo "note: no libopenal.so.1 here: the WAV is not tested"
    finish cli_sound
    exit $?
fi

# rec NAME SECONDS LEVEL-LINES... : a recording standing at cell (1,1)
# for SECONDS in 0.05 s records; WALK (env) adds room steps at 1.5 s, 0.5 s apart
rec() {
    name=$1 secs=$2; shift 2
    {
        printf 'holonomy-rec 2\nsession 20261126T000000Z-00000000\nstart 2026-11-26T00:00:00Z\n'
        printf 'version 0.1.0\nlevel %s\n' "$name"
        for l in "$@"; do printf 'L %s\n' "$l"; done
        printf 'end\n'
        awk -v secs="$secs" -v walk="${WALK:-}" 'BEGIN {
            c = 1; r = 1; k = 1; n = length(walk)
            for (i = 0; i * 0.05 <= secs + 1e-9; i++) {
                t = i * 0.05
                if (k <= n && t >= 1.5 + (k - 1) * 0.5 - 1e-9) {
                    d = substr(walk, k, 1); k++
                    if (d == "N") r--; if (d == "S") r++; if (d == "E") c++; if (d == "W") c--
                }
                printf "%.2f f=9 h=%.1f,1.6,%.1f,0,0,0,1\n", t, c + 0.5, r + 0.5
            }
        }'
    } >"$T/$name.rec"
}

# stats FILE FROM TO: "L R" the mean square of each channel between seconds FROM and TO
stats() {
    od -An -v -t d2 -j 44 "$1" | awk -v a="$2" -v b="$3" '{
        for (i = 1; i <= NF; i++) {
            f = int(k / 2); ch = k % 2; k++
            if (f >= a * 48000 && f < b * 48000) { s[ch] += $i * $i; m[ch]++ }
        }
    } END { printf "%.6g %.6g\n", s[0] / (m[0] ? m[0] : 1), s[1] / (m[1] ? m[1] : 1) }'
}

# the header: RIFF WAVE, PCM, 2 channels, 48000 Hz, 16 bits
rec east 4 "mode flag" "seed 5" "flag Ef" "cues sound" "sound cues"
run "east" 0 "$H" replay "$T/east.rec" --wav "$T/east.wav"
hdr=$(od -An -v -t x1 -N 44 "$T/east.wav" | tr -d ' \n')
case "$hdr" in
52494646????????57415645666d7420100000000100020080bb000000ee02000400100064617461????????) ok ;;
*) bad "not a 16-bit stereo 48 kHz WAV: $hdr" ;;
esac
# 4 s of records plus 1 s: 5 s of frames
sz=$(wc -c <"$T/east.wav")
[ "$sz" -eq $((44 + 5 * 48000 * 4)) ] && ok || bad "east.wav is $sz bytes, want $((44 + 5 * 48000 * 4))"

# east: right louder; west: left louder (beyond the start chime: 1.5 s to 3.5 s)
set -- $(stats "$T/east.wav" 1.5 3.5)
awk -v l="$1" -v r="$2" 'BEGIN { exit !(r > 2 * l && r > 1000) }' && ok ||
    bad "a beacon due east is not louder on the right: L $1 R $2"
rec west 4 "mode flag" "seed 5" "flag Wf" "cues sound" "sound cues"
run "west" 0 "$H" replay "$T/west.rec" --wav "$T/west.wav"
set -- $(stats "$T/west.wav" 1.5 3.5)
awk -v l="$1" -v r="$2" 'BEGIN { exit !(l > 2 * r && l > 1000) }' && ok ||
    bad "a beacon due west is not louder on the left: L $1 R $2"

# the same recording, the same bytes
run "east again" 0 "$H" replay "$T/east.rec" --wav "$T/east2.wav"
cmp -s "$T/east.wav" "$T/east2.wav" && ok || bad "the same recording gave other bytes"

# the level falls with the true distance: the beacon 1, 2 and 3 tiles east
# (floor k m: centres on one geodesic, a step is a cell), 0.1 m below the
# ear; model G(d) = sqrt(x/sinh x) / (1 + d), x = k e the floor
# distance in curvature units, e = 2 acosh(cos(pi/5)/sin(pi/4)).
# The power ratio is the square of the gain ratio (the same direction, so
# the same pan law), within 3 %.
for f in E Ef Eff; do
    rec "d$f" 4 "mode flag" "seed 5" "flag $f" "cues sound" "sound cues"
    run "distance $f" 0 "$H" replay "$T/d$f.rec" --wav "$T/d$f.wav"
    stats "$T/d$f.wav" 1.5 3.5 >"$T/d$f.st"
done
for f in Ef Eff; do
    k=$(printf '%s' "$f" | wc -c)
    awk -v k="$k" -v a="$(cat "$T/dE.st")" -v b="$(cat "$T/d$f.st")" 'BEGIN {
        split(a, A, " "); split(b, B, " ")
        pi = 3.14159265358979; c = cos(pi / 5) / sin(pi / 4); e = 2 * log(c + sqrt(c * c - 1))
        x1 = e; xk = k * e; d1 = sqrt(1 + 0.01); dk = sqrt(k * k + 0.01)
        g1 = sqrt(x1 / ((exp(x1) - exp(-x1)) / 2)) / (1 + d1)
        gk = sqrt(xk / ((exp(xk) - exp(-xk)) / 2)) / (1 + dk)
        want = (gk / g1) ^ 2; got = (B[1] + B[2]) / (A[1] + A[2])
        if (got < want * 0.97 || got > want * 1.03) { print want, got; exit 1 }
    }' >"$T/ratio" && ok || bad "beacon $k tiles east: power ratio (want, got) $(cat "$T/ratio")"
done

# footsteps: onsets at the room steps (1.5 s, 2 s, 2.5 s: E, N, W), no
# beacon (the flag far), no ambience; the start chime is over by 1.2 s
WALK=ENW rec steps 3.5 "mode flag" "seed 5" "flag Wrf" "cues poles" "sound cues"
run "steps" 0 "$H" replay "$T/steps.rec" --wav "$T/steps.wav"
od -An -v -t d2 -j 44 "$T/steps.wav" | awk '{
    for (i = 1; i <= NF; i++) {
        f = int(k / 2); k++
        if (f < 1.3 * 48000) continue
        a = $i < 0 ? -$i : $i
        if (a > 300 && f - last > 0.3 * 48000) { printf "%.3f\n", f / 48000; }
        if (a > 300) last = f
    }
}' >"$T/onsets"
awk 'BEGIN { split("1.5 2 2.5", w, " ") } { n++; d = $1 - w[n]; if (d < 0 || d > 0.005) exit 1 }
    END { exit n != 3 }' "$T/onsets" && ok ||
    bad "footstep onsets $(tr '\n' ' ' <"$T/onsets"), want 1.5 2 2.5 (within 5 ms)"

# sound off: every sample zero (with a beacon cue and steps)
WALK=ENW rec off 3.5 "mode flag" "seed 5" "flag Ef" "cues sound" "sound off"
run "off" 0 "$H" replay "$T/off.rec" --wav "$T/off.wav"
nz=$(od -An -v -t d2 -j 44 "$T/off.wav" | tr -s ' ' '\n' | grep -c -v '^0*$')
[ "$nz" -eq 0 ] && ok || bad "sound off: $nz samples not zero"

# sound all: the forest is heard (birds, water, wind) with nothing else
rec all 3 "mode explore" "seed 5" "sound all"
run "all" 0 "$H" replay "$T/all.rec" --wav "$T/all.wav"
set -- $(stats "$T/all.wav" 1.5 3)
awk -v l="$1" -v r="$2" 'BEGIN { exit !(l > 1000 && r > 1000) }' && ok ||
    bad "sound all: the ambience is silent: L $1 R $2"

# the output never names the recording; a bad level line is refused
run "wav is the recording" 2 "$H" replay "$T/east.rec" --wav "$T/east.rec" &&
    one_line "wav input" "--wav"
printf 'mode flag\nflag Wrf\nsound loud\n' >"$T/bad.lvl"
run "bad sound line" 2 "$H" game "$T/bad.lvl" && one_line "sound line" "not all, cues or off"
printf 'mode flag\nflag Wrf\ncues sound poles\nsound cues\n' >"$T/ok.lvl"
printf '' >"$T/in"
expect_status "sound cue accepted" 0 "$H" game "$T/ok.lvl"
# no half-written file: a folder that does not exist
run "wav in a missing folder" 2 "$H" replay "$T/east.rec" --wav "$T/nope/x.wav" &&
    one_line "missing folder" "nope"
finish cli_sound
