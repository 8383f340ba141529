"""Simulation3d's external loads and held velocities (python/bind_simulation_3d.cpp,
world/external_loads_3d.hpp) against the closed forms of a box on a table: Coulomb sliding under a
push, the holding force of a driven box, a spin under a torque, and the energy balance that books
their work as external work."""
import math

import numpy as np
import pytest

import blockdem

G = 9.81       # [m/s^2]
MU = 0.5
MASS = 16.0    # [kg] 0.4 x 0.4 x 0.1 m at 1000 kg/m^3
I_ZZ = MASS * (0.4 ** 2 + 0.4 ** 2) / 12.0   # [kg m^2] about the vertical axis
DT = 2e-5      # [s]


def box_on_table(mu=MU, hovering=False, slab="fixed"):
    """A flat 16 kg box resting on a fixed slab (low, so that a push at its centroid slides it
    rather than tips it), and with hovering a second box in the air, far from everything."""
    text = f"""dimension = 3
[simulation]
duration = 1.0
output_interval = 0.01
dt = {DT}
[contact]
kn = 1e8
ks = 1e8
mu = {mu}
e = 0.5
[[bodies]]
name = "slab"
kind = "{slab}"
shape = "box"
size = [4.0, 4.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "box"
shape = "box"
size = [0.4, 0.4, 0.1]
position = [0.0, 0.0, 0.05]
density = 1000.0
"""
    if hovering:
        text += """[[bodies]]
name = "crate"
shape = "box"
size = [0.4, 0.4, 0.1]
position = [1.0, 1.0, 1.0]
density = 1000.0
"""
    sim = blockdem.Simulation3d(blockdem.Scenario.from_toml(text), threads=1)
    sim.step(1000)  # 0.02 s: the box settles on its springs
    return sim


def velocity(sim, body):
    return sim.velocities[sim.body_names.index(body)]


def steps(seconds):
    return int(round(seconds / DT))


def test_a_push_above_friction_accelerates_the_box_at_f_minus_mu_m_g_over_m():
    sim = box_on_table()
    force_n = 1.5 * MU * MASS * G
    sim.set_external_force("box", [force_n, 0.0, 0.0])
    sim.step(steps(0.02))  # the shear springs load up to the friction cap (a few ms) first
    t0, v0 = sim.t, velocity(sim, "box")[0]
    sim.step(steps(0.1))
    acceleration = (velocity(sim, "box")[0] - v0) / (sim.t - t0)
    # Closed form (F - mu m g) / m; 0.5 %: the normal springs' ringing from the settling and the
    # tilt the push's moment gives the box move the normal force by less than that.
    assert acceleration == pytest.approx((force_n - MU * MASS * G) / MASS, rel=5e-3)
    assert abs(velocity(sim, "box")[1]) < 1e-9
    energy = sim.energy()
    assert energy["external_work_J"] > 0.0
    assert energy["balance_error"] < 1e-3


def test_a_push_below_friction_leaves_the_box_where_it_is():
    sim = box_on_table()
    x0 = sim.positions[1].copy()
    sim.set_external_force(1, [0.5 * MU * MASS * G, 0.0, 0.0])
    sim.step(steps(0.1))
    # The shear springs' elastic give, F / (4 ks) ~ 1e-7 m, and nothing more.
    assert np.max(np.abs(sim.positions[1] - x0)) < 1e-6
    assert sim.energy()["balance_error"] < 1e-3


def test_a_held_velocity_drives_the_box_and_the_holding_force_is_the_friction():
    sim = box_on_table(hovering=True)
    sim.hold_velocity("box", [0.2, 0.0, 0.0])
    sim.hold_velocity("crate", [0.0, 0.0, 0.1])  # lifted at a steady speed
    sim.step(steps(0.05))
    assert velocity(sim, "box") == pytest.approx([0.2, 0.0, 0.0], abs=1e-9)
    assert velocity(sim, "crate") == pytest.approx([0.0, 0.0, 0.1], abs=1e-9)
    fx, fy, fz, *_ = sim.external_force("box")
    # In steady sliding the holding force balances the friction mu m g (0.5 %: the normal force
    # still rings slightly); the lift holds the weight m g to round-off.
    assert fx == pytest.approx(MU * MASS * G, rel=5e-3)
    assert abs(fy) < 1e-6 * MASS * G
    assert sim.external_force("crate")[2] == pytest.approx(MASS * G, rel=1e-9)
    assert sim.energy()["balance_error"] < 1e-3
    # Released, the box slides to a stop.
    sim.release_velocity("box")
    assert sim.external_force("box") == (0.0,) * 6
    sim.step(steps(0.1))
    assert abs(velocity(sim, "box")[0]) < 1e-3


