"""A held prescribed velocity (Simulation.hold_velocity / release_velocity): the body moves at
the held velocity whatever its contacts do, the force that holds it is its external load
(world/external_loads.hpp) and its work closes the energy balance; released, it moves freely."""
import numpy as np
import pytest

import blockdem
from conftest import block_on_table

G = 9.81  # [m/s^2]
MU = 0.5


def settled_block():
    """The 1 kg block of block_on_table, settled on its normal springs for 0.3 s."""
    sim = blockdem.Simulation(blockdem.Scenario.from_dict(block_on_table(mu=MU, duration=1.0, dt=1e-5)), history=False)
    sim.run(until=0.3)
    return sim


def test_a_held_block_slides_at_its_velocity_against_coulomb_friction():
    sim = settled_block()
    block = sim.body_id("block")
    sim.hold_velocity("block", (0.1, 0.0))
    x0, t0 = sim.positions[block, 0], sim.t
    sim.step(4000)    # the shear springs load, then the block slides
    e0, t1 = sim.energy(), sim.t
    sim.step(16000)   # 0.16 s of steady slip
    # Held exactly (round-off of the force that holds it): velocity, no rotation, position.
    np.testing.assert_allclose(sim.velocities[block], [0.1, 0.0], atol=1e-12)
    assert sim.angular_velocities[block] == pytest.approx(0.0, abs=1e-12)
    assert sim.positions[block, 0] - x0 == pytest.approx(0.1 * (sim.t - t0), rel=1e-9)
    # The holding force is what friction takes while the block slides: mu N, N the contacts'
    # normal force (the weight: nothing moves vertically); tolerance 1e-9 (Coulomb's cap is
    # exact at a sliding point; the shear dashpot adds nothing at a steady slip).
    c = sim.contacts()
    assert c["sliding"].all()
    fx, fy, torque = sim.external_force("block")
    assert fx == pytest.approx(MU * c["normal_force"].sum(), rel=1e-9)
    assert c["normal_force"].sum() == pytest.approx(1.0 * G, rel=1e-6)
    # Its work is booked: over the steady slip it is friction's, mu m g v dt (1e-6: measured
    # 3.7e-8, the normal springs' last ringing), and the balance's residual does not change (the residual left by the start of
    # the hold, 2.5e-6 J of 0.1 J, is the velocity jump's: kinetic energy booked at the half-step
    # velocities, as set_velocity does).
    e = sim.energy()
    assert e["external_work_J"] - e0["external_work_J"] == pytest.approx(MU * G * 0.1 * (sim.t - t1), rel=1e-6)
    assert e["residual_J"] == pytest.approx(e0["residual_J"], abs=1e-12)
    assert e["balance_error"] < 1e-4


def test_a_released_block_stops_at_mu_g():
    sim = settled_block()
    block = sim.body_id("block")
    sim.hold_velocity(block, (0.1, 0.0))
    sim.step(5000)
    sim.release_velocity(block)
    assert sim.external_force(block) == (0.0, 0.0, 0.0)
    # Released at v0 = 0.1 m/s, it decelerates at mu g while sliding (1 %, the sliding row's
    # tolerance) and stops after v0 / (mu g) = 20.4 ms.
    # The stop is read as the velocity's first crossing of zero (every 10 steps, 0.1 ms: 0.5 %),
    # tolerance 2 %.
    decelerations, released_s, stop_s = [], sim.t, None
    for _ in range(300):   # 30 ms
        sim.step(10)
        if sim.contacts()["sliding"].all() and sim.velocities[block, 0] > 0.01:
            decelerations.append(sim.accelerations[block, 0])
        if stop_s is None and sim.velocities[block, 0] <= 0.0:
            stop_s = sim.t - released_s
    assert len(decelerations) > 50
    np.testing.assert_allclose(decelerations, -MU * G, rtol=0.01)
    assert stop_s == pytest.approx(0.1 / (MU * G), rel=0.02)


def test_held_velocity_refuses_what_it_cannot_hold():
    sim = settled_block()
    with pytest.raises(ValueError, match="not dynamic"):
        sim.hold_velocity("table", (0.1, 0.0))
    with pytest.raises(ValueError, match="finite"):
        sim.hold_velocity("block", (float("nan"), 0.0))
    with pytest.raises(KeyError):
        sim.release_velocity("nobody")
