#!/usr/bin/env bash
# Installs what is missing, builds, and shows raystep: the default scene rendered to a PNG.
set -euo pipefail
RAYSTEP_ROOT="$(cd "$(dirname "$0")/.." && pwd)"
source "$RAYSTEP_ROOT/scripts/deps.sh"

# One build folder serves both scripts, and configuring it needs the test libraries too.
ensure_packages "${RAYSTEP_BUILD_PACKAGES[@]}" "${RAYSTEP_TEST_PACKAGES[@]}"
configure "$RAYSTEP_ROOT/build"
build "$RAYSTEP_ROOT/build" raystep-cli

# The replay GUI is not built yet (issue 5): until it is, and whenever there is no display,
# render the default scene with the command-line tool.
mkdir -p "$RAYSTEP_ROOT/out"
png="$RAYSTEP_ROOT/out/default.png"
"$RAYSTEP_ROOT/build/app/cli/raystep-cli" render default -o "$png" --stats "$RAYSTEP_ROOT/out/default-stats.json" "$@"
echo "raystep: rendered the default scene to $png"
