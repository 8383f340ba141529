#!/usr/bin/env bash
# Builds the project and its tests with clang, AddressSanitizer and UndefinedBehaviorSanitizer in
# BUILD_DIR (default build-sanitize) and runs the whole test suite there (docs/checks.md). Any
# sanitizer report fails the test that triggered it. The only suppressions are the Open MPI
# libraries' own leaks (scripts/lsan-suppressions.txt), by library name.
#   scripts/sanitize.sh [BUILD_DIR] [extra ctest arguments...]
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=$(realpath -m "${1:-$source_dir/build-sanitize}")
shift || true

# One file a unit (BLOCKDEM_UNITY_BUILD off): the one build that compiles every file alone, so
# that a file which only compiles with what another file of its unit brings in is caught here.
cmake -S "$source_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DBLOCKDEM_SANITIZE=ON -DBLOCKDEM_BUILD_BENCHMARKS=OFF -DBLOCKDEM_UNITY_BUILD=OFF >/dev/null
cmake --build "$build_dir" -j "${JOBS:-$(nproc)}"

# halt_on_error: the first report ends the process with a failure status, which fails the test.
# fast_unwind_on_malloc=0: full stacks for every allocation, through libraries built without frame
# pointers, so that a leak inside Open MPI shows Open MPI's libraries and is matched by name.
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:fast_unwind_on_malloc=0"
export LSAN_OPTIONS="suppressions=$source_dir/scripts/lsan-suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The fuzz smoke is left out: it builds and runs its own sanitized harnesses (make test runs it).
ctest --test-dir "$build_dir" --output-on-failure -j "${JOBS:-$(nproc)}" -LE fuzz "$@"
