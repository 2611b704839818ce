#!/usr/bin/env bash
# The wheels as users get them: scripts/build_wheel.sh, then each wheel `pip install`ed into a
# fresh virtual environment of the Python it is for, with pymeshlab, trimesh, pytest and Dask at
# the pinned versions, `import vrsimplify` and a 1 M-face run, and the package's tests
# (python/tests) run from outside the source tree against the installed files only:
#   - cp311 on Debian's python3 (3.11);
#   - cp312-abi3 on the CPython 3.13 scripts/lib/cpython.sh builds, and on CPython 3.14 and
#     3.15 inside the Debian sid root (scripts/setup.sh --roots; skipped, saying so, without
#     it; 3.15 with Debian's numpy and without pymeshlab, which PyPI has no 3.15 builds of);
#   - the sdist, built by `pip install` (a compiler at hand) on Debian's python3: the numpy API.
# Then the examples the README and the documentation show, in the cp311 environment. Prints
# each wheel's size and import time.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
"$top/scripts/build_wheel.sh"
pin() { grep -E "^$1==" "$top/requirements.txt"; }
pins=("$(pin pymeshlab)" "$(pin numpy)" "$(pin trimesh)" "$(pin pytest)" "$(pin dask)" "$(pin distributed)" "$(pin fsspec)")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# A 1 M-face run: an icosphere of 1 310 720 faces to 10 %.
big_run='import numpy as np, trimesh, vrsimplify
m = trimesh.creation.icosphere(subdivisions=8)
r = vrsimplify.simplify(np.asarray(m.vertices), np.asarray(m.faces), ratio=0.1)
assert r.report["target_reached"] and len(r.faces) <= 131072, r.report
print("a %d-face run to %d faces" % (len(m.faces), len(r.faces)))'

suite() { # LABEL PYTHON WHEEL [pip runner...]
  local label=$1 python=$2 wheel=$3 env=$scratch/$1
  "$python" -m venv "$env/venv"
  # With the [trimesh] extra, as the README installs it (scipy from it, pinned).
  "$env/venv/bin/python" -m pip install -q --disable-pip-version-check "$wheel[trimesh]" "${pins[@]}" "$(pin scipy)"
  cd "$env"
  "$env/venv/bin/python" -c "import vrsimplify, sys; assert '$env' in vrsimplify.__file__, vrsimplify.__file__"
  local ms
  ms=$("$env/venv/bin/python" -c "import time; t = time.perf_counter(); import vrsimplify; print(f'{1e3 * (time.perf_counter() - t):.0f}')")
  echo "test_wheel [$label]: $(basename "$wheel"): $(du -k "$wheel" | cut -f1) KiB, import vrsimplify ${ms} ms, $("$env/venv/bin/python" -c "$big_run")"
  PATH="$env/venv/bin:$PATH" VRS_REQUIRE_PYMESHLAB=1 QT_QPA_PLATFORM=offscreen \
    "$env/venv/bin/python" -m pytest -q -p no:cacheprovider --rootdir "$env" "$top/python/tests"
  cd "$top"
}

cp311=$(ls "$top"/dist/vrsimplify-*-cp311-cp311-*.whl)
abi3=$(ls "$top"/dist/vrsimplify-*-cp312-abi3-*.whl)
sdist=$(ls "$top"/dist/vrsimplify-*.tar.gz)
suite cp311 /usr/bin/python3 "$cp311"
echo "test_wheel: the examples the README and the documentation show"
PATH="$scratch/cp311/venv/bin:$PATH" QT_QPA_PLATFORM=offscreen "$scratch/cp311/venv/bin/python" "$top/tests/docs/run_examples.py" "$top"
suite cp313-abi3 "$("$top/scripts/lib/cpython.sh")" "$abi3"

