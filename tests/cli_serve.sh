#!/bin/sh
# cli_serve.sh - a fresh machine and serving the web build (issue 25 item 8):
# platform/web/serve.py started on 127.0.0.1 with a free port, fetched with
# curl (Accept-Encoding br, gzip, none; Content-Encoding, Cache-Control,
# ETag and 304, types, nothing outside the folder), stopped; HTTPS with the
# certificate of platform/web/make_cert.sh; platform/debian/apt_get.sh waiting for an
# apt lock (a fake apt-get); the make targets' order and messages.
# Loopback only, everything in a scratch folder; each server is stopped by
# its own process id.
. "$(dirname "$0")/lib.sh"
R=$(cd "$(dirname "$0")/.." && pwd)
SERVE="$R/platform/web/serve.py"
# Debian's python3 (deps-web) when there; a python3 on PATH otherwise
PY=python3
[ -x /usr/bin/python3 ] && PY=/usr/bin/python3

if ! command -v "$PY" >/dev/null 2>&1 || ! command -v curl >/dev/null 2>&1; then
    echo "cli_serve: python3 or curl missing: the server is not checked (make deps-web)"
    skip_server=1
else
    skip_server=0
fi

# fetch NAME PATH [HEADER]: headers in $T/h (lower case), body in $T/b
fetch() {
    curl -sS --max-time 10 -o "$T/b" -D "$T/h0" ${3:+-H "$3"} "http://127.0.0.1:$PORT$2" 2>"$T/cerr" ||
        { bad "$1: curl failed: $(cat "$T/cerr")"; return 1; }
    tr -d '\r' <"$T/h0" | tr 'A-Z' 'a-z' >"$T/h"
}
header() { sed -n "s/^$1: //p" "$T/h" | head -1; }

