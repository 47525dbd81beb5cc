#!/usr/bin/env bash
# CI's short fuzzing pass: builds every libFuzzer target (clang, build-fuzz/) and runs each for
# SECONDS (default 25) from its seeds in a fresh working corpus. A crash, leak, timeout or sanitizer
# report fails the run (the input is kept in tests/fuzz/findings/).
#   tests/fuzz/ci.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-25} build=${FUZZ_BUILD:-build-fuzz}
targets=(ri_yaml nk_csv cgats catalog scene ocio exr_env)
start=$(date +%s)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DFRESNEL_LAB_FUZZ=ON \
  -DFRESNEL_LAB_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for t in "${targets[@]}"; do
  if ! FUZZ_WORK="$work" tests/fuzz/run.sh "$t" "$seconds" "$build" >"$work/$t.log" 2>&1; then
    tail -n 40 "$work/$t.log" >&2
    echo "fuzz: fuzz_$t FAILED (input in tests/fuzz/findings/)" >&2
    exit 1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$t.log")
  echo "fuzz: fuzz_$t ${runs:-?} executions in ${seconds} s, no crash" >&2
done
echo "fuzz: every harness passed in $(($(date +%s) - start)) s" >&2
