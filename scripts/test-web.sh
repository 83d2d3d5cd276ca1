#!/usr/bin/env bash
# The web page's tests in Debian's headless Chromium (tests/web/web.test.mjs), on a page built by
# scripts/build-web.sh: scripts/test-web.sh OUTDIR. Installs the test's npm packages (package-lock)
# the first time; playwright-core drives /usr/bin/chromium and never downloads a browser.
set -euo pipefail
dir=${1:?usage: scripts/test-web.sh OUTDIR (of scripts/build-web.sh)}
src=$(cd "$(dirname "$0")/.." && pwd)
dir=$(cd "$dir" && pwd)
command -v chromium >/dev/null || { echo "test-web: chromium is missing: scripts/install-deps.sh web" >&2; exit 1; }
cd "$src/tests/web"
if [ ! -d node_modules/playwright-core ]; then
  PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund
fi
S4D_WEB_DIR=$dir node --test --test-concurrency=1 .
