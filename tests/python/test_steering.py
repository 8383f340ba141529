"""Steering a run from Python: a motion array, external forces and velocity changes, each against
its closed form, with the energy balance closed."""
import numpy as np
import pytest

import blockdem
from conftest import block_on_table


def test_a_motion_array_drives_the_table():
    # a = 1 m/s^2 held: the table moves a t^2 / 2 exactly (the series is integrated exactly).
    s = blockdem.Scenario.from_dict(block_on_table(duration=0.2))
    s.set_motion(np.ones(101), dt=0.002)
    sim = blockdem.Simulation(s)
    table = sim.body_id("table")
    x0 = sim.positions[table, 0]
    sim.run(until=0.1)
    assert sim.positions[table, 0] - x0 == pytest.approx(0.5 * 0.1**2, rel=1e-9)


def frictionless():
    return blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table(mu=0.0, duration=1.0)))


def test_an_external_force_pushes_a_block_on_a_frictionless_table():
    # x = F t^2 / (2 m) from rest; the central difference integrates a constant force exactly
    # but for the start's half step: tolerance 1e-3 of the distance (dt / t = 1e-3).
    sim = frictionless()
    block = sim.body_id("block")
    sim.step(100)  # (the block on its springs first)
    x0, t0 = sim.positions[block, 0], sim.t
    sim.set_external_force("block", (2.0, 0.0))
    sim.run(until=t0 + 0.5)
    assert sim.positions[block, 0] - x0 == pytest.approx(2.0 * 0.5**2 / 2, rel=1e-3)
    e = sim.energy()
    assert e["external_work_J"] == pytest.approx(e["kinetic_J"], rel=1e-2)
    assert e["balance_error"] < 1e-3
    with pytest.raises(ValueError, match="not dynamic"):
        sim.set_external_force("table", (1.0, 0.0))
    with pytest.raises(KeyError):
        sim.set_external_force("nobody", (1.0, 0.0))
    with pytest.raises(ValueError, match="finite"):
        sim.set_external_force(block, (float("nan"), 0.0))
    with pytest.raises(TypeError):
        sim.set_external_force(block, (1.0, 2.0, 3.0))


def test_a_velocity_set_between_steps_is_kept_on_a_frictionless_table():
    sim = frictionless()
    block = sim.body_id("block")
    sim.step(5000)  # (at rest on its springs: the kinetic energy it had is below 1e-9 J)
    assert sim.energy()["kinetic_J"] < 1e-9
    x0, t0 = sim.positions[block, 0], sim.t
    sim.set_velocity("block", (0.1, 0.0))
    sim.run(until=t0 + 0.3)
    assert sim.positions[block, 0] - x0 == pytest.approx(0.1 * 0.3, rel=1e-6)
    e = sim.energy()
    assert e["external_work_J"] == pytest.approx(0.5 * 1.0 * 0.1**2, rel=1e-3)
    assert e["balance_error"] < 1e-3
