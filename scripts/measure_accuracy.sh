#!/usr/bin/env bash
# Re-measures docs/accuracy.md: kernel speeds, accuracy figures, plots. About 5 minutes.
set -euo pipefail
RAYSTEP_ROOT="$(cd "$(dirname "$0")/.." && pwd)"
source "$RAYSTEP_ROOT/scripts/deps.sh"
ensure_packages "${RAYSTEP_BUILD_PACKAGES[@]}" "${RAYSTEP_TEST_PACKAGES[@]}" "${RAYSTEP_GUI_PACKAGES[@]}" \
  python3-matplotlib
configure "$RAYSTEP_ROOT/build"
build "$RAYSTEP_ROOT/build" raystep_bench_kernels raystep_accuracy
mkdir -p "$RAYSTEP_ROOT/docs/data" "$RAYSTEP_ROOT/docs/images"
"$RAYSTEP_ROOT/build/bench/raystep_bench_kernels" --benchmark_min_time=1 \
  --benchmark_out="$RAYSTEP_ROOT/docs/data/kernels_bench.json" --benchmark_out_format=json
"$RAYSTEP_ROOT/build/bench/raystep_accuracy" --out "$RAYSTEP_ROOT/docs/data/accuracy.json" \
  --images "$RAYSTEP_ROOT/docs/images"
# Debian's interpreter: python3-matplotlib is installed for it, whatever python3 is first on PATH.
/usr/bin/python3 "$RAYSTEP_ROOT/scripts/plot_accuracy.py"
