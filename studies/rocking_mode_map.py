#!/usr/bin/python3
"""Rocking-mode maps: the paper's three modes (in-phase, anti-phase, subharmonic), DEM beside
Housner.

A slender block (b = 0.1 m, h = 0.4 m, studies/scenarios/sine_block.toml) on a sine table; each
cell of an amplitude x frequency grid is coloured by the steady mode that the rule of
docs/rocking_modes.md finds (none, sliding, in-phase, anti-phase, subharmonic of period 2 or 3
table periods, irregular, overturned), once for the DEM (`blockdem sweep`) and once for
Housner's equation of motion on the same grid (`blockdem sweep --solver housner`, Housner's
restitution r = 1 - 1.5 sin^2 alpha, which the DEM's e = 0.2 contact reproduces). Two grids:
  overview: 0.25-8 Hz x 0.2-1.6 g, dense just above the static line a/g = b/h (in-phase band);
  fine:     the subharmonic region, 3.5-7.5 Hz x 0.84-1.56 g.
Every case runs 120 table periods from rest; the rule reads the last 72. A case whose block
failed (overturned, fell or left the model: the sweep's block.failed column, docs/outputs.md
"Outcomes") is drawn as overturned.

    /usr/bin/python3 studies/rocking_mode_map.py [--out out/studies/modes] [--big] [--mpi N]

Default: 266 + 1517 cases per solver (the fine DEM grid took 27 min of wall time on a 2-core machine
shared with other jobs; the rest a few minutes).
--big: the fine grid at half the steps (4 times the cases).
Writes rocking_mode_map.csv (one row per grid, solver and cell) and rocking_mode_map.png in --out.
"""
import argparse
import collections
import csv
import pathlib

import sweep_common as sc

B, H, GRAVITY = 0.1, 0.4, 9.81  # [m], [m], [m/s^2]: studies/scenarios/sine_block.toml
CYCLES = 120                    # table periods per case: the subharmonic start-up lasts 30-80
# The subharmonic point of tests/unit/test_rocking_mode.cpp and docs/rocking_modes.md.
TEST_POINT = (6.0, 1.0)         # [Hz], [g]
CLASSES = ["none", "sliding", "in_phase", "anti_phase", "subharmonic_2", "subharmonic_3", "irregular", "overturned"]
COLOURS = ["#ffffff", "#c7e9c0", "#fdae6b", "#6baed6", "#dadaeb", "#756bb1", "#bdbdbd", "#de2d26"]
LABELS = {"in_phase": "in-phase", "anti_phase": "anti-phase", "subharmonic_2": "subharmonic, period 2T",
          "subharmonic_3": "subharmonic, period 3T", "overturned": "overturned / fell (failed)"}


def grids(big):
    overview = ([0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 7.0, 8.0],
                [0.2, 0.255, 0.26, 0.265, 0.27, 0.3] + [round(0.4 + 0.1 * k, 3) for k in range(13)])
    step_f, step_a = (0.05, 0.01) if big else (0.1, 0.02)
    fine = ([round(3.5 + step_f * k, 4) for k in range(round(4.0 / step_f) + 1)],
            [round(0.84 + step_a * k, 4) for k in range(round(0.72 / step_a) + 1)])
    return {"overview": overview, "fine": fine}


def cell_class(row):
    """The map's class of one results.csv row."""
    if row["status"] != "completed":
        return "failed"
    if row["block.failed"] == "1":
        return "overturned"
    mode = row["block.mode"]
    return f"subharmonic_{row['block.rocking_period_ratio']}" if mode == "subharmonic" else mode


def run_grid(blockdem, out, name, freqs, amps_g, solver, launcher):
    cases = out / f"{name}_frequencies.csv"
    # Period, cycles and duration move together: one case list row per frequency.
    sc.write_case_list(cases, ["table_motion.horizontal.period", "table_motion.horizontal.cycles", "simulation.duration"],
                       [[sc.fmt(1 / f), CYCLES, sc.fmt(CYCLES / f)] for f in freqs])
    amplitudes = ",".join(sc.fmt(a * GRAVITY) for a in amps_g)
    extra = ["--cases", str(cases), "--vary", f"table_motion.horizontal.amplitude={amplitudes}", "-q"]
    if solver == "housner":
        extra += ["--solver", "housner"]
    # Housner's solver is cheap and single-block: never under mpirun.
    return sc.run_sweep(blockdem, sc.SCENARIOS / "sine_block.toml", out / f"{name}_{solver}", extra,
                        launcher if solver == "dem" else ())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=str(sc.SOURCE_DIR / "out" / "studies" / "modes"))
    ap.add_argument("--blockdem")
    ap.add_argument("--big", action="store_true")
    ap.add_argument("--mpi", type=int, default=0, help="run the DEM sweeps with mpirun -n N")
    args = ap.parse_args()
    blockdem = sc.find_blockdem(args.blockdem)
    out = pathlib.Path(args.out)
    maps = {}  # (grid, solver) -> {(f, a): class}
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "rocking_mode_map.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["grid", "solver", "frequency_hz", "amplitude_g", "mode", "rocking_period_ratio", "phase_lag_deg",
                    "peak_rotation_rad", "status"])
        for name, (freqs, amps_g) in grids(args.big).items():
            for solver in ("dem", "housner"):
                cells = maps.setdefault((name, solver), {})
                for row in run_grid(blockdem, out, name, freqs, amps_g, solver, sc.launcher_from(args)):
                    fr = round(1.0 / float(row["table_motion.horizontal.period"]), 4)
                    a = round(float(row["table_motion.horizontal.amplitude"]) / GRAVITY, 4)
                    cells[(fr, a)] = cell_class(row)
                    w.writerow([name, solver, sc.fmt(fr), sc.fmt(a), cells[(fr, a)], row["block.rocking_period_ratio"],
                                row["block.phase_lag_deg"], row["block.peak_rotation_rad"], row["status"]])
    for (name, solver), cells in maps.items():
        print(f"{name} {solver}:", dict(collections.Counter(cells.values())))
    for name in grids(args.big):
        dem, housner = maps[(name, "dem")], maps[(name, "housner")]
        same = sum(dem[k] == housner[k] for k in dem)
        sub = [k for k in dem if dem[k].startswith("subharmonic") and housner[k] == dem[k]]
        print(f"{name}: DEM and Housner give the same mode in {same} of {len(dem)} cells; "
              f"both subharmonic in {len(sub)}")
    plot(out / "rocking_mode_map.png", grids(args.big), maps)
    print(f"wrote {out / 'rocking_mode_map.csv'} and {out / 'rocking_mode_map.png'}")


