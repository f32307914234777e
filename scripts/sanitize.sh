#!/usr/bin/env bash
# Builds the `sanitize` preset (Debug, assertions live, AddressSanitizer and
# UndefinedBehaviorSanitizer, into build-sanitize/) and runs the unit suites
# under it, but those labelled no_sanitize (docs/hardening.md). Extra
# arguments go to ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HRSPACE_PRESET=sanitize "$root/scripts/build.sh"
cd "$root"
exec ctest --preset sanitize "$@"
