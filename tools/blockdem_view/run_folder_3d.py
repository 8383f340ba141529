"""A 3-D run folder (docs/3d.md, "Outputs") read into arrays: history.csv (per body the centroid,
the turn since t = 0 as a quaternion and a rotation vector, the tilt, the velocity), energy.csv,
summary.json, scenario.toml and the VTK frames' list."""
import tomllib
from pathlib import Path

import numpy as np

from .run_folder import RunFolderError, _read_csv, _read_json
from .vtp_reader import BodyFrame, VtpFormatError, read_body_frame, read_collection

MAX_READ = 60  # bodies whose history.csv columns are read (the largest peak tilts), besides the table


def twist_rad(qw, qz):
    """Rotation about the vertical [rad], counter-clockwise seen from above, unwrapped over time.

    The turn q is split as q = swing * twist, the twist about z applied first and the swing about
    a horizontal axis after it (the tilt); then twist = 2 atan2(qz, qw) exactly, since a swing has
    no z part. Unlike the rotation vector's z component it does not mix in the tilt."""
    sign = np.where(qw < 0.0, -1.0, 1.0)  # q and -q are the same turn
    return np.unwrap(2.0 * np.arctan2(sign * qz, sign * qw))


def rotate(q, v):
    """Each row of v (n x 3) turned by the unit quaternion in the same row of q (n x 4, w first):
    v + 2 w (u x v) + 2 u x (u x v), with u the vector part."""
    w, u = q[:, :1], q[:, 1:]
    uv = np.cross(u, v)
    return v + 2.0 * w * uv + 2.0 * np.cross(u, uv)


def azimuth_deg(vector):
    """The direction of a horizontal vector [deg], from +x towards +y (counter-clockwise seen from
    above), in [0, 360); None for a zero vector."""
    x, y = float(vector[0]), float(vector[1])
    if x == 0.0 and y == 0.0:
        return None
    return float(np.degrees(np.arctan2(y, x))) % 360.0


