#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test through ctest:
# first the Release build (core, course, CLI and the app under Xvfb), then a clang build of the
# core's, the course's and the CLI's tests under AddressSanitizer + UBSan, with a short run of each
# fuzz target (docs/reliability.md).
set -euo pipefail
RAYSTEP_ROOT="$(cd "$(dirname "$0")/.." && pwd)"
source "$RAYSTEP_ROOT/scripts/deps.sh"

ensure_packages "${RAYSTEP_BUILD_PACKAGES[@]}" "${RAYSTEP_TEST_PACKAGES[@]}" \
  "${RAYSTEP_GUI_PACKAGES[@]}" "${RAYSTEP_SANITIZER_PACKAGES[@]}"

echo "== Release build and tests"
configure "$RAYSTEP_ROOT/build"
build "$RAYSTEP_ROOT/build"
ctest --test-dir "$RAYSTEP_ROOT/build" --output-on-failure -j2

echo "== Core and CLI tests under AddressSanitizer + UndefinedBehaviorSanitizer (clang), fuzz smoke runs"
symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:external_symbolizer_path=$symbolizer
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:external_symbolizer_path=$symbolizer
# assimp's own leaks on its error paths are suppressed (tests/fuzz/lsan.supp); the model
# importer's process shows its stderr here, so a report inside it is seen, not only its end.
export LSAN_OPTIONS=suppressions=$RAYSTEP_ROOT/tests/fuzz/lsan.supp:print_suppressions=0
export RAYSTEP_IMPORTER_STDERR=1
asan="$RAYSTEP_ROOT/build-asan"
# A build folder made by an earlier test.sh with GCC: the compiler of a build folder is fixed.
if [ -f "$asan/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++-14$' "$asan/CMakeCache.txt"; then
  rm -rf "$asan"
fi
# The app is left out here: Qt's and VTK's own allocations would drown the report.
CC=clang-14 CXX=clang++-14 configure "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DRAYSTEP_SANITIZE=ON -DRAYSTEP_BUILD_GUI=OFF -DRAYSTEP_FUZZ=ON
build "$asan"
ctest --test-dir "$asan" --output-on-failure -j2 -L 'core|course|cli|fuzz'
