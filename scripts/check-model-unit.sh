#!/usr/bin/env bash
# Acceptance check of the closed model unit, in one build of a scratch copy of the tree.
#
# Copies: renamed copies of a rotating model file and of the hardest one (models/basis.h, a template
# over its number of terms) plus their entries in the registry build, and `reproduce`, `table
# speed`, `plan`, `shader`, `lut` and the whole test suite show the new models (their CPU and GPU
# costs unmeasured) and never fail on them. `git status` in the copy lists the files the new models
# touched: the new units, src/fresnel/registry.h and README.md's list of models, nothing else.
#
# Faults: five faulty units, each a copy with one thing wrong, registered in the same build; the
# test suite must fail naming each of them:
#   kernel    the kernel 3 % low at every angle, in C++ and GLSL alike
#   glsl      the GLSL kernel 3 % low, the C++ kernel right
#   tables    the first table term's GLSL weight 3 % low (the generated IBL and area code)
#   average   the closed-form hemispherical average 0.01 high
#   derive    derive() 10 % low on each channel's first parameter (F0 for most models)
# each seeded into the rotating model's copy, or into the basis copy where the rotating model has
# no table terms or no closed-form average. A fault is caught when a failing test's failure
# message (or its trace) names the faulty model. The one suite run passes the check when every
# failing test names a fault, no failure names a clean copy and no sanitizer reported.
#
# Works under /tmp on the tracked files' working-tree content, never in the repository: the copy
# is a git repository of its own. Builds fresnel-lab, fl_tests and fl_vulkan_tests (Release,
# ccache) and runs CTest.
#   scripts/check-model-unit.sh [MODEL]   MODEL: the model file to copy beside basis (default:
#                                         chosen by the commit, rotating over models/*.h but basis)
# Environment: FL_CHECK_DIR (scratch folder, default /tmp/fresnel-lab-check-model-unit; a fixed
# path, so that ccache hits on the next run; kept when a step fails), FL_CHECK_KEEP=1 keeps it
# always, FL_CHECK_JOBS (default 2), FL_CHECK_SANITIZE=1 builds the copy with ASan + UBSan and runs
# its whole suite through the copy's scripts/test-sanitize.sh (every target), then the commands
# with the sanitized binary: CI's sanitizer pass and this check in one build. Exit status: 0 when
# every step passes and every fault is caught, 1 otherwise.
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

failures=0 failed=()
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

