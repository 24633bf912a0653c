# Shared by scripts/test and scripts/demo: install what is missing, configure
# once, build incrementally. Sourced, not run.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${ACO_BUILD_DIR:-$ROOT/build}"
cd "$ROOT"

# Debian packages the build and the tests need. Checked with dpkg (fast) and
# installed only when missing, so a second run costs nothing.
BUILD_PACKAGES=(cmake ninja-build g++ gcc make libeigen3-dev libtinyxml2-dev libgtest-dev libgmock-dev libbenchmark-dev
                nlohmann-json3-dev libcli11-dev libnanoflann-dev help2man)
TEST_PACKAGES=(python3-ezdxf librsvg2-bin)
# LinuxCNC's standalone interpreter rs274 reads our programs back in the tests
# (gcc and make above also build GRBL's own parser, tests/grbl-sim).
# Headless chromium prints the setup sheet to PDF and pdftotext reads it back.
# KiCad 6's pcbnew Python module and its demo boards test the KiCad plugin
# (its dialog in Xvfb); KiCad's PCM schema is checked with python3-jsonschema.
TEST_PACKAGES_NO_RECOMMENDS=(linuxcnc-uspace gerbv chromium poppler-utils kicad kicad-demos python3-jsonschema xvfb xauth)

missing_packages() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

install_packages() {
  local recommends="$1"; shift
  local missing
  missing=$(missing_packages "$@")
  [ -z "$missing" ] && return 0
  echo "acodrill: installing Debian packages: $(echo $missing | tr '\n' ' ')" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  if [ ! -f /tmp/.acodrill-apt-updated ]; then
    $sudo apt-get update -qq && touch /tmp/.acodrill-apt-updated
  fi
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $recommends $missing >/dev/null
}

# build [cmake configure arguments]: configure once (later arguments are
# ignored; the cache keeps them), then build; BUILD_TARGETS limits what is built.
build() {
  local jobs
  jobs=$(nproc 2>/dev/null || echo 2)
  if [ ! -f "$BUILD/build.ninja" ]; then
    cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  fi
  # shellcheck disable=SC2086
  cmake --build "$BUILD" -j "$jobs" ${BUILD_TARGETS:+--target $BUILD_TARGETS}
}
