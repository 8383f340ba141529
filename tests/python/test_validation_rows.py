"""More README validation rows through Python (test_validation.py has the Newmark slip and the
impact ratio). Each test names its row; the reference is a closed form, or the project's
independent solvers reached through the module (blockdem.housner_rocking,
blockdem.rigid_plastic_sliding), never the DEM itself. Long rows run a reduced configuration
that still meets the row's reference and tolerance, as each comment says."""
import math

import numpy as np
import pytest

import blockdem

G = 9.81  # [m/s^2]


def table_body(width=4.0):
    return {"name": "table", "kind": "driven", "shape": "rectangle", "width": width, "height": 0.2,
            "center": [0.0, -0.1], "density": 1000.0}


def scene(bodies, contact, duration, dt, gravity=G, **simulation):
    sim = {"duration": duration, "dt": dt, "gravity": gravity, "output_interval": dt * 10}
    sim.update(simulation)
    return blockdem.Scenario.from_dict({"simulation": sim, "contact": contact, "bodies": bodies})


def drop(e, meaning, **contact):
    """A 0.5 x 0.2 m, 1 kg block falling flat at 1 m/s onto the table, gravity off: the rebound
    ratio is v_out / v_in exactly (no gravity during the contact)."""
    law = {"kn": 1.0e6, "ks": 1.0e6, "mu": 0.5, "e": e, "e_meaning": meaning, "h_s": 0.0}
    law.update(contact)
    block = {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.5, "height": 0.2,
             "center": [0.0, 0.1005], "mass": 1.0, "velocity": [0.0, -1.0]}
    sim = blockdem.Simulation(scene([table_body(), block], law, 0.03, 1e-6, gravity=0.0), history=False)
    sim.run()
    return sim.velocities[sim.body_id("block"), 1]


@pytest.mark.parametrize("e", [0.2, 0.6, 0.95])
def test_flat_drop_rebound_meaning(e):
    # Row "flat drop, e = 0.2 ... 0.95, rebound meaning": requested e, tolerance 2% (the two
    # corner springs act as one; the 2% is the row's, measured within 0.16%).
    assert drop(e, "rebound") == pytest.approx(e, rel=0.02)


@pytest.mark.parametrize("e", [0.2, 0.6, 0.95])
def test_flat_drop_zero_overlap_termination(e):
    # Row "flat drop, termination = zero_overlap, paper e": the paper's damped spring, contact
    # ending where the overlap returns to zero, rebounds at e exactly; tolerance 1%.
    assert drop(e, "paper", termination="zero_overlap") == pytest.approx(e, rel=0.01)


def test_head_on_impact_of_equal_blocks():
    # Row "head-on impact of equal blocks": relative velocity ratio = requested e (reduced
    # mass), tolerance 2%.
    law = {"kn": 1.0e6, "ks": 1.0e6, "mu": 0.0, "e": 0.3, "e_meaning": "rebound", "h_s": 0.0}
    bodies = [{"name": f"b{i}", "kind": "dynamic", "shape": "rectangle", "width": 0.2, "height": 0.2,
               "center": [s * 0.1005, 0.0], "mass": 1.0, "velocity": [-s * 1.0, 0.0]} for i, s in enumerate((-1, 1))]
    sim = blockdem.Simulation(scene(bodies, law, 0.02, 1e-6, gravity=0.0), history=False)
    sim.run()
    v = sim.velocities[:, 0]
    assert (v[1] - v[0]) / 2.0 == pytest.approx(0.3, rel=0.02)
    assert v.sum() == pytest.approx(0.0, abs=1e-12)  # momentum


def sliding_scene(duration, vertical=None):
    s = blockdem.Scenario.from_file(SOURCE / "examples/paper/sliding.toml")
    s.set("simulation.duration", duration)
    if vertical is not None:
        s.set_motion(vertical, dt=0.01, direction="vertical")
    return s


SOURCE = None


@pytest.fixture(autouse=True)
def _source(source_dir):
    global SOURCE
    SOURCE = source_dir


def sliding_accelerations(sim, until):
    """The block's horizontal acceleration well inside sliding phases: every contact point has
    slid at every step for the last 20 ms, as in tests/validation/test_sliding.cpp; the first
    0.2 s are left out (the block settles onto its normal springs while the table already
    shakes above mu g)."""
    block, out, run_length = sim.body_id("block"), [], 0
    sim.step(max(0, int(round((0.2 - sim.t) / sim.dt))))
    checks = int(round(0.02 / sim.dt))
    while sim.t < until - 1e-12:
        sim.step(1)
        c = sim.contacts()
        run_length = run_length + 1 if len(c) and c["sliding"].all() else 0
        if run_length > checks:
            out.append(sim.accelerations[block, 0])
    return np.array(out)


