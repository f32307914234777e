#!/usr/bin/env bash
# Results that cannot be mixed (docs/experiments.md "Run identity", issue 33),
# end to end on the hrspace command: each case runs tiny sweeps (a few
# iterations) and checks the exit status and the message.
# Usage: integrity_test.sh HRSPACE SOURCE_DIR
set -u
bin="$(realpath "$1")"; src="$(realpath "$2")"
tmp=$(mktemp -d)
cleanup() {
  if [ -n "${mounted:-}" ]; then umount "$tmp/full" 2>/dev/null; fi
  rm -rf "$tmp"
}
trap cleanup EXIT
cd "$tmp" || exit 1
fails=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }

# expect NAME STATUS PATTERN CMD...: CMD exits STATUS and its stderr matches
# the extended regular expression PATTERN (and never says "internal error").
expect() {
  local name="$1" want="$2" pattern="$3"; shift 3
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" != "$want" ]; then
    fail "$name: exit $got, expected $want"; cat "$tmp/out" "$tmp/err"; return
  fi
  if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" "$tmp/err"; then
    fail "$name: stderr does not match '$pattern':"; cat "$tmp/err"; return
  fi
  if grep -q "internal error" "$tmp/err"; then fail "$name: internal error:"; cat "$tmp/err"; return; fi
  echo "ok   $name"
}

# A sweep of a few iterations: the timing study's quick rooms, one seed.
tiny=(--quick --seeds 1)

# 1. The same study with other --iterations: refused, naming the column.
expect "first sweep" 0 "" "$bin" experiment timing "${tiny[@]}" --iterations 2 --out E
expect "same options resume" 0 "" "$bin" experiment timing "${tiny[@]}" --iterations 2 --out E
grep -q "timing: 0 run, 8 already stored" "$tmp/out" || { fail "resume ran something:"; cat "$tmp/out"; }
expect "other --iterations refused" 2 "iterations '2'.*iterations '3'" \
  "$bin" experiment timing "${tiny[@]}" --iterations 3 --out E
grep -q "already stored" "$tmp/out" && fail "other --iterations reported runs as stored"
expect "other --threads refused" 2 "threads" \
  "$bin" experiment timing "${tiny[@]}" --iterations 2 --threads 2 --out E
/usr/bin/python3 - E/timing/runs.csv <<'PY' || fail "runs.csv lacks identity columns"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
need = ["version", "commit", "iterations", "threads", "quick", "scene_digest", "planner_config"]
bad = [f"{r['key']}: {c}" for r in rows for c in need if not r.get(c)]
bad += [f"{r['key']}: iterations {r['iterations']}" for r in rows if r.get("iterations") != "2"]
print("\n".join(bad) if bad else f"runs.csv: {len(rows)} rows with identity columns")
sys.exit(1 if bad or len(rows) != 8 else 0)
PY

# 2. An edited scene of the same file name: refused, naming the digest.
mkdir -p a b
cp "$src/scenes/office.json" a/office.json
cp "$src/scenes/office.json" b/office.json
echo " " >>b/office.json
rooms=(--seeds 1 --iterations 2 --rooms)
expect "scene stored" 0 "" "$bin" experiment ao_graph "${rooms[@]}" a/office.json --out F
echo " " >>a/office.json
expect "edited scene refused" 2 "scene_digest" \
  "$bin" experiment ao_graph "${rooms[@]}" a/office.json --out F

# 3. Two scenes of one file name in --rooms: refused up front, naming both.
expect "same name, two scenes" 2 "a/office.json and b/office.json" \
  "$bin" experiment ao_graph "${rooms[@]}" a/office.json,b/office.json --out G
expect "same scene twice" 2 "a/office.json and a/office.json" \
  "$bin" experiment ao_graph "${rooms[@]}" a/office.json,a/office.json --out G
[ -e G ] && fail "a refused --rooms created its output"

# 4. Bad --scenes and --rooms: exit 2 naming the path, before any run.
expect "--scenes missing" 2 "--scenes nowhere: no such directory" \
  "$bin" experiment ao_graph --seeds 1 --scenes nowhere --out G
expect "--scenes a file" 2 "--scenes a/office.json: not a directory" \
  "$bin" experiment ao_graph --seeds 1 --scenes a/office.json --out G
mkdir -p only_bedroom
cp "$src/scenes/bedroom.json" only_bedroom/
expect "--scenes without a later study's rooms" 2 "only_bedroom/[a-z_]+\.json" \
  "$bin" experiment all --quick --iterations 2 --scenes only_bedroom --out G
[ -e G ] && fail "no run may start when a later study's scene is missing"
expect "--rooms missing" 2 "nope.json" "$bin" experiment ao_graph --rooms nope.json --out G

# 5. Output errors: exit 1 with the path and the system's reason.
: >afile
expect "--out under a file" 1 "afile/sub: cannot create directory: Not a directory" \
  "$bin" experiment ao_graph "${rooms[@]}" a/office.json --out afile/sub
