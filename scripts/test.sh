#!/usr/bin/env bash
# Installs what the tests need, builds everything (release, with tests) and runs the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh test
cmake -S . -B build-test -G Ninja -DCMAKE_BUILD_TYPE=Release -DS4D_BUILD_TESTS=ON -DS4D_BUILD_BENCH=ON
cmake --build build-test -j"$(nproc)"
cd build-test
ctest --output-on-failure -j"$(nproc)" --timeout 600
