#!/usr/bin/env bash
# Dilating joints through a restart (docs/physics.md, "Dilation"): a dry wall of per-length
# joints with dilation_deg = 25 on a shaken driven course, run straight to T and stopped at T/2
# then restarted from its state file: history.csv, energy.csv, summary.json and interfaces.csv
# are byte-identical (the state file keeps every point's dilation). The shaking makes joints
# slide, so the wall's points dilate: the run differs from the same wall without dilation.
# Usage: test_restart_dilation.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
source "$(dirname "$0")/restart_check.sh"
export OMP_WAIT_POLICY=passive

dir="$tmp/wall"
mkdir -p "$dir"
cat > "$dir/wall.toml" <<TOML
[simulation]
duration = 0.3
output_interval = 0.005
[contact]
stiffness = "per_length"
kn = 1.0e10
ks = 4.0e9
mu = 0.6
dilation_deg = 25.0
e = 0.5
[[assemblies]]
type = "wall"
name = "brick"
density = 1800.0
length = 2.0
courses = 6
brick_length = 0.4
brick_height = 0.2
record = true
driven_zone = [[-1.0, -0.01], [3.0, -0.01], [3.0, 0.19], [-1.0, 0.19]]
[output]
interfaces = "all"
[table_motion.horizontal]
type = "sine"
amplitude = 1.5
unit = "g"
period = 0.2
TOML

restart_matches "dilating wall" "$dir/wall.toml" "$dir" 0.15
# The dilation acts: without it the same wall moves otherwise.
sed 's/^dilation_deg = 25.0$//' "$dir/wall.toml" > "$dir/dry.toml"
"$bin" run "$dir/dry.toml" --out "$dir/dry" -q --threads 1 > /dev/null 2> "$dir/dry.log" || fail "dry run: $(tail -2 "$dir/dry.log")"
cmp -s "$dir/full/history.csv" "$dir/dry/history.csv" && fail "the wall moves the same without dilation"
[ "$failures" -eq 0 ] || exit 1
echo "dilating wall: restarted at T/2 gives identical files; dilation changes the run"
