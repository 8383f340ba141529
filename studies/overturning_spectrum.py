#!/usr/bin/python3
"""Overturning spectrum: the minimum one-sine / one-cosine pulse amplitude that overturns a
block, against the pulse's circular frequency over Housner's frequency parameter p, for chosen
block sizes. The DEM (blockdem sweep) on a grid of amplitudes, and on the same figure the
equation-of-motion (Housner) solution from the project's own solver (blockdem sweep --solver
housner) on a finer grid.

    /usr/bin/python3 studies/overturning_spectrum.py [--out out/studies/spectrum] [--big] [--mpi N]

Default: 2 blocks x 2 shapes x 5 frequencies x 33 amplitudes = 660 DEM cases, and 6868 cheap
Housner cases (about two minutes on 2 cores). --big: 10 frequencies and amplitude steps half as wide (4x the cases).
A rerun resumes where it stopped (the sweep's own resume).
Writes overturning_spectrum.csv and overturning_spectrum.png in --out.
"""
import argparse
import csv
import math
import pathlib

import sweep_common as sc

# (label, half width b [m], half height h [m]); density as the scenario's block (2400 kg/m^3).
BLOCKS = [("b=0.2 m, h=0.8 m", 0.2, 0.8), ("b=0.125 m, h=1.0 m", 0.125, 1.0)]
SHAPES = ["one_sine", "one_cosine"]
DENSITY = 2400.0  # [kg/m^3] per unit thickness
GRAVITY = 9.81    # [m/s^2] as the scenario


def grid(args):
    ratios = [1.5, 2, 3, 4, 5] if not args.big else [1.25, 1.5, 2, 2.5, 3, 3.5, 4, 5, 6, 7]
    step = 0.125 if not args.big else 0.0625
    amplitude_ratios = [1.0 + step * k for k in range(int(round(4.0 / step)) + 1)]  # 1 .. 5 g tan(alpha)
    return ratios, amplitude_ratios


def case_rows(ratios, amplitude_ratios):
    """One case per block, shape, frequency ratio and amplitude ratio; amplitudes in m/s^2."""
    rows, meta = [], []
    for label, b, h in BLOCKS:
        p = sc.housner_p(b, h, GRAVITY)
        static = GRAVITY * b / h
        for shape in SHAPES:
            for r in ratios:
                period = 2.0 * math.pi / (r * p)
                for a in amplitude_ratios:
                    rows.append([sc.fmt(2 * b), sc.fmt(2 * h), f"[0, {sc.fmt(h)}]", sc.fmt(DENSITY * 4 * b * h),
                                 shape, sc.fmt(period), sc.fmt(a * static)])
                    meta.append((label, shape, r, a))
    return rows, meta


KEYS = ["bodies.block.width", "bodies.block.height", "bodies.block.center", "bodies.block.mass",
        "table_motion.horizontal.type", "table_motion.horizontal.period", "table_motion.horizontal.amplitude"]


def minima(results, meta):
    """Smallest amplitude ratio that overturns, per (block, shape, frequency ratio)."""
    best = {}
    for row, (label, shape, r, a) in zip(results, meta):
        if row["status"] != "completed" or row["block.overturned"] != "1":
            continue
        key = (label, shape, r)
        best[key] = min(best.get(key, math.inf), a)
    return best


def run(args, blockdem, solver, amplitude_ratios, ratios):
    rows, meta = case_rows(ratios, amplitude_ratios)
    out = pathlib.Path(args.out) / solver
    sc.write_case_list(out.with_suffix(".cases.csv"), KEYS, rows)
    extra = ["--cases", str(out.with_suffix(".cases.csv")), "--solver", solver, "--housner-dt", "2e-4"]
    launcher = sc.launcher_from(args) if solver == "dem" else ()
    results = sc.run_sweep(blockdem, sc.SCENARIOS / "pulse_block.toml", out, extra, launcher)
    return minima(results, meta)


def write_csv(path, ratios, dem, housner):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["block", "shape", "pulse_w_over_p", "dem_min_amplitude_over_g_tan_alpha",
                    "housner_min_amplitude_over_g_tan_alpha"])
        for label, _, _ in BLOCKS:
            for shape in SHAPES:
                for r in ratios:
                    d, h = dem.get((label, shape, r)), housner.get((label, shape, r))
                    w.writerow([label, shape, r, "" if d is None else sc.fmt(d), "" if h is None else sc.fmt(h)])


def plot(path, ratios, dem, housner, fine_ratios):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), sharey=True)
    colours = ["tab:blue", "tab:red"]
    for ax, shape in zip(axes, SHAPES):
        for (label, _, _), colour in zip(BLOCKS, colours):
            xs = [r for r in fine_ratios if (label, shape, r) in housner]
            ax.plot(xs, [housner[(label, shape, r)] for r in xs], "-", color=colour, lw=1.2,
                    label=f"Housner EOM, {label}")
            xd = [r for r in ratios if (label, shape, r) in dem]
            ax.plot(xd, [dem[(label, shape, r)] for r in xd], "o", color=colour, mfc="none",
                    label=f"DEM, {label}")
        ax.axhline(1.0, color="grey", lw=0.8, ls=":")
        ax.set_title(shape.replace("_", "-") + " pulse")
        ax.set_xlabel(r"pulse frequency $\omega_p / p$")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel(r"minimum overturning amplitude $a_p / (g \tan\alpha)$")
    axes[0].legend(fontsize=7, loc="upper left")
    fig.suptitle("Overturning spectrum: DEM (blockdem sweep) vs Housner's equation of motion")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=str(sc.SOURCE_DIR / "out" / "studies" / "spectrum"))
    ap.add_argument("--blockdem")
    ap.add_argument("--big", action="store_true", help="finer grids (about 4x the cases)")
    ap.add_argument("--mpi", type=int, default=0, help="run the DEM sweep with mpirun -n N")
    args = ap.parse_args()
    blockdem = sc.find_blockdem(args.blockdem)
    ratios, amplitude_ratios = grid(args)
    dem = run(args, blockdem, "dem", amplitude_ratios, ratios)
    # The reference is cheap: a finer grid in both directions.
    fine_ratios = sorted(set(ratios) | {1.25 + 0.25 * k for k in range(int((max(ratios) - 1.25) / 0.25) + 1)})
    fine_amplitudes = [1.0 + 0.04 * k for k in range(101)]
    housner = run(args, blockdem, "housner", fine_amplitudes, fine_ratios)
    out = pathlib.Path(args.out)
    write_csv(out / "overturning_spectrum.csv", ratios, dem, housner)
    plot(out / "overturning_spectrum.png", ratios, dem, housner, fine_ratios)
    print(f"wrote {out / 'overturning_spectrum.csv'} and {out / 'overturning_spectrum.png'}")


if __name__ == "__main__":
    main()