if [ "$skip_server" = 0 ]; then
    W="$T/web" Z="$T/web-z"
    mkdir -p "$W" "$Z"
    awk 'BEGIN { for (i = 0; i < 3000; i++) printf "%d holonomy %d\n", i, i * i % 97 }' >"$W/holonomy.wasm"
    awk 'BEGIN { print "<!doctype html><title>t</title>"; for (i = 0; i < 200; i++) print "<p>line " i "</p>" }' >"$W/index.html"
    awk 'BEGIN { for (i = 0; i < 400; i++) print "var a" i " = " i ";" }' >"$W/page.js"
    printf 'tiny\n' >"$W/small.js"
    printf 'secret\n' >"$W/.hidden"
    printf 'outside\n' >"$T/outside.txt"
    gzip -9 -n -c "$W/holonomy.wasm" >"$Z/holonomy.wasm.gz"
    have_br=0
    if command -v brotli >/dev/null 2>&1; then
        brotli -q 11 -c "$W/holonomy.wasm" >"$Z/holonomy.wasm.br" && have_br=1
    else
        echo "cli_serve: brotli missing: the br checks are skipped (make deps-web installs it)"
    fi
    touch -d '2020-01-01' "$W/holonomy.wasm"

    if start_server "$T/log" "$W" --precompressed "$Z" --bind 127.0.0.1 --port 0; then
        ok
        if [ "$have_br" = 1 ] && fetch "br" /holonomy.wasm "Accept-Encoding: gzip, deflate, br"; then
            [ "$(header content-encoding)" = br ] && cmp -s "$T/b" "$Z/holonomy.wasm.br" &&
                brotli -d -c "$T/b" | cmp -s - "$W/holonomy.wasm" && ok || bad "br: not the .br file"
            [ "$(header cache-control)" = no-cache ] && ok || bad "br: Cache-Control '$(header cache-control)'"
            [ "$(header content-type)" = application/wasm ] && ok || bad "br: type '$(header content-type)'"
            [ "$(header vary)" = accept-encoding ] && ok || bad "br: no Vary"
        fi
        if fetch "gzip" /holonomy.wasm "Accept-Encoding: gzip"; then
            [ "$(header content-encoding)" = gzip ] && cmp -s "$T/b" "$Z/holonomy.wasm.gz" &&
                gzip -dc "$T/b" | cmp -s - "$W/holonomy.wasm" && ok || bad "gzip: not the .gz file"
            [ "$(header cache-control)" = no-cache ] && ok || bad "gzip: Cache-Control"
            tag=$(header etag)
            [ -n "$tag" ] && ok || bad "gzip: no ETag"
            # the same tag again: 304, no body
            curl -sS --max-time 10 -o "$T/b2" -w '%{http_code}' -H "Accept-Encoding: gzip" \
                -H "If-None-Match: $(sed -n 's/^[Ee][Tt][Aa][Gg]: //p' "$T/h0" | tr -d '\r')" \
                "http://127.0.0.1:$PORT/holonomy.wasm" >"$T/code"
            [ "$(cat "$T/code")" = 304 ] && [ ! -s "$T/b2" ] && ok || bad "If-None-Match: $(cat "$T/code")"
        fi
        if fetch "identity" /holonomy.wasm; then
            [ -z "$(header content-encoding)" ] && cmp -s "$T/b" "$W/holonomy.wasm" && ok || bad "identity"
        fi
        if fetch "gzip;q=0" /holonomy.wasm "Accept-Encoding: gzip;q=0, br;q=0"; then
            [ -z "$(header content-encoding)" ] && ok || bad "q=0 still encoded"
        fi
        # no precompressed copy: gzip made by the server; the page at /
        if fetch "on the fly" / "Accept-Encoding: gzip, br"; then
            [ "$(header content-encoding)" = gzip ] && gzip -dc "$T/b" | cmp -s - "$W/index.html" &&
                ok || bad "index.html: not gzip of the page"
            case $(header content-type) in text/html*) ok ;; *) bad "index type" ;; esac
        fi
        if fetch "small" /small.js "Accept-Encoding: gzip"; then
            [ -z "$(header content-encoding)" ] && cmp -s "$T/b" "$W/small.js" && ok || bad "small file encoded"
        fi
        # a precompressed copy older than its file is not sent (the copies
        # dated a day back: no wait for the clock to pass their time)
        touch -d '1 day ago' "$Z"/holonomy.wasm.*
        echo "// changed" >>"$W/holonomy.wasm"
        if fetch "stale" /holonomy.wasm "Accept-Encoding: gzip, br"; then
            [ "$(header content-encoding)" = gzip ] && gzip -dc "$T/b" | cmp -s - "$W/holonomy.wasm" &&
                ok || bad "stale .br/.gz sent for a newer file"
        fi
        for p in /.hidden /../outside.txt /%2e%2e/outside.txt /none.js /page.js/x; do
            code=$(curl -sS --max-time 10 --path-as-is -o /dev/null -w '%{http_code}' "http://127.0.0.1:$PORT$p")
            [ "$code" = 404 ] && ok || bad "GET $p: $code, want 404"
        done
        code=$(curl -sS --max-time 10 -I -o "$T/hh" -w '%{http_code}' "http://127.0.0.1:$PORT/page.js")
        [ "$code" = 200 ] && grep -qi '^cache-control: no-cache' "$T/hh" && ok || bad "HEAD: $code"
        stop_server
    else
        bad "serve.py did not start: $(cat "$T/log.err")"
        kill "$SPID" 2>/dev/null
    fi

    # bad arguments: exit 2, one line
    run "serve no folder" 2 "$PY" "$SERVE" "$T/none" --port 0 && one_line "serve no folder" "not a folder"
    run "serve bad port" 2 "$PY" "$SERVE" "$W" --port 70000 && one_line "serve bad port" "70000"
    run "serve bad option" 2 "$PY" "$SERVE" "$W" --nope && one_line "serve bad option" "serve.py"

    # HTTPS: the certificate for an address, checked by curl against it
    if command -v openssl >/dev/null 2>&1; then
        run "make_cert" 0 sh "$R/platform/web/make_cert.sh" "$T/cert" 127.0.0.1 && [ "$(cat "$T/out")" = 127.0.0.1 ] &&
            ok || bad "make_cert: printed '$(cat "$T/out")'"
        openssl x509 -in "$T/cert/cert.pem" -noout -text | grep -q 'IP Address:127.0.0.1' && ok || bad "no SAN"
        before=$(cksum <"$T/cert/cert.pem")
        run "make_cert again" 0 sh "$R/platform/web/make_cert.sh" "$T/cert" 127.0.0.1
        [ "$(cksum <"$T/cert/cert.pem")" = "$before" ] && ok || bad "certificate made again for the same address"
        run "make_cert bad address" 2 sh "$R/platform/web/make_cert.sh" "$T/cert2" 'a;b' && one_line "cert address" "not an IPv4"
        if start_server "$T/slog" "$W" --bind 127.0.0.1 --port 0 --https "$T/cert/cert.pem" "$T/cert/key.pem"; then
            grep -q "https://127.0.0.1:$PORT/" "$T/slog" && ok || bad "https line"
            code=$(curl -sS --max-time 10 --cacert "$T/cert/cert.pem" -H 'Accept-Encoding: gzip' -o "$T/b" \
                -D "$T/h0" -w '%{http_code}' "https://127.0.0.1:$PORT/page.js" 2>"$T/cerr")
            [ "$code" = 200 ] && grep -qi '^content-encoding: gzip' "$T/h0" && gzip -dc "$T/b" | cmp -s - "$W/page.js" &&
                ok || bad "https: $code $(cat "$T/cerr")"
            stop_server
        else
            bad "https server did not start: $(cat "$T/slog.err")"
            kill "$SPID" 2>/dev/null
        fi
    else
        echo "cli_serve: openssl missing: HTTPS not checked"
    fi
