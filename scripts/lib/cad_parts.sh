#!/usr/bin/env bash
# Makes (once per version of the modelling script and its pins) the CAD data set: the parts of
# bench/cad/make_parts.py, modelled in build123d (OpenCASCADE) and exported to STL as CAD tools
# do, under $VRS_CACHE/cad-parts-<hash>/; prints that folder.
#   scripts/lib/cad_parts.sh
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
hash=$(cat "$top/bench/cad/make_parts.py" "$top/bench/cad/requirements.txt" | sha256sum | cut -c1-12)
dir=$cache/cad-parts-$hash
if [ ! -f "$dir/.done" ]; then
  "$top/scripts/lib/pinned_venv.sh" "$cache/cad-venv" "$top/bench/cad/requirements.txt" >&2
  rm -rf "$dir"
  "$cache/cad-venv/bin/python" "$top/bench/cad/make_parts.py" "$dir" >&2
  touch "$dir/.done"
fi
echo "$dir"
