"""Publication figures of one or several runs (matplotlib, Agg backend: no display needed).

Each figure is saved in every requested format (png, svg, pdf) under the same stem."""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

KIND_COLOURS = {"dynamic": "#c0504d", "fixed": "#7f7f7f", "driven": "#4f81bd"}
STYLE = {
    "font.size": 9,
    "axes.titlesize": 9,
    "axes.labelsize": 9,
    "legend.fontsize": 8,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "savefig.dpi": 200,
    "savefig.bbox": "tight",
    # Constrained layout keeps tick labels, axis labels, titles and legends of every panel apart.
    "figure.constrained_layout.use": True,
}
WIDTH_IN = 6.7  # [in] a two-column journal page


def save(fig, folder, stem, formats):
    """Writes fig as folder/stem.<format> for each format; returns the paths."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for fmt in formats:
        path = folder / f"{stem}.{fmt}"
        fig.savefig(path)
        paths.append(path)
    plt.close(fig)
    return paths


def dynamic_bodies(run, chosen=None, limit=6):
    names = run.recorded("dynamic")
    if chosen:
        missing = [n for n in chosen if n not in names]
        if missing:
            raise KeyError(f"not recorded dynamic bodies: {', '.join(missing)}; recorded: {', '.join(names)}")
        return list(chosen)
    return names[:limit]


def acceleration_figure(run, bodies, folder, formats):
    """Fig. 5 style: the table's horizontal acceleration on top, each body's below it."""
    table = run.recorded_table()
    rows = ([table] if table else []) + bodies
    if not rows:
        return []
    with plt.rc_context(STYLE):
        fig, axes = plt.subplots(len(rows), 1, sharex=True, squeeze=False,
                                 figsize=(WIDTH_IN, 1.3 + 1.2 * len(rows)))
        for ax, name in zip(axes[:, 0], rows):
            colour = KIND_COLOURS[run.body(name)["kind"]]
            ax.plot(run.t_s, run.series(name, "ax"), lw=0.7, color=colour)
            ax.set_ylabel(f"{name}\n$a_x$ [m/s$^2$]")
        axes[-1, 0].set_xlabel("time [s]")
        # (a figure title, not the top panel's: it then never meets that panel's tick offset)
        fig.suptitle(f"{run.title()}: horizontal acceleration")
        fig.align_ylabels(axes[:, 0])
        return save(fig, folder, "acceleration", formats)


def response_figure(run, bodies, folder, formats):
    """Rotation and displacement relative to the table of each body."""
    with plt.rc_context(STYLE):
        fig, (rot, disp) = plt.subplots(2, 1, sharex=True, figsize=(WIDTH_IN, 4.2))
        for name in bodies:
            rot.plot(run.t_s, run.series(name, "rot"), lw=0.8, label=name)
            disp.plot(run.t_s, run.relative_displacement_m(name, "x"), lw=0.8, label=name)
        rot.set_ylabel("rotation [rad]\n(counter-clockwise +)")
        ref = run.recorded_table() or "ground"
        disp.set_ylabel(f"$u_x$ relative to\n{ref} [m]")
        disp.set_xlabel("time [s]")
        fig.suptitle(f"{run.title()}: rotation and relative displacement")
        if len(bodies) > 1:  # below the panels, where it covers no curve
            fig.legend(*rot.get_legend_handles_labels(), loc="upper center", bbox_to_anchor=(0.5, 0.0),
                       ncol=min(len(bodies), 6), frameon=False)
        fig.align_ylabels([rot, disp])
        return save(fig, folder, "response", formats)


ENERGY_TERMS = [
    ("kinetic_J", "kinetic"),
    ("gravitational_change_J", "gravitational (change)"),
    ("elastic_J", "elastic (springs)"),
    ("normal_dashpot_J", "normal dashpots (dissipated)"),
    ("shear_dashpot_J", "shear dashpots (dissipated)"),
    ("friction_J", "friction (dissipated)"),
    ("removed_J", "taken out with bodies that left"),
]
# The work done on the bodies from outside: by the driven table, and by gravity as a table tilts.
WORK_TERMS = [
    ("table_work_J", "work done by the table"),
    ("tilt_work_J", "work done by the turning gravity"),
]


def energy_figure(run, folder, formats):
    """Every ledger term over time, and the balance residual below."""
    e = run.energy
    if e is None:
        return []
    with plt.rc_context(STYLE):
        fig, (terms, residual) = plt.subplots(2, 1, sharex=True, figsize=(WIDTH_IN, 4.6),
                                              gridspec_kw={"height_ratios": [3, 1]})
        # Files of older runs lack the removed and tilt columns; a term that stays 0 is not drawn.
        present = [(c, label) for c, label in ENERGY_TERMS + WORK_TERMS if c in e]
        for column, label in present:
            if column in ("removed_J", "tilt_work_J") and not e[column].any():
                continue
            style = {"lw": 1.4, "color": "k"} if column == "table_work_J" else {"lw": 0.9}
            terms.plot(e["t_s"], e[column], label=label, **style)
        # stored + dissipated + removed, less the initial kinetic and elastic energy: equals the
        # work done from outside when the balance closes (residual_J is the difference).
        held = sum(e[c] for c, _ in ENERGY_TERMS if c in e)
        work = sum(e[c] for c, _ in WORK_TERMS if c in e)
        accounted = held - (held - work - e["residual_J"])[0]
        terms.plot(e["t_s"], accounted, lw=1.0, ls="--", color="0.5", label="stored + dissipated - initial")
        terms.set_ylabel("energy [J]")
        # Below the panels: inside, eight entries cover the curves whatever corner they take.
        fig.legend(*terms.get_legend_handles_labels(), loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3,
                   frameon=False)
        fig.suptitle(f"{run.title()}: energy balance")
        residual.plot(e["t_s"], e["residual_J"], lw=0.8, color="#9467bd")
        residual.set_ylabel("residual [J]")
        residual.set_xlabel("time [s]")
        fig.align_ylabels([terms, residual])
        return save(fig, folder, "energy", formats)


def view_origin(box):
    """A round point (x0, y0) [m] to draw a scene relative to when it lies far from the origin
    compared with its size (a block at x = 1000 m): its tick labels then stay short ("-0.2",
    not "999.8", or an offset "+1e3" that meets the axis label). (0, 0) otherwise."""
    origin = []
    for low, high in ((box[0], box[1]), (box[2], box[3])):
        middle, size = 0.5 * (low + high), high - low
        step = 10.0 ** np.floor(np.log10(size)) if size > 0 else 1.0
        origin.append(float(np.round(middle / step) * step) if abs(middle) > 5 * size else 0.0)
    return tuple(origin)


def draw_bodies(ax, run, row, box):
    """The drawable bodies at one history row as filled polygons, clipped to box, drawn relative
    to view_origin(box) (the axis labels say so). Returns the collection and the origin."""
    origin = np.array(view_origin(box))
    bodies = run.drawable()
    polygons = [run.outline_at(b, row) - origin for b in bodies]
    colours = [KIND_COLOURS[b["kind"]] for b in bodies]
    collection = PolyCollection(polygons, facecolors=colours, edgecolors="k", linewidths=0.6, alpha=0.9)
    ax.add_collection(collection)
    ax.set_xlim(box[0] - origin[0], box[1] - origin[0])
    ax.set_ylim(box[2] - origin[1], box[3] - origin[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]" if origin[0] == 0 else f"x - {origin[0]:g} [m]")
    ax.set_ylabel("y [m]" if origin[1] == 0 else f"y - {origin[1]:g} [m]")
    return collection, origin


def snapshot_figure(run, times, folder, formats):
    """Fig. 6 style: the bodies side by side at the chosen times, on one common scale."""
    if not run.drawable():
        return []
    rows = [run.row_at(t) for t in times]
    box = run.view_box(range(0, rows[-1] + 1))
    aspect = (box[3] - box[2]) / (box[1] - box[0])
    # Tall scenes (a tombstone) side by side as in the paper; wide ones (a row of blocks) stacked.
    side_by_side = aspect >= 0.5
    with plt.rc_context(STYLE):
        if side_by_side:
            size = (WIDTH_IN, min(6.0, WIDTH_IN / len(rows) * aspect + 0.9))
            fig, axes = plt.subplots(1, len(rows), sharey=True, squeeze=False, figsize=size)
            panels = axes[0]
        else:
            size = (WIDTH_IN, min(9.0, len(rows) * (WIDTH_IN * aspect + 0.35) + 0.5))
            fig, axes = plt.subplots(len(rows), 1, sharex=True, squeeze=False, figsize=size)
            panels = axes[:, 0]
        for ax, row in zip(panels, rows):
            draw_bodies(ax, run, row, box)
            ax.set_title(f"t = {run.t_s[row]:.2f} s")
            ax.grid(False)
        for ax in panels[1:] if side_by_side else panels[:-1]:
            (ax.set_ylabel if side_by_side else ax.set_xlabel)("")
        # An equal-aspect panel is narrower than its share of the page: once laid out, at most
        # one x tick label per half inch of its real width (matplotlib's own count assumes
        # three-character labels, and "-0.25" beside "0.00" then touch).
        fig.canvas.draw()
        for ax in panels:
            width_in = ax.get_window_extent().width / fig.dpi
            ax.xaxis.set_major_locator(MaxNLocator(nbins=max(1, int(width_in / 0.5)), min_n_ticks=2))
        return save(fig, folder, "snapshots", formats)


def comparison_figure(runs, labels, body, folder, formats, overlay=False):
    """Fig. 5 style for several runs: the first run's table acceleration on top, then the body's
    acceleration of each run stacked (or all overlaid in one panel)."""
    for run in runs:
        if body not in run.recorded():
            raise KeyError(f"{run.path}: no recorded body '{body}'; recorded: {', '.join(run.recorded())}")
    first = runs[0]
    table = first.table_name()
    panels = 1 + (1 if overlay else len(runs)) if table else (1 if overlay else len(runs))
    with plt.rc_context(STYLE):
        fig, axes = plt.subplots(panels, 1, sharex=True, sharey=not overlay, squeeze=False,
                                 figsize=(WIDTH_IN, 1.3 + 1.1 * panels))
        axes = list(axes[:, 0])
        if table:
            ax = axes.pop(0)
            ax.plot(first.t_s, first.series(table, "ax"), lw=0.7, color=KIND_COLOURS["driven"])
            ax.set_ylabel(f"{table}\n$a_x$ [m/s$^2$]")
        for k, (run, label) in enumerate(zip(runs, labels)):
            ax = axes[0] if overlay else axes[k]
            ax.plot(run.t_s, run.series(body, "ax"), lw=0.7, label=label)
            if not overlay:
                ax.set_ylabel(f"{label}\n$a_x$ [m/s$^2$]")
        if overlay:
            axes[0].set_ylabel(f"{body} $a_x$ [m/s$^2$]")
            fig.legend(*axes[0].get_legend_handles_labels(), loc="upper center", bbox_to_anchor=(0.5, 0.0),
                       ncol=min(len(runs), 4), frameon=False)
        fig.axes[-1].set_xlabel("time [s]")
        fig.suptitle(f"{body}: horizontal acceleration, {len(runs)} runs")
        fig.align_ylabels(fig.axes)
        return save(fig, folder, "acceleration_comparison", formats)
