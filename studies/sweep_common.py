"""Shared by the study scripts: find the blockdem binary, run a sweep, read its table.

The studies drive `blockdem sweep` (docs/sweeps.md) and only post-process its results.csv, so
that every number in a figure comes from the C++ engine; Python draws and fits.
Run them with Debian's /usr/bin/python3 (python3-matplotlib, python3-numpy).
"""
import csv
import math
import os
import pathlib
import subprocess
import sys

SOURCE_DIR = pathlib.Path(__file__).resolve().parent.parent
SCENARIOS = SOURCE_DIR / "studies" / "scenarios"


def find_blockdem(given=None):
    """The blockdem binary: --blockdem, $BLOCKDEM, or build/blockdem in the source tree."""
    for candidate in (given, os.environ.get("BLOCKDEM"), SOURCE_DIR / "build" / "blockdem"):
        if candidate and pathlib.Path(candidate).is_file():
            return str(pathlib.Path(candidate).resolve())
    sys.exit("blockdem not found: build it (make build), or pass --blockdem PATH or set $BLOCKDEM")


def write_case_list(path, keys, rows):
    """A --cases file: header of scenario keys, one row of values per case."""
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        w.writerows(rows)


def run_sweep(blockdem, scenario, out_dir, extra, launcher=()):
    """Runs (or resumes) a sweep and returns its rows as dicts. `launcher`: e.g. mpirun words."""
    command = [*launcher, blockdem, "sweep", str(scenario), "--out", str(out_dir), *extra]
    print("+", " ".join(command), flush=True)
    subprocess.run(command, check=True)
    with open(pathlib.Path(out_dir) / "results.csv", newline="") as f:
        return list(csv.DictReader(f))


def launcher_from(args):
    """mpirun words for --mpi N (with --oversubscribe, and --allow-run-as-root only as root)."""
    if not getattr(args, "mpi", 0):
        return ()
    words = ["mpirun", "--oversubscribe", "-n", str(args.mpi)]
    if os.geteuid() == 0:
        words.insert(1, "--allow-run-as-root")
    return tuple(words)


def housner_p(b, h, g=9.81):
    """Housner's frequency parameter p = sqrt(3 g / (4 R)) [rad/s] of a b x h half-size block."""
    return math.sqrt(3.0 * g / (4.0 * math.hypot(b, h)))


def fmt(x):
    """Numbers for case lists: short and exact enough."""
    return f"{x:.8g}"
