#!/usr/bin/python3
"""Fragility of a three-drum marble column (examples/columns/drum_column_elcentro.toml) from a
record suite, in one page of Python with blockdem.sweep.

Each record is scaled to a list of target PGAs; a case fails when a drum's outcome is
overturned, fell or left_model (the sweep's "<drum>.failed" columns, docs/outputs.md). A
lognormal curve P(PGA) = Phi(ln(PGA / theta) / beta) is fitted by maximum likelihood (one
Bernoulli trial per case). Records: the horizontal PEER AT2 files of
../shared/data/ground-motions/peer-at2 when present; otherwise seeded synthetic Kanai-Tajimi
motions that blockdem makes itself (type = "synthetic", docs/records.md).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/fragility_drum_column.py [--out DIR]
        [--quick] [--synthetic] [--threads N]

--quick (the test's configuration): 6 records x 6 levels of 10 s. Default: every record x 8
levels of 15 s. Writes fragility.csv and fragility.png (matplotlib) in --out.
"""
import argparse
import math
import pathlib

import numpy as np

import blockdem

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENARIO = ROOT / "examples" / "columns" / "drum_column_elcentro.toml"
RECORDS = ROOT.parent / "shared" / "data" / "ground-motions" / "peer-at2"
VERTICAL = {"RinaldiUP.AT2"}   # a vertical component: refused as a horizontal motion (docs/records.md)


def record_files(count):
    """The horizontal AT2 records, sorted by name; empty when the data set is absent."""
    if not RECORDS.is_dir():
        return []
    files = sorted(f for f in RECORDS.iterdir() if f.suffix.lower() == ".at2" and f.name not in VERTICAL)
    return files[:count] if count else files


def column_scenario():
    """The column of SCENARIO. Without ../shared/data its El Centro motion (the file's last table)
    cannot load, and every motion here is set by the sweep or set_motion anyway: it is dropped."""
    if RECORDS.is_dir():
        return blockdem.Scenario.from_file(str(SCENARIO))
    text = SCENARIO.read_text(encoding="utf-8").split("[table_motion.horizontal]")[0]
    return blockdem.Scenario.from_toml(text, base_dir=str(SCENARIO.parent))


def run_suite(levels_g, duration_s, count, synthetic, threads):
    """The sweep's table and the name of its record column."""
    scenario = column_scenario()
    scenario.set("simulation.duration", duration_s + 3.0)   # 3 s of rest after the motion
    files = [] if synthetic else record_files(count)
    if files:
        table = blockdem.sweep(scenario, records=files, target_pga=levels_g, target_pga_unit="g",
                               record_keys={"duration": duration_s, "taper": 0.5, "baseline": "polynomial"},
                               threads=threads)
        return table, "record", "real records (PEER AT2)"
    scenario.set_motion(motion={"type": "synthetic", "seed": 1, "target_pga": 0.3, "target_pga_unit": "g",
                                "duration": duration_s})
    seeds = list(range(1, (count or 9) + 1))
    table = blockdem.sweep(scenario, vary={"table_motion.horizontal.seed": seeds,
                                           "table_motion.horizontal.target_pga": levels_g}, threads=threads)
    return table, "table_motion.horizontal.seed", "synthetic Kanai-Tajimi motions"


def failures(table):
    """Per case: completed, and failed (any drum overturned, fell or left the model)."""
    completed = table["status"] == "completed"
    failed = np.zeros(len(completed), dtype=bool)
    for body in table["bodies"]:
        failed |= table[body + ".failed"]
    return completed, failed & completed


def normal_cdf(x):
    return 0.5 * (1.0 + np.vectorize(math.erf)(np.asarray(x) / math.sqrt(2.0)))


def fit_lognormal(pga, failed):
    """Maximum-likelihood (theta, beta) on a log grid refined twice: no optimiser needed, and a
    flat likelihood (all cases failing or none) shows up as theta at the grid's edge."""
    ln_x = np.log(pga)
    lo, hi = ln_x.min() - 1.0, ln_x.max() + 1.0
    b_lo, b_hi = 0.05, 2.0
    best = (0.0, 0.0)
    for _ in range(3):
        ln_theta, beta = np.meshgrid(np.linspace(lo, hi, 121), np.linspace(b_lo, b_hi, 80), indexing="ij")
        p = normal_cdf((ln_x[None, None, :] - ln_theta[..., None]) / beta[..., None])
        p = np.clip(p, 1e-12, 1.0 - 1e-12)
        log_l = np.where(failed, np.log(p), np.log1p(-p)).sum(axis=-1)
        i, j = np.unravel_index(np.argmax(log_l), log_l.shape)
        best = (ln_theta[i, j], beta[i, j])
        d_ln, d_b = (hi - lo) / 12.0, (b_hi - b_lo) / 8.0
        lo, hi = best[0] - d_ln, best[0] + d_ln
        b_lo, b_hi = max(0.01, best[1] - d_b), best[1] + d_b
    return math.exp(best[0]), best[1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="out/python/fragility")
    ap.add_argument("--quick", action="store_true", help="6 records x 6 levels of 10 s (the test's configuration)")
    ap.add_argument("--synthetic", action="store_true", help="synthetic motions even when records are present")
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args()
    levels = [0.15, 0.3, 0.45, 0.6, 0.8, 1.0] if args.quick else [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0]
    duration = 10.0 if args.quick else 15.0
    table, motion_column, source = run_suite(levels, duration, 6 if args.quick else 0, args.synthetic, args.threads)
    completed, failed = failures(table)
    pga_g = table["table_pga_m_s2"] / 9.80665
    theta, beta = fit_lognormal(pga_g[completed], failed[completed])

    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "fragility.csv", "w") as f:
        f.write("case_id,motion,table_pga_g,status,failed\n")
        for i in range(len(completed)):
            f.write(f"{table['case_id'][i]},{table[motion_column][i]},{pga_g[i]:.6g},{table['status'][i]},"
                    f"{int(failed[i])}\n")
    print(f"{source}: {len(completed)} cases, {int(completed.sum())} completed, {int(failed.sum())} failed; "
          f"lognormal fit theta = {theta:.3f} g, beta = {beta:.3f}")
    plot(out / "fragility.png", pga_g[completed], failed[completed], theta, beta, source)
    return table, theta, beta


def plot(path, pga_g, failed, theta, beta, source):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    levels = np.unique(np.round(pga_g, 6))
    share = [failed[np.isclose(pga_g, x)].mean() for x in levels]
    ax.plot(levels, share, "o", label="share of cases failed")
    x = np.linspace(0.01, max(levels.max(), theta) * 1.3, 200)
    ax.plot(x, normal_cdf(np.log(x / theta) / beta), "-", label=f"lognormal: theta {theta:.2f} g, beta {beta:.2f}")
    ax.set_xlabel("table PGA [g]")
    ax.set_ylabel("P(failure)")
    ax.set_ylim(-0.03, 1.03)
    ax.set_title(f"Three-drum column, {source}", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
