#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Compares the geometry kernel's answers at two revisions, bit for bit (docs/verifying-refactors.md).
#
#   bash scripts/compare-answers.sh [--keep] [REV_A [REV_B]]
#
# For each revision: a throwaway git worktree under a temporary directory, its library alone built
# (Release, two jobs; tests, benchmarks, apps and dynamics off) and installed into a scratch
# prefix, then dump_answers built against that installed library and run. The two dumps (192,000
# lines, every field of every answer in %a) are compared line by line.
#
# REV_A, REV_B: anything `git rev-parse` accepts, or WORKTREE: this checkout's working tree, its
# tracked files as they are now, staged or not (untracked files are left out; `git add` them).
# Defaults: REV_B = WORKTREE, REV_A = HEAD when tracked files have uncommitted changes and HEAD~1
# otherwise. So with no arguments it checks the last change, committed or not.
#
# The dump tool is the one in this checkout (bench/geometry: dump_answers.cpp, answer_text.*,
# answer_families.*, dump_answers.cmake; bench/common), as it is now, for both revisions, whether
# or not they have a dump_answers of their own: both sides print the same inputs in the same
# format, and only the library differs. It uses the public API only, so it builds against any
# revision whose public headers still declare what it prints; where they do not, the build of the
# tool fails and says so.
#
# Prints "identical: N lines" and exits 0, or the number of differing lines (per family) and the
# first differing pairs, and exits 1. Exits 2 on an error (bad arguments, unknown revision, a build
# or a dump that failed). --keep keeps the temporary directory (dumps, builds, logs) and prints
# its path. JOBS (default 2) sets the build jobs; TMPDIR where the temporary directory goes.
set -Eeuo pipefail

usage() { sed -n '2,/^set -E/p' "$0" | sed -e '$d' -e 's/^# \{0,1\}//'; }
die() { echo "compare-answers: $*" >&2; exit 2; }
trap 'die "failed at line $LINENO: $BASH_COMMAND"' ERR

keep=false
revisions=()
for argument in "$@"; do
  case $argument in
    -h | --help) usage; exit 0 ;;
    --keep) keep=true ;;
    -*) die "unknown option '$argument' (see --help)" ;;
    *) revisions+=("$argument") ;;
  esac
