#!/usr/bin/env bash
# The web page's size and speed (issue 13): gzip size of vplab.wasm + vplab.js, the first frame over
# fresh loads in headless Chromium, and the frame time of the default scene's three views in the page
# beside the desktop's `vplab bench --only frames` (bench/web/bench.mjs; its options pass through:
# --loads N, --frames N, --runs N, --json FILE). VPLAB_WEB_DIR and VPLAB_BIN as for scripts/web-test.sh.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/web-tools.sh"

export VPLAB_WEB_DIR="${VPLAB_WEB_DIR:-$root/build-web}"
export VPLAB_BIN="${VPLAB_BIN:-${VPLAB_BUILD:-$root/build}/vplab}"
node "$root/bench/web/bench.mjs" "$@"
