#!/usr/bin/env bash
# BUILD_TESTING=OFF, CTest's standard option (issue 39 item 8): a packager's configuration has the
# program, its libraries and its install rules, and none of the test suites, the fuzz targets or the
# Google Benchmark targets, nor needs GoogleTest or Google Benchmark to configure. (Building vplab alone
# and installing it was checked by hand: docs/tests.md; building it again here would cost CI minutes.)
# Usage: without_tests_test.sh SOURCE_DIR
set -euo pipefail
source=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "without_tests_test: $*" >&2; exit 1; }

cmake -S "$source" -B "$work/build" -DBUILD_TESTING=OFF >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log" >&2; fail "configuring with BUILD_TESTING=OFF failed"; }
cmake --build "$work/build" --target help >"$work/targets"
for wanted in vplab vplab_install_files vplab_pipeline vplab_course; do
  grep -qx "\.\.\. $wanted" "$work/targets" || fail "BUILD_TESTING=OFF has no target $wanted"
done
if grep -E '^\.\.\. (test_|fuzz_|bench_pipeline|gtest|gmock|benchmark)' "$work/targets"; then
  fail "BUILD_TESTING=OFF still builds the test targets above"
fi
grep -q 'GTest_DIR\|benchmark_DIR' "$work/build/CMakeCache.txt" &&
  fail "BUILD_TESTING=OFF still looked for GoogleTest or Google Benchmark"
[ -f "$work/build/CTestTestfile.cmake" ] && fail "BUILD_TESTING=OFF still registered tests with ctest"
# The install rules make the generated files (manual page, completion, icon, changelog) themselves.
grep -q -- '--target.*vplab_install_files' "$work/build/app/cmake_install.cmake" ||
  fail "cmake --install does not make the generated files it installs"
echo "without_tests_test: BUILD_TESTING=OFF has vplab and its install rules, no test, fuzz or benchmark target"