def test_sliding_block_accelerates_at_mu_g():
    # Row "sliding above mu g (paper Fig. 5)": while it slides, the block's acceleration is
    # mu g = 2.943 m/s^2, tolerance 1% (h_s = 1 damps the shear springs out within steps).
    sim = blockdem.Simulation(sliding_scene(1.0), history=False)
    a = sliding_accelerations(sim, 1.0)
    assert len(a) > 100
    np.testing.assert_allclose(np.abs(a), 0.3 * G, rtol=0.01)


def test_sliding_with_the_table_accelerating_down():
    # Row "table also accelerating down at 0.3 g": friction carries mu (g - 0.3 g), 1%. The
    # table's downward acceleration ramps up over 0.3 s (a smooth start) and then holds.
    down = np.minimum(np.arange(101) * 0.01 / 0.3, 1.0) * -0.3 * G
    sim = blockdem.Simulation(sliding_scene(1.0, vertical=down), history=False)
    sim.step(int(round(0.4 / sim.dt)))   # past the ramp
    a = sliding_accelerations(sim, 1.0)
    assert len(a) > 100
    np.testing.assert_allclose(np.abs(a), 0.3 * 0.7 * G, rtol=0.01)


def block_on_tilt(tilt_deg, duration, mu=0.5, **simulation):
    law = {"kn": 1.0e7, "ks": 1.0e7, "mu": mu, "e": 0.4, "e_meaning": "paper", "h_s": 1.0}
    block = {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.4, "height": 0.2,
             "center": [0.0, 0.1], "mass": 10.0}
    return blockdem.Simulation(scene([table_body(), block], law, duration, 1e-5, tilt_deg=tilt_deg, **simulation))


@pytest.mark.parametrize("tilt", [30.0, 35.0, 45.0])
def test_incline_slides_at_g_sin_minus_mu_cos(tilt):
    # Row "incline 30, 35, 45 deg, mu = 0.5": acceleration g (sin a - mu cos a) along the slope
    # (-x in the table's frame), tolerance 1%: fitted from x(t) between 0.1 and 0.4 s, after the
    # release transient of the springs.
    sim = block_on_tilt(tilt, 0.4)
    sim.run()
    h = sim.history()
    t, x = h["t"], h["x"][:, h["bodies"].index("block")]
    late = t >= 0.1
    accel = 2.0 * np.polyfit(t[late], x[late], 2)[0]
    a = math.radians(tilt)
    assert -accel == pytest.approx(G * (math.sin(a) - 0.5 * math.cos(a)), rel=0.01)


@pytest.mark.parametrize("tilt", [10.0, 20.0, 25.0])
def test_incline_below_friction_sticks(tilt):
    # Row "incline 10, 20, 25 deg": sticks; slip within 3 x the elastic shear displacement
    # m g sin a / (2 ks) of the two corner springs.
    sim = block_on_tilt(tilt, 0.5)
    x0 = sim.positions[sim.body_id("block"), 0]
    sim.run()
    elastic = 10.0 * G * math.sin(math.radians(tilt)) / (2 * 1.0e7)
    assert abs(sim.positions[sim.body_id("block"), 0] - x0) <= 3 * elastic


def rocking_block(theta0, duration, motion=None):
    """The row's slender block (b = 0.2, h = 0.8 m), tilted by theta0 about its left corner."""
    b, h = 0.2, 0.8
    cx = -b + b * math.cos(theta0) - h * math.sin(theta0)
    cy = b * math.sin(theta0) + h * math.cos(theta0)
    law = {"kn": 1e9, "ks": 1e9, "mu": 2.0, "e": 0.2, "e_meaning": "paper", "h_s": 1.0}
    block = {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 2 * b, "height": 2 * h,
             "center": [cx, cy], "rotation": theta0, "density": 1536.0}
    s = scene([dict(table_body(), density=1536.0), block], law, duration, 2e-5, output_interval=2e-4)
    if motion is not None:
        s.set_motion(motion=motion)
    return blockdem.Simulation(s)


def peaks_and_impacts(t, theta):
    peaks = [theta[i] for i in range(1, len(theta) - 1)
             if abs(theta[i]) > 1e-4 and abs(theta[i]) >= abs(theta[i - 1]) and abs(theta[i]) > abs(theta[i + 1])]
    impacts = [t[i] for i in range(len(theta) - 1) if theta[i] * theta[i + 1] < 0]
    return peaks, impacts


