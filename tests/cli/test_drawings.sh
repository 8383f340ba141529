#!/usr/bin/env bash
# Drawings in and out (docs/drawings.md), end to end: the DXF example (a wall of 13 stones on a
# shaken slab) runs; `blockdem export --dxf` writes its blocks at a saved time (the last, the
# nearest to --time, a state file or a VTK frame); the drawing at t = 0 read back through
# [[geometry]] gives the run's corners within 1e-9 m; a state file and a VTK frame of the same
# time give the same drawing within 1e-8 m; a run without saved times and a bad drawing are
# refused with exit status 2, naming the folder, or the file, the entity and its layer (an open
# polyline, also when it is its layer's only one; a coordinate that is not a finite number, with
# its line).
#   bash tests/cli/test_drawings.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
blockdem=$1 source_dir=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# The example, shortened, with VTK frames and a state file at its end.
"$blockdem" run "$source_dir/examples/dxf/stone_wall.toml" --out "$work/wall" -q --set simulation.duration=0.4 \
  --set output.vtk=true --save-state 0.4 >/dev/null
[ -s "$work/wall/state/t_0.400000s.h5" ] || fail "no state file at 0.4 s"

# Export: the last saved time (the state file at 0.4 s, exact), the frame at t = 0 and one nearest 0.1 s.
"$blockdem" export "$work/wall" --dxf "$work/last.dxf" > "$work/last.log"
grep -q "wrote .*last.dxf: 14 blocks on 2 layers (BLOCKS, GROUND), in m, at t = 0.4 s from .*t_0.400000s.h5" "$work/last.log" ||
  fail "export of the last time: $(cat "$work/last.log")"
"$blockdem" export "$work/wall" --dxf "$work/start.dxf" --time 0 > "$work/start.log"
grep -q "at t = 0 s from .*bodies_000000.vtp" "$work/start.log" || fail "export at t = 0: $(cat "$work/start.log")"
"$blockdem" export "$work/wall" --dxf "$work/early.dxf" --time 0.11 > "$work/early.log"
grep -q "at t = 0.12 s from .*bodies_000003.vtp" "$work/early.log" || fail "export nearest 0.11 s: $(cat "$work/early.log")"

# The t = 0 drawing read back through [[geometry]] (units m, the same layers) gives the bodies of
# the original run: bodies.json of a short run holds them in the drawing's order. (A drawing of
# a later time holds the contacts' overlaps, which a new run refuses at its start, as it should.)
cat > "$work/readback.toml" <<TOML
[simulation]
duration = 0.001
[contact]
kn = 1.0e8
ks = 1.0e8
mu = 0.6
e = 0.5
[[geometry]]
file = "$work/start.dxf"
units = "m"
[geometry.layers]
GROUND = { kind = "driven" }
BLOCKS = { density = 2200.0, thickness = 0.3 }
TOML
"$blockdem" run "$work/readback.toml" --out "$work/readback" -q --set output.vtk=false >/dev/null
/usr/bin/python3 - "$work" <<'PY'
import json, math, sys
work = sys.argv[1]
def corners(run):
    return [(b["assembly"], [(b["initial_centroid_m"][0] + x, b["initial_centroid_m"][1] + y) for x, y in b["corners_m"]])
            for b in json.load(open(f"{work}/{run}/bodies.json"))["bodies"]]
a, b = corners("wall"), corners("readback")
assert len(a) == len(b) == 14, (len(a), len(b))
assert [l for l, _ in a] == [l for l, _ in b], "layers differ"
# Each corner to its nearest (the first corner may differ); 1e-9 m: the issue's tolerance. The
# VTK frame keeps 9 significant digits, which hold the drawing's whole millimetres exactly.
w = max(min(math.dist(p, q) for q in cb) for (_, ca), (_, cb) in zip(a, b) for p in ca)
assert w < 1e-9, f"t = 0 round trip off by {w} m"
print(f"ok: t = 0 round trip through export and [[geometry]] within {w:.1e} m")
PY

# At 0.4 s: the export from the state file (exact) and from the VTK frame (9 digits) agree, and
# the stones have moved since t = 0 (the drawing is of the shaken wall).
rm -rf "$work/wall/state"
"$blockdem" export "$work/wall" --dxf "$work/last_vtk.dxf" --time 0.4 | grep -q "bodies_000010.vtp" || fail "VTK frame at 0.4 s"
/usr/bin/python3 - "$work" <<'PY'
import math, sys
work = sys.argv[1]
def polylines(file):
    lines = [l.strip() for l in open(file)]
    pairs = list(zip(lines[0::2], lines[1::2]))
    out, current = [], None
    for code, value in pairs:
        if code == "0":
            current = [] if value == "LWPOLYLINE" else None
            if current is not None: out.append(current)
        elif current is not None and code == "10": current.append([float(value), None])
        elif current is not None and code == "20": current[-1][1] = float(value)
    return out
