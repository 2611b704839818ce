"""`vrsimplify serve` against hostile .glb files, with a real HTTP client: only the page, three.js,
the .glb and the images it names inside its own folder are served; any other path is 404,
whatever the .glb's JSON says (relative, absolute, percent-encoded, through a symlink); a
request naming another host is refused; HEAD answers as GET without the body."""
import http.client
import json
import os
import struct
import subprocess

import pytest


def glb_naming(path, uris):
    """A binary glTF whose images name `uris` (its JSON is all the server reads of it)."""
    doc = json.dumps({"asset": {"version": "2.0"},
                      "images": [{"uri": u} for u in uris]}).encode()
    doc += b" " * (-len(doc) % 4)
    path.write_bytes(struct.pack("<III", 0x46546C67, 2, 20 + len(doc))
                     + struct.pack("<II", len(doc), 0x4E4F534A) + doc)


@pytest.fixture()
def hostile(tmp_path):
    """A .glb in site/ naming a texture beside it, files above and outside its folder, and a
    symlink beside it that leads out."""
    site = tmp_path / "site"
    (site / "tex").mkdir(parents=True)
    (site / "tex" / "ok.png").write_bytes(b"\x89PNG inside")
    (tmp_path / "secret.txt").write_text("above the folder")
    os.symlink(tmp_path / "secret.txt", site / "link.png")
    os.symlink("/etc/hostname", site / "tex" / "host.png")
    uris = ["tex/ok.png", "../secret.txt", "../../../../../../etc/passwd", "/etc/hostname",
            "%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/group", "link.png", "tex/host.png",
            "file:///etc/passwd", "tex/%2e%2e/%2e%2e/secret.txt"]
    glb_naming(site / "evil.glb", uris)
    return site / "evil.glb"


def serve(glb, *extra):
    server = subprocess.Popen(["vrsimplify", "serve", str(glb), "--port", "0", *extra],
                              stdout=subprocess.PIPE, text=True)
    line = server.stdout.readline()
    host, port = line.split("http://")[1].split("/")[0].rsplit(":", 1)
    return server, host, int(port)


def ask(port, path, method="GET", host=None):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    c.putrequest(method, path, skip_host=True)
    c.putheader("Host", host if host is not None else f"127.0.0.1:{port}")
    c.endheaders()
    r = c.getresponse()
    body = r.read()
    c.close()
    return r.status, r.headers, body


def test_only_files_inside_the_folder_are_served(hostile):
    server, _, port = serve(hostile)
    try:
        status, _, body = ask(port, "/tex/ok.png")
        assert (status, body) == (200, b"\x89PNG inside")
        passwd = open("/etc/passwd", "rb").read()
        for path in ["/secret.txt", "/etc/passwd", "/etc/hostname", "/etc/group",
                     "/%2e%2e/secret.txt", "/..%2fsecret.txt", "/link.png", "/tex/host.png",
                     "/tex/..%2f..%2fsecret.txt", "//etc/passwd", "/three/../../secret.txt",
                     "/%2fetc%2fpasswd", "/node_modules/three/package.json"]:
            status, _, body = ask(port, path)
            assert status == 404, (path, status)
            assert b"root:" not in body and b"above the folder" not in body and body != passwd
    finally:
        server.terminate()
        server.wait(10)


def test_a_request_for_another_host_is_refused(hostile):
    """DNS rebinding: a page at evil.example whose name now points at 127.0.0.1 sends
    Host: evil.example; the server answers only to its own address."""
    server, _, port = serve(hostile)
    try:
        assert ask(port, "/evil.glb")[0] == 200
        assert ask(port, "/evil.glb", host=f"localhost:{port}")[0] == 200
        assert ask(port, "/evil.glb", host=f"[::1]:{port}")[0] == 200
        for other in (f"evil.example:{port}", "evil.example", "", f"10.1.2.3:{port}"):
            status, _, body = ask(port, "/evil.glb", host=other)
            assert status == 421, (other, status)
            assert b"glTF" not in body
    finally:
        server.terminate()
        server.wait(10)


def test_allow_host_names_another_host(hostile):
    server, _, port = serve(hostile, "--allow-host", "viewer.lan")
    try:
        assert ask(port, "/evil.glb", host=f"viewer.lan:{port}")[0] == 200
        assert ask(port, "/evil.glb", host=f"other.lan:{port}")[0] == 421
    finally:
        server.terminate()
        server.wait(10)


def test_head_answers_like_get_without_a_body(hostile):
    server, _, port = serve(hostile)
    try:
        status, headers, body = ask(port, "/evil.glb", "HEAD")
        assert status == 200 and body == b""
        assert int(headers["Content-Length"]) == hostile.stat().st_size
        assert headers["Content-Type"] == "model/gltf-binary"
        assert ask(port, "/etc/passwd", "HEAD")[0] == 404
    finally:
        server.terminate()
        server.wait(10)
