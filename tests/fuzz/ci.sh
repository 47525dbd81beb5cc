#!/usr/bin/env bash
# CI's short fuzzing pass: builds every libFuzzer target (clang, build-fuzz/) and runs each for
# RUNS inputs (default 20000, about 10-25 s each here) from its seeds in a fresh working corpus,
# with a fixed seed: the same commit explores the same inputs on every machine, so this pass is a
# repeatable regression test rather than a lottery. Open-ended fuzzing is tests/fuzz/run.sh. A
# crash, leak, timeout or sanitizer report fails the run (the input is kept in tests/fuzz/findings/).
#   tests/fuzz/ci.sh [RUNS]
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-20000} build=${FUZZ_BUILD:-build-fuzz}
targets=(ri_yaml nk_csv sopra_nk wvase_mat catalog scene ocio exr_env)
start=$(date +%s)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DFRESNEL_LAB_FUZZ=ON \
  -DFRESNEL_LAB_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for t in "${targets[@]}"; do
  # 900 s only bounds a pathological run; -runs ends every normal one.
  if ! FUZZ_WORK="$work" FUZZ_ARGS="-seed=1 -runs=$runs" tests/fuzz/run.sh "$t" 900 "$build" \
    >"$work/$t.log" 2>&1; then
    tail -n 40 "$work/$t.log" >&2
    echo "fuzz: fuzz_$t FAILED (input in tests/fuzz/findings/)" >&2
    exit 1
  fi
  echo "fuzz: fuzz_$t $runs executions (seed 1), no crash" >&2
done
echo "fuzz: every harness passed in $(($(date +%s) - start)) s" >&2