done
((${#revisions[@]} <= 2)) || die "at most two revisions, got ${#revisions[@]}: ${revisions[*]} (see --help)"
jobs=${JOBS:-2}
[[ $jobs =~ ^[1-9][0-9]*$ ]] || die "JOBS must be a positive whole number, got '$jobs'"

checkout=$(cd "$(dirname "$0")/.." && pwd)
git -C "$checkout" rev-parse --git-dir >/dev/null 2>&1 || die "$checkout is not a git checkout"
for tool_file in bench/geometry/dump_answers.cmake bench/common/uniform_source.hpp; do
  [[ -f $checkout/$tool_file ]] || die "the dump tool is missing from this checkout: $tool_file"
done

# WORKTREE as a commit: `git stash create` writes the working tree's tracked files into a commit
# object without touching the working tree, the index or the stash list; it prints nothing when
# there is nothing uncommitted, and HEAD is then the working tree.
worktree_has_changes() { ! git -C "$checkout" diff --quiet HEAD --; }
resolve() {
  local rev=$1 commit
  if [[ $rev == WORKTREE ]]; then
    commit=$(git -C "$checkout" stash create)
    [[ -n $commit ]] || commit=$(git -C "$checkout" rev-parse HEAD)
  else
    commit=$(git -C "$checkout" rev-parse --verify --quiet "$rev^{commit}") ||
      die "unknown revision '$rev'"
  fi
  echo "$commit"
}

if ((${#revisions[@]} == 0)); then
  if worktree_has_changes; then revisions=(HEAD); else revisions=(HEAD~1); fi
fi
((${#revisions[@]} == 2)) || revisions+=(WORKTREE)
rev_a=${revisions[0]} rev_b=${revisions[1]}
# (|| exit: resolve has said what went wrong in its subshell already.)
commit_a=$(resolve "$rev_a") || exit 2
commit_b=$(resolve "$rev_b") || exit 2
untracked=$(git -C "$checkout" ls-files --others --exclude-standard | wc -l)
if [[ $rev_a == WORKTREE || $rev_b == WORKTREE ]] && ((untracked > 0)); then
  echo "compare-answers: note: $untracked untracked files are not part of WORKTREE" >&2
fi
head=$(git -C "$checkout" rev-parse HEAD)
[[ $rev_a != WORKTREE || $commit_a != "$head" ]] || rev_a="WORKTREE = HEAD"
[[ $rev_b != WORKTREE || $commit_b != "$head" ]] || rev_b="WORKTREE = HEAD"

scratch=$(mktemp -d "${TMPDIR:-/tmp}/compare-answers.XXXXXX")
worktrees=()
# shellcheck disable=SC2317  # run by the EXIT trap
cleanup() {
  local status=$?
  for tree in "${worktrees[@]}"; do git -C "$checkout" worktree remove --force "$tree" >/dev/null 2>&1 || true; done
  if $keep; then echo "compare-answers: kept $scratch" >&2; else rm -rf "$scratch"; fi
  exit "$status"
}
trap cleanup EXIT
trap 'die "interrupted"' INT TERM

# The tool's sources, copied once so that both sides build the same snapshot.
mkdir -p "$scratch/tool/bench"
cp -r "$checkout/bench/geometry" "$checkout/bench/common" "$scratch/tool/bench/"
cat >"$scratch/tool/CMakeLists.txt" <<'EOF'
# dump_answers against an installed clearjoint (CMAKE_PREFIX_PATH), from scripts/compare-answers.sh.
cmake_minimum_required(VERSION 3.20)
project(clearjoint_dump_answers LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
find_package(clearjoint REQUIRED)
include(${CMAKE_CURRENT_SOURCE_DIR}/bench/geometry/dump_answers.cmake)
EOF

# run LOG COMMAND...: the command's output goes to LOG; on failure its tail is shown.
run() {
  local log=$1
  shift
  if ! "$@" >>"$log" 2>&1; then
    tail -n 25 "$log" >&2
    die "'$*' failed (whole log: $log; --keep keeps it)"
  fi
}

# dump SIDE REV COMMIT: builds and runs dump_answers for one revision into $scratch/SIDE.txt.
dump() {
  local side=$1 rev=$2 commit=$3 start=$SECONDS
  local dir=$scratch/$side log=$scratch/$side.log
  mkdir -p "$dir"
  echo "compare-answers: $side = $rev (${commit:0:10}): building the library and dump_answers" >&2
  run "$log" git -C "$checkout" worktree add --detach "$dir/src" "$commit"
  worktrees+=("$dir/src")
  run "$log" cmake -S "$dir/src" -B "$dir/build" -DCMAKE_BUILD_TYPE=Release \
    -DCLEARJOINT_BUILD_TESTS=OFF -DCLEARJOINT_BUILD_BENCHMARKS=OFF \
    -DCLEARJOINT_BUILD_APPS=OFF -DCLEARJOINT_BUILD_DYNAMICS=OFF
  run "$log" cmake --build "$dir/build" -j "$jobs"
  run "$log" cmake --install "$dir/build" --prefix "$dir/prefix"
  run "$log" cmake -S "$scratch/tool" -B "$dir/tool-build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$dir/prefix"
  run "$log" cmake --build "$dir/tool-build" -j "$jobs" --target dump_answers
  local tool=$dir/tool-build/dump_answers
  # The library the tool loads must be this revision's, found through the build RPATH.
  local libraries
  libraries=$(ldd "$tool")
  grep -q "libclearjoint_geometry[^ ]* => $dir/prefix/" <<<"$libraries" ||
    die "$side's dump_answers does not load the library built here: $(grep clearjoint <<<"$libraries")"
  "$tool" >"$scratch/$side.txt" 2>>"$log" || die "$side's dump_answers failed (log: $log)"
  echo "compare-answers: $side: $(wc -l <"$scratch/$side.txt") lines in $((SECONDS - start)) s" >&2
}

start=$SECONDS
dump A "$rev_a" "$commit_a"
dump B "$rev_b" "$commit_b"
echo "A = $rev_a (${commit_a:0:10}), B = $rev_b (${commit_b:0:10}); $((SECONDS - start)) s"

lines_a=$(wc -l <"$scratch/A.txt")
lines_b=$(wc -l <"$scratch/B.txt")
if cmp -s "$scratch/A.txt" "$scratch/B.txt"; then
  echo "identical: $lines_a lines"
  exit 0
fi

# Line by line (paste pads the shorter dump with empty lines): the count per family, then the
# first pairs with the fields that differ (numbered from 1, the family name being field 1).
paste -d '\n' "$scratch/A.txt" "$scratch/B.txt" | awk -v shown=5 -v lines_a="$lines_a" -v lines_b="$lines_b" '
  NR % 2 == 1 { a = $0; next }
  a != $0 {
    differing++
    family = a != "" ? a : $0
    sub(/ .*/, "", family)
    if (!(family in per_family)) order[++families] = family
    per_family[family]++
    if (differing <= shown) {
      n = split(a, fa, " "); m = split($0, fb, " ")
      fields = ""; listed = 0
      for (i = 1; i <= (n > m ? n : m); i++) {
        if (fa[i] == fb[i]) continue
        if (++listed <= 4) fields = fields sprintf("\n    field %d: %s -> %s", i, fa[i], fb[i])
      }
      if (listed > 4) fields = fields sprintf("\n    and %d more fields", listed - 4)
      pairs = pairs sprintf("line %d, %d field%s:%s\n  A: %s\n  B: %s\n", NR / 2, listed,
                            listed == 1 ? " differs" : "s differ", fields, a, $0)
    }
  }
  END {
    printf "differ: %d of %d lines", differing, NR / 2
    if (lines_a != lines_b) printf " (A has %d lines, B %d)", lines_a, lines_b
    printf "\n"
    for (i = 1; i <= families; i++) printf "  %-20s %d\n", order[i], per_family[order[i]]
    printf "first %d differing pairs:\n%s", (differing < shown ? differing : shown), pairs
  }'
exit 1
