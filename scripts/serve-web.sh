#!/usr/bin/env bash
# Serves the web page built by scripts/build-web.sh on 127.0.0.1 (a page must come from a server,
# not file://): scripts/serve-web.sh OUTDIR [PORT], then open http://127.0.0.1:PORT/ (default 8080).
# Add ?open=scenarios/spun-trefoil-tighten.json (a file of the site, or a generator call).
set -euo pipefail
dir=${1:?usage: scripts/serve-web.sh OUTDIR [PORT]}
port=${2:-8080}
[ -f "$dir/index.html" ] || { echo "serve-web: $dir has no index.html: build it with scripts/build-web.sh $dir" >&2; exit 1; }
echo "serve-web: http://127.0.0.1:$port/  (Ctrl+C stops)"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$dir"
