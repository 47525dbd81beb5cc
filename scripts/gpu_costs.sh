#!/usr/bin/env bash
# GPU cost of every model's shader function, deterministic: for each model and lighting,
# `fresnel-lab shader MODEL --lighting L --harness` (the function inside a compute shader whose
# inputs come from a uniform block) is compiled by glslangValidator, validated by spirv-val,
# optimized by `spirv-opt -O` (which inlines the function into the entry point) and disassembled;
# the entry point's instructions are counted, without the harness's interface (labels, access
# chains, loads, stores, return). Arithmetic: float and integer operations and vector products;
# extended: GLSL.std.450 instructions (pow, sqrt, exp, clamp, mix, fma, ...); texture: image samples.
#   scripts/gpu_costs.sh [BUILD_DIR]          writes bench/gpu_costs.csv
#   scripts/gpu_costs.sh --check [BUILD_DIR]  counts again and compares with bench/gpu_costs.csv
#   scripts/gpu_costs.sh --count FILE.comp    counts one GLSL compute shader's entry point the same
#                                              way (instructions,arithmetic,extended,texture)
set -euo pipefail
cd "$(dirname "$0")/.."
check=0 count_file=""
if [ "${1:-}" = "--check" ]; then check=1; shift; fi
if [ "${1:-}" = "--count" ]; then count_file="$2"; shift 2; fi
build="${1:-build}"
tool="$build/src/fresnel-lab"
for t in glslangValidator spirv-val spirv-opt spirv-dis; do
  command -v "$t" >/dev/null || { echo "gpu_costs: $t not found (Debian glslang-tools, spirv-tools; scripts/setup.sh)" >&2; exit 2; }
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

count() {  # disassembly -> instructions,arithmetic,extended,texture of %main
  awk '
    /%main = OpFunction / { inside = 1; next }
    inside && /OpFunctionEnd/ { inside = 0 }
    inside {
      op = ($2 == "=") ? $3 : $1
      if (op ~ /^Op(Label|AccessChain|Load|Store|Return|Variable)$/) next
      total++
      if (op == "OpExtInst") ext++
      else if (op ~ /^OpImage/) tex++
      else if (op ~ /^Op[FISU](Add|Sub|Mul|Div|Rem|Mod|Negate)$/ || op ~ /^Op(VectorTimesScalar|MatrixTimesScalar|VectorTimesMatrix|MatrixTimesVector|MatrixTimesMatrix|Dot|OuterProduct)$/) arith++
    }
    END { printf "%d,%d,%d,%d\n", total, arith, ext, tex }'
}

# FILE.comp -> its disassembly after spirv-opt -O, both SPIR-V modules validated.
optimized() {
  glslangValidator -V "$1" -o "$work/a.spv" > "$work/log" || { cat "$work/log" >&2; exit 1; }
  spirv-val "$work/a.spv"
  spirv-opt -O "$work/a.spv" -o "$work/o.spv"
  spirv-val "$work/o.spv"
  spirv-dis "$work/o.spv"
}

if [ -n "$count_file" ]; then
  optimized "$count_file" | count
  exit 0
fi
[ -x "$tool" ] || { echo "gpu_costs: $tool not built" >&2; exit 2; }
models=$(grep -v '^#' bench/model_costs.csv | tail -n +2 | cut -d, -f1)

out="$work/gpu_costs.csv"
{
  echo "# GPU cost of each model's shader function, written by scripts/gpu_costs.sh; read by \`table speed\` and \`plan\`."
  echo "# SPIR-V instructions of the entry point of \`fresnel-lab shader MODEL --lighting L --harness\` after spirv-opt -O"
  echo "# (the function inlined; the harness's labels, access chains, loads, stores and return not counted)."
  echo "# tools: $(glslangValidator --version | head -1 | sed 's/^Glslang Version: /glslang /'), $(spirv-opt --version 2>&1 | head -1 | cut -d' ' -f1-2)"
  echo "model,lighting,instructions,arithmetic,extended,texture"
  for m in $models; do
    for l in punctual ibl area; do
      src="$work/$m-$l.comp"
      "$tool" -q shader "$m" --lighting "$l" --harness > "$src"
      echo "$m,$l,$(optimized "$src" | count)"
    done
  done
} > "$out"

if [ "$check" = 1 ]; then
  if diff <(grep -v '^#' bench/gpu_costs.csv) <(grep -v '^#' "$out"); then
    echo "gpu_costs: bench/gpu_costs.csv matches the tools ($(grep '^# tools:' "$out" | cut -d' ' -f3-))"
  else
    echo "gpu_costs: bench/gpu_costs.csv differs from what the tools count now (above); regenerate with scripts/gpu_costs.sh" >&2
    exit 1
  fi
else
  cp "$out" bench/gpu_costs.csv
  echo "gpu_costs: wrote bench/gpu_costs.csv" >&2
fi
