#!/usr/bin/env bash
# Sourced by setup.sh, web.sh and web-tools.sh: the one place that knows how vplab installs what it
# needs from Debian's packages.

# Installs those of the given Debian packages that are not installed yet (with sudo when not root);
# does nothing, not even `apt-get update`, when all of them are. A node or npm already on PATH
# counts as installed: one from elsewhere (e.g. NodeSource's, which brings its own npm) is as good
# as Debian's nodejs and npm.
vplab_install_missing() {
  local p missing=()
  for p in "$@"; do
    case "$p" in nodejs | npm) command -v "${p/nodejs/node}" >/dev/null && continue ;; esac
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "vplab: installing ${missing[*]}" >&2
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -q
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}
