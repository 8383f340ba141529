#!/usr/bin/env bash
# `blockdem limit` (docs/limit_analysis.md): a slender block topples at lambda = b/h = 0.25
# (14.036 deg) about the corner the load pushes it to; a semicircular arch at t/R = 0.15 forms
# four hinges, the same lambda both ways and with --non-associative; at t/R = 0.10 it has no
# equilibrium; --json writes the forces and the mechanism (and a write that fails exits 4); a
# friction of any size up to 1e300 leaves the block's b/h; bad arch keys and a bad direction are
# refused with exit status 2.
# Usage: test_limit_command.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }
data=$src/tests/data/limit

out=$("$bin" limit "$data/block.toml" 2>&1) || fail "limit failed: $out"
expect_in "$out" "collapse multiplier lambda = 0.25 (a table tilted by 14.0362 deg"
expect_in "$out" "base / slender: hinges at (0.1, 0)"
out=$("$bin" limit "$data/block.toml" --direction -x 2>&1) || fail "limit -x failed: $out"
expect_in "$out" "base / slender: hinges at (-0.1, 0)"
out=$("$bin" limit "$data/block.toml" --set contact.mu=0.2 2>&1) || fail "limit mu = 0.2 failed: $out"
expect_in "$out" "collapse multiplier lambda = 0.2 "
expect_in "$out" "base / slender: slides"
# A friction that cannot bind, however large, leaves the topple at b/h both ways (mu = 1e10 gave
# -0.25, 1e15 gave 0, 1e300 aborted inside GLPK with exit 134).
for mu in 10 1e10 1e15 1e300; do
  for dir in +x -x; do
    out=$("$bin" limit "$data/block.toml" --set contact.mu=$mu --direction $dir 2>&1) || fail "limit mu = $mu $dir: exit $?: $out"
    expect_in "$out" "collapse multiplier lambda = 0.25 (a table tilted by 14.0362 deg"
    if [ "$dir" = +x ]; then expect_in "$out" "base / slender: hinges at (0.1, 0)"; else expect_in "$out" "base / slender: hinges at (-0.1, 0)"; fi
  done
done
# Non-associative friction too: the wall with a window gave "no equilibrium" from mu = 1e9 on;
# a joint that cannot slip keeps its associative rows, and the mechanism is the associative one.
for mu in 1e9 1e300; do
  out=$("$bin" limit "$src/examples/limit/wall_with_window.toml" --non-associative --set contact.mu=$mu 2>&1) \
    || fail "non-associative mu = $mu: exit $?: $out"
  expect_in "$out" "collapse multiplier lambda = 0.666667 "
done
# --json to a full device: exit 4 naming it, and the device stays (it was removed, so that a
# second run wrote a plain file and exited 0). A device node of our own, where one can be made.
if mknod "$tmp/full" c 1 7 2>/dev/null; then
  for attempt in 1 2; do
    out=$("$bin" limit "$data/block.toml" --json "$tmp/full" 2>&1); rc=$?
    [ $rc -eq 4 ] || fail "--json to a full device (attempt $attempt): exit $rc, expected 4: $out"
    expect_in "$out" "could not write the output: $tmp/full: cannot write"
  done
  [ -c "$tmp/full" ] || fail "--json to a full device removed the device"
else
  echo "skipped: cannot make a device node (--json to a full device)"
fi

out=$("$bin" limit "$data/arch.toml" --json "$tmp/arch.json" 2>&1) || fail "arch failed: $out"
expect_in "$out" "20 dynamic bodies, 21 interfaces"
[ "$(grep -c ': hinges at' <<<"$out")" -eq 4 ] || fail "expected 4 hinges: $out"
/usr/bin/python3 - "$tmp/arch.json" <<'PY' || fail "arch.json"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "collapse", j["status"]
assert abs(j["lambda"] - 0.14935) < 5e-5, j["lambda"]
motions = [i["motion"] for i in j["interfaces"]]
assert sum(m.startswith("hinge") for m in motions) == 4, motions
assert len(j["mechanism"]) == 20
# every voussoir in equilibrium is implied by the LP; the thrust points lie on their joints
for i in j["interfaces"]:
    assert min(i["normal_N"]) >= 0.0
PY
out=$("$bin" limit "$data/arch.toml" --non-associative --json "$tmp/na.json" 2>&1) || fail "arch non-associative failed: $out"
expect_in "$out" "non-associative friction: 1 LPs after the associative one"
expect_in "$out" "collapse multiplier lambda = 0.14935"
grep -q '"friction": "non_associative"' "$tmp/na.json" || fail "na.json: no friction field"
out=$("$bin" limit "$data/arch.toml" --direction -x 2>&1) || fail "arch -x failed: $out"
expect_in "$out" "collapse multiplier lambda = 0.14935"
out=$("$bin" limit "$data/arch.toml" --set assemblies.v.ring_thickness=0.10 2>&1) || fail "thin arch failed: $out"
expect_in "$out" "no equilibrium: the blocks cannot carry their own weight"

run_bad() {  # expected text, arguments...
  local expected=$1; shift
  local msg; msg=$("$bin" limit "$@" 2>&1); local rc=$?
  [ $rc -eq 2 ] || fail "$*: exit $rc, expected 2 ($msg)"
  expect_in "$msg" "$expected"
}
run_bad "key 'assemblies.v.rise'" "$data/arch.toml" --set assemblies.v.rise=1.5
run_bad "key 'assemblies.v.ring_thickness'" "$data/arch.toml" --set assemblies.v.ring_thickness=2.5
run_bad "key 'assemblies.v.rise': must be at least span / 1000" "$data/arch.toml" --set assemblies.v.rise=1e-300
run_bad "key 'assemblies.v.span': the span must be < 10 km" "$data/arch.toml" --set assemblies.v.span=1e300
run_bad "key 'assemblies.v.voussoirs'" "$data/arch.toml" --set assemblies.v.voussoirs=2
run_bad "key 'assemblies.v.abutments'" "$data/arch.toml" --set 'assemblies.v.abutments="loose"'
run_bad "direction" "$data/arch.toml" --direction up

[ $failures -eq 0 ] && echo "limit command: all checks passed"
exit $((failures > 0))
