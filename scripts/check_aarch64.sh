#!/usr/bin/env bash
# Compiles the whole core (algorithms/) for ARM64 with Debian's cross compiler: syntax and code
# generation, nothing is linked or run. A student's ARM64 laptop must build raystep, so no x86
# intrinsic may leave base/simd.h, where each has a portable twin.
# Usage: scripts/check_aarch64.sh [OUTDIR]   (needs g++-aarch64-linux-gnu; test.sh installs it)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
OUT="${1:-$(mktemp -d)}"
CXX=aarch64-linux-gnu-g++
command -v "$CXX" >/dev/null || { echo "check_aarch64: $CXX not found (apt install g++-aarch64-linux-gnu)" >&2; exit 2; }
# The third-party headers the core uses, and only those: the host's /usr/include as a whole would
# put x86's C library headers before the cross compiler's own.
INC="$OUT/include"
mkdir -p "$INC"
for h in glm nlohmann boost tbb oneapi stb tiny_obj_loader.h assimp; do
  [ -e "/usr/include/$h" ] || { echo "check_aarch64: /usr/include/$h missing" >&2; exit 2; }
  ln -sfn "/usr/include/$h" "$INC/$h"
done
mapfile -t SOURCES < <(cd "$ROOT" && find algorithms -name '*.cpp' | sort)
status=0
printf '%s\n' "${SOURCES[@]}" | xargs -P "$(nproc)" -I{} sh -c \
  '"$0" -std=c++20 -O2 -Wall -Wextra -Wpedantic -Werror -Wno-psabi -march=armv8-a -I"$1/algorithms" -isystem "$2" \
     -c "$1/{}" -o "$3/$(echo {} | tr / _).o" || { echo "check_aarch64: {} does not compile for ARM64" >&2; exit 255; }' \
  "$CXX" "$ROOT" "$INC" "$OUT" || status=$?
if [ "$status" -ne 0 ]; then exit 1; fi
# Every object is ARM64 code: the check compiled what it claims.
for o in "$OUT"/*.o; do
  aarch64-linux-gnu-readelf -h "$o" | grep -q "Machine:.*AArch64" ||
    { echo "check_aarch64: $o is not ARM64 code" >&2; exit 1; }
done
echo "check_aarch64: ${#SOURCES[@]} core sources compile for ARM64 ($(aarch64-linux-gnu-g++ -dumpversion))"
