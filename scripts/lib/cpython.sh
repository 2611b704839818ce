#!/usr/bin/env bash
# A CPython 3.13 for this machine, whose own Python is 3.11: the interpreter the stable-ABI
# wheel (cp312-abi3, for CPython 3.12 and later) is built with, linked against this machine's
# glibc so that the wheel runs wherever Debian 12 / Ubuntu 22.04 binaries do. Built once from
# Debian trixie's source package (the orig tarball, pinned by sha256, fetched through the
# separate apt configuration of debian_source.sh) into $VRS_CACHE/cpython-3.13; prints the
# interpreter's path.
#   scripts/lib/cpython.sh           -> $VRS_CACHE/cpython-3.13/bin/python3.13
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
version='3.13.5-2+deb13u5' orig='python3.13_3.13.5.orig.tar.xz'
sha=93e583f243454e6e9e4588ca2c2662206ad961659863277afcdb96801647d640
prefix=$cache/cpython-3.13
if [ "$(cat "$prefix/.sha256" 2>/dev/null)" = "$sha" ] && [ -x "$prefix/bin/python3.13" ]; then
  echo "$prefix/bin/python3.13"
  exit 0
fi
tarball=$("$here/debian_source.sh" python3.13 "$version" "$orig" "$sha")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "cpython: building Python 3.13 into $prefix (once, a few minutes)" >&2
tar -xJf "$tarball" -C "$work"
cd "$work"/Python-3.13*
./configure --prefix="$prefix" --without-ensurepip --disable-test-modules >"$work/configure.log" 2>&1 ||
  { tail -n 20 "$work/configure.log" >&2; exit 1; }
make -j "$(nproc)" >"$work/make.log" 2>&1 || { tail -n 30 "$work/make.log" >&2; exit 1; }
rm -rf "$prefix"
make install >"$work/install.log" 2>&1 || { tail -n 20 "$work/install.log" >&2; exit 1; }
"$prefix/bin/python3.13" -c 'import ssl, zlib, ctypes, lzma, bz2' ||
  { echo "cpython: the build lacks a module pip needs" >&2; exit 1; }
echo "$sha" >"$prefix/.sha256"
echo "$prefix/bin/python3.13"
