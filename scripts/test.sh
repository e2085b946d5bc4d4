#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test through ctest:
# first the Release build (core, CLI and the app under Xvfb), then the core's and the CLI's tests
# again under AddressSanitizer + UBSan.
set -euo pipefail
RAYSTEP_ROOT="$(cd "$(dirname "$0")/.." && pwd)"
source "$RAYSTEP_ROOT/scripts/deps.sh"

ensure_packages "${RAYSTEP_BUILD_PACKAGES[@]}" "${RAYSTEP_TEST_PACKAGES[@]}" "${RAYSTEP_GUI_PACKAGES[@]}"

echo "== Release build and tests"
configure "$RAYSTEP_ROOT/build"
build "$RAYSTEP_ROOT/build"
ctest --test-dir "$RAYSTEP_ROOT/build" --output-on-failure -j2

echo "== Core tests under AddressSanitizer + UndefinedBehaviorSanitizer"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The app is left out here: Qt's and VTK's own allocations would drown the report.
configure "$RAYSTEP_ROOT/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRAYSTEP_SANITIZE=ON \
  -DRAYSTEP_BUILD_GUI=OFF
build "$RAYSTEP_ROOT/build-asan"
ctest --test-dir "$RAYSTEP_ROOT/build-asan" --output-on-failure -j2 -L 'core|cli'
