"""The `vrsimplify` console script the package installs runs the command-line tool."""
import json
import shutil
import subprocess

from conftest import MESHES


def test_console_script_simplifies_a_shipped_mesh(tmp_path):
    exe = shutil.which("vrsimplify")
    assert exe, "the console script is not on PATH"
    out = tmp_path / "out.ply"
    p = subprocess.run([exe, str(MESHES / "fandisk.off"), str(out), "--ratio", "0.1", "--json"],
                       capture_output=True, text=True, check=True)
    report = json.loads(p.stdout)
    assert report["ok"] and report["target_reached"] and out.stat().st_size > 0
    bad = subprocess.run([exe, str(MESHES / "fandisk.off"), str(out), "--ratio", "7"],
                         capture_output=True, text=True)
    assert bad.returncode != 0 and "ratio must be in [0, 1]" in bad.stderr
    assert out.stat().st_size > 0  # the earlier output is not destroyed by a failed run
