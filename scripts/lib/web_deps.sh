#!/usr/bin/env bash
# What the viewer page and its browser tests need: Node.js with npm and Debian's Chromium (from
# apt when missing), and web/package-lock.json's packages (three.js, Khronos' glTF-Validator,
# puppeteer-core: pinned) in web/node_modules, downloaded through npm's configured registry
# into a cache under $VRS_CACHE. Idempotent: a second run only checks.
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
sudo_=""
[ "$(id -u)" -eq 0 ] || sudo_="sudo"
missing=()
command -v npm >/dev/null || missing+=(nodejs npm)
command -v chromium >/dev/null || missing+=(chromium)
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  $sudo_ apt-get update -qq
  $sudo_ env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
stamp=$top/web/node_modules/.vrsimplify-lock
if ! cmp -s "$top/web/package-lock.json" "$stamp" 2>/dev/null; then
  echo "setup: npm ci in web/ (three.js, gltf-validator, puppeteer-core)"
  (cd "$top/web" && npm ci --cache "$cache/npm" --no-audit --no-fund --loglevel=error >/dev/null)
  cp "$top/web/package-lock.json" "$stamp"
fi
