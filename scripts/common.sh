# Shared set-up for scripts/demo.sh and scripts/test.sh (sourced, not run).
# Installs the Debian packages that are missing (Debian 12; as root, or through sudo), then
# configures and builds the project with CMake.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
JOBS="${JOBS:-$(nproc)}"

# The library's build and test dependencies.
BUILD_PACKAGES=(g++ make cmake libcgal-dev libeigen3-dev libboost-graph-dev catch2
                libsuitesparse-dev libopenblas-dev libmetis-dev libtbb-dev ccache)
# The stripe editor (examples/Programs/Editor): an HTTP library, a JSON library, three.js for the page.
EDITOR_PACKAGES=(pkg-config libcpp-httplib-dev nlohmann-json3-dev libjs-three)

install_packages() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    return 0
  fi
  echo "== Installing Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
  fi
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
}

# configure_and_build BUILD_DIR [CMAKE_ARGS...] -- [TARGETS...]
configure_and_build() {
  local dir="$1"
  shift
  local cmake_args=() targets=()
  while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do cmake_args+=("$1"); shift; done
  [ "$#" -gt 0 ] && shift
  targets=("$@")
  local launcher=()
  if command -v ccache >/dev/null 2>&1; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    # paths relative to the checkout, so that clones in other folders share the cache
    export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$ROOT}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-true}"
  fi
  echo "== Configuring $dir"
  cmake -S "$ROOT" -B "$dir" "${launcher[@]}" "${cmake_args[@]}"
  echo "== Building $dir"
  if [ "${#targets[@]}" -gt 0 ]; then
    cmake --build "$dir" -j "$JOBS" --target "${targets[@]}"
  else
    cmake --build "$dir" -j "$JOBS"
  fi
}
