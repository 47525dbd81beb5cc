#!/usr/bin/env bash
# Acceptance check of the closed model unit: a renamed copy of an existing model file plus its
# entry in the registry builds, and `reproduce`, `table speed`, `plan`, `shader`, `lut` and the
# whole test suite pass and show the new model (its CPU and GPU costs unmeasured).
#
# Works on a scratch copy of the tracked files (their working-tree content) under /tmp, never in
# the repository: the copy is a git repository of its own, so `git status` there lists the files
# the new model touched (must be 2: the new unit and src/fresnel/registry.h). Builds only
# fresnel-lab and fl_tests (Release, ccache), then runs the commands and CTest.
#   scripts/check-model-unit.sh [MODEL]    default schlick: models/schlick.h → models/schlick_copy.h
# Environment: FL_CHECK_DIR (scratch folder, default /tmp/fresnel-lab-check-model-unit; a fixed
# path, so that ccache hits on the next run; kept when a step fails), FL_CHECK_KEEP=1 keeps it
# always, FL_CHECK_JOBS
# (default 2), FL_CHECK_SANITIZE=1 builds the copy with ASan + UBSan and runs its whole suite
# through the copy's scripts/test-sanitize.sh (every target), then the commands with the sanitized
# binary: CI's sanitizer pass and this check in one build. Exit status: 0 when every step passes,
# 1 otherwise.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
model="${1:-schlick}"
copy="${model}_copy"
scratch="${FL_CHECK_DIR:-/tmp/fresnel-lab-check-model-unit}"
jobs="${FL_CHECK_JOBS:-2}"
repo="$scratch/repo"
start=$(date +%s)
unit="src/fresnel/models/$model.h"
[ -f "$src/$unit" ] || { echo "check-model-unit: no $unit" >&2; exit 2; }

# The scratch copy: tracked files, with ../shared (database, test data) and the npm packages the
# tests use linked from the source tree.
rm -rf "$scratch"
mkdir -p "$repo"
(cd "$src" && git ls-files -z | tar --null -T - -cf -) | tar -xf - -C "$repo"
[ -e "$src/../shared" ] && ln -s "$(cd "$src/../shared" && pwd)" "$scratch/shared"
for d in tests/browser tests/validators; do
  [ -d "$src/$d/node_modules" ] && ln -s "$src/$d/node_modules" "$repo/$d/node_modules"
done
cd "$repo"
git init -q . && git add -A && git -c user.name=check -c user.email=check@localhost commit -qm base
printf 'node_modules\nbuild/\n' >> .git/info/exclude

# The renamed copy: the unit struct (the first struct inside `namespace models`) Type → TypeCopy,
# the model's name and its helpers model → model_copy, so both files can be included together.
type=$(awk '/^namespace models/ { m = 1 } m && /^struct [A-Za-z0-9_]+ \{/ { print $2; exit }' "$unit")
[ -n "$type" ] || { echo "check-model-unit: no unit struct in $unit" >&2; exit 2; }
# One pass per name, prefixes and whole words together, so that no name is renamed twice; names
# qualified by another scope (Term::Schlick, a table term) are kept.
sed -E -e "s/::${type}\\b/::@KEEP@/g" -e "s/\\b${model}(_|\\b)/${copy}\\1/g" \
  -e "s/\\b(k?)${type}([A-Z]|\\b)/\\1${type}Copy\\2/g" -e "s/::@KEEP@/::${type}/g" \
  "$unit" > "src/fresnel/models/$copy.h"
# One entry in the registry (and its include).
sed -i "s|#include \"fresnel/models/$model.h\"|&\n#include \"fresnel/models/$copy.h\"|" \
  src/fresnel/registry.h
perl -0pi -e "s/(using Registry = ModelList<[^;]*?)>;/\$1, models::${type}Copy>;/s" \
  src/fresnel/registry.h
grep -q "models::${type}Copy>" src/fresnel/registry.h ||
  { echo "check-model-unit: could not add the registry entry" >&2; exit 2; }
echo "check-model-unit: $unit → src/fresnel/models/$copy.h (models::${type}Copy, \"$copy\")"
echo "files touched:"
git status --porcelain | sed 's/^/  /'
touched=$(git status --porcelain | wc -l)

