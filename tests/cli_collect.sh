#!/bin/sh
# cli_collect.sh - `make web-serve` collecting a class's answers (issue 37;
# docs/teaching.md "Collecting a class's answers"): platform/web/serve.py
# --collect started on 127.0.0.1 with a free port in a scratch folder;
# pupils' answer files sent as the page sends them land as CLASS/HASH.csv
# (the same file twice kept once) and `holonomy report --class` reads the
# folder; hostile uploads are refused and write nothing: class codes that
# are paths (../, /, %2F, dots) or bad, names the client gives, a body
# over the file's bound (refused before it is read), no Content-Length, a
# body that ends early or stalls, files that are not answers files, more
# files, bytes or classes than the bounds (507 full); no temporary file is
# left. Without --collect the server says it does not collect. Each
# server is stopped by its own process id.
. "$(dirname "$0")/lib.sh"
R=$(cd "$(dirname "$0")/.." && pwd)
SERVE="$R/platform/web/serve.py"
PY=python3
[ -x /usr/bin/python3 ] && PY=/usr/bin/python3
if ! command -v "$PY" >/dev/null 2>&1; then
    echo "cli_collect: python3 missing: not checked (make deps-web)"
    echo "cli_collect: 0 passed, 0 failed"
    exit 0
fi

# The client: `send PORT METHOD TARGET BODYFILE [LENGTH [STALL]]` sends a
# raw request (Content-Length LENGTH, "none" for none; default the body's
# size), only the body's bytes, then waits STALL seconds before closing
# (or reading); prints the status and the answer's line. (A request the
# server refuses unread, 411 and 413, is sent with no body: the server's
# close would reset the connection before the answer is read.)
cat >"$T/send.py" <<'PYEOF'
import socket, sys, time
port, method, target, path = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
body = open(path, "rb").read() if path != "-" else b""
length = sys.argv[5] if len(sys.argv) > 5 else str(len(body))
stall = float(sys.argv[6]) if len(sys.argv) > 6 else 0
s = socket.create_connection(("127.0.0.1", port), timeout=20)
head = "%s %s HTTP/1.1\r\nHost: x\r\n" % (method, target)
if length != "none":
    head += "Content-Length: %s\r\n" % length
s.sendall((head + "\r\n").encode() + body)
if stall:
    time.sleep(stall)
    s.shutdown(socket.SHUT_WR)
data = b""
try:
    while True:
        chunk = s.recv(65536)
        if not chunk:
            break
        data += chunk
        if b"\r\n\r\n" in data and data.split(b"\r\n\r\n", 1)[1].endswith(b"\n"):
            break
except (socket.timeout, ConnectionResetError):
    pass
line = data.split(b"\r\n", 1)[0].decode(errors="replace")
text = data.split(b"\r\n\r\n", 1)[1].decode(errors="replace").strip() if b"\r\n\r\n" in data else ""
print(line.split(" ")[1] if " " in line else "none", text)
PYEOF
send() { "$PY" "$T/send.py" "$PORT" "$@" 2>"$T/serr"; }
# want NAME STATUS ARGS...: send ARGS, the status is STATUS
want() {
    name=$1 st=$2; shift 2
    got=$(send "$@")
    case "$got" in "$st "*) ok ;; *) bad "$name: '$got', want $st" ;; esac
}

A='session,participant,attempt,questionnaire,when,item,kind,value,time,shown_ms,answered_ms'
printf '%s\ns1,p01,1,pretest,before_level,square_q5,choice,No,1.5,0,1500\ns1,p01,1,pretest,before_level,corner_q5,likert,5,1.2,1500,2700\n' "$A" >"$T/p01.csv"
printf '%s\ns2,p02,1,pretest,before_level,square_q5,choice,Yes,2.5,0,2500\ns2,p02,2,posttest,before_level,square_q5,choice,No,1.0,9000,10000\n' "$A" >"$T/p02.csv"
printf '%s\ns3,p03,1,pretest,before_level,growth_q5,likert,12,3.0,0,3000\n' "$A" >"$T/p03.csv"
printf '%s\ns4,p04,1,pretest,before_level,home_q5,likert,5,3.0,0,3000\n' "$A" >"$T/p04.csv"

C="$T/collect"
mkdir -p "$T/web"
printf '<!doctype html><title>t</title>\n' >"$T/web/index.html"

# ---- without --collect: not collecting -----------------------------------
if start_server "$T/s0.log" "$T/web" --bind 127.0.0.1 --port 0; then
    ok
    want "no collect: GET" 404 GET /collect -
    want "no collect: POST" 404 POST "/collect?class=4b" -
    stop_server
else
    bad "the server did not start: $(cat "$T/s0.log.err")"
fi

