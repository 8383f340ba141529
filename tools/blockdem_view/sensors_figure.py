"""The sensors of a run (sensors.csv, docs/outputs.md) beside the table's motion: one panel for
the table's horizontal acceleration, one per accelerometer (a_x, as filtered in the run), and one
with every relative sensor's (LVDT's) horizontal displacement."""
from pathlib import Path

import numpy as np

from . import figures


def read_sensors_csv(path):
    """{column: array} of sensors.csv (the '#' lines above the header are its units and filters),
    and the comment lines."""
    path = Path(path)
    comments, header = [], None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#"):
                comments.append(line[1:].strip())
            else:
                header = line.strip().split(",")
                break
    if header is None:
        return {}, comments
    data = np.loadtxt(path, delimiter=",", comments="#", skiprows=len(comments) + 1, ndmin=2)
    if data.shape[0] == 0:
        data = np.zeros((0, len(header)))
    return {name: data[:, k] for k, name in enumerate(header)}, comments


def _sensor_names(columns, suffix):
    return [c[: -len(suffix)] for c in columns if c.endswith(suffix)]


def sensors_figure(run, folder, formats):
    """Writes folder/sensors.<fmt> when the run has sensors; returns the paths ([] otherwise)."""
    path = run.path / "sensors.csv"
    if not path.is_file():
        return []
    columns, comments = read_sensors_csv(path)
    if "t" not in columns or len(columns["t"]) == 0:
        return []
    t = columns["t"]
    accelerometers = _sensor_names(columns, ".ax")
    lvdts = _sensor_names(columns, ".dx")
    table = run.recorded_table()
    panels = ([("table", table)] if table else []) + [("accelerometer", n) for n in accelerometers]
    if lvdts:
        panels.append(("relative", None))
    if not panels:
        return []
    filters = {c.split(":", 1)[0]: c.split(";", 1)[-1].strip() for c in comments[1:] if ":" in c}
    plt = figures.plt
    with plt.rc_context(figures.STYLE):
        fig, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False, figsize=(figures.WIDTH_IN, 1.3 + 1.25 * len(panels)))
        for ax, (kind, name) in zip(axes[:, 0], panels):
            if kind == "table":
                ax.plot(run.t_s, run.series(name, "ax"), lw=0.7, color=figures.KIND_COLOURS["driven"])
                ax.set_ylabel(f"table '{name}'\n$a_x$ [m/s$^2$]")
            elif kind == "accelerometer":
                ax.plot(t, columns[f"{name}.ax"], lw=0.7, color="#c0504d")
                ax.set_ylabel(f"sensor '{name}'\n$a_x$ [m/s$^2$]")
                note = filters.get(name, "")
                if note:
                    ax.text(0.01, 0.97, note.split(", causal")[0], transform=ax.transAxes, va="top", fontsize=7, alpha=0.8)
            else:
                for n in lvdts:
                    ax.plot(t, 1e3 * columns[f"{n}.dx"], lw=0.8, label=n)
                ax.set_ylabel(f"sensor '{lvdts[0]}'\n$d_x$ [mm]" if len(lvdts) == 1 else "relative sensors\n$d_x$ [mm]")
                if len(lvdts) > 1:
                    ax.legend(loc="best")
        axes[-1, 0].set_xlabel("time [s]")
        axes[0, 0].set_title(f"{run.title()}: sensors beside the table motion")
        fig.align_ylabels(axes[:, 0])
        return figures.save(fig, folder, "sensors", formats)
