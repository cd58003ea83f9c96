#!/usr/bin/env bash
# Quick start, command 2: set up, build, and run the whole test suite through ctest (build/, Release);
# then the web page (build-web/, scripts/web.sh) in headless Chromium (scripts/web-test.sh); then the
# same suite under AddressSanitizer + UndefinedBehaviorSanitizer with leak checking (build-asan/,
# CMakePresets.json "asan"; tests/sanitizers/lsan.supp lists Mesa's own leaks), and every fuzz target
# for FUZZ_SECONDS (default 30) over its corpus (build-fuzz/, scripts/fuzz.sh).
# Arguments go to the first ctest run. VPLAB_WEB=0 leaves out the web page, VPLAB_SANITIZERS=0 the
# sanitizer and fuzz stages.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
ctest --test-dir "$VPLAB_BUILD" --output-on-failure -j "$(nproc)" "$@"

if [ "${VPLAB_WEB:-1}" != 0 ]; then
  echo "test.sh: the web page (build-web/) in headless Chromium" >&2
  "$VPLAB_ROOT/scripts/web.sh"
  "$VPLAB_ROOT/scripts/web-test.sh"
fi

if [ "${VPLAB_SANITIZERS:-1}" != 0 ]; then
  cd "$VPLAB_ROOT"
  echo "test.sh: the test suite under ASan + UBSan (build-asan/)" >&2
  cmake --preset asan >/dev/null
  cmake --build build-asan -j "$(nproc)" --target vplab test_pipeline test_io test_course test_text test_views test_workers test_document test_inspect test_lessons test_practice test_session test_export test_render test_ui test_course_kit test_cli test_monkey  # not the benchmarks
  ctest --preset asan -j "$(nproc)"
  echo "test.sh: every fuzz target for ${FUZZ_SECONDS:-30} s over its corpus (build-fuzz/)" >&2
  scripts/fuzz.sh "${FUZZ_SECONDS:-30}"
fi
