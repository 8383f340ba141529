#!/usr/bin/env bash
# `blockdem report` works on every example (run for 0.1 s), also where the table and the blocks
# are not in history.csv (assembly blocks are recorded only on request), and says what it
# cannot plot: on stderr and in report.html.
# Usage: test_report_examples.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

for scenario in "$src"/examples/*/*.toml; do
  name=$(basename "$(dirname "$scenario")")-$(basename "$scenario" .toml)
  out=$tmp/$name
  if ! "$bin" run "$scenario" --out "$out" -q --set simulation.duration=0.1 > "$out.run.log" 2>&1; then
    fail "$name: run: $(tail -2 "$out.run.log")"; continue
  fi
  # The animation file only for the rock slope (nothing of it can be drawn): the slow part.
  extra=--no-animation
  [ "$name" = assemblies-rock_slope ] && extra=
  "$bin" report "$out" $extra > "$out.report.log" 2>&1 || { fail "$name: report: $(tail -3 "$out.report.log")"; continue; }
  [ -s "$out/report.html" ] || fail "$name: no report.html"
done

slope=$tmp/assemblies-rock_slope
grep -q "blockdem report: note: The table 'rock0' is not in history.csv" "$slope.report.log" || fail "rock slope: no note on the table"
grep -q "dynamic bodies are not in history.csv" "$slope.report.log" || fail "rock slope: no note on the blocks"
grep -q "What this report cannot show" "$slope/report.html" || fail "rock slope: report.html does not list what it cannot show"
grep -q "What this report cannot show" "$tmp/paper-rocking/report.html" && fail "rocking: a complete run has nothing to declare"

[ $failures -eq 0 ] && echo "the report works on every example"
exit $failures