failures=0
step() {  # step NAME COMMAND... : runs it, logs to $scratch/NAME.log, prints pass or FAIL
  local name="$1" t0 rc=0
  shift
  t0=$(date +%s)
  "$@" > "$scratch/$name.log" 2>&1 || rc=$?
  if [ "$rc" = 0 ]; then
    printf '  %-14s pass  (%ss)\n' "$name" $(($(date +%s) - t0))
  else
    printf '  %-14s FAIL  (exit %s, %ss; last lines of %s:)\n' "$name" "$rc" \
      $(($(date +%s) - t0)) "$scratch/$name.log"
    tail -n 15 "$scratch/$name.log" | sed 's/^/      /'
    failures=$((failures + 1))
  fi
}
shows() {  # shows FILE PATTERN... : every pattern is in FILE
  local f="$1"
  shift
  for p in "$@"; do grep -q -- "$p" "$f" || { echo "missing '$p' in $f"; return 1; }; done
}

build() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -DCMAKE_C_COMPILER_LAUNCHER=ccache
  CCACHE_BASEDIR="$repo" nice -n 5 cmake --build build -j"$jobs" --target fresnel-lab fl_tests
}
cli=build/src/fresnel-lab
out="$scratch/out"
mkdir -p "$out"
reproduce() {
  "$cli" -q reproduce --out "$out/reports" --no-figures &&
    shows "$out/reports/models.csv" "$copy" &&
    shows "$out/reports/speed.csv" "$copy,derived,unmeasured" &&
    shows "$out/reports/index.html" "$copy"
}
speed() {
  "$cli" -q table speed > "$out/speed.md" && shows "$out/speed.md" "$copy" "unmeasured"
}
plan() {
  "$cli" -q plan examples/scene_ibl.yaml > "$out/plan.md" &&
    shows "$out/plan.md" "Unmeasured cost" "$copy" &&
    "$cli" -q plan examples/scene_ibl.yaml --format json > "$out/plan.json" &&
    shows "$out/plan.json" "\"unmeasured\"" "$copy"
}
shader() {
  for l in punctual ibl area; do
    "$cli" -q shader "$copy" --lighting "$l" > "$out/shader-$l.glsl" &&
      shows "$out/shader-$l.glsl" "fresnel_$copy" || return 1
  done
  "$cli" -q shader "$copy" --lang hlsl --lighting area > "$out/shader.hlsl" &&
    shows "$out/shader.hlsl" "fresnel_$copy"
}
lut() {
  "$cli" -q lut dfg --out "$out/dfg.csv" --size 8 --samples 256 &&
    "$cli" -q lut ltc-moments --out "$out/ltc_moments.csv" --size 8 --samples 256 &&
    "$cli" -q table lut-accuracy gold > "$out/lut-accuracy.md" &&
    shows "$out/lut-accuracy.md" "$copy"
}
suite() { ctest --test-dir build -j"$jobs" --output-on-failure; }
sanitize="${FL_CHECK_SANITIZE:-0}"
if [ "$sanitize" = 1 ]; then
  # The commands below run the sanitized binary: leaks in system libraries as test-sanitize.sh
  # suppresses them.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
  export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$repo/scripts/lsan.supp:print_suppressions=0}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
fi

echo "steps (logs in $scratch/NAME.log):"
if [ "$sanitize" = 1 ]; then
  step asan-suite scripts/test-sanitize.sh build
  grep -E "tests passed|tests failed" "$scratch/asan-suite.log" | sed 's/^/  ctest: /' || true
else
  step build build
fi
if [ "$failures" = 0 ]; then
  step reproduce reproduce
  step table-speed speed
  step plan plan
  step shader shader
  step lut lut
  if [ "$sanitize" != 1 ]; then
    step ctest suite
    grep -E "tests passed|tests failed" "$scratch/ctest.log" | sed 's/^/  ctest: /' || true
  fi
fi
[ "$touched" = 2 ] || { echo "files touched: $touched, expected 2"; failures=$((failures + 1)); }
echo "check-model-unit: $([ "$failures" = 0 ] && echo PASS || echo "FAIL ($failures)"), $(($(date +%s) - start)) s"
# Kept when a step failed (its logs) or when asked.
[ "$failures" != 0 ] || [ "${FL_CHECK_KEEP:-0}" = 1 ] || { cd /; rm -rf "$scratch"; }
[ "$failures" = 0 ]