def test_free_rocking_against_housners_equation():
    # Row "free rocking from alpha/2": Housner's equation (the project's RK4 solver, here
    # blockdem.housner_rocking); peaks within 3%, impact times within 1% (over the first
    # three half-cycles: the DEM heel's r is 0.913 against Housner's 0.912, and it compounds).
    alpha = math.atan(0.25)
    sim = rocking_block(alpha / 2, 2.5)
    sim.run()
    h = sim.history()
    theta = alpha / 2 + h["rot"][:, h["bodies"].index("block")]
    dem_peaks, dem_impacts = peaks_and_impacts(h["t"], theta)
    ref = blockdem.housner_rocking(0.2, 0.8, blockdem.Motion.rest(), end=2.5, dt=1e-5, theta0=alpha / 2)
    ref_peaks, _ = peaks_and_impacts(ref["t"], ref["theta"])
    for dem, housner in zip(dem_peaks[:3], ref_peaks[:3]):
        assert abs(dem) == pytest.approx(abs(housner), rel=0.03)
    for dem, housner in zip(dem_impacts[:3], ref["impact_times"][:3]):
        assert dem == pytest.approx(housner, rel=0.01)
    assert len(dem_impacts) >= 3


@pytest.mark.parametrize("amplitude_g", [0.3, 0.5])
def test_one_sine_pulse_against_housner(amplitude_g):
    # Row "one-sine pulse 0.3 g / 0.5 g" (T = 1 s): Housner's equation rocks to 0.099 rad and
    # recovers / overturns; DEM peak within 5% (its springs delay uplift a little) / overturns.
    sim = rocking_block(0.0, 3.0, motion={"type": "one_sine", "amplitude": amplitude_g, "unit": "g", "period": 1.0})
    block, peak = sim.body_id("block"), 0.0
    while not sim.done and peak < 1.2:
        sim.step(500)
        peak = max(peak, abs(sim.rotations[block]))
    ref = blockdem.housner_rocking(0.2, 0.8, blockdem.Motion.one_sine(amplitude_g * G, 1.0), end=3.0, dt=1e-5)
    if ref["overturned"]:
        assert peak > 1.2
    else:
        assert ref["peak_theta"] == pytest.approx(0.099, abs=5e-4)
        assert peak == pytest.approx(ref["peak_theta"], rel=0.05)


def test_energy_balance_of_a_shaken_sliding_block():
    # Row "sliding block 250 gal ... energy balance closes": reduced from 150 s to 20 s; the
    # balance error (residual over table work + dissipation) stays under the row's 0.1%.
    s = blockdem.Scenario.from_file(SOURCE / "examples/paper/sliding.toml")
    s.set("simulation.duration", 20.0)
    s.set_motion(motion={"type": "sine", "amplitude": 2.5, "unit": "m/s^2", "period": 1.0, "phase_deg": 90})
    sim = blockdem.Simulation(s, history=False)
    sim.run()
    assert abs(sim.energy()["balance_error"]) < 1e-3


def test_interface_forces_of_a_drum_column_at_rest():
    # Row "interface forces, 3-drum column at rest": each joint carries the weight above it,
    # tolerance 1e-4 of that weight (the dashpots have damped the start after 1 s).
    # The file's last table is its El Centro motion (../shared/data); this row needs no motion.
    text = (SOURCE / "examples/columns/drum_column_material.toml").read_text(encoding="utf-8")
    s = blockdem.Scenario.from_toml(text.split("[table_motion.horizontal]")[0], base_dir=str(SOURCE / "examples/columns"))
    s.set_motion(motion={"type": "none"})
    s.set("simulation.duration", 1.0)
    sim = blockdem.Simulation(s, history=False)
    sim.run()
    names = sim.body_names
    drums = sorted((n for n in names if n.startswith("drum")), key=lambda n: sim.positions[sim.body_id(n), 1])
    c = sim.contacts()
    for i, drum in enumerate(drums):
        above = sum(sim.masses[sim.body_id(d)] for d in drums[i:]) * G   # the scenario's default g
        below = sim.body_id(drums[i - 1]) if i else sim.body_id("table")
        me = sim.body_id(drum)
        joint = ((c["body_a"] == below) & (c["body_b"] == me)) | ((c["body_a"] == me) & (c["body_b"] == below))
        assert c["normal_force"][joint].sum() == pytest.approx(above, rel=1e-4), drum


# The rows' L: foot 0.4 x 0.15 m, stem 0.1 m wide and 0.8 m tall overall, standing on the foot's
# left end; as rectangles (w, h, cx, cy): the foot, and the stem above it.
L_OUTLINE = [[0, 0], [0.4, 0], [0.4, 0.15], [0.1, 0.15], [0.1, 0.8], [0, 0.8]]
L_RECTANGLES = [(0.4, 0.15, 0.2, 0.075), (0.1, 0.65, 0.05, 0.475)]


def l_area_centroid():
    area = sum(w * h for w, h, _, _ in L_RECTANGLES)
    return (area, sum(w * h * x for w, h, x, _ in L_RECTANGLES) / area,
            sum(w * h * y for w, h, _, y in L_RECTANGLES) / area)


