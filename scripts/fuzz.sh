#!/usr/bin/env bash
# Builds the libFuzzer targets (CMakePresets.json "fuzz": clang, ASan + UBSan, into build-fuzz/) and
# runs each of them, one after the other, for SECONDS (default 60) over its corpus:
#   tests/fuzz/corpus/<target>/  the findings kept as regression inputs (read only)
#   assets/, tests/data/         the seeds
#   build-fuzz/corpus/<target>/  what the fuzzer adds (not in git)
# A crash, leak, sanitizer report or timeout stops that target, leaves the input in
# build-fuzz/findings/<target>/ and makes the script fail. FUZZ_TARGETS="fuzz_obj" picks targets.
# Usage: scripts/fuzz.sh [SECONDS] [extra libFuzzer options...]
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
build="$root/build-fuzz"

cmake --preset fuzz -S "$root" >/dev/null
cmake --build "$build" -j "$(nproc)" --target fuzz_scene fuzz_obj fuzz_lesson

declare -A seeds=(
  [fuzz_scene]="$root/assets/scenes $root/tests/data"
  [fuzz_obj]="$root/assets/meshes $root/tests/data"
  [fuzz_lesson]="$root/assets/lessons"
)
declare -A dicts=([fuzz_scene]=scene.dict [fuzz_obj]=obj.dict [fuzz_lesson]=lesson.dict)

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
status=0
for target in ${FUZZ_TARGETS:-fuzz_scene fuzz_obj fuzz_lesson}; do
  corpus="$build/corpus/$target" findings="$build/findings/$target"
  mkdir -p "$corpus" "$findings"
  echo "fuzz.sh: $target for ${seconds}s" >&2
  # One process (the machine is shared); inputs up to 8 kB (FUZZ_MAX_LEN); 10 s or 2 GB for one input is a finding.
  # The kept findings run first (tests/fuzz/corpus/<target>: they must pass), then new inputs.
  "$build/tests/fuzz/$target" -max_total_time="$seconds" -max_len=${FUZZ_MAX_LEN:-8192} -timeout=10 -rss_limit_mb=2048 \
    -dict="$root/tests/fuzz/${dicts[$target]}" -artifact_prefix="$findings/" -print_final_stats=1 \
    "$@" "$corpus" "$root/tests/fuzz/corpus/${target#fuzz_}" ${seeds[$target]} 2>"$build/$target.log" || status=1
  grep -E "stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb|ERROR|SUMMARY" \
    "$build/$target.log" >&2 || true
done
exit $status
