#!/usr/bin/env bash
# Makes (or keeps) a virtual environment of Debian's python3 holding exactly a requirements
# file's pinned packages: rebuilt from scratch whenever that file changes (its sha256 is kept
# inside), so an environment never drifts from what the repository pins.
#   scripts/lib/pinned_venv.sh VENV_DIR REQUIREMENTS_FILE
set -euo pipefail
venv=$1 req=$2
sha=$(sha256sum "$req" | cut -d' ' -f1)
[ "$(cat "$venv/.requirements.sha256" 2>/dev/null)" = "$sha" ] && exit 0
echo "Python virtual environment $venv ($(basename "$req"))"
rm -rf "$venv"
/usr/bin/python3 -m venv "$venv"
"$venv/bin/pip" install -q --disable-pip-version-check -r "$req"
echo "$sha" >"$venv/.requirements.sha256"
