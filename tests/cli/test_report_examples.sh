#!/usr/bin/env bash
# `blockdem report` works on every example (run for 0.1 s), 3-D ones included, also where the table and the blocks
# are not in history.csv (assembly blocks are recorded only on request), and says what it
# cannot plot: on stderr and in report.html. The figures in PNG alone (--formats png: the SVG
# copies were a third of this test's time) but for one 2-D and one 3-D example, which keep the
# default PNG and SVG; the formats option itself is checked at the end.
# Usage: test_report_examples.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

for scenario in "$src"/examples/*/*.toml; do
  name=$(basename "$(dirname "$scenario")")-$(basename "$scenario" .toml)
  out=$tmp/$name
  # Examples driven by the shared earthquake records run only beside ../shared (as in CI).
  if grep -q "shared/data/" "$scenario" && [ ! -d "$src/../shared/data" ]; then
    echo "SKIP $name: ../shared/data is not present"; continue
  fi
  if ! "$bin" run "$scenario" --out "$out" -q --set simulation.duration=0.1 > "$out.run.log" 2>&1; then
    fail "$name: run: $(tail -2 "$out.run.log")"; continue
  fi
  # A 3-D run: its own report (outcome table, figures drawn from the VTK frames; docs/3d.md).
  if grep -q "^dimension *= *3" "$scenario"; then
    formats=png
    [ "$name" = 3d-drum_column ] && formats=png,svg
    "$bin" report "$out" --formats $formats > "$out.report.log" 2>&1 || { fail "$name: report of a 3-D run: $(tail -3 "$out.report.log")"; continue; }
    grep -q "<table id='outcome-table'>" "$out/report.html" || fail "$name: report.html has no outcome table"
    for stem in snapshots response table_motion energy; do
      [ -s "$out/figures/$stem.png" ] || fail "$name: no figures/$stem.png"
      grep -q "id='figure-$stem'" "$out/report.html" || fail "$name: figure $stem is not in report.html"
    done
    continue
  fi
  # The animation file only for the rock slope (nothing of it can be drawn): the slow part.
  extra=--no-animation
  [ "$name" = assemblies-rock_slope ] && extra=
  formats=png
  [ "$name" = assemblies-wall_with_window ] && formats=png,svg
  "$bin" report "$out" --formats $formats $extra > "$out.report.log" 2>&1 || { fail "$name: report: $(tail -3 "$out.report.log")"; continue; }
  [ -s "$out/report.html" ] || fail "$name: no report.html"
done

slope=$tmp/assemblies-rock_slope
grep -q "blockdem report: note: The table 'rock0' is not in history.csv" "$slope.report.log" || fail "rock slope: no note on the table"
grep -q "dynamic bodies are not in history.csv" "$slope.report.log" || fail "rock slope: no note on the blocks"
grep -q "What this report cannot show" "$slope/report.html" || fail "rock slope: report.html does not list what it cannot show"
grep -q "What this report cannot show" "$tmp/paper-rocking/report.html" && fail "rocking: a complete run has nothing to declare"

# A result that may be wrong says so: blocks dropped onto each other at 0.64 of the start's limit
# run above the stable limit of the stack they form (docs/physics.md): warned on stderr, in
# summary.json and at the top of the report; a clean run has no warnings section.
warn=$tmp/warned
"$bin" run "$src/tests/cli/data/unstable_stack.toml" --out "$warn" -q --set simulation.dt=5.0e-3 \
  --set simulation.max_energy_error=1e9 > "$warn.run.log" 2>&1 || fail "warned run: $(tail -2 "$warn.run.log")"
grep -q "WARNING: dt = 0.005 s was above the stable limit of the live contacts" "$warn.run.log" || fail "no warning on stderr"
grep -q '"dt_above_live_limit": true' "$warn/summary.json" || fail "summary.json does not flag the live limit"
"$bin" report "$warn" --no-animation --formats png > /dev/null 2>&1 || fail "report of the warned run"
grep -q "id='warnings'" "$warn/report.html" || fail "report.html does not show the warnings"
grep -q "id='warnings'" "$tmp/paper-sliding/report.html" && fail "sliding: a clean run shows a warnings section"

# --formats: the PNGs and only the formats asked for; an unknown one refused, naming it.
sliding=$tmp/paper-sliding
ls "$sliding"/figures/*.svg >/dev/null 2>&1 && fail "--formats png wrote SVG files"
rm -rf "$sliding/figures"
"$bin" report "$sliding" --no-animation --formats pdf > "$sliding.pdf.log" 2>&1 || fail "--formats pdf: $(tail -2 "$sliding.pdf.log")"
for stem in acceleration energy snapshots; do
  [ -s "$sliding/figures/$stem.png" ] && [ -s "$sliding/figures/$stem.pdf" ] || fail "--formats pdf: no $stem.png and $stem.pdf"
  [ -e "$sliding/figures/$stem.svg" ] && fail "--formats pdf wrote $stem.svg"
done
for stem in 3d-drum_column/figures/snapshots assemblies-wall_with_window/figures/snapshots; do
  [ -s "$tmp/$stem.svg" ] || fail "the default formats: no $stem.svg"
done
if "$bin" report "$sliding" --no-animation --formats png,eps > "$sliding.eps.log" 2>&1; then fail "--formats eps was taken"; fi
grep -q "unknown figure format 'eps'" "$sliding.eps.log" || fail "--formats eps: no message naming it: $(tail -2 "$sliding.eps.log")"

[ $failures -eq 0 ] && echo "the report works on every example"
exit $failures
