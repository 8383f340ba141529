#!/usr/bin/env bash
# End-to-end: 3-D scenarios (dimension = 3, docs/3d.md). The drum column example runs; its
# history.csv, energy.csv, summary.json and VTK polygons exist and parse, with the columns, rows
# and frames the scenario asks for, faces turned outward, the same bytes at 1 and 2 threads; a
# slender block overturns about the axis across the shaking; bad scenarios exit with status 2
# naming the file and the key or the bodies: an unknown key, overlapping bodies, a non-convex
# polyhedron, a dt above the stable bound, a record of two components where three are asked; a
# ledger that stops closing or a block sinking into the table ends the run with status 3; a 2-D command refuses a 3-D file; Ctrl-C leaves whole files and status "interrupted"; a light block
# landing on a heavy one with dt above its contacts' stable bound is reported (the live stable step),
# with its energy balance error above 1 %; a block on soft springs reports its deepest overlap
# (summary.json checks.overlap and a warning).
# Usage: test_run_3d.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1
src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }

# 1. The example, shortened to 0.3 s: files and their contents.
"$bin" run "$src/examples/3d/drum_column.toml" --out "$tmp/run" --set simulation.duration=0.3 -q >"$tmp/out.txt" 2>&1 \
    || fail "the drum column example failed: $(cat "$tmp/out.txt")"
for f in history.csv energy.csv summary.json scenario.toml vtk/bodies.pvd vtk/bodies_000000.vtp; do
    [[ -s "$tmp/run/$f" ]] || fail "missing $f"
done
/usr/bin/python3 - "$tmp/run" <<'PY' || fail "the outputs do not parse as expected"
import csv, json, math, sys, xml.etree.ElementTree as ET
run = sys.argv[1]
rows = list(csv.reader(open(f"{run}/history.csv")))
header = rows[0]
assert header[0] == "t_s", header[:3]
for body in ("table", "drum_1", "drum_2", "drum_3"):
    for col in ("x_m", "qw", "qz", "rx_rad", "tilt_rad", "vz_m_s"):
        assert f"{body}.{col}" in header, (body, col)
# output_interval 0.005 s over 0.3 s: rows at 0, 0.005, ..., 0.3
assert len(rows) - 1 == 61, len(rows)
assert all(len(r) == len(header) for r in rows[1:])
last = dict(zip(header, map(float, rows[-1])))
assert abs(last["t_s"] - 0.3) < 1e-9, last["t_s"]
q = [last[f"drum_3.q{c}"] for c in "wxyz"]
assert abs(sum(v * v for v in q) - 1.0) < 1e-12, q
energy = list(csv.reader(open(f"{run}/energy.csv")))
assert energy[0][0] == "t_s" and energy[0][-1] == "balance_error" and len(energy) == len(rows), energy[0]
s = json.load(open(f"{run}/summary.json"))
assert s["status"] == "completed" and s["dimension"] == 3, s["status"]
assert s["dt_s"] <= 0.5 * s["critical_dt_s"] * (1 + 1e-12), (s["dt_s"], s["critical_dt_s"])
names = [b["name"] for b in s["bodies"]]
assert names == ["table", "drum_1", "drum_2", "drum_3"], names
for b in s["bodies"][1:]:
    assert b["overturned"] is False and len(b["slip_m"]) == 2 and b["peak_tilt_rad"] >= 0.0, b
assert s["energy_j"]["balance_error_relative"] < 1e-3, s["energy_j"]
pvd = ET.parse(f"{run}/vtk/bodies.pvd").getroot()
frames = pvd.findall(".//DataSet")
assert len(frames) == s["vtk_frames"] == 8, len(frames)   # every 0.04 s over 0.3 s
piece = ET.parse(f"{run}/vtk/{frames[-1].get('file')}").getroot().find(".//Piece")
# 6 faces of the table, 16 + 2 of each 16-sided drum; 8 + 3 x 32 points
assert piece.get("NumberOfPolys") == str(6 + 3 * 18) and piece.get("NumberOfPoints") == str(8 + 3 * 32), piece.attrib
offsets = piece.find(".//DataArray[@Name='offsets']").text.split()
connectivity = piece.find(".//DataArray[@Name='connectivity']").text.split()
assert int(offsets[-1]) == len(connectivity) == 6 * 4 + 3 * (16 * 4 + 2 * 16)
# Faces counter-clockwise seen from outside: the signed volume they enclose (divergence theorem,
# each face a fan) is the bodies' volume, 2 x 2 x 0.2 m plus three 16-gon drums (round-off of
# the 9 digits written).
xyz = [float(v) for v in piece.find(".//Points/DataArray").text.split()]
p = [xyz[k:k + 3] for k in range(0, len(xyz), 3)]
cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
volume, start = 0.0, 0
for end in map(int, offsets):
    face = [p[int(i)] for i in connectivity[start:end]]
    for k in range(1, len(face) - 1):
        volume += sum(x * y for x, y in zip(face[0], cross(face[k], face[k + 1]))) / 6.0
    start = end