# CPython 3.14 and 3.15 in the sid root: Debian's python3.1x there has no ensurepip, so pip runs
# from its wheel (the one CPython 3.13 bundles); this machine's certificates go in for pip.
# PyPI has no numpy nor pymeshlab for 3.15 yet (numpy 2.4.6: cp314 at most): there the venv sees
# Debian's numpy (built for 3.14 and 3.15), pip and the C extensions Dask's distributed needs
# (meshlab_root.sh installs them), pip adds the pinned pure-Python rest, and pymeshlab's tests
# are skipped, saying so.
root=$cache/roots/sid
sid_suite() { # PYTHON (python3.14 | python3.15)
  local python=$1 inside=/tmp/vrs-wheel-test venv_opts="--without-pip" pip_pins="${pins[*]} $(pin scipy) pip"
  local require=1 pip=""
  if [ "$python" = python3.15 ]; then # the pip CPython 3.13 bundles fails on 3.15: Debian's
    venv_opts="--without-pip --system-site-packages" require="" pip="venv/bin/python -m pip"
    pip_pins="$(pin trimesh) $(pin pytest) $(pin dask) $(pin distributed) $(pin fsspec)"
  fi
  rm -rf "$root$inside" && mkdir -p "$root$inside"
  cp "$abi3" "$root$inside/"
  mkdir -p "$root$inside/python" # the tests read ../../meshes and ../examples
  cp -r "$top/python/tests" "$top/python/examples" "$root$inside/python/"
  cp -r "$top/meshes" "$root$inside/meshes"
  cp /etc/ssl/certs/ca-certificates.crt "$root$inside/ca.crt"
  cp "$(dirname "$("$top/scripts/lib/cpython.sh")")"/../lib/python3.13/ensurepip/_bundled/pip-*.whl "$root$inside/"
  local pipwhl pip_env="" var
  pipwhl=$(basename "$(ls "$root$inside"/pip-*.whl)")
  [ -n "$pip" ] || pip="venv/bin/python $pipwhl/pip"
  # pip inside uses the index this machine's pip is configured with (file and environment).
  [ -f /etc/pip.conf ] && cp /etc/pip.conf "$root$inside/pip.conf" && pip_env="PIP_CONFIG_FILE=$inside/pip.conf"
  for var in PIP_INDEX_URL PIP_EXTRA_INDEX_URL PIP_TRUSTED_HOST; do
    [ -n "${!var:-}" ] && pip_env="$pip_env $var=${!var}"
  done
  cat >"$root$inside/run.sh" <<RUN
set -e
cd $inside
export PIP_CERT=$inside/ca.crt PIP_DISABLE_PIP_VERSION_CHECK=1 QT_QPA_PLATFORM=offscreen VRS_REQUIRE_PYMESHLAB=$require $pip_env
$python -m venv $venv_opts venv
$pip install -q $(basename "$abi3") $pip_pins
venv/bin/python -c "import sys, numpy, vrsimplify; print(sys.version.split()[0], 'import ok', vrsimplify.__version__, 'numpy', numpy.__version__)"
venv/bin/python -c '$big_run'
PATH=$inside/venv/bin:\$PATH venv/bin/python -m pytest -q -p no:cacheprovider -rs --rootdir $inside python/tests
RUN
  echo "test_wheel [${python#python}-abi3, Debian sid root]: $(basename "$abi3")"
  "$top/scripts/lib/in_root.sh" "$root" bash "$inside/run.sh"
  rm -rf "$root$inside"
}
for python in python3.14 python3.15; do
  if [ -x "$root/usr/bin/$python" ]; then
    sid_suite "$python"
  else
    echo "test_wheel: no $python in the Debian sid root ($root; scripts/setup.sh --roots makes it): not tried"
  fi
done

echo "test_wheel [sdist]: pip install $(basename "$sdist") (built here)"
/usr/bin/python3 -m venv "$scratch/sdist"
"$scratch/sdist/bin/python" -m pip install -q --disable-pip-version-check "$sdist" "$(pin numpy)"
(cd "$scratch" && "$scratch/sdist/bin/python" -c "$(printf '%s\n' 'import numpy as np, vrsimplify' \
  'v = np.random.default_rng(1).random((200, 3)); v[:, 2] = 0' \
  'f = np.array([[i, i + 1, i + 2] for i in range(0, 195, 3)])' \
  'r = vrsimplify.simplify(v, f, ratio=0.5); print("sdist: import and a run ok,", r.report["stop_reason"])')")
