#!/usr/bin/env bash
# End-to-end: the generated 3-D assemblies (docs/3d.md, "Rock mass and random packing"). The
# rock slope and random packing examples run (shortened) and say what they built in summary.json
# and on the terminal; the packing's bodies are the same bytes from one run to the next; bad
# assemblies exit with status 2 naming the file and the key: an unknown key, a dip outside
# [0, 90], a dip direction outside [0, 360), a spacing <= 0, a region that is not convex, a
# packing that does not fit, a brick wall of one brick a course (its odd courses empty).
# Usage: test_assemblies_3d.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1
src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }

# 1. The examples, shortened.
out=$("$bin" run "$src/examples/3d/rock_slope.toml" --out "$tmp/slope" --set simulation.duration=0.02 2>&1) \
    || fail "the rock slope example failed: $out"
expect_in "$out" "rock mass 'rock': 54 blocks (19 driven, 35 free) from 13 joints"
for run in 1 2; do
    out=$("$bin" run "$src/examples/3d/random_packing.toml" --out "$tmp/pack$run" --set simulation.duration=0.01 2>&1) \
        || fail "the random packing example failed: $out"
done
expect_in "$out" "random packing 'rock': 48 hull bodies (seed 2026), volume fraction"
/usr/bin/python3 - "$tmp" <<'PY' || fail "the outputs are not as expected"
import json, sys
tmp = sys.argv[1]
slope = json.load(open(f"{tmp}/slope/summary.json"))
assert slope["status"] == "completed", slope["status"]
assert slope["assemblies"][0].startswith("rock mass 'rock': 54 blocks"), slope["assemblies"]
kinds = [b["kind"] for b in slope["bodies"]]
assert kinds.count("driven") == 19 and kinds.count("dynamic") == 35, kinds
pack = json.load(open(f"{tmp}/pack1/summary.json"))
assert len(pack["bodies"]) == 53, len(pack["bodies"])
assert "volume fraction 0.06" in pack["assemblies"][0], pack["assemblies"]
PY
# The first frame of the packing (the bodies as placed) is the same bytes in both runs.
cmp -s "$tmp/pack1/vtk/bodies_000000.vtp" "$tmp/pack2/vtk/bodies_000000.vtp" || fail "the same seed gave other bodies"
cmp -s "$tmp/pack1/history.csv" "$tmp/pack2/history.csv" || fail "the same seed gave another history"

# 2. Bad input: exit status 2, the file and the key named.
bad() {  # name, sed expression applied to an example, example, expected text
    sed -e "$2" "$src/examples/3d/$3.toml" >"$tmp/bad_$1.toml"
    out=$("$bin" run "$tmp/bad_$1.toml" --out "$tmp/out_$1" -q 2>&1); status=$?
    [[ $status -eq 2 ]] || fail "$1: exit status $status, expected 2: $out"
    expect_in "$out" "bad_$1.toml"
    expect_in "$out" "$4"
}
bad unknown_key 's/^spacing = 2.0 .*/spacing = 2.0\nspaceing = 1.0/' rock_slope "'assemblies.rock.joint_sets[0].spaceing'"
bad dip 's/^dip_deg = 35.0 .*/dip_deg = 95.0/' rock_slope "'assemblies.rock.joint_sets[0].dip_deg'"
bad dip_direction 's/^dip_direction_deg = 270.0 .*/dip_direction_deg = 360.0/' rock_slope "'assemblies.rock.joint_sets[0].dip_direction_deg'"
bad spacing 's/^spacing = 2.0 .*/spacing = 0.0/' rock_slope "'assemblies.rock.joint_sets[0].spacing'"
bad concave 's/\[4, 4, 8\]\]/[4, 4, 8], [6, 2, 4]]/' rock_slope "'assemblies.rock.region_vertices'"
bad no_fit 's/^count = 48.*/count = 65/' random_packing "'assemblies.rock.count'"
expect_in "$out" "do not fit"
# One brick a course: the odd courses (one brick fewer) would be empty, the bricks above floating.
bad one_brick_a_course 's/^bricks_per_course = 12.*/bricks_per_course = 1/' brick_wall "'assemblies.brick.bricks_per_course': is 1 with 6 courses"
expect_in "$out" "the bricks above would float"

[[ $failures -eq 0 ]] && echo "test_assemblies_3d: all passed"
exit $((failures > 0))
