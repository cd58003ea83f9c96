#!/usr/bin/env bash
# Quick start, command 1: set up, build, and open the viewer on the default lecture scene.
# Extra arguments go to vplab (for example: scripts/run.sh --scene assets/scenes/oblique-cabinet.json).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
# Without a display the viewer cannot open: the quick start asks for its headless fallback here, the
# pipeline dump and the three views in the working directory (vplab alone writes nothing unasked).
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  exec "$VPLAB_BUILD/vplab" --no-display-dir . "$@"
fi
exec "$VPLAB_BUILD/vplab" "$@"