def edges(values):
    mids = [(a + b) / 2 for a, b in zip(values, values[1:])]
    return [values[0] - (mids[0] - values[0])] + mids + [values[-1] + (values[-1] - mids[-1])]


def draw(ax, freqs, amps_g, cells, by_index):
    import numpy as np
    from matplotlib.colors import ListedColormap
    index = {m: k for k, m in enumerate(CLASSES)}
    z = np.full((len(amps_g), len(freqs)), np.nan)
    for i, a in enumerate(amps_g):
        for j, f in enumerate(freqs):
            z[i, j] = index.get(cells.get((round(f, 4), round(a, 4))), np.nan)
    if by_index:
        # Equal cells for an uneven grid (amplitudes crowd near the static line), labelled with values.
        x, y = np.arange(len(freqs) + 1) - 0.5, np.arange(len(amps_g) + 1) - 0.5
        ax.set_xticks(range(len(freqs)), [f"{f:g}" for f in freqs], fontsize=7, rotation=90)
        ax.set_yticks(range(len(amps_g)), [f"{a:g}" for a in amps_g], fontsize=7)
    else:
        x, y = edges(freqs), edges(amps_g)
        ax.tick_params(labelsize=8)
    ax.pcolormesh(x, y, z, cmap=ListedColormap(COLOURS), vmin=-0.5, vmax=len(CLASSES) - 0.5,
                  edgecolors="#888888" if by_index else "face", linewidth=0.3 if by_index else 0.0)


def plot(path, grid_axes, maps):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch, Rectangle
    import numpy as np
    fig, axes = plt.subplots(2, 2, figsize=(12, 10.5))
    of, oa = grid_axes["overview"]
    ff, fa = grid_axes["fine"]
    for col, solver in enumerate(("dem", "housner")):
        title = "DEM (blockdem)" if solver == "dem" else "Housner's equation (r = 1 - 1.5 sin² α)"
        ax = axes[0, col]
        draw(ax, of, oa, maps[("overview", solver)], by_index=True)
        static_row = np.interp(B / H, oa, range(len(oa)))
        ax.axhline(static_row, color="k", lw=1.2, ls="--")
        ax.text(len(of) - 0.6, static_row, "a/g = b/h", va="bottom", ha="right", fontsize=7)
        # The fine grid's region, in index coordinates of the overview.
        x0, x1 = np.interp([ff[0], ff[-1]], of, range(len(of)))
        y0, y1 = np.interp([fa[0], fa[-1]], oa, range(len(oa)))
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, ec="k", lw=1.2))
        ax.set_title(f"{title}: overview", fontsize=10)
        ax = axes[1, col]
        draw(ax, ff, fa, maps[("fine", solver)], by_index=False)
        ax.plot(*TEST_POINT, marker="*", ms=13, mfc="yellow", mec="k")
        ax.set_title(f"{title}: subharmonic region (framed above)", fontsize=10)
        for row in range(2):
            axes[row, col].set_xlabel("table frequency [Hz]")
            axes[row, col].set_ylabel("table acceleration amplitude a/g [-]")
    handles = [Patch(facecolor=c, edgecolor="#888888", label=LABELS.get(m, m)) for m, c in zip(CLASSES, COLOURS)]
    handles.append(plt.Line2D([], [], ls="", marker="*", ms=11, mfc="yellow", mec="k", label=f"test point {TEST_POINT[0]:g} Hz, {TEST_POINT[1]:g} g"))
    fig.legend(handles=handles, loc="lower center", ncol=5, fontsize=8, frameon=False)
    fig.suptitle(f"Rocking modes of a b = {B} m, h = {H} m block (b/h = {B / H:g}) on a sine table, "
                 f"from rest, {CYCLES} periods", fontsize=11)
    fig.tight_layout(rect=(0, 0.05, 1, 0.97))
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
