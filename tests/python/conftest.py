"""Shared scenarios of the Python suite (run by ctest as python.pytest, PYTHONPATH=<build>/python)."""
import os
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("BLOCKDEM_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def block_on_table(mu=0.5, duration=0.2, dt=1e-4, **extra_simulation):
    """A 0.5 x 0.2 m, 1 kg block resting on a driven table (the paper's sliding case, at rest)."""
    simulation = {"duration": duration, "dt": dt, "gravity": 9.81, "output_interval": 1e-3}
    simulation.update(extra_simulation)
    return {
        "simulation": simulation,
        "contact": {"kn": 2.0e4, "ks": 2.0e4, "mu": mu, "e": 0.4, "e_meaning": "paper", "h_s": 1.0},
        "bodies": [
            {"name": "table", "kind": "driven", "shape": "rectangle", "width": 4.0, "height": 0.2,
             "center": [0.0, -0.1], "density": 1000.0},
            {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.5, "height": 0.2,
             "center": [0.0, 0.1], "mass": 1.0},
        ],
    }


@pytest.fixture
def source_dir():
    return SOURCE_DIR


def pytest_configure(config):
    # The longer rows (several seconds each): still run by `make test`; `-m "not slow"` skips them.
    config.addinivalue_line("markers", "slow: a row that takes several seconds")
