#!/usr/bin/env bash
# Sourced by web-test.sh and web-bench.sh: installs what driving the page in a browser needs, from
# Debian's packages (only what is missing, with sudo when not root) and npm (tests/web/, from its lock
# file, devDependencies only: puppeteer-core, which downloads no browser, and pngjs).

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
vplab_install_missing chromium nodejs npm

# puppeteer-core downloads nothing on install; this keeps any other package from trying to fetch a browser
export PUPPETEER_SKIP_DOWNLOAD=1
npm ci --prefix "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/web" --no-audit --no-fund --prefer-offline --loglevel=error