def test_l_and_t_mass_properties():
    # Row "L and T sections as concave polygon bodies": area, centroid and polar inertia of
    # their rectangles by parallel axes, 1e-12 relative.
    law = {"kn": 1e8, "ks": 1e8, "mu": 0.6, "e": 0.5, "e_meaning": "rebound", "h_s": 0.0}
    rho = 2000.0  # [kg/m^3], unit thickness
    bodies = [table_body(), {"name": "L", "kind": "dynamic", "shape": "polygon", "vertices": L_OUTLINE, "density": rho}]
    sim = blockdem.Simulation(scene(bodies, law, 0.01, 1e-5), history=False)
    area, cx, cy = l_area_centroid()
    rects = L_RECTANGLES
    polar = sum(w * h * ((w * w + h * h) / 12 + (x - cx) ** 2 + (y - cy) ** 2) for w, h, x, y in rects)
    i = sim.body_id("L")
    assert sim.masses[i] == pytest.approx(rho * area, rel=1e-12)
    assert sim.inertias[i] == pytest.approx(rho * polar, rel=1e-12)
    np.testing.assert_allclose(sim.positions[i], [cx, cy], rtol=1e-12)


def test_rounded_corner_to_corner_impact_has_no_spin():
    # Row "corner-to-corner impact of two squares along their diagonal, rounded": by symmetry
    # the squares rebound along the diagonal without spin; bound 1e-9.
    law = {"kn": 1e6, "ks": 1e6, "mu": 0.5, "e": 0.5, "e_meaning": "rebound", "h_s": 0.0, "rounding": 0.01}
    half_diagonal = 0.1 * math.sqrt(2)
    bodies = [{"name": f"s{i}", "kind": "dynamic", "shape": "rectangle", "width": 0.2, "height": 0.2,
               "rotation": math.pi / 4, "center": [s * (half_diagonal + 5e-4), 0.0], "mass": 1.0,
               "velocity": [-s * 1.0, 0.0]} for i, s in enumerate((-1, 1))]
    sim = blockdem.Simulation(scene(bodies, law, 0.02, 1e-6, gravity=0.0), history=False)
    sim.run()
    assert np.abs(sim.angular_velocities).max() < 1e-9
    assert np.abs(sim.velocities[:, 1]).max() < 1e-9
    assert sim.velocities[1, 0] > 0.1  # they did meet and rebound


def joint_contact(kn, ks, mu):
    """Per-length joint stiffness [Pa/m], damped (h = 0.5) so that statics is reached."""
    return {"stiffness": "per_length", "kn": kn, "ks": ks, "mu": mu, "h_n": 0.5, "h_s": 0.5}


def derived_step_scene(bodies, contact, duration, **simulation):
    sim = {"duration": duration, "gravity": G, "dt_safety": 0.3, "output_interval": 0.01}
    sim.update(simulation)
    return blockdem.Scenario.from_dict({"simulation": sim, "contact": contact, "bodies": bodies})


def test_per_length_column_closes_each_joint_by_sigma_over_kn():
    # Row "column of 4 blocks under gravity, stiffness = per_length": each joint closes by
    # sigma / kn (JKN = 1e9 Pa/m), tolerance 1%. Blocks 0.5 x 0.25 m, 0.4 m thick, 100 kg.
    width, height, thickness, mass = 0.5, 0.25, 0.4, 100.0
    bodies = [{"name": "base", "kind": "fixed", "shape": "rectangle", "width": 1.0, "height": 0.2,
               "center": [0.0, -0.1]}]
    bodies += [{"name": f"block{i}", "kind": "dynamic", "shape": "rectangle", "width": width, "height": height,
                "center": [0.0, (i + 0.5) * height], "mass": mass, "thickness": thickness} for i in range(4)]
    sim = blockdem.Simulation(derived_step_scene(bodies, joint_contact(1e9, 0.5e9, 0.6), 0.3), history=False)
    sim.run()
    c = sim.contacts()
    ids = [sim.body_id("base")] + [sim.body_id(f"block{i}") for i in range(4)]
    for j in range(4):
        joint = (c["body_a"] == min(ids[j], ids[j + 1])) & (c["body_b"] == max(ids[j], ids[j + 1]))
        sigma = (4 - j) * mass * G / (width * thickness)
        assert c["overlap"][joint].mean() == pytest.approx(sigma / 1e9, rel=0.01), f"joint {j}"
    assert sim.energy()["balance_error"] < 1e-3


