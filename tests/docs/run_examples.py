"""Runs the examples the README and the documentation show, as a reader would paste them: every
```python block (with the names it takes as given — vertices, faces, colors, a trimesh mesh,
in.obj / in.ply / scan.ply files — made from meshes/fandisk.off first; a Dask Client address
becomes a LocalCluster of two worker processes, a plugin path the installed one) and every
`vrsimplify ...` command in inline code, in a scratch folder. Exit 1 with the failing example.

    python run_examples.py REPO_ROOT      (in an environment with the wheel, pymeshlab, trimesh,
                                           dask installed; `vrsimplify` on PATH)
"""
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile
import textwrap

import numpy as np

def main():
    top = pathlib.Path(sys.argv[1])
    pages = [top / "README.md"] + sorted((top / "docs").glob("*.md")) + sorted(
        (top / "docs").glob("*/*.md"))
    work = pathlib.Path(tempfile.mkdtemp(prefix="vrs-examples-"))
    os.chdir(work)


    def read_off(path):
        words = [w for line in open(path) for w in line.split("#")[0].split()]
        nv, nf = int(words[1]), int(words[2])
        v = np.array(words[4:4 + 3 * nv], dtype=np.float64).reshape(nv, 3)
        rest = np.array(words[4 + 3 * nv:], dtype=np.int64).reshape(nf, 4)
        return v, rest[:, 1:]


    vertices, faces = read_off(top / "meshes" / "fandisk.off")
    import trimesh

    mesh = trimesh.Trimesh(vertices, faces, process=False)
    for name in ("in.obj", "in.ply", "scan.ply", "in.off", "scan.obj"):
        mesh.export(work / name)


    np.save(work / "vertices.npy", vertices)
    np.save(work / "faces.npy", faces)
    prelude = textwrap.dedent("""
        import numpy as np, trimesh
        vertices = np.load("vertices.npy"); faces = np.load("faces.npy")
        colors = np.random.default_rng(1).random((len(vertices), 3))
        mesh = trimesh.Trimesh(vertices, faces, process=False)
        normals = np.asarray(mesh.vertex_normals)
        """)

    def adapt(code):
        import vrsimplify
        plugin = pathlib.Path(vrsimplify.__file__).parent / "plugins" / "libfilter_vertex_removal.so"
        code = re.sub(r'"/path/to/[^"]*libfilter_vertex_removal\.so"', repr(str(plugin)), code)
        code = re.sub(r'Client\("tcp://[^"]*"\)', "__client__", code)
        code = code.replace('workdir="/shared/tmp"', f'workdir={str(work / "shared")!r}')
        # A fresh interpreter per example, as a reader pastes it; a Dask client of our own.
        cluster = ("    from dask.distributed import Client, LocalCluster\n"
                   "    __client__ = Client(LocalCluster(n_workers=2, threads_per_worker=1,"
                   " processes=True, dashboard_address=None))\n") if "__client__" in code else ""
        return (prelude + "\n\nif __name__ == '__main__':\n" + cluster
                + textwrap.indent(code, "    ") + "\n")

    failures, ran = [], 0
    for page in pages:
        text = page.read_text()
        for block in re.findall(r"```python\n(.*?)```", text, flags=re.S):
            script = work / "example.py"
            script.write_text(adapt(textwrap.dedent(block)))
            r = subprocess.run([sys.executable, str(script)], capture_output=True, text=True)
            ran += 1
            if r.returncode != 0:
                failures.append(f"{page.name}: {r.stderr.strip()[-800:]}\n{script.read_text()}")
        commands = re.findall(r"`(vrsimplify [^`]+)`", text)
        for block in re.findall(r"```sh\n(.*?)```", text, flags=re.S):
            joined = re.sub(r"\\\n\s*", " ", "\n".join(l.split(" #")[0] for l in block.splitlines()))
            commands += [l.strip() for l in joined.splitlines() if l.strip().startswith("vrsimplify ")]
        for command in commands:
            cluster = None
            if "tcp://head:8786" in command:  # a Dask scheduler of our own
                from dask.distributed import LocalCluster
                cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
                command = command.replace("tcp://head:8786", cluster.scheduler_address)
            command = command.replace("/shared/tmp", str(work / "shared"))
            args = shlex.split(command)
            if any(a.startswith(("IN", "OUT", "[")) or "..." in a for a in args):
                continue  # a synopsis, not a command
            if args[1] == "serve":  # a server: it must start and serve the page, then it stops
                ran += 1
                error = serve_check(args)
                if error:
                    failures.append(f"{page.name}: `{command}`: {error}")
                continue
            # As a reader types it: through the shell (redirections included).
            r = subprocess.run(["bash", "-c", command], capture_output=True, text=True)
            if cluster:
                cluster.close()
            ran += 1
            if r.returncode != 0:
                failures.append(f"{page.name}: `{command}` exited {r.returncode}: {r.stderr.strip()}")
    print(f"run_examples: {ran} examples run, {len(failures)} failed")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def serve_check(args):
    """Runs `vrsimplify serve ...` on a free port: "" once its page answers, else what failed."""
    import urllib.request

    server = subprocess.Popen(args + ["--port", "0"], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)
    try:
        line = server.stdout.readline()
        if " at http://" not in line:
            return f"did not start: {line} {server.stderr.read()}"
        base = line.split(" at ")[1].split()[0]
        page = urllib.request.urlopen(base, timeout=20).read().decode()
        return "" if "viewer.js" in page else "no viewer page at " + base
    except OSError as e:
        return str(e)
    finally:
        server.terminate()
        server.wait(10)


if __name__ == "__main__":  # Dask's worker processes import this file again
    main()
