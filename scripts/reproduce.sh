#!/usr/bin/env bash
# Regenerates the paper's experiments (§VI) and figures with the harness:
# every study (or the ones named), then the figures and REPRODUCTION.md.
#
#   scripts/reproduce.sh [--quick] [--out DIR] [--jobs N] [--publish] [STUDY ...]
#
# Studies: hrspace experiment list. Runs already stored under DIR are
# skipped, so an interrupted reproduction resumes where it stopped; a stored
# run of other options (another commit, iterations, scene) is refused. The
# smoke run (--quick) and the full run have their own default DIR, so the
# one never mixes into the other.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

usage() {
  cat <<'USAGE'
usage: scripts/reproduce.sh [--quick] [--out DIR] [--jobs N] [--publish] [STUDY ...]
       scripts/reproduce.sh --status

Runs the studies of the experiments harness (default: all of them) into DIR
(default out/reproduce, with --quick out/reproduce-quick), then draws the
figures into DIR/figures and writes DIR/REPRODUCTION.md (the paper's claims
against ours). Runs already stored in DIR are skipped; a stored run made with
other options, scenes or code is refused (exit 2), never mixed in.

  --quick      2 seeds, 100 iterations, the smallest sweeps (a smoke run, minutes);
               default DIR out/reproduce-quick
  --out DIR    output root (default out/reproduce, or out/reproduce-quick)
  --jobs N     designs run at once, one thread each (default 1)
  --publish    also copy the figures, summaries and REPRODUCTION.md into
               paper_figures/ (what README and docs embed). With named studies,
               only generalization and tradeoff, whose sections of REPRODUCTION.md
               stand alone: their figure, summary and section replace the
               published ones and name their own commit. A --quick run is
               never published, nor a run whose study failed or was stopped
               (its figures are drawn in DIR/figures; the exit status is the
               study's).
  --status     only say whether paper_figures/ is current: "current" (exit 0) when
               the code under geometry/, rs/, planning/ and optimize/ at every
               commit REPRODUCTION.md names (the run's, and any study run on
               its own) equals HEAD's, and the room zoo (experiments/room_zoo*,
               studies_generalization.cpp) at the commits of the generalization
               and tradeoff studies too; else "stale" (exit 1)
  STUDY ...    timing rs_decomposition rrt_iterations sensitivity small_room ao_graph designs
               hard_rooms design_loop method generalization tradeoff

Environment: HRSPACE_BIN uses that hrspace binary instead of building one.
USAGE
}

out=""
jobs=1
quick=()
publish=()
studies=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --quick) quick=(--quick) ;;
    --publish) publish=(--publish) ;;
    --status) status_only=1 ;;
    --out) [ $# -ge 2 ] && [ -n "$2" ] || { echo "reproduce.sh: --out needs a directory" >&2; exit 2; }; out="$2"; shift ;;
    --out=*) out="${1#--out=}"; [ -n "$out" ] || { echo "reproduce.sh: --out needs a directory" >&2; exit 2; } ;;
    --jobs) [ $# -ge 2 ] || { echo "reproduce.sh: --jobs needs a number" >&2; exit 2; }; jobs="$2"; shift ;;
    --jobs=*) jobs="${1#--jobs=}" ;;
    -*) echo "reproduce.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) studies+=("$1") ;;
  esac
  shift
