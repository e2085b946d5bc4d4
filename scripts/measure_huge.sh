#!/usr/bin/env bash
# Brute force on a huge model, measured (docs/reliability.md, "Background work in the app"):
# makes a 1.2 M-triangle OBJ (a 775 x 775 grid of quads, two triangles each), then runs the
# GUI test RobustModels.DISABLED_BruteForceOnAHugeModel on it under Xvfb, which prints how long
# the window was away, the app's memory, the replay's size and how long Cancel took; and the
# CLI's import of the same model (time and peak memory of raystep-cli and its importer).
# Not part of ctest: the model alone is 45 MB and its kd-tree takes seconds.
# Usage: scripts/measure_huge.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
model="$work/huge-1m.obj"
awk -v n=775 'BEGIN {
  for (j = 0; j <= n; ++j) for (i = 0; i <= n; ++i)
    printf "v %g %g %g\n", i / n, 0.1 * sin(i * 0.05) * cos(j * 0.05), j / n
  for (j = 0; j < n; ++j) for (i = 0; i < n; ++i) {
    a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 1; d = c + 1
    printf "f %d %d %d\nf %d %d %d\n", a, b, d, a, d, c
  }
}' > "$model"
echo "model: $(grep -c '^f' "$model") triangles, $(du -h "$model" | cut -f1)"
echo "== raystep-cli build (import only, brute force: nothing to build)"
/usr/bin/time -f "%e s, peak %M KB (raystep-cli or its importer, the larger)" \
  "$build/app/cli/raystep-cli" build "$model" --accel bruteforce | head -1
echo "== the app: open (kd-tree), pick brute force, its first pixel, Cancel"
HOME="$work/home" RAYSTEP_HUGE_MODEL="$model" xvfb-run -a -s "-screen 0 1920x1080x24" \
  "$build/tests/gui/raystep_gui_tests" --gtest_also_run_disabled_tests \
  --gtest_filter='RobustModels.DISABLED_BruteForceOnAHugeModel' 2>&1 |
  grep -E '^(open|asked|not asked|brute force|first pixel|Cancel)|OK|FAILED' || true