def test_per_length_joint_shears_by_tau_over_ks():
    # Row "flat block on a table tilted 10 deg, per-length joint": the base slips elastically by
    # tau / ks before sliding (tan 10 deg < mu = 0.6), tolerance 1%.
    width, height, mass, ks = 1.0, 0.1, 500.0, 5e8
    bodies = [{"name": "table", "kind": "fixed", "shape": "rectangle", "width": 2.0, "height": 0.2, "center": [0.0, -0.1]},
              {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": width, "height": height,
               "center": [0.0, 0.05], "mass": mass}]
    sim = blockdem.Simulation(derived_step_scene(bodies, joint_contact(1e9, ks, 0.6), 0.3, tilt_deg=10.0), history=False)
    i = sim.body_id("block")
    x0 = sim.positions[i, 0]
    sim.run()
    base_slip = sim.positions[i, 0] - x0 + sim.rotations[i] * 0.5 * height
    expected = -mass * G * math.sin(math.radians(10.0)) / (ks * width * 1.0)
    assert base_slip == pytest.approx(expected, rel=0.01)
    assert not sim.contacts()["sliding"].any()


def tilting_table(width, height, mu, start_deg, duration):
    """The row's tilting table: a 2500 kg/m^3 block settled at start_deg, the tilt then rising
    at 0.5 deg/s; the summary's table tilt at the block's first slip and first tipping."""
    bodies = [{"name": "table", "kind": "fixed", "shape": "rectangle", "width": 2.0, "height": 0.2, "center": [0.0, -0.1]},
              {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": width, "height": height,
               "center": [0.0, 0.5 * height], "mass": 2500.0 * width * height}]
    contact = {"kn": 1e8, "ks": 1e8, "mu": mu, "h_n": 0.3, "h_s": 1.0}
    s = blockdem.Scenario.from_dict({
        "simulation": {"duration": duration, "gravity": G, "tilt_deg": start_deg, "tilt_rate_deg_s": 0.5,
                       "output_interval": 0.01},
        "contact": contact, "bodies": bodies, "settling": {}})
    sim = blockdem.Simulation(s, history=False)
    summary = sim.run()
    block = next(b for b in summary["bodies"] if b["name"] == "block")
    return block["table_tilt_deg_at"]


def test_tilting_table_slender_block_topples_at_atan_b_over_h():
    # Row "tilting table at 0.5 deg/s: slender block (b/h = 0.25, mu = 0.6)": tips at
    # atan(b/h) = 14.036 deg; the row's window 0 to +0.4 deg (the tilt keeps rising while the
    # rotation grows to the detection size; tests/validation/test_tilting_table.cpp).
    at = tilting_table(0.2, 0.8, 0.6, 12.0, 6.0)
    expected = math.degrees(math.atan(0.25))
    assert expected <= at["rocking_onset"] <= expected + 0.4
    # The row's measured figure: the tilt from level last passing the critical angle, 0.05 deg.
    assert at["overturning"] == pytest.approx(expected, abs=0.05)


def test_tilting_table_squat_block_slides_at_atan_mu():
    # Row "tilting table: squat block (b/h = 1, mu = 0.6)": slides at atan(mu) = 30.964 deg,
    # window 0 to +0.4 deg.
    at = tilting_table(0.4, 0.4, 0.6, 29.0, 6.0)
    expected = math.degrees(math.atan(0.6))
    assert expected <= at["slip_onset"] <= expected + 0.4


def settled_block_on_tilt(tilt_deg, mu, duration, motion=None):
    """A 0.2 x 0.1 m, 1 kg block on a level table tilted by tilt_deg (gravity turned), settled
    with friction held ([settling]: kinetic ratio 1e-10), kn = ks = 1e6 N/m, h_n 0.3, h_s 1."""
    bodies = [{"name": "table", "kind": "driven", "shape": "rectangle", "width": 2.0, "height": 0.2, "center": [0.0, -0.1],
               "density": 1000.0},
              {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.2, "height": 0.1,
               "center": [0.0, 0.05], "mass": 1.0}]
    s = blockdem.Scenario.from_dict({
        "simulation": {"duration": duration, "gravity": G, "tilt_deg": tilt_deg, "output_interval": 0.01},
        "contact": {"kn": 1e6, "ks": 1e6, "mu": mu, "h_n": 0.3, "h_s": 1.0}, "bodies": bodies,
        "settling": {"kinetic_ratio": 1e-10, "window": 0.05, "max_time": 2.0}})
    if motion is not None:
        s.set_motion(motion=motion)
    return blockdem.Simulation(s, history=False)


def test_settled_block_below_the_friction_angle_starts_in_equilibrium():
    # Row "settled block on a 20 deg incline, mu = 0.5": starts in equilibrium, slip below 1e-9 m.
    sim = settled_block_on_tilt(20.0, 0.5, 0.5)
    start = sim.positions[sim.body_id("block")].copy()
    sim.run()
    assert np.abs(sim.positions[sim.body_id("block")] - start).max() < 1e-9


