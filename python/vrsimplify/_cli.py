"""The `vrsimplify` console script: runs the command-line tool the wheel carries."""
import os
import pathlib
import sys


def main() -> None:
    if sys.argv[1:2] == ["serve"]:  # the viewer page and a .glb, over HTTP (vrsimplify.serve)
        from .serve import main as serve
        sys.exit(serve(sys.argv[2:]))
    exe = pathlib.Path(__file__).with_name("bin") / "vrsimplify"
    if not exe.is_file():
        sys.exit("vrsimplify: this package was built without the command-line tool "
                 "(vcglib was not found at build time; scripts/setup.sh fetches it)")
    # --scheduler hands the run to this package's Dask driver, with this Python.
    os.environ.setdefault("VRS_PYTHON", sys.executable)
    os.execv(exe, [str(exe), *sys.argv[1:]])  # same process: exit code and signals as the tool's


if __name__ == "__main__":
    main()
