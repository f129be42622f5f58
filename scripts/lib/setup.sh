# Shared set-up for scripts/run and scripts/test (sourced, not executed):
# install what is missing on Debian/Ubuntu, then configure and build.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD_DIR="${FUNCTIONLAB_BUILD_DIR:-$ROOT/build}"

# Debian 12 package names. Qt, GLM, hidapi, libusb and SQLite are for the
# viewer, haptics and grading parts; libsodium signs the gradebook's log;
# xbyak compiles formulas to machine code (the batch evaluator's JIT);
# bubblewrap isolates each submission grade batch checks; muParser, Draco and
# meshoptimizer are benchmark peers only (functionlab-bench links them);
# npm installs X_ITE, the X3D browser every `export-web` page ships
# (install_web_viewer below).
# Installed with --no-install-recommends, so every package CMake needs is
# named here even where another package only recommends it (libqt6opengl6-dev:
# Qt6 3DRender needs Qt6OpenGL, a mere Recommends of qt6-base-dev).
# scripts/check-fresh-machine proves this list on a clean Debian 12 root.
PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git
  libgtest-dev libgmock-dev libbenchmark-dev libmuparser-dev
  libsleef-dev libxbyak-dev libglm-dev libeigen3-dev libsqlite3-dev libsodium-dev libhidapi-dev libusb-1.0-0-dev
  qt6-base-dev libqt6opengl6-dev qt6-3d-dev qt6-websockets-dev zlib1g-dev
  xvfb xauth libgl1-mesa-dri fonts-dejavu-core
  bubblewrap
  libdraco-dev libmeshoptimizer-dev
)
# npm_ci_pinned FROM TO MARKER WHAT CONSEQUENCE: the npm packages FROM's
# package.json and package-lock.json pin, installed into TO with `npm ci`
# unless MARKER (a file under TO) is there with the same lock file. A
# failure is said (WHAT could not be installed: CONSEQUENCE), never fatal.
npm_ci_pinned() {
  local from="$1" to="$2" marker="$3" what="$4" consequence="$5"
  if [ -f "$to/$marker" ] && cmp -s "$from/package-lock.json" "$to/package-lock.json"; then
    return 0
  fi
  if ! command -v npm >/dev/null 2>&1; then
    log "warning: no npm for $what: $consequence"
    return 0
  fi
  log "installing $what (npm ci in $to)"
  mkdir -p "$to"
  cp "$from/package.json" "$from/package-lock.json" "$to/"
  (cd "$to" && npm ci --no-audit --no-fund --loglevel=error >/dev/null) ||
    log "warning: npm could not install $what: $consequence"
}

# Node and npm install X_ITE (install_web_viewer); a machine that has them
# from elsewhere (NodeSource's nodejs carries its own npm, which Debian's npm
# package conflicts with) keeps them: they are asked of the commands, not of
# dpkg.
COMMAND_PACKAGES=(node:nodejs npm:npm)
# Only for scripts/fuzz (libFuzzer); skipped with a warning where the
# distribution names them differently.
OPTIONAL_PACKAGES=(clang libclang-rt-14-dev)

log() { printf '\033[1m==> %s\033[0m\n' "$*" >&2; }

# The packages of the arguments that dpkg does not have installed.
not_installed() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

# apt-get as root, or through sudo.
SUDO=()
as_root() {
  if [ "$(id -u)" -ne 0 ] && [ ${#SUDO[@]} -eq 0 ]; then
    command -v sudo >/dev/null 2>&1 || { log "need root or sudo to run: $*"; return 1; }
    SUDO=(sudo)
  fi
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive "$@"
}

# `apt-get update`, once per run (apt-cache knows new packages only after it).
APT_UPDATED=0
apt_update_once() {
  [ "$APT_UPDATED" = 1 ] && return 0
  as_root apt-get update -qq || return 1
  APT_UPDATED=1
}

# apt-get with the package lists fresh.
apt_get() {
  apt_update_once || return 1
  as_root apt-get "$@"
}

install_missing_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    log "not a Debian/Ubuntu system: install the equivalents of: ${PACKAGES[*]}"
    return 0
  fi
  local missing=() optional=() p
  mapfile -t missing < <(not_installed "${PACKAGES[@]}")
  mapfile -t optional < <(not_installed "${OPTIONAL_PACKAGES[@]}")
  for p in "${COMMAND_PACKAGES[@]}"; do
    command -v "${p%%:*}" >/dev/null 2>&1 || missing+=("${p#*:}")
  done
  [ ${#missing[@]} -eq 0 ] && [ ${#optional[@]} -eq 0 ] && return 0
  apt_update_once || exit 1
  for p in "${optional[@]}"; do
    if apt-cache show "$p" >/dev/null 2>&1; then
      missing+=("$p")
    else
      log "optional package $p is not available here: scripts/fuzz will not work"
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing: ${missing[*]}"
  apt_get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# The programs the interop tests (CTest label `interop`) open our exports
# with: Debian's view3dscene and assimp, and the Khronos glTF validator from
# npm, pinned by tests/interop/package-lock.json and installed under
# $BUILD_DIR/interop-tools. A tool that cannot be installed is reported and
# its tests skip, saying so; the rest of the suite does not depend on them.
# view3dscene and assimp open our exports (tests/interop); chromium shows the
# grading reports as a student's browser would (tests/cli, grade report).
# GNU parallel grades a class in shards as a cluster would (tests/cli, grade merge).
# python3-vtk9 is bench mesh's peer, VTK's Flying Edges (tests/cli, bench mesh).
TEST_TOOL_PACKAGES=(view3dscene assimp-utils chromium parallel python3-vtk9)

install_test_tools() {
  command -v dpkg-query >/dev/null 2>&1 || { log "not Debian: interop tools not installed"; return 0; }
  local wanted=("${TEST_TOOL_PACKAGES[@]}")
  local missing=()
  mapfile -t missing < <(not_installed "${wanted[@]}")
  if [ ${#missing[@]} -gt 0 ]; then
    log "installing the interop test tools: ${missing[*]}"
    apt_get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null ||
      log "warning: could not install ${missing[*]}: their interop tests will be skipped"
  fi
  npm_ci_pinned "$ROOT/tests/interop" "$BUILD_DIR/interop-tools" \
    node_modules/gltf-validator/package.json "the glTF validator" "its interop tests will be skipped"
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

# X_ITE, the X3D browser `functionlab export-web` copies into every page
# (never fetched from a CDN): from npm, pinned by web/package-lock.json,
# into $BUILD_DIR/web-viewer, where functionlab finds it
# (web/web_page.h findXite). Without it export-web says how to get it; the
# rest of the suite does not need it.
install_web_viewer() {
  npm_ci_pinned "$ROOT/web" "$BUILD_DIR/web-viewer" node_modules/x_ite/dist/x_ite.min.js \
    "X_ITE for export-web" "export-web will say so"
}

setup() {
  install_missing_packages
  install_web_viewer
  configure_and_build "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
}