def test_settled_block_above_the_friction_angle_slides_from_the_first_step():
    # Row "settled block on a 30 deg incline, mu = 0.5": slip g (sin a - mu cos a) t^2 / 2 from
    # t = 0, tolerance 0.2% (what settling leaves of the velocity is 0.07% at 0.1 s). As in
    # tests/validation/test_incline_and_energy.cpp: a fixed slab turned by 30 deg, dt = 1e-5 s.
    slope = math.radians(30.0)
    c, s_ = math.cos(slope), math.sin(slope)
    bodies = [{"name": "slab", "kind": "fixed", "shape": "rectangle", "width": 10.0, "height": 0.5, "center": [0.0, 0.0],
               "rotation": slope},
              {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.2, "height": 0.1,
               "center": [-0.3 * s_, 0.3 * c], "rotation": slope, "mass": 1.0}]
    sim = blockdem.Simulation(blockdem.Scenario.from_dict({
        "simulation": {"duration": 0.5, "dt": 1e-5, "gravity": G, "output_interval": 0.01},
        "contact": {"kn": 1e6, "ks": 1e6, "mu": 0.5, "h_n": 0.3, "h_s": 1.0}, "bodies": bodies,
        "settling": {"kinetic_ratio": 1e-10, "window": 0.05, "max_time": 2.0}}), history=False)
    block = sim.body_id("block")
    start = sim.positions[block].copy()
    downhill = np.array([-c, -s_])
    a = G * (s_ - 0.5 * c)
    for t in (0.1, 0.2, 0.5):
        sim.run(until=t)
        assert (sim.positions[block] - start) @ downhill == pytest.approx(0.5 * a * t * t, rel=0.002), f"t = {t}"


@pytest.mark.parametrize("amplitude", [3.0, 9.0])
def test_tilted_table_shaken_along_its_surface_follows_newmark(amplitude):
    # Row "table tilted 20 deg, shaken along its surface (3 and 9 m/s^2)": Newmark's block on an
    # incline (blockdem.rigid_plastic_sliding with slope; asymmetric yield), final slip after
    # 4 cycles of T = 0.5 s, tolerance 0.5% (the 1e6 N/m springs smear each stick-slip change).
    sine = {"type": "sine", "amplitude": amplitude, "unit": "m/s^2", "period": 0.5, "cycles": 4}
    sim = settled_block_on_tilt(20.0, 0.5, 2.5, motion=sine)
    start = sim.positions[:, 0].copy()
    sim.run()
    moved = sim.positions[:, 0] - start
    dem = moved[sim.body_id("block")] - moved[sim.body_id("table")]
    ref = blockdem.rigid_plastic_sliding(blockdem.Motion.sine(amplitude, 0.5, cycles=4), 0.5, end=2.5, dt=1e-5,
                                         slope=math.radians(20.0))
    newmark = ref["displacement"][-1]
    assert newmark < -0.01   # down the slope, by centimetres
    assert dem == pytest.approx(newmark, rel=0.005)


def l_on_table(duration, tilt_deg=0.0, tilt_rate=0.0, kinetic_ratio=1e-8):
    bodies = [{"name": "table", "kind": "fixed", "shape": "rectangle", "width": 2.0, "height": 0.2, "center": [0.2, -0.1]},
              {"name": "L", "kind": "dynamic", "shape": "polygon", "vertices": L_OUTLINE, "density": 2500.0}]
    return blockdem.Simulation(blockdem.Scenario.from_dict({
        "simulation": {"duration": duration, "gravity": G, "tilt_deg": tilt_deg, "tilt_rate_deg_s": tilt_rate,
                       "output_interval": 0.01},
        "contact": {"kn": 1e8, "ks": 1e8, "mu": 0.6, "h_n": 0.3, "h_s": 0.3 if tilt_rate == 0.0 else 1.0},
        "bodies": bodies, "settling": {"kinetic_ratio": kinetic_ratio}}), history=False)


def test_l_block_rests_on_its_corners_by_the_lever_rule():
    # Row "L block (foot 0.4 x 0.15 m, stem 0.1 x 0.8 m) settled on a table": corner supports by
    # the lever rule about the centroid (2130.61 / 935.02 N), tolerance 1e-3 of the weight
    # (settled to a kinetic ratio of 1e-13, as the C++ test: the forces then vibrate by < 7e-5 W).
    sim = l_on_table(0.01, kinetic_ratio=1e-13)
    sim.step(1)
    _, cx, _ = l_area_centroid()
    weight = sim.masses[sim.body_id("L")] * G
    c = sim.contacts()
    left = c["normal_force"][np.abs(c["x"]) < 0.01].sum()
    right = c["normal_force"][np.abs(c["x"] - 0.4) < 0.01].sum()
    assert weight * (0.4 - cx) / 0.4 == pytest.approx(2130.61, abs=0.01)
    assert left == pytest.approx(weight * (0.4 - cx) / 0.4, abs=1e-3 * weight)
    assert right == pytest.approx(weight * cx / 0.4, abs=1e-3 * weight)


