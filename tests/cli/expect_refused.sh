# Sourced by the CLI tests of refused input. expect_refused <words> <blockdem arguments...> runs
# $blockdem under a time limit and expects exit status 2 and the words on stderr; $work is the
# test's scratch folder and fail its way to fail.
expect_refused() {
  local words=$1
  shift
  set +e
  timeout 120 "$blockdem" "$@" > "$work/out.txt" 2> "$work/err.txt"
  local status=$?
  set -e
  [ $status -eq 2 ] || { cat "$work/out.txt" "$work/err.txt"; fail "exit status $status (expected 2) for: $*"; }
  grep -qF -- "$words" "$work/err.txt" || { cat "$work/err.txt"; fail "message for: $* (expected: $words)"; }
}
