#!/usr/bin/env bash
# End-to-end tests of the hrspace command. Usage: cli_test.sh HRSPACE SOURCE_DIR
set -u
bin="$1"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
check() {  # check NAME EXPECTED_STATUS COMMAND... ; stdout in $tmp/out, stderr in $tmp/err
  local name="$1" want="$2"; shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" != "$want" ]; then
    echo "FAIL $name: exit $got, expected $want"; sed 's/^/  stderr: /' "$tmp/err" | head -5; fails=$((fails+1))
  else
    echo "ok   $name"
  fi
}
expect_err() {  # expect_err NAME PATTERN: stderr is one line matching PATTERN
  local lines; lines=$(wc -l <"$tmp/err")
  if [ "$lines" != 1 ] || ! grep -q -- "$2" "$tmp/err"; then
    echo "FAIL $1: stderr should be one line matching '$2', got:"; sed 's/^/  /' "$tmp/err"; fails=$((fails+1))
  fi
}
expect_out() {  # expect_out NAME PATTERN (grep -x on stdout)
  if ! grep -qx -- "$2" "$tmp/out"; then
    echo "FAIL $1: stdout lacks line '$2'"; head -5 "$tmp/out" | sed 's/^/  /'; fails=$((fails+1))
  fi
}

# validate
for f in "$src"/scenes/*.json; do
  check "validate $(basename "$f")" 0 "$bin" validate "$f"
done
check "validate missing file" 2 "$bin" validate "$tmp/nope.json"
expect_err "missing file message" "nope.json"
printf '' >"$tmp/empty.json"
check "validate empty file" 2 "$bin" validate "$tmp/empty.json"
expect_err "empty file message" "empty.json"
# Issue 33: bounded reads. Devices and FIFOs are refused by name; stdin stops at the limit.
check "validate /dev/zero" 2 "$bin" validate /dev/zero
expect_err "device message" "/dev/zero: not a regular file"
mkfifo "$tmp/fifo"
check "validate a FIFO" 2 timeout 20 "$bin" validate "$tmp/fifo"
expect_err "FIFO message" "fifo: not a regular file"
check "design from endless stdin" 2 timeout 60 sh -c "\"$bin\" design - --out \"$tmp/dz\" </dev/zero"
expect_err "stdin limit message" "stdin: more than the 64 MiB"
check "collide poses from /dev/zero" 2 "$bin" collide "$src/scenes/bedroom.json" --poses /dev/zero
expect_err "poses device message" "/dev/zero: not a regular file"
printf '{"format": ' >"$tmp/broken.json"
check "validate invalid JSON" 2 "$bin" validate "$tmp/broken.json"
expect_err "invalid JSON message" "broken.json"
sed 's/"width": 0.9/"width": -0.9/' "$src/scenes/bedroom.json" >"$tmp/neg.json"
check "validate negative door width" 2 "$bin" validate "$tmp/neg.json"
expect_err "negative width names the pointer" "/door/width"
check "validate without a scene" 2 "$bin" validate
# An angle larger than 2π is legal but looks like degrees: a warning, exit 0.
sed 's/"pose": \[3.4, 1.8, 0.0\]/"pose": [3.4, 1.8, 360]/' "$src/scenes/office.json" >"$tmp/deg.json"
check "validate heading in degrees" 0 "$bin" validate "$tmp/deg.json"
expect_err "degrees warning" "warning: .*deg.json: /objects/1/pose/2: angle 360 is larger than 2π"
# Furniture 0.01 m past a wall: refused, naming the wall and the amount.
sed 's/"pose": \[4.815, 3.0, 3.141592653589793\]/"pose": [4.835, 3.0, 3.141592653589793]/' \
  "$src/scenes/office.json" >"$tmp/out.json"
check "validate past the wall" 2 "$bin" validate "$tmp/out.json"
expect_err "past the wall message" '/objects/2/pose: the footprint of "bookshelf" sticks out 0.01 m past the wall from (5,0) to (5,4)'
check "unknown command" 2 "$bin" frobnicate
check "unknown option" 2 "$bin" collide "$src/scenes/bedroom.json" --posse x
check "help" 0 "$bin" --help
check "collide help" 0 "$bin" collide --help

# collide: header, one row per pose in order, free flag, clearances
printf 'x,y,theta\n2.2,1.2,0\n-1,0,0\n0.2,0.2,0\n' >"$tmp/poses.csv"
check "collide" 0 "$bin" collide "$src/scenes/bedroom.json" --poses "$tmp/poses.csv"
expect_out "collide header" "x,y,theta,free,clear_left,clear_right"
[ "$(wc -l <"$tmp/out")" = 4 ] || { echo "FAIL collide: expected 4 lines"; fails=$((fails+1)); }
[ "$(sed -n 3p "$tmp/out" | cut -d, -f4)" = 0 ] || { echo "FAIL collide: outside pose must not be free"; fails=$((fails+1)); }
[ "$(sed -n 4p "$tmp/out" | cut -d, -f4)" = 0 ] || { echo "FAIL collide: corner pose must not be free"; fails=$((fails+1)); }
printf '2.2,1.2,0\n' | "$bin" collide "$src/scenes/bedroom.json" --poses - >"$tmp/stdin.out" 2>&1
[ "$(sed -n 2p "$tmp/stdin.out")" = "$(sed -n 2p "$tmp/out")" ] || { echo "FAIL collide: stdin without header differs"; fails=$((fails+1)); }
printf '1,2,x\n' >"$tmp/badposes.csv"
check "collide bad number" 2 "$bin" collide "$src/scenes/bedroom.json" --poses "$tmp/badposes.csv"
expect_err "bad number names line and field" "line 1, field 3"
printf '1,2\n' >"$tmp/short.csv"
check "collide short row" 2 "$bin" collide "$src/scenes/bedroom.json" --poses "$tmp/short.csv"

# rs: header, word and signed segments; bad radius
printf 'x0,y0,t0,x1,y1,t1\n0,0,0,2,0,0\n0,0,0,-1,0,0\n0,0,0,0,0,0\n' >"$tmp/pairs.csv"
check "rs" 0 "$bin" rs --radius 0.7 --pairs "$tmp/pairs.csv"
expect_out "rs header" "length,word,segments"
expect_out "rs straight ahead" "2,S+,2"
expect_out "rs straight back" "1,S-,-1"
expect_out "rs identical poses" "0,,"
check "rs zero radius" 2 "$bin" rs --radius 0 --pairs "$tmp/pairs.csv"
check "rs missing radius" 2 "$bin" rs --pairs "$tmp/pairs.csv"

# plan / tour with either planner; proposed-only options are checked
bed="$src/scenes/bedroom.json"
check "plan baseline" 0 "$bin" plan "$bed" --from 0.9,1.2,0 --to 2.0,1.2,0
grep -q '"found": *true' "$tmp/out" || { echo "FAIL: plan baseline found no path"; fails=$((fails + 1)); }
check "plan proposed" 0 "$bin" plan "$bed" --from 0.9,1.2,0 --to 2.0,1.2,0 --planner proposed
grep -q '"found": *true' "$tmp/out" || { echo "FAIL: plan proposed found no path"; fails=$((fails + 1)); }
check "plan proposed samples only" 0 "$bin" plan "$bed" --from 0.9,1.2,0 --to 2.0,1.2,0 --planner proposed --reuse samples
check "plan reuse without proposed" 2 "$bin" plan "$bed" --from 0.9,1.2,0 --to 2.0,1.2,0 --reuse samples
expect_err "reuse needs proposed" "--reuse needs --planner default"
check "plan reuse across layouts" 2 "$bin" plan "$bed" --from 0.9,1.2,0 --to 2.0,1.2,0 --planner proposed --reuse paths
expect_err "plan rejects paths" "--reuse: 'paths'"
check "plan unknown planner" 2 "$bin" plan "$bed" --from 0.9,1.2,0 --to 2.0,1.2,0 --planner fast
expect_err "unknown planner" "--planner: unknown planner 'fast'"
# A room split by a partition whose gap (0.5 m) is narrower than the chair
# (0.65 m): a leg across it is certified impossible; one within a half is not.
cat >"$tmp/split.json" <<'JSON'
{"format": "hrspace-scene/1", "name": "split",
 "room": {"size": [6, 3]},
 "door": {"center": [1.0, 0.0], "width": 0.9},
 "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
 "objects": [{"id": "partition", "size": [0.2, 2.5], "pose": [3.0, 1.25, 0], "fixed": true}],
 "activity": {"transitions": {"door": {"partition": 1.0}}}}
JSON
check "plan across a closed partition" 0 "$bin" plan "$tmp/split.json" --from 1.0,1.5,0 --to 4.6,2.0,0
grep -q '"found":false' "$tmp/out" && grep -q '"impossible":true' "$tmp/out" ||
  { echo "FAIL: leg across the partition not proven impossible"; sed 's/^/  /' "$tmp/out"; fails=$((fails + 1)); }
check "plan within one half" 0 "$bin" plan "$tmp/split.json" --from 1.0,1.5,0 --to 2.0,2.0,1.0
grep -q '"impossible":false' "$tmp/out" ||
  { echo "FAIL: leg within one half called impossible"; fails=$((fails + 1)); }
check "tour proposed" 0 "$bin" tour "$bed" --sequence door,tv --planner proposed
grep -q '"sequence"' "$tmp/out" || { echo "FAIL: tour proposed printed no tour"; fails=$((fails + 1)); }
check "tour reuse trees" 2 "$bin" tour "$bed" --sequence door,tv --planner proposed --reuse trees
check "plan reuse shortcuts" 2 "$bin" plan "$bed" --from 0.9,1.2,0 --to 2.0,1.2,0 --planner proposed --reuse shortcuts
expect_err "plan rejects shortcuts" "shortcuts would do nothing here"
check "tour reuse proofs (removed)" 2 "$bin" tour "$bed" --sequence door,tv --planner proposed --reuse samples,proofs
expect_err "proofs is no technique" "--reuse: unknown technique 'proofs'"
check "tour proposed budget" 0 "$bin" tour "$bed" --sequence door,tv,bed --planner proposed --reuse samples,steering,paths,shortcuts,budget
grep -q '"sequence"' "$tmp/out" || { echo "FAIL: tour with a budget printed no tour"; fails=$((fails + 1)); }
check "plan reuse budget" 2 "$bin" plan "$bed" --from 0.9,1.2,0 --to 2.0,1.2,0 --planner proposed --reuse samples,budget
expect_err "plan rejects budget" "budget would do nothing here"
check "reuse unknown technique" 2 "$bin" tour "$bed" --sequence door,tv --planner proposed --reuse proof
expect_err "unknown technique" "--reuse: unknown technique 'proof'"

# Hardening (issue 20, docs/hardening.md), by class.
# CsvRowsAreNeverDropped: a header is exactly the column names; any other
# first line is data and is refused with its line number.
for first in 'nan,1,1' 'inf,0,0' '1e400,0,0' 'x;y;theta' 'X,Y,THETA' 'x,y'; do
  printf '%s\n2.2,1.2,0\n' "$first" >"$tmp/first.csv"
  check "CsvRowsAreNeverDropped collide '$first'" 2 "$bin" collide "$bed" --poses "$tmp/first.csv"
  expect_err "CsvRowsAreNeverDropped '$first' names line 1" "first.csv: line 1"
done
printf ' x , y ,theta\n2.2,1.2,0\n' >"$tmp/spaced.csv"
check "CsvRowsAreNeverDropped spaced header" 0 "$bin" collide "$bed" --poses "$tmp/spaced.csv"
[ "$(wc -l <"$tmp/out")" = 2 ] || { echo "FAIL spaced header: expected 2 lines"; fails=$((fails+1)); }
printf 'nan,0,0,1,0,0\n' | "$bin" rs --radius 1 >"$tmp/out" 2>"$tmp/err"
[ $? = 2 ] || { echo "FAIL CsvRowsAreNeverDropped rs: nan row not refused"; fails=$((fails+1)); }
expect_err "CsvRowsAreNeverDropped rs names line 1" "stdin: line 1, field 1"
# RsAnswersAreRightOrRefused: radius and coordinates within the format's limits.
printf '0,0,0,1,0,0\n' >"$tmp/one.csv"
for r in 1e12 1e-300 0.0001 2001; do
  check "RsAnswersAreRightOrRefused radius $r" 2 "$bin" rs --radius "$r" --pairs "$tmp/one.csv"
  expect_err "RsAnswersAreRightOrRefused radius $r message" "--radius: must be within"
done
for r in 0.001 2000; do
  check "RsAnswersAreRightOrRefused radius $r" 0 "$bin" rs --radius "$r" --pairs "$tmp/one.csv"
  expect_out "RsAnswersAreRightOrRefused radius $r straight" "1,S+,1"
done
printf '1e200,0,0,1,0,0\n' >"$tmp/far.csv"
check "RsAnswersAreRightOrRefused coordinates 1e200" 2 "$bin" rs --radius 1 --pairs "$tmp/far.csv"
expect_err "RsAnswersAreRightOrRefused 1e200 names the field" "line 1, field 1 (x0)"
# LateChecksComeFirst: a directory as input, an unwritable --out, big room coordinates.
check "LateChecksComeFirst --poses directory" 2 "$bin" collide "$bed" --poses "$tmp"
expect_err "LateChecksComeFirst directory named" "is a directory"
check "LateChecksComeFirst --pairs directory" 2 "$bin" rs --radius 1 --pairs "$tmp"
check "LateChecksComeFirst scene directory" 2 "$bin" validate "$tmp"
touch "$tmp/afile"
check "LateChecksComeFirst --out under a file" 2 "$bin" design "$bed" --out "$tmp/afile/sub" --iterations 1
expect_err "LateChecksComeFirst --out named" "afile/sub"
sed 's/\[4.5, 0\], \[4.5, 4.0\], \[0, 4.0\]/[1500, 0], [1500, 4.0], [0, 4.0]/' "$bed" >"$tmp/km.json"
grep -q 1500 "$tmp/km.json" || { echo "FAIL: km.json not made"; fails=$((fails+1)); }
check "LateChecksComeFirst room beyond 1 km" 2 "$bin" validate "$tmp/km.json"
expect_err "LateChecksComeFirst room pointer" "/room/polygon/1/0: must be within"
# validate: what a design will face (information, exit 0), skipped by --quiet.
check "validate outlook" 0 "$bin" validate "$src/scenes/l_studio.json"
expect_out "validate sealed L-studio" "tours      0/10 found in the input layout (the design must open the others)"
expect_out "validate unmet preference" "           wall_angle sofa: off by 90 deg (tolerance 3)"
check "validate quiet" 0 "$bin" validate "$src/scenes/l_studio.json" --quiet
if grep -q "^tours" "$tmp/out"; then echo "FAIL: --quiet printed the outlook"; fails=$((fails+1)); fi
# The README's study count is the code's.
studies=$("$bin" experiment list | wc -l)
grep -q "^$studies studies (\`hrspace experiment list\`" "$src/README.md" || { echo "FAIL: README does not say $studies studies"; fails=$((fails+1)); }
# design --planner: presets and items, refused before any work with one line.
check "design unknown preset" 2 "$bin" design "$bed" --out "$tmp/dp" --iterations 1 --planner fast
expect_err "design unknown preset named" "--planner: unknown planner preset 'fast' (default, baseline, paper, literal)"
check "design technique on the RRT" 2 "$bin" design "$bed" --out "$tmp/dp" --iterations 1 --planner baseline,trees
expect_err "design technique on the RRT named" "'trees': the baseline preset plans each leg with the RRT"
check "design preset with items" 0 "$bin" design "$bed" --out "$tmp/dp" --iterations 2 --planner literal,goalskip
# Issue 33: the set of files is marked by manifest.json (written last), and
# a second writer into one --out is refused while the first holds its lock.
/usr/bin/python3 - "$tmp/dp" <<'PY' || { echo "FAIL manifest"; fails=$((fails+1)); }
import json, os, sys
d = sys.argv[1]
m = json.load(open(os.path.join(d, "manifest.json")))
names = sorted(f["name"] for f in m["files"])
assert names == ["design.svg", "layout.json", "report.json", "tours.json"], names
for f in m["files"]:
    data = open(os.path.join(d, f["name"]), "rb").read()
    h = 14695981039346656037
    for c in data:
        h = ((h ^ c) * 1099511628211) % (1 << 64)
    assert len(data) == f["bytes"] and f"{h:016x}" == f["fnv1a64"], f
print("ok   manifest matches the files")
# accessibility.json and design.html are pinned by report.json's digests.
report = json.load(open(os.path.join(d, "report.json")))
for section in ("accessibility", "viewer"):
    name = report[section]["file"]
    data = open(os.path.join(d, name), "rb").read()
    h = 14695981039346656037
    for c in data:
        h = ((h ^ c) * 1099511628211) % (1 << 64)
    assert f"{h:016x}" == report[section]["fnv1a64"], (section, name)
html = open(os.path.join(d, "design.html"), encoding="utf-8").read()
assert "http-equiv=\"Content-Security-Policy\"" in html and "default-src 'none'" in html
print("ok   report.json pins accessibility.json and design.html")
PY
# view: the page's path; one line naming DIR when there is none.
check "view" 0 env -u DISPLAY -u WAYLAND_DISPLAY "$bin" view "$tmp/dp"
[ "$(cat "$tmp/out")" = "$(cd "$tmp/dp" && pwd)/design.html" ] || { echo "FAIL view printed $(cat "$tmp/out")"; fails=$((fails+1)); }
check "view --print" 0 "$bin" view "$tmp/dp" --print
check "view without a design" 2 "$bin" view "$tmp"
expect_err "view without a design message" "no design.html"
check "view of a missing directory" 2 "$bin" view "$tmp/none"
check "view help" 0 "$bin" view --help
mkdir -p "$tmp/locked"
check "design into a locked --out" 2 sh -c "( flock 9; \"$bin\" design \"$bed\" --out \"$tmp/locked\" --iterations 1 ) 9>\"$tmp/locked/.hrspace.lock\""
expect_err "locked --out message" "locked: in use by another hrspace run"
check "experiment into a locked --out" 2 sh -c "( flock 9; \"$bin\" experiment method --quick --out \"$tmp/locked\" ) 9>\"$tmp/locked/.hrspace.lock\""
expect_err "locked experiment message" "locked: in use by another hrspace run"
check "design after the lock is released" 0 "$bin" design "$bed" --out "$tmp/locked" --iterations 1
grep -q '"planner": "literal,goalskip"' "$tmp/dp/report.json" || { echo "FAIL: report.json planner name"; fails=$((fails+1)); }
check "design default preset" 0 "$bin" design "$bed" --out "$tmp/dd" --iterations 2
grep -q '"planner": "default"' "$tmp/dd/report.json" || { echo "FAIL: default planner not in report.json"; fails=$((fails+1)); }
"$bin" design --help >"$tmp/help"
for p in default baseline paper literal goalskip refuse escape early samples steering paths trees; do
  grep -q "^    $p " "$tmp/help" || { echo "FAIL: design --help lacks $p"; fails=$((fails+1)); }
done
# StdoutWriteErrorsAreExitOne: every subcommand checks its output.
# generate: rooms and witnesses that pass validate, the same for a seed and
# any --threads, one-line errors naming the option for bad values
check "generate" 0 "$bin" generate --out "$tmp/zoo" --seed 4 --count 3 --objects 4-9 --threads 1
[ "$(wc -l <"$tmp/out")" = 3 ] || { echo "FAIL generate: expected one line per room"; fails=$((fails+1)); }
grep -q "^zoo_4_1 .*tours 10/10" "$tmp/out" || { echo "FAIL generate: no line for zoo_4_1 with 10/10 tours"; fails=$((fails+1)); }
for f in "$tmp"/zoo/zoo_4_{1,2,3}.json "$tmp"/zoo/zoo_4_{1,2,3}.witness.json; do
  check "validate generated $(basename "$f")" 0 "$bin" validate "$f"
done
check "generate again, two threads" 0 "$bin" generate --out "$tmp/zoo2" --seed 4 --count 3 --objects 4-9 --threads 2
diff -r "$tmp/zoo" "$tmp/zoo2" >/dev/null || { echo "FAIL generate: same seed, other files"; fails=$((fails+1)); }
check "generate one room by its index" 0 "$bin" generate --out "$tmp/zoo4" --seed 4 --first 3 --count 1 --objects 4-9 --threads 1 --no-check
[ "$(ls "$tmp/zoo4")" = "$(printf 'zoo_4_3.json\nzoo_4_3.witness.json')" ] || { echo "FAIL generate --first: expected only zoo_4_3"; fails=$((fails+1)); }
cmp -s "$tmp/zoo4/zoo_4_3.json" "$tmp/zoo/zoo_4_3.json" || { echo "FAIL generate --first: zoo_4_3 differs from the third room of --count 3"; fails=$((fails+1)); }
check "generate help" 0 "$bin" generate --help
for bad in "--objects 3-9" "--objects 9-5" "--objects x" "--objects 4-101" "--shape oval" "--count 0" "--first 0" "--seed -1"; do
  # shellcheck disable=SC2086
  check "generate $bad" 2 "$bin" generate --out "$tmp/zoo3" $bad
  expect_err "generate $bad names the option" "${bad%% *}"
done
check "generate without --out" 2 "$bin" generate
expect_err "generate without --out message" "--out"

if [ -w /dev/full ]; then
  for cmd in "validate $bed" "collide $bed --poses $tmp/poses.csv" "rs --radius 0.7 --pairs $tmp/pairs.csv" \
             "plan $bed --from 0.9,1.2,0 --to 2.0,1.2,0" "tour $bed --sequence door,tv" "--help" "validate --help" \
             "view $tmp/dp --print"; do
    # shellcheck disable=SC2086
    "$bin" $cmd >/dev/full 2>"$tmp/err"; got=$?
    if [ "$got" != 1 ] || ! grep -q "cannot write to standard output" "$tmp/err"; then
      echo "FAIL StdoutWriteErrorsAreExitOne '$cmd': exit $got"; sed 's/^/  /' "$tmp/err"; fails=$((fails+1))
    else
      echo "ok   StdoutWriteErrorsAreExitOne '$cmd'"
    fi
  done
fi

if [ "$fails" -ne 0 ]; then echo "$fails failure(s)"; exit 1; fi
echo "all CLI checks passed"
