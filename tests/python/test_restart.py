"""README row "stop at T/2, --restart to T ... byte-identical" through Python: state files
written by Simulation(save_state=...) or by finish() before the end, and a run restarted from
one with Simulation.from_state, over the CLI's own state-file code (run/scenario_run.hpp)."""
import filecmp

import pytest

import blockdem

FILES = ("history.csv", "energy.csv", "summary.json")


def rocking(source_dir):
    s = blockdem.Scenario.from_file(source_dir / "examples/paper/rocking.toml")
    s.set("simulation.duration", 2.0)
    s.set("output.vtk", False)
    return s


def same_files(a, b):
    for name in FILES:
        assert filecmp.cmp(a / name, b / name, shallow=False), f"{name} differs between {a} and {b}"


def test_restart_at_half_time_ends_as_the_straight_run(source_dir, tmp_path):
    # Row "stop at T/2, --restart to T: rocking block ..., 1/2 threads": the run straight to T,
    # byte-identical (tolerance none: the restart restores every bit of the state).
    s = rocking(source_dir)
    full = blockdem.Simulation(s, threads=1, out_dir=tmp_path / "full", save_state=[1.0])
    summary = full.run()
    assert summary["status"] == "completed" and len(summary["state_files"]) == 1
    state = tmp_path / "full" / "state" / "t_1.000000s.h5"
    assert state.exists()
    # (a) into a new folder, with 2 threads;
    restarted = blockdem.Simulation.from_state(state, out_dir=tmp_path / "new", threads=2)
    assert restarted.t == pytest.approx(1.0, abs=restarted.dt)
    assert restarted.run()["status"] == "completed"
    same_files(tmp_path / "full", tmp_path / "new")
    # (b) a Python run stopped at T/2 by finish() (its state written as the CLI's interrupted
    # run's), continued in its own folder.
    half = blockdem.Simulation(s, threads=2, out_dir=tmp_path / "half")
    half.run(until=1.0)
    stopped = half.finish()
    assert stopped["status"] == "interrupted" and len(stopped["state_files"]) == 1
    del half
    again = blockdem.Simulation.from_state(stopped["state_files"][0], threads=1)
    again.run()
    same_files(tmp_path / "full", tmp_path / "half")
    # The restarted state reads like any other: the views follow it.
    assert again.positions.shape == (len(again.body_names), 2)


def test_state_files_need_a_folder_and_a_real_state(source_dir, tmp_path):
    s = rocking(source_dir)
    with pytest.raises(ValueError, match="give out_dir"):
        blockdem.Simulation(s, save_state=[1.0])
    with pytest.raises(ValueError, match="save_state_every"):
        blockdem.Simulation(s, out_dir=tmp_path / "x", save_state_every=0.0)
    garbage = tmp_path / "garbage.h5"
    garbage.write_text("not a state")
    with pytest.raises(blockdem.InputError, match="garbage.h5"):
        blockdem.Simulation.from_state(garbage, scenario=source_dir / "examples/paper/rocking.toml", out_dir=tmp_path / "y")
