#!/usr/bin/env bash
# Sub-contacts through the command line (docs/physics.md, "Sub-contacts"): the bonded wall of
# test_restart_bonds.sh with [contact] sub_contacts = 4. Every joint touching at the start
# counts its 4 points, all bonded (interfaces.csv); the wall shaken until bonds break, stopped
# at T/2 and restarted from its state file, gives byte-identical outputs (the state file keeps
# the interior points with their history and bonds).
# Usage: test_sub_contacts.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
source "$(dirname "$0")/restart_check.sh"
export OMP_WAIT_POLICY=passive

cat > "$tmp/wall.toml" <<TOML
[simulation]
duration = 0.3
output_interval = 0.005
[contact]
stiffness = "per_length"
kn = 1.0e10
ks = 4.0e9
mu = 0.6
cohesion = 4.0e3
tensile_strength = 2.0e3
residual_mu = 0.5
sub_contacts = 4
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
bonded = true
driven_zone = [[-1.0, -0.01], [3.0, -0.01], [3.0, 0.19], [-1.0, 0.19]]
[output]
interfaces = "all"
[table_motion.horizontal]
type = "sine"
amplitude = 1.5
unit = "g"
period = 0.2
TOML

restart_matches "sub-contacts wall" "$tmp/wall.toml" "$tmp" 0.15
# At t = 0 every touching joint of the wall is edge to edge: 4 points, 4 bonded.
start_rows=$(awk -F, '$1 == "0" && $6 > 0' "$tmp/full/interfaces.csv" | wc -l)
[ "$start_rows" -gt 0 ] || fail "no touching interface at t = 0"
awk -F, '$1 == "0" && $6 > 0 && ($6 != 4 || $9 != 4) { bad = 1 } END { exit bad }' "$tmp/full/interfaces.csv" \
  || fail "a joint at t = 0 does not count 4 bonded points"
# Bonds broke during the shaking.
awk -F, 'NR > 2 && $10 > 0 { found = 1 } END { exit !found }' "$tmp/full/interfaces.csv" \
  || fail "no broken point in interfaces.csv"

[ "$failures" -eq 0 ] && echo "test_sub_contacts: ok"
exit "$failures"
