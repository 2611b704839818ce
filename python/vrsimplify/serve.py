"""Serves a levels-of-detail .glb and the viewer page that streams it (HTTP range requests).

    vrsimplify serve OUT.glb [--port 8000] [--host 127.0.0.1] [--throttle BYTES_PER_SECOND]
    python -m vrsimplify.serve OUT.glb ...

Open the printed address: the page draws the coarsest level as soon as its bytes arrive and
swaps in the finer ones. ``--throttle`` slows the model's responses (the .glb and its texture)
to that rate, to watch (or test) a model arriving over a slow network; the page and three.js,
which a browser keeps cached, come at full speed.

What it serves: the page, three.js, the .glb, and the files the .glb's images name only where
they resolve (after percent-decoding and symlinks) inside the .glb's own folder; any other path
is 404. A .glb comes from anywhere, and its JSON may name ``../../etc/passwd``.

Who may ask: it listens on 127.0.0.1 unless ``--host`` says otherwise, and answers only requests
whose ``Host`` header names the address it listens on, ``localhost`` or a loopback address (a
page on another site cannot reach it by pointing a name of its own at 127.0.0.1). ``--host
0.0.0.0`` exposes the model and the page to every machine that can reach this one; requests
that name this machine by an IP address are answered, by a name only if ``--allow-host NAME``.
"""
from __future__ import annotations

import argparse
import http.server
import ipaddress
import mimetypes
import pathlib
import re
import sys
import time
import urllib.parse

_TYPES = {".glb": "model/gltf-binary", ".js": "text/javascript", ".html": "text/html",
          ".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg"}


def web_root() -> pathlib.Path:
    """The viewer's files: packaged beside this module, or the source tree's web/ folder."""
    here = pathlib.Path(__file__).resolve().parent
    for candidate in (here / "web", here.parents[1] / "web"):
        if (candidate / "index.html").is_file():
            return candidate
    raise FileNotFoundError("the viewer page is not installed with this package")


def three_root(web: pathlib.Path) -> pathlib.Path:
    """three.js: packaged as web/three, or web/node_modules/three in a source tree."""
    for candidate in (web / "three", web / "node_modules" / "three"):
        if (candidate / "build" / "three.module.js").is_file():
            return candidate
    raise FileNotFoundError("three.js is missing: in a source tree, scripts/setup.sh installs it "
                            "(web/node_modules)")


def images_of(glb: pathlib.Path, refused: list[str] | None = None) -> dict[str, pathlib.Path]:
    """The files the .glb's images name, by the URL path a browser asks for them at when the
    .glb is served at /NAME (a URI reaching above the root resolves at it, as in a browser);
    only those that resolve inside the .glb's folder (symlinks followed), never above it. The
    URIs left out go to `refused`."""
    import json
    import struct

    with open(glb, "rb") as f:
        head = f.read(20)
        if len(head) < 20 or head[:4] != b"glTF":
            return {}
        (json_bytes,) = struct.unpack_from("<I", head, 12)
        doc = json.loads(f.read(json_bytes))
    folder = glb.resolve().parent
    out = {}
    for image in doc.get("images", []) if isinstance(doc, dict) else []:
        uri = image.get("uri", "") if isinstance(image, dict) else ""
        if not isinstance(uri, str) or not uri or uri.startswith("data:"):
            continue
        url = urllib.parse.urljoin("http://host/" + urllib.parse.quote(glb.name), uri)
        f = (folder / urllib.parse.unquote(uri)).resolve()
        # Another server's file, an absolute path or one outside the folder: never served.
        if urllib.parse.urlsplit(uri).scheme or uri.startswith("/") or folder not in f.parents:
            if refused is not None:
                refused.append(uri)
            continue
        out[urllib.parse.unquote(urllib.parse.urlsplit(url).path)] = f
    return out


def allowed_hosts(host: str, extra: list[str]) -> set[str]:
    """The names a request's Host header may give (port aside): the listening address,
    localhost and the loopback addresses, and any --allow-host."""
    names = {"localhost", "127.0.0.1", "::1", host.strip("[]").lower()}
    return names | {e.lower() for e in extra}


def host_allowed(header: str | None, names: set[str], wildcard: bool) -> bool:
    """Whether a Host header names this server: one of `names`, or, listening on every
    interface, any IP address (a name would let DNS rebinding in)."""
    if not header:
        return False
    m = re.fullmatch(r"\[([0-9a-fA-F:.]+)\](?::\d+)?|([^:\[\]]+)(?::\d+)?", header.strip())
    if not m:
        return False
    name = (m.group(1) or m.group(2)).lower()
    if name in names:
        return True
    try:
        ip = ipaddress.ip_address(name)
    except ValueError:
        return False
    return ip.is_loopback or wildcard


