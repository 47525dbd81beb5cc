#!/usr/bin/env bash
# Fresnel Lab setup for a fresh Debian 12 machine: installs every package the build, tests and
# benchmarks need (Debian packages, and the npm packages of the export validators pinned by
# tests/validators/package-lock.json), builds (Release, build/), and regenerates reports/ with
# `reproduce`.
#   scripts/setup.sh              install + build + reproduce
#   scripts/setup.sh --deps-only  install the packages (and the browser test's npm packages) only (what CI calls)
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  g++ cmake make pkg-config
  libceres-dev libeigen3-dev
  libopencolorio-dev
  libopenexr-dev libimath-dev
  libyaml-dev libcli11-dev libfmt-dev libtbb-dev nlohmann-json3-dev libhwy-dev
  googletest libgtest-dev libgmock-dev libbenchmark-dev libxml2-utils
  liblcms2-dev libcairo2-dev libpng-dev fonts-dejavu-core libgif-dev libwebp-dev
  clang libclang-rt-14-dev clang-format python3
  glslang-tools spirv-tools
  mesa-vulkan-drivers libvulkan-dev vulkan-tools
  chromium nodejs npm
)

missing=()
for p in "${PACKAGES[@]}"; do
  # A Node.js that already brings npm (e.g. from nodesource) serves as well as Debian's two packages.
  if [ "$p" = nodejs ] || [ "$p" = npm ]; then command -v node >/dev/null && command -v npm >/dev/null && continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# The npm packages each Node test needs, exactly as its package-lock.json pins them, installed again
# only when that lock file changes: tests/validators (MaterialX 1.39 as WebAssembly, the Khronos glTF
# validator) and tests/browser (puppeteer-core, which drives Debian's chromium).
for dir in tests/validators tests/browser; do
  if ! cmp -s "$dir/package-lock.json" "$dir/node_modules/.fresnel-lab-lock" 2>/dev/null; then
    echo "setup: npm ci in $dir" >&2
    (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
    cp "$dir/package-lock.json" "$dir/node_modules/.fresnel-lab-lock"
  fi
done
[ "${1:-}" = "--deps-only" ] && exit 0

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
./build/src/fresnel-lab reproduce --out reports
echo "setup: built build/src/fresnel-lab and regenerated reports/" >&2
