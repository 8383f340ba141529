"""blockdem.Simulation3d (python/bind_simulation_3d.cpp): a 3-D scenario stepped from Python with the
2-D Simulation's API, against `blockdem run` on the same file and against closed forms."""
import csv
import json
import math

import numpy as np
import pytest

import blockdem
from conftest import block_on_table

# A 0.4 x 0.4 x 0.8 m block at rest on a fixed slab, and a 10 cm cube falling 0.05 m onto it.
DROP = """dimension = 3
[simulation]
duration = 0.2
output_interval = 0.01
dt = 2e-5
[contact]
kn = 1e7
ks = 1e7
mu = 0.5
e = 0.5
[[bodies]]
name = "slab"
kind = "fixed"
shape = "box"
size = [2.0, 2.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "pier"
shape = "box"
size = [0.4, 0.4, 0.8]
position = [0.0, 0.0, 0.4]
density = 2000.0
[[bodies]]
name = "cube"
shape = "box"
size = [0.1, 0.1, 0.1]
position = [0.0, 0.0, 0.9]
density = 1000.0
"""


def test_a_falling_cube_follows_free_fall_until_it_lands():
    sim = blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP), threads=1)
    assert sim.body_names == ["slab", "pier", "cube"]
    assert sim.t == 0.0 and sim.step_index == 0 and sim.dt == pytest.approx(2e-5)
    assert sim.positions.shape == (3, 3) and sim.quaternions.shape == (3, 4)
    np.testing.assert_array_equal(sim.quaternions[:, 0], 1.0)   # the turn since t = 0
    z0 = sim.positions[2, 2]
    assert sim.step(2500) == 2500                               # t = 0.05 s, in flight
    # Central differences integrate a constant g exactly at the steps (z = z0 - g t^2 / 2 up to
    # the start's half step, g dt t / 2 = 5e-6 m): within 1e-5 m.
    assert sim.t == pytest.approx(0.05, abs=1e-12)
    assert sim.positions[2, 2] == pytest.approx(z0 - 0.5 * 9.81 * 0.05 ** 2, abs=1e-5)
    assert sim.velocities[2, 2] == pytest.approx(-9.81 * 0.05, rel=1e-9)
    # Then it lands on the pier's top (z = 0.8 m, its centroid 0.05 m above) and rebounds: it
    # neither sinks into the pier by more than the springs' sag (1 mm) nor rises to where it fell
    # from (e = 0.5 takes energy away).
    lowest, highest = z0, 0.0
    while not sim.done:
        sim.step(50)
        lowest = min(lowest, sim.positions[2, 2])
        if lowest < 0.851:  # (landed: the rebound from here on)
            highest = max(highest, sim.positions[2, 2])
    assert sim.t == pytest.approx(0.2, abs=1e-12)
    assert 0.849 < lowest < 0.85 and highest < z0 - 0.02, (lowest, highest)
    energy = sim.energy()
    assert abs(energy["balance_error"]) < 1e-2
    summary = sim.summary()
    assert summary["dimension"] == 3 and summary["status"] == "completed"  # at its end (sim.done)
    assert summary["bodies"][2]["name"] == "cube"


def test_stepped_from_python_writes_the_files_of_blockdem_run(tmp_path, source_dir):
    """The drum column example cut into uneven pieces from Python: the same history.csv as one run."""
    scenario = blockdem.Scenario.from_file(source_dir / "examples/3d/drum_column.toml")
    scenario.set("simulation.duration", 0.1)  # (480 steps of 2.08e-4 s)
    whole = blockdem.Simulation3d(scenario, threads=1, out_dir=tmp_path / "whole")
    whole.step(10 ** 9)
    whole_summary = whole.finish()
    cut = blockdem.Simulation3d(scenario, threads=1, out_dir=tmp_path / "cut")
    for n in (1, 17, 300, 5):
        assert cut.step(n) == n
    cut.step(10 ** 9)
    cut_summary = cut.finish()
    assert cut_summary["status"] == whole_summary["status"] == "completed"
    for name in ("history.csv", "energy.csv", "summary.json"):
        assert (tmp_path / "cut" / name).read_bytes() == (tmp_path / "whole" / name).read_bytes(), name
    rows = list(csv.reader(open(tmp_path / "whole" / "history.csv")))
    assert rows[0][0] == "t_s" and "drum_3.qw" in rows[0]
    assert float(rows[-1][0]) == pytest.approx(0.1, abs=1e-9)
    assert json.load(open(tmp_path / "whole" / "summary.json"))["dimension"] == 3


def test_a_3d_scenario_given_to_the_2d_simulation_names_simulation3d():
    with pytest.raises(blockdem.InputError, match="Simulation3d"):
        blockdem.Simulation(blockdem.Scenario.from_toml(DROP))


def test_a_2d_scenario_given_to_the_3d_simulation_names_simulation():
    # The 3-D reader called the 2-D keys unknown ("key 'simulation': unknown key").
    with pytest.raises(blockdem.InputError, match=r"key 'dimension': is not given, so the scenario is 2-D: a 2-D "
                                                  r"scenario runs in blockdem.Simulation \("):
        blockdem.Simulation3d(blockdem.Scenario.from_dict(block_on_table()))
    with pytest.raises(blockdem.InputError, match=r"key 'dimension': is 2: a 2-D scenario runs in blockdem.Simulation \("):
        blockdem.Simulation3d(blockdem.Scenario.from_dict({"dimension": 2, **block_on_table()}))


