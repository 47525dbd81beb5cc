#!/usr/bin/env bash
# Acceptance check of the closed model unit, in two builds of a scratch copy of the tree.
#
# Clean: renamed copies of a rotating model file and of the hardest one (models/basis.h, a template
# over its number of terms) plus their entries in the registry build, and `reproduce`, `table
# speed`, `plan`, `shader`, `lut` and the whole test suite pass and show the new models (their CPU
# and GPU costs unmeasured). `git status` in the copy lists the files the new models touched: the
# new units, src/fresnel/registry.h and README.md's list of models, nothing else.
#
# Faults: five faulty units, each a copy with one thing wrong, registered together in one more
# build (incremental on the clean one); the test suite must fail naming each of them:
#   kernel    the kernel 3 % low at every angle, in C++ and GLSL alike
#   glsl      the GLSL kernel 3 % low, the C++ kernel right
#   tables    the first table term's GLSL weight 3 % low (the generated IBL and area code)
#   average   the closed-form hemispherical average 0.01 high
#   derive    derive() 10 % low on each channel's first parameter (F0 for most models)
# each seeded into the rotating model's copy, or into the basis copy where the rotating model has
# no table terms or no closed-form average. A fault is caught when a failing test's failure
# message (or its trace) names the faulty model.
#
# Works under /tmp on the tracked files' working-tree content, never in the repository: the copy
# is a git repository of its own. Builds fresnel-lab, fl_tests and fl_vulkan_tests (Release,
# ccache) and runs CTest.
#   scripts/check-model-unit.sh [MODEL]   MODEL: the model file to copy beside basis (default:
#                                         chosen by the commit, rotating over models/*.h but basis)
# Environment: FL_CHECK_DIR (scratch folder, default /tmp/fresnel-lab-check-model-unit; a fixed
# path, so that ccache hits on the next run; kept when a step fails), FL_CHECK_KEEP=1 keeps it
# always, FL_CHECK_JOBS (default 2), FL_CHECK_SANITIZE=1 builds the clean copy with ASan + UBSan
# and runs its whole suite through the copy's scripts/test-sanitize.sh (every target), then the
# commands with the sanitized binary: CI's sanitizer pass and this check in one build (the faulty
# build is then a sanitized one too). Exit status: 0 when every step passes and every fault is
# caught, 1 otherwise.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
scratch="${FL_CHECK_DIR:-/tmp/fresnel-lab-check-model-unit}"
jobs="${FL_CHECK_JOBS:-2}"
sanitize="${FL_CHECK_SANITIZE:-0}"
repo="$scratch/repo"
start=$(date +%s)
units=src/fresnel/models

