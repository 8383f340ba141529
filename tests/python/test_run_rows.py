"""The README's last run rows through Python: the tombstone under a 5 g one-sine pulse at 0.95
of the printed stable step, the period-3 subharmonic against Housner's equation, and
`calibrate` to Housner's r (blockdem.calibrate_rocking). Each test names its row and carries
its tolerance."""
import math

import numpy as np
import pytest

import blockdem

G = 9.81  # [m/s^2]


@pytest.mark.slow
def test_tombstone_under_a_five_g_pulse_at_095_of_the_limit():
    # Row "tombstone, 5 g one-sine pulse at 0.95 of the printed limit": completes, energy
    # balance within 3 % (the stiff h_s = 1 base under 5 g: the row's own tolerance).
    s = blockdem.Scenario.from_dict({
        "simulation": {"duration": 1.5, "dt_safety": 0.95, "gravity": G, "output_interval": 1e-2},
        "contact": {"kn": 1e9, "ks": 1e9, "mu": 0.8, "h_n": 0.4559, "h_s": 1.0},
        "bodies": [
            {"name": "table", "kind": "driven", "shape": "rectangle", "width": 4.0, "height": 0.2,
             "center": [0.0, -0.1], "density": 1000.0},
            {"name": "tombstone", "kind": "dynamic", "shape": "rectangle", "width": 0.4, "height": 1.6,
             "center": [0.0, 0.8], "mass": 665.6, "inertia": 150.87},
        ],
    })
    s.set_motion(motion={"type": "one_sine", "amplitude": 5.0 * 9.80665, "period": 0.5})
    sim = blockdem.Simulation(s, history=False)
    # The limit the tool prints is below the old one-corner estimate (1.9e-4 s), at which a 5 g
    # pulse diverged at 0.9: dt = 0.95 x the two-corner limit.
    assert sim.dt < 0.95 * 1.5e-4
    sim.run()
    assert sim.done
    assert sim.t == pytest.approx(1.5, abs=2 * sim.dt)
    assert abs(sim.energy()["balance_error"]) < 0.03


SUBHARMONIC_HZ, SUBHARMONIC_G, SUBHARMONIC_CYCLES = 6.0, 1.0, 120


def section_of_last_periods(theta_at, periods):
    """theta at the start of each of the given table periods."""
    return [theta_at(k / SUBHARMONIC_HZ) for k in periods]


@pytest.mark.slow
def test_period_three_subharmonic_is_housners_orbit(source_dir):
    # Row "period-3 subharmonic, 0.2 x 0.8 m block, 6 Hz, 1.0 g sine": Housner's equation (the
    # project's solver, blockdem.housner_rocking, r = 1 - 1.5 sin^2 alpha = 0.912, the share the
    # DEM's e = 0.2 heel loses) settles into a period-3 orbit; the DEM's Poincare section (theta
    # at each period's start) over the last three periods lies on Housner's three points within
    # 1e-3 rad (about 3 % of the swing): the same orbit, not just the same label.
    period = 1.0 / SUBHARMONIC_HZ
    s = blockdem.Scenario.from_file(str(source_dir / "studies/scenarios/sine_block.toml"))
    s.set("table_motion.horizontal.period", period)
    s.set("table_motion.horizontal.amplitude", SUBHARMONIC_G * G)
    s.set("table_motion.horizontal.cycles", SUBHARMONIC_CYCLES)
    s.set("simulation.duration", SUBHARMONIC_CYCLES * period)
    sim = blockdem.Simulation(s, history=False)
    block = sim.body_id("block")
    last = range(SUBHARMONIC_CYCLES - 6, SUBHARMONIC_CYCLES)

    def dem_theta(t):
        sim.run(until=t)
        return float(sim.rotations[block])

    dem = section_of_last_periods(dem_theta, last)
    ref = blockdem.housner_rocking(0.1, 0.4, blockdem.Motion.sine(SUBHARMONIC_G * G, period),
                                   end=SUBHARMONIC_CYCLES * period, dt=1e-5)
    assert not ref["overturned"]

    def housner_theta(t):
        i = int(round(t / (ref["t"][1] - ref["t"][0])))
        return float(ref["theta"][i])

    housner = section_of_last_periods(housner_theta, last)
    for section in (dem, housner):
        # period 3: repeats after three periods, not after one
        assert abs(section[5] - section[2]) < 1e-3 and abs(section[4] - section[1]) < 1e-3
        assert abs(section[5] - section[4]) > 5e-3
    for a, b in zip(sorted(dem[-3:]), sorted(housner[-3:])):
        assert a == pytest.approx(b, abs=1e-3)


