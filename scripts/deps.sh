#!/usr/bin/env bash
# Installs the Debian 12 packages raystep needs; sourced by run.sh and test.sh.
# Every package the build or the tests use is listed here, so a fresh machine needs nothing by hand.

RAYSTEP_BUILD_PACKAGES=(
  build-essential cmake pkg-config
  libglm-dev nlohmann-json3-dev libcli11-dev libtbb-dev libtinyobjloader-dev libstb-dev libboost-dev
  libassimp-dev  # models (.obj .ply .stl .gltf .glb): raystep_import
)
# The replay app: Qt6 widgets, Qt's own Italian for its dialogs (qtbase_it), VTK (its config needs
# MPI's C target: mpi-default-dev comes with it), and what runs it without a screen (xvfb-run) with
# Mesa's software OpenGL.
RAYSTEP_GUI_PACKAGES=(
  qt6-base-dev qt6-translations-l10n libvtk9-dev xvfb xauth libgl1-mesa-dri
)
RAYSTEP_TEST_PACKAGES=(
  googletest libgtest-dev libbenchmark-dev libembree-dev
  python3  # tests/practice: the generators' answers recomputed by an independent reader
  g++-aarch64-linux-gnu  # scripts/check_aarch64.sh: the core compiles for ARM64
  glmark2-data  # the Stanford bunny (models/bunny.obj, 69,666 triangles) of the model tests
)
# test.sh's second build: clang 14 with its sanitizer and libFuzzer runtimes, and llvm-14 for
# llvm-symbolizer (readable stacks in sanitizer reports).
RAYSTEP_SANITIZER_PACKAGES=(
  clang-14 libclang-rt-14-dev llvm-14
)

# ensure_packages PKG...: install those that are not installed yet (apt-get, as root or through sudo).
ensure_packages() {
  local missing=()
  local p
  for p in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then sudo="sudo"; else
      echo "raystep: missing packages (${missing[*]}) and not root: install them as root first" >&2
      return 1
    fi
  fi
  echo "raystep: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# configure DIR [CMAKE ARGS...]: configure (Release unless told otherwise); quiet after the first time.
configure() {
  local dir="$1"; shift
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S "$RAYSTEP_ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@"
  else
    cmake -S "$RAYSTEP_ROOT" -B "$dir" "$@" >/dev/null
  fi
}

# build DIR [TARGET...]: incremental build with -j2 (all targets when none is named).
build() {
  local dir="$1"; shift
  local targets=()
  local t
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build "$dir" -j2 "${targets[@]}"
}