expected=$((${#copied[@]} + 2))  # the new units, the registry and the README
[ "$touched" = "$expected" ] ||
  { echo "files touched: $touched, expected $expected"; failures=$((failures + 1)); }

# The faults, each a unit deriving from a copy with one member replaced (the templates of
# tests/fresnel/seeded_faults.h), in models/faults.h, registered in the same build as the copies.
has() { grep -q "\.$2 = true" "$units/$1.h"; }
declare -A fault_model
for f in kernel glsl derive; do fault_model[$f]="$model"; done
fault_model[tables]=$(has "$model" table_terms && echo "$model" || echo basis)
fault_model[average]=$(has "$model" closed_form_average && echo "$model" || echo basis)
faults=(kernel glsl tables average derive)
fault_names=()
for f in "${faults[@]}"; do fault_names+=("${fault_model[$f]}_copy_$f"); done
{
  cat tests/fresnel/seeded_faults.h
  for m in "${copied[@]}"; do echo "#include \"fresnel/models/${m}_copy.h\""; done
  echo "namespace fl::fresnel::models {"
  for f in "${faults[@]}"; do
    m="${fault_model[$f]}"
    echo "struct Seeded_${f} : seeded::$(tr a-z A-Z <<< "${f:0:1}")${f:1}Fault<${entry[$m]#models::}> {"
    echo "  static constexpr const char* kName = \"${m}_copy_${f}\";"
    echo "  static constexpr const char* kLabel = \"Seeded ${f} fault, a copy of ${m}\";"
    echo "};"
  done
  echo "}  // namespace fl::fresnel::models"
} > "$units/faults.h"
register fresnel/models/faults.h $(for f in "${faults[@]}"; do echo "models::Seeded_$f"; done)
document "${fault_names[@]}"

build() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -DCMAKE_C_COMPILER_LAUNCHER=ccache
  CCACHE_BASEDIR="$repo" nice -n 5 cmake --build build -j"$jobs" --target fresnel-lab fl_tests \
    fl_vulkan_tests
}
# The whole suite, once (through the copy's scripts/test-sanitize.sh, which builds first, with the
# sanitizer pass): it passes when CTest ran to its summary; its failures are judged below.
suite() {
  if [ "$sanitize" = 1 ]; then
    env CCACHE_BASEDIR="$repo" scripts/test-sanitize.sh build || true
  else
    ctest --test-dir build -j"$jobs" --output-on-failure --timeout 1200 || true
  fi
  grep -qE "tests passed|tests failed" "$scratch/suite.log"
}
cli=build/src/fresnel-lab
out="$scratch/out"
mkdir -p "$out"
# The suite's browser.reproduce has just run `reproduce` (with figures) on this copy: its report is
# checked rather than made a second time.
reproduce() {
  local reports=build/tests/browser/report
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
if [ "$sanitize" = 1 ]; then
  # The commands below run the sanitized binary: leaks in system libraries as test-sanitize.sh
  # suppresses them.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
  export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$repo/scripts/lsan.supp:print_suppressions=0}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
fi

echo "copies and faults in one build (logs in $scratch/NAME.log):"
[ "$sanitize" = 1 ] || step build build
[ "$failures" != 0 ] || step suite suite
grep -E "tests passed|tests failed" "$scratch/suite.log" 2>/dev/null | sed 's/^/  ctest: /' || true
if [ "$failures" = 0 ]; then
  step reproduce reproduce
  step table-speed speed
  step plan plan
  step shader shader
  step lut lut
fi

# Each failure message with its trace, attributed to the test it belongs to; the tests CTest lists
# as failed.
caught=0
if [ -f "$scratch/suite.log" ]; then
  awk '/Test +#[0-9]+: / { for (i = 1; i <= NF; ++i) if ($i ~ /^#[0-9]+:$/) test = $(i + 1) }
       /: Failure$/ { on = 1 }
       /^\[ +(OK|FAILED|RUN) / || /^[0-9]+\/[0-9]+ Test/ { on = 0 }
       on { print test "\t" $0 }' "$scratch/suite.log" > "$scratch/failures.txt"
  mapfile -t failed < <(sed -n '/The following tests FAILED:/,$p' "$scratch/suite.log" |
    sed -nE 's/^[[:space:]]*[0-9]+ - ([^ ]+) .*/\1/p')
  any_fault=$(IFS='|'; echo "${fault_names[*]}")
  for f in "${fault_names[@]}"; do
    by=$(grep -P "\\b${f}\\b" "$scratch/failures.txt" | cut -f1 | sort -u | tr '\n' ' ' || true)
    if [ -n "$by" ]; then
      caught=$((caught + 1))
      printf '  %-24s caught by %s\n' "$f" "$by"
    else
      printf '  %-24s NOT CAUGHT\n' "$f"
    fi
  done
  # Every failing test names a fault; no failure names a clean copy; no sanitizer report.
  for t in "${failed[@]}"; do
    grep -qP "^\\Q${t}\\E\t.*\\b(${any_fault})\\b" "$scratch/failures.txt" ||
      { echo "  $t failed naming no fault"; failures=$((failures + 1)); }
  done
  for m in "${copied[@]}"; do
    ! grep -qP "\\b${m}_copy\\b" "$scratch/failures.txt" ||
      { echo "  a failure names the clean copy ${m}_copy"; failures=$((failures + 1)); }
  done
  ! grep -qE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$scratch/suite.log" ||
    { echo "  a sanitizer report in $scratch/suite.log"; failures=$((failures + 1)); }
fi
[ "$caught" = "${#faults[@]}" ] || failures=$((failures + 1))
echo "check-model-unit: models copied: ${copied[*]}; faults seeded: ${#faults[@]}; faults caught:" \
  "$caught; failing tests: ${#failed[@]}"
echo "check-model-unit: $([ "$failures" = 0 ] && echo PASS || echo "FAIL ($failures)"), $(($(date +%s) - start)) s"
# Kept when a step failed (its logs) or when asked.
[ "$failures" != 0 ] || [ "${FL_CHECK_KEEP:-0}" = 1 ] || { cd /; rm -rf "$scratch"; }
[ "$failures" = 0 ]
