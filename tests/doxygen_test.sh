#!/usr/bin/env bash
# The API reference builds without a warning: runs doxygen with docs/Doxyfile
# from SOURCE_DIR into WORK_DIR and fails when its warning log is not empty
# (undocumented members are not warned about; broken commands, unknown
# parameters and unresolved references are).
# Usage: doxygen_test.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src="$1" work="$2"
command -v doxygen >/dev/null || { echo "FAIL: doxygen not installed (scripts/setup.sh installs it)"; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cd "$src"
{ cat docs/Doxyfile; echo "OUTPUT_DIRECTORY = $work"; echo "WARN_LOGFILE = $work/warnings.log"; } |
  doxygen - >"$work/doxygen.log" 2>&1 || { cat "$work/doxygen.log"; exit 1; }
[ -f "$work/html/index.html" ] || { echo "FAIL: no html/index.html"; cat "$work/doxygen.log"; exit 1; }
if [ -s "$work/warnings.log" ]; then
  echo "FAIL: doxygen warned ($(wc -l <"$work/warnings.log") lines):"
  cat "$work/warnings.log"
  exit 1
fi
echo "doxygen test passed: $(ls "$work/html" | wc -l) files, no warning"
