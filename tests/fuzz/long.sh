#!/usr/bin/env bash
# A long fuzz session of one target that keeps going past findings (docs/reliability.md):
# libFuzzer's fork mode with one worker; every crashing, timing-out or memory-hungry input is kept.
# Usage: tests/fuzz/long.sh BUILD_DIR TARGET SECONDS OUT_DIR [MORE LIBFUZZER FLAGS]
#   OUT_DIR/corpus grows (seeded from tests/fuzz/corpus/TARGET), OUT_DIR/crash-*, timeout-*, oom-*
#   are the findings, OUT_DIR/log.txt the run's log.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build=$1 target=$2 seconds=$3 out=$4
shift 4
mkdir -p "$out/corpus"
[ -n "$(ls -A "$out/corpus")" ] || cp -R "$here/corpus/$target/." "$out/corpus/"
args=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 -max_total_time="$seconds"
      -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 -artifact_prefix="$out/"
      -print_final_stats=1)
[ -f "$here/dict/$target.dict" ] && args+=(-dict="$here/dict/$target.dict")
"$build/tests/fuzz/fuzz_$target" "${args[@]}" "$@" "$out/corpus" 2>&1 | tee "$out/log.txt"