expected = 0.8 + 3 * 8 * 0.09 * math.sin(2 * math.pi / 16) * 0.5
assert abs(volume - expected) < 1e-7 * expected, (volume, expected)
PY
# ParaView's own reader (Debian python3-vtk9, in the Makefile's list) reads the frame.
/usr/bin/python3 - "$tmp/run/vtk/bodies_000007.vtp" <<'PY' || fail "VTK's reader does not read the frame as written"
import sys
import vtk
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
mesh = reader.GetOutput()
assert mesh.GetNumberOfCells() == 60 and mesh.GetNumberOfPoints() == 104, (mesh.GetNumberOfCells(), mesh.GetNumberOfPoints())
for name in ("body", "tilt_rad", "speed_m_s"):
    assert mesh.GetCellData().GetArray(name).GetNumberOfTuples() == 60, name
PY
# The contact frames ([output] vtk_contacts, on by default as in 2-D), read by VTK's reader: one
# vertex a point, unit normals from a to b, the normal force the force's component along the
# normal; listed in contacts.pvd as the bodies' frames are; none with vtk_contacts = false.
/usr/bin/python3 - "$tmp/run/vtk" <<'PY' || fail "the 3-D contact frames"
import sys, xml.etree.ElementTree as ET
import vtk
folder = sys.argv[1]
listed = [d.get("file") for d in ET.parse(f"{folder}/contacts.pvd").getroot().findall(".//DataSet")]
assert listed == [f"contacts_{k:06d}.vtp" for k in range(8)], listed
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(f"{folder}/contacts_000007.vtp")
reader.Update()
mesh = reader.GetOutput()
n = mesh.GetNumberOfPoints()
assert n > 0 and mesh.GetNumberOfCells() == n, (n, mesh.GetNumberOfCells())
data = mesh.GetPointData()
for name in ("normal_force_n", "shear_force_n", "overlap_m", "sliding", "body_a", "body_b", "normal", "force_n"):
    assert data.GetArray(name).GetNumberOfTuples() == n, name
for k in range(n):
    nx, ny, nz = data.GetArray("normal").GetTuple3(k)
    assert abs(nx * nx + ny * ny + nz * nz - 1.0) < 1e-6, (nx, ny, nz)
    fx, fy, fz = data.GetArray("force_n").GetTuple3(k)
    assert abs(fx * nx + fy * ny + fz * nz - data.GetArray("normal_force_n").GetValue(k)) < 1e-6 * (1 + abs(fz)), k
    assert data.GetArray("body_a").GetValue(k) < data.GetArray("body_b").GetValue(k)
PY
"$bin" run "$src/examples/3d/drum_column.toml" --out "$tmp/nocontacts" --set simulation.duration=0.05 --set output.vtk_contacts=false -q \
    >/dev/null 2>&1 || fail "vtk_contacts = false refused"
ls "$tmp/nocontacts/vtk/"contacts* >/dev/null 2>&1 && fail "vtk_contacts = false still writes contact frames"
"$bin" run "$src/examples/3d/drum_column.toml" --out "$tmp/badflag" --set simulation.duration=0.05 --set output.vtk_contacts=3 -q \
    >"$tmp/badflag.log" 2>&1
[[ $? -eq 2 ]] && grep -q "output.vtk_contacts': must be true or false" "$tmp/badflag.log" \
    || fail "vtk_contacts = 3 is not refused by name: $(cat "$tmp/badflag.log")"

# The same bytes at 1 and 2 threads (world/parallel.hpp's rules carry through the run).
"$bin" run "$src/examples/3d/drum_column.toml" --out "$tmp/run2" --set simulation.duration=0.3 -q -j 2 >/dev/null 2>&1 \
    || fail "the drum column at 2 threads failed"
"$bin" run "$src/examples/3d/drum_column.toml" --out "$tmp/run1" --set simulation.duration=0.3 -q -j 1 >/dev/null 2>&1 \
    || fail "the drum column at 1 thread failed"
for f in history.csv energy.csv vtk/bodies_000007.vtp vtk/contacts_000007.vtp; do
    cmp -s "$tmp/run1/$f" "$tmp/run2/$f" || fail "$f differs between 1 and 2 threads"
done

