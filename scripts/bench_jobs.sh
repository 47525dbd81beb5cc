#!/usr/bin/env bash
# Times whole commands of two builds side by side, alternating runs in one session (the machine's
# noise hits both alike), and writes the section "Jobs against the previous main" at the end of
# reports/bench.md: per job the median wall time, CPU time (user + system) and peak memory of
# $JOB_RUNS runs (default 5) for each build, and the ratio. Commit the file.
#   scripts/bench_jobs.sh BASE_CLI NEW_CLI [JOBS]
#   BASE_CLI, NEW_CLI: fresnel-lab binaries (e.g. a git worktree of the previous main, built beside)
#   JOBS: comma-separated names from: reproduce, presets_all, lut_ltc, curve_fitted (default all)
set -euo pipefail
cd "$(dirname "$0")/.."
base=$1 new=$2 jobs=${3:-reproduce,presets_all,lut_ltc,curve_fitted}
runs=${JOB_RUNS:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
command_of() {  # the job's arguments
  case $1 in
    reproduce) echo "-q reproduce --no-figures --out $tmp/out" ;;
    presets_all) echo "-q presets ** --format csv" ;;
    lut_ltc) echo "-q lut ltc --size 64 --out $tmp/ltc.exr" ;;
    curve_fitted) echo "-q curve gold --model f82 --params fitted" ;;
  esac
}
describe() {
  case $1 in
    reproduce) echo '`reproduce --no-figures` (every table, every fit, the 28-material catalog)' ;;
    presets_all) echo "\`presets '**'\` (every loadable database page, every model fitted)" ;;
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
  echo "Written by \`scripts/bench_jobs.sh\`: each job run $runs times per build, the builds alternating run by run"
  echo "in one session; medians. Machine: $(nproc) hardware threads, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //');"
  echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo
  echo "| job | previous wall s | wall s | ratio | previous CPU s | CPU s | previous peak MB | peak MB |"
  echo "|---|---|---|---|---|---|---|---|"
} >"$tmp/section"
IFS=, read -ra names <<<"$jobs"
for job in "${names[@]}"; do
  : >"$tmp/base.$job"; : >"$tmp/new.$job"
  for ((i = 0; i < runs; ++i)); do
    run_once "$base" "$job" >>"$tmp/base.$job"
    run_once "$new" "$job" >>"$tmp/new.$job"
    echo "bench_jobs: $job run $((i + 1))/$runs" >&2
  done
  col() { awk -v c="$2" '{print $c}' "$tmp/$1.$job" | median; }
  bw=$(col base 1) nw=$(col new 1) bc=$(col base 2) nc=$(col new 2) bm=$(col base 3) nm=$(col new 3)
  awk -v d="$(describe "$job")" -v bw="$bw" -v nw="$nw" -v bc="$bc" -v nc="$nc" -v bm="$bm" -v nm="$nm" \
    'BEGIN {printf "| %s | %.2f | %.2f | %.1f× | %.2f | %.2f | %.0f | %.0f |\n", d, bw, nw, bw / nw, bc, nc, bm / 1024, nm / 1024}' \
    >>"$tmp/section"
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)." >>"$tmp/section"
report=reports/bench.md
if grep -qF "$section" "$report"; then
  sed "/^$section\$/,\$d" "$report" >"$tmp/report"
else
  cp "$report" "$tmp/report"; echo >>"$tmp/report"
fi
cat "$tmp/report" "$tmp/section" >"$report.tmp" && mv "$report.tmp" "$report"
echo "bench_jobs: wrote the jobs section of $report" >&2
