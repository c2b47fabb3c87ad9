# mock_study_gen.awk - one participant's --input lines for the mock 2 x 2
# studies (tests/cli_mock_study.sh, tests/cli_mock_study_r.sh): practice,
# four conditions of two levels, the pointing question after each level,
# the SSQ after each condition, a closing screen.
# -v plan=...: a letter per condition level in play order: D the optimal
# walk (done), L a longer walk (done), T a wrong step then the time limit
# (3 s), R a wrong step, restart, the optimal walk. Lines 0.25 s apart (a
# line a second while standing); after a level, the head back in cell
# (1,1) turned to a yaw of its own, confirm (the pointing), confirm (the
# end screen); instructions: confirm, then confirm (the ready screen). SSQ item i of the condition at position k answered
# (3i + 5p + 7k + p int(i/4)) mod 4: the middle mark is 1, t= moves one
# mark down, m= one up, confirm answers. -v kill=K: the lines end 2 s
# into slot K (a step east, then 30,000 frames 30 us apart, so that the
# session is killed there); -v from=K starts at slot K (a resumed session,
# whose first level mid-condition begins on the ready screen:
# no practice).
# -v tlx=1: the TLX after the last SSQ (the study's `after study`), item i
# answered 50 + 5 ((3i + p) mod 5 - 2). -v killq=K (K odd): the lines end
# in the SSQ after slot K, its items 1..5 answered (stalled as for kill);
# -v ssqfrom=I with from=K+1: the resumed session first answers that
# SSQ's items I..16.
function line(extra, c, r) {
    printf "%.2f f=9%s h=%.1f,1.6,%.1f,%s\n", t, extra, c + 0.5, r + 0.5, q
    t += 0.25
}
function quat(y,   h) { h = y * 3.14159265358979 / 360; return sprintf("0,%.7f,0,%.7f", sin(h), cos(h)) }
function level(w, c0, r0, y, point,   i, c, r, d, L) {
    L = t; c = c0; r = r0; q = quat(0)
    line("", c, r)
    for (i = 1; i <= length(w); i++) {
        d = substr(w, i, 1)
        if (d == "N") r--; if (d == "S") r++; if (d == "E") c++; if (d == "W") c--
        line("", c, r)
    }
    if (t < L + 1) t = L + 1
    while (t <= L + 3.01) { line("", c, r); t += 0.75 }
    t = L + 3.25; q = quat(y)
    line("", 1, 1)
    if (point) { line(" p=1", 1, 1); line("", 1, 1) }  # the pointing's confirm
    line(" p=1", 1, 1)                                  # the end screen's
}
function screen(ready) { q = quat(0); line("", 1, 1); line(" p=1", 1, 1); if (ready) line(" p=1", 1, 1) }
function ssq(k, lo, hi,   i, v) {
    q = quat(0)
    for (i = lo; i <= hi; i++) {
        v = (i * 3 + p * 5 + k * 7 + int(i / 4) * p) % 4
        if (v == 0) line(" t=1,0", 1, 1)
        if (v >= 2) line(" m=1,0", 1, 1)
        if (v == 3) { line("", 1, 1); line(" m=1,0", 1, 1) }
        line(" p=1", 1, 1)
    }
}
function tlx_items(   i, d, j) {
    q = quat(0)
    for (i = 1; i <= 6; i++) {
        d = (3 * i + p) % 5 - 2
        for (j = 1; j <= (d < 0 ? -d : d); j++) {
            if (j > 1) line("", 1, 1)
            line(d < 0 ? " t=1,0" : " m=1,0", 1, 1)
        }
        line(" p=1", 1, 1)
    }
}
function stall(   i) {
    for (i = 1; i <= 30000; i++)
        printf "%.5f f=9 h=1.5,1.6,1.5,%s\n", t - 0.25 + i * 0.00003, q
}
BEGIN {
    t = 0; if (kill == "") kill = -1; if (killq == "") killq = -1; if (from == "") from = 0
    if (from == 0) { screen(1); q = quat(0); level("N", 1, 1, 0, 0) }
    if (ssqfrom != "") ssq(int((from - 1) / 2) + 1, ssqfrom, 16)
    if (from % 2 == 1) { q = quat(0); line("", 1, 1); line(" p=1", 1, 1) } # a resume's ready screen
    for (s = from; s < 8; s++) {
        if (s % 2 == 0) screen(1)           # the condition's instructions, the ready screen
        a = substr(plan, s + 1, 1); y = (37 * s + 61 * p) % 360
        if (s == kill) {
            q = quat(0); line("", 1, 1); line("", 2, 1); t += 0.5; line("", 2, 1)
            t += 0.75; line("", 2, 1)
            for (i = 1; i <= 30000; i++)
                printf "%.5f f=9 h=2.5,1.6,1.5,%s\n", t - 0.25 + i * 0.00003, q
            exit
        }
        best = s % 2 ? "WS" : "N"; long = s % 2 ? "EWWS" : "EWN"
        if (a == "D") level(best, 1, 1, y, 1)
        if (a == "L") level(long, 1, 1, y, 1)
        if (a == "T") level("E", 1, 1, y, 1)
        if (a == "R") {
            q = quat(0); line("", 1, 1); line("", 2, 1); line(" p=20", 2, 1)
            level(best, 2, 1, y, 1)
        }
        if (s == killq) { ssq(int(s / 2) + 1, 1, 5); stall(); exit }
        if (s % 2 == 1) ssq(int(s / 2) + 1, 1, 16)
    }
    if (tlx) tlx_items()
    screen(); line("", 1, 1)                # the closing screen
}
