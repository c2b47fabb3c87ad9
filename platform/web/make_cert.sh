#!/bin/sh
# make_cert.sh DIR [ADDRESS] - a self-signed certificate for serving the web
# build over HTTPS to a headset on the same network (make web-serve-https;
# docs/web.md, "A headset on the LAN").
# ADDRESS: the computer's LAN address (default: the source address of its
# route to the internet, else the first of hostname -I). Writes DIR/cert.pem,
# DIR/key.pem (RSA 2048, 825 days, subjectAltName the address, 127.0.0.1
# and localhost) and DIR/address, again only when the address changed; prints
# the address. Exit 2 with one line when openssl is missing or no address
# is found.
set -u
dir=${1:?usage: make_cert.sh DIR [ADDRESS]}
addr=${2:-}
if [ -z "$addr" ]; then
    addr=$(ip -4 route get 1.1.1.1 2>/dev/null | sed -n 's/.* src \([0-9.]*\).*/\1/p' | head -1)
fi
if [ -z "$addr" ]; then
    addr=$(hostname -I 2>/dev/null | tr ' ' '\n' | grep -v '^127\.' | grep '^[0-9.]*$' | head -1)
fi
if [ -z "$addr" ]; then
    echo "make_cert.sh: no LAN address found; give one: make web-serve-https WEB_LAN=192.168.1.20" >&2
    exit 2
fi
case $addr in
    *[!0-9.]*) echo "make_cert.sh: '$addr' is not an IPv4 address" >&2; exit 2 ;;
esac
command -v openssl >/dev/null 2>&1 || { echo "make_cert.sh: openssl is missing: run make deps-web" >&2; exit 2; }
mkdir -p "$dir" || exit 1
if [ -f "$dir/cert.pem" ] && [ -f "$dir/key.pem" ] && [ "$(cat "$dir/address" 2>/dev/null)" = "$addr" ]; then
    echo "$addr"
    exit 0
fi
tmp=$(mktemp -d "$dir/.new.XXXXXX") || exit 1
if ! openssl req -x509 -newkey rsa:2048 -nodes -days 825 -sha256 \
        -subj "/CN=Holonomy on $addr" \
        -addext "subjectAltName=IP:$addr,IP:127.0.0.1,DNS:localhost" \
        -addext "extendedKeyUsage=serverAuth" \
        -keyout "$tmp/key.pem" -out "$tmp/cert.pem" >"$tmp/log" 2>&1; then
    echo "make_cert.sh: openssl failed: $(tail -1 "$tmp/log")" >&2
    rm -rf "$tmp"
    exit 1
fi
chmod 600 "$tmp/key.pem"
mv "$tmp/key.pem" "$dir/key.pem" && mv "$tmp/cert.pem" "$dir/cert.pem" && echo "$addr" >"$dir/address"
rm -rf "$tmp"
echo "$addr"
