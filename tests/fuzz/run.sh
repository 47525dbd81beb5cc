#!/usr/bin/env bash
# Runs one libFuzzer target seeded from the bad/good input corpus.
#   tests/fuzz/run.sh TARGET SECONDS [BUILD_DIR]
#   TARGET: ri_yaml | nk_csv | sopra_nk | wvase_mat | catalog | scene | ocio | exr_env
# Build first: CC=clang CXX=clang++ cmake -S . -B build-fuzz -DFRESNEL_LAB_FUZZ=ON -DFRESNEL_LAB_BENCH=OFF
#              cmake --build build-fuzz --target fuzz_TARGET
# The working corpus grows in $FUZZ_WORK/TARGET (default /tmp/fresnel-lab-fuzz); crashers land in
# tests/fuzz/findings/ (git-ignored): copy each, once fixed, into tests/bad_input/.
set -euo pipefail
cd "$(dirname "$0")/../.."
target=$1 seconds=$2 build=${3:-build-fuzz}
work=${FUZZ_WORK:-/tmp/fresnel-lab-fuzz}/$target
mkdir -p "$work" tests/fuzz/findings
case $target in
  ri_yaml) seeds=(tests/bad_input/ri_yaml tests/good_input/ri_bom_crlf.yml tests/good_input/ri_bom.yml tests/good_input/ri_crlf_formula.yml tests/good_input/db) ;;
  nk_csv) seeds=(tests/bad_input/csv tests/bad_input/text tests/bad_input/decimal_comma tests/bad_input/energy
    tests/good_input/nk_bom_crlf.csv tests/good_input/nk_cr_only.csv tests/good_input/nk_no_k.csv
    tests/good_input/nk_gold_like.csv tests/good_input/nk_gold_like_decimal_comma.csv tests/good_input/nk_energy_ev.csv
    tests/good_input/nk_semicolon_mixed_marks.csv tests/good_input/nk_trailing_separator.csv tests/good_input/nk_cp1252_micro.txt) ;;
  sopra_nk) seeds=(tests/bad_input/sopra tests/good_input/sopra_decimal_comma.nk) ;;
  wvase_mat) seeds=(tests/bad_input/wvase tests/good_input/wvase_gold_like.mat) ;;
  catalog) seeds=(tests/bad_input/catalog tests/good_input/catalog materials) ;;
  scene) seeds=(tests/bad_input/scene examples) ;;
  ocio) seeds=(tests/bad_input/ocio tests/good_input/ocio) ;;
  exr_env) seeds=(tests/bad_input/env tests/good_input/env) ;;
  *) echo "unknown target $target" >&2; exit 2 ;;
esac
for s in "${seeds[@]}"; do
  if [ -d "$s" ]; then find "$s" -type f -exec cp -n {} "$work/" \; ; else cp -n "$s" "$work/"; fi
done
# Extra libFuzzer options (e.g. -jobs=1, -print_final_stats=1 is always on) from $FUZZ_ARGS.
exec "$build/tests/fuzz/fuzz_$target" "$work" -dict="tests/fuzz/$target.dict" -max_total_time="$seconds" \
  ${FUZZ_ARGS:-} -max_len=8192 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="tests/fuzz/findings/$target-"
