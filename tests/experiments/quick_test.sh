#!/usr/bin/env bash
# End to end: scripts/reproduce.sh --quick writes every study's tables, every
# figure and REPRODUCTION.md; a rerun resumes (runs nothing); a study re-run
# with one job writes the same runs as with two (timing columns aside).
# Usage: quick_test.sh HRSPACE SOURCE_DIR
set -u
bin="$1"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }

export HRSPACE_BIN="$bin"
rc=0; "$src/scripts/reproduce.sh" --quick --jobs 2 --out "$tmp/q" >"$tmp/log" 2>&1 || rc=$?
if [ "$rc" != 0 ]; then fail "reproduce.sh --quick exited $rc"; cat "$tmp/log"; fi

/usr/bin/python3 - "$tmp/q" <<'PY' || fails=$((fails + 1))
import csv, os, sys
root = sys.argv[1]
studies = [line.split()[0] for line in os.popen(os.environ["HRSPACE_BIN"] + " experiment list")
           if line.strip()]
assert len(studies) >= 11, studies
bad = []
for s in studies:
    for f in ("runs.csv", "summary.csv"):
        p = os.path.join(root, s, f)
        try:
            rows = list(csv.DictReader(open(p, newline="")))
        except OSError as e:
            bad.append(f"{p}: {e}"); continue
        if not rows:
            bad.append(f"{p}: no rows")
        if f == "runs.csv":
            for r in rows:
                for col in ("study", "key", "commit", "cpu", "threads"):
                    if not r.get(col):
                        bad.append(f"{p}: row {r.get('key')} lacks {col}")
        else:
            for r in rows:
                if not r.get("commit"):
                    bad.append(f"{p}: summary row lacks its commit")
# The tables the studies add beside runs.csv.
for table in ("timing/trace.csv", "rrt_iterations/histogram.csv", "rs_decomposition/samples.csv"):
    if not os.path.exists(os.path.join(root, table)):
        bad.append(f"{table}: missing")
regions = [r for r in csv.DictReader(open(os.path.join(root, "rs_decomposition", "runs.csv")))
           if r.get("kind") == "regions"]
if not regions or not all(float(r.get("lookup_ns_far") or 0) > 0 and float(r.get("exact_ns_far") or 0) > 0
                          for r in regions):
    bad.append("rs_decomposition: regions runs lack the look-up cost")
alphas = {r.get("alpha") for r in csv.DictReader(open(os.path.join(root, "ao_graph", "runs.csv")))}
if alphas != {"scene", "uniform"}:
    bad.append(f"ao_graph: alpha arms {alphas}, expected scene and uniform")
figures = ["timing", "rs_partition", "rs_decomposition_time", "rrt_iterations", "rrt_threshold",
           "small_room_time", "small_room_designs", "ao_graph_designs", "designs_cover",
           "fig1_weights", "ao_graphs", "goal_poses", "generalization", "timing_trace", "sensitivity",
           "designs_cover_paper", "tradeoff"]
for name in figures:
    for ext, magic in (("png", b"\x89PNG\r\n\x1a\n"), ("svg", b"<svg")):
        p = os.path.join(root, "figures", f"{name}.{ext}")
        if not os.path.exists(p) or os.path.getsize(p) < 1000:
            bad.append(f"{p}: missing or nearly empty"); continue
        head = open(p, "rb").read(4096)
        if (ext == "png" and not head.startswith(magic)) or (ext == "svg" and magic not in head):
            bad.append(f"{p}: not a {ext.upper()} file")
rep = open(os.path.join(root, "REPRODUCTION.md")).read()
rows = [l for l in rep.splitlines() if l.startswith("| ") and not l.startswith("| claim")]
claims = ["Abstract", "96.06", "whole designs: the paper's planner", "whole designs: the default preset vs the literal",
          "whole designs: the default preset vs our baseline", "identical layouts", "§V-A: samples",
          "look-up", "partition", "rrt-it", "§V-C", "§VI-B", "similar", "§VI-C", "uniform-α control",
          "cover3", "Fig. 1", "converges", "sensitivity"]
# Every speed row carries the quality of both sides, with an interval.
for r in rows:
    if "cuts planning time" in r and not ("tours" in r and "95 % CI" in r):
        bad.append(f"REPRODUCTION.md: a speed row without quality or interval: {r[:80]}")
for c in claims:
    if not any(c in r for r in rows):
        bad.append(f"REPRODUCTION.md: no row for the claim '{c}'")
for b in bad:
    print("FAIL", b)
print(f"checked {len(studies)} studies, {len(figures)} figures, {len(rows)} claims")
sys.exit(1 if bad else 0)
PY

# A rerun finds every run stored.
rc=0; "$bin" experiment all --quick --out "$tmp/q" >"$tmp/again" 2>&1 || rc=$?
if [ "$rc" != 0 ]; then fail "rerun exited $rc"; cat "$tmp/again"; fi
if grep -v " 0 run, " "$tmp/again" | grep -q "run,"; then fail "rerun ran something:"; cat "$tmp/again"; fi

# One job or two: the same runs (a cheap study).
"$bin" experiment ao_graph --quick --jobs 1 --out "$tmp/one" >/dev/null 2>&1 || fail "ao_graph --jobs 1"
/usr/bin/python3 - "$tmp/q/ao_graph/runs.csv" "$tmp/one/ao_graph/runs.csv" <<'PY' || fails=$((fails + 1))
import csv, sys
def rows(p):
    return [{k: v for k, v in r.items() if not (k.endswith(("_s", "_ms", "_share")) or k in ("commit", "cpu", "cores"))}
            for r in csv.DictReader(open(p, newline=""))]
a, b = rows(sys.argv[1]), rows(sys.argv[2])
if a != b or not a:
    print("FAIL ao_graph runs differ between --jobs 2 and --jobs 1"); sys.exit(1)
print(f"ao_graph: {len(a)} runs identical with 1 and 2 jobs")
PY

[ "$fails" = 0 ] && echo "quick_test: all checks passed" || echo "quick_test: $fails failure(s)"
exit $((fails > 0))
