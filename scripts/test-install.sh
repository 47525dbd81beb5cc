#!/usr/bin/env bash
# Installs the build to a temporary prefix and runs the installed tool from another folder:
# --version, `presets gold` and `reproduce --out DIR` (with --db), the error without a database,
# and checks that the installed binary holds no path of the source tree.
#   scripts/test-install.sh [BUILD_DIR] [DATABASE]
# (defaults: build, ../shared/refractiveindex.info-database/database beside the repository)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$src/build}" && pwd)
db=${2:-$src/../shared/refractiveindex.info-database/database}
db=$(cd "$db" && pwd)
unset FRESNEL_LAB_DB FRESNEL_LAB_COSTS FRESNEL_LAB_GPU_COSTS FRESNEL_LAB_FONT OCIO

tmp=$(mktemp -d /tmp/fresnel-lab-install.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
tool=$prefix/bin/fresnel-lab
mkdir -p "$tmp/elsewhere"
cd "$tmp/elsewhere"

fail() { echo "test-install: $*" >&2; exit 1; }
step() {  # step NAME COMMAND...: runs it, fails on a non-zero exit status
  local name=$1; shift
  "$@" >"$tmp/$name.out" 2>"$tmp/$name.err" || { cat "$tmp/$name.err" >&2; fail "$name: exit status $?"; }
  echo "ok: $name"
}

step version "$tool" --version
grep -Eq '^fresnel-lab [0-9]+\.[0-9]+\.[0-9]+ \(commit [0-9a-f]+|unknown\)' "$tmp/version.out" ||
  fail "--version printed: $(cat "$tmp/version.out")"
cat "$tmp/version.out"
step presets "$tool" --db "$db" -q presets gold
grep -q '^Gold,metal,' "$tmp/presets.out" || fail "presets gold printed no gold row"
step reproduce "$tool" --db "$db" -q reproduce --out "$tmp/elsewhere/reports"
[ -s reports/index.html ] && [ -s reports/schlick.csv ] || fail "reproduce wrote no report"
echo "ok: reproduce wrote $(find reports -type f | wc -l) files"

# Without a database an installed tool names both ways to give one.
set +e
"$tool" presets gold >/dev/null 2>"$tmp/nodb.err"
rc=$?
set -e
[ "$rc" = 2 ] || fail "no database: exit status $rc, expected 2"
grep -q -- '--db' "$tmp/nodb.err" && grep -q 'FRESNEL_LAB_DB' "$tmp/nodb.err" ||
  fail "no database: $(cat "$tmp/nodb.err")"
echo "ok: no database: $(cat "$tmp/nodb.err")"

# The installed binary holds no path of the source tree (nor of the build tree inside it). A
# sanitized build (FRESNEL_LAB_SANITIZE) names its source files on purpose, in UBSan's reports and
# its debug line tables: the check is for the builds a user installs.
if grep -q "^FRESNEL_LAB_SANITIZE:BOOL=ON" "$build/CMakeCache.txt"; then
  echo "ok: source-path check skipped (a sanitized build names its sources in its reports)"
else
  if strings "$tool" | grep -F "$src"; then fail "the installed binary holds source-tree paths"; fi
  echo "ok: strings finds no $src in the installed binary"
fi
