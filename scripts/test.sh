#!/usr/bin/env bash
# Builds hrspace and runs its whole test suite (unit and slow labels), then
# the unit suites again, but those labelled no_sanitize, under
# AddressSanitizer and UndefinedBehaviorSanitizer with assertions live
# (scripts/sanitize.sh, preset `sanitize`; docs/hardening.md).
# Extra arguments go to the first ctest only and skip the sanitizer run,
# e.g. scripts/test.sh -L unit
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
cd "$root"
if [ $# -gt 0 ]; then
  exec ctest --preset default "$@"
fi
ctest --preset default
echo "hrspace: the unit suites under AddressSanitizer and UBSan (preset sanitize)"
exec "$root/scripts/sanitize.sh"