fi

# ---- platform/debian/apt_get.sh: waits while another apt holds a lock ----------------
cat >"$T/fake-apt" <<'EOF'
#!/bin/sh
# fails with apt's lock message while $FAKE_DIR/locked-N counts down
echo "$*" >>"$FAKE_DIR/calls"
n=$(cat "$FAKE_DIR/locked" 2>/dev/null || echo 0)
if [ "$n" = always ] || [ "$n" -gt 0 ]; then
    [ "$n" = always ] || echo $((n - 1)) >"$FAKE_DIR/locked"
    echo "E: Could not get lock /var/lib/apt/lists/lock. It is held by process 4242 (apt-get)"
    echo "E: Unable to lock directory /var/lib/apt/lists/"
    exit 100
fi
if [ -f "$FAKE_DIR/broken" ]; then echo "E: Unable to locate package nope"; exit 100; fi
exit 0
EOF
chmod +x "$T/fake-apt"
export FAKE_DIR="$T/fake" APT_GET_PAUSE=0.1
mkdir -p "$FAKE_DIR"
echo 2 >"$FAKE_DIR/locked"
run "apt waits for the lock" 0 env APT_GET_CMD="$T/fake-apt" sh "$R/platform/debian/apt_get.sh" 20 update -qq
[ "$(wc -l <"$FAKE_DIR/calls")" = 3 ] && ok || bad "apt_get: $(wc -l <"$FAKE_DIR/calls") calls, want 3"
grep -q 'waiting up to 20 s' "$T/out" && ok || bad "apt_get: no word about the wait"
grep -q -- '-o DPkg::Lock::Timeout=20 update -qq' "$FAKE_DIR/calls" && ok || bad "apt_get args: $(head -1 "$FAKE_DIR/calls")"
rm -f "$FAKE_DIR/calls"; echo always >"$FAKE_DIR/locked"
s0=$(date +%s)
run "apt gives up" 100 env APT_GET_CMD="$T/fake-apt" sh "$R/platform/debian/apt_get.sh" 2 update
s1=$(date +%s)
[ $((s1 - s0)) -le 4 ] && [ "$(wc -l <"$FAKE_DIR/calls")" -ge 3 ] && grep -q 'Could not get lock' "$T/out" && ok ||
    bad "apt_get: gave up after $((s1 - s0)) s, $(wc -l <"$FAKE_DIR/calls") calls"
