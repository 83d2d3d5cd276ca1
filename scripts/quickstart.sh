#!/usr/bin/env bash
# Quick start: installs what is missing, builds a release build, and runs the main job:
# the app window on a display, or the headless demo (paper objects rendered to PNG) without one.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh build
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DS4D_BUILD_TESTS=OFF -DS4D_BUILD_BENCH=OFF
cmake --build build --target shadow4d -j"$(nproc)"
if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
  exec build/apps/shadow4d/shadow4d "$@"
else
  echo "quickstart: no display, running the headless demo"
  exec build/apps/shadow4d/shadow4d demo --out demo-output "$@"
fi
