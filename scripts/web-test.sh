#!/usr/bin/env bash
# The browser tests (issue 13, section 3): installs Debian's chromium and node (when missing) and the
# test tooling from npm (tests/web/package-lock.json: puppeteer-core, no browser download, and pngjs),
# then runs tests/web/*.test.mjs with node's test runner against the page in build-web/ (scripts/web.sh)
# and the desktop build/vplab (in $VPLAB_BUILD, if set). VPLAB_WEB_DIR and VPLAB_BIN choose others;
# CHROMIUM another browser.
# Exits non-zero when a test fails.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/web-tools.sh"

export VPLAB_WEB_DIR="${VPLAB_WEB_DIR:-$root/build-web}"
export VPLAB_BIN="${VPLAB_BIN:-${VPLAB_BUILD:-$root/build}/vplab}"
for need in "$VPLAB_WEB_DIR/index.html" "$VPLAB_BIN"; do
  if [ ! -e "$need" ]; then
    echo "web-test.sh: $need is missing: build the page with scripts/web.sh and the desktop vplab with scripts/setup.sh" >&2
    exit 1
  fi
done

cd "$root"
node --test tests/web/*.test.mjs