state, vtk, start = (polylines(f"{work}/{n}.dxf") for n in ("last", "last_vtk", "start"))
assert len(state) == len(vtk) == len(start) == 14
w = max(math.dist(p, q) for a, b in zip(state, vtk) for p, q in zip(a, b))
assert w < 1e-8, f"state and VTK exports at 0.4 s differ by {w} m"
moved = max(math.dist(p, q) for a, b in zip(state, start) for p, q in zip(a, b))
assert moved > 1e-4, f"the stones did not move ({moved} m)"
print(f"ok: exports at 0.4 s from the state file and the VTK frame agree within {w:.1e} m; the stones moved up to {moved:.1e} m")
PY

# A run folder with nothing saved, and a bad drawing: exit status 2 with the reason.
"$blockdem" run "$source_dir/examples/dxf/stone_wall.toml" --out "$work/bare" -q --set simulation.duration=0.01 \
  --set output.vtk=false >/dev/null
set +e
"$blockdem" export "$work/bare" --dxf "$work/bare.dxf" 2>"$work/err"; status=$?
set -e
[ $status -eq 2 ] || fail "export of a run without frames: exit $status"
grep -q "the run saved no blocks to export" "$work/err" || fail "no reason: $(cat "$work/err")"
/usr/bin/python3 - "$source_dir/examples/dxf/stone_wall.dxf" "$work/open.dxf" <<'PY'
import sys
text = open(sys.argv[1]).read()
# The first stone (handle 102) drawn open: its closed flag (group 70 = 1) cleared.
at = text.index("  5\n102\n")
flag = text.index(" 70\n1\n", at)
open(sys.argv[2], "w").write(text[:flag] + " 70\n0\n" + text[flag + 6:])
PY
sed "s|stone_wall.dxf|$work/open.dxf|" "$source_dir/examples/dxf/stone_wall.toml" > "$work/open.toml"
set +e
"$blockdem" check "$work/open.toml" >/dev/null 2>"$work/err"; status=$?
set -e
[ $status -eq 2 ] || fail "an open polyline: exit $status"
grep -q "open.dxf: polyline (handle 102) on layer 'BLOCKS' is open" "$work/err" || fail "open polyline message: $(cat "$work/err")"
# The slab (handle 101), the only polyline of layer GROUND, drawn open: the polyline is named, not
# the layer as missing (it said "no closed outline on layer 'GROUND' (did you mean 'GROUND'?)").
/usr/bin/python3 - "$source_dir/examples/dxf/stone_wall.dxf" "$work" <<'PY'
import sys
text = open(sys.argv[1]).read()
at = text.index("  5\n101\n")
flag = text.index(" 70\n1\n", at)
open(sys.argv[2] + "/open_slab.dxf", "w").write(text[:flag] + " 70\n0\n" + text[flag + 6:])
# Stone 102's first x coordinate '4x0' (dxflib read it as 4), and the slab's a NaN (dxflib dropped the corner).
at = text.index("  5\n102\n")
x = text.index(" 10\n", at) + 4
end = text.index("\n", x)
open(sys.argv[2] + "/badnum.dxf", "w").write(text[:x] + "4x0" + text[end:])
print(text[:x].count("\n") + 1, file=open(sys.argv[2] + "/badnum.line", "w"))
x = text.index(" 10\n", text.index("  5\n101\n")) + 4
open(sys.argv[2] + "/nan.dxf", "w").write(text[:x] + "nan" + text[text.index("\n", x):])
PY
for case in open_slab badnum nan; do
  sed "s|stone_wall.dxf|$work/$case.dxf|" "$source_dir/examples/dxf/stone_wall.toml" > "$work/$case.toml"
done
set +e
"$blockdem" check "$work/open_slab.toml" >/dev/null 2>"$work/err"; status=$?
set -e
[ $status -eq 2 ] || fail "the only polyline of a layer open: exit $status"
grep -q "open_slab.dxf: polyline (handle 101) on layer 'GROUND' is open: a block is a closed polyline (close it in the drawing)" \
  "$work/err" || fail "open slab message: $(cat "$work/err")"
! grep -q "did you mean" "$work/err" || fail "a layer guessed: $(cat "$work/err")"
set +e
"$blockdem" check "$work/badnum.toml" >/dev/null 2>"$work/err"; status=$?
set -e
[ $status -eq 2 ] || fail "a coordinate '4x0': exit $status"
grep -qF "badnum.dxf: line $(cat "$work/badnum.line"): group 10 of the LWPOLYLINE (handle 102) holds '4x0', which is not a number" \
  "$work/err" || fail "'4x0' message: $(cat "$work/err")"
set +e
"$blockdem" check "$work/nan.toml" >/dev/null 2>"$work/err"; status=$?
set -e
[ $status -eq 2 ] || fail "a coordinate 'nan': exit $status"
grep -qF "group 10 of the LWPOLYLINE (handle 101) holds 'nan', which is not a finite number" "$work/err" ||
  fail "'nan' message: $(cat "$work/err")"
echo "drawing checks passed"
