#!/usr/bin/python3
"""Overturning spectrum of a slender block under one-sine pulses: the smallest pulse amplitude
that overturns it, against the pulse's circular frequency over Housner's frequency parameter p,
from the DEM (blockdem.sweep) and from Housner's equation of motion (blockdem.sweep with
solver="housner": the project's RK4 solver of Housner's 1963 equation, Housner's r per impact).

The block: studies/scenarios/pulse_block.toml, b = 0.2 m, h = 0.8 m (alpha = atan(b/h),
R = sqrt(b^2 + h^2), p = sqrt(3 g / (4 R)) = 2.99 rad/s). Amplitudes are given in units of
g tan(alpha): below 1 the block never lifts off (statics), so every minimum is at least 1.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/overturning_spectrum.py [--out DIR]
        [--quick] [--threads N]

--quick (the test's configuration): w/p = 2, 3 and 4, DEM amplitudes 1 to 3 in steps of 0.125.
Default: w/p = 1.5 to 6, amplitudes 1 to 5. Housner's grid is 0.02 wide in both.
Writes overturning_spectrum.csv and overturning_spectrum.png (matplotlib) in --out.
"""
import argparse
import math
import pathlib

import numpy as np

import blockdem

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENARIO = ROOT / "studies" / "scenarios" / "pulse_block.toml"
B_M, H_M = 0.2, 0.8   # [m] half width and half height, as the scenario's block
GRAVITY = 9.81        # [m/s^2] as the scenario


def housner_p():
    """[rad/s] Housner's frequency parameter sqrt(3 g / (4 R))."""
    return math.sqrt(3.0 * GRAVITY / (4.0 * math.hypot(B_M, H_M)))


def minimum_overturning(solver, ratios, amplitude_ratios, threads):
    """{w/p: smallest amplitude ratio that overturns (NaN when none on the grid)}."""
    p, static = housner_p(), GRAVITY * B_M / H_M
    cases = [{"table_motion.horizontal.period": 2.0 * math.pi / (r * p), "table_motion.horizontal.amplitude": a * static}
             for r in ratios for a in amplitude_ratios]
    table = blockdem.sweep(str(SCENARIO), cases=cases, solver=solver, housner_dt=2.0e-4, threads=threads)
    assert (table["status"] == "completed").all(), table["error"]
    over = table["block.overturned"].reshape(len(ratios), len(amplitude_ratios))
    grid = np.asarray(amplitude_ratios)
    return {r: (grid[row].min() if row.any() else math.nan) for r, row in zip(ratios, over)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="out/python/overturning_spectrum")
    ap.add_argument("--quick", action="store_true", help="w/p = 2, 3 and 4, amplitudes 1 to 3 (the test's configuration)")
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args()
    ratios = [2.0, 3.0, 4.0] if args.quick else [1.5, 2.0, 3.0, 4.0, 5.0, 6.0]
    top = 3.0 if args.quick else 5.0
    dem_step, housner_step = 0.125, 0.02
    dem = minimum_overturning("dem", ratios, np.arange(1.0, top + 1e-9, dem_step), args.threads)
    housner = minimum_overturning("housner", ratios, np.arange(1.0, top + 1e-9, housner_step), args.threads)

    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "overturning_spectrum.csv", "w") as f:
        f.write("pulse_w_over_p,dem_min_amplitude_over_g_tan_alpha,housner_min_amplitude_over_g_tan_alpha\n")
        for r in ratios:
            f.write(f"{r:g},{dem[r]:.4g},{housner[r]:.4g}\n")
            print(f"w/p = {r:g}: DEM {dem[r]:.3f}, Housner {housner[r]:.3f} (g tan alpha; DEM grid {dem_step})")
    plot(out / "overturning_spectrum.png", ratios, dem, housner)
    return dem, housner, dem_step


def plot(path, ratios, dem, housner):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(ratios, [housner[r] for r in ratios], "-", label="Housner's equation (RK4)")
    ax.plot(ratios, [dem[r] for r in ratios], "o", label="DEM (blockdem.sweep)")
    ax.axhline(1.0, color="grey", lw=0.8, ls=":", label="uplift, g tan(alpha)")
    ax.set_xlabel("pulse frequency / p")
    ax.set_ylabel("min. overturning amplitude / (g tan alpha)")
    ax.set_title("One-sine pulse, block b = 0.2 m, h = 0.8 m", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