mkdir -p full
if mount -t tmpfs -o size=64k tmpfs full 2>/dev/null; then
  mounted=1
  dd if=/dev/zero of=full/filler bs=4k 2>/dev/null
  expect "full disk" 1 "No space left on device" \
    "$bin" experiment ao_graph "${rooms[@]}" a/office.json --out full/E
else
  echo "skip full disk (cannot mount a tmpfs here)"
fi

# 6. Stored results that cannot be used: exit 2 naming the file.
mkdir -p H/ao_graph/runs/ao_graph-office-s1-all-scene.csv
expect "directory in place of a run file" 2 "H/ao_graph/runs/ao_graph-office-s1-all-scene.csv: is a directory" \
  "$bin" experiment ao_graph "${rooms[@]}" a/office.json --out H
expect "two seeds" 0 "" "$bin" experiment ao_graph --seeds 2 --iterations 2 --rooms a/office.json --out I
cp I/ao_graph/runs/ao_graph-office-s1-all-scene.csv I/ao_graph/runs/ao_graph-office-s2-all-scene.csv
expect "key cell not the file name" 2 "ao_graph-office-s2-all-scene.csv: key cell 'ao_graph-office-s1-all-scene'" \
  "$bin" experiment ao_graph --seeds 2 --iterations 2 --rooms a/office.json --out I

# 7. merge: shards that differ in anything but --shard are refused.
shard=(ao_graph --seeds 2 --rooms a/office.json)
expect "shard 1" 0 "" "$bin" experiment "${shard[@]}" --iterations 2 --shard 1/2 --out S1
expect "shard 2, other iterations" 0 "" "$bin" experiment "${shard[@]}" --iterations 3 --shard 2/2 --out S2
expect "shard 2" 0 "" "$bin" experiment "${shard[@]}" --iterations 2 --shard 2/2 --out S3
expect "merge of other iterations refused" 2 "iterations '2'.*iterations '3'" \
  "$bin" experiment merge "${shard[@]}" --out M S1 S2
expect "merge of one sweep" 0 "" "$bin" experiment merge "${shard[@]}" --out M S1 S3

# 8. The argument parser: an option given twice, an empty --out.
expect "--iterations twice" 2 "option --iterations given twice" \
  "$bin" experiment ao_graph --iterations 3 --iterations 4 --out G
expect "--quick twice" 2 "option --quick given twice" "$bin" experiment ao_graph --quick --quick --out G
expect "--seed twice (design)" 2 "option --seed given twice" \
  "$bin" design "$src/scenes/bedroom.json" --seed 1 --seed 2 --out G
expect "--out empty" 2 "--out: empty directory name" "$bin" experiment ao_graph --out ""
[ -e G ] && fail "a refused command created its output"

# 9. reproduce.sh: the smoke run and the full run default to different roots.
# A copy of the script in a fake checkout, with a stub binary and plotter.
mkdir -p fake/scripts fake/paper_figures
cp "$src/scripts/reproduce.sh" fake/scripts/
printf '#!/bin/sh\nexit 0\n' >fake/scripts/setup.sh
printf 'import sys\nprint("plot", sys.argv[1])\n' >fake/paper_figures/plot.py
printf '#!/bin/sh\nwhile [ $# -gt 0 ]; do [ "$1" = --out ] && echo "$2" >>"%s/outs"; shift; done\n' \
  "$tmp" >stub