# The rotating model: named, or the commit's hash modulo the number of model files (basis aside).
mapfile -t candidates < <(cd "$src/$units" && ls -- *.h | sed 's/\.h$//' | grep -vx basis)
if [ $# -ge 1 ]; then
  model="$1"
else
  commit=$(git -C "$src" rev-parse HEAD)
  model="${candidates[$((0x${commit:0:7} % ${#candidates[@]}))]}"
fi
[ -f "$src/$units/$model.h" ] || { echo "check-model-unit: no $units/$model.h" >&2; exit 2; }
[ "$model" != basis ] || { echo "check-model-unit: basis is always copied; name another" >&2; exit 2; }
copied=("$model" basis)

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

# copy_unit MODEL: writes models/MODEL_copy.h, a renamed copy of models/MODEL.h, and prints the
# registry entry of its unit ("models::TypeCopy" or, for a template, "models::TypeCopy<args>" with
# the arguments of the original's last registry entry). Renamed: every name the file defines at
# namespace scope (types and kConstants get "Copy", functions "_copy"), wherever it is used
# unqualified; the unit's kName becomes "MODEL_copy" and its kLabel "Copy of MODEL".
copy_unit() {
  perl -e '
    use strict; use warnings;
    my ($model, $in, $out, $registry) = @ARGV;
    local $/; open(my $f, "<", $in) or die; my $t = <$f>; close $f;
    my $k = index($t, "kName =");
    die "check-model-unit: no kName in $in\n" if $k < 0;
    my ($type, $templ, $pre) = (undef, undef, substr($t, 0, $k));
    while ($pre =~ /(template <[^>]*>\s*\n)?struct (\w+) \{/g) { ($templ, $type) = ($1, $2); }
    die "check-model-unit: no unit struct in $in\n" unless $type;
    my %new;
    for my $line (split /\n/, $t) {
      next if $line =~ /^(namespace|using|static_assert|return|#|\/\/|\}|\{|template\b|\s)/;
      if ($line =~ /^struct (\w+)/) { $new{$1} = "$1Copy"; next; }
      if ($line =~ /^(?:inline\s+)?(?:static\s+)?constexpr\s[^=(]*?\b(\w+)\s*(?:\[[^\]]*\]\s*)*[={]/) {
        $new{$1} = "$1Copy"; next;
      }
      if ($line =~ /^[A-Za-z_][\w:<>,\s\*&]*?\b(\w+)\(/) {
        my $n = $1; $new{$n} = $n =~ /^(k?[A-Z])/ ? "${n}Copy" : "${n}_copy";
      }
    }
    for my $n (sort { length($b) <=> length($a) } keys %new) {
      $t =~ s/(?<![\w:.])\Q$n\E\b/$new{$n}/g;
    }
    $t =~ s/(static constexpr const char\* kName = )[^;]+;/$1"${model}_copy";/ or die "no kName\n";
    $t =~ s/(static constexpr const char\* kLabel = )[^;]+;/$1"Copy of $model";/ or die "no kLabel\n";
    open(my $o, ">", $out) or die; print $o $t; close $o;
    open(my $r, "<", $registry) or die; my $reg = <$r>; close $r;
    my $args = "";
    if ($templ) { my @a = ($reg =~ /models::\Q$type\E(<[^>]*>)/g); die "no entry of $type\n" unless @a; $args = $a[-1]; }
    print "models::$new{$type}$args\n";
  ' "$1" "$units/$1.h" "$units/$1_copy.h" src/fresnel/registry.h
}
# register INCLUDE ENTRY...: the include after the registry's last model include, the entries at
# the end of the Registry list.
register() {
  local include="$1" e
  shift
  perl -0pi -e 's|(.*#include "fresnel/models/[^"]+"\n)|$1#include "'"$include"'"\n|s' \
    src/fresnel/registry.h
  for e in "$@"; do
    perl -0pi -e "s/(using Registry = ModelList<[^;]*?)>;/\$1, ${e}>;/s" src/fresnel/registry.h
    grep -qF "${e}>;" src/fresnel/registry.h ||
      { echo "check-model-unit: could not add the registry entry $e" >&2; exit 2; }
  done
}

# document NAME...: NAME in the README's list of models, which names exactly the registry's
# (tests/fresnel/test_registry.cpp).
document() {
  local n
  for n in "$@"; do
    perl -0pi -e 's/(- \*\*Models\*\* \(`--model`\): )/$1`'"$n"'`, /' README.md
    grep -qF "\`$n\`" README.md || { echo "check-model-unit: could not list $n in README.md" >&2; exit 2; }
  done
}

declare -A entry
for m in "${copied[@]}"; do
  entry[$m]=$(copy_unit "$m")
  register "fresnel/models/${m}_copy.h" "${entry[$m]}"
  document "${m}_copy"
  echo "check-model-unit: $units/$m.h → $units/${m}_copy.h (${entry[$m]}, \"${m}_copy\")"
done
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
shows_copies() {  # shows_copies FILE [SUFFIX]: every copy's name (followed by SUFFIX) is in FILE
  local m
  for m in "${copied[@]}"; do shows "$1" "${m}_copy${2:-}" || return 1; done
}

build() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -DCMAKE_C_COMPILER_LAUNCHER=ccache
  CCACHE_BASEDIR="$repo" nice -n 5 cmake --build build -j"$jobs" --target fresnel-lab fl_tests \
    fl_vulkan_tests
}
cli=build/src/fresnel-lab
out="$scratch/out"
mkdir -p "$out"
# With the sanitizer pass, the suite's browser.reproduce has just run the sanitized `reproduce` on
# this copy (with figures): its report is checked rather than made a second time.
reproduce() {
  local reports="$out/reports"
  if [ "$sanitize" = 1 ]; then
    reports=build/tests/browser/report
  else
    "$cli" -q reproduce --out "$reports" --no-figures || return 1
  fi
  shows_copies "$reports/models.csv" && shows_copies "$reports/speed.csv" ",derived,unmeasured" &&
    shows_copies "$reports/index.html"
}
speed() {
  "$cli" -q table speed > "$out/speed.md" && shows "$out/speed.md" "unmeasured" &&
    shows_copies "$out/speed.md"
}
plan() {
  "$cli" -q plan examples/scene_ibl.yaml > "$out/plan.md" &&
    shows "$out/plan.md" "Unmeasured cost" && shows_copies "$out/plan.md" &&
    "$cli" -q plan examples/scene_ibl.yaml --format json > "$out/plan.json" &&
    shows "$out/plan.json" "\"unmeasured\"" && shows_copies "$out/plan.json"
}
shader() {
  local m l
  for m in "${copied[@]}"; do
    for l in punctual ibl area; do
      "$cli" -q shader "${m}_copy" --lighting "$l" > "$out/shader-$m-$l.glsl" &&
        shows "$out/shader-$m-$l.glsl" "fresnel_${m}_copy" || return 1
    done
    "$cli" -q shader "${m}_copy" --lang hlsl --lighting area > "$out/shader-$m.hlsl" &&
      shows "$out/shader-$m.hlsl" "fresnel_${m}_copy" || return 1
  done
}
lut() {
  "$cli" -q lut dfg --out "$out/dfg.csv" --size 8 --samples 256 &&
    "$cli" -q lut ltc-moments --out "$out/ltc_moments.csv" --size 8 --samples 256 &&
    "$cli" -q table lut-accuracy gold > "$out/lut-accuracy.md" &&
    shows_copies "$out/lut-accuracy.md"
}
suite() { ctest --test-dir build -j"$jobs" --output-on-failure; }
if [ "$sanitize" = 1 ]; then
  # The commands below run the sanitized binary: leaks in system libraries as test-sanitize.sh
  # suppresses them.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
  export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$repo/scripts/lsan.supp:print_suppressions=0}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
fi

echo "clean copies (logs in $scratch/NAME.log):"
if [ "$sanitize" = 1 ]; then
  step asan-suite env CCACHE_BASEDIR="$repo" scripts/test-sanitize.sh build
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
expected=$((${#copied[@]} + 2))  # the new units, the registry and the README
[ "$touched" = "$expected" ] ||
  { echo "files touched: $touched, expected $expected"; failures=$((failures + 1)); }
clean_seconds=$(($(date +%s) - start))

# The faults, each a unit deriving from a copy with one member replaced (the templates of
# tests/fresnel/seeded_faults.h), in models/faults.h.
has() { grep -q "\.$2 = true" "$units/$1.h"; }
declare -A fault_model
for f in kernel glsl derive; do fault_model[$f]="$model"; done
fault_model[tables]=$(has "$model" table_terms && echo "$model" || echo basis)
fault_model[average]=$(has "$model" closed_form_average && echo "$model" || echo basis)
faults=(kernel glsl tables average derive)
{
  cat tests/fresnel/seeded_faults.h
  for m in "${copied[@]}"; do echo "#include \"fresnel/models/${m}_copy.h\""; done
  echo "namespace fl::fresnel::models {"
  for f in "${faults[@]}"; do
    m="${fault_model[$f]}"
    echo "struct Seeded_${f} : seeded::$(tr a-z A-Z <<< "${f:0:1}")${f:1}Fault<${entry[$m]#models::}> {"
    echo "  static constexpr const char* kName = \"${m}_copy_${f}\";"
    echo "  static constexpr const char* kLabel = \"Seeded fault ${f} in ${m}_copy\";"
    echo "};"
  done
  echo "}  // namespace fl::fresnel::models"
} > "$units/faults.h"
register fresnel/models/faults.h $(for f in "${faults[@]}"; do echo "models::Seeded_$f"; done)
document $(for f in "${faults[@]}"; do echo "${fault_model[$f]}_copy_$f"; done)

# The suite but its end-to-end runs of the CLI (browser, validators, README, install, basis
# regeneration), which check documents rather than name a model; its failures are what is looked at.
fault_suite() {
  ctest --test-dir build -j"$jobs" --output-on-failure --timeout 1200 \
    -E "^(browser|Validators|Readme|Install)\\.|^Basis\\.regenerates" || true
}
echo "faulty copies, registered together (logs in $scratch/NAME.log):"
if [ "$failures" = 0 ]; then
  if [ "$sanitize" = 1 ]; then
    step faults-build env CCACHE_BASEDIR="$repo" nice -n 5 cmake --build build -j"$jobs"
  else
    step faults-build build
  fi
fi
caught=0
if [ "$failures" = 0 ]; then
  step faults-suite fault_suite
  # Each failure message with its trace, attributed to the test it belongs to.
  awk '/Test +#[0-9]+: / { for (i = 1; i <= NF; ++i) if ($i ~ /^#[0-9]+:$/) test = $(i + 1) }
       /: Failure$/ { on = 1 }
       /^\[ +(OK|FAILED|RUN) / || /^[0-9]+\/[0-9]+ Test/ { on = 0 }
       on { print test "\t" $0 }' "$scratch/faults-suite.log" > "$scratch/failures.txt"
  for f in "${faults[@]}"; do
    name="${fault_model[$f]}_copy_$f"
    by=$(grep -P "\\b${name}\\b" "$scratch/failures.txt" | cut -f1 | sort -u | tr '\n' ' ' || true)
    if [ -n "$by" ]; then
      caught=$((caught + 1))
      printf '  %-24s caught by %s\n' "$name" "$by"
    else
      printf '  %-24s NOT CAUGHT\n' "$name"
    fi
  done
fi
[ "$caught" = "${#faults[@]}" ] || failures=$((failures + 1))
echo "check-model-unit: models copied: ${copied[*]}; faults seeded: ${#faults[@]}; faults caught:" \
  "$caught; clean copies ${clean_seconds} s, faults $(($(date +%s) - start - clean_seconds)) s"
echo "check-model-unit: $([ "$failures" = 0 ] && echo PASS || echo "FAIL ($failures)"), $(($(date +%s) - start)) s"
# Kept when a step failed (its logs) or when asked.
[ "$failures" != 0 ] || [ "${FL_CHECK_KEEP:-0}" = 1 ] || { cd /; rm -rf "$scratch"; }
[ "$failures" = 0 ]
