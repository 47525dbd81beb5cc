#!/usr/bin/env bash
# Kills runs while they write and counts what they leave: sets that mix two runs' files, and
# staging left behind. Outputs are replaced as a whole or not at all (docs/commands.md, "Outputs").
#   scripts/kill-test.sh FRESNEL_LAB MODE TRIALS [DATABASE]
#   MODE lut:     `lut ltc --size 8` writes FILE_1.exr, FILE_2.exr, FILE_3.exr and FILE.csv; the folder
#                 holds the --samples 256 set and a --samples 512 run is killed.
#   MODE library: `library 'main/Au/nk/*'` replaces a folder; the folder holds the --class metal
#                 library and a --class all run is killed.
# Each trial kills with SIGKILL or SIGTERM (alternating), either as soon as the run's staging
# appears in the folder or after a random delay within the run's duration. It counts, right after
# the kill, sets that are neither wholly old nor wholly new ("mixed") and staging present
# ("staging"); then a later run writes another file into the folder, which recovers what the
# killed run left, and it counts mixed sets and leftovers again. Prints one summary line.
set -uo pipefail
cli=$1 mode=$2 trials=$3 db=${4:-}
[[ -n "$db" ]] && cli="$cli --db $db"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case $mode in
  lut)
    old=(lut ltc --size 8 --samples 256 --out) new=(lut ltc --size 8 --samples 512 --out)
    target=ltc.exr later=(lut energy --size 2 --samples 256 --out "$work/d/probe.csv") ;;
  library)
    old=(library 'main/Au/nk/*' --class metal --out)
    new=(library 'main/Au/nk/*' --class all --out)
    target=lib later=(lut energy --size 2 --samples 256 --out "$work/d/probe.csv") ;;
  *) echo "unknown mode $mode" >&2; exit 2 ;;
esac
# The state of the folder: a checksum of the output set (probe.csv aside), or "none".
state() {
  (cd "$work/d" && find . -path ./probe.csv -prune -o -type f -print 2>/dev/null |
    grep -v -e '/\.fresnel-lab-' -e '\.new\.[0-9]*/' -e '\.old\.[0-9]*/' -e '\.ready\.[0-9]*/' |
    LC_ALL=C sort | xargs -r sha256sum | sha256sum | cut -c1-16)
}
leftovers() {
  find "$work/d" -mindepth 1 -maxdepth 1 \( -name '.fresnel-lab-*' -o -name '*.tmp.[0-9]*' \
    -o -name '*.new.[0-9]*' -o -name '*.old.[0-9]*' -o -name '*.ready.[0-9]*' \) | wc -l
}
mkdir -p "$work/d"
$cli -q "${new[@]}" "$work/d/$target" || exit 1
new_state=$(state)
rm -rf "$work/d" && mkdir -p "$work/d"
t0=$(date +%s.%N)
$cli -q "${old[@]}" "$work/d/$target" || exit 1
duration=$(echo "$(date +%s.%N) - $t0" | bc)
old_state=$(state)
mixed_now=0 staged_now=0 mixed_after=0 left_after=0 old_kept=0 new_whole=0 none=0
for ((i = 0; i < trials; i++)); do
  sig=$((i % 2 ? 15 : 9))
  $cli -q "${new[@]}" "$work/d/$target" 2>/dev/null &
  pid=$!
  if ((i % 4 < 2)); then
    # As soon as the staging appears.
    until compgen -G "$work/d/.fresnel-lab-*" >/dev/null || compgen -G "$work/d/$target.*" >/dev/null ||
      ! kill -0 $pid 2>/dev/null; do :; done
  else
    sleep "$(echo "scale=3; $duration * $RANDOM / 32767" | bc)"
  fi
  kill -$sig $pid 2>/dev/null
  wait $pid 2>/dev/null
  s=$(state)
  [[ "$s" != "$old_state" && "$s" != "$new_state" ]] && ((mixed_now++))
  (($(leftovers) > 0)) && ((staged_now++))
  $cli -q "${later[@]}" >/dev/null 2>&1
  s=$(state)
  if [[ "$s" == "$old_state" ]]; then ((old_kept++));
  elif [[ "$s" == "$new_state" ]]; then ((new_whole++));
  else ((mixed_after++)); fi
  left_after=$((left_after + $(leftovers)))
  # Back to the old set for the next trial.
  if [[ "$s" != "$old_state" ]]; then
    rm -rf "$work/d" && mkdir -p "$work/d"
    $cli -q "${old[@]}" "$work/d/$target" || exit 1
  fi
done
echo "kill-test $mode: $trials trials; right after the kill: $mixed_now mixed sets, $staged_now" \
  "with staging present; after a later run: $mixed_after mixed sets, $left_after leftovers" \
  "($old_kept old sets kept whole, $new_whole new sets whole)"
((mixed_after == 0 && left_after == 0))
