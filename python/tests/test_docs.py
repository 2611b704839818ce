"""The Python API's documentation is its docstrings (the site's reference is generated from
them): every public function names each of its parameters there, and Result each field."""
import dataclasses
import inspect

import vrsimplify
import vrsimplify.tiled


def test_every_parameter_is_documented():
    for fn in (vrsimplify.simplify, vrsimplify.tiled.simplify, vrsimplify.bounding_box_diagonal,
               vrsimplify.lods, vrsimplify.write_glb):
        doc = inspect.getdoc(fn) or ""
        missing = [p for p in inspect.signature(fn).parameters
                   if p not in doc and p not in ("mesh_vertices", "mesh_faces", "vertices", "path")]
        assert missing == [], f"{fn.__module__}.{fn.__name__}: {missing} not in its docstring"


def test_results_document_their_fields():
    for cls in (vrsimplify.Result, vrsimplify.Lods, vrsimplify.LodLevel):
        source = inspect.getsource(cls)
        for field in dataclasses.fields(cls):
            line = next(l for l in source.splitlines() if l.strip().startswith(f"{field.name}:"))
            after = source[source.index(line) + len(line):].lstrip()
            assert after.startswith('"""'), f"{cls.__name__}.{field.name} has no docstring"


def test_one_report_in_python_and_the_cli(tmp_path):
    """The numpy API's report has exactly the keys Report types; the CLI's JSON the same ones
    (plus its total time; the bound's keys only when tracked)."""
    import json
    import subprocess

    import numpy as np
    import trimesh

    m = trimesh.creation.icosphere(subdivisions=3)
    r = vrsimplify.simplify(np.asarray(m.vertices), np.asarray(m.faces), ratio=0.3)
    typed = set(vrsimplify.Report.__annotations__)
    assert set(r.report) == typed
    assert r.report["error_bound"] is None and r.report["error_bound_percent"] is None
    m.export(tmp_path / "in.ply")
    for extra, bound in (([], False), (["--error-bound"], True)):
        out = subprocess.run(["vrsimplify", str(tmp_path / "in.ply"), str(tmp_path / "out.ply"),
                              "--ratio", "0.3", "--json", *extra],
                             capture_output=True, text=True, check=True).stdout
        keys = set(json.loads(out)) - {"seconds_total"}
        expected = typed - (set() if bound else {"error_bound", "error_bound_percent"})
        assert keys == expected, (keys ^ expected)
