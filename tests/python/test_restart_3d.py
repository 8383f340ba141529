"""State files and restarts of a 3-D run from Python: Simulation3d(save_state=..., save_state_every=...),
finish() before the end, and Simulation3d.from_state, over the CLI's own 3-D state-file code
(run/scenario_run_3d.hpp), checked as test_restart.py checks the 2-D ones and as
tests/cli/test_restart_3d.sh checks `blockdem run --restart` in 3-D."""
import filecmp
import math

import numpy as np
import pytest

import blockdem
from conftest import block_on_table

FILES = ("history.csv", "energy.csv", "summary.json", "vtk/bodies.pvd")
# What a summary returned by finish() holds besides summary.json: the wall clock and the folder.
NOT_IN_THE_FILE = ("wall_time_s", "run_folder", "state_files")
DURATION_S = 0.3
HALF_S = 0.15


def drums(source_dir):
    """The drum column example (three drums on a table shaken in x, y and z), 0.3 s: its contacts
    carry shear history and its VTK frames are written, so a restart has both to carry on."""
    s = blockdem.Scenario.from_file(source_dir / "examples/3d/drum_column.toml")
    s.set("simulation.duration", DURATION_S)
    return s


def same_files(a, b):
    for name in FILES:
        assert filecmp.cmp(a / name, b / name, shallow=False), f"{name} differs between {a} and {b}"
    assert sorted(p.name for p in (a / "vtk").iterdir()) == sorted(p.name for p in (b / "vtk").iterdir())


def steps_to(sim, t_s):
    return round(t_s / sim.dt) - sim.step_index


def to_the_end(sim):
    """Steps to the end in uneven pieces (a run does not depend on how it is cut), then finishes."""
    while not sim.done:
        sim.step(333)
    return sim.finish()


def without_wall_clock(summary):
    return {k: v for k, v in summary.items() if k not in NOT_IN_THE_FILE}


def test_restart_at_half_time_ends_as_the_straight_run(source_dir, tmp_path):
    # As tests/cli/test_restart_3d.sh's drum rows, through Python: a run straight to T on one
    # thread, saving states at T/2 (save_state) and every 0.1 s (save_state_every, the end's
    # included); restarted from two of them into new folders on two threads, the files end byte for byte as the straight
    # run's, and the final state is the same to the last bit (tolerance none: a restart
    # restores every bit of the state, and the step does not depend on the thread count).
    s = drums(source_dir)
    full = blockdem.Simulation3d(s, threads=1, out_dir=tmp_path / "full", save_state=[HALF_S], save_state_every=0.1)
    summary = to_the_end(full)
    assert summary["status"] == "completed"
    names = [p.rsplit("/", 1)[-1] for p in summary["state_files"]]
    assert names == ["t_0.100000s.h5", "t_0.150000s.h5", "t_0.200000s.h5", "t_0.300000s.h5"], names
    moved = np.abs(full.positions - blockdem.Simulation3d(s, threads=1).positions).max()
    assert moved > 1e-3, "the drums hardly moved: the restart would carry little"
    before = {name: (tmp_path / "full" / name).read_bytes() for name in FILES}

    for name, folder in (("t_0.150000s.h5", "new"), ("t_0.200000s.h5", "every")):
        restarted = blockdem.Simulation3d.from_state(tmp_path / "full" / "state" / name, out_dir=tmp_path / folder, threads=2)
        assert restarted.t == pytest.approx(float(name[2:-4]), abs=restarted.dt)
        assert restarted.body_names == full.body_names
        ended = to_the_end(restarted)
        same_files(tmp_path / "full", tmp_path / folder)
        assert without_wall_clock(ended) == without_wall_clock(summary)
        np.testing.assert_array_equal(restarted.positions, full.positions)
        np.testing.assert_array_equal(restarted.quaternions, full.quaternions)
        np.testing.assert_array_equal(restarted.velocities, full.velocities)
    # The straight run's folder was only read: its files were copied before they were cut.
    for name, data in before.items():
        assert (tmp_path / "full" / name).read_bytes() == data, name


def test_finish_before_the_end_writes_a_state_that_goes_on_in_place(source_dir, tmp_path):
    # A Python run stopped at T/2 by finish() writes its state as the CLI's interrupted run does
    # (summary["state_files"]); from_state without out_dir continues its own folder, cutting
    # the row written at the stop, and the folder ends as the straight run's.
    s = drums(source_dir)
    to_the_end(blockdem.Simulation3d(s, threads=1, out_dir=tmp_path / "full"))
    half = blockdem.Simulation3d(s, threads=2, out_dir=tmp_path / "half")
    half.step(steps_to(half, HALF_S))
    stopped = half.finish()
    assert stopped["status"] == "interrupted" and stopped["time_s"] == pytest.approx(HALF_S, abs=half.dt)
    assert len(stopped["state_files"]) == 1
    assert (tmp_path / "half" / "summary.json").exists()
    del half
    again = blockdem.Simulation3d.from_state(stopped["state_files"][0], threads=1)
    # (The time stopped at is the last row; the state to go on from is the step after it.)
    assert again.step_index == stopped["steps"] + 1
    with pytest.raises(ValueError, match="keeps no history"):
        again.history()   # (its rows would start at the state's time)
    assert to_the_end(again)["status"] == "completed"
    same_files(tmp_path / "full", tmp_path / "half")


