#!/usr/bin/python3
"""Fragility curve: the probability of failure of a block or an assembly (a column of drums)
against the peak table acceleration, from a suite of records each scaled to a set of target
PGAs by `blockdem sweep --records ... --target-pga ...`; a lognormal curve
P(x) = Phi(ln(x / theta) / beta) fitted by maximum likelihood (binomial, one trial per
case), with a 95% confidence band from the inverse of the observed information (delta method).

Records: the real accelerograms in /work/shared/data/ground-motions/ (or --records-dir) when
present; otherwise seeded synthetic Kanai-Tajimi motions (scenario key type = "synthetic").

    /usr/bin/python3 studies/fragility.py [--out out/studies/fragility] [--big] [--mpi N]
        [--scenario examples/columns/column3_elcentro.toml] [--body drum2]
        [--measure failure|overturning|sliding --sliding-threshold 0.01]

Failure (--measure failure, the default): a case fails when a dynamic body's outcome is
overturned, fell or left_model (the sweep's <body>.failed column, docs/outputs.md "Outcomes");
any dynamic body of the scenario, or only --body. A drum that came off a column has failed even
when it landed upright. --measure overturning counts only <body>.overturned (the rule before
outcomes existed); sliding adds a peak base slip above --sliding-threshold.
--scenario: the block or assembly (default studies/scenarios/sine_block.toml); its
[table_motion.horizontal] table must come last in the file (it is replaced by the suite's motion).

Default: 9 records (or 9 seeds) x 8 PGA levels = 72 cases of 15 s (about a minute on 2 cores).
--big: 16 levels, and 30 synthetic seeds when there are no records.
Writes fragility.csv (cases), fragility_fit.csv (theta, beta, band) and fragility.png in --out.
"""
import argparse
import csv
import math
import pathlib
import re

import numpy as np

import sweep_common as sc

GROUND_MOTIONS = pathlib.Path("/work/shared/data/ground-motions")
# Horizontal components (the vertical RinaldiUP and the RSN6 copy of IELC180 are left out).
SUITE = ["peer-at2/IELC180.AT2", "peer-at2/ARL360.at2", "peer-at2/Rinaldi228.AT2", "peer-at2/Rinaldi318.AT2",
         "peer-at2/RSN763_LOMAP_GIL067.AT2", "peer-at2/RSN763_LOMAP_GIL337.AT2", "peer-at2/NIS090.AT2",
         "plain-text/Northridge.dat", "plain-text/elCentro.dat dt=0.02 unit=g"]
DURATION_S = 15.0


def scenario_with(out, motion_table, scenario):
    """The study's block or assembly with its table motion replaced and the run DURATION_S long."""
    text = pathlib.Path(scenario).read_text()
    text = text[: text.index("[table_motion.horizontal]")] + motion_table
    # The first `duration =` at the start of a line is [simulation]'s (the motion's is cut off).
    text = re.sub(r"(?m)^duration = .*$", f"duration = {DURATION_S}", text, count=1)
    path = out / "scenario.toml"
    path.write_text(text)
    return path


def run_records(args, blockdem, out, levels):
    folder = pathlib.Path(args.records_dir)
    listing = out / "records.txt"
    listing.write_text("".join(f"{folder / line}\n" for line in SUITE if (folder / line.split()[0]).is_file()))
    scenario = scenario_with(out, '[table_motion.horizontal]\ntype = "none"\n', args.scenario)
    return sc.run_sweep(blockdem, scenario, out / "sweep",
                        ["--records", str(listing), "--target-pga", ",".join(levels), "--target-pga-unit", "g",
                         "--record-key", f"duration={DURATION_S}"], sc.launcher_from(args)), "target_pga_g", "record"