def make_handler(glb: pathlib.Path, web: pathlib.Path, throttle: float, log: bool,
                 hosts: set[str] | None = None, wildcard: bool = False):
    three = three_root(web)
    hosts = allowed_hosts("127.0.0.1", []) if hosts is None else hosts
    images = images_of(glb)  # only these files beside the page, three.js and the .glb
    model_files = set(images.values())

    class Handler(http.server.BaseHTTPRequestHandler):
        protocol_version = "HTTP/1.1"

        def log_message(self, fmt, *args):  # noqa: D401 - quiet unless asked
            if log:
                sys.stderr.write("serve: " + (fmt % args) + "\n")

        def _file_for(self, path: str) -> pathlib.Path | None:
            path = urllib.parse.unquote(path)
            if path in ("", "/"):
                return None
            if path == "/" + glb.name:
                return glb
            roots = [(web, "/"), (three, "/three/")]
            for root, prefix in sorted(roots, key=lambda r: -len(r[1])):
                if path.startswith(prefix):
                    f = (root / path[len(prefix):]).resolve()
                    # Nothing outside its root (no "..", no links out), never node_modules.
                    if f.is_file() and root.resolve() in f.parents and "node_modules" not in \
                            f.relative_to(root.resolve()).parts:
                        return f
            f = images.get(path)  # a texture the .glb names, inside its folder
            if f is None:
                return None
            f = f.resolve()  # again: a link may have changed since the server started
            return f if f.is_file() and glb.parent.resolve() in f.parents else None

        def do_GET(self):  # noqa: N802
            self._answer(body=True)

        def do_HEAD(self):  # noqa: N802
            self._answer(body=False)

        def _answer(self, body: bool):
            if not host_allowed(self.headers.get("Host"), hosts, wildcard):
                self.send_error(421, "this server answers only to the address it listens on")
                return
            url = urllib.parse.urlsplit(self.path)
            if url.path in ("", "/"):
                self.send_response(302)
                self.send_header("Location", "/index.html?url=/" + urllib.parse.quote(glb.name))
                self.send_header("Content-Length", "0")
                self.end_headers()
                return
            f = self._file_for(url.path)
            if f is None:
                self.send_error(404)
                return
            size = f.stat().st_size
            start, end, status = 0, size, 200
            header = self.headers.get("Range")
            if header:
                m = re.fullmatch(r"bytes=(\d*)-(\d*)", header.strip())
                if not m or (not m.group(1) and not m.group(2)):
                    self.send_error(416)
                    return
                if m.group(1):
                    start = int(m.group(1))
                    end = min(size, int(m.group(2)) + 1) if m.group(2) else size
                else:  # the last N bytes
                    start, end = max(0, size - int(m.group(2))), size
                if start >= size or start >= end:
                    self.send_response(416)
                    self.send_header("Content-Range", f"bytes */{size}")
                    self.send_header("Content-Length", "0")
                    self.end_headers()
                    return
                status = 206
            self.send_response(status)
            kind = _TYPES.get(f.suffix.lower()) or mimetypes.guess_type(f.name)[0] or \
                "application/octet-stream"
            self.send_header("Content-Type", kind)
            self.send_header("Content-Length", str(end - start))
            self.send_header("Accept-Ranges", "bytes")
            self.send_header("Cache-Control", "no-store")
            if status == 206:
                self.send_header("Content-Range", f"bytes {start}-{end - 1}/{size}")
            self.end_headers()
            if not body:
                return
            rate = throttle if f == glb or f in model_files else 0
            with open(f, "rb") as src:
                src.seek(start)
                left = end - start
                chunk = 16384
                t0 = time.monotonic()
                sent = 0
                while left > 0:
                    data = src.read(min(chunk, left))
                    if not data:
                        break
                    try:
                        self.wfile.write(data)
                    except (BrokenPipeError, ConnectionResetError):
                        return
                    left -= len(data)
                    sent += len(data)
                    if rate > 0:  # hold the rate to `throttle` bytes a second
                        ahead = sent / rate - (time.monotonic() - t0)
                        if ahead > 0:
                            time.sleep(ahead)

    return Handler


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="vrsimplify serve", description=__doc__.split("\n\n")[0])
    p.add_argument("glb", type=pathlib.Path, help="the .glb to serve (vrsimplify IN OUT.glb --lods ...)")
    p.add_argument("--host", default="127.0.0.1",
                   help="the address to listen on (default 127.0.0.1: this machine only); "
                        "0.0.0.0 exposes the page and the model to every machine that reaches this one")
    p.add_argument("--allow-host", action="append", default=[], metavar="NAME",
                   help="also answer requests that name this server NAME (a host name others reach it by)")
    p.add_argument("--port", type=int, default=8000, help="0: any free port (printed)")
    p.add_argument("--throttle", type=float, default=0, help="bytes a second per response of the model: the .glb and its texture (0: full speed)")
    p.add_argument("--log", action="store_true", help="print every request")
    a = p.parse_args(argv)
    if not a.glb.is_file():
        p.error(f"{a.glb}: no such file")
    try:
        web = web_root()
        refused: list[str] = []
        images_of(a.glb.resolve(), refused)
        for uri in refused:
            print(f"vrsimplify serve: not serving {uri!r}: it lies outside {a.glb.resolve().parent} "
                  "(write the .glb beside its textures)", file=sys.stderr)
        wildcard = a.host in ("0.0.0.0", "::", "")
        handler = make_handler(a.glb.resolve(), web, a.throttle, a.log,
                               allowed_hosts(a.host, a.allow_host), wildcard)
    except FileNotFoundError as e:
        print(f"vrsimplify serve: {e}", file=sys.stderr)
        return 2
    server = http.server.ThreadingHTTPServer((a.host, a.port), handler)
    host, port = server.server_address[:2]
    print(f"serving {a.glb} at http://{host}:{port}/ (Ctrl-C stops)", flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
