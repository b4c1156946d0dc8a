#!/usr/bin/env bash
# Installs the Debian 12 packages Radiosity Textbook needs, if any are missing. Idempotent and quiet when all are there.
set -euo pipefail
packages=(
  cmake g++ ninja-build pkg-config ccache clang-format clang libclang-rt-14-dev llvm
  libvtk9-dev qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev libqt6openglwidgets6 qt6-charts-dev qt6-svg-dev
  libeigen3-dev libboost-dev libcgal-dev libgmp-dev libmpfr-dev libgtest-dev libembree-dev libtbb-dev
  nlohmann-json3-dev libcli11-dev libmd4c-dev libmd4c-html0-dev
  qt6-webengine-dev libjs-katex poppler-utils librsvg2-bin
  xvfb xauth mesa-utils libgl1-mesa-dri fonts-dejavu-core
  emscripten libjs-three chromium
)
# The web edition's tests run node and npm (tests/browser); a node from elsewhere with its own npm will do.
command -v npm >/dev/null 2>&1 || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
