#!/usr/bin/env bash
# Installs missing packages, configures (first time) and builds hrspace.
# Quiet when nothing changes; prints the build log when the build fails.
# Usage: scripts/build.sh [cmake --build target ...]
# HRSPACE_PRESET selects the CMake preset (default: default, into build/).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
cd "$root"
# ccache keys on paths relative to the checkout, and not on the build
# directory (debug builds), so clones and worktrees share hits.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
preset="${HRSPACE_PRESET:-default}"
dir="build"
[ "$preset" = default ] || dir="build-$preset"
log="$root/$dir/build.log"
mkdir -p "$root/$dir"
# Builds are serialized: this machine has two cores and several users of them.
exec 9>"/tmp/hrspace-build.lock"
flock 9
if [ ! -f "$dir/build.ninja" ]; then
  if ! cmake --preset "$preset" >"$log" 2>&1; then cat "$log" >&2; exit 1; fi
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
if ! cmake --build --preset "$preset" "${targets[@]}" >"$log" 2>&1; then
  grep -v '^\[' "$log" | head -200 >&2
  echo "hrspace: build failed; full log in $log" >&2
  exit 1
fi
