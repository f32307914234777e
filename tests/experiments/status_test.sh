#!/usr/bin/env bash
# scripts/reproduce.sh --status in a scratch repository: "current" while
# geometry/, rs/, planning/ and optimize/ equal those of the commit that
# REPRODUCTION.md names, "stale" after a change there, "current" again for
# changes elsewhere; a study run on its own at a commit whose code differs
# from HEAD's makes it stale; the zoo studies' commits are also stale after a
# change to the room generator; a dirty or unknown commit is stale.
# Usage: status_test.sh SOURCE_DIR
set -u
src="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
expect() {  # expect NAME STATUS PATTERN
  local out; out=$("$tmp/r/scripts/reproduce.sh" --status 2>&1); local got=$?
  if [ "$got" != "$2" ] || ! grep -q -- "$3" <<<"$out"; then
    echo "FAIL $1: exit $got, '$out'"; fails=$((fails + 1))
  else
    echo "ok   $1"
  fi
}
cd "$tmp" && git init -q r && cd r || exit 1
git config user.email t@example.org; git config user.name test
mkdir -p scripts paper_figures geometry optimize docs
cp "$src/scripts/reproduce.sh" scripts/
echo a >geometry/a.cpp; echo b >optimize/b.cpp; echo d >docs/d.md
git add -A && git commit -qm base
made=$(git rev-parse --short=12 HEAD)
printf 'Command: x. Code: commit `%s`; machine: y.\n' "$made" >paper_figures/REPRODUCTION.md
git add -A && git commit -qm publish
expect "published at an ancestor with the same code" 0 "current: paper_figures/ was made at $made"
echo more >>docs/d.md && git commit -qam docs
expect "a change outside the code keeps it current" 0 "current"
old=$made
echo more >>optimize/b.cpp && git commit -qam code
expect "a change under optimize/ makes it stale" 1 "stale: results made at $old (1 file(s) changed since)"
made=$(git rev-parse --short=12 HEAD)
printf 'Code: commit `%s`.\nThe `zoo` study at commit `%s`: ...\n' "$made" "$old" >paper_figures/REPRODUCTION.md
git add -A && git commit -qm republish
expect "a study made alone at older code is stale" 1 "stale: results made at $old (1 file(s)"
printf 'Code: commit `%s`.\nThe `zoo` study at commit `%s`: ...\n' "$made" "$made" >paper_figures/REPRODUCTION.md
git add -A && git commit -qm republish2
expect "every named commit current" 0 "current: paper_figures/ was made at $made;"
# The zoo studies: a change to the room generator makes their commit stale,
# another change under experiments/ does not.
mkdir -p experiments
echo z >experiments/room_zoo.cpp; echo h >experiments/harness.cpp
git add -A && git commit -qm zoo
made=$(git rev-parse --short=12 HEAD)
printf 'Code: commit `%s`.\nThe `generalization` study at commit `%s` (machine: m): ...\n' "$made" "$made" \
  >paper_figures/REPRODUCTION.md
git add -A && git commit -qm republish3
echo more >>experiments/harness.cpp && git commit -qam harness
expect "a change under experiments/ outside the zoo keeps it current" 0 "current"
echo more >>experiments/room_zoo.cpp && git commit -qam generator
expect "a change to the room zoo makes the zoo study stale" 1 "stale: results made at $made (the room zoo: 1 file(s) changed since)"
printf 'Code: commit `%s`.\n' "$made" >paper_figures/REPRODUCTION.md
git add -A && git commit -qm republish4
expect "without a zoo study the generator does not matter" 0 "current"
printf 'Code: commit `%s-dirty`;\n' "$made" >paper_figures/REPRODUCTION.md
expect "a dirty tree is stale" 1 "uncommitted changes"
printf 'Code: commit `0123456789ab`;\n' >paper_figures/REPRODUCTION.md
expect "an unknown commit is stale" 1 "not in this repository"
echo "$fails failure(s)"
[ "$fails" = 0 ]