def test_a_torque_about_z_spins_a_box_on_a_frictionless_table_at_t_over_i_zz():
    sim = box_on_table(mu=0.0)
    torque_n_m = 2.0
    sim.set_external_force("box", [0.0, 0.0, 0.0], [0.0, 0.0, torque_n_m])
    t0 = sim.t
    w0 = sim.angular_velocities[1][2]
    sim.step(steps(0.1))
    alpha = (sim.angular_velocities[1][2] - w0) / (sim.t - t0)
    # Closed form T / I_zz; 1e-3: the frictionless table adds no moment about z but the angular
    # velocity at t is the mean of two half steps, one step's torque off at the start.
    assert alpha == pytest.approx(torque_n_m / I_ZZ, rel=1e-3)
    energy = sim.energy()
    assert energy["external_work_J"] == pytest.approx(0.5 * I_ZZ * sim.angular_velocities[1][2] ** 2, rel=1e-2)
    assert energy["balance_error"] < 1e-3
    sim.clear_external_forces()
    assert sim.external_force("box") == (0.0,) * 6


def test_loads_are_refused_for_a_fixed_body_a_wrong_vector_and_an_unknown_name():
    sim = box_on_table()
    with pytest.raises(ValueError, match="'slab' is not dynamic"):
        sim.set_external_force("slab", [1.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="'slab' is not dynamic"):
        sim.hold_velocity(0, [1.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="force must have 3 components"):
        sim.set_external_force("box", [1.0, 0.0])
    with pytest.raises(ValueError, match="angular_velocity must have 3 components"):
        sim.set_velocity("box", [1.0, 0.0, 0.0], [0.0, 1.0])
    with pytest.raises(ValueError, match="finite"):
        sim.set_external_force("box", [math.nan, 0.0, 0.0])
    with pytest.raises(KeyError, match="no body is named 'statue'"):
        sim.set_external_force("statue", [1.0, 0.0, 0.0])
    with pytest.raises(IndexError):
        sim.release_velocity(7)
    driven = box_on_table(slab="driven")
    with pytest.raises(ValueError, match="'slab' is not dynamic"):
        driven.set_velocity("slab", [0.1, 0.0, 0.0])


def test_set_velocity_books_the_kinetic_energy_it_adds_as_external_work():
    sim = box_on_table(mu=0.0)
    before = sim.energy()["external_work_J"]
    sim.set_velocity("box", [0.3, 0.0, 0.0], [0.0, 0.0, 1.0])
    added = sim.energy()["external_work_J"] - before
    assert added == pytest.approx(0.5 * MASS * 0.3 ** 2 + 0.5 * I_ZZ * 1.0 ** 2, rel=1e-6)
    sim.step(steps(0.05))
    assert velocity(sim, "box")[0] == pytest.approx(0.3, rel=1e-3)
    assert sim.energy()["balance_error"] < 1e-3


def rotation_matrix(q):
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def test_a_held_spin_about_a_skew_axis_is_held_by_the_gyroscopic_torque():
    sim = box_on_table(hovering=True)
    crate = sim.body_names.index("crate")
    omega = np.array([1.0, 2.0, 3.0])  # [rad/s] world frame
    sim.hold_velocity("crate", [0.0, 0.0, 0.0], omega.tolist())
    sim.step(steps(0.1))
    # The held quantity is the half-step angular momentum I omega; the angular velocity at t is read
    # from the mean of two half steps' momenta at the orientation at t, which turned in between:
    # first order in |omega| dt = 7.5e-5 (measured 5.7e-5).
    assert np.linalg.norm(sim.angular_velocities[crate] - omega) < 2e-4 * np.linalg.norm(omega)
    # The crate (0.4 x 0.4 x 0.1 m) was placed along the axes: its inertia now is R I0 R^T with R
    # its turn since t = 0; holding omega takes dL/dt = omega x (I omega) (Euler), and its weight.
    lengths = np.array([0.4, 0.4, 0.1])
    squares = lengths ** 2
    i0 = np.diag(MASS / 12.0 * (squares.sum() - squares))
    r = rotation_matrix(sim.quaternions[crate])
    expected = np.cross(omega, r @ i0 @ r.T @ omega)
    load = np.array(sim.external_force("crate"))
    # 1e-3 of the torque: the held load is the change of I omega over one step, the derivative at
    # the half step before t (|omega| dt / 2 ~ 4e-5 relative), and the turn read as written (1e-6).
    assert np.linalg.norm(load[3:] - expected) < 1e-3 * np.linalg.norm(expected)
    assert load[:3] == pytest.approx([0.0, 0.0, MASS * G], rel=1e-9, abs=1e-9)
    assert sim.energy()["balance_error"] < 1e-3
