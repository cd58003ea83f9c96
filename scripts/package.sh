#!/usr/bin/env bash
# The Debian package for lab machines (README "Install"): sets up and builds (setup.sh), then
# `cpack -G DEB` writes $VPLAB_BUILD/vplab_VERSION_ARCH.deb (cmake/Package.cmake says what is in it).
# Install it with `sudo apt-get install ./vplab_VERSION_ARCH.deb`.
set -euo pipefail
# Debian's DEB_BUILD_OPTIONS=nocheck: the package is built without the test suites (BUILD_TESTING=OFF).
if [[ " ${DEB_BUILD_OPTIONS:-} " == *" nocheck "* ]]; then
  export VPLAB_BUILD_TESTING=OFF
fi
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$VPLAB_BUILD"
cpack -G DEB >/dev/null
deb=$(ls -t vplab_*.deb | head -1)
echo "$VPLAB_BUILD/$deb ($(du -h "$deb" | cut -f1)); install it with: sudo apt-get install ./$deb"
