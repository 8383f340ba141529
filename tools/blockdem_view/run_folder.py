"""One run folder read into arrays: the time histories, the energy ledger, the body outlines."""
import json
import math
import tomllib
from pathlib import Path

import numpy as np


class RunFolderError(Exception):
    """A folder that is not a complete blockdem run folder."""


def _read_csv(path, usecols=None):
    """Header names and a 2-D array (rows x columns) of a numeric CSV file (of the columns usecols
    only, when given); RunFolderError naming the file when it is not one."""
    try:
        with open(path, encoding="utf-8") as f:
            header = f.readline().strip().split(",")
        data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2, usecols=usecols)
    except (ValueError, UnicodeDecodeError) as e:
        raise RunFolderError(f"{path}: not a CSV file of numbers under a header line: {e}") from e
    if data.shape[0] == 0:
        data = np.zeros((0, len(header) if usecols is None else len(usecols)))
    return header, data


def _read_json(path):
    """A JSON file's value; RunFolderError naming the file when it is not JSON."""
    try:
        return json.loads(Path(path).read_text(encoding="utf-8"))
    except (ValueError, UnicodeDecodeError) as e:
        raise RunFolderError(f"{path}: not a readable JSON file: {e}") from e


def run_dimension(folder):
    """3 for a folder whose summary.json says so, else 2 (also when there is no summary.json:
    RunFolder then says what is missing)."""
    path = Path(folder) / "summary.json"
    if not path.is_file():
        return 2
    summary = _read_json(path)  # (a damaged one is named, not taken for a 2-D run's)
    return 3 if isinstance(summary, dict) and summary.get("dimension") == 3 else 2


