# lib.sh - shared helpers of the shell tests (tests/cli_*.sh source it).
# Sets H (the binary, $HOLONOMY or build/holonomy) and T (a scratch folder
# removed on exit); counts checks; `finish NAME` prints the closing line
# "NAME: N passed, M failed" and sets the exit status.
set -u
H=${HOLONOMY:-build/holonomy}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fails=0 passes=0
ok() { passes=$((passes + 1)); }
bad() { fails=$((fails + 1)); echo "FAIL: $*"; }

# expect NAME STATUS STDOUT CMD...: stdin from $T/in; checks status and stdout
expect() {
  name=$1 want_status=$2 want_out=$3; shift 3
  "$@" <"$T/in" >"$T/out" 2>"$T/err"; st=$?
  printf '%s' "$want_out" >"$T/want"
  if [ "$st" != "$want_status" ]; then bad "$name: status $st, want $want_status"; return; fi
  if ! cmp -s "$T/out" "$T/want"; then bad "$name: stdout differs"; diff "$T/want" "$T/out" | head -5; return; fi
  ok
}

# expect_status NAME STATUS CMD...: stdin from $T/in; checks the status only
expect_status() {
  name=$1 want_status=$2; shift 2
  "$@" <"$T/in" >"$T/out" 2>"$T/err"; st=$?
  if [ "$st" != "$want_status" ]; then bad "$name: status $st, want $want_status"; else ok; fi
}

# run NAME STATUS CMD...: no stdin redirection; stdout in $T/out, stderr in $T/err
run() {
  name=$1 want=$2; shift 2
  "$@" >"$T/out" 2>"$T/err"; st=$?
  if [ "$st" != "$want" ]; then bad "$name: status $st, want $want ($(head -c 200 "$T/err"))"; return 1; fi
  ok
}

# err_one_nl: the last stderr holds exactly one newline (`wc -l` is 1),
# counted in the shell (a `wc` and a subshell a check before, about 300
# checks in the suites): a first line read to its newline, then no other
# (a last line without its newline counts as none, as for wc)
err_one_nl() { { IFS= read -r _l && ! IFS= read -r _l; } <"$T/err"; }

# err_line TEXT: the last stderr is exactly one line mentioning TEXT
err_line() {
  if ! err_one_nl || ! grep -q -- "$1" "$T/err"; then
    bad "stderr should be one line with '$1', got: $(cat "$T/err")"; else ok; fi
}

# one_line NAME TEXT: the last stderr is exactly one line mentioning TEXT
one_line() {
  if ! err_one_nl || ! grep -q -- "$2" "$T/err"; then
    bad "$1: stderr should be one line with '$2', got: $(cat "$T/err")"; else ok; fi
}

# walk_input WALK [T0] [BUTTONS]: input record lines (core/hol_input_io.h)
# of a tracked head standing at the cell centres of the room steps WALK
# from cell (1,1), from time T0 (default 0), 0.25 s a step ('-' for none);
# the first line holds BUTTONS (hex) if given
walk_input() {
    printf '%s\n' "$1" | awk -v t0="${2:-0}" -v b="${3:-}" '{
        c = 1; r = 1; t = t0 + 0
        printf "%s f=9%s h=%.1f,1.6,%.1f,0,0,0,1\n", t, (b == "" ? "" : " b=" b), c + 0.5, r + 0.5
        n = length($0); if ($0 == "-") n = 0
        for (i = 1; i <= n; i++) {
            d = substr($0, i, 1)
            if (d == "N") r--; if (d == "S") r++; if (d == "E") c++; if (d == "W") c--
            t += 0.25
            printf "%s f=9 h=%.1f,1.6,%.1f,0,0,0,1\n", t, c + 0.5, r + 0.5
        }
    }'
}