def test_l_block_overturns_on_a_tilting_table_when_its_centroid_passes_the_pivot():
    # Row "L block on a tilting table at 0.5 deg/s, mu = 0.6": overturns at atan(x_c / y_c) =
    # 23.321 deg, tolerance 0.05 deg; it tips 0 to 0.4 deg after (the detection's lag).
    sim = l_on_table(6.0, tilt_deg=21.0, tilt_rate=0.5)
    summary = sim.run()
    at = next(b for b in summary["bodies"] if b["name"] == "L")["table_tilt_deg_at"]
    _, cx, cy = l_area_centroid()
    expected = math.degrees(math.atan(cx / cy))
    assert expected == pytest.approx(23.321, abs=1e-3)
    assert at["overturning"] == pytest.approx(expected, abs=0.05)
    assert expected <= at["rocking_onset"] < expected + 0.4


def test_rocking_onset_at_the_static_threshold():
    # Row "rocking onset, slow ramp": the table's acceleration ramps to 1.2 g b/h over 6 s; the
    # heel lifts (one contact point left) at a = g b/h, tolerance 2%.
    threshold = G * 0.25
    dt = 0.01
    ramp = np.arange(601) * dt / 6.0 * 1.2 * threshold
    s = blockdem.Scenario.from_dict({
        "simulation": {"duration": 6.0, "dt": 2e-5, "gravity": G, "output_interval": 0.01},
        "contact": {"kn": 1e9, "ks": 1e9, "mu": 2.0, "e": 0.2, "e_meaning": "paper", "h_s": 1.0},
        "bodies": [dict(table_body(), density=1536.0),
                   {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.4, "height": 1.6,
                    "center": [0.0, 0.8], "density": 1536.0}]})
    s.set_motion(ramp, dt=dt)
    sim = blockdem.Simulation(s, history=False)
    sim.step(int(0.2 / sim.dt))
    onset = None
    while not sim.done:
        sim.step(50)
        if len(sim.contacts()) == 1:
            onset = sim.accelerations[sim.body_id("table"), 0]
            break
    assert onset is not None, "no uplift up to 1.2 g b/h"
    assert abs(onset) / threshold == pytest.approx(1.0, abs=0.02)


def test_rounded_corners_leave_the_newmark_slip_unchanged():
    # Row "rounded corners (rounding = 1e-3 of the block): Newmark slip": the paper's sliding
    # block with r = 0.2 mm against Newmark's rigid-plastic block (blockdem.rigid_plastic_sliding,
    # a = 3.5 cos(2 pi t)), tolerance 2% + u_e (u_e = mu m g / (2 ks) = 74 um), after 5 s.
    s = blockdem.Scenario.from_file(SOURCE / "examples/paper/sliding.toml")
    s.set("contact.rounding", 2e-4)
    sim = blockdem.Simulation(s, history=False)
    start = sim.positions[:, 0].copy()
    sim.run()
    moved = sim.positions[:, 0] - start
    dem = moved[sim.body_id("block")] - moved[sim.body_id("table")]
    ref = blockdem.rigid_plastic_sliding(blockdem.Motion.sine(3.5, 1.0, phase=math.pi / 2), 0.3, end=5.0, dt=1e-5)
    u_e = 0.3 * 1.0 * G / (2 * 2.0e4)
    assert dem == pytest.approx(ref["displacement"][-1], abs=0.02 * abs(ref["displacement"][-1]) + u_e)


def test_a_block_on_too_soft_contacts_stops_as_penetration():
    # Row "block on contacts 2000x too soft": the run stops with a penetration error (a
    # SimulationError through Python), not a result.
    law = {"kn": 10.0, "ks": 10.0, "mu": 0.5, "e": 0.4, "e_meaning": "paper", "h_s": 1.0}
    block = {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.5, "height": 0.2,
             "center": [0.0, 0.1], "mass": 1.0}
    sim = blockdem.Simulation(scene([table_body(), block], law, 5.0, 1e-3), history=False)
    with pytest.raises(blockdem.SimulationError, match="penetration"):
        sim.run()


