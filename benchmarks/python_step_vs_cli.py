"""Stepping a 1e4-brick wall from Python against the CLI (docs/python.md, "Speed").

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/python_step_vs_cli.py [build/blockdem [repeats]]

Prints body-steps/s of `blockdem run` (run_info.json's wall time: the stepping and the writers),
of Simulation.step(1000), and of Simulation.run with a callback every 100 steps; three repeats
by default,
each after the other, so that a loaded machine shows as spread. Not a test: nothing is asserted.
"""
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import blockdem

WALL = """
[simulation]
duration = 0.04        # 1000 steps
dt = 4.0e-5
output_interval = 1e300
[contact]
kn = 6.0e7
ks = 6.0e7
mu = 0.6
e = 0.5
e_meaning = "rebound"
h_s = 0.2
[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 22.0
height = 0.2
center = [10.0, -0.1]
density = 1000.0
[[assemblies]]
type = "wall"
name = "brick"
density = 2000.0
length = 20.0
courses = 100
brick_length = 0.2
brick_height = 0.1
[table_motion.horizontal]
type = "sine"
amplitude = 0.3
unit = "g"
period = 0.5
"""


def main():
    cli = sys.argv[1] if len(sys.argv) > 1 else "build/blockdem"
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    steps = 1000
    with tempfile.TemporaryDirectory() as tmp:
        scenario_file = Path(tmp) / "wall.toml"
        scenario_file.write_text(WALL)
        scenario = blockdem.Scenario.from_file(scenario_file)
        for repeat in range(repeats):
            out = Path(tmp) / f"cli{repeat}"
            subprocess.run([cli, "run", str(scenario_file), "--out", str(out), "-q", "--threads", "1"], check=True,
                           stdout=subprocess.DEVNULL)
            cli_s = json.loads((out / "run_info.json").read_text())["wall_time_s"]
            sim = blockdem.Simulation(scenario, threads=1, history=False)
            bodies = len(sim.body_names)
            start = time.perf_counter()
            sim.step(steps)
            step_s = time.perf_counter() - start
            sim = blockdem.Simulation(scenario, threads=1, history=False)
            start = time.perf_counter()
            sim.run(until=steps * sim.dt, callback=lambda s: s.positions[1, 0], every=100 * sim.dt)
            callback_s = time.perf_counter() - start
            rate = bodies * steps
            print(f"{bodies} bodies, {steps} steps: CLI {rate / cli_s:.3g} body-steps/s, step({steps}) {rate / step_s:.3g}, "
                  f"callback every 100 steps {rate / callback_s:.3g}", flush=True)


if __name__ == "__main__":
    main()
