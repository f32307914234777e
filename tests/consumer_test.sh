#!/usr/bin/env bash
# The installed package works for a downstream project:
#   1. cmake --install BUILD --prefix WORK/prefix   (libraries, headers, command,
#      Python module, CMake package)
#   2. configures tests/consumer/ against that prefix only (find_package(hrspace
#      CONFIG)), builds it with ccache into WORK/build, runs it (one leg);
#   3. runs the installed command and imports the installed Python module.
# Usage: consumer_test.sh SOURCE_DIR BUILD_DIR WORK_DIR [PYTHON|none] [CMAKE_ARG...]
# (none: hrspace was built without its Python module; the CMAKE_ARGs, such as
# the build's compiler and sanitizer flags, go to the consumer's configure)
set -euo pipefail
src="$1" build="$2" work="$3" python="${4:-/usr/bin/python3}"
shift $(($# < 4 ? $# : 4))
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in bin/hrspace include/hrspace/planning/rrt.h lib/cmake/hrspace/hrspaceConfig.cmake \
         lib/cmake/hrspace/hrspaceTargets.cmake; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
# Builds on this machine are serialized (scripts/build.sh): wait for the lock.
exec 9>"/tmp/hrspace-build.lock"
flock -w 1800 9
cmake -S "$src/tests/consumer" -B "$work/build" "${generator[@]}" "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" "$@" >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
flock -u 9

"$work/build/plan_one_leg" "$src/scenes/bedroom.json" 0.9 1.2 0 4.03 2.39 -1.79
"$prefix/bin/hrspace" validate "$src/scenes/bedroom.json" >/dev/null
if [ "$python" = none ]; then echo "consumer test passed (no Python module)"; exit 0; fi
pydir=$(find "$prefix/lib" -path '*-packages/hrspace' -type d | head -1)
[ -n "$pydir" ] || { echo "FAIL: Python package not installed"; exit 1; }
PYTHONPATH="$(dirname "$pydir")" PYTHONDONTWRITEBYTECODE=1 "$python" -c "
import hrspace, sys
s = hrspace.Scene(sys.argv[1])
assert hrspace.CSpace(s).is_free([0.9, 1.2, 0.0])
print('installed Python module:', hrspace.__file__)
" "$src/scenes/bedroom.json"
echo "consumer test passed"