chmod +x stub fake/scripts/*.sh
HRSPACE_BIN="$tmp/stub" fake/scripts/reproduce.sh --quick timing >/dev/null 2>&1 || fail "reproduce.sh --quick (stub)"
HRSPACE_BIN="$tmp/stub" fake/scripts/reproduce.sh timing >/dev/null 2>&1 || fail "reproduce.sh (stub)"
if [ "$(cat outs 2>/dev/null)" != "$tmp/fake/out/reproduce-quick
$tmp/fake/out/reproduce" ]; then
  fail "reproduce.sh default roots:"; cat outs
else
  echo "ok   reproduce.sh --quick -> out/reproduce-quick, full -> out/reproduce"
fi
fake/scripts/reproduce.sh --help | grep -q "out/reproduce-quick" || fail "reproduce.sh --help lacks out/reproduce-quick"

# 10. reproduce.sh --publish: never a smoke run; with named studies only the
# ones whose section of REPRODUCTION.md stands alone, passed on as --only.
printf 'import sys\nprint("plot", " ".join(sys.argv[1:]))\n' >fake/paper_figures/plot.py
expect "--quick --publish refused" 2 "smoke run is never published" \
  env HRSPACE_BIN="$tmp/stub" fake/scripts/reproduce.sh --quick --publish generalization
expect "--publish of a paper study alone refused" 2 "--publish timing: a study of the paper" \
  env HRSPACE_BIN="$tmp/stub" fake/scripts/reproduce.sh --publish generalization timing
expect "--publish generalization alone" 0 "" \
  env HRSPACE_BIN="$tmp/stub" fake/scripts/reproduce.sh --publish generalization tradeoff
grep -q -- "--publish --only generalization --only tradeoff" "$tmp/out" ||
  { fail "reproduce.sh --publish STUDY did not pass --only:"; cat "$tmp/out"; }
expect "--publish of the full run" 0 "" env HRSPACE_BIN="$tmp/stub" fake/scripts/reproduce.sh --publish
grep -q -- "--only" "$tmp/out" && { fail "the full run published with --only:"; cat "$tmp/out"; }

# 10b. A study that fails (or is stopped) publishes nothing: its exit
# status is the script's, and the plotter runs without --publish.
printf '#!/bin/sh\nexit 3\n' >failing
chmod +x failing
expect "--publish after a failed study" 3 "did not finish \\(exit 3\\): nothing is published" \
  env HRSPACE_BIN="$tmp/failing" fake/scripts/reproduce.sh --publish
grep -q -- "--publish" "$tmp/out" && { fail "a failed study was published:"; cat "$tmp/out"; }
expect "--publish STUDY after a failed study" 3 "nothing is published" \
  env HRSPACE_BIN="$tmp/failing" fake/scripts/reproduce.sh --publish generalization
grep -q -- "--publish\|--only" "$tmp/out" && { fail "a failed study was published:"; cat "$tmp/out"; }

# 11. plot.py refuses to publish smoke runs, and --only replaces one section.
mkdir -p P/generalization
printf 'key,quick\na,1\n' >P/generalization/runs.csv
expect "plot.py --publish of a smoke run refused" 2 "smoke runs .* not published" \
  /usr/bin/python3 "$src/paper_figures/plot.py" P --publish
/usr/bin/python3 - "$src/paper_figures" <<'PY' || fail "plot.py splice_section"
import sys
sys.path.insert(0, sys.argv[1])
import plot
z, t = plot.ZOO_HEADING, plot.TRADEOFF_HEADING
doc = f"# R\n\n| claims |\n\n{z}\n\nold zoo\n\n{t}\n\nold tradeoff\n"
new = plot.splice_section(doc, z, ["", z, "", "new zoo"])
assert new == f"# R\n\n| claims |\n\n{z}\n\nnew zoo\n\n{t}\n\nold tradeoff\n", new
new = plot.splice_section(new, t, ["", t, "", "new tradeoff"])
assert new.endswith(f"{t}\n\nnew tradeoff\n") and "new zoo" in new, new
assert plot.splice_section("# R\n", z, ["", z, "", "x"]) == f"# R\n\n{z}\n\nx\n"
print("ok   plot.py splice_section")
PY
# plot.py --publish --only generalization on a copy of paper_figures/: the
# zoo section, figure and summary are replaced; the claims and the
# tradeoff section stay byte for byte.
mkdir -p pf Q/generalization
cp "$src"/paper_figures/*.py pf/
h=study,key,bucket,zoo_seed,index,seed,planner,version,commit,iterations,threads,quick,total_s,planning_s
h=$h,tours_found,tours_total,objects,success,witness_tourable,cost_le_witness,prefs_met,prefs_total
h=$h,prefs_share,worst_angle_deg,angle_over_20,cpu
{
  echo "$h"
  echo "generalization,g1,4-8,1,101,1,all,0,abc123,700,1,0,4.5,4.0,10,10,8,1,1,1,11,12,0.92,3,0,CPU-X"
  echo "generalization,g2,4-8,1,101,1,baseline,0,abc123,700,1,0,9.5,9.0,9,10,8,1,1,0,10,12,0.83,25,1,CPU-X"
} >Q/generalization/runs.csv
printf 'bucket,planner,n\n4-8,all,1\n' >Q/generalization/summary.csv
{
  printf '# R\n\n| claim |\n|---|\n| a claim |\n\n'
  printf '%s\n\nold zoo\n\n' "## Beyond the paper: rooms nobody tuned for (the room zoo)"
  printf '%s\n\nold tradeoff\n' "## Beyond the paper: preferences against tours (the trade-off study)"
} >pf/REPRODUCTION.md
cp pf/REPRODUCTION.md before.md
expect "plot.py --publish --only generalization" 0 "" \
  /usr/bin/python3 pf/plot.py Q --publish --only generalization --command "the command"
grep -q 'The `generalization` study at commit `abc123` (machine: CPU-X), run and published alone by `the command`' \
  pf/REPRODUCTION.md || { fail "--only: the zoo section does not name commit, machine and command"; cat pf/REPRODUCTION.md; }
grep -q "old zoo" pf/REPRODUCTION.md && fail "--only: the old zoo section is still there"
[ "$(sed -n '1,6p' pf/REPRODUCTION.md)" = "$(sed -n '1,6p' before.md)" ] || fail "--only: the claims changed"
[ "$(tail -3 pf/REPRODUCTION.md)" = "$(tail -3 before.md)" ] || fail "--only: the tradeoff section changed"
cmp -s Q/generalization/summary.csv pf/tables/generalization_summary.csv || fail "--only: summary not published"
[ -s pf/figures/generalization.svg ] || fail "--only: figure not published"
expect "plot.py --only without --publish refused" 2 "--only needs --publish" \
  /usr/bin/python3 pf/plot.py Q --only generalization

[ "$fails" = 0 ] && echo "integrity_test: all checks passed" || echo "integrity_test: $fails failure(s)"
exit $((fails > 0))
