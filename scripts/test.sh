#!/usr/bin/env bash
# Builds hrspace and runs its whole test suite (unit and slow labels).
# Extra arguments go to ctest, e.g. scripts/test.sh -L unit
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
cd "$root"
exec ctest --preset default "$@"
