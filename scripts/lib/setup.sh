# Shared set-up for scripts/run and scripts/test (sourced, not executed):
# install what is missing on Debian/Ubuntu, then configure and build.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD_DIR="${FUNCTIONLAB_BUILD_DIR:-$ROOT/build}"

# Debian 12 package names. Qt, GLM, hidapi, libusb and SQLite are for the
# viewer, haptics and grading parts; muParser is a benchmark peer only.
# Installed with --no-install-recommends, so every package CMake needs is
# named here even where another package only recommends it (libqt6opengl6-dev:
# Qt6 3DRender needs Qt6OpenGL, a mere Recommends of qt6-base-dev).
# scripts/check-fresh-machine proves this list on a clean Debian 12 root.
PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git
  libgtest-dev libgmock-dev libbenchmark-dev libmuparser-dev
  libsleef-dev libglm-dev libeigen3-dev libsqlite3-dev libhidapi-dev libusb-1.0-0-dev
  qt6-base-dev libqt6opengl6-dev qt6-3d-dev qt6-websockets-dev zlib1g-dev
  xvfb xauth libgl1-mesa-dri fonts-dejavu-core
)
# Only for scripts/fuzz (libFuzzer); skipped with a warning where the
# distribution names them differently.
OPTIONAL_PACKAGES=(clang libclang-rt-14-dev)

log() { printf '\033[1m==> %s\033[0m\n' "$*" >&2; }

install_missing_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    log "not a Debian/Ubuntu system: install the equivalents of: ${PACKAGES[*]}"
    return 0
  fi
  local missing=() optional=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  for p in "${OPTIONAL_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || optional+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && [ ${#optional[@]} -eq 0 ] && return 0
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || { log "need root or sudo to install: ${missing[*]}"; exit 1; }
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  for p in "${optional[@]}"; do
    if apt-cache show "$p" >/dev/null 2>&1; then
      missing+=("$p")
    else
      log "optional package $p is not available here: scripts/fuzz will not work"
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing: ${missing[*]}"
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# configure DIR [extra cmake args...]: CMake's errors reach stderr.
configure() {
  local dir="$1"
  shift
  local generator=()
  command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    log "configuring $dir"
    cmake -S "$ROOT" -B "$dir" "${generator[@]}" "$@" >/dev/null
  else
    cmake -S "$ROOT" -B "$dir" "$@" >/dev/null
  fi
}

# build DIR
build() {
  log "building $1"
  cmake --build "$1" --parallel "$(nproc 2>/dev/null || echo 2)"
}

# configure_and_build DIR [extra cmake args...]
configure_and_build() {
  configure "$@"
  build "$1"
}

setup() {
  install_missing_packages
  configure_and_build "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
}
