#!/usr/bin/env bash
# Builds the documentation site into build/site with `mkdocs build --strict` (a broken link, a
# missing page or a Python reference that does not resolve fails it): docs/ and the benchmark
# reports (bench/*.md with their renders and plots, fuzz/open/README.md) and CHANGELOG.md are
# staged into build/docs-src first, so the reports stay where the benchmarks write them. MkDocs and its
# plugins are pinned in docs/requirements.txt, in $VRS_CACHE/docs-venv.
#   scripts/docs.sh            -> build/site/index.html
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
"$top/scripts/lib/pinned_venv.sh" "$cache/docs-venv" "$top/docs/requirements.txt"
stage=$top/build/docs-src
rm -rf "$stage" && mkdir -p "$stage/bench" "$stage/fuzz/open"
cp "$top"/docs/*.md "$stage/"
cp -r "$top/docs/start" "$top/docs/guides" "$stage/"
cp -r "$top/docs/images" "$stage/"
cp "$top"/bench/*.md "$stage/bench/"
cp -r "$top/bench/renders" "$top/bench/plots" "$stage/bench/"
cp "$top/fuzz/open/README.md" "$stage/fuzz/open/"
cp "$top/CHANGELOG.md" "$stage/changelog.md"
cd "$top"
NO_MKDOCS_2_WARNING=1 "$cache/docs-venv/bin/mkdocs" build --strict --quiet
echo "docs: $top/build/site/index.html ($(find "$top/build/site" -name '*.html' | wc -l) pages)"
