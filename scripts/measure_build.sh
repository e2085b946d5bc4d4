#!/usr/bin/env bash
# Re-measures the build and recording figures of docs/performance.md and plots build time
# against N (docs/images/build-scaling.png). About 1 minute (the 1M-triangle kd-tree dominates).
set -euo pipefail
RAYSTEP_ROOT="$(cd "$(dirname "$0")/.." && pwd)"
source "$RAYSTEP_ROOT/scripts/deps.sh"
ensure_packages "${RAYSTEP_BUILD_PACKAGES[@]}" "${RAYSTEP_TEST_PACKAGES[@]}" "${RAYSTEP_GUI_PACKAGES[@]}" \
  python3-matplotlib
configure "$RAYSTEP_ROOT/build"
build "$RAYSTEP_ROOT/build" raystep_bench_build raystep_bench_embree
mkdir -p "$RAYSTEP_ROOT/docs/data" "$RAYSTEP_ROOT/docs/images"
"$RAYSTEP_ROOT/build/bench/raystep_bench_build" \
  --benchmark_out="$RAYSTEP_ROOT/docs/data/build_bench.json" --benchmark_out_format=json
"$RAYSTEP_ROOT/build/bench/raystep_bench_embree" \
  --benchmark_out="$RAYSTEP_ROOT/docs/data/embree_bench.json" --benchmark_out_format=json
/usr/bin/python3 "$RAYSTEP_ROOT/scripts/plot_build.py"