def test_t_section_mass_properties():
    # Row "L and T sections as concave polygon bodies": the T (web 0.1 x 0.5 m, flange 0.6 x
    # 0.1 m on top), area, centroid, polar inertia by parallel axes, 1e-12 relative.
    law = {"kn": 1e8, "ks": 1e8, "mu": 0.6, "e": 0.5, "e_meaning": "rebound", "h_s": 0.0}
    T = [[-0.05, 0.0], [0.05, 0.0], [0.05, 0.5], [0.3, 0.5], [0.3, 0.6], [-0.3, 0.6], [-0.3, 0.5], [-0.05, 0.5]]
    rects = [(0.1, 0.5, 0.0, 0.25), (0.6, 0.1, 0.0, 0.55)]
    rho = 2000.0
    sim = blockdem.Simulation(scene([table_body(), {"name": "T", "kind": "dynamic", "shape": "polygon", "vertices": T,
                                                    "density": rho}], law, 0.01, 1e-5), history=False)
    area = sum(w * h for w, h, _, _ in rects)
    cy = sum(w * h * y for w, h, _, y in rects) / area
    polar = sum(w * h * ((w * w + h * h) / 12 + x ** 2 + (y - cy) ** 2) for w, h, x, y in rects)
    i = sim.body_id("T")
    assert sim.masses[i] == pytest.approx(rho * area, rel=1e-12)
    assert sim.inertias[i] == pytest.approx(rho * polar, rel=1e-12)
    assert sim.positions[i, 1] == pytest.approx(cy, rel=1e-12) and abs(sim.positions[i, 0]) < 1e-15


def test_sliding_below_mu_g_stays_within_the_elastic_shear():
    # Row "sliding below mu g (0.8 mu g)": the paper's block under 0.8 mu g cos(2 pi t) does not
    # slide: its slip relative to the table stays within 2 x m a / (2 ks) (the two shear
    # springs' elastic travel, doubled for the dynamic overshoot).
    s = blockdem.Scenario.from_file(SOURCE / "examples/paper/sliding.toml")
    s.set("simulation.duration", 3.0)
    a = 0.8 * 0.3 * G
    s.set_motion(motion={"type": "sine", "amplitude": a, "unit": "m/s^2", "period": 1.0, "phase_deg": 90})
    sim = blockdem.Simulation(s)
    sim.run()
    h = sim.history()
    slip = h["x"][:, h["bodies"].index("block")] - h["x"][:, h["bodies"].index("table")]
    slip -= slip[0]
    assert np.abs(slip).max() <= 2 * 1.0 * a / (2 * 2.0e4)


def test_no_uplift_held_just_below_the_threshold():
    # Row "rocking onset, slow ramp": "no uplift at 0.95 for 5 s": the table's acceleration rises
    # to 0.95 g b/h in 2 s and holds; both corners stay on the table.
    threshold = G * 0.25
    t = np.arange(701) * 0.01
    accel = np.minimum(t / 2.0, 1.0) * 0.95 * threshold
    s = blockdem.Scenario.from_dict({
        "simulation": {"duration": 7.0, "dt": 2e-5, "gravity": G, "output_interval": 0.01},
        "contact": {"kn": 1e9, "ks": 1e9, "mu": 2.0, "e": 0.2, "e_meaning": "paper", "h_s": 1.0},
        "bodies": [dict(table_body(), density=1536.0),
                   {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.4, "height": 1.6,
                    "center": [0.0, 0.8], "density": 1536.0}]})
    s.set_motion(accel, dt=0.01)
    sim = blockdem.Simulation(s, history=False)
    sim.step(int(0.2 / sim.dt))
    while not sim.done:
        sim.step(250)
        assert len(sim.contacts()) == 2, f"lifted at t = {sim.t}"


def test_bonded_block_breaks_in_tension_at_sigma_t_times_area():
    # Row "direct tension of a bonded block, table accelerating up": a 100 kg block bonded under
    # a driven ceiling accelerating up at 100 t m/s^2; the bond breaks at sigma_t A = 5000 N
    # (sigma_t = 1e4 Pa, A = 0.5 m x 1 m), tolerance 1%.
    # (h_n = 0.9: a scenario takes h_n below 1; the C++ test sets 1 on the model itself.)
    contact = dict(joint_contact(1e9, 5e8, 0.6), cohesion=1e5, tensile_strength=1e4, h_n=0.9)
    bodies = [{"name": "ceiling", "kind": "driven", "shape": "rectangle", "width": 1.0, "height": 0.2,
               "center": [0.0, 0.1], "density": 1000.0, "bonded": True},
              {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 0.5, "height": 0.2,
               "center": [0.0, -0.1], "mass": 100.0, "bonded": True}]
    s = derived_step_scene(bodies, contact, 0.6)
    s.set_motion(np.arange(61) * 0.01 * 100.0, dt=0.01, direction="vertical")
    sim = blockdem.Simulation(s, history=False)
    intact = 1   # BondState::intact
    assert (sim.contacts()["bond"] == intact).sum() == 2
    last_pull = None
    while not sim.done:
        c = sim.contacts()
        if (c["bond"] == intact).sum() < 2:
            break
        last_pull = -c["normal_force"].sum()   # the normal points from the ceiling (a) down: a pull is < 0
        sim.step(10)
    assert last_pull == pytest.approx(5000.0, rel=0.01)
