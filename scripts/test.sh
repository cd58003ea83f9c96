#!/usr/bin/env bash
# Quick start, command 2: set up, build, and run the whole test suite through ctest (build/, Release);
# then the same suite under AddressSanitizer + UndefinedBehaviorSanitizer with leak checking
# (build-asan/, CMakePresets.json "asan"; tests/sanitizers/lsan.supp lists Mesa's own leaks), and every
# fuzz target for FUZZ_SECONDS (default 30) over its corpus (build-fuzz/, scripts/fuzz.sh).
# Arguments go to the first ctest run. VPLAB_SANITIZERS=0 runs only the first stage.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
ctest --test-dir "$VPLAB_BUILD" --output-on-failure -j "$(nproc)" "$@"

if [ "${VPLAB_SANITIZERS:-1}" != 0 ]; then
  cd "$VPLAB_ROOT"
  echo "test.sh: the test suite under ASan + UBSan (build-asan/)" >&2
  cmake --preset asan >/dev/null
  cmake --build build-asan -j "$(nproc)" --target vplab test_pipeline test_views test_app  # not the benchmarks
  ctest --preset asan -j "$(nproc)"
  echo "test.sh: every fuzz target for ${FUZZ_SECONDS:-30} s over its corpus (build-fuzz/)" >&2
  scripts/fuzz.sh "${FUZZ_SECONDS:-30}"
fi
