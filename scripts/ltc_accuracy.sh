#!/usr/bin/env bash
# Writes reports/ltc-vs-ltc_code.md: the 64 x 64 LTC fit against ltc_code's published table on
# held-out error, neighbour jumps and bilinear lookups, and the fit's wall and CPU time (medians of
# $LTC_RUNS runs, default 5). Not part of `reproduce`: it takes seconds and the time depends on the
# machine. Commit the file.
#   scripts/ltc_accuracy.sh [BUILD_DIR]        default build dir: build
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target ltc_accuracy
"$BUILD/bench/ltc_accuracy" --runs "${LTC_RUNS:-5}" --out reports/ltc-vs-ltc_code.md
echo "ltc_accuracy: wrote reports/ltc-vs-ltc_code.md" >&2
