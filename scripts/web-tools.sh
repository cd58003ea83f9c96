#!/usr/bin/env bash
# Sourced by web-test.sh and web-bench.sh: installs what driving the page in a browser needs, from
# Debian's packages (only what is missing, with sudo when not root) and npm (tests/web/, from its lock
# file, devDependencies only: puppeteer-core, which downloads no browser, and pngjs).

web_packages=(chromium nodejs npm)
web_missing=()
for p in "${web_packages[@]}"; do
  # node from elsewhere (e.g. NodeSource's, which brings its own npm) is as good as Debian's
  case "$p" in nodejs | npm) command -v "${p/nodejs/node}" >/dev/null && continue ;; esac
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || web_missing+=("$p")
done
if ((${#web_missing[@]})); then
  echo "vplab: installing ${web_missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -q
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${web_missing[@]}"
fi

# puppeteer-core downloads nothing on install; this keeps any other package from trying to fetch a browser
export PUPPETEER_SKIP_DOWNLOAD=1
npm ci --prefix "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/web" --no-audit --no-fund --prefer-offline --loglevel=error
