"""Checks the report of a 3-D run folder against the run's own files (test_report_3d.sh).

  /usr/bin/python3 check_report_3d.py RUN_DIR TOOLS_DIR

- every number of the outcome table is summary.json's, as shown (4 significant digits), and the
  azimuths are those of summary.json's peak tilt axis;
- the .vtp reader: each body's vertex mean in the last frame is its centroid in summary.json
  (to the 9 digits the writer keeps), 6 faces a box, kinds in summary.json's order;
- the pictures' bodies (the first frame posed from history.csv) are the frames at their times;
- the lean direction and the tilt, measured at the peak from the slender block's own corners,
  agree with the table and with history.csv's tilt;
- a frame in another format, or with counts that do not match, is refused naming the file;
- the twist of a made-up turn (a twist about z, then a swing about a horizontal axis) is the
  twist, also past pi;
- the figures exist and are in the page; the plots end where history.csv ends.
Prints what failed and exits 1."""
import json
import math
import re
import sys
from html.parser import HTMLParser
from pathlib import Path

import numpy as np

run_dir, tools = Path(sys.argv[1]), Path(sys.argv[2])
sys.path.insert(0, str(tools))
from blockdem_view.run_folder_3d import RunFolder3d, azimuth_deg, twist_rad  # noqa: E402
from blockdem_view.vtp_reader import VtpFormatError, read_body_frame  # noqa: E402

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


class OutcomeCells(HTMLParser):
    """{body: {data-key: text}} of the outcome table."""

    def __init__(self):
        super().__init__()
        self.rows, self.body, self.key = {}, None, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "tr" and "data-body" in a:
            self.body = a["data-body"]
            self.rows[self.body] = {}
        elif tag == "td" and self.body and "data-key" in a:
            self.key = a["data-key"]
            self.rows[self.body][self.key] = ""

    def handle_endtag(self, tag):
        if tag == "td":
            self.key = None
        elif tag == "tr":
            self.body = None

    def handle_data(self, data):
        if self.body and self.key:
            self.rows[self.body][self.key] += data


def shown(text):
    """The first number of a cell."""
    match = re.search(r"[-+]?\d+(\.\d*)?(e[-+]?\d+)?", text)
    return float(match.group(0)) if match else None


def same(text, value, what):
    """The cell shows value to its 4 significant digits."""
    number = shown(text)
    ok = number is not None and abs(number - value) <= 5e-4 * abs(value) + 1e-300
    check(ok, f"{what}: shown {text!r}, summary.json {value!r}")


page = (run_dir / "report.html").read_text(encoding="utf-8")
summary = json.loads((run_dir / "summary.json").read_text(encoding="utf-8"))
parser = OutcomeCells()
parser.feed(page)
for b in summary["bodies"]:
    if b["kind"] != "dynamic":
        check(b["name"] not in parser.rows, f"{b['name']}: a {b['kind']} body in the outcome table")
        continue
    cells = parser.rows.get(b["name"])
    if cells is None:
        failures.append(f"{b['name']}: no row in the outcome table")
        continue
    name = b["name"]
    same(cells["peak_tilt_rad"], b["peak_tilt_rad"], f"{name} peak tilt")
    same(cells["peak_tilt_time_s"], b["peak_tilt_time_s"], f"{name} peak tilt time")
    same(cells["slip_x_m"], b["slip_m"][0], f"{name} slip x")
    same(cells["slip_y_m"], b["slip_m"][1], f"{name} slip y")
    same(cells["slip_length_m"], math.hypot(*b["slip_m"]), f"{name} |slip|")
    same(cells["peak_slip_m"], b["peak_slip_m"], f"{name} peak slip")
    check(cells["overturned"].startswith("yes" if b["overturned"] else "no"), f"{name} overturned: {cells['overturned']!r}")
    check(cells["outcome"].startswith(b["outcome"].replace("_", " ")), f"{name} outcome: {cells['outcome']!r}")
    ax, ay = b["peak_tilt_axis"][:2]
    same(cells["peak_tilt_axis_azimuth_deg"], math.degrees(math.atan2(ay, ax)) % 360, f"{name} axis azimuth")
    same(cells["lean_azimuth_deg"], math.degrees(math.atan2(-ax, ay)) % 360, f"{name} lean azimuth")
check(f"Balance error at the end: {summary['energy_j']['balance_error_relative']:.3g}" in page, "balance error")

run = RunFolder3d(run_dir)
kinds = run.kinds_by_index()
check(kinds == [b["kind"] for b in summary["bodies"]], f"kinds {kinds}")
last = run.frame_near(1e9)
check(abs(last.time_s - summary["time_s"]) < 1e-6, f"last frame at {last.time_s} s, run ends at {summary['time_s']} s")
body_of_face = last.face_body()
for index, b in enumerate(summary["bodies"]):
    faces = np.flatnonzero(body_of_face == index)
    check(len(faces) == 6, f"{b['name']}: {len(faces)} faces in the last frame")
    corners = np.unique(np.concatenate([last.connectivity[last.face_starts()[f]:last.offsets[f]] for f in faces]))
    centre = last.points_m[corners].mean(axis=0)
    check(np.abs(centre - b["position_m"]).max() < 1e-7, f"{b['name']}: vertex mean {centre}, summary {b['position_m']}")

