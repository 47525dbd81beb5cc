#!/usr/bin/env bash
# Writes reports/lookdev/: gold, chromium and glass BK7 under the studio and sunset environments of
# ../shared/testdata/hdri/, the truth against Schlick, F82 and Gulbrandsen (derived parameters):
# per material and environment a contact sheet (NAME-ENV.sheet.png) and an animated flip
# (NAME-ENV.flip.webp: lossless, 512 px; per model the truth, the model and its difference frame),
# and README.md with every heat map's mean and max ΔE2000 and its mean by view angle. 512 px,
# roughness 0.25, 512 samples per strategy (where the heat maps of metals under a sky stop changing,
# to 0.05 ΔE2000). Not part of `reproduce`: it renders for 1.5 to 2.5 minutes on two cores.
#   scripts/lookdev.sh [BUILD_DIR]        default build dir: build
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
HDRI="${FRESNEL_LAB_HDRI:-../shared/testdata/hdri}"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target fresnel-lab
tmp="$(mktemp -d reports/.lookdev.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
{
  echo "# Look-dev renders: the truth against Schlick, F82 and Gulbrandsen"
  echo
  echo "Written by \`scripts/lookdev.sh\`: \`fresnel-lab render MATERIAL --env ENV.exr --compare schlick,f82,gulbrandsen"
  echo "--size 512 --samples 512\` (roughness 0.25, derived parameters, ACEScg, D60). Each contact sheet has one row"
  echo "per model: truth, model, ΔE2000 heat map. Each flip (lossless animated WebP, 512 px, 0.9 s a frame, looping)"
  echo "shows per model the truth, the model, and a difference frame: the ΔE2000 heat map on the sheet's scale and"
  echo "mid grey + 32 × (model − truth) in display codes, side by side. Mean by view angle: between the normal and"
  echo "the view, from the sphere's centre (0°) to its rim (90°)."
  echo
  echo "| material | environment | model | mean | max | 0–30° | 30–60° | 60–80° | 80–90° | sheet | flip |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
} > "$tmp/README.md"
mkdir "$tmp/out"
for env in studio sunset; do
  for material in gold chromium "glass BK7"; do
    key="$(echo "$material" | tr 'A-Z ' 'a-z_')-$env"
    "$BUILD/src/fresnel-lab" render "$material" --env "$HDRI/$env.exr" --compare schlick,f82,gulbrandsen \
      --size 512 --samples 512 --out "$tmp/$key.exr" 2> "$tmp/$key.log"
    awk -v m="$material" -v e="$env" -v k="$key" '/ΔE2000 truth vs/ {
        model=$5; sub(":", "", model); mean=$7; sub(",", "", mean); max=$9;
        n=split($0, a, /(0–30°|30–60°|60–80°|80–90°) /); b="";
        for (i = 2; i <= n; ++i) { v=a[i]; sub(/,.*/, "", v); b=b " | " v }
        printf "| %s | %s | %s | %s | %s%s | [sheet](%s.sheet.png) | [flip](%s.flip.webp) |\n", m, e, model, mean, max, b, k, k
      }' "$tmp/$key.log" >> "$tmp/README.md"
    mv "$tmp/$key.sheet.png" "$tmp/$key.flip.webp" "$tmp/out/"
    rm "$tmp/$key.log" "$tmp/$key".*png "$tmp/$key.exr"
  done
done
mv "$tmp/README.md" "$tmp/out/"
rm -rf reports/lookdev
mv "$tmp/out" reports/lookdev
echo "lookdev: wrote reports/lookdev" >&2
