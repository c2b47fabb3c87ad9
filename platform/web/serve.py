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
- --collect CDIR (issue 37, docs/teaching.md "Collecting a class's
  answers"; make web-serve COLLECT=CDIR): GET /collect answers 200 "collecting" (404 without
  --collect: the page shows its "send to teacher" button only on 200);
  POST /collect?class=CODE with a pupil's answers file as the body
  (answers.csv's header first, text, at most --collect-file bytes,
  Content-Length given) stores it as CDIR/CODE/HASH.csv, HASH the first
  16 hex digits of the body's SHA-256 (no name from the client is ever
  used as a path; the same file sent twice is kept once, 200), written
  to a temporary file, flushed and renamed (atomic). CODE: a letter or
  digit, then up to 31 letters, digits, '-' or '_' (400 else). A folder
  holds at most --collect-files files and --collect-folder bytes, CDIR
  at most --collect-classes folders: past them 507 "full" and nothing
  written. A body that stalls --collect-timeout seconds is dropped.
  411 without Content-Length, 413 over the file's bound (the
  body not read), 400 for a body that ends early, is not an answers
  file or is not UTF-8 text; 201 "saved CODE/HASH.csv". Every answer is
  text/plain, one line.
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


ANSWERS_HEADER = b"session,participant,attempt,questionnaire,when,item,kind,value,time"
COLLECT_LOCK = threading.Lock()


def class_ok(code):
    """1 for a class code: a letter or digit, then up to 31 of [A-Za-z0-9_-]."""
    return 1 <= len(code) <= 32 and code[0].isascii() and code[0].isalnum() and \
        all(c.isascii() and (c.isalnum() or c in "-_") for c in code)


def answers_ok(body):
    """1 for a pupil's answers file: UTF-8 text opening with the header."""
    if not body.startswith(ANSWERS_HEADER) or b"\0" in body:
        return False
    try:
        body.decode("utf-8")
    except UnicodeDecodeError:
        return False
    return True


def collect_store(cfg, code, body):
    """(status, message) of storing body in CDIR/code (under COLLECT_LOCK)."""
    name = hashlib.sha256(body).hexdigest()[:16] + ".csv"
    folder = os.path.join(cfg["dir"], code)
    with COLLECT_LOCK:
        if not os.path.isdir(folder):
            classes = [d for d in os.listdir(cfg["dir"])
                       if os.path.isdir(os.path.join(cfg["dir"], d))]
            if len(classes) >= cfg["classes"]:
                return 507, "full: %d class folders already" % len(classes)
            os.mkdir(folder)
        final = os.path.join(folder, name)
        if os.path.exists(final):
            return 200, "already received %s/%s" % (code, name)
        files = [f for f in os.listdir(folder) if f.endswith(".csv") and f[0] != "."]
        used = sum(os.path.getsize(os.path.join(folder, f)) for f in files)
        if len(files) + 1 > cfg["files"] or used + len(body) > cfg["folder"]:
            return 507, "full: class %s holds %d files, %d bytes" % (code, len(files), used)
        tmp = os.path.join(folder, ".tmp-%d-%s" % (os.getpid(), name[:-4]))
        try:
            with open(tmp, "wb") as f:
                f.write(body)
                f.flush()
                os.fsync(f.fileno())
            os.replace(tmp, final)
        except OSError as e:
            try:
                os.unlink(tmp)
            except OSError:
                pass
            return 500, "cannot write: %s" % e.strerror
    return 201, "saved %s/%s" % (code, name)


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

    def say(self, status, text):
        body = (text + "\n").encode()
        self.send_response(status)
        self.send_header("Content-Type", "text/plain; charset=utf-8")
        self.send_header("Cache-Control", "no-store")
        self.send_header("Content-Length", str(len(body)))
        if status >= 400:
            self.send_header("Connection", "close")
            self.close_connection = True
        self.end_headers()
        self.wfile.write(body)

    def do_GET(self):
        if urllib.parse.urlsplit(self.path).path == "/collect" and self.server.collect:
            self.say(200, "collecting")
            return
        self.answer(False)

    def do_POST(self):
        cfg = self.server.collect
        url = urllib.parse.urlsplit(self.path)
        if url.path != "/collect" or not cfg:
            self.say(404, "not collecting")
            return
        # the length first and the body read (within the bound) before any
        # other refusal, so that the answer is not lost to a reset
        n = self.headers.get("Content-Length")
        if n is None or not n.isascii() or not n.isdigit() or len(n) > 12:
            self.say(411, "Content-Length needed")
            return
        if int(n) > cfg["file"]:
            self.say(413, "too large: a file holds at most %d bytes" % cfg["file"])
            return
        try:
            body = self.rfile.read(int(n))
        except OSError:
            body = b""
        if len(body) != int(n):
            self.say(400, "the body ended early (%d of %s bytes)" % (len(body), n))
            return
        codes = urllib.parse.parse_qs(url.query).get("class", [])
        if len(codes) != 1 or not class_ok(codes[0]):
            self.say(400, "bad class code: a letter or digit, then up to 31 of A-Z a-z 0-9 - _")
            return
        if not answers_ok(body):
            self.say(400, "not an answers file (answers.csv's header, UTF-8 text)")
            return
        status, text = collect_store(cfg, codes[0], body)
        self.say(status, text)

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
    p.add_argument("--collect", metavar="CDIR",
                   help="receive pupils' answer files into CDIR/CLASS/ (docs/teaching.md)")
    p.add_argument("--collect-file", type=int, default=256 * 1024, metavar="BYTES",
                   help="a file's bound (default 262144)")
    p.add_argument("--collect-folder", type=int, default=16 << 20, metavar="BYTES",
                   help="a class folder's bound (default 16 MB)")
    p.add_argument("--collect-files", type=int, default=500, metavar="N",
                   help="files in a class folder, at most (default 500)")
    p.add_argument("--collect-timeout", type=float, default=10, metavar="S",
                   help="seconds a body may stall before it is dropped (default 10)")
    p.add_argument("--collect-classes", type=int, default=100, metavar="N",
                   help="class folders, at most (default 100)")
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
    srv.collect = None
    if a.collect:
        if min(a.collect_file, a.collect_folder, a.collect_files, a.collect_classes) < 1:
            usage_error("the --collect bounds must be at least 1")
        try:
            os.makedirs(a.collect, exist_ok=True)
        except OSError as e:
            usage_error("cannot make --collect '%s': %s" % (a.collect, e.strerror))
        Handler.timeout = a.collect_timeout  # a stalled body is dropped
        srv.collect = {"dir": os.path.realpath(a.collect), "file": a.collect_file,
                       "folder": a.collect_folder, "files": a.collect_files,
                       "classes": a.collect_classes}
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
    if srv.collect:
        print("collecting answers into %s" % srv.collect["dir"], flush=True)
    try:
        srv.serve_forever()
    except KeyboardInterrupt:
        pass
    srv.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