class RunFolder3d:
    """The files of one 3-D run, with the quantities the report shows."""

    def __init__(self, folder):
        self.path = Path(folder)
        for name in ("history.csv", "summary.json"):
            if not (self.path / name).is_file():
                raise RunFolderError(f"{self.path}: no {name} (is this a folder written by `blockdem run`?)")
        self.summary = _read_json(self.path / "summary.json")
        if not isinstance(self.summary, dict):
            raise RunFolderError(f"{self.path / 'summary.json'}: not a run's summary (no object at its top)")
        self.bodies = self.summary.get("bodies", [])
        self.columns = self._read_history(self.path / "history.csv")
        self.t_s = self.columns["t_s"]
        self.energy = None
        if (self.path / "energy.csv").is_file():
            header, data = _read_csv(self.path / "energy.csv")
            self.energy = {name: data[:, k] for k, name in enumerate(header)}
        scenario = self.path / "scenario.toml"
        self.scenario_text = scenario.read_text(encoding="utf-8") if scenario.is_file() else ""
        try:
            self.scenario = tomllib.loads(self.scenario_text)
        except tomllib.TOMLDecodeError:
            self.scenario = {}
        self.frames = self._frame_list()

    def _read_history(self, path):
        """history.csv's columns, of every body on a run of up to MAX_READ bodies; above, of the
        table and of the MAX_READ largest peak tilts only (a 1e4-body run writes 15 columns a
        body: parsing them all would take most of the report's time and memory)."""
        try:
            with open(path, encoding="utf-8") as f:
                header = f.readline().strip().split(",")
        except UnicodeDecodeError as e:
            raise RunFolderError(f"{path}: not a CSV file of numbers under a header line: {e}") from e
        if not header or header[0] != "t_s":
            raise RunFolderError(f"{path}: the first column is not t_s")
        dynamic = sorted((b for b in self.bodies if b.get("kind") == "dynamic"), key=lambda b: -b.get("peak_tilt_rad", 0.0))
        wanted = None
        if len(dynamic) > MAX_READ:
            names = {b["name"] for b in dynamic[:MAX_READ]} | {b["name"] for b in self.bodies if b.get("kind") == "driven"}
            wanted = [k for k, c in enumerate(header) if k == 0 or c.rsplit(".", 1)[0] in names]
        _, data = _read_csv(path, usecols=wanted)
        if data.shape[0] == 0:
            raise RunFolderError(f"{path}: no rows")
        names = header if wanted is None else [header[k] for k in wanted]
        return {name: data[:, k] for k, name in enumerate(names)}

    def _frame_list(self):
        pvd = self.path / "vtk" / "bodies.pvd"
        if not pvd.is_file():
            return []
        try:
            return [(t, p) for t, p in read_collection(pvd) if p.is_file()]
        except VtpFormatError as e:
            raise RunFolderError(str(e)) from e

    def title(self):
        return str(self.scenario.get("title", self.path.name))

    # ----- bodies -----
    def names(self, kind=None):
        return [b["name"] for b in self.bodies if kind is None or b["kind"] == kind]

    def response(self, name):
        """The summary.json entry of a body."""
        return next(b for b in self.bodies if b["name"] == name)

    def kinds_by_index(self):
        """Each body's kind in the order of summary.json, which is the VTK frames' body index."""
        return [b["kind"] for b in self.bodies]

    def table_name(self):
        """A driven body: every driven body follows the table's motion, so any one gives it."""
        driven = [n for n in self.names("driven") if self.has_series(n)]
        return driven[0] if driven else None

    def has_series(self, name):
        return f"{name}.x_m" in self.columns

    def ranked_dynamic(self, limit=None):
        """Dynamic bodies in history.csv, the largest peak tilt first (the ones to look at)."""
        names = [n for n in self.names("dynamic") if self.has_series(n)]
        names.sort(key=lambda n: -self.response(n).get("peak_tilt_rad", 0.0))
        return names if limit is None else names[:limit]

    # ----- time histories -----
    def series(self, name, field):
        """history.csv column <body>.<field> (x_m, y_m, z_m, qw .. qz, rx_rad .. rz_rad, tilt_rad, vx_m_s ..)."""
        return self.columns[f"{name}.{field}"]

    def table_displacement_m(self, axis):
        """The table's displacement since t = 0 along x, y or z [m]; zeros with no driven body."""
        table = self.table_name()
        if table is None:
            return np.zeros_like(self.t_s)
        u = self.series(table, f"{axis}_m")
        return u - u[0]

    def slip_m(self, name, axis):
        """Horizontal centroid displacement relative to the table since t = 0 [m] (summary.json's slip_m)."""
        u = self.series(name, f"{axis}_m")
        return u - u[0] - self.table_displacement_m(axis)

    def twist_rad(self, name):
        return twist_rad(self.series(name, "qw"), self.series(name, "qz"))

    def table_acceleration_m_s2(self, axis):
        """The table's acceleration along x, y or z [m/s^2]: history.csv has its velocity at each
        output time (exact, from the motion), differentiated here by central differences, so a
        record is seen through the output interval."""
        table = self.table_name()
        v = self.series(table, f"v{axis}_m_s")
        return np.gradient(v, self.t_s) if len(v) > 1 else np.zeros_like(v)

    # ----- frames -----
    def frame_near(self, time_s):
        """The VTK frame nearest to time_s, read; None when no frames were written."""
        if not self.frames:
            return None
        t, path = min(self.frames, key=lambda f: abs(f[0] - time_s))
        try:
            return read_body_frame(path, t)
        except VtpFormatError as e:
            raise RunFolderError(str(e)) from e

    def bodies_at(self, time_s):
        """The bodies at the history row nearest time_s: the first frame's faces moved by each body's
        centroid and turn since t = 0 from history.csv (a corner at t is x(t) + R(q(t)) (corner at
        0 - x(0))), so that a picture shows the peak tilt itself, not the frame up to half a frame
        interval away. The nearest frame where a moving body's columns were not read (large runs)
        or the first frame is not at t = 0; None with no frames."""
        if not self.frames:
            return None
        moving = [k for k, b in enumerate(self.bodies) if b["kind"] != "fixed"]
        if self.frames[0][0] != 0.0 or not all(self.has_series(self.bodies[k]["name"]) for k in moving):
            return self.frame_near(time_s)
        first = self.frame_near(0.0)
        row = int(np.argmin(np.abs(self.t_s - time_s)))
        count = len(self.bodies)
        start, now = np.zeros((count, 3)), np.zeros((count, 3))
        turn, tilt = np.tile([1.0, 0.0, 0.0, 0.0], (count, 1)), np.zeros(count)
        for k in moving:
            name = self.bodies[k]["name"]
            start[k] = [self.series(name, f"{a}_m")[0] for a in "xyz"]
            now[k] = [self.series(name, f"{a}_m")[row] for a in "xyz"]
            turn[k] = [self.series(name, c)[row] for c in ("qw", "qx", "qy", "qz")]
            tilt[k] = self.series(name, "tilt_rad")[row]
        body_of_point = np.zeros(len(first.points_m), dtype=int)
        body_of_point[first.connectivity] = np.repeat(first.face_body(), first.face_sizes())
        points = now[body_of_point] + rotate(turn[body_of_point], first.points_m - start[body_of_point])
        cells = {"body": first.cell_data["body"], "tilt_rad": tilt[first.face_body()]}
        return BodyFrame(float(self.t_s[row]), points, first.connectivity, first.offsets, cells)

    def picture_times(self):
        """[(label, time [s])]: the start, the largest peak tilt of a dynamic body, the end."""
        end = float(self.t_s[-1])
        times = [("start", 0.0)]
        ranked = self.ranked_dynamic(1)
        if ranked and self.response(ranked[0]).get("peak_tilt_rad", 0.0) > 0.0:
            b = self.response(ranked[0])
            times.append((f"peak tilt of {b['name']} ({b['peak_tilt_time_s']:.3g} s)", float(b["peak_tilt_time_s"])))
        times.append(("end", end))
        return times

    def limitations(self):
        """What this folder's files cannot show, one sentence each."""
        notes = []
        status = self.summary.get("status", "completed")
        if status != "completed":
            end = self.summary.get("end_time_s")
            of = f" of {end:.4g} s" if isinstance(end, (int, float)) else ""
            notes.append(f"The run is {status} at t = {float(self.t_s[-1]):.4g} s{of}: every plot ends there.")
        if self.table_name() is None:
            notes.append("No driven body (table) in history.csv: no table motion plotted, and slips are plotted "
                         "relative to the ground.")
        if not self.frames:
            notes.append("No VTK frames (vtk/bodies.pvd; [output] vtk = false, or 'auto' on a large run): no pictures "
                         "of the bodies. Set [output] vtk = true to have them.")
        if self.energy is None:
            notes.append("No energy.csv: no energy plot.")
        return notes