done
if [ "${status_only:-0}" = 1 ]; then
  # The published results are current when the code that decides them is
  # HEAD's: every commit REPRODUCTION.md names (its "Code: commit" and the
  # commit of each study run on its own) has the same geometry/, rs/,
  # planning/ and optimize/ as HEAD.
  rep="$root/paper_figures/REPRODUCTION.md"
  made=$(grep -o 'commit `[^`]*`' "$rep" 2>/dev/null | sed 's/.*`\(.*\)`/\1/' | awk '!seen[$0]++')
  if [ -z "$made" ]; then echo "reproduce.sh: stale: paper_figures/REPRODUCTION.md names no commit"; exit 1; fi
  stale=()
  for c in $made; do
    case "$c" in *-dirty) echo "reproduce.sh: stale: published from a tree with uncommitted changes ($c)"; exit 1 ;; esac
    if ! git -C "$root" cat-file -e "$c^{commit}" 2>/dev/null; then
      echo "reproduce.sh: stale: commit $c is not in this repository"; exit 1
    fi
    changed=$(git -C "$root" diff --name-only "$c" HEAD -- geometry rs planning optimize | wc -l)
    [ "$changed" = 0 ] || stale+=("$c ($changed file(s) changed since)")
  done
  # The zoo studies also depend on the rooms the generator draws.
  zoo_made=$({ grep -o 'The `\(generalization\|tradeoff\)` study at commit `[^`]*`' "$rep" || true; } |
             sed 's/.*`\(.*\)`$/\1/' | awk '!seen[$0]++')
  for c in $zoo_made; do
    changed=$(git -C "$root" diff --name-only "$c" HEAD -- experiments/room_zoo.h experiments/room_zoo.cpp \
              experiments/room_zoo_plant.cpp experiments/studies_generalization.cpp | wc -l)
    [ "$changed" = 0 ] || stale+=("$c (the room zoo: $changed file(s) changed since)")
  done
  if [ ${#stale[@]} = 0 ]; then
    echo "reproduce.sh: current: paper_figures/ was made at $(echo $made | tr ' ' ','); geometry/, rs/, planning/ and optimize/ are unchanged since${zoo_made:+, and the room zoo since the commits of the zoo studies}"
    exit 0
  fi
  echo "reproduce.sh: stale: results made at ${stale[*]} under geometry/, rs/, planning/, optimize/ or the room zoo (REPRODUCTION.md names which studies; run scripts/reproduce.sh --jobs 2 --publish, or --publish generalization tradeoff for the zoo's)"
  exit 1
fi
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "reproduce.sh: --jobs '$jobs': expected a whole number >= 1" >&2; exit 2; }
[ ${#studies[@]} -gt 0 ] || studies=(all)
only=()
if [ ${#publish[@]} -gt 0 ]; then
  [ ${#quick[@]} = 0 ] || { echo "reproduce.sh: --quick with --publish: a smoke run is never published" >&2; exit 2; }
  if [ "${studies[*]}" != all ]; then
    for s in "${studies[@]}"; do
      case "$s" in
        generalization|tradeoff) only+=(--only "$s") ;;
        *) echo "reproduce.sh: --publish $s: a study of the paper is published by the full run (no STUDY); alone, only generalization and tradeoff" >&2; exit 2 ;;
      esac
    done
  fi
fi
if [ -z "$out" ]; then
  # A smoke run never shares its default root with the full run.
  if [ ${#quick[@]} -gt 0 ]; then out="$root/out/reproduce-quick"; else out="$root/out/reproduce"; fi
fi

if [ -n "${HRSPACE_BIN:-}" ]; then
  bin="$HRSPACE_BIN"
else
  "$root/scripts/build.sh" hrspace
  bin="$root/build/cli/hrspace"
fi
python=/usr/bin/python3
"$python" -c "import matplotlib" 2>/dev/null || "$root/scripts/setup.sh"

commit="$(git -C "$root" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null)" ]; then commit="$commit-dirty"; fi
export HRSPACE_COMMIT="$commit"

start=$(date +%s)
command="scripts/reproduce.sh${quick:+ ${quick[*]}} --jobs $jobs${studies:+ ${studies[*]}}"
status=0
for s in "${studies[@]}"; do
  "$bin" experiment "$s" --out "$out" --jobs "$jobs" "${quick[@]}" || { status=$?; break; }
done
# A study that failed or was stopped leaves its runs incomplete: the figures
# of what is stored are drawn for a look, and nothing is published.
if [ "$status" != 0 ] && [ ${#publish[@]} -gt 0 ]; then
  echo "reproduce.sh: study '$s' did not finish (exit $status): nothing is published; the figures of the runs stored so far are in $out/figures" >&2
  publish=()
  only=()
fi
"$python" "$root/paper_figures/plot.py" "$out" --command "$command" "${publish[@]}" "${only[@]}"
end=$(date +%s)
echo "reproduce.sh: $((end - start)) s wall time on $(nproc) cores; outputs in $out"
exit $status
