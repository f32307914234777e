#!/usr/bin/env bash
# `hrspace --version`, the Python module's __version__ and report.json agree.
# Usage: version_test.sh HRSPACE SOURCE_DIR PROJECT_VERSION PYTHON PYTHONPATH
# (PYTHON "none" when the module is not built).
set -u
bin="$1"; src="$2"; want="$3"; python="$4"; pypath="$5"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL $*"; fails=$((fails+1)); }

line=$("$bin" --version 2>"$tmp/err"); status=$?
[ "$status" = 0 ] || fail "--version exits $status"
[ -s "$tmp/err" ] && fail "--version writes to stderr: $(cat "$tmp/err")"
re='^hrspace ([0-9]+\.[0-9]+\.[0-9]+) \(commit ([0-9a-f]{7}|unknown)\)$'
if [[ "$line" =~ $re ]]; then
  version="${BASH_REMATCH[1]}"; commit="${BASH_REMATCH[2]}"
  echo "ok   --version: $line"
else
  fail "--version prints '$line', expected 'hrspace X.Y.Z (commit abcdef1)'"; version=""; commit=""
fi
[ "$version" = "$want" ] || fail "--version says '$version', CMakeLists.txt '$want'"
"$bin" --version extra >/dev/null 2>&1; [ $? = 2 ] || fail "--version with an argument should exit 2"

if [ "$python" != none ]; then
  py=$(PYTHONPATH="$pypath" "$python" -c 'import hrspace; print(hrspace.__version__, hrspace.__commit__)')
  [ "$py" = "$version $commit" ] || fail "Python says '$py', the command '$version $commit'"
  [ "$py" = "$version $commit" ] && echo "ok   hrspace.__version__ == $version"
fi

"$bin" design "$src/scenes/bedroom.json" --out "$tmp/d" --iterations 1 --seed 1 >/dev/null 2>"$tmp/err" \
  || fail "design exits $?: $(head -3 "$tmp/err")"
report="$tmp/d/report.json"
if [ -f "$report" ]; then
  got=$("${python/none/python3}" -c 'import json,sys; r=json.load(open(sys.argv[1])); print(r["version"], r["commit"])' "$report" 2>&1)
  [ "$got" = "$version $commit" ] || fail "report.json has '$got', the command '$version $commit'"
  [ "$got" = "$version $commit" ] && echo "ok   report.json version and commit"
else
  fail "no report.json"
fi
[ "$fails" = 0 ] || { echo "$fails failure(s)"; exit 1; }
