"""blockdem.Simulation: stepping, the zero-copy views, contacts, energy, history, outputs, errors."""
import filecmp
import gc
import os
import subprocess
import threading

import numpy as np
import pytest

import blockdem
from conftest import block_on_table


def simulation(**kw):
    return blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table()), **kw)


def test_view_shapes_and_types():
    sim = simulation()
    n = len(sim.body_names)
    assert n == 2
    for name in ("positions", "velocities", "accelerations"):
        v = getattr(sim, name)
        assert v.shape == (n, 2) and v.dtype == np.float64, name
    for name in ("rotations", "angular_velocities", "angular_accelerations", "masses", "inertias"):
        v = getattr(sim, name)
        assert v.shape == (n,) and v.dtype == np.float64, name
    assert sim.masses[sim.body_id("block")] == pytest.approx(1.0)
    np.testing.assert_allclose(sim.positions[1], [0.0, 0.1], atol=1e-3)


def test_views_are_read_only():
    sim = simulation()
    with pytest.raises(ValueError):
        sim.positions[0, 0] = 1.0
    with pytest.raises(ValueError):
        sim.masses[:] = 0.0


def test_views_are_zero_copy_across_steps():
    sim = simulation()
    p, v = sim.positions, sim.velocities
    pointers = (p.__array_interface__["data"][0], v.__array_interface__["data"][0])
    before = p.copy()
    sim.step(300)
    assert sim.step_index == 300 and sim.t == pytest.approx(300 * sim.dt)
    assert (sim.positions.__array_interface__["data"][0], sim.velocities.__array_interface__["data"][0]) == pointers
    # The old view sees the new state: it is the world's own array.
    np.testing.assert_array_equal(p, sim.positions)
    assert not np.array_equal(p, before)  # (the block settles on its springs)


def test_a_view_keeps_the_simulation_alive():
    sim = simulation()
    p = sim.positions
    sim.step(10)
    expected = p.copy()
    del sim
    gc.collect()
    np.testing.assert_array_equal(p, expected)  # readable: the view holds the simulation


def test_step_argument_errors():
    sim = simulation()
    with pytest.raises(ValueError):
        sim.step(-1)
    with pytest.raises(TypeError):
        sim.step("ten")
    with pytest.raises(TypeError):
        blockdem.Simulation({"not": "a scenario"})
    with pytest.raises(ValueError):
        simulation(threads=0)
    # As the CLI's -j: 1 to 4096 (1e9 ran out of memory).
    with pytest.raises(ValueError, match="threads must be 1 to 4096, got 1000000000"):
        simulation(threads=10**9)


def test_the_summary_says_the_status_finish_returned():
    sim = simulation()
    sim.step(10)
    assert sim.summary()["status"] == "running"
    assert sim.finish()["status"] == "interrupted"
    assert sim.summary()["status"] == "interrupted"  # it said "running"


def test_step_after_an_error_raises():
    # A soft contact under a dropped block, and a penetration limit it breaks at once.
    d = block_on_table(max_overlap=1e-4)
    d["bodies"][1]["center"] = [0.0, 0.15]
    sim = blockdem.Simulation(blockdem.Scenario.from_dict(d))
    with pytest.raises(blockdem.SimulationError, match="penetration"):
        sim.step(2000)
    assert sim.failed
    with pytest.raises(RuntimeError, match="stopped on an error"):
        sim.step(1)


def test_run_with_a_callback_every_interval():
    sim = simulation()
    times = []
    assert sim.run(until=0.05, callback=lambda s: times.append(s.t), every=0.01) is None
    np.testing.assert_allclose(times, [0.01, 0.02, 0.03, 0.04, 0.05], atol=1e-9)
    stop_at = []
    sim.run(until=0.2, callback=lambda s: stop_at.append(s.t) or s.t < 0.07, every=0.01)
    assert sim.t == pytest.approx(0.07) and not sim.done
    summary = sim.run()  # to the end: finishes
    assert sim.done and summary["status"] == "completed"
    with pytest.raises(RuntimeError):
        sim.step(1)


def test_contacts_energy_and_history():
    sim = blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table(duration=1.0)))
    sim.step(5000)  # 0.5 s: the block rests on its two corners
    c = sim.contacts()
    assert len(c) == 2 and set(c.dtype.names) >= {"body_a", "body_b", "x", "y", "nx", "ny", "normal_force",
                                                  "shear_force", "overlap", "sliding"}
    # At rest the two points carry the weight (the dashpots have died out to 1e-3).
    assert c["normal_force"].sum() == pytest.approx(9.81, rel=1e-3)
    np.testing.assert_allclose(c["ny"], 1.0)
    e = sim.energy()
    assert e["balance_error"] < 1e-3 and e["elastic_J"] > 0
    h = sim.history()
    assert "block" in h["bodies"]
    column = h["bodies"].index("block")
    rows, n = len(h["t"]), len(h["bodies"])
    assert rows == 501 and h["x"].shape == (rows, n) and h["energy"]["kinetic_J"].shape == (rows,)
    assert h["y"][-1, column] == sim.positions[h["body_ids"][column], 1]