def run_synthetic(args, blockdem, out, levels, seeds):
    scenario = scenario_with(out, '[table_motion.horizontal]\ntype = "synthetic"\nseed = 1\n'
                                  f'target_pga = 0.3\ntarget_pga_unit = "g"\nduration = {DURATION_S}\n', args.scenario)
    return sc.run_sweep(blockdem, scenario, out / "sweep",
                        ["--vary", f"table_motion.horizontal.seed=1:{seeds}:1",
                         "--vary", f"table_motion.horizontal.target_pga={','.join(levels)}"],
                        sc.launcher_from(args)), "table_motion.horizontal.target_pga", "table_motion.horizontal.seed"


def failed(row, body, args):
    """The failure rule of --measure for one body of one case (see the module's text)."""
    if args.measure == "failure":
        return row[body + ".failed"] == "1"
    if args.measure == "overturning":
        return row[body + ".overturned"] == "1"
    return row[body + ".overturned"] == "1" or float(row[body + ".peak_sliding_m"]) > args.sliding_threshold


def phi(z):
    return 0.5 * (1.0 + np.vectorize(math.erf)(np.asarray(z) / math.sqrt(2.0)))


def negative_log_likelihood(params, x, y):
    mu, beta = params
    if beta <= 0:
        return math.inf
    p = np.clip(phi((np.log(x) - mu) / beta), 1e-12, 1 - 1e-12)
    return -float(np.sum(y * np.log(p) + (1 - y) * np.log(1 - p)))


def hessian(f, p, h=1e-4):
    n = len(p)
    out = np.zeros((n, n))
    for i in range(n):
        for j in range(n):
            def at(di, dj):
                q = np.array(p, dtype=float)
                q[i] += di
                q[j] += dj
                return f(q)
            out[i, j] = (at(h, h) - at(h, -h) - at(-h, h) + at(-h, -h)) / (4 * h * h)
    return out


def fit_lognormal(x, y):
    """MLE of (ln theta, beta): a grid for a safe start, then Newton steps on the likelihood."""
    f = lambda q: negative_log_likelihood(q, x, y)
    grid = [(mu, b) for mu in np.linspace(np.log(x.min()) - 1, np.log(x.max()) + 1, 81) for b in np.linspace(0.05, 2, 79)]
    best = np.array(min(grid, key=f))
    for _ in range(50):
        g = np.array([(f(best + d) - f(best - d)) / 2e-5 for d in (np.array([1e-5, 0]), np.array([0, 1e-5]))])
        step = np.linalg.solve(hessian(f, best), g)
        trial = best - step
        while f(trial) > f(best) and np.linalg.norm(step) > 1e-12:
            step /= 2
            trial = best - step
        best = trial
        if np.linalg.norm(step) < 1e-9:
            break
    covariance = np.linalg.inv(hessian(f, best))
    return best, covariance


