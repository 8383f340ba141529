"""Reads a run's VTK output with VTK's own reader (Debian's python3-vtk9), not ours, and checks
that every frame holds one polygon per body with the right corners, the per-body and
per-contact fields, and the times listed in the .pvd collections.
Usage: check_vtk.py RUN_DIR EXPECTED_FRAMES [FIRST,LAST] (contact points in the first and last
frame; - for either: not checked)"""
import json
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import vtk

run, expected_frames = Path(sys.argv[1]), int(sys.argv[2])
bodies = json.loads((run / "bodies.json").read_text())["bodies"]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL", what)


def read(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    check(reader.GetErrorCode() == 0, f"{path.name}: read without error")
    return reader.GetOutput()


def frames(collection):
    root = ET.parse(run / "vtk" / collection).getroot()
    return [(float(d.get("timestep")), run / "vtk" / d.get("file")) for d in root.iter("DataSet")]


body_frames, contact_frames = frames("bodies.pvd"), frames("contacts.pvd")
check(len(body_frames) == expected_frames, f"{len(body_frames)} body frames, expected {expected_frames}")
check(len(contact_frames) == len(body_frames), "one contact file per body frame")
corners = sum(len(b["corners_m"]) for b in bodies)
contact_counts = []
for (t, path), (tc, cpath) in zip(body_frames, contact_frames):
    poly = read(path)
    check(poly.GetNumberOfPolys() == len(bodies), f"{path.name}: {poly.GetNumberOfPolys()} polygons, expected {len(bodies)}")
    check(poly.GetNumberOfPoints() == corners, f"{path.name}: {poly.GetNumberOfPoints()} points, expected {corners}")
    for k, b in enumerate(bodies):
        check(poly.GetCell(k).GetNumberOfPoints() == len(b["corners_m"]), f"{path.name}: polygon {k} corners")
    cells = poly.GetCellData()
    for name, comps in (("id", 1), ("kind", 1), ("velocity_m_s", 3), ("rotation_rad", 1), ("angular_velocity_rad_s", 1),
                        ("displacement_m", 3)):
        array = cells.GetArray(name)
        check(array is not None and array.GetNumberOfTuples() == len(bodies) and array.GetNumberOfComponents() == comps,
              f"{path.name}: cell array {name}")
    check(poly.GetPointData().GetArray("velocity_m_s") is not None, f"{path.name}: corner velocities")
    time = poly.GetFieldData().GetArray("TimeValue").GetValue(0)
    check(abs(time - t) < 1e-9 and abs(tc - t) < 1e-9, f"{path.name}: TimeValue {time} = pvd time {t}")
    contacts = read(cpath)
    n = contacts.GetNumberOfPoints()
    check(contacts.GetNumberOfVerts() == n, f"{cpath.name}: one vertex per contact point")
    for name in ("normal_force_n", "shear_force_n", "sliding", "overlap_m", "force_n", "normal", "body_a", "body_b"):
        array = contacts.GetPointData().GetArray(name)
        check(array is not None and array.GetNumberOfTuples() == n, f"{cpath.name}: point array {name}")
    if n:
        forces = contacts.GetPointData().GetArray("normal_force_n")
        check(min(forces.GetValue(i) for i in range(n)) >= 0.0, f"{cpath.name}: no tension")
    contact_counts.append(n)
print("contact points per frame:", " ".join(map(str, contact_counts)))
sys.stdout.flush()
if len(sys.argv) > 3:
    first, last = sys.argv[3].split(",")  # "-" checks nothing
    if first != "-":
        check(contact_counts[0] == int(first), f"contact points in the first frame: {contact_counts[0]}, expected {first}")
    if last != "-":
        check(contact_counts[-1] == int(last), f"contact points in the last frame: {contact_counts[-1]}, expected {last}")
print(f"{len(body_frames)} frames checked, {len(failures)} failures")
sys.exit(1 if failures else 0)