def test_state_files_need_a_folder_and_times_in_the_run(source_dir, tmp_path):
    s = drums(source_dir)
    with pytest.raises(ValueError, match="give out_dir"):
        blockdem.Simulation3d(s, save_state=[HALF_S])
    with pytest.raises(ValueError, match="give out_dir"):
        blockdem.Simulation3d(s, save_state_every=0.1)
    for bad in (-0.1, math.nan, math.inf):
        with pytest.raises(ValueError, match="save_state: .* is not a time >= 0"):
            blockdem.Simulation3d(s, out_dir=tmp_path / "x", save_state=[bad])
    for bad in (0.0, -1.0, math.nan):
        with pytest.raises(ValueError, match="save_state_every must be a time > 0"):
            blockdem.Simulation3d(s, out_dir=tmp_path / "x", save_state_every=bad)
    # A time after the end is the CLI's refusal of --save-state (an InputError, a ValueError).
    with pytest.raises(blockdem.InputError, match="outside the run"):
        blockdem.Simulation3d(s, out_dir=tmp_path / "x", save_state=[2 * DURATION_S])
    assert not (tmp_path / "x").exists(), "a refused run wrote files"


def test_a_file_that_is_no_3d_state_is_refused_by_its_name(source_dir, tmp_path):
    with pytest.raises(blockdem.InputError, match="nowhere.h5.*no such state file"):
        blockdem.Simulation3d.from_state(tmp_path / "nowhere.h5", out_dir=tmp_path / "a")
    garbage = tmp_path / "garbage.h5"
    garbage.write_text("not a state")
    with pytest.raises(blockdem.InputError, match="garbage.h5"):
        blockdem.Simulation3d.from_state(garbage, out_dir=tmp_path / "b")

    # A 2-D state handed to Simulation3d, and a 3-D state to the 2-D Simulation: each names
    # the file, its dimension and the class that goes on from it.
    flat = blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table()), threads=1, out_dir=tmp_path / "flat",
                               save_state=[0.1])
    flat.run()
    flat_state = tmp_path / "flat" / "state" / "t_0.100000s.h5"
    with pytest.raises(blockdem.InputError, match=r"t_0.100000s.h5: a 2-D state: a 3-D run cannot go on from it .*"
                                                  r"blockdem\.Simulation\.from_state"):
        blockdem.Simulation3d.from_state(flat_state, out_dir=tmp_path / "c")
    s = drums(source_dir)
    s.set("simulation.duration", 0.02)
    to_the_end(blockdem.Simulation3d(s, threads=1, out_dir=tmp_path / "deep", save_state=[0.01]))
    deep_state = tmp_path / "deep" / "state" / "t_0.010000s.h5"
    with pytest.raises(blockdem.InputError, match=r"t_0.010000s.h5: a 3-D state: a 2-D run cannot go on from it .*"
                                                  r"blockdem\.Simulation3d\.from_state"):
        blockdem.Simulation.from_state(deep_state, out_dir=tmp_path / "d")
    # A 3-D state with a 2-D scenario given: the CLI's message, naming the state.
    with pytest.raises(blockdem.InputError, match="t_0.010000s.h5: a 3-D state: scenario .*sliding.toml is not 3-D"):
        blockdem.Simulation3d.from_state(deep_state, scenario=source_dir / "examples/paper/sliding.toml",
                                         out_dir=tmp_path / "e")
    for folder in "abcde":
        assert not (tmp_path / folder).exists(), f"a refused restart wrote into {folder}/"


def test_a_restart_under_a_changed_scenario_goes_on_with_a_warning(source_dir, tmp_path):
    # As `blockdem run --restart STATE SCENARIO` with another friction: the run goes on from the
    # state under the scenario given, and says so (a UserWarning naming both files).
    s = drums(source_dir)
    s.set("simulation.duration", 0.02)
    to_the_end(blockdem.Simulation3d(s, threads=1, out_dir=tmp_path / "run", save_state=[0.01]))
    s.set("contact.mu", 0.4)
    changed = tmp_path / "changed.toml"
    changed.write_text(s.to_toml())
    with pytest.warns(UserWarning, match=r"changed.toml is not the one state .*t_0.010000s.h5 was saved with"):
        sim = blockdem.Simulation3d.from_state(tmp_path / "run" / "state" / "t_0.010000s.h5", scenario=changed,
                                               out_dir=tmp_path / "changed")
    assert to_the_end(sim)["status"] == "completed"
