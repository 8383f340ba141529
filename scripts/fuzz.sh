#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang with ASan and UBSan) in their own build folder and
# runs each one in turn for a bounded time on a corpus seeded from examples/, fuzz/seeds/,
# tests/data/records/ and ../shared/data/ground-motions/ when present (docs/checks.md).
#
#   scripts/fuzz.sh [--build-dir DIR] [--seconds N] [--smoke] [--no-build] [HARNESS...]
#
# --seconds N  time per harness (default 300); --smoke: 4 s for the scenario and override
# harnesses (slow inputs: each builds a world), 1 s for the others (hundreds to thousands of
# inputs a second), but never before every seed and regression input has run once (libFuzzer
# replays them all before it looks at the clock), fixed random seed and a throw-away corpus (the
# check `make test` runs). HARNESS: names such as fuzz_scenario (default: all). The corpus grows
# in DIR/corpus/HARNESS, findings land in DIR/findings/, logs in DIR/logs/.
# Exit status 1 when any harness found a crash, a sanitizer report, a leak, a timeout or ran out
# of memory; a summary table (CPU seconds, executions, coverage, corpus, findings) is printed.
set -euo pipefail

source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=
seconds=
smoke=0
build=1
harnesses=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir=$(realpath -m "$2"); shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --smoke) smoke=1; shift ;;
    --no-build) build=0; shift ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) harnesses+=("$1"); shift ;;
  esac
done
all=(fuzz_scenario fuzz_overrides fuzz_time_series_csv fuzz_record_auto fuzz_record_peer_at2 fuzz_record_knet
     fuzz_record_cosmos_v2 fuzz_record_jma_csv fuzz_record_plain fuzz_drawing)
[ ${#harnesses[@]} -eq 0 ] && harnesses=("${all[@]}")
# The smoke (-O0) and a long run (-O1) each in their own folder: sharing one, each would rebuild
# the whole sanitized library for the other's flags.
if [ -z "$build_dir" ]; then
  if [ "$smoke" = 1 ]; then build_dir="$source_dir/build/fuzz-smoke"; else build_dir="$source_dir/build/fuzz"; fi
fi

if [ "$build" = 1 ]; then
  # Only what the harnesses need: the library and fuzz/ (no tests, benchmarks, MPI or OpenMP),
  # with line tables only, so that the reports keep their file and line. At -O1 for a long run,
  # where inputs a second count; at -O0 for the smoke, whose build `make test` waits for and whose
  # inputs are mostly the seeds: the build takes half the CPU (docs/checks.md), each input about
  # three times as long.
  opt=-O1
  [ "$smoke" = 1 ] && opt=-O0
  cmake -S "$source_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$opt -gline-tables-only -DNDEBUG" \
    -DCMAKE_CXX_COMPILER=clang++-14 \
    -DBLOCKDEM_FUZZ=ON -DBLOCKDEM_BUILD_TESTS=OFF -DBLOCKDEM_BUILD_BENCHMARKS=OFF -DBLOCKDEM_WITH_MPI=OFF \
    -DCMAKE_DISABLE_FIND_PACKAGE_OpenMP=ON >/dev/null
  cmake --build "$build_dir" -j "${JOBS:-$(nproc)}" --target fuzzers
fi

# Record files: the test records, and the real ones beside the repository when they are there.
records="$source_dir/tests/data/records"
record_dirs=("$records")
shared="$source_dir/../shared/data/ground-motions"
[ -d "$shared" ] && record_dirs+=("$shared")

# Seed files for one harness, one path a line (missing ones are skipped).
seed_files() {
  local regressions="$source_dir/fuzz/regressions/${1#fuzz_}"
  [ -d "$regressions" ] && find "$regressions" -type f
  case "$1" in
    fuzz_scenario) find "$source_dir/examples" "$source_dir/tests/cli/data" "$source_dir/fuzz/seeds/scenario" -name '*.toml' ;;
    fuzz_overrides) find "$source_dir/fuzz/seeds/overrides" -type f ;;
    fuzz_drawing) find "$source_dir/examples/dxf" "$source_dir/fuzz/seeds/drawing" \( -name '*.dxf' -o -name '*.txt' \) ;;
    fuzz_time_series_csv)
      find "$source_dir/fuzz/seeds/time_series_csv" -type f
      echo "$records/two_columns.csv"; echo "$records/values_only.txt" ;;
    fuzz_record_auto) find "${record_dirs[@]}" -type f ! -name '*.py' ! -name '*.json' ! -name '*.md' ! -name '.*' ;;
    fuzz_record_peer_at2) find "${record_dirs[@]}" -iname '*.at2' ;;
    fuzz_record_knet) find "${record_dirs[@]}" \( -name 'knet*' -o -name 'kiknet*' -o -name '*.NS' -o -name '*.EW*' \) ;;
    fuzz_record_cosmos_v2) find "${record_dirs[@]}" \( -name '*.V2' -o -name '*.V2c' \) ;;
    fuzz_record_jma_csv) find "${record_dirs[@]}" -name '*jma*.csv' ;;
    fuzz_record_plain)
      find "${record_dirs[@]}" -name '*.dat'
      echo "$records/two_columns.csv"; echo "$records/values_only.txt" ;;
  esac
}

