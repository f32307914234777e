#!/usr/bin/env bash
# The C++ example of docs/cpp.md (examples/cpp/) builds and runs against an
# installed hrspace, as tests/consumer_test.sh does for tests/consumer/:
#   1. cmake --install BUILD --prefix WORK/prefix;
#   2. configures examples/cpp/ against that prefix only (find_package(hrspace
#      CONFIG), headers included as <hrspace/...>), builds it with ccache into
#      WORK/build;
#   3. runs it on scenes/bedroom.json (two poses, one leg, a 20-iteration
#      design) and checks what it prints.
# Usage: cpp_example_test.sh SOURCE_DIR BUILD_DIR WORK_DIR [CMAKE_ARG...]
# (the CMAKE_ARGs, such as the build's compiler and flags, go to the example's configure)
set -euo pipefail
src="$1" build="$2" work="$3"
shift 3
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
[ -e "$prefix/include/hrspace/geometry/scene.h" ] || { echo "FAIL: headers not installed"; exit 1; }

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
# Builds on this machine are serialized (scripts/build.sh): wait for the lock.
exec 9>"/tmp/hrspace-build.lock"
flock -w 1800 9
cmake -S "$src/examples/cpp" -B "$work/build" "${generator[@]}" "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" "$@" >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
flock -u 9

"$work/build/design_example" "$src/scenes/bedroom.json" | tee "$work/output.txt"
grep -qx 'free: 1 0' "$work/output.txt" || { echo "FAIL: expected 'free: 1 0'"; exit 1; }
grep -Eqx 'leg: found 1, [0-9.]+ m, [LSR+-]+' "$work/output.txt" || { echo "FAIL: no leg found"; exit 1; }
grep -Eqx 'tours found [0-9]+/10, preferences met [0-9]+/[0-9]+' "$work/output.txt" ||
  { echo "FAIL: no design line"; exit 1; }
echo "cpp example test passed"