# The pictures pose the first frame from history.csv: at a frame's own time they are that frame
# (the quaternion's convention, the centroids, the point-to-body map).
for time_s, path in run.frames[1:]:
    posed, written = run.bodies_at(time_s), read_body_frame(path, time_s)
    check(abs(posed.time_s - time_s) < 1e-9, f"no history row at the frame time {time_s}")
    error = np.abs(posed.points_m - written.points_m).max()
    check(error < 1e-7, f"posed at {time_s} s: {error:.3g} m from the frame")

# The slender block's own axis at its peak, from its initially bottom corners to its initially
# top ones (the writer keeps the vertex order from frame to frame).
slender = summary["bodies"].index(next(b for b in summary["bodies"] if b["name"] == "slender"))
first, peak = run.frame_near(0.0), run.bodies_at(summary["bodies"][slender]["peak_tilt_time_s"])


def corners_of(frame, index):
    faces = np.flatnonzero(frame.face_body() == index)
    ids = np.unique(np.concatenate([frame.connectivity[frame.face_starts()[f]:frame.offsets[f]] for f in faces]))
    return frame.points_m[ids]


start = corners_of(first, slender)
top = start[:, 2] > start[:, 2].mean()
now = corners_of(peak, slender)
up = now[top].mean(axis=0) - now[~top].mean(axis=0)
tilt = math.acos(up[2] / np.linalg.norm(up))
row_tilt = run.series("slender", "tilt_rad")[run.t_s == peak.time_s][0]
check(abs(tilt - row_tilt) < 1e-6, f"slender tilt from its corners {tilt}, history.csv's {row_tilt}")
lean = shown(parser.rows["slender"]["lean_azimuth_deg"])
measured = azimuth_deg(up)
gap = abs((measured - lean + 180) % 360 - 180)
# 2 degrees: the picture is at the output row nearest the peak (0.01 s apart), not at the peak's step.
check(gap < 2.0, f"slender leans towards {measured:.2f} deg in the picture, the table says {lean}")

# Twist of a made-up turn: q = swing (0.7 rad about a horizontal axis) * twist (about z).
for angle in (0.3, -1.2, 2.9):
    half_s, half_t = 0.35, angle / 2
    axis = np.array([math.cos(0.4), math.sin(0.4), 0.0])
    sw = np.array([math.cos(half_s), *(math.sin(half_s) * axis)])
    tw = np.array([math.cos(half_t), 0.0, 0.0, math.sin(half_t)])
    w = sw[0] * tw[0] - sw[1:] @ tw[1:]
    xyz = sw[0] * tw[1:] + tw[0] * sw[1:] + np.cross(sw[1:], tw[1:])
    got = twist_rad(np.array([w, -w]), np.array([xyz[2], -xyz[2]]))  # q and -q: the same turn
    check(np.allclose(got, angle, atol=1e-12), f"twist of a made-up turn: {got}, expected {angle}")
ramp = np.linspace(0.0, 9.0, 200)
check(np.allclose(twist_rad(np.cos(ramp / 2), np.sin(ramp / 2)), ramp, atol=1e-12), "twist is not unwrapped past pi")

# A frame the reader cannot read is refused naming the file: binary data, a polygon count that
# does not match the offsets.
text = run.frames[0][1].read_text(encoding="utf-8")
for label, bad in (("binary", text.replace('format="ascii"', 'format="binary"', 1)),
                   ("count", re.sub(r'NumberOfPolys="\d+"', 'NumberOfPolys="5"', text))):
    path = run_dir / f"bad_{label}.vtp"
    path.write_text(bad, encoding="utf-8")
    try:
        read_body_frame(path, 0.0)
        failures.append(f"{label}: a bad frame was read")
    except VtpFormatError as e:
        check(str(path) in str(e), f"{label}: the error does not name the file: {e}")
    path.unlink()

for stem in ("snapshots", "response", "table_motion", "energy"):
    check((run_dir / "figures" / f"{stem}.png").is_file(), f"no figures/{stem}.png")
    check(f"id='figure-{stem}'" in page, f"{stem} is not in the page")
data = json.loads(re.search(r'<script type="application/json" id="report-data">(.*?)</script>', page, re.S).group(1))
tilt_plot = next(p for p in data["plots"] if p["title"] == "Tilt")
check(abs(tilt_plot["rows"][-1][0] - float(run.t_s[-1])) < 1e-9, "the tilt plot does not end at history.csv's end")
column = tilt_plot["labels"].index("slender")
check(abs(tilt_plot["rows"][-1][column] - run.series("slender", "tilt_rad")[-1]) < 1e-6, "the tilt plot's last value")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
