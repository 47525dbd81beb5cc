#!/usr/bin/env bash
# Runs every example command of README.md's tour (the lines of its sh blocks that start with
# `fresnel-lab`) in a scratch folder that sees the repository's examples/, tests/ and materials/
# and the database's ../shared beside it, and fails naming each one that does not exit 0.
#   scripts/check-readme-examples.sh [FRESNEL_LAB] [SHARED_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cli=$(realpath "${1:-$root/build/src/fresnel-lab}")
shared=$(realpath "${2:-$root/../shared}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/repo"
ln -s "$shared" "$work/shared"
for d in examples tests materials; do ln -s "$root/$d" "$work/repo/$d"; done
mkdir "$work/bin"
ln -s "$cli" "$work/bin/fresnel-lab"
# Lines starting with `fresnel-lab` inside ```sh blocks.
mapfile -t examples < <(awk '/^ *```sh/ {sh = 1; next} /^ *```/ {sh = 0} sh && /^ *fresnel-lab / {sub(/^ */, ""); print}' "$root/README.md")
[ "${#examples[@]}" -gt 0 ] || { echo "check-readme-examples: no example found in README.md" >&2; exit 1; }
failed=0
cd "$work/repo"
for cmd in "${examples[@]}"; do
  if ! PATH="$work/bin:$PATH" bash -c "$cmd" >"$work/out" 2>"$work/err"; then
    echo "check-readme-examples: FAILED: $cmd" >&2
    tail -n 3 "$work/err" >&2
    failed=$((failed + 1))
  fi
done
echo "check-readme-examples: ${#examples[@]} examples, $failed failed"
[ "$failed" = 0 ]
