#!/usr/bin/env bash
# Redraws the program's icons with the program itself (run it after changing the trefoil scene):
#   packaging/make-icons.sh BUILD/apps/shadow4d/shadow4d
# shadow4d-256.png is the trefoil as the window draws it (lit tubes, depth colour); shadow4d.svg
# is its crossing diagram (`render --svg`) on a dark rounded square, for any size.
set -euo pipefail
bin=${1:?usage: packaging/make-icons.sh PATH/TO/shadow4d}
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/../scenes/trefoil-knot.json
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" render "$scene" --size 256x256 --out "$here/shadow4d-256.png" --svg "$tmp/diagram.svg" >/dev/null
sed -e 's|<rect width="256" height="256" fill="#ffffff"/>|<rect width="256" height="256" rx="44" fill="#16191f"/>|' \
    -e 's|stroke="#1a1a1a"|stroke="#e0353f"|g' \
    -e 's|stroke-width="[0-9.]*" stroke-linecap="butt"|stroke-width="13" stroke-linecap="butt"|' \
    -e 's|<title>[^<]*</title>|<title>shadow4d: a trefoil knot</title>|' \
    "$tmp/diagram.svg" >"$here/shadow4d.svg"
grep -q 'rx="44"' "$here/shadow4d.svg" || { echo "make-icons.sh: render --svg changed its output; update the sed lines" >&2; exit 1; }
echo "$here/shadow4d-256.png"
echo "$here/shadow4d.svg"
