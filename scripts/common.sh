# Shared by scripts/test and scripts/demo: install what is missing, configure
# once, build incrementally. Sourced, not run.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${ACO_BUILD_DIR:-$ROOT/build}"
cd "$ROOT"

# Debian packages the build and the tests need. Checked with dpkg (fast) and
# installed only when missing, so a second run costs nothing.
BUILD_PACKAGES=(cmake ninja-build g++ gcc make libeigen3-dev libtinyxml2-dev libgtest-dev libgmock-dev libbenchmark-dev
                nlohmann-json3-dev libcli11-dev libnanoflann-dev help2man zlib1g-dev)
TEST_PACKAGES=(python3-ezdxf librsvg2-bin zip)
# LinuxCNC's standalone interpreter rs274 reads our programs back in the tests
# (gcc and make above also build GRBL's own parser, tests/grbl-sim).
# Headless chromium prints the setup sheet to PDF and pdftotext reads it back.
# KiCad 6's pcbnew Python module and its demo boards test the KiCad plugin
# (its dialog in Xvfb); KiCad's PCM schema is checked with python3-jsonschema.
# FreeCAD 0.20's freecadcmd runs acodrill as its post-processor (issue 83).
TEST_PACKAGES_NO_RECOMMENDS=(linuxcnc-uspace gerbv chromium poppler-utils kicad kicad-demos python3-jsonschema xvfb xauth freecad)

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

# Issue 69: Debian's KiCad 9 (bookworm-backports) unpacked beside the installed
# KiCad 6, so the plugin's tests run on both: downloaded once, with the few
# bookworm libraries KiCad 6 did not bring, through a private apt source list
# (the machine's own apt configuration is left as it is), into build-deps/kicad9.
KICAD9_VERSION="9.0.8+dfsg-1~bpo12+1"
KICAD9_DIR="$ROOT/build-deps/kicad9"
fetch_kicad9() {
  [ -f "$KICAD9_DIR/.complete" ] && return 0
  local apt="$ROOT/build-deps/kicad9-apt"
  mkdir -p "$apt/etc" "$apt/lists/partial" "$apt/cache/archives/partial" "$apt/debs"
  cat > "$apt/etc/kicad9.sources" <<SOURCES
Types: deb
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-backports
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
  local opts=(-o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$apt/etc" -o Dir::State::Lists="$apt/lists"
              -o Dir::Cache="$apt/cache")
  echo "acodrill: fetching Debian's KiCad $KICAD9_VERSION for the plugin's tests" >&2
  apt-get "${opts[@]}" -qq update
  (cd "$apt/debs" && apt-get "${opts[@]}" -qq download "kicad=$KICAD9_VERSION" libgit2-1.5 libnng1 libmbedtls14 \
     libmbedx509-1 libmbedcrypto7 libhttp-parser2.9 libsecret-1-0 2>/dev/null)
  rm -rf "$KICAD9_DIR"
  mkdir -p "$KICAD9_DIR"
  local deb
  for deb in "$apt"/debs/*.deb; do dpkg -x "$deb" "$KICAD9_DIR"; done
  touch "$KICAD9_DIR/.complete"
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

# A library's sources from Debian's source package, for the Windows and
# browser builds of what Debian builds for Linux only (tinyxml2; zlib for
# the page): fetched once into DIR/src through a private apt source list
# (the machine's own apt configuration is left as it is). Prints the source
# folder.  fetch_debian_source DIR PACKAGE
fetch_debian_source() {
  local deps="$1" package="$2"
  local src
  src=$(find "$deps/src" -maxdepth 1 -type d -name "$package-*" 2>/dev/null | head -n 1)
  if [ -z "$src" ]; then
    local apt_src=(-o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$deps/apt/etc" -o Dir::State::Lists="$deps/apt/lists")
    mkdir -p "$deps/apt/etc" "$deps/apt/lists/partial" "$deps/src"
    cat > "$deps/apt/etc/debian-src.sources" <<SOURCES
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
    apt-get "${apt_src[@]}" -qq update >&2
    (cd "$deps/src" && apt-get "${apt_src[@]}" -qq source --download-only "$package" 2>/dev/null >&2)
    tar -xf "$deps"/src/"${package}"_*.orig.tar.* -C "$deps/src"
    src=$(find "$deps/src" -maxdepth 1 -type d -name "$package-*" | head -n 1)
  fi
  echo "$src"
}
fetch_tinyxml2_source() { fetch_debian_source "$1" tinyxml2; }