def test_bad_arguments_are_refused():
    with pytest.raises(ValueError, match="threads"):
        blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP), threads=0)
    # 1e9 threads ran the machine out of memory (MemoryError); the CLI's -j takes 1 to 4096.
    with pytest.raises(ValueError, match="threads must be 1 to 4096, got 1000000000"):
        blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP), threads=10**9)
    with pytest.raises(ValueError, match="threads must be 1 to 4096, got 4097"):
        blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP), threads=4097)
    sim = blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP), threads=1)
    with pytest.raises(ValueError, match="n >= 0"):
        sim.step(-1)


def test_the_summary_says_the_status_finish_returned():
    # summary() said "running" after finish() had returned "interrupted".
    sim = blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP), threads=1)
    sim.step(10)
    assert sim.summary()["status"] == "running"
    assert sim.finish()["status"] == "interrupted"
    assert sim.summary()["status"] == "interrupted"
    short = blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP.replace("duration = 0.2", "duration = 0.01")), threads=1)
    short.step(1000)
    assert short.done and short.summary()["status"] == "completed"
    assert short.finish()["status"] == "completed" and short.summary()["status"] == "completed"


def test_a_settled_pier_starts_loaded_and_its_contacts_carry_its_weight():
    # [settling] in 3-D (world/settling_3d.hpp): the pier laid exactly touching the slab settles
    # before t = 0, so at t = 0 it sits m g / (4 kn) into the slab (each of its four corners
    # carries a quarter of its weight) and starts from rest; contacts() then shows four points
    # whose normal forces sum to its weight. Closed forms: statics; tolerances 1e-3 of the
    # closure and of m g. (Without the cube, which would land on the pier while settling.)
    text = DROP.split('[[bodies]]\nname = "cube"')[0].replace("[[bodies]]", "[settling]\n[[bodies]]", 1)
    sim = blockdem.Simulation3d(blockdem.Scenario.from_toml(text), threads=1)
    assert sim.t == 0.0 and sim.summary()["settling"]["steps"] > 0
    m_g = 0.4 * 0.4 * 0.8 * 2000.0 * 9.81
    closure = m_g / (4 * 1e7)
    assert sim.positions[1, 2] == pytest.approx(0.4 - closure, abs=1e-3 * closure)
    c = sim.contacts()
    on_slab = c[(c["body_a"] == 0) & (c["body_b"] == 1)]
    assert len(on_slab) == 4 and np.all(on_slab["nz"] > 0.999999)
    assert on_slab["normal_force"].sum() == pytest.approx(m_g, rel=1e-3)
    assert np.all(on_slab["overlap"] == pytest.approx(closure, rel=1e-3))
    assert set(c.dtype.names) >= {"x", "y", "z", "nx", "ny", "nz", "fx", "fy", "fz", "shear_force", "sliding"}


def test_history_holds_the_rows_history_csv_writes(tmp_path):
    # history() (run/run_trace_3d.hpp) keeps the rows of history.csv and energy.csv in memory at
    # full precision: the same times, bodies (all but the fixed slab) and values as the files
    # (written to 9 significant digits: compared to 1e-8 relative).
    sim = blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP), threads=1, out_dir=tmp_path / "run")
    sim.step(5000)
    sim.finish()
    h = sim.history()
    assert h["bodies"] == ["pier", "cube"] and list(h["body_ids"]) == [1, 2]
    rows = list(csv.DictReader(open(tmp_path / "run" / "history.csv")))
    assert len(h["t"]) == len(rows) == 11 and h["x"].shape == (11, 2)
    for r, row in enumerate(rows):
        assert h["t"][r] == pytest.approx(float(row["t_s"]), abs=1e-12)
        for k, name in enumerate(h["bodies"]):
            for key, column in (("z", "z_m"), ("qw", "qw"), ("tilt", "tilt_rad"), ("vz", "vz_m_s")):
                assert h[key][r, k] == pytest.approx(float(row[f"{name}.{column}"]), rel=1e-8, abs=1e-12), (r, name, key)
    energy = list(csv.DictReader(open(tmp_path / "run" / "energy.csv")))
    np.testing.assert_allclose(h["energy"]["kinetic_J"], [float(e["kinetic_J"]) for e in energy], rtol=1e-8, atol=1e-12)
    with pytest.raises(ValueError, match="keeps no history"):
        blockdem.Simulation3d(blockdem.Scenario.from_toml(DROP), history=False).history()


def test_ctrl_c_while_the_model_settles_raises_at_once():
    # A window far longer than settling is allowed: without the stop it would settle for hours.
    import _thread
    import threading
    import time

    text = DROP.split('[[bodies]]\nname = "cube"')[0].replace(
        "[[bodies]]", "[settling]\nwindow = 1000.0\nmax_time = 1.0e4\n[[bodies]]", 1)
    threading.Timer(0.3, _thread.interrupt_main).start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        blockdem.Simulation3d(blockdem.Scenario.from_toml(text), threads=1)
    assert time.monotonic() - started < 5.0
