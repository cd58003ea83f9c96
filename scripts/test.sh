#!/usr/bin/env bash
# Quick start, command 2: set up, build, and run the whole test suite through ctest.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
ctest --test-dir "$VPLAB_BUILD" --output-on-failure -j "$(nproc)" "$@"
