#!/usr/bin/env bash
# Builds the web page: the same window (GLFW + WebGL2 + Dear ImGui) compiled by Debian's emscripten
# into OUTDIR (index.html, shadow4d.js, shadow4d.wasm, shadow4d.data), a static folder any web
# server can host (scripts/serve-web.sh serves it on 127.0.0.1).
#   scripts/build-web.sh OUTDIR [BUILD_DIR]     (BUILD_DIR: build-web in the checkout)
# Needs: scripts/install-deps.sh web (emscripten and the header-only libraries).
set -euo pipefail
out=${1:?usage: scripts/build-web.sh OUTDIR [BUILD_DIR]}
src=$(cd "$(dirname "$0")/.." && pwd)
build=${2:-$src/build-web}
mkdir -p "$build" "$out"
build=$(cd "$build" && pwd)
# This image's node is not Debian's: emscripten's JS optimiser needs Debian's acorn.
export NODE_PATH=/usr/share/nodejs
command -v emcmake >/dev/null || { echo "build-web: emscripten is missing: scripts/install-deps.sh web" >&2; exit 1; }

# Dear ImGui's own sources (libimgui-dev ships headers and a native library only): Debian's imgui
# source package of the installed libimgui-dev's version, fetched once into the build folder
# through a private sources list (deb-src of the Debian mirror this system uses).
imgui=$build/imgui
if [ ! -f "$imgui/imgui.cpp" ]; then
  version=$(dpkg-query -W -f '${source:Version}' libimgui-dev)
  apt_dir=$build/imgui-apt
  mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$build/imgui-src"
  mirror=$(grep -h -m1 '^URIs:' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{print $2}' | head -1)
  suite=$(grep -h -m1 '^Suites:' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{print $2}' | head -1)
  [ -n "$mirror" ] || mirror=$(awk '$1 == "deb" {print $2; exit}' /etc/apt/sources.list)
  [ -n "$suite" ] || suite=$(awk '$1 == "deb" {print $3; exit}' /etc/apt/sources.list)
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $mirror $suite main" > "$apt_dir/sources.list"
  apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o Dir::Etc::SourceParts=/nonexistent
            -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache" -o APT::Sandbox::User=root)
  apt-get -qq "${apt_opts[@]}" update
  (cd "$build/imgui-src" && apt-get -qq "${apt_opts[@]}" source --download-only "imgui=$version")
  rm -rf "$imgui" && mkdir -p "$imgui"
  tar xf "$build"/imgui-src/imgui_*.orig.tar.* -C "$imgui" --strip-components=1
fi

start=$(date +%s)
emcmake cmake -S "$src" -B "$build" -G Ninja -DS4D_WEB=ON -DCMAKE_BUILD_TYPE=Release \
  "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG" \
  -DS4D_IMGUI_SOURCE_DIR="$imgui" > "$build/configure.log" || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" --target shadow4d -j"${JOBS:-2}"
cp "$src/web/index.html" "$build"/apps/shadow4d/shadow4d.{js,wasm,data} "$out/"
echo "build-web: $out ($(du -sh "$out" | cut -f1)) in $(( $(date +%s) - start )) s; serve it with scripts/serve-web.sh $out"
