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


BONDED_WALL = """
[simulation]
duration = 0.3
output_interval = 0.005
[contact]
stiffness = "per_length"
{extra}
kn = 1.0e10
ks = 4.0e9
mu = 0.6
cohesion = 4.0e3
tensile_strength = 2.0e3
residual_mu = 0.5
e = 0.5
[[assemblies]]
type = "wall"
name = "brick"
density = 1800.0
length = 2.0
courses = 6
brick_length = 0.4
brick_height = 0.2
record = true
bonded = true
driven_zone = [[-1.0, -0.01], [3.0, -0.01], [3.0, 0.19], [-1.0, 0.19]]
[output]
interfaces = "all"
vtk = false
[table_motion.horizontal]
type = "sine"
amplitude = 1.5
unit = "g"
period = 0.2
"""


@pytest.mark.parametrize("extra", ["", "rounding = 0.005"], ids=["sharp", "rounded"])
def test_bonded_wall_restarted_at_half_time_ends_as_the_straight_run(tmp_path, extra):
    # Rows "bonded wall shaken until bonds break, stopped at T/2 and restarted" (sharp, and with
    # rounded corners r = 5 mm): the run straight to T, byte-identical (history, energy,
    # summary, interfaces); the bonds' states and the interfaces' measurements go on from the
    # state. The wall of tests/cli/test_restart_bonds.sh, without VTK.
    s = blockdem.Scenario.from_toml(BONDED_WALL.format(extra=extra))
    full = blockdem.Simulation(s, threads=1, out_dir=tmp_path / "full", save_state=[0.15])
    summary = full.run()
    broken = [i for i in summary["interfaces"]["list"] if i["first_break_time_s"] is not None]
    assert broken, "the shaking broke no bond: the restart would not carry a broken one"
    restarted = blockdem.Simulation.from_state(tmp_path / "full" / "state" / "t_0.150000s.h5", out_dir=tmp_path / "new",
                                               threads=2)
    restarted.run()
    for name in FILES + ("interfaces.csv",):
        assert filecmp.cmp(tmp_path / "full" / name, tmp_path / "new" / name, shallow=False), name
