#!/usr/bin/env bash
# Installs the Debian 12 packages shadow4d needs that are not yet installed (as root or via sudo).
# Usage: scripts/install-deps.sh [build|test|web]   (test adds what only the test suite needs, web
# what the web page's build and browser tests need; test includes web)
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev nlohmann-json3-dev libcli11-dev libspdlog-dev libstb-dev
  libglfw3-dev libimgui-dev libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri
  regina-normal-dev libgmp-dev libxml2-dev libspnav-dev libsdl2-dev libasound2-dev
  libgtest-dev libbenchmark-dev
)
if [[ "${1:-build}" == test || "${1:-build}" == web ]]; then
  # The web page (scripts/build-web.sh, scripts/test-web.sh): Debian's emscripten, xz for Dear
  # ImGui's source package, Chromium for the browser tests, npm for their playwright-core.
  packages+=(emscripten xz-utils chromium)
  command -v npm >/dev/null || packages+=(npm)
fi
if [[ "${1:-build}" == test ]]; then
  # clang and its sanitizer and libFuzzer runtimes for the checked builds; llvm for the
  # symbolizer that puts file:line into their reports.
  packages+=(xvfb xauth libfcl-dev libbullet-dev clang libclang-rt-14-dev llvm)
  # The package test checks the .desktop entry and the .s4d MIME type as the desktop reads them.
  packages+=(desktop-file-utils shared-mime-info)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
