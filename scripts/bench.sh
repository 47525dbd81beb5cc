#!/usr/bin/env bash
# Runs the Google Benchmark programs and writes reports/bench.md (machine noted) and
# bench/model_costs.csv (the per-model costs `table speed` and `plan` read; commit both).
#   scripts/bench.sh [BUILD_DIR]        default build dir: build
# Extra Google Benchmark flags can go in $BENCH_FLAGS (e.g. --benchmark_filter=de2000).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target bench_speed fresnel-lab
"$BUILD/bench/bench_speed" --fl_write=. --benchmark_repetitions="${BENCH_REPETITIONS:-3}" \
  --benchmark_min_time="${BENCH_MIN_TIME:-0.2}" ${BENCH_FLAGS:-}
# The speed table's plot, from the costs just written.
"$BUILD/src/fresnel-lab" -q speed --plot reports/speed.png >/dev/null
echo "bench: wrote reports/bench.md, bench/model_costs.csv and reports/speed.png" >&2
