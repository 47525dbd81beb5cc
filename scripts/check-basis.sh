#!/usr/bin/env bash
# Regenerates the Fresnel basis from the database (`fresnel-lab basis`, docs/basis.md) and checks it
# byte for byte against the committed data/basis/ and src/fresnel/basis_polynomials.h; with
# --update, writes them instead. Exits 77 (skipped, for CTest) when the database is absent, except
# in CI (the environment variable CI set, as CI runners set it): there a missing database fails.
#   scripts/check-basis.sh [--update] [FRESNEL_LAB [DATABASE]]
# Default FRESNEL_LAB: build/src/fresnel-lab (built first); default DATABASE: ../shared's.
set -euo pipefail
cd "$(dirname "$0")/.."
update=0
if [[ "${1:-}" == "--update" ]]; then
  update=1
  shift
fi
cli="${1:-}"
db="${2:-../shared/refractiveindex.info-database/database}"
if [[ ! -d "$db/data" ]]; then
  if [[ -n "${CI:-}" && "${CI}" != false && "${CI}" != 0 ]]; then
    echo "check-basis: FAILED: database not found (looked for $db/data; CI is set)" >&2
    exit 1
  fi
  echo "check-basis: no database at $db; skipped" >&2
  exit 77
fi
if [[ -z "$cli" ]]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build -j"$(nproc)" --target fresnel-lab
  cli=build/src/fresnel-lab
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
"$cli" --db "$db" basis --out "$tmp/basis"
header="src/fresnel/basis_polynomials.h"
if ((update)); then
  mkdir -p data/basis
  rm -f data/basis/*
  cp "$tmp/basis/basis_polynomials.h" "$header"
  find "$tmp/basis" -maxdepth 1 -type f ! -name basis_polynomials.h -exec cp {} data/basis/ \;
  echo "check-basis: wrote data/basis/ and $header" >&2
  exit 0
fi
status=0
cmp "$tmp/basis/basis_polynomials.h" "$header" || status=1
for f in "$tmp"/basis/*; do
  name="$(basename "$f")"
  [[ "$name" == basis_polynomials.h ]] && continue
  cmp "$f" "data/basis/$name" || status=1
done
for f in data/basis/*; do
  [[ -e "$tmp/basis/$(basename "$f")" ]] || { echo "check-basis: $f is not generated" >&2; status=1; }
done
if ((status)); then
  echo "check-basis: the regenerated basis differs from the committed one" >&2
else
  echo "check-basis: byte-identical" >&2
fi
exit "$status"
