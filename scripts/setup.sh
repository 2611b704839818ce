#!/usr/bin/env bash
# Installs what a fresh Debian bookworm machine lacks to build and test vrsimplify (MeshLab
# 2020.09 included), then fetches the sources the build reads but the repository never holds
# (vcglib and MeshLab's headers: 2020.09 from Debian's `meshlab` source package, 2022.02 and
# 2025.07 from trixie's and sid's, see scripts/lib/meshlab_sources.sh; meshoptimizer's encoder
# for compressed .glb files, scripts/lib/meshoptimizer_sources.sh), the real test meshes
# (Debian's `libcgal-demo`) and pymeshlab with the Python test tools, pinned
# (requirements.txt), into a virtual environment under $VRS_CACHE (default /var/cache/vrsimplify),
# and the viewer page's tools (scripts/lib/web_deps.sh: Node.js, Chromium, pinned npm packages).
# With --roots it also makes the Debian trixie and sid roots holding the real MeshLab 2022.02
# and 2025.07 GUIs (scripts/lib/meshlab_root.sh; a few minutes, once).
# Idempotent: a second run only checks.
#   scripts/setup.sh [--roots] [EXTRA_DEBIAN_PACKAGE...]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
third="$top/third_party"
cache=${VRS_CACHE:-/var/cache/vrsimplify}
roots=0
if [ "${1:-}" = --roots ]; then roots=1; shift; fi
sudo_=""
[ "$(id -u)" -eq 0 ] || sudo_="sudo"

want=(build-essential cmake pkg-config git xz-utils libgtest-dev libgmock-dev libbenchmark-dev
      clang-format libeigen3-dev
      # MeshLab itself, what its plugin headers need, and a display for it
      meshlab qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev
      xvfb xauth xdotool imagemagick
      # the benchmark's peers and plots
      libmeshoptimizer-dev libvtk9-dev libopenmesh-dev gnuplot-nox
      # robustness: the fuzzer (clang 14 + libFuzzer) and the sweep over assimp's test models
      clang-14 libfuzzer-14-dev libclang-rt-14-dev libassimp-dev assimp-testmodels time
      # the newer MeshLabs: their sources through a separate apt configuration, their GUIs in
      # debootstrap roots, pymeshlab in a virtual environment
      dpkg-dev debootstrap python3-venv
      # Python's headers for the package's extension module, and what the CPython 3.13 that
      # builds the stable-ABI wheel needs (scripts/lib/cpython.sh: ssl, zlib, ctypes, lzma, bz2)
      python3-dev libssl-dev zlib1g-dev libffi-dev libbz2-dev liblzma-dev)
want+=("$@")
missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

# `apt-get source` needs a deb-src entry mirroring the machine's own deb entry.
src_list=/etc/apt/sources.list.d/vrsimplify-deb-src.sources
need_src=0
[ -f "$third/meshlab/vcglib/vcg/complex/complex.h" ] || need_src=1
if [ "$need_src" -eq 1 ] && ! grep -rqs '^Types:.*deb-src\|^deb-src' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  . /etc/os-release
  printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$("$top/scripts/lib/debian_mirror.sh")" "$VERSION_CODENAME" | $sudo_ tee "$src_list" >/dev/null
fi
if [ ${#missing[@]} -gt 0 ] || [ "$need_src" -eq 1 ] || [ ! -d "$third/cgal-data" ]; then
  echo "setup: apt-get update"
  $sudo_ apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  $sudo_ env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

mkdir -p "$third"
if [ "$need_src" -eq 1 ]; then
  echo "setup: fetching Debian's meshlab source package (vcglib, MeshLab headers)"
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get source --download-only meshlab >/dev/null 2>&1)
  orig=$(ls "$tmp"/meshlab_*.orig.tar.xz | head -n 1)
  rm -rf "$third/meshlab" && mkdir -p "$third/meshlab"
  tar -xJf "$orig" -C "$third/meshlab" --strip-components=1
  rm -rf "$tmp"
fi

if [ ! -d "$third/cgal-data" ]; then
  echo "setup: fetching Debian's libcgal-demo data set (real test meshes)"
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download libcgal-demo >/dev/null 2>&1 && dpkg -x libcgal-demo_*.deb x)
  mkdir -p "$third/cgal-data"
  tar -xzf "$tmp/x/usr/share/doc/libcgal-dev/data.tar.gz" -C "$third/cgal-data"
  rm -rf "$tmp"
fi
for v in 2022.02 2025.07; do
  "$top/scripts/lib/meshlab_sources.sh" "$v" "$third/meshlab-$v"
done
# meshoptimizer's encoder, for the .glb writer's EXT_meshopt_compression (gltf/CMakeLists.txt).
"$top/scripts/lib/meshoptimizer_sources.sh" "$third/meshoptimizer"

# pymeshlab, pytest, trimesh and auditwheel, pinned, in a virtual environment of their own
# (rebuilt when requirements.txt changes). Debian's python3, whatever else is on PATH.
"$top/scripts/lib/pinned_venv.sh" "$cache/venv" "$top/requirements.txt"
# Node.js, Chromium and the viewer page's pinned npm packages (web/package-lock.json).
"$top/scripts/lib/web_deps.sh"

if [ "$roots" -eq 1 ]; then
  for suite in trixie sid; do
    "$top/scripts/lib/meshlab_root.sh" "$suite" >/dev/null
  done
fi
echo "setup: ok"
