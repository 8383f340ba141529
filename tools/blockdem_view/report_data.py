"""The data a report embeds: animation frames and the series of its zoomable plots, thinned so
that the page stays small and quick (the full records stay in history.csv and energy.csv)."""
import numpy as np

MAX_PLOT_ROWS = 30000   # dygraphs draws this many rows per plot without lag
MAX_FRAMES = 1500       # animation frames embedded (about 1 MB per 10 bodies)


def _round(values, digits=6):
    """Floats with `digits` significant digits, as plain Python numbers for JSON."""
    return [float(f"{v:.{digits}g}") for v in np.asarray(values, dtype=float)]


def _stride(n, limit):
    return max(1, int(np.ceil(n / limit)))


def animation_data(run, fps=25):
    """Frames at fps of simulated time (at most MAX_FRAMES) with each drawable body's pose."""
    t = run.t_s
    if not run.drawable():  # nothing to draw (run.limitations() says why): an empty player
        return {"t": _round(t[:1]), "bodies": [], "view": [0, 1, 0, 1], "scene": [0, 1, 0, 1]}
    count = int(min(MAX_FRAMES, np.floor((t[-1] - t[0]) * fps) + 1))
    rows = sorted({run.row_at(x) for x in np.linspace(t[0], t[-1], max(count, 2))})
    bodies = []
    for b in run.drawable():
        entry = {"name": b["name"], "kind": b["kind"], "corners": [_round(c) for c in b["corners_m"]]}
        if b["recorded"]:
            entry["x"] = _round(run.series(b["name"], "x")[rows], 9)
            entry["y"] = _round(run.series(b["name"], "y")[rows], 9)
            entry["rot"] = _round(run.series(b["name"], "rot")[rows], 7)
        else:
            entry["fixed"] = _round(b["initial_centroid_m"], 9)
        bodies.append(entry)
    return {"t": _round(t[rows], 7), "bodies": bodies, "view": _round(run.view_box()),
            "scene": _round(_scene_box(run))}


def _scene_box(run):
    """Everything drawable at t = 0 (the whole table), for the 'whole scene' view."""
    pts = np.vstack([run.outline_at(b, 0) for b in run.drawable()])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 0.05 * max(hi - lo)
    return [lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad]


def _plot(run, labels, columns, ylabel, title):
    n = len(run.t_s) if columns else 0
    step = _stride(n, MAX_PLOT_ROWS)
    rows = np.column_stack([c[::step] for c in columns]) if columns else np.zeros((0, 0))
    return {"title": title, "ylabel": ylabel, "labels": labels,
            "rows": [_round(r) for r in rows], "thinned": step > 1}


def plot_data(run, bodies):
    """Series for the zoomable plots: accelerations, rotations, relative displacements, energy."""
    t = run.t_s
    table = run.recorded_table()
    accel_names = ([table] if table else []) + bodies
    plots = []
    if accel_names:
        plots.append(_plot(run, ["t"] + accel_names, [t] + [run.series(b, "ax") for b in accel_names],
                           "a_x [m/s²]", "Horizontal acceleration"))
    if bodies:
        plots.append(_plot(run, ["t"] + bodies, [t] + [run.series(b, "rot") for b in bodies],
                           "rotation [rad]", "Rotation (counter-clockwise +)"))
        plots.append(_plot(run, ["t"] + bodies, [t] + [run.relative_displacement_m(b) for b in bodies],
                           "u_x [m]", f"Horizontal displacement relative to {table or 'the ground'}"))
    if run.energy is not None:
        e = run.energy
        names = [c for c in ["kinetic_J", "gravitational_change_J", "elastic_J", "normal_dashpot_J",
                             "shear_dashpot_J", "friction_J", "removed_J", "table_work_J", "tilt_work_J", "residual_J"]
                 if c in e]
        step = _stride(len(e["t_s"]), MAX_PLOT_ROWS)
        rows = np.column_stack([e["t_s"][::step]] + [e[c][::step] for c in names])
        plots.append({"title": "Energy balance", "ylabel": "energy [J]", "labels": ["t"] + names,
                      "rows": [_round(r) for r in rows], "thinned": step > 1})
    return plots
