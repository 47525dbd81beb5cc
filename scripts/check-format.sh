#!/usr/bin/env bash
# Every C++ source file of the repository (src/, tests/, bench/) as clang-format (.clang-format)
# writes it, no function in src/ longer than 60 lines (scripts/check-function-length.py), no file
# in src/ over 400 lines without its reason (scripts/check-file-length.py), and no #include against
# the layers (scripts/check-layers.py, docs/architecture.md).
#   scripts/check-format.sh        exit 1 naming every file clang-format would change
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check-format: clang-format not found (Debian clang-format)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.cc' '*.hpp')
status=0
clang-format --dry-run -Werror "${files[@]}" || status=1
python3 scripts/check-function-length.py src || status=1
python3 scripts/check-file-length.py || status=1
python3 scripts/check-layers.py || status=1
if [ "$status" = 0 ]; then
  echo "check-format: ${#files[@]} files formatted, no function in src/ over 60 lines"
fi
exit "$status"
