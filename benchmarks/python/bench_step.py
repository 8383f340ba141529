#!/usr/bin/python3
"""The Python module's stepping cost (docs/python.md, "Speed"): scene S3 (a running-bond wall of
N bricks on a shaken table, scenes/masonry.cpp; 1e4 by default) stepped from Python with
sim.step(1000), against `blockdem run` on the same scenario and against the bare step that
`blockdem bench --scene wall` times, and the cost of a Python callback every 100 steps. Runs alternate (CLI, sim.step, sim.run with a callback) so that a loaded
machine slows all three alike; each figure is the best of its runs, as `blockdem bench` reports.
Both wall-clock and CPU time (this process's, all threads; the CLI's "CPU ms/step" column) are
given: on a loaded machine the wall clock includes time spent waiting for a core. Not a test:
nothing is asserted on time.

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/python/bench_step.py [--bricks 10000]
        [--steps 1000] [--rounds 3] [--threads 1] [--cli build/blockdem]

The scene is written here as a scenario (the same bricks, table, contact and motion as
s3_wall_scene: 0.2 x 0.1 m bricks of 40 kg in round(sqrt(2N)) columns, odd rows shifted by
0.1 m; kn = ks = 6e7 N/m, mu = 0.6, e = 0.5 rebound, h_s = 0.2; 0.3 g sin(4 pi t); dt = 1e-4 s),
with the bricks not recorded (record = false) as in the bench.
"""
import argparse
import math
import os
import resource
import subprocess
import tempfile
import time

import blockdem


def s3_wall(bricks, duration_s):
    columns = max(2, round(math.sqrt(2.0 * bricks)))
    length, height = 0.2, 0.1
    bodies = [{"name": "table", "kind": "driven", "shape": "polygon", "density": 1000.0,
               "vertices": [[-0.5, -0.2], [columns * length + 0.5, -0.2], [columns * length + 0.5, 0.0], [-0.5, 0.0]]}]
    made, row = 0, 0
    while made < bricks:
        in_row, x0 = (columns, 0.0) if row % 2 == 0 else (columns - 1, 0.5 * length)
        for j in range(in_row):
            if made == bricks:
                break
            x = x0 + j * length
            bodies.append({"name": f"brick{made}", "kind": "dynamic", "shape": "rectangle", "width": length,
                           "height": height, "center": [x + 0.5 * length, (row + 0.5) * height], "mass": 40.0,
                           "record": False})
            made += 1
        row += 1
    return blockdem.Scenario.from_dict({
        "simulation": {"duration": duration_s, "dt": 1e-4, "gravity": 9.81, "output_interval": duration_s},
        "contact": {"kn": 6e7, "ks": 6e7, "mu": 0.6, "e": 0.5, "e_meaning": "rebound", "h_s": 0.2},
        "bodies": bodies,
        "table_motion": {"horizontal": {"type": "sine", "amplitude": 0.3, "unit": "g", "period": 0.5}}})


def cli_brick_steps_per_s(cli, bricks, steps, threads):
    """(wall-clock, CPU) brick-steps/s of one `blockdem bench` run."""
    out = subprocess.run([cli, "bench", "--scene", "wall", "--sizes", str(bricks), "--threads", str(threads),
                          "--work", str(bricks * steps), "--repeats", "1"], check=True, capture_output=True, text=True).stdout
    row = next(line for line in out.splitlines() if line.startswith("| wall |")).split("|")
    return float(row[7]), bricks / (float(row[6]) * 1e-3)   # block-steps/s; bricks / CPU s per step


def cli_run_brick_steps_per_s(cli, scenario_toml, bricks, steps, threads):
    """(wall-clock, CPU) brick-steps/s of `blockdem run` on the same scenario: two runs, of 5 and
    of 5 + steps steps, so that the difference leaves out reading and building the scene."""
    figures = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in (5, 5 + steps):
            path = os.path.join(tmp, f"wall{n}.toml")
            with open(path, "w") as f:
                f.write(scenario_toml.replace("duration = 100.0", f"duration = {n * 1e-4 + 0.5e-4!r}", 1))
            cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
            wall = time.perf_counter()
            subprocess.run([cli, "run", path, "--out", os.path.join(tmp, f"out{n}"), "-q", "--threads", str(threads)],
                           check=True, stdout=subprocess.DEVNULL)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            figures.append((time.perf_counter() - wall, after.ru_utime + after.ru_stime - cpu.ru_utime - cpu.ru_stime))
    (w0, c0), (w1, c1) = figures
    return bricks * steps / (w1 - w0), bricks * steps / (c1 - c0)


def timed(bricks, steps, work):
    """(wall-clock, CPU) brick-steps/s of work()."""
    wall, cpu = time.perf_counter(), time.process_time()
    work()
    return bricks * steps / (time.perf_counter() - wall), bricks * steps / (time.process_time() - cpu)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bricks", type=int, default=10000)
    ap.add_argument("--steps", type=int, default=1000)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--cli", default="build/blockdem")
    args = ap.parse_args()
    started = time.perf_counter()
    scenario = s3_wall(args.bricks, 100.0)
    sim = blockdem.Simulation(scenario, threads=args.threads, history=False)
    scenario_toml = scenario.to_toml()
    assert "duration = 100.0" in scenario_toml
    print(f"scene S3, {args.bricks} bricks, built in {time.perf_counter() - started:.1f} s; "
          f"{args.steps} steps per run, {args.threads} thread(s), {args.rounds} rounds")
    sim.step(5)   # the bench's warm-up
    calls = []
    best = {k: [0.0, 0.0] for k in ("cli", "run", "step", "callback")}

    def keep(name, figures):
        best[name] = [max(b, f) for b, f in zip(best[name], figures)]

    def with_callback():
        sim.run(until=sim.t + args.steps * sim.dt, callback=lambda s: calls.append(s.positions[0, 0]), every=100 * sim.dt)

    for r in range(args.rounds):
        keep("cli", cli_brick_steps_per_s(args.cli, args.bricks, args.steps, args.threads))
        keep("run", cli_run_brick_steps_per_s(args.cli, scenario_toml, args.bricks, args.steps, args.threads))
        keep("step", timed(args.bricks, args.steps, lambda: sim.step(args.steps)))
        keep("callback", timed(args.bricks, args.steps, with_callback))
        print(f"round {r + 1} (best so far, wall / CPU): " +
              ", ".join(f"{k} {w:.4g} / {c:.4g}" for k, (w, c) in best.items()))
    assert len(calls) >= args.rounds * (args.steps // 100 - 1), len(calls)
    for i, clock in enumerate(("wall-clock", "CPU")):
        cli, run, step, callback = best["cli"][i], best["run"][i], best["step"][i], best["callback"][i]
        print(f"{clock} brick-steps/s, best of {args.rounds}: CLI bench {cli:.4g}; CLI run {run:.4g}; "
              f"Python sim.step({args.steps}) {step:.4g} ({100 * (step / cli - 1):+.1f}% vs bench, "
              f"{100 * (step / run - 1):+.1f}% vs run); with a callback every 100 steps "
              f"{callback:.4g} ({100 * (callback / step - 1):+.1f}% vs sim.step)")

if __name__ == "__main__":
    main()