def test_threads_give_identical_results():
    a, b = simulation(threads=1), simulation(threads=2)
    a.step(500)
    b.step(500)
    np.testing.assert_array_equal(a.positions, b.positions)


def test_the_gil_is_released_while_stepping():
    sim = blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table(duration=20.0)))
    worker = threading.Thread(target=sim.step, args=(150000,))
    ticks = 0
    worker.start()
    while worker.is_alive():
        ticks += 1
    worker.join()
    assert sim.step_index == 150000
    assert ticks > 1000  # this thread ran while the other stepped


def test_out_dir_writes_the_clis_files(tmp_path, source_dir):
    cli = os.environ.get("BLOCKDEM_CLI", str(source_dir / "build/blockdem"))
    if not os.path.exists(cli):
        pytest.skip("the blockdem executable is not built")
    scenario = source_dir / "examples/paper/sliding.toml"
    args = ["--set", "simulation.duration=0.5"]
    subprocess.run([cli, "run", str(scenario), "--out", str(tmp_path / "cli"), "-q", *args], check=True,
                   stdout=subprocess.DEVNULL)
    s = blockdem.Scenario.from_file(scenario)
    s.set("simulation.duration", 0.5)
    sim = blockdem.Simulation(s, out_dir=tmp_path / "py")
    sim.step(1234)
    sim.run()
    for name in ("history.csv", "energy.csv", "bodies.json"):
        assert filecmp.cmp(tmp_path / "cli" / name, tmp_path / "py" / name, shallow=False), name
    # summary.json: the same but for the scenario copy's note of how it was set (--set or set()).
    assert (tmp_path / "py" / "summary.json").read_text() == (tmp_path / "cli" / "summary.json").read_text()
    with pytest.raises(blockdem.InputError, match="--force"):
        blockdem.Simulation(s, out_dir=tmp_path / "py")


def test_many_simulations_do_not_leak():
    scenario = blockdem.Scenario.from_dict(block_on_table(duration=0.01))

    def rss_kb():
        with open("/proc/self/status") as f:
            return next(int(line.split()[1]) for line in f if line.startswith("VmRSS"))

    for _ in range(2000):  # warm-up: allocator pools and caches reach their size
        blockdem.Simulation(scenario, history=False).step(2)
    before = rss_kb()
    for _ in range(100000):  # the count
        blockdem.Simulation(scenario, history=False).step(2)
    gc.collect()
    assert rss_kb() - before < 2048, "memory grew by more than 2 MiB over 1e5 simulations"


def test_ctrl_c_interrupts_a_long_step_and_the_run_goes_on():
    import _thread

    sim = blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table(duration=100.0)))
    threading.Timer(0.05, _thread.interrupt_main).start()
    with pytest.raises(KeyboardInterrupt):
        sim.step(10**6)
    reached = sim.step_index
    assert 0 < reached < 10**6 and not sim.failed
    assert sim.step(10) == 10 and sim.step_index == reached + 10


def test_a_second_thread_cannot_step_or_read_contacts_while_one_steps():
    sim = blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table(duration=50.0)))
    worker = threading.Thread(target=sim.step, args=(300000,))
    worker.start()
    refused = {"step": False, "contacts": False}
    while worker.is_alive():
        try:
            sim.step(1)
        except RuntimeError as e:
            refused["step"] = "another thread" in str(e)
        try:
            sim.contacts()
        except RuntimeError as e:
            refused["contacts"] = "another thread" in str(e)
        if all(refused.values()):
            break
    worker.join()
    assert all(refused.values())
    assert len(sim.contacts()) == 2  # and all is well after it


def test_a_run_with_files_dropped_before_finish_ends_them(tmp_path):
    sim = blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table()), out_dir=tmp_path / "run")
    sim.step(500)
    del sim
    gc.collect()
    import json
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["status"] == "interrupted" and summary["time_s"] == pytest.approx(0.05)
    rows = (tmp_path / "run" / "history.csv").read_text().strip().splitlines()
    assert rows[-1].startswith("0.05,")  # the time reached is the last row


def test_ctrl_c_while_the_model_settles_raises_at_once():
    # A window far longer than settling is allowed: without the stop it would settle for hours.
    import _thread
    import time

    scenario = block_on_table(duration=1.0)
    scenario["settling"] = {"window": 1000.0, "max_time": 1.0e4}
    threading.Timer(0.3, _thread.interrupt_main).start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        blockdem.Simulation(blockdem.Scenario.from_dict(scenario))
    assert time.monotonic() - started < 5.0