@pytest.mark.slow
def test_calibrate_to_housners_restitution():
    # Row "`calibrate` to Housner's r (slender block)": r = 1 - 1.5 sin^2 alpha, 1e-3 on r. The
    # slender block of the C++ test (0.2 x 1.0 m, kn = 1e8, no tension): asked for Housner's r,
    # the fit finds a contact whose free rocking loses exactly Housner's share; it lands where
    # the heel no longer bounces (h_n >= 0.3).
    width, height = 0.2, 1.0
    housner = 1.0 - 1.5 * math.sin(math.atan(width / height)) ** 2
    fit = blockdem.calibrate_rocking(width=width, height=height, kn=1e8, target_restitution=housner, tolerance=1e-3)
    assert fit["housner_restitution"] == pytest.approx(housner, rel=1e-12)
    assert fit["found"]
    assert fit["achieved_restitution"] == pytest.approx(housner, abs=1e-3)
    assert fit["h_n"] >= 0.3
    assert fit["dem_runs"] == len(fit["scan"])
    with pytest.raises(ValueError):
        blockdem.calibrate_rocking(width=width, height=height, kn=1e8, target_restitution=1.2)
    with pytest.raises(ValueError):
        blockdem.calibrate_rocking(width=width, height=height, kn=1e8, target_restitution=0.8, termination="sticky")
    # A block that cannot rock is refused before any DEM run, as by the CLI: too squat (b/h >=
    # sqrt 2: Housner's r <= 0). One that slides (mu 0.05 under a 0.2 x 0.6 m block) is refused
    # after the fit, whose run gained energy at an impact (r 1.23, 1.25).
    with pytest.raises(ValueError, match="at least sqrt"):
        blockdem.calibrate_rocking(width=2.0, height=0.2, kn=1e8, target_restitution=0.8)
    with pytest.raises(RuntimeError, match="gained energy at impact"):
        blockdem.calibrate_rocking(width=0.2, height=0.6, kn=1e7, mu=0.05, target_restitution=0.8)


@pytest.mark.slow
def test_tilting_table_wall_with_associative_joints_against_the_lp(source_dir):
    # Row "tilting table vs LP: the wall with a window with associative joints (per-length,
    # tan psi = mu = 0.8), started as built 8 deg below, 1 deg/s": associative LP 0.4728, 3 %
    # (this start), and the LP's 24 moving bricks move. The row's protocol in full (about 7.6 s
    # of tilt, 15 to 20 s here): a start 3 deg below was tried and collapses at -5.6 %, so the
    # start cannot be shortened without leaving the row's tolerance (docs/limit_analysis.md: the
    # collapse depends on the start). Read at 1 cm of centroid movement (the C++ test adds the
    # rotation times the bounding radius: 0.4643 there, 0.4639 here).
    s = blockdem.Scenario.from_file(str(source_dir / "examples/limit/wall_with_window.toml"))
    d = s.to_dict()
    d.pop("settling")    # as built, not settled
    d["contact"] = {"stiffness": "per_length", "kn": 1e10, "ks": 5e9, "mu": 0.8,
                    "dilation_deg": math.degrees(math.atan(0.8)), "h_n": 0.3, "h_s": 1.0}
    # (As the C++ test: bricks side by side touch exactly and their head joints flip between one
    # and two points, whose per-length stiffness differs, so the ledger's error relative to the
    # first steps' tiny energies passes the default guard.)
    d["simulation"]["max_energy_error"] = 100.0
    s = blockdem.Scenario.from_dict(d)
    lp = blockdem.limit_analysis(s, direction="-x")
    assert lp["lambda"] == pytest.approx(0.4728, abs=1e-4)
    start = math.degrees(math.atan(lp["lambda"])) - 8.0
    s.set("simulation.tilt_deg", start)
    s.set("simulation.tilt_rate_deg_s", 1.0)
    s.set("simulation.duration", 11.0)
    sim = blockdem.Simulation(s, history=False)
    p0 = sim.positions.copy()
    tilt = None
    while not sim.done:
        sim.step(50)
        moved = np.hypot(*(sim.positions - p0).T)
        if moved.max() > 1e-2:
            tilt = start + 1.0 * sim.t
            break
    assert tilt is not None
    dem = math.tan(math.radians(tilt))
    assert dem < lp["lambda"]
    assert dem == pytest.approx(lp["lambda"], rel=0.03)
    # Moving: above 10 % of the fastest (the C++ test's rule, there on each block's fastest point;
    # here on centroids, for the LP's virtual velocities and the DEM's displacements alike).
    speed = np.hypot(lp["mechanism"][:, 0], lp["mechanism"][:, 1])
    lp_moving = set(np.flatnonzero(speed > 0.1 * speed.max()))
    dem_moving = set(np.flatnonzero(moved > 0.1 * moved.max()))
    assert len(lp_moving) == 24
    assert lp_moving <= dem_moving and len(dem_moving) <= len(lp_moving) + 4


