#!/usr/bin/env bash
# Bonded joints with rounded corners through a restart (docs/physics.md, "Rounded corners"): as
# test_restart_bonds.sh with [contact] rounding = 5 mm. A bonded wall on a driven course, shaken
# until some bonds break, run straight to T and stopped at T/2 then restarted from its state
# file: history.csv, energy.csv, summary.json and interfaces.csv are byte-identical. The run
# bonds the rounded joints at the start, breaks some bonds and reports them.
# Usage: test_restart_bonds_rounded.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
export OMP_WAIT_POLICY=passive
py=/usr/bin/python3

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
e = 0.5
rounding = 0.005
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

"$bin" run "$tmp/wall.toml" --out "$tmp/full" -q --threads 1 --save-state 0.15 > /dev/null 2> "$tmp/full.log" \
  || fail "full run: $(tail -2 "$tmp/full.log")"
state=$(ls "$tmp/full/state/"t_*.h5 2>/dev/null | head -1)
[ -n "$state" ] || fail "no state file in $tmp/full/state"
"$bin" run --restart "$state" --out "$tmp/restarted" -q --threads 2 > /dev/null 2> "$tmp/restarted.log" \
  || fail "restart: $(tail -2 "$tmp/restarted.log")"
for f in history.csv energy.csv summary.json interfaces.csv; do
  cmp -s "$tmp/full/$f" "$tmp/restarted/$f" || fail "$f differs between the straight run and the restarted one"
done

$py - "$tmp/full" <<'PY' || fail "the bonds are not reported"
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
print(f"bonded points at t = 0: {sum(int(r['bonded_points']) for r in first)}; interfaces with a broken bond: {len(broken)}")
PY

[ $failures -eq 0 ] && echo "bonded wall with rounded corners: restarted at T/2 gives identical files; bonds reported"
exit $((failures > 0))
