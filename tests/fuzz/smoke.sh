#!/usr/bin/env bash
# A bounded run of one fuzz target, for ctest: the committed seed corpus is copied to a temporary
# folder (libFuzzer adds to its corpus folder; the repository is not touched), the target runs for
# SECONDS, and a finding (crash, sanitizer report, timeout, memory) fails the test, its input kept
# in FINDINGS.
# Usage: smoke.sh TARGET CORPUS DICT|"" FINDINGS SECONDS
set -euo pipefail
target=$1 corpus=$2 dict=$3 findings=$4 seconds=$5
# assimp's own leaks (review 3, class 18) are not findings; raystep's still are.
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$(dirname "$0")/lsan.supp:print_suppressions=0}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -R "$corpus/." "$work/"
mkdir -p "$findings"
args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048
      -artifact_prefix="$findings/" -print_final_stats=1)
[ -n "$dict" ] && args+=(-dict="$dict")
"$target" "${args[@]}" "$work"
