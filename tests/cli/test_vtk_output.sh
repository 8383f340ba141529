#!/usr/bin/env bash
# VTK output: frames read back by VTK's own reader (python3-vtk9) hold one polygon per body with
# its corners and fields, and the contact points with their forces; the [output] keys switch
# the frames on and off (the "auto" rule included).
#   bash tests/cli/test_vtk_output.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
blockdem=$1 source_dir=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT

# Keys first: they need no view package.
"$blockdem" run "$source_dir/examples/paper/sliding.toml" --out "$work/off" -q --set output.vtk=false >/dev/null
[ ! -e "$work/off/vtk" ] || { echo "FAIL: vtk = false still wrote vtk/"; exit 1; }
# 2 bodies x 500001 frames is above the auto cap of 200000 body-frames: no frames.
"$blockdem" run "$source_dir/examples/paper/sliding.toml" --out "$work/auto" -q \
  --set simulation.duration=5 --set output.vtk_interval=1e-5 >/dev/null
[ ! -e "$work/auto/vtk" ] || { echo "FAIL: vtk = auto wrote frames above the cap"; exit 1; }
grep -q '"vtk": null' "$work/auto/summary.json" || { echo "FAIL: summary.json outputs.vtk should be null"; exit 1; }
if "$blockdem" check "$source_dir/examples/paper/sliding.toml" --set output.vtk_intervall=1 >/dev/null 2>"$work/err"; then
  echo "FAIL: a misspelt [output] key was accepted"; exit 1
fi
grep -q "did you mean 'vtk_interval'" "$work/err" || { echo "FAIL: no suggestion for the misspelt key"; cat "$work/err"; exit 1; }
echo "ok: [output] keys"

source "$source_dir/tests/cli/view_deps.sh"
need_package python3-vtk9 /usr/bin/python3 -c "import vtk"

# Two bodies dropped from the air: no contact points at first, 2 + 2 corners resting at the end.
"$blockdem" run "$source_dir/tests/cli/data/two_drops.toml" --out "$work/drops" -q >/dev/null
/usr/bin/python3 "$source_dir/tests/cli/check_vtk.py" "$work/drops" 11 0,4
# The paper's sliding block, default interval (0.04 s over 5 s: 126 frames); flat on the table at
# the end: 2 points (at t = 0 it only touches, with zero overlap).
"$blockdem" run "$source_dir/examples/paper/sliding.toml" --out "$work/sliding" -q >/dev/null
/usr/bin/python3 "$source_dir/tests/cli/check_vtk.py" "$work/sliding" 126 -,2
echo "VTK output checks passed"
