#!/usr/bin/env python3
"""serve.py - serves the web build (build/web/) for `make web-serve` and
`make web-serve-https` (docs/web.md, "Serving").

Contract
- Serves the regular files of DIR (GET and HEAD; nothing outside DIR, no
  listing, no dot files): `/` is index.html.
- Compression: a file FILE served with Accept-Encoding naming br gets
  FILE.br of the --precompressed folder (default DIR) when that file exists
  and is not older than FILE
  (make web-serve writes FILE.br and FILE.gz of the page, the scripts and
  the wasm into build/web-z/, beside build/web/ so that the build's own
  folder and its measured size stay as they are), else one naming gzip
  gets FILE.gz, or
  FILE compressed here (gzip, kept in memory by modification time) when it
  is larger than 1 KB and of a text or wasm type; then Content-Encoding
  says which, and Vary: Accept-Encoding is always sent.
- Caching: the build's names carry no hash, so every answer is
  `Cache-Control: no-cache` (the browser keeps the file and asks again) with
  a strong ETag of the file's size and modification time; If-None-Match
  with it answers 304 Not Modified, no body. (A new build is seen at once,
  an unchanged file costs one round trip.)
- Types: .wasm application/wasm (streaming compilation), .js
  text/javascript, .html text/html, others by Python's table.
- --https CERT KEY serves TLS (make web-serve-https makes a self-signed
  certificate for the computer's LAN address; docs/web.md says how the
  headset trusts it).
- Prints one line "serving DIR on http(s)://HOST:PORT/" once listening
  (--port 0: a free port, the line names it), then serves until SIGINT or
  SIGTERM (exit 0). Bad arguments: exit 2 with one line on stderr.
"""
import argparse
import gzip
import hashlib
import http.server
import mimetypes
import os
import signal
import ssl
import sys
import threading
import urllib.parse

TYPES = {".wasm": "application/wasm", ".js": "text/javascript; charset=utf-8",
         ".mjs": "text/javascript; charset=utf-8", ".html": "text/html; charset=utf-8",
         ".css": "text/css; charset=utf-8", ".json": "application/json",
         ".svg": "image/svg+xml", ".png": "image/png"}
COMPRESSIBLE = (".wasm", ".js", ".mjs", ".html", ".css", ".json", ".svg", ".txt")
GZ_CACHE = {}
GZ_LOCK = threading.Lock()


def content_type(path):
    ext = os.path.splitext(path)[1].lower()
    return TYPES.get(ext) or mimetypes.guess_type(path)[0] or "application/octet-stream"


def accepts(header, coding):
    """1 when the Accept-Encoding header names coding with a q above 0."""
    for part in (header or "").split(","):
        fields = [f.strip() for f in part.split(";")]
        if fields[0].lower() != coding:
            continue
        q = 1.0
        for f in fields[1:]:
            if f.lower().startswith("q="):
                try:
                    q = float(f[2:])
                except ValueError:
                    q = 0.0
        return q > 0
    return False


def gzip_of(path, st):
    key = (path, st.st_mtime_ns, st.st_size)
    with GZ_LOCK:
        if key in GZ_CACHE:
            return GZ_CACHE[key]
    with open(path, "rb") as f:
        data = gzip.compress(f.read(), compresslevel=9, mtime=0)
    with GZ_LOCK:
        GZ_CACHE.clear() if len(GZ_CACHE) > 64 else None
        GZ_CACHE[key] = data
    return data


