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
"$build/tests/fuzz/fuzz_$target" "${args[@]}" "$@" "$out/corpus" > >(tee "$out/log.txt") 2>&1 &
fuzzer=$!

# libFuzzer's timeout handler allocates; when the alarm comes inside ASan's allocator the worker
# deadlocks (0% CPU, forever). A worker whose CPU time stands still for 30 s is ended, so the
# session goes on; each such end is counted in OUT_DIR/hung.txt.
declare -A last still
while kill -0 "$fuzzer" 2>/dev/null; do
  sleep 10
  kids=$(pgrep -d, -P "$fuzzer" || echo 0)
  for pid in $(pgrep -P "$kids" || true) ${kids//,/ }; do
    # Only a worker, and not while it waits for its symbolizer (a child of its own).
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "fuzz_$target" ] || continue
    pgrep -P "$pid" >/dev/null && continue
    cpu=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null || echo "")
    [ -n "$cpu" ] || continue
    if [ "${last[$pid]:-}" = "$cpu" ]; then still[$pid]=$(( ${still[$pid]:-0} + 1 )); else still[$pid]=0; fi
    last[$pid]=$cpu
    if [ "${still[$pid]}" -ge 3 ]; then
      echo "$(date +%T) worker $pid stood still for 30 s: ended" >> "$out/hung.txt"
      kill -9 "$pid" 2>/dev/null || true
    fi
  done
done
wait "$fuzzer"