def shaken_rock_slope(source_dir, rounding_m, duration_s):
    """examples/assemblies/rock_slope.toml (128 blocks) under a 0.3 g sine of period 0.5 s (the
    C++ row's motion), stepped one step at a time: the number of pair normals that turn by more
    than 30 deg in one step (flips), the largest turn of one, and the largest energy error."""
    s = blockdem.Scenario.from_file(str(source_dir / "examples/assemblies/rock_slope.toml"))
    s.set("contact.rounding", rounding_m)
    s.set("simulation.duration", duration_s)
    s.set_motion(motion={"type": "sine", "amplitude": 0.3, "unit": "g", "period": 0.5})
    sim = blockdem.Simulation(s, history=False)
    last, flips, largest_turn, largest_error = {}, 0, 0.0, 0.0
    while not sim.done:
        sim.step(1)
        c = sim.contacts()
        now = {}
        for a, b, nx, ny in zip(c["body_a"], c["body_b"], c["nx"], c["ny"]):
            now.setdefault((a, b), (nx, ny))   # a pair's points share its normal
        for pair, n in now.items():
            if pair in last:
                turn = math.acos(max(-1.0, min(1.0, n[0] * last[pair][0] + n[1] * last[pair][1])))
                largest_turn = max(largest_turn, turn)
                flips += turn > math.pi / 6
        last = now
        largest_error = max(largest_error, abs(sim.energy()["balance_error"]))
    return flips, largest_turn, largest_error


@pytest.mark.slow
def test_jointed_rock_slope_rounded_against_sharp(source_dir):
    # Row "jointed rock slope, 2 s of 0.3 g: rounded (r = 1 % of least width) against sharp": no
    # contact normal turning > 30 deg in a step; 0 flips, turn < 0.01 rad; the balance closes at
    # least as well as sharp's. Reduced: the example's slope (128 blocks, not the C++ scene's
    # 150), r = 1 cm (the module does not give the blocks' least width; the scenario refuses a
    # rounding above 0.25 of any block's least width, and accepts this one; the row's point is
    # that the arcs remove the flips), and the first 0.3 s (one step at a time from Python, with
    # contacts() and energy() every step: 4410 steps per model). Measured over 0.3 s: see
    # docs/python.md.
    sharp = shaken_rock_slope(source_dir, 0.0, 0.3)
    rounded = shaken_rock_slope(source_dir, 0.01, 0.3)
    assert sharp[0] > 0            # the scene meets corners, and the sharp model flips there
    assert rounded[0] == 0
    assert rounded[1] < 0.01
    assert rounded[2] <= sharp[2]
