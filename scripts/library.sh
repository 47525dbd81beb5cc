#!/usr/bin/env bash
# Writes reports/library/: the preset library of the whole database (`fresnel-lab library`, every
# conductor page covering the visible range), with its flags, MaterialX, gallery and index.html. Not
# part of `reproduce`: it fits every model on hundreds of pages (about 20 s). Commit the folder.
#   scripts/library.sh [BUILD_DIR]        default build dir: build
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target fresnel-lab
tmp="$(mktemp -d reports/.library.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
"$BUILD/src/fresnel-lab" library --out "$tmp/library"
rm -rf reports/library
mv "$tmp/library" reports/library
echo "library: wrote reports/library" >&2