class Handler(http.server.BaseHTTPRequestHandler):
    server_version = "holonomy-serve"
    protocol_version = "HTTP/1.1"

    def log_message(self, fmt, *args):  # one line a request, on stderr
        sys.stderr.write("%s %s\n" % (self.address_string(), fmt % args))

    def resolve(self):
        """The file a request names, or None."""
        path = urllib.parse.unquote(urllib.parse.urlsplit(self.path).path)
        if path.endswith("/"):
            path += "index.html"
        parts = [p for p in path.split("/") if p]
        if any(p.startswith(".") or "\0" in p for p in parts):
            return None
        full = os.path.realpath(os.path.join(self.server.root, *parts))
        if not full.startswith(self.server.root + os.sep) or not os.path.isfile(full):
            return None
        return full

    def body_for(self, full):
        """(bytes, Content-Encoding or None, stat of the file sent)."""
        st = os.stat(full)
        ae = self.headers.get("Accept-Encoding")
        z = os.path.join(self.server.z, os.path.relpath(full, self.server.root))
        for coding, ext in (("br", ".br"), ("gzip", ".gz")):
            if accepts(ae, coding) and os.path.isfile(z + ext) and \
                    os.stat(z + ext).st_mtime_ns >= st.st_mtime_ns:
                with open(z + ext, "rb") as f:
                    return f.read(), coding, st
        if accepts(ae, "gzip") and st.st_size > 1024 and full.lower().endswith(COMPRESSIBLE):
            return gzip_of(full, st), "gzip", st
        with open(full, "rb") as f:
            return f.read(), None, st

    def answer(self, head):
        full = self.resolve()
        if full is None:
            self.send_error(404, "Not Found")
            return
        try:
            body, coding, st = self.body_for(full)
        except OSError:
            self.send_error(500, "Cannot read the file")
            return
        tag = '"%s"' % hashlib.sha1(("%d-%d-%s" % (st.st_size, st.st_mtime_ns, coding or ""))
                                    .encode()).hexdigest()[:20]
        status = 304 if self.headers.get("If-None-Match") == tag else 200
        self.send_response(status)
        self.send_header("Content-Type", content_type(full))
        self.send_header("Cache-Control", "no-cache")
        self.send_header("ETag", tag)
        self.send_header("Vary", "Accept-Encoding")
        if coding:
            self.send_header("Content-Encoding", coding)
        if status == 200:
            self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        if status == 200 and not head:
            self.wfile.write(body)

    def do_GET(self):
        self.answer(False)

    def do_HEAD(self):
        self.answer(True)


def usage_error(msg):
    sys.stderr.write("serve.py: %s\n" % msg)
    sys.exit(2)


class Parser(argparse.ArgumentParser):
    def error(self, message):
        usage_error(message.replace("\n", " "))


def main():
    p = Parser(description="Serve the web build with precompressed files and cache headers.")
    p.add_argument("dir", help="the folder served (build/web)")
    p.add_argument("--bind", default="127.0.0.1", help="address (default 127.0.0.1)")
    p.add_argument("--port", type=int, default=8080, help="port (0: a free one; default 8080)")
    p.add_argument("--precompressed", metavar="ZDIR",
                   help="folder of FILE.br and FILE.gz copies (default: DIR)")
    p.add_argument("--https", nargs=2, metavar=("CERT", "KEY"), help="serve TLS with these PEM files")
    a = p.parse_args()
    if not os.path.isdir(a.dir):
        usage_error("'%s' is not a folder (make web builds build/web)" % a.dir)
    if not 0 <= a.port <= 65535:
        usage_error("--port %d is not 0..65535" % a.port)
    try:
        srv = http.server.ThreadingHTTPServer((a.bind, a.port), Handler)
    except OSError as e:
        usage_error("cannot listen on %s:%d: %s" % (a.bind, a.port, e.strerror))
    srv.daemon_threads = True
    srv.root = os.path.realpath(a.dir)
    srv.z = os.path.realpath(a.precompressed or a.dir)
    scheme = "http"
    if a.https:
        ctx = ssl.SSLContext(ssl.PROTOCOL_TLS_SERVER)
        try:
            ctx.load_cert_chain(a.https[0], a.https[1])
        except (OSError, ssl.SSLError) as e:
            usage_error("cannot load the certificate: %s" % e)
        srv.socket = ctx.wrap_socket(srv.socket, server_side=True)
        scheme = "https"
    signal.signal(signal.SIGTERM, lambda *_: threading.Thread(target=srv.shutdown).start())
    host, port = srv.server_address[:2]
    print("serving %s on %s://%s:%d/ (Ctrl-C stops)" % (a.dir, scheme, host, port), flush=True)
    try:
        srv.serve_forever()
    except KeyboardInterrupt:
        pass
    srv.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
