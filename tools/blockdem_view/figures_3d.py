"""Figures of a 3-D run folder (RunFolder3d): the bodies at a few times in four views, tilt, slip
and twist over time, the table's three components, and the energy ledger with its balance error."""
import numpy as np

from .drawing_3d import VIEWS, draw_frame, screen_extent
from .figures import ENERGY_TERMS, KIND_COLOURS, STYLE, WIDTH_IN, WORK_TERMS, plt, save

MAX_CURVES = 6  # bodies per time-history panel: the largest peak tilts
MAX_VECTOR_FACES = 20000  # above (faces a frame, times 12 panels), the pictures are PNG only: an
                          # SVG of 1e5 polygons or more is many MB and slow in any viewer


def _legend_below(fig, ax, count):
    if count > 1:
        fig.legend(*ax.get_legend_handles_labels(), loc="upper center", bbox_to_anchor=(0.5, 0.0),
                   ncol=min(count, 6), frameon=False)


def response_figure(run, folder, formats):
    """Tilt, slip along x and y relative to the table, and twist of the bodies that tilted most."""
    bodies = run.ranked_dynamic(MAX_CURVES)
    if not bodies:
        return []
    ref = run.table_name() or "the ground"
    with plt.rc_context(STYLE):
        fig, axes = plt.subplots(4, 1, sharex=True, figsize=(WIDTH_IN, 6.4))
        for name in bodies:
            axes[0].plot(run.t_s, run.series(name, "tilt_rad"), lw=0.8, label=name)
            axes[1].plot(run.t_s, run.slip_m(name, "x"), lw=0.8, label=name)
            axes[2].plot(run.t_s, run.slip_m(name, "y"), lw=0.8, label=name)
            axes[3].plot(run.t_s, run.twist_rad(name), lw=0.8, label=name)
        axes[0].set_ylabel("tilt [rad]")
        axes[1].set_ylabel(f"slip $u_x$ [m]\nrelative to {ref}")
        axes[2].set_ylabel(f"slip $u_y$ [m]\nrelative to {ref}")
        axes[3].set_ylabel("twist [rad]\n(about z, ccw +)")
        axes[3].set_xlabel("time [s]")
        fig.suptitle(f"{run.title()}: tilt, slip and twist")
        _legend_below(fig, axes[0], len(bodies))
        fig.align_ylabels(axes)
        return save(fig, folder, "response", formats)


def table_motion_figure(run, folder, formats):
    """The table's acceleration along x, y (horizontal) and z (vertical)."""
    if run.table_name() is None:
        return []
    with plt.rc_context(STYLE):
        fig, axes = plt.subplots(3, 1, sharex=True, sharey=True, figsize=(WIDTH_IN, 4.2))
        for ax, axis in zip(axes, "xyz"):
            ax.plot(run.t_s, run.table_acceleration_m_s2(axis), lw=0.7, color=KIND_COLOURS["driven"])
            ax.set_ylabel(f"$a_{axis}$ [m/s$^2$]")
        axes[2].set_xlabel("time [s]")
        fig.suptitle(f"{run.title()}: table acceleration ({run.table_name()})")
        fig.align_ylabels(axes)
        return save(fig, folder, "table_motion", formats)


def energy_figure(run, folder, formats):
    """Every ledger term over time, then the residual [J] and the balance error (|residual| over
    the largest term) on a log scale."""
    e = run.energy
    if e is None:
        return []
    with plt.rc_context(STYLE):
        fig, (terms, residual, error) = plt.subplots(3, 1, sharex=True, figsize=(WIDTH_IN, 5.6),
                                                     gridspec_kw={"height_ratios": [3, 1, 1.3]})
        for column, label in ENERGY_TERMS + WORK_TERMS:
            if column in e and e[column].any():
                style = {"lw": 1.4, "color": "k"} if column == "table_work_J" else {"lw": 0.9}
                terms.plot(e["t_s"], e[column], label=label, **style)
        terms.set_ylabel("energy [J]")
        residual.plot(e["t_s"], e["residual_J"], lw=0.8, color="#9467bd")
        residual.set_ylabel("residual [J]")
        if "balance_error" in e:
            positive = e["balance_error"] > 0.0
            error.semilogy(e["t_s"][positive], e["balance_error"][positive], lw=0.8, color="#8c564b")
        error.set_ylabel("balance error [-]\n(|residual| / largest)")
        error.set_xlabel("time [s]")
        fig.suptitle(f"{run.title()}: energy ledger")
        fig.legend(*terms.get_legend_handles_labels(), loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3,
                   frameon=False)
        fig.align_ylabels([terms, residual, error])
        return save(fig, folder, "energy", formats)


def _limits(frames, kinds, camera, margin=0.12):
    """One view box for all the frames of a column, padded by a share of its larger side."""
    extents = [screen_extent(f, kinds, camera) for f in frames]
    lo = np.min([x[0] for x in extents], axis=0)
    hi = np.max([x[1] for x in extents], axis=0)
    pad = margin * max(hi - lo)
    return lo - pad, hi + pad


def snapshot_figure(run, folder, formats):
    """The bodies at the start, at the largest peak tilt and at the end (the first VTK frame posed
    from history.csv, run.bodies_at), each in the axonometric view, the plan and two elevations."""
    if not run.frames:
        return []
    chosen = []  # (label, frame), a frame drawn once even when two labels fall on it
    for label, time_s in run.picture_times():
        frame = run.bodies_at(time_s)
        if chosen and chosen[-1][1].time_s == frame.time_s:
            chosen[-1] = (chosen[-1][0] + " and " + label, frame)
        else:
            chosen.append((label, frame))
    kinds = run.kinds_by_index()
    frames = [f for _, f in chosen]
    edge = 0.3 if len(frames[0].offsets) < 5000 else 0.1
    if len(frames[0].offsets) > MAX_VECTOR_FACES:
        formats = ["png"]
    with plt.rc_context(STYLE):
        fig, axes = plt.subplots(len(chosen), len(VIEWS), squeeze=False,
                                 figsize=(WIDTH_IN * 1.5, 0.6 + 2.4 * len(chosen)))
        for column, (name, (camera, labels)) in enumerate(VIEWS.items()):
            limits = _limits(frames, kinds, camera)
            for row, (label, frame) in enumerate(chosen):
                ax = axes[row, column]
                draw_frame(ax, frame, kinds, camera, limits, edge)
                ax.grid(False)
                ax.set_xlabel(labels[0])
                ax.set_ylabel(labels[1])
                if not labels[0]:  # the axonometric view has no axes to read from
                    ax.set_xticks([])
                    ax.set_yticks([])
                ax.set_title(f"{name}\n{label}, t = {frame.time_s:.3g} s" if column == 0 else name)
        fig.suptitle(f"{run.title()}: the bodies")
        return save(fig, folder, "snapshots", formats)


def make_run_figures_3d(run, formats=("png", "svg")):
    """Writes every figure of a 3-D run to run.path/figures/; returns {stem: [paths]}."""
    folder = run.path / "figures"
    return {
        "snapshots": snapshot_figure(run, folder, formats),
        "response": response_figure(run, folder, formats),
        "table_motion": table_motion_figure(run, folder, formats),
        "energy": energy_figure(run, folder, formats),
    }
