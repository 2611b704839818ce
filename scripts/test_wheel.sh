#!/usr/bin/env bash
# The wheel as a user gets it: scripts/build_wheel.sh, then `pip install dist/*.whl` into a
# fresh virtual environment (Debian's python3) with pymeshlab, trimesh, pytest and Dask at the pinned
# versions, `python -c "import vrsimplify"`, and the package's tests (python/tests) run from
# outside the source tree against the installed files only. Prints the wheel's size and the
# import time.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/build_wheel.sh"
wheel=$(ls "$top"/dist/vrsimplify-*.whl)
env=$(mktemp -d)
trap 'rm -rf "$env"' EXIT
/usr/bin/python3 -m venv "$env/venv"
pin() { grep -E "^$1==" "$top/requirements.txt"; }
"$env/venv/bin/pip" install -q --disable-pip-version-check "$wheel" \
  "$(pin pymeshlab)" "$(pin trimesh)" "$(pin pytest)" "$(pin dask)" "$(pin distributed)" "$(pin fsspec)"
cd "$env"
"$env/venv/bin/python" -c "import vrsimplify, sys; assert '$env' in vrsimplify.__file__, vrsimplify.__file__"
import_ms=$("$env/venv/bin/python" -c "import time; t = time.perf_counter(); import vrsimplify; print(f'{1e3 * (time.perf_counter() - t):.0f}')")
echo "test_wheel: $(basename "$wheel"): $(du -k "$wheel" | cut -f1) KiB, import vrsimplify ${import_ms} ms"
PATH="$env/venv/bin:$PATH" VRS_REQUIRE_PYMESHLAB=1 QT_QPA_PLATFORM=offscreen \
  "$env/venv/bin/python" -m pytest -q -p no:cacheprovider --rootdir "$env" "$top/python/tests"
echo "test_wheel: the examples the README and the documentation show"
PATH="$env/venv/bin:$PATH" QT_QPA_PLATFORM=offscreen "$env/venv/bin/python" "$top/tests/docs/run_examples.py" "$top"
