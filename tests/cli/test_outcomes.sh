#!/usr/bin/env bash
# `blockdem run` says what happened (docs/outputs.md, "Outcomes"): a cube knocked off a stack
# FELL (though it never overturned); past the table's edge it LEFT THE MODEL and was taken out,
# the run going on; bad outcome keys are named errors with exit status 2.
# Usage: test_outcomes.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }
scene=$src/tests/data/outcomes/knocked_off.toml

out=$("$bin" run "$scene" --out "$tmp/fell" -q 2>&1) || fail "run failed: $out"
expect_in "$out" "upper: FELL from its supporters at t = "
expect_in "$out" "came to rest at"
expect_in "$out" "lower: stable"
expect_in "$out" "1 of 2 blocks fell"
grep -q '"outcome": "fell"' "$tmp/fell/summary.json" || fail "summary.json: no fell outcome"

out=$("$bin" run "$scene" --out "$tmp/left" -q --set bodies.table.width=1.2 2>&1) || fail "narrow-table run failed: $out"
expect_in "$out" "upper: LEFT THE MODEL at t = "
expect_in "$out" "(taken out of the run)"
/usr/bin/python3 - "$tmp/left/summary.json" <<'PY' || fail "summary.json of the narrow table"
import json, sys
s = json.load(open(sys.argv[1]))
upper = next(b for b in s["bodies"] if b["name"] == "upper")
assert upper["outcome"] == "left_model", upper["outcome"]
assert upper["peak_abs_relative_displacement_m"] < 3.0, upper["peak_abs_relative_displacement_m"]
assert [l["body"] for l in s["domain"]["left"]] == ["upper"]
assert s["energy_j"]["balance_error_relative"] < 0.01
PY

run_bad() {  # expected text, --set value
  local msg; msg=$("$bin" run "$scene" --out "$tmp/bad" -q --set "$2" 2>&1); local rc=$?
  [ $rc -eq 2 ] || fail "$2: exit $rc, expected 2 ($msg)"
  expect_in "$msg" "$1"
}
run_bad "key 'outcomes.fall_drop_ratio': must be >= 0" "outcomes.fall_drop_ratio=-1"
run_bad "key 'outcomes.rest_speed': must be a number" 'outcomes.rest_speed="fast"'
run_bad "key 'simulation.domain': [[-1, 0], [1, 5]] m does not contain body 'table'" "simulation.domain=[[-1, 0], [1, 5]]"
# Every body fixed or driven: nothing would move, and such a run reported nothing; refused.
msg=$("$bin" run "$scene" --out "$tmp/still" -q --set 'bodies.upper.kind="fixed"' --set 'bodies.lower.kind="driven"' 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "nothing to move: exit $rc, expected 2 ($msg)"
expect_in "$msg" "knocked_off.toml: the model has no dynamic body (2 fixed, 1 driven), so nothing would move"
# A body thrown at 1e200 m/s leaves at once with an infinite energy: the run ended "completed"
# with an energy error of nan, and then named the table as the fastest body. It stops (exit 3)
# naming the body that left.
msg=$("$bin" run "$scene" --out "$tmp/thrown" -q --set 'bodies.upper.velocity=[1e200, 0]' 2>&1)
rc=$?
[ $rc -eq 3 ] || fail "a body thrown at 1e200 m/s: exit $rc, expected 3 ($msg)"
expect_in "$msg" "body 'upper' left the model at t = "
expect_in "$msg" "with a kinetic energy beyond the range of a number (check its initial velocity)"

[ $failures -eq 0 ] && echo "all outcome checks passed"
exit $failures
