#!/usr/bin/env bash
# Writes Fresnel Lab's export documents and checks them with the renderers' own tools (node scripts
# beside this file; packages pinned in package.json, installed by scripts/setup.sh).
#   check_exports.sh KIND CLI DB MATERIALS OUT_DIR
#   KIND: generalized_schlick | open_pbr_surface | standard_surface (MaterialX documents in every
#   built-in space and two spaces of tests/good_input/ocio/studio.ocio, one of which MaterialX
#   does not know) or gltf (glTF materials in linear Rec.709, built-in and through the config, and
#   converted from ACEScg). Each also checks the document `library` writes in that format.
set -euo pipefail
kind=$1 cli=$2 db=$3 materials=$4 out=$5
here=$(cd "$(dirname "$0")" && pwd)
config="$here/../good_input/ocio/studio.ocio"
command -v node >/dev/null || { echo "check_exports: node not found (scripts/setup.sh installs nodejs and npm)"; exit 1; }
[ -d "$here/node_modules" ] || { echo "check_exports: $here/node_modules missing (scripts/setup.sh runs npm ci there)"; exit 1; }
rm -rf "$out"
mkdir -p "$out"
fl() { "$cli" -q --db "$db" --materials "$materials" "$@"; }
# The library's documents: two gold pages, every preset format (documents/preset_formats.h).
fl library 'main/Au/nk/J*' --no-gallery --out "$out/library"
if [ "$kind" = gltf ]; then
  fl --space lin_rec709 presets --format gltf >"$out/presets.gltf"
  fl --ocio-config "$config" --space "Linear Rec.709 (sRGB)" presets --format gltf >"$out/presets_ocio.gltf"
  fl presets --format gltf >"$out/presets_acescg.gltf"
  cp "$out/library/library.gltf" "$out/library.gltf"
  exec node "$here/gltf.mjs" "$out"/*.gltf
fi
case "$kind" in
  generalized_schlick) cp "$out/library/library.mtlx" "$out/$kind-library.mtlx" ;;
  open_pbr_surface) cp "$out/library/library_openpbr.mtlx" "$out/$kind-library.mtlx" ;;
  *) cp "$out/library/library_$kind.mtlx" "$out/$kind-library.mtlx" ;;
esac
for space in acescg lin_rec709 aces2065-1 lin_rec2020 lin_p3d65; do
  fl --space "$space" presets --format mtlx --shader "$kind" >"$out/$kind-$space.mtlx"
done
fl --ocio-config "$config" --space ACEScg presets --format mtlx --shader "$kind" >"$out/$kind-ocio_acescg.mtlx"
fl --ocio-config "$config" --space "Linear Adobe RGB (1998)" presets --format mtlx --shader "$kind" \
  >"$out/$kind-ocio_adobe_rgb.mtlx"
exec node "$here/materialx.mjs" "$out"/*.mtlx
