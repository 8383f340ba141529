#!/usr/bin/env bash
# Bonded joints through a restart (docs/physics.md, "Mohr-Coulomb joints and bonds"): a bonded
# wall on a driven course, shaken until some bonds break, run straight to T and stopped at T/2
# then restarted from its state file: history.csv, energy.csv, summary.json and interfaces.csv
# are byte-identical (the state file keeps every point's bond); the same with rounded corners. The run breaks some bonds and
# reports them (interfaces.csv, summary.json), books their energy, and draws them (VTK field
# "bond").
# Usage: test_restart_bonds.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
source "$(dirname "$0")/restart_check.sh"
export OMP_WAIT_POLICY=passive
py=/usr/bin/python3

# One bonded wall, sharp or with rounded corners (docs/physics.md, "Rounded corners"): the
# extra [contact] line is the only difference.
check_wall() {
  local name=$1 extra=$2 dir="$tmp/$1"
  mkdir -p "$dir"
  cat > "$dir/wall.toml" <<TOML
[simulation]
duration = 0.3
output_interval = 0.005
[contact]
stiffness = "per_length"
$extra
kn = 1.0e10
ks = 4.0e9
mu = 0.6
cohesion = 4.0e3
tensile_strength = 2.0e3
residual_mu = 0.5
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
vtk = true
vtk_interval = 0.1
[table_motion.horizontal]
type = "sine"
amplitude = 1.5
unit = "g"
period = 0.2
TOML

  restart_matches "$name" "$dir/wall.toml" "$dir" 0.15

  $py - "$dir/full" "$name" <<'PY' || fail "$name: the bonds are not reported"
import csv, json, sys, pathlib
d = pathlib.Path(sys.argv[1])
rows = [r for r in csv.DictReader(l for l in open(d / "interfaces.csv") if not l.startswith("#"))]
first = [r for r in rows if float(r["t"]) == 0.0]
assert sum(int(r["bonded_points"]) for r in first) > 0, "no bonded point at the start"
s = json.load(open(d / "summary.json"))
broken = [i for i in s["interfaces"]["list"] if i["first_break_time_s"] is not None]
assert broken, "the shaking broke no bond"
assert s["energy_j"]["bond_breakage_dissipated"] > 0.0, s["energy_j"]
vtp = sorted((d / "vtk").glob("contacts_*.vtp"))
assert vtp and 'Name="bond"' in vtp[-1].read_text(), "no bond field in the contacts' VTK"
print(f"{sys.argv[2]}: bonded points at t = 0: {sum(int(r['bonded_points']) for r in first)}; interfaces with a broken bond: {len(broken)}")
PY
}

check_wall sharp ""
check_wall rounded "rounding = 0.005"

# check prints the joint per unit length and the per-point stiffness of the start contacts:
# A running-bond bed joint overlaps half a 0.4 m brick; each of its two points carries half of
# that: JKN 1e10 Pa/m x 0.1 m x 1 m = 1e9 N/m.
out=$("$bin" check "$tmp/sharp/wall.toml" 2>&1)
grep -q "per unit length of joint: kn = 1e+10 Pa/m, ks = 4e+09 Pa/m" <<< "$out" || fail "check: no per-length kn, ks: $out"
grep -q "per-length joint: kn = 1e+09, ks = 4e+08 N/m per point" <<< "$out" || fail "check: no per-point stiffness of the start contacts"

[ $failures -eq 0 ] && echo "bonded wall, sharp and rounded: restarted at T/2 gives identical files; bonds reported"
exit $((failures > 0))