# start_xvfb [SALT]: an Xvfb of its own, killed when the script ends;
# exports DISPLAY once the server accepts clients. Xvfb picks a free display
# number itself and writes it to a FIFO when it is ready (-displayfd), so
# nothing polls: the read blocks until then (or until Xvfb ends, at once,
# when it cannot start: a failed check, then DISPLAY names no server and
# every window check fails). SALT is not used any more (the number was made
# from the script's pid and SALT, and the readiness polled with a play of 2
# frames: about 1 s of CPU a start). -noreset: the server is not reset each
# time its last client leaves (each play, each xdotool: Xvfb's reset and an
# xkbcomp, about 1.5 s of CPU in cli_play's 19). Returns 1 (nothing
# started) without Xvfb.
start_xvfb() {
    command -v Xvfb >/dev/null 2>&1 || return 1
    rm -f "$T/.xvfb.fd"
    mkfifo "$T/.xvfb.fd" || { bad "Xvfb: no FIFO in $T"; return 0; }
    Xvfb -displayfd 3 -screen 0 320x240x24 -nolisten tcp -noreset 3>"$T/.xvfb.fd" >/dev/null 2>&1 &
    XPID=$!
    trap 'kill $XPID 2>/dev/null; rm -rf "$T"' EXIT
    read -r xvfb_n <"$T/.xvfb.fd" || xvfb_n=
    rm -f "$T/.xvfb.fd"
    case $xvfb_n in
    [0-9]*) export DISPLAY=":$xvfb_n" ;;
    *) bad "Xvfb did not start"; export DISPLAY=":none" ;;
    esac
}

# wait_for SECONDS COND...: until a COND holds (0) or SECONDS pass (1):
# -e PATH exists, -n DIR PREFIX N (at least N entries named PREFIX...),
# -c DIR N (other than N entries, dot files not counted), -l FILE N (at
# least N lines), -p PID ended. tests/wait_for.c ($WAIT_FOR, which make
# test and make cli-run-NAME build) polls in one process every 5 ms; a
# suite run by hand needs it built (make build/tests/wait_for): without
# it, the wait says so and fails (2), and so does the check.
WAIT_FOR=${WAIT_FOR:-$(dirname "$H")/tests/wait_for}
case $WAIT_FOR in /*) ;; *) WAIT_FOR=$(pwd)/$WAIT_FOR ;; esac
wait_for() {
    [ -x "$WAIT_FOR" ] || { echo "wait_for: $WAIT_FOR is not built (make build/tests/wait_for)" >&2
                            return 2; }
    "$WAIT_FOR" "$@"
}

# A replay's logs against the play's: every file byte for byte, but
# environment.csv, study-HASH.txt and order.csv, which only a live session
# writes (docs/research.md: Session metadata; docs/logs.md: Provenance and
# codebook), and provenance.csv, which names the build that wrote the folder
# (a replay by another build, or of one session of an appended folder,
# has other rows). codebook.csv is compared: one build writes one.
logs_diff() { diff -r -x environment.csv -x 'study-*.txt' -x order.csv -x provenance.csv "$@"; }

# start_server LOG ARGS...: platform/web/serve.py ($PY $SERVE, which the
# suite sets) with ARGS in the background; sets SPID and PORT from its first
# line (within 10 s); 1 when it did not start (cli_serve, cli_collect)
start_server() {
    log=$1; shift
    "$PY" "$SERVE" "$@" >"$log" 2>"$log.err" &
    SPID=$!
    for _ in $(seq 1 50); do
        PORT=$(sed -n 's|^serving .* on https*://127\.0\.0\.1:\([0-9]*\)/.*|\1|p' "$log")
        [ -n "$PORT" ] && return 0
        kill -0 "$SPID" 2>/dev/null || return 1
        sleep 0.2
    done
    return 1
}
# stop_server: SIGTERM to SPID, ended within 5 s (ok) or not (bad, SIGKILL)
stop_server() {
    kill "$SPID" 2>/dev/null
    for _ in $(seq 1 25); do kill -0 "$SPID" 2>/dev/null || break; sleep 0.2; done
    if kill -0 "$SPID" 2>/dev/null; then bad "server $SPID did not stop on SIGTERM"; kill -9 "$SPID"; else ok; fi
    wait "$SPID" 2>/dev/null
}

finish() {
  echo "$1: $passes passed, $fails failed"
  [ "$fails" = 0 ]
}