# A minimal scenario to break one key at a time.
cat > "$tmp/box.toml" <<'TOML'
dimension = 3
[simulation]
duration = 0.01
[contact]
kn = 1e6
ks = 1e6
mu = 0.5
[[bodies]]
name = "table"
kind = "fixed"
shape = "box"
size = [2.0, 2.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "block"
shape = "box"
size = [0.4, 0.4, 0.8]
position = [0.0, 0.0, 0.4]
density = 2000.0
TOML
"$bin" run "$tmp/box.toml" --out "$tmp/box" -q >/dev/null 2>&1 || fail "the minimal box scenario failed"

# A slender block (0.2 x 0.2 x 1 m) under a 0.6 g one-sine pulse along y overturns about x;
# its overturning angle is atan(0.1 / 0.5); its slip is along y only.
cat > "$tmp/topple.toml" <<'TOML'
dimension = 3
[simulation]
duration = 3.0
[contact]
kn = 1e7
ks = 1e7
mu = 0.8
e = 0.5
[[bodies]]
name = "table"
kind = "driven"
shape = "box"
size = [4.0, 4.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "slender"
shape = "box"
size = [0.2, 0.2, 1.0]
position = [0.0, 0.0, 0.5]
density = 2000.0
[table_motion.y]
type = "one_sine"
amplitude = 0.6
unit = "g"
period = 0.8
TOML
"$bin" run "$tmp/topple.toml" --out "$tmp/topple" -q >/dev/null 2>&1 || fail "the toppling block failed"
/usr/bin/python3 - "$tmp/topple/summary.json" <<'PY' || fail "the slender block's summary"
import json, math, sys
b = json.load(open(sys.argv[1]))["bodies"][1]
assert b["overturned"] is True, b
assert abs(b["overturning_angle_rad"] - math.atan(0.2)) < 1e-12, b["overturning_angle_rad"]
assert b["peak_tilt_rad"] > 1.4 and abs(abs(b["peak_tilt_axis"][0]) - 1.0) < 1e-6, b
assert abs(b["slip_m"][0]) < 1e-9 and abs(b["slip_m"][1]) > 0.1, b["slip_m"]
# The overturning time (as in 2-D: the last outward crossing of the limit) lies between the last
# history row still inside the limit and the first one past it, and every later row stays past.
import csv, pathlib
rows = list(csv.DictReader(open(pathlib.Path(sys.argv[1]).parent / "history.csv")))
t_over, limit = b["overturning_time_s"], b["overturning_angle_rad"]
tilts = [(float(r["t_s"]), float(r[b["name"] + ".tilt_rad"])) for r in rows]
inside = [t for t, tilt in tilts if tilt <= limit]
assert inside and inside[-1] <= t_over, (inside[-1:], t_over)
after = [tilt for t, tilt in tilts if t > t_over]
assert after and min(after) > limit and t_over - inside[-1] < 0.05, (t_over, inside[-1])
PY

refused() {  # refused NAME EXPECTED... (the scenario in $tmp/bad.toml)
    local name=$1; shift
    out=$("$bin" run "$tmp/bad.toml" --out "$tmp/bad_$name" -q 2>&1); status=$?
    [[ $status -eq 2 ]] || fail "$name: exit status $status, expected 2: $out"
    for e in "$@"; do expect_in "$out" "$e"; done
}

sed 's/^size = \[0.4, 0.4, 0.8\]/sise = [0.4, 0.4, 0.8]/' "$tmp/box.toml" >"$tmp/bad.toml"
refused unknown_key "bad.toml" "bodies.block" "sise"

sed 's/^position = \[0.0, 0.0, 0.4\]/position = [0.0, 0.0, 0.35]/' "$tmp/box.toml" >"$tmp/bad.toml"
refused overlap "bad.toml" "'table'" "'block'" "overlap at the start"

cat "$tmp/box.toml" - >"$tmp/bad.toml" <<'TOML'
[[bodies]]
name = "dented"
shape = "polyhedron"
vertices = [[2, 0, 0], [3, 0, 0], [2, 1, 0], [3, 1, 0], [2, 0, 1], [3, 0, 1], [2, 1, 1], [3, 1, 1], [2.5, 0.5, 0.5]]
density = 2000.0
TOML
refused non_convex "bad.toml" "key 'bodies.dented'" "body 'dented'" "vertex 8"

sed 's/^duration = 0.01/duration = 0.01\ndt = 0.01/' "$tmp/box.toml" >"$tmp/bad.toml"
refused dt "bad.toml" "simulation.dt" "stable limit"

printf 'time,NS,EW\n' >"$tmp/two.csv"
for k in $(seq 0 100); do printf '%s,0.01,-0.01\n' "$(awk "BEGIN{print $k * 0.01}")" >>"$tmp/two.csv"; done
cat "$tmp/box.toml" - >"$tmp/bad.toml" <<TOML
[table_motion.record]
file = "two.csv"
unit = "g"
components = ["NS", "EW", "UD"]
TOML
refused two_components "two.csv" "UD"

# A ledger that stops closing ends the run as in 2-D: exit status 3, summary.json "failed".
out=$("$bin" run "$tmp/box.toml" --out "$tmp/unstable" --set simulation.max_energy_error=1e-12 --set simulation.duration=0.1 -q 2>&1); status=$?
[[ $status -eq 3 ]] || fail "energy stop: exit status $status, expected 3: $out"
expect_in "$out" "energy balance error"
grep -q '"status": "failed"' "$tmp/unstable/summary.json" || fail "energy stop: summary.json not failed"

# Springs far too soft for the block (kn = 10 N/m a point): it sinks, and the run stops as in 2-D.
out=$("$bin" run "$tmp/box.toml" --out "$tmp/soft" --set contact.kn=10 --set simulation.dt=1e-3 --set simulation.duration=0.5 -q 2>&1); status=$?
[[ $status -eq 3 ]] || fail "overlap stop: exit status $status, expected 3: $out"
expect_in "$out" "penetration: bodies 'table' and 'block'"

out=$("$bin" limit "$tmp/box.toml" 2>&1); status=$?
[[ $status -eq 2 ]] || fail "limit on a 3-D scenario: exit status $status, expected 2: $out"
expect_in "$out" "dimension"

# Ctrl-C (SIGINT) in the middle of a 3-D run: exit status 130, summary.json "interrupted",
# history.csv and energy.csv end at whole rows of their header's width.
"$bin" run "$src/examples/3d/brick_wall.toml" --out "$tmp/int" -q >"$tmp/int.txt" 2>&1 &
pid=$!
for _ in $(seq 200); do [[ -s "$tmp/int/history.csv" ]] && break; sleep 0.05; done
sleep 0.5
kill -s INT $pid
wait $pid; status=$?
[[ $status -eq 130 ]] || fail "SIGINT: exit status $status, expected 130: $(cat "$tmp/int.txt")"
/usr/bin/python3 - "$tmp/int" <<'PY' || fail "the interrupted 3-D run's files are not whole"
import csv, json, sys
folder = sys.argv[1]
assert json.load(open(f"{folder}/summary.json"))["status"] == "interrupted"
for name in ("history.csv", "energy.csv"):
    text = open(f"{folder}/{name}").read()
    assert text.endswith("\n"), name
    rows = list(csv.reader(text.splitlines()))
    assert len(rows) >= 2 and all(len(r) == len(rows[0]) for r in rows), name
PY

# The live stable step (docs/3d.md, "The run"): three 0.3 m cubes of 54 kg dropped from 1 mm gaps
# onto each other and the table. None touches anything at t = 0, so the start's limit is that of a
# cube landing flat on the table alone (3.59e-4 s: world/world_3d_start.hpp), and the default dt
# is half of it; stacked, their highest mode is stiffer (1.5e-4 s), and dt is above its limit: the
# run says so (summary.json checks and warnings, and on stderr), naming the body and when, and the
# ledger's error above 1 % with it. With dt well below the same run has nothing to say.
cat > "$tmp/stack.toml" <<'TOML'
dimension = 3
[simulation]
duration = 0.3
output_interval = 0.01
[contact]
kn = 1e7
ks = 1e7
mu = 0.5
e = 0.5
[[bodies]]
name = "table"
kind = "fixed"
shape = "box"
size = [2.0, 2.0, 0.2]
position = [0.0, 0.0, -0.1]
TOML
for cube in "low 0.151" "middle 0.452" "top 0.753"; do  # (name, centre height [m]: 1 mm gaps)
    read -r name height <<<"$cube"
    printf '[[bodies]]\nname = "%s"\nshape = "box"\nsize = [0.3, 0.3, 0.3]\nposition = [0.0, 0.0, %s]\ndensity = 2000.0\n' \
        "$name" "$height" >>"$tmp/stack.toml"
done
out=$("$bin" run "$tmp/stack.toml" --out "$tmp/stack" -q 2>&1); status=$?
[[ $status -eq 0 ]] || fail "the dropped stack: exit status $status, expected 0 (a warning, not a stop): $out"
expect_in "$out" "above the stable limit of the live contacts"
"$bin" run "$tmp/stack.toml" --out "$tmp/stack_fine" --set simulation.dt=2e-5 -q >"$tmp/stack_fine.txt" 2>&1 \
    || fail "the dropped stack at dt = 2e-5 s failed: $(cat "$tmp/stack_fine.txt")"
/usr/bin/python3 - "$tmp/stack" "$tmp/stack_fine" <<'PY' || fail "the live stable step is not reported as expected"
import json, sys
coarse = json.load(open(f"{sys.argv[1]}/summary.json"))
step = coarse["checks"]["time_step"]
# Nothing touches at the start: the limit is a cube's landing flat on the table, 3.5949e-4 s
# (the proven bound below it), and dt half of it, rounded down to whole steps of the output interval.
assert abs(step["stable_limit_at_start_s"] - 3.5949e-4) < 1e-4 * 3.5949e-4, step
assert step["proven_stable_below_s"] < step["stable_limit_at_start_s"], step
assert 0.98 * 0.5 * 3.5949e-4 < step["dt_s"] <= 0.5 * step["stable_limit_at_start_s"] * (1 + 1e-12), step
assert step["dt_above_live_limit"] is True and step["least_live_limit_body"] in ("low", "middle", "top"), step
# The lowest gap closes after sqrt(2 x 0.001 / 9.81) = 0.014 s; the watch looks every 32 steps.
assert 0.014 < step["dt_above_live_limit_from_s"] < 0.3, step
assert step["least_live_limit_s"] < step["dt_s"] < step["stable_limit_at_start_s"], step
assert any("live contacts" in w for w in coarse["warnings"]), coarse.get("warnings")
energy = coarse["checks"]["energy"]
assert energy["balance_error_relative"] > 0.01 and energy["warning_ratio"] == 0.01 and energy["stop_ratio"] == 0.5, energy
assert any("energy balance error is" in w for w in coarse["warnings"]), coarse.get("warnings")
fine = json.load(open(f"{sys.argv[2]}/summary.json"))
step = fine["checks"]["time_step"]
assert step["dt_above_live_limit"] is False and step["dt_above_live_limit_from_s"] is None, step
assert step["dt_s"] < step["least_live_limit_s"], step
assert fine["checks"]["energy"]["balance_error_relative"] < 0.01, fine["checks"]["energy"]
assert "warnings" not in fine, fine["warnings"]
PY
expect_in "$out" "energy balance error is"

# The deepest overlap (summary.json checks.overlap, a warning above 1 % of the thinner body's
# least width): a 10 cm cube of 1 kg placed on the table on four corner springs of 1000 N/m sinks
# to 9.81 / 4000 = 2.45 mm at rest, and, let go at the springs' ends, overshoots to at most twice
# that (undamped; e = 0.5 damps it): 2.5 to 4.9 % of its width, a warning, not a stop.
cat > "$tmp/soft_block.toml" <<'TOML'
dimension = 3
[simulation]
duration = 0.3
dt = 2e-4
output_interval = 0.01
[contact]
kn = 1000.0
ks = 1000.0
mu = 0.5
e = 0.5
[[bodies]]
name = "table"
kind = "fixed"
shape = "box"
size = [1.0, 1.0, 0.1]
position = [0.0, 0.0, -0.05]
[[bodies]]
name = "block"
shape = "box"
size = [0.1, 0.1, 0.1]
position = [0.0, 0.0, 0.05]
density = 1000.0
TOML
out=$("$bin" run "$tmp/soft_block.toml" --out "$tmp/soft_block" -q 2>&1); status=$?
[[ $status -eq 0 ]] || fail "the soft block: exit status $status, expected 0 (a warning, not a stop): $out"
expect_in "$out" "WARNING: bodies 'table' and 'block' overlapped by"
/usr/bin/python3 - "$tmp/soft_block" <<'PY' || fail "the deepest overlap is not reported as expected"
import json, sys
summary = json.load(open(f"{sys.argv[1]}/summary.json"))
overlap = summary["checks"]["overlap"]
assert overlap["bodies"] == ["table", "block"], overlap
static_m = 9.81 / 4000.0
assert static_m < overlap["max_m"] < 2.0 * static_m, overlap
assert abs(overlap["max_ratio"] - overlap["max_m"] / 0.1) < 1e-12, overlap
assert overlap["warning_ratio"] == 0.01 and overlap["limit_ratio"] == 0.25, overlap
assert 0.0 < overlap["time_s"] < 0.3, overlap
assert len(summary["warnings"]) == 1 and "soft for their load" in summary["warnings"][0], summary["warnings"]
PY

if [[ $failures -gt 0 ]]; then echo "$failures failure(s)"; exit 1; fi
echo "test_run_3d: all passed"