rm -f "$FAKE_DIR/calls"; echo 0 >"$FAKE_DIR/locked"; touch "$FAKE_DIR/broken"
run "apt other error" 100 env APT_GET_CMD="$T/fake-apt" sh "$R/platform/debian/apt_get.sh" 20 install nope
[ "$(wc -l <"$FAKE_DIR/calls")" = 1 ] && ok || bad "apt_get retried another error"
rm -f "$FAKE_DIR/broken" "$FAKE_DIR/calls"

# make deps goes through it (as root, with the fake: no real apt runs; the
# dry run is checked first so that an older Makefile never reaches apt)
M() { env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make --no-print-directory -C "$R" "$@"; }
if [ "$(id -u)" = 0 ] && M -n deps DEB_PACKAGES=holonomy-no-such-package APT_GET_CMD="$T/fake-apt" |
        grep -q 'platform/debian/apt_get.sh'; then
    ok
    echo 1 >"$FAKE_DIR/locked"
    run "make deps waits" 0 M -s deps DEB_PACKAGES=holonomy-no-such-package APT_GET_CMD="$T/fake-apt" APT_LOCK_WAIT=20
    grep -q 'install -y -qq --no-install-recommends holonomy-no-such-package' "$FAKE_DIR/calls" && ok ||
        bad "make deps: $(cat "$FAKE_DIR/calls")"
elif [ "$(id -u)" = 0 ]; then
    bad "make deps does not run platform/debian/apt_get.sh"
fi

# ---- make's order and messages ---------------------------------------------
run "make web without emcc" 2 M web EMCC=holonomy-no-emcc && one_line "web without emcc" "run make deps-web first"
run "make web-serve without emcc" 2 M web-serve EMCC=holonomy-no-emcc && one_line "web-serve" "make deps-web"
mkdir -p "$T/bin" && ln -s "$(command -v make)" "$T/bin/make"
run "make web-serve without brotli" 2 env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS PATH="$T/bin" make --no-print-directory -C "$R" -n web-serve EMCC=/bin/true &&
    one_line "web-serve without brotli" "brotli is not installed: run make deps-web first"
# test and run: deps before any build; web-test: deps-web before the build
M -n test >"$T/n" 2>&1
d=$(grep -n 'dpkg -s' "$T/n" | head -1 | cut -d: -f1)
s=$(grep -n 'test-suites' "$T/n" | head -1 | cut -d: -f1)
[ -n "$d" ] && [ -n "$s" ] && [ "$d" -lt "$s" ] && ok || bad "make test: deps ($d) not before the suites ($s)"
M -n run >"$T/n" 2>&1
d=$(grep -n 'dpkg -s' "$T/n" | head -1 | cut -d: -f1)
p=$(grep -n 'holonomy play' "$T/n" | head -1 | cut -d: -f1)
[ -n "$d" ] && [ -n "$p" ] && [ "$d" -lt "$p" ] && ok || bad "make run: deps ($d) not before play ($p)"
M -n web-test EMCC=holonomy-no-emcc >"$T/n" 2>&1
d=$(grep -n 'emscripten' "$T/n" | head -1 | cut -d: -f1)
e=$(grep -n 'run make deps-web first' "$T/n" | head -1 | cut -d: -f1)
[ -n "$d" ] && [ -n "$e" ] && [ "$d" -lt "$e" ] && ok || bad "make web-test: deps-web ($d) not before the build ($e)"

finish cli_serve
