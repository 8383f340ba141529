#!/usr/bin/python3
"""Figure of a ground-motion record and its response spectrum, for `blockdem motion`.

Reads DIR/record.csv and DIR/spectrum.csv written by `blockdem motion FILE --out DIR` and writes
DIR/motion.png: acceleration, velocity and displacement (as recorded and baseline-corrected) and
the pseudo-acceleration spectrum. Run with Debian's /usr/bin/python3 (python3-matplotlib,
python3-numpy). Exit status 3 when matplotlib or numpy is missing, so the caller can say so.
"""
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as error:
    print(f"plot_motion.py: {error}; install python3-matplotlib and python3-numpy", file=sys.stderr)
    sys.exit(3)

G = 9.80665  # [m/s^2] the standard gravity used everywhere in blockdem's record handling


def main(folder):
    record = np.genfromtxt(os.path.join(folder, "record.csv"), delimiter=",", names=True)
    spectrum = np.genfromtxt(os.path.join(folder, "spectrum.csv"), delimiter=",", names=True, skip_header=1)
    t = record["time_s"]
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), constrained_layout=True)
    axes[0].plot(t, record["acceleration_m_s2"] / G, lw=0.6, color="k")
    axes[0].set_ylabel("acceleration [g]")
    for ax, name, unit in ((axes[1], "velocity", "m/s"), (axes[2], "displacement", "m")):
        ax.plot(t, record[f"{name}_{unit.replace('/', '_')}"], lw=0.8, label="as recorded")
        ax.plot(t, record[f"corrected_{name}_{unit.replace('/', '_')}"], lw=0.8, label="baseline-corrected")
        ax.set_ylabel(f"{name} [{unit}]")
        ax.legend(loc="upper right", fontsize="small")
    axes[2].set_xlabel("time [s]")
    positive = spectrum["period_s"] > 0
    axes[3].semilogx(spectrum["period_s"][positive], spectrum["psa_g"][positive], color="k")
    axes[3].set_xlabel("period [s]")
    axes[3].set_ylabel("pseudo-acceleration [g]")
    with open(os.path.join(folder, "spectrum.csv")) as f:
        axes[3].set_title(f.readline().lstrip("# ").strip(), fontsize="small")
    for ax in axes:
        ax.grid(True, which="both", lw=0.3)
    fig.savefig(os.path.join(folder, "motion.png"), dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: plot_motion.py DIR (with DIR/record.csv and DIR/spectrum.csv)", file=sys.stderr)
        sys.exit(2)
    main(sys.argv[1])
