#!/usr/bin/env bash
# Quick start, command 1: set up, build, and open the viewer on the default lecture scene.
# Extra arguments go to vplab (for example: scripts/run.sh --scene assets/scenes/oblique-cabinet.json).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
exec "$VPLAB_BUILD/vplab" "$@"
