#!/usr/bin/env bash
# Prints the URI of the Debian archive this machine's apt already uses for its own release
# (the first `deb` entry whose suite is the release's codename), so the project never names a
# mirror itself: machines differ in mirrors. Reads deb822 (*.sources) and one-line (*.list) files.
#   scripts/lib/debian_mirror.sh            -> e.g. http://mirror.example/debian
set -euo pipefail
. /etc/os-release
codename=${VERSION_CODENAME:?no VERSION_CODENAME in /etc/os-release}
files=()
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] && files+=("$f")
done
uri=$(awk -v want="$codename" '
  # deb822 stanzas: fields until a blank line
  FILENAME ~ /\.sources$/ {
    if ($0 ~ /^[[:space:]]*$/) { stanza(); next }
    if ($1 == "Types:") types = $0
    if ($1 == "URIs:") uris = $2
    if ($1 == "Suites:") suites = $0
    if ($1 == "Enabled:") enabled = $2
    next
  }
  # one-line entries: deb [options] URI SUITE COMPONENTS...
  $1 == "deb" {
    i = 2; if ($i ~ /^\[/) { while ($i !~ /\]$/) i++; i++ }
    if ($(i + 1) == want && !found) { print $i; found = 1 }
  }
  function stanza() {
    if (!found && enabled != "no" && types ~ /[[:space:]]deb([[:space:]]|$)/) {
      n = split(suites, s, /[[:space:]]+/)
      for (j = 2; j <= n; j++) if (s[j] == want) { print uris; found = 1; break }
    }
    types = uris = suites = enabled = ""
  }
  ENDFILE { if (FILENAME ~ /\.sources$/) stanza() }
' "${files[@]}" | head -n 1)
[ -n "$uri" ] || { echo "debian_mirror: no deb entry for $codename in apt's sources" >&2; exit 1; }
echo "${uri%/}"
