"""Serves a levels-of-detail .glb and the viewer page that streams it (HTTP range requests).

    vrsimplify serve OUT.glb [--port 8000] [--host 127.0.0.1] [--throttle BYTES_PER_SECOND]
    python -m vrsimplify.serve OUT.glb ...

Open the printed address: the page draws the coarsest level as soon as its bytes arrive and
swaps in the finer ones. ``--throttle`` slows the model's responses (the .glb and its texture)
to that rate, to watch (or test) a model arriving over a slow network; the page and three.js,
which a browser keeps cached, come at full speed. Only the .glb and the files beside it (its texture) are
served (by the URLs it names them with), besides the page and three.js.
"""
from __future__ import annotations

import argparse
import http.server
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


def images_of(glb: pathlib.Path) -> dict[str, pathlib.Path]:
    """The files the .glb's images name, by the URL path a browser asks for them at when the
    .glb is served at /NAME (a URI reaching above the root resolves at it, as in a browser)."""
    import json
    import struct

    with open(glb, "rb") as f:
        head = f.read(20)
        if len(head) < 20 or head[:4] != b"glTF":
            return {}
        (json_bytes,) = struct.unpack_from("<I", head, 12)
        doc = json.loads(f.read(json_bytes))
    out = {}
    for image in doc.get("images", []):
        uri = image.get("uri", "")
        if uri and not uri.startswith("data:"):
            url = urllib.parse.urljoin("http://host/" + urllib.parse.quote(glb.name), uri)
            out[urllib.parse.unquote(urllib.parse.urlsplit(url).path)] = \
                (glb.parent / urllib.parse.unquote(uri)).resolve()
    return out


def make_handler(glb: pathlib.Path, web: pathlib.Path, throttle: float, log: bool):
    three = three_root(web)
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
            f = images.get(path)  # the texture the .glb names
            return f if f is not None and f.is_file() else None

        def do_GET(self):  # noqa: N802
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
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--port", type=int, default=8000, help="0: any free port (printed)")
    p.add_argument("--throttle", type=float, default=0, help="bytes a second per response of the model: the .glb and its texture (0: full speed)")
    p.add_argument("--log", action="store_true", help="print every request")
    a = p.parse_args(argv)
    if not a.glb.is_file():
        p.error(f"{a.glb}: no such file")
    try:
        web = web_root()
        handler = make_handler(a.glb.resolve(), web, a.throttle, a.log)
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