class RunFolder:
    """history.csv, energy.csv, bodies.json, summary.json and scenario.toml of one run."""

    def __init__(self, folder):
        self.path = Path(folder)
        if run_dimension(self.path) == 3:  # no bodies.json: say what reads it, not that it is no run
            raise RunFolderError(f"{self.path}: a 3-D run: these figures are 2-D; `blockdem report` makes the 3-D "
                                 "figures and report (run_folder_3d.py, docs/3d.md)")
        for name in ("history.csv", "summary.json", "bodies.json"):
            if not (self.path / name).is_file():
                raise RunFolderError(f"{self.path}: no {name} (is this a folder written by `blockdem run`?)")
        header, data = _read_csv(self.path / "history.csv")
        self.columns = {name: data[:, k] for k, name in enumerate(header)}
        if "t" not in self.columns:
            raise RunFolderError(f"{self.path / 'history.csv'}: no column t (its header: {','.join(header[:5])}...)")
        self.t_s = self.columns["t"]
        self.summary = _read_json(self.path / "summary.json")
        bodies = _read_json(self.path / "bodies.json")
        if not isinstance(bodies, dict) or not isinstance(bodies.get("bodies"), list):
            raise RunFolderError(f"{self.path / 'bodies.json'}: no list of bodies")
        self.bodies = bodies["bodies"]
        # Wall-clock time and restarts (run_info.json, absent in folders of older versions).
        info = self.path / "run_info.json"
        self.run_info = _read_json(info) if info.is_file() else {}
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

    # ----- bodies -----
    def body(self, name):
        for b in self.bodies:
            if b["name"] == name:
                return b
        raise KeyError(name)

    def recorded(self, kind=None):
        """Names of the bodies in history.csv, optionally of one kind (dynamic, fixed, driven)."""
        return [b["name"] for b in self.bodies if b["recorded"] and (kind is None or b["kind"] == kind)]

    def table_name(self):
        """The body displacements are measured against (the driven table), or None for the ground."""
        ref = self.summary.get("displacements_relative_to", "ground")
        return None if ref == "ground" else ref

    def recorded_table(self):
        """The table if its motion is in history.csv (driven assembly blocks are not recorded
        by default), else None: its acceleration cannot be plotted, and displacements are then
        plotted relative to the ground."""
        table = self.table_name()
        return table if table is not None and self.has_series(table) else None

    def has_series(self, body):
        return f"{body}.x" in self.columns

    def limitations(self):
        """What this folder's files cannot show, one sentence each (the report lists them)."""
        notes = []
        status = self.summary.get("status", "completed")
        if status != "completed":
            end = self.summary.get("end_time_s")
            of = f" of {end:.4g} s" if isinstance(end, (int, float)) else ""
            notes.append(f"The run is {status} at t = {float(self.t_s[-1]):.4g} s{of}: every plot ends there.")
        table = self.table_name()
        if table is not None and not self.has_series(table):
            notes.append(f"The table '{table}' is not in history.csv: its acceleration is not plotted, and displacements "
                         "are plotted relative to the ground (summary.json's are relative to the table). "
                         "Set record = true on it to plot them.")
        unrecorded = [b for b in self.bodies if b["kind"] == "dynamic" and not b["recorded"]]
        if unrecorded:
            names = ", ".join(b["name"] for b in unrecorded[:5]) + (", ..." if len(unrecorded) > 5 else "")
            notes.append(f"{len(unrecorded)} dynamic bodies are not in history.csv ({names}; assembly blocks are not "
                         "recorded unless the assembly says record = true): they are neither plotted nor drawn. "
                         "Their outcome is in summary.json and their motion in the VTK frames when written.")
        if not self.drawable():
            notes.append("No body can be drawn from history.csv: no snapshots and no animation.")
        if self.energy is None:
            notes.append("No energy.csv: no energy plot.")
        return notes

    def title(self):
        return str(self.scenario.get("title", self.path.name))

    # ----- time histories -----
    def series(self, body, field):
        """history.csv column <body>.<field> (x, y, rot, vx, vy, vrot, ax, ay, arot)."""
        return self.columns[f"{body}.{field}"]

    def relative_displacement_m(self, body, axis="x"):
        """Centroid displacement of body since t = 0 relative to the table's [m]."""
        u = self.series(body, axis) - self.series(body, axis)[0]
        table = self.table_name()
        if table is not None and f"{table}.{axis}" in self.columns:
            u = u - (self.series(table, axis) - self.series(table, axis)[0])
        return u

    def response(self, body):
        """The summary.json entry of a body."""
        for b in self.summary.get("bodies", []):
            if b["name"] == body:
                return b
        return {}

    # ----- outlines -----
    def outline_at(self, body, row):
        """Corners [m] (n x 2) of a body at history row `row`; static unrecorded bodies stay put."""
        corners = np.asarray(body["corners_m"], dtype=float)
        if body["recorded"]:
            x, y, rot = (self.columns[f"{body['name']}.{f}"][row] for f in ("x", "y", "rot"))
        else:
            (x, y), rot = body["initial_centroid_m"], 0.0
        c, s = math.cos(rot), math.sin(rot)
        return np.column_stack((x + c * corners[:, 0] - s * corners[:, 1], y + s * corners[:, 0] + c * corners[:, 1]))

    def drawable(self):
        """Bodies whose outline is known at every time: recorded ones and unrecorded fixed ones."""
        return [b for b in self.bodies if b["recorded"] or b["kind"] == "fixed"]

    def row_at(self, time_s):
        """The history row nearest to time_s."""
        return int(np.clip(np.searchsorted(self.t_s, time_s), 0, len(self.t_s) - 1))

    def view_box(self, rows=None, margin=0.15):
        """(xmin, xmax, ymin, ymax) [m] enclosing the dynamic bodies over the rows, with a margin.

        Only dynamic bodies set the view: a 4 m table under a 0.5 m block would make the block
        a speck. With no dynamic body, every drawable body sets it."""
        chosen = [b for b in self.drawable() if b["kind"] == "dynamic"] or self.drawable()
        rows = range(len(self.t_s)) if rows is None else rows
        step = max(1, len(rows) // 400)  # extents change slowly: 400 samples are plenty
        pts = np.vstack([self.outline_at(b, r) for r in list(rows)[::step] + [list(rows)[-1]] for b in chosen])
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        width, height = hi - lo
        # Each direction padded by its own size (a wide scene needs no tall margins), but never
        # by less than a quarter of the other, so that a flat scene keeps some height.
        pad_x = margin * max(width, 0.25 * height)
        pad_y = margin * max(height, 0.25 * width)
        # A deeper strip below the lowest body, so that what it stands on is visible.
        return lo[0] - pad_x, hi[0] + pad_x, lo[1] - 2 * pad_y, hi[1] + pad_y

    def snapshot_times(self, count=6):
        """Evenly spaced times [s]; for a toppling body they end shortly after it overturned."""
        end = float(self.t_s[-1])
        overturned = [b["overturning_time_s"] for b in self.summary.get("bodies", []) if b.get("overturned")]
        if overturned:
            end = min(end, 1.25 * max(overturned) + 1.0)  # the fall to the ground takes about a second
        return list(np.linspace(0.0, end, count))
