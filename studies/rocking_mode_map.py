#!/usr/bin/python3
"""Rocking-mode map: a slender block (b = 0.1 m, h = 0.4 m) on a sine table, each cell of an
amplitude x frequency grid coloured by the steady rocking mode that blockdem's classifier finds
(none, sliding, in-phase, anti-phase, subharmonic, irregular, overturned; docs/sweeps.md), with
the static overturning line a/g = b/h. Failure follows docs/outputs.md "Outcomes": a case whose
block failed (overturned, fell or left the model: the sweep's block.failed column) is drawn as
overturned.

    /usr/bin/python3 studies/rocking_mode_map.py [--out out/studies/modes] [--big] [--mpi N]

Default: 9 frequencies x 13 amplitudes = 117 cases of 20 table periods each (about two minutes
on 2 cores). --big: 16 x 20 cells and 30 periods per case.
Writes rocking_mode_map.csv and rocking_mode_map.png in --out.
"""
import argparse
import collections
import csv
import pathlib

import sweep_common as sc

B, H, GRAVITY = 0.1, 0.4, 9.81  # [m], [m], [m/s^2]: studies/scenarios/sine_block.toml
MODES = ["none", "sliding", "in_phase", "anti_phase", "subharmonic", "irregular", "overturned"]
COLOURS = ["#ffffff", "#c7e9c0", "#fdae6b", "#6baed6", "#9e9ac8", "#bdbdbd", "#de2d26"]


def grid(big):
    if big:
        freqs = [0.75 + 0.3 * k for k in range(16)]
        amps_g = [0.26 + 0.025 * k for k in range(20)]
        return freqs, amps_g, 30
    # Rows close above the static line (b/h = 0.25) show the thin band of in-phase rocking.
    return [0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0], [0.2, 0.255, 0.26, 0.27] + [0.3 + 0.05 * k for k in range(9)], 20


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=str(sc.SOURCE_DIR / "out" / "studies" / "modes"))
    ap.add_argument("--blockdem")
    ap.add_argument("--big", action="store_true")
    ap.add_argument("--mpi", type=int, default=0, help="run the sweep with mpirun -n N")
    args = ap.parse_args()
    blockdem = sc.find_blockdem(args.blockdem)
    freqs, amps_g, cycles = grid(args.big)
    out = pathlib.Path(args.out)
    # Period, cycles and duration move together: one case list row per frequency.
    cases = out / "frequencies.csv"
    sc.write_case_list(cases, ["table_motion.horizontal.period", "table_motion.horizontal.cycles", "simulation.duration"],
                       [[sc.fmt(1 / f), cycles, sc.fmt(cycles / f)] for f in freqs])
    amplitudes = ",".join(sc.fmt(a * GRAVITY) for a in amps_g)
    rows = sc.run_sweep(blockdem, sc.SCENARIOS / "sine_block.toml", out / "sweep",
                        ["--cases", str(cases), "--vary", f"table_motion.horizontal.amplitude={amplitudes}"],
                        sc.launcher_from(args))
    cells = {}
    with open(out / "rocking_mode_map.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["frequency_hz", "amplitude_g", "mode", "rocking_period_ratio", "phase_lag_deg",
                    "peak_rotation_rad", "status"])
        for row in rows:
            fr = 1.0 / float(row["table_motion.horizontal.period"])
            a = float(row["table_motion.horizontal.amplitude"]) / GRAVITY
            mode = row["block.mode"] if row["status"] == "completed" else "failed"
            # Failure as in docs/outputs.md "Outcomes": a block that fell or left the model is
            # drawn with the overturned ones (the rocking classifier only knows overturning).
            if row["status"] == "completed" and row["block.failed"] == "1":
                mode = "overturned"
            cells[(round(fr, 6), round(a, 6))] = mode
            w.writerow([sc.fmt(fr), sc.fmt(a), mode, row["block.rocking_period_ratio"], row["block.phase_lag_deg"],
                        row["block.peak_rotation_rad"], row["status"]])
    print("modes:", dict(collections.Counter(cells.values())))
    plot(out / "rocking_mode_map.png", freqs, amps_g, cells)
    print(f"wrote {out / 'rocking_mode_map.csv'} and {out / 'rocking_mode_map.png'}")


def edges(values):
    mids = [(a + b) / 2 for a, b in zip(values, values[1:])]
    return [values[0] - (mids[0] - values[0])] + mids + [values[-1] + (values[-1] - mids[-1])]


def plot(path, freqs, amps_g, cells):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch
    import numpy as np
    index = {m: k for k, m in enumerate(MODES)}
    z = np.full((len(amps_g), len(freqs)), np.nan)
    for i, a in enumerate(amps_g):
        for j, f in enumerate(freqs):
            mode = cells.get((round(f, 6), round(a * GRAVITY / GRAVITY, 6)))
            if mode in index:
                z[i, j] = index[mode]
    fig, ax = plt.subplots(figsize=(7.5, 5))
    # Rows of equal height (the amplitudes crowd near the static line), labelled with their a/g.
    rows = np.arange(len(amps_g) + 1) - 0.5
    ax.pcolormesh(edges(freqs), rows, z, cmap=ListedColormap(COLOURS), vmin=-0.5, vmax=len(MODES) - 0.5,
                  edgecolors="#888888", linewidth=0.3)
    ax.set_yticks(range(len(amps_g)), [f"{a:.3g}" for a in amps_g], fontsize=8)
    ax.axhline(np.interp(B / H, amps_g, range(len(amps_g))), color="k", lw=1.5, ls="--")
    ax.text(freqs[-1], np.interp(B / H, amps_g, range(len(amps_g))), "static overturning a/g = b/h  ", va="bottom",
            ha="right", fontsize=8)
    ax.set_xlabel("table frequency [Hz]")
    ax.set_ylabel("table acceleration amplitude a/g [-]")
    ax.set_title(f"Rocking modes of a b = {B} m, h = {H} m block on a sine table (DEM)")
    labels = {"overturned": "overturned / fell (failed)"}
    ax.legend(handles=[Patch(facecolor=c, edgecolor="#888888", label=labels.get(m, m.replace("_", "-")))
                       for m, c in zip(MODES, COLOURS)],
              fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