def band(mu, beta, covariance, xs, z95=1.959964):
    z = (np.log(xs) - mu) / beta
    grad = np.stack([-1.0 / beta * np.ones_like(z), -z / beta])  # dz/dmu, dz/dbeta
    sd = np.sqrt(np.einsum("ik,ij,jk->k", grad, covariance, grad))
    return phi(z), phi(z - z95 * sd), phi(z + z95 * sd)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=str(sc.SOURCE_DIR / "out" / "studies" / "fragility"))
    ap.add_argument("--blockdem")
    ap.add_argument("--records-dir", default=str(GROUND_MOTIONS))
    ap.add_argument("--synthetic", action="store_true", help="use synthetic motions even when records are present")
    ap.add_argument("--scenario", default=str(sc.SCENARIOS / "sine_block.toml"), help="block or assembly to judge")
    ap.add_argument("--body", help="judge only this dynamic body (default: a case fails when any fails)")
    ap.add_argument("--measure", choices=["failure", "overturning", "sliding"], default="failure")
    ap.add_argument("--sliding-threshold", type=float, default=0.01, help="[m] peak base slip that counts as failure")
    ap.add_argument("--big", action="store_true")
    ap.add_argument("--mpi", type=int, default=0)
    args = ap.parse_args()
    blockdem = sc.find_blockdem(args.blockdem)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    levels = [sc.fmt(0.1 * k) for k in range(1, 9)] if not args.big else [sc.fmt(0.05 * k) for k in range(1, 17)]
    if not args.synthetic and (pathlib.Path(args.records_dir) / "peer-at2").is_dir():
        rows, level_key, motion_key = run_records(args, blockdem, out, levels)
        source = "records from " + args.records_dir
    else:
        rows, level_key, motion_key = run_synthetic(args, blockdem, out, levels, 30 if args.big else 9)
        source = "synthetic Kanai-Tajimi motions"
    cases = [r for r in rows if r["status"] == "completed"]
    x = np.array([float(r[level_key]) for r in cases])
    bodies = [c[: -len(".failed")] for c in (rows[0].keys() if rows else []) if c.endswith(".failed")]
    if args.body:
        if args.body not in bodies:
            raise SystemExit(f"--body {args.body}: not a dynamic body of the scenario ({', '.join(bodies)})")
        bodies = [args.body]
    y = np.array([1.0 if any(failed(r, b, args) for b in bodies) else 0.0 for r in cases])
    with open(out / "fragility.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["motion", "pga_g", "failed", "outcomes", "peak_rotation_rad", "peak_sliding_m"])
        for r, yi in zip(cases, y):
            w.writerow([r[motion_key], r[level_key], int(yi), " ".join(f"{b}:{r[b + '.outcome']}" for b in bodies),
                        max(float(r[b + ".peak_rotation_rad"]) for b in bodies),
                        max(float(r[b + ".peak_sliding_m"]) for b in bodies)])
    if y.min() == y.max():
        print(f"every case gave failed = {int(y[0])}: no curve to fit; widen the PGA levels")
        return
    (mu, beta), cov = fit_lognormal(x, y)
    xs = np.linspace(0.02, x.max() * 1.25, 200)
    p, lo, hi = band(mu, beta, cov, xs)
    with open(out / "fragility_fit.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["# median theta [g]", math.exp(mu), "beta", beta, "sd(ln theta)", math.sqrt(cov[0, 0]),
                    "sd(beta)", math.sqrt(cov[1, 1]), "cases", len(y)])
        w.writerow(["pga_g", "probability", "lower_95", "upper_95"])
        w.writerows([[sc.fmt(a), sc.fmt(b), sc.fmt(c), sc.fmt(d)] for a, b, c, d in zip(xs, p, lo, hi)])
    print(f"lognormal fit: median {math.exp(mu):.3f} g, beta {beta:.3f} ({len(y)} cases, {int(y.sum())} failures)")
    plot(out / "fragility.png", x, y, xs, p, lo, hi, mu, beta, args, source)
    print(f"wrote {out / 'fragility.csv'}, {out / 'fragility_fit.csv'} and {out / 'fragility.png'}")


def plot(path, x, y, xs, p, lo, hi, mu, beta, args, source):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.fill_between(xs, lo, hi, color="tab:blue", alpha=0.2, label="95% confidence band")
    ax.plot(xs, p, color="tab:blue", label=f"lognormal MLE: median {math.exp(mu):.2f} g, beta {beta:.2f}")
    levels = sorted(set(x))
    ax.plot(levels, [y[x == v].mean() for v in levels], "ko", label="fraction of the suite per level")
    jitter = (np.random.default_rng(1).random(len(x)) - 0.5) * 0.02
    ax.plot(x, y + jitter * 2, "|", color="grey", alpha=0.6, label="cases (0 / 1)")
    what = {"failure": "overturned, fell or left the model", "overturning": "overturning"}.get(
        args.measure, f"base slip > {args.sliding_threshold} m or overturning")
    ax.set_xlabel("PGA of the table motion [g]")
    ax.set_ylabel(f"P({what})")
    ax.set_title(f"Fragility of {pathlib.Path(args.scenario).stem} ({source.split(' from ')[0]})", fontsize=10)
    ax.set_ylim(-0.05, 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