# ---- collecting ---------------------------------------------------------------
if start_server "$T/s1.log" "$T/web" --bind 127.0.0.1 --port 0 --collect "$C" \
    --collect-file 600 --collect-files 3 --collect-folder 700 --collect-classes 2 \
    --collect-timeout 1; then
    ok
    grep -q "^collecting answers into " "$T/s1.log" && ok || bad "no collecting line"
    want "GET collect" 200 GET /collect -
    want "the page still served" 200 GET / -
    # pupils' files
    want "p01 saved" 201 POST "/collect?class=4b" "$T/p01.csv"
    want "p01 again: kept once" 200 POST "/collect?class=4b" "$T/p01.csv"
    want "p02 saved, a name given is no path" 201 POST "/collect?class=4b&name=../../evil.csv" "$T/p02.csv"
    h1=$(sha256sum "$T/p01.csv" | cut -c1-16)
    cmp -s "$T/p01.csv" "$C/4b/$h1.csv" && ok || bad "p01 not stored as 4b/$h1.csv"
    # class codes that are paths or bad
    for code in .. ../x ..%2F..%2Fx %2Fetc a/b . -a _a '' "a%00b" "%C3%A4" 'a%20b' \
        abcdefghijklmnopqrstuvwxyz0123456789; do
        want "class '$code'" 400 POST "/collect?class=$code" "$T/p03.csv"
    done
    want "two class codes" 400 POST "/collect?class=4b&class=4c" "$T/p03.csv"
    want "no class code" 400 POST "/collect" "$T/p03.csv"
    want "a path after collect" 404 POST "/collect/../x?class=4b" -
    # bodies
    want "no Content-Length" 411 POST "/collect?class=4b" - none
    want "a bad Content-Length" 411 POST "/collect?class=4b" - -5
    t0=$(date +%s)
    want "a huge body, not read" 413 POST "/collect?class=4b" - 1000000000
    [ $(($(date +%s) - t0)) -le 3 ] && ok || bad "a huge body took long"
    want "a body that ends early" 400 POST "/collect?class=4b" "$T/p03.csv" 400 0.1
    want "a body that stalls" 400 POST "/collect?class=4b" "$T/p03.csv" 300 3
    printf 'session,participant\nx,y\n' >"$T/other.csv"
    want "not an answers file" 400 POST "/collect?class=4b" "$T/other.csv"
    { cat "$T/p03.csv"; printf 'a\0b\n'; } >"$T/nul.csv"
    want "a NUL in it" 400 POST "/collect?class=4b" "$T/nul.csv"
    { cat "$T/p03.csv"; printf 'a\377b\n'; } >"$T/bin.csv"
    want "not UTF-8" 400 POST "/collect?class=4b" "$T/bin.csv"
    # the bounds: 3 files, 700 bytes a folder, 2 folders
    want "p03 saved (the third)" 201 POST "/collect?class=4b" "$T/p03.csv"
    want "a fourth file: full" 507 POST "/collect?class=4b" "$T/p04.csv"
    want "another class" 201 POST "/collect?class=4c_2" "$T/p01.csv"
    awk -v a="$A" 'BEGIN { print a; for (i = 0; i < 8; i++) print "s9,p09,1,pretest,before_level,home_q5,likert,5,3.0,0,3000" }' >"$T/big.csv"
    want "over the folder's bytes: full" 507 POST "/collect?class=4c_2" "$T/big.csv"
    want "a third class: full" 507 POST "/collect?class=5a" "$T/p01.csv"
    want "the server still serves" 200 GET /collect -
    # what is on disk: the two folders, their files, nothing else
    (cd "$C" && find . | LC_ALL=C sort) >"$T/tree"
    h2=$(sha256sum "$T/p02.csv" | cut -c1-16) h3=$(sha256sum "$T/p03.csv" | cut -c1-16)
    printf '.\n./4b\n./4b/%s.csv\n./4b/%s.csv\n./4b/%s.csv\n./4c_2\n./4c_2/%s.csv\n' \
        "$h1" "$h2" "$h3" "$h1" | LC_ALL=C sort >"$T/tree.want"
    cmp -s "$T/tree" "$T/tree.want" && ok || { bad "the collect folder holds:"; cat "$T/tree"; }
    [ ! -e "$T/evil.csv" ] && [ ! -e "$R/evil.csv" ] && ok || bad "a client's name was used"
    stop_server
else
    bad "the server did not start: $(cat "$T/s1.log.err")"
fi

# ---- bad arguments ----------------------------------------------------------------
"$PY" "$SERVE" "$T/web" --port 0 --collect "$C" --collect-files 0 >"$T/out" 2>"$T/err"
[ $? = 2 ] && grep -q "at least 1" "$T/err" && ok || bad "--collect-files 0 taken"

# ---- the teacher's report reads the class folder ----------------------------------
if run "report --class" 0 "$H" report --class "$C/4b" --out "$T/rep"; then
    for p in p01 p02 p03; do
        grep -q "^$p," "$T/rep/class_pupils.csv" && ok || bad "report: no $p"
    done
fi

echo "cli_collect: $passes passed, $fails failed"
[ "$fails" = 0 ]
