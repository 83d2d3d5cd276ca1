#!/usr/bin/env bash
# Builds the Debian package of shadow4d into OUTDIR: the program, its data (knot index, link
# table, braids), the scenarios and scenes as examples, the desktop entry and icon, the .s4d MIME
# type and the manual page (packaging/CMakeLists.txt). Install it with: apt install ./OUTDIR/shadow4d_*.deb
# Usage: scripts/package-deb.sh OUTDIR [BUILD_DIR]
#   BUILD_DIR: a configured build folder to package from (default: build-package, configured here
#   as a release build without tests); only the program and the manual page are built.
set -euo pipefail
out=${1:?usage: scripts/package-deb.sh OUTDIR [BUILD_DIR]}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath -m -- "${2:-$root/build-package}")
mkdir -p "$out"
out=$(cd "$out" && pwd)
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DS4D_BUILD_TESTS=OFF -DS4D_BUILD_BENCH=OFF
fi
cmake --build "$build" --target shadow4d man_page -j"$(nproc)"
# CPack stages the install under its own folder; only the .deb goes to OUTDIR.
staging="$build/package"
rm -rf "$staging"
(cd "$build" && cpack -G DEB -B "$staging" --config CPackConfig.cmake)
debs=("$staging"/shadow4d_*.deb)
[[ -f "${debs[0]}" ]] || { echo "package-deb: cpack made no .deb in $staging" >&2; exit 1; }
cp "${debs[@]}" "$out"/
for d in "${debs[@]}"; do
  echo "package-deb: $out/$(basename "$d") ($(du -h "$d" | cut -f1))"
done
