#!/usr/bin/env bash
# Installs what is missing, builds, and opens raystep, the replay app, on its default lesson
# (the slides' 2D grid and DDA example). Without a display it renders the default scene to a PNG
# with the command-line tool and says where it is. Arguments go to the app (or to
# `raystep-cli render` without a display).
set -euo pipefail
RAYSTEP_ROOT="$(cd "$(dirname "$0")/.." && pwd)"
source "$RAYSTEP_ROOT/scripts/deps.sh"

# One build folder serves both scripts, and configuring it needs every library the tests use.
ensure_packages "${RAYSTEP_BUILD_PACKAGES[@]}" "${RAYSTEP_TEST_PACKAGES[@]}" "${RAYSTEP_GUI_PACKAGES[@]}"
configure "$RAYSTEP_ROOT/build"
build "$RAYSTEP_ROOT/build" raystep-cli raystep

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  echo "raystep: opening the replay app on lesson 1 (Lessons menu: all 13)"
  exec "$RAYSTEP_ROOT/build/app/gui/raystep" "$@"
fi

mkdir -p "$RAYSTEP_ROOT/out"
png="$RAYSTEP_ROOT/out/default.png"
"$RAYSTEP_ROOT/build/app/cli/raystep-cli" render default -o "$png" --stats "$RAYSTEP_ROOT/out/default-stats.json" "$@"
echo "raystep: no display, so the default scene was rendered instead: $png"
echo "raystep: (with a display, ./scripts/run.sh opens the app; for a picture of the app without one:"
echo "          xvfb-run -a build/app/gui/raystep --screenshot out/raystep.png)"