# Dictionary: the harness's own tokens, plus every `key` the docs name for the scenario ones.
make_dict() {
  local dict="$build_dir/dicts/$1.dict"
  mkdir -p "$build_dir/dicts"
  case "$1" in
    fuzz_scenario|fuzz_overrides)
      cat "$source_dir/fuzz/dicts/${1#fuzz_}.dict"
      grep -oh '`[a-z_]\{2,\}`' "$source_dir"/docs/scenario.md "$source_dir"/docs/records.md \
        "$source_dir"/docs/assemblies.md "$source_dir"/docs/outputs-visual.md "$source_dir"/docs/drawings.md 2>/dev/null | tr -d '`' | sort -u |
        sed 's/.*/"&"/' ;;
    fuzz_time_series_csv) cat "$source_dir/fuzz/dicts/csv.dict" ;;
    fuzz_drawing) cat "$source_dir/fuzz/dicts/drawing.dict" ;;
    *) cat "$source_dir/fuzz/dicts/records.dict" ;;
  esac >"$dict"
  echo "$dict"
}

# Time of one harness: --seconds, else the smoke's share (see the top), else 300 s.
run_seconds() {
  if [ -n "$seconds" ]; then echo "$seconds"
  elif [ "$smoke" = 0 ]; then echo 300
  else case "$1" in fuzz_scenario|fuzz_overrides) echo 4 ;; *) echo 1 ;; esac
  fi
}

max_len() {
  case "$1" in
    fuzz_scenario) echo 8192 ;;
    fuzz_overrides|fuzz_time_series_csv) echo 4096 ;;
    *) echo 65536 ;;  # a 6000-sample record; longer seeds are cut
  esac
}

summary="$build_dir/logs/summary.txt"
mkdir -p "$build_dir/logs" "$build_dir/findings"
printf '%-24s %8s %12s %8s %8s %8s %s\n' harness cpu_s executions cov ft corpus findings >"$summary"
status=0
for h in "${harnesses[@]}"; do
  exe="$build_dir/fuzz/$h"
  [ -x "$exe" ] || { echo "fuzz.sh: $exe is not built" >&2; exit 2; }
  seeds="$build_dir/seeds/$h"
  rm -rf "$seeds"; mkdir -p "$seeds"
  seed_files "$h" | while read -r f; do [ -f "$f" ] && cp "$f" "$seeds/"; done
  if [ "$smoke" = 1 ]; then
    # Stops at the first finding; reproducible (fixed seed) and leaves no corpus behind.
    corpus=$(mktemp -d); extra=(-seed=1)
  else
    # Goes on after a finding (each one is saved) in a child process, so that one known crash
    # does not end the campaign for that harness.
    corpus="$build_dir/corpus/$h"; mkdir -p "$corpus"
    extra=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  fi
  log="$build_dir/logs/$h.log"
  before=$(ls "$build_dir/findings" | grep -c "^$h-" || true)
  set +e
  # One process at a time, at the lowest priority: the machine is shared.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
  TIMEFORMAT='%U %S'
  { time nice -n 19 "$exe" "$corpus" "$seeds" -dict="$(make_dict "$h")" \
      -max_total_time="$(run_seconds "$h")" -max_len="$(max_len "$h")" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$build_dir/findings/$h-" "${extra[@]}" >"$log" 2>&1; } 2>"$log.time"
  rc=$?
  set -e
  cpu=$(awk '{printf "%.0f", $1 + $2}' "$log.time" 2>/dev/null || echo "?")
  # Plain runs end with stat:: lines; fork runs print "#EXECS: cov: N ft: N ..." as they go.
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  [ -n "$execs" ] || execs=$(grep -o '^#[0-9]*: cov' "$log" | tail -1 | tr -dc '0-9')
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  size=$(ls "$corpus" | wc -l)
  after=$(ls "$build_dir/findings" | grep -c "^$h-" || true)
  found=$((after - before))
  [ "$smoke" = 1 ] && rm -rf "$corpus"
  printf '%-24s %8s %12s %8s %8s %8s %s\n' "$h" "$cpu" "${execs:-?}" "${cov:-?}" "${ft:-?}" "$size" "$found" >>"$summary"
  # The smoke's short run must still have replayed every seed and regression input: libFuzzer
  # prints INITED after the last one.
  if [ "$smoke" = 1 ] && [ "$rc" -eq 0 ] && ! grep -qw INITED "$log"; then
    status=1
    echo "fuzz.sh: $h stopped before it had replayed its seeds (no INITED in $log)" >&2
  fi
  if [ "$rc" -ne 0 ] || [ "$found" -gt 0 ]; then
    status=1
    echo "fuzz.sh: $h FOUND A PROBLEM (exit $rc); log $log:" >&2
    { grep -E 'ERROR|runtime error|terminate called|what\(\)|SUMMARY|Test unit written|artifact' "$log" || true; } | head -20 >&2
  fi
done
cat "$summary"
exit $status
