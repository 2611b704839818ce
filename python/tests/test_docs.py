"""The Python API's documentation is its docstrings (the site's reference is generated from
them): every public function names each of its parameters there, and Result each field."""
import dataclasses
import inspect

import vrsimplify
import vrsimplify.tiled


def test_every_parameter_is_documented():
    for fn in (vrsimplify.simplify, vrsimplify.tiled.simplify, vrsimplify.bounding_box_diagonal):
        doc = inspect.getdoc(fn) or ""
        missing = [p for p in inspect.signature(fn).parameters
                   if p not in doc and p not in ("mesh_vertices", "mesh_faces", "vertices")]
        assert missing == [], f"{fn.__module__}.{fn.__name__}: {missing} not in its docstring"


def test_result_documents_its_fields():
    source = inspect.getsource(vrsimplify.Result)
    for field in dataclasses.fields(vrsimplify.Result):
        line = next(l for l in source.splitlines() if l.strip().startswith(f"{field.name}:"))
        after = source[source.index(line) + len(line):].lstrip()
        assert after.startswith('"""'), f"Result.{field.name} has no docstring"
