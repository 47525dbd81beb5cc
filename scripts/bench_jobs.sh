#!/usr/bin/env bash
# Times whole commands of two builds side by side, alternating runs in one session (the machine's
# noise hits both alike), and writes the section "Jobs against the previous main" at the end of
# reports/bench.md: per job the median wall time, CPU time (user + system) and peak memory of
# $JOB_RUNS runs (default 5) for each build, and the ratio; the whole-database jobs (presets_all,
# library_all) run $SLOW_RUNS times (default $JOB_RUNS: a previous build may take minutes each).
# Commit the file.
#   scripts/bench_jobs.sh BASE_CLI NEW_CLI [JOBS]
#   BASE_CLI, NEW_CLI: fresnel-lab binaries (e.g. a git worktree of the previous main, built beside)
#   JOBS: comma-separated names from: reproduce, presets_all, library_all, lut_ltc, curve_fitted,
#   de2000 (default all). de2000 runs each build's bench_speed (found beside the CLI, in
#   ../bench/) for its CIEDE2000 group: ns per pair of each build's fastest ΔE2000 and Little CMS's.
set -euo pipefail
cd "$(dirname "$0")/.."
base=$1 new=$2 jobs=${3:-reproduce,presets_all,library_all,lut_ltc,curve_fitted,de2000}
runs=${JOB_RUNS:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
command_of() {  # the job's arguments
  case $1 in
    reproduce) echo "-q reproduce --no-figures --out $tmp/out" ;;
    presets_all) echo "-q presets ** --format csv" ;;
    library_all) echo "-q --min-coverage 0 library ** --class all --no-gallery --out $tmp/library" ;;
    lut_ltc) echo "-q lut ltc --size 64 --out $tmp/ltc.exr" ;;
    curve_fitted) echo "-q curve gold --model f82 --params fitted" ;;
  esac
}
describe() {
  case $1 in
    reproduce) echo '`reproduce --no-figures` (every table, every fit, the 28-material catalog)' ;;
    presets_all) echo "\`presets '**'\` (every loadable database page; the models presets prints)" ;;
    library_all) echo "\`library '**' --class all\`, coverage 0 (every loadable page, every model fitted)" ;;
    lut_ltc) echo '`lut ltc --size 64` (the Ceres LTC fit)' ;;
    curve_fitted) echo '`curve gold --model f82 --params fitted`' ;;
  esac
}
median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }
run_once() {  # CLI JOB -> "wall cpu peak_kb"
  local args
  read -ra args <<<"$(command_of "$2")"
  set -f
  /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$1" "${args[@]}" >/dev/null 2>"$tmp/err" ||
    { echo "bench_jobs: $2 failed with $1: $(tail -1 "$tmp/err")" >&2; exit 1; }
  set +f
  awk '{printf "%s %.2f %s\n", $1, $2 + $3, $4}' "$tmp/time"
}
section="## Jobs against the previous main"
{
  echo "$section"
  echo
  echo "Written by \`scripts/bench_jobs.sh\`: each job run the stated number of times per build, the builds alternating run by run"
  echo "in one session; medians. Machine: $(nproc) hardware threads, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //');"
  echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo
  echo "| job | previous wall s | wall s | ratio | previous CPU s | CPU s | previous peak MB | peak MB |"
  echo "|---|---|---|---|---|---|---|---|"
} >"$tmp/section"
# ns per pair of a bench_speed run's ΔE2000 rows: fastest of ours, and Little CMS.
de2000_once() {
  local bench
  bench="$(dirname "$1")/../bench/bench_speed"
  "$bench" --benchmark_filter=de2000 --benchmark_out="$tmp/de.csv" --benchmark_out_format=csv >/dev/null 2>&1 ||
    { echo "bench_jobs: $bench failed" >&2; exit 1; }
  awk -F, '/^"de2000\/ours/ {v = $4 / $NF; if (best == "" || v < best) best = v}
           /^"de2000\/lcms"/ {l = $4 / $NF} END {printf "%.2f %.2f\n", best, l}' "$tmp/de.csv"
}
de2000_row() {
  : >"$tmp/base.de"; : >"$tmp/new.de"
  for ((i = 0; i < runs; ++i)); do
    de2000_once "$base" >>"$tmp/base.de"; de2000_once "$new" >>"$tmp/new.de"
    echo "bench_jobs: de2000 run $((i + 1))/$runs" >&2
  done
  local bo bl no nl
  bo=$(awk '{print $1}' "$tmp/base.de" | median) bl=$(awk '{print $2}' "$tmp/base.de" | median)
  no=$(awk '{print $1}' "$tmp/new.de" | median) nl=$(awk '{print $2}' "$tmp/new.de" | median)
  awk -v bo="$bo" -v bl="$bl" -v no="$no" -v nl="$nl" 'BEGIN {
    printf "\nCIEDE2000, ns per colour pair (bench_speed, 1024 pairs across CIELAB, median CPU time of %d runs per build):\n\n", '"$runs"'
    print "| build | fastest of ours | Little CMS | Little CMS time / ours |"
    print "|---|---|---|---|"
    printf "| previous main | %.1f | %.1f | %.2f× |\n", bo, bl, bl / bo
    printf "| this build | %.1f | %.1f | %.2f× |\n", no, nl, nl / no
    printf "\nOurs against the previous main: %.1f×.\n", bo / no }' >>"$tmp/section.de"
}
: >"$tmp/section.de"
IFS=, read -ra names <<<"$jobs"
for job in "${names[@]}"; do
  if [ "$job" = de2000 ]; then de2000_row; continue; fi
  : >"$tmp/base.$job"; : >"$tmp/new.$job"
  n=$runs
  case $job in presets_all | library_all) n=${SLOW_RUNS:-$runs} ;; esac
  for ((i = 0; i < n; ++i)); do
    run_once "$base" "$job" >>"$tmp/base.$job"
    run_once "$new" "$job" >>"$tmp/new.$job"
    echo "bench_jobs: $job run $((i + 1))/$n" >&2
  done
  col() { awk -v c="$2" '{print $c}' "$tmp/$1.$job" | median; }
  bw=$(col base 1) nw=$(col new 1) bc=$(col base 2) nc=$(col new 2) bm=$(col base 3) nm=$(col new 3)
  awk -v n="$n" -v d="$(describe "$job")" -v bw="$bw" -v nw="$nw" -v bc="$bc" -v nc="$nc" -v bm="$bm" -v nm="$nm" \
    'BEGIN {printf "| %s | %.2f | %.2f | %.1f× | %.2f | %.2f | %.0f | %.0f |\n", d " (" n (n == 1 ? " run)" : " runs)"), bw, nw, bw / nw, bc, nc, bm / 1024, nm / 1024}' \
    >>"$tmp/section"
done
cat "$tmp/section.de" >>"$tmp/section"
echo >>"$tmp/section"
echo "Load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)." >>"$tmp/section"
report=reports/bench.md
if grep -qF "$section" "$report"; then
  sed "/^$section\$/,\$d" "$report" >"$tmp/report"
else
  cp "$report" "$tmp/report"; echo >>"$tmp/report"
fi
cat "$tmp/report" "$tmp/section" >"$report.tmp" && mv "$report.tmp" "$report"
echo "bench_jobs: wrote the jobs section of $report" >&2
