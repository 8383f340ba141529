"""A run steered from Python (set_external_force, hold_velocity) saved mid-run and continued with
from_state ends byte for byte as the run that never stopped, in 2-D and 3-D: the state file carries
the caller's loads and held velocities (/external_loads, /external_loads3d) and the external work
booked so far (/energy external_work_j), io/external_loads_state.hpp."""
import filecmp

import numpy as np
import pytest

import blockdem
from conftest import block_on_table

FILES = ("history.csv", "energy.csv", "summary.json")
# What a returned summary holds besides summary.json: the wall clock and the folder.
NOT_IN_THE_FILE = ("wall_time_s", "run_folder", "state_files")
DURATION_S = 0.2
SAVE_S = 0.1
HOLD_S = 0.04   # the hold starts here, before the save; the push acts from t = 0


def without_wall_clock(summary):
    return {k: v for k, v in summary.items() if k not in NOT_IN_THE_FILE}


def step_to(sim, t_s):
    sim.step(round(t_s / sim.dt) - sim.step_index)


def same_files(a, b):
    for name in FILES:
        assert filecmp.cmp(a / name, b / name, shallow=False), f"{name} differs between {a} and {b}"


def two_blocks_on_a_table():
    """block_on_table with a second block beside the first: one pushed, one held."""
    d = block_on_table(mu=0.5, duration=DURATION_S)
    held = dict(d["bodies"][1], name="held", center=[1.0, 0.1])
    d["bodies"][1]["name"] = "pushed"
    d["bodies"].append(held)
    return blockdem.Scenario.from_dict(d)


def two_boxes_on_a_slab():
    return blockdem.Scenario.from_toml(f"""dimension = 3
[simulation]
duration = {DURATION_S}
output_interval = 0.005
[contact]
kn = 1e6
ks = 1e6
mu = 0.5
e = 0.5
[[bodies]]
name = "slab"
kind = "fixed"
shape = "box"
size = [4.0, 4.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "pushed"
shape = "box"
size = [0.4, 0.4, 0.1]
position = [0.0, 0.0, 0.05]
density = 1000.0
[[bodies]]
name = "held"
shape = "box"
size = [0.4, 0.4, 0.1]
position = [1.0, 1.0, 0.05]
density = 1000.0
""")


# Per dimension: the class, the scenario, the push (force, torque), the held velocity (velocity,
# angular velocity), and the views compared at the end.
DIMENSIONS = {
    "2d": (blockdem.Simulation, two_blocks_on_a_table, ((12.0, 0.0), 0.05), ((0.1, 0.0), 0.0),
           ("positions", "rotations", "velocities", "angular_velocities")),
    "3d": (blockdem.Simulation3d, two_boxes_on_a_slab, ((100.0, 20.0, 0.0), (0.0, 0.0, 1.5)),
           ((0.1, -0.05, 0.0), (0.0, 0.0, 0.5)), ("positions", "quaternions", "velocities", "angular_velocities")),
}


def steered(cls, scenario, push, hold, **kwargs):
    """A run pushed from t = 0 and holding a body from HOLD_S on, stepped to SAVE_S."""
    sim = cls(scenario, threads=1, **kwargs)
    sim.set_external_force("pushed", push[0], torque=push[1])
    step_to(sim, HOLD_S)
    sim.hold_velocity("held", hold[0], angular_velocity=hold[1])
    step_to(sim, SAVE_S)
    return sim


def to_the_end(sim):
    while not sim.done:
        sim.step(333)   # (uneven pieces: a run does not depend on how it is cut)
    return sim.finish()


@pytest.mark.parametrize("dimension", DIMENSIONS)
def test_a_steered_run_restarted_ends_as_the_straight_run(dimension, tmp_path):
    # The straight run saves its state at T/2 while pushed and held; restarted from it in a new
    # folder on two threads, with no load set again, the files end byte for byte as the straight
    # run's and the final state is the same to the last bit (tolerance none: a restart restores
    # every bit of the state, loads included).
    cls, scenario, push, hold, views = DIMENSIONS[dimension]
    s = scenario()
    full = steered(cls, s, push, hold, out_dir=tmp_path / "full", save_state=[SAVE_S])
    loads_at_save = {body: full.external_force(body) for body in ("pushed", "held")}
    summary = to_the_end(full)
    assert summary["status"] == "completed" and len(summary["state_files"]) == 1
    held = full.body_names.index("held")
    assert np.allclose(full.velocities[held][:2], hold[0][:2], atol=1e-9), "the hold did not hold: the test tests nothing"
    assert full.energy()["external_work_J"] != 0.0

    restarted = cls.from_state(summary["state_files"][0], out_dir=tmp_path / "new", threads=2)
    # The loads as they were at the save (the held body's is the force that held it last).
    for body, load in loads_at_save.items():
        assert restarted.external_force(body) == load, body
    ended = to_the_end(restarted)
    same_files(tmp_path / "full", tmp_path / "new")
    assert without_wall_clock(ended) == without_wall_clock(summary)
    for view in views:
        np.testing.assert_array_equal(getattr(restarted, view), getattr(full, view), err_msg=view)
    assert restarted.energy() == full.energy()
    for body in ("pushed", "held"):
        assert restarted.external_force(body) == full.external_force(body), body


@pytest.mark.parametrize("dimension", DIMENSIONS)
def test_a_steered_run_stopped_by_finish_goes_on_in_place(dimension, tmp_path):
    # finish() at T/2 writes the state as an interrupted run; from_state without out_dir goes on
    # in the run's own folder, which ends as the straight run's.
    cls, scenario, push, hold, _ = DIMENSIONS[dimension]
    s = scenario()
    to_the_end(steered(cls, s, push, hold, out_dir=tmp_path / "full"))
    half = steered(cls, s, push, hold, out_dir=tmp_path / "half")
    stopped = half.finish()
    assert stopped["status"] == "interrupted" and len(stopped["state_files"]) == 1
    del half
    again = cls.from_state(stopped["state_files"][0], threads=1)
    assert to_the_end(again)["status"] == "completed"
    same_files(tmp_path / "full", tmp_path / "half")
