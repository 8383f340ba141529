"""The README's unit-level validation rows through Python: the no-tension rebound formula, the
contact law over a load/slip/reversal history, the dilating joint point, the Butterworth sensor
filter (python/bind_laws.cpp), and the stable step of a block on two corners (through a
scenario whose dt is derived). Each test names its row and carries its tolerance."""
import math

import numpy as np
import pytest

import blockdem


def rk4_no_tension_rebound(h_n, steps_per_period=4000):
    """Rebound of F = max(0, d + 2 h_n d') (unit mass and stiffness) from d = 0, d' = 1, by RK4
    on d'' = -(d + 2 h_n d'), the end (force back to zero) found by linear interpolation of the
    force between the two steps around it: an independent solution of Schwager and Poeschel's
    problem, whose speed at the end is accurate to O(dt^2) (about 1e-7 here)."""
    dt = 2.0 * math.pi / steps_per_period

    def rate(s):
        return np.array([s[1], -(s[0] + 2.0 * h_n * s[1])])

    state = np.array([0.0, 1.0])
    for _ in range(20 * steps_per_period):
        k1 = rate(state)
        k2 = rate(state + 0.5 * dt * k1)
        k3 = rate(state + 0.5 * dt * k2)
        k4 = rate(state + dt * k3)
        new = state + dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
        force_before, force_after = state[0] + 2 * h_n * state[1], new[0] + 2 * h_n * new[1]
        if force_after <= 0.0 and new[1] < 0.0:
            s = force_before / (force_before - force_after)
            return -(state[1] + s * (new[1] - state[1]))
        state = new
    raise AssertionError("the contact did not end")


@pytest.mark.parametrize("h_n", [0.05, 0.2, 0.5, 1.0, 2.0, 3.0])
def test_no_tension_rebound_formula_against_rk4(h_n):
    # Row "no-tension rebound formula" (h = 0.05 ... 3): direct RK4 integration, 1e-4.
    assert blockdem.restitution_no_tension(h_n) == pytest.approx(rk4_no_tension_rebound(h_n), abs=1e-4)


def test_rebound_damping_ratio_inverts_the_formula():
    # The calibration the rows rely on: damping_ratio_rebound is the inverse of the formula
    # (bisection: to 1e-9), and the paper's pair of formulas are each other's inverse.
    for e in (0.1, 0.4, 0.8, 0.95):
        assert blockdem.restitution_no_tension(blockdem.damping_ratio_rebound(e)) == pytest.approx(e, abs=1e-9)
        assert blockdem.restitution_paper(blockdem.damping_ratio_paper(e)) == pytest.approx(e, rel=1e-12)
    for bad in (lambda: blockdem.damping_ratio_rebound(0.0), lambda: blockdem.damping_ratio_paper(1.5),
                lambda: blockdem.restitution_no_tension(-0.1), lambda: blockdem.restitution_paper(1.0)):
        with pytest.raises(ValueError):
            bad()


def load_slip_reversal_history(dt, steps):
    """Prescribed kinematics: closing, then a shear that sticks, slides, reverses and slides back,
    a normal unloading that drops the friction cap under a loaded spring, then reloading; the
    overlap stays positive (the point never opens), so the springs' energies are 0.5 k x^2."""
    t = np.arange(1, steps + 1) * dt
    normal_speed = -2e-4 * np.cos(2 * math.pi * t / (steps * dt)) - 0.5e-4  # [m/s], > 0 separating
    overlap = -np.cumsum(normal_speed) * dt                                  # from 0 at step -1
    shift = 1e-5 - min(overlap.min(), 0.0)
    normal_speed[0] -= shift / dt                                            # an initial closure
    overlap = -np.cumsum(normal_speed) * dt
    tangential_speed = 3e-3 * np.sin(4 * math.pi * t / (steps * dt) + 0.4)
    return overlap, normal_speed, tangential_speed


def work_balance_residuals(r, overlap, normal_speed, tangential_speed, dt, kn, ks, stored=None):
    """Per-step (trapezoidal work on the bodies) + (change of stored energy) + dissipation,
    which the law makes zero; and the scale it is compared with."""
    fn = np.concatenate([[0.0], r["normal_N"]])
    fs = np.concatenate([[0.0], r["shear_N"]])
    work = 0.5 * (fn[:-1] + fn[1:]) * normal_speed * dt + 0.5 * (fs[:-1] + fs[1:]) * tangential_speed * dt
    if stored is None:
        stored = 0.5 * kn * overlap ** 2 + 0.5 * r["shear_spring_N"] ** 2 / ks
    change = np.diff(np.concatenate([[0.0], stored]))
    dissipated = r["normal_dashpot_work_J"] + r["shear_dashpot_work_J"] + r["friction_work_J"]
    scale = np.abs(work).sum() + np.abs(dissipated).sum() + stored.max()
    return work + change + dissipated, scale


@pytest.mark.parametrize("zero_overlap", [False, True])
def test_contact_law_work_balance_over_any_history(zero_overlap):
    # Row "contact law over any load/slip/reversal history": trapezoidal work = -(stored change)
    # - dissipation, 1e-12 (of the history's work: round-off only).
    kn, ks, mu, dt = 1e6, 5e5, 0.6, 1e-4
    overlap, vn, vt = load_slip_reversal_history(dt, 4000)
    r = blockdem.contact_point_history(kn=kn, ks=ks, mu=mu, cn=300.0, cs=200.0, dt=dt, overlap=overlap,
                                       normal_speed=vn, tangential_speed=vt, zero_overlap=zero_overlap)
    # The history visits every branch: sticking, sliding both ways, the cap dropping under the spring.
    assert r["sliding"].any() and (~r["sliding"]).any()
    slid = r["shear_spring_N"][r["sliding"]]
    assert (slid > 0).any() and (slid < 0).any()
    assert np.all(np.abs(r["shear_spring_N"]) <= mu * np.maximum(r["normal_N"], 0.0) * (1 + 1e-12) + 1e-12)
    assert r["friction_work_J"].min() >= -1e-12 * np.abs(r["friction_work_J"]).sum()
    residual, scale = work_balance_residuals(r, overlap, vn, vt, dt, kn, ks)
    assert np.abs(residual).max() <= 1e-12 * scale


def test_dilating_joint_point_under_fixed_normal_displacement():
    # Row "dilating joint point, slip under fixed normal displacement": while it slides the
    # normal force rises by kn tan(psi) du_p a step, du_p = ks du_s / (ks + mu kn tan(psi));
    # per-step work balance; both 1e-12 (round-off).
    kn, ks, mu, tan_psi, dt = 2e6, 1e6, 0.7, 0.2, 1e-4
    steps, du_s = 300, 2e-6                       # [m] slip a step
    overlap = np.full(steps, 1e-4)                # [m] held, after closing in the first step
    closing = np.zeros(steps)
    closing[0] = -overlap[0] / dt                 # [m/s] the first step's approach
    r = blockdem.joint_point_history(kn=kn, ks=ks, mu=mu, tan_dilation=tan_psi, dt=dt, overlap=overlap,
                                     normal_speed=closing, tangential_speed=np.full(steps, du_s / dt))
    sliding = np.flatnonzero(r["sliding"])
    assert sliding.size > 100
    steady = sliding[1:]                          # the first sliding step only partly slips
    du_p = ks * du_s / (ks + mu * kn * tan_psi)
    rise = np.diff(r["normal_N"])[steady - 1]
    assert np.abs(rise - kn * tan_psi * du_p).max() <= 1e-12 * kn * tan_psi * du_p * 1e3
    assert np.allclose(np.diff(r["dilation_m"])[steady - 1], tan_psi * du_p, rtol=1e-9, atol=0)
    stored = 0.5 * kn * (overlap + r["dilation_m"]) ** 2 + 0.5 * r["shear_spring_N"] ** 2 / ks
    residual, scale = work_balance_residuals(r, overlap, closing, np.full(steps, du_s / dt), dt, kn, ks, stored)
    assert np.abs(residual).max() <= 1e-12 * scale
    # Associative (tan psi = mu): the slip's work all goes into the dilation, none is dissipated.
    a = blockdem.joint_point_history(kn=kn, ks=ks, mu=mu, tan_dilation=mu, dt=dt, overlap=overlap,
                                     normal_speed=closing, tangential_speed=np.full(steps, du_s / dt))
    assert a["sliding"].any()
    assert np.abs(a["friction_work_J"]).max() <= 1e-12 * np.abs(a["shear_N"] * du_s).max()


@pytest.mark.parametrize("order", range(1, 9))
def test_butterworth_magnitude_against_the_analog_formula(order):
    # Row "Butterworth sensor filter, orders 1 to 8": 1/sqrt(1 + (f/fc)^2n), 1e-3 for f < fs/20
    # (the bilinear transform's warping tan(pi f T) departs from pi f T above that), with the
    # C++ test's fc = 50 Hz at fs = 10 kHz. Over the whole band the digital magnitude is the
    # warped formula 1/sqrt(1 + (tan(pi f T) / tan(pi fc T))^2n), to round-off.
    fs, fc = 10000.0, 50.0
    f = np.linspace(0.0, fs / 20, 201)
    analog = 1.0 / np.sqrt(1.0 + (f / fc) ** (2 * order))
    assert np.abs(blockdem.butterworth_magnitude(fc, order, fs, f) - analog).max() <= 1e-3
    band = np.linspace(0.0, 0.49 * fs, 50)
    warped = np.tan(math.pi * band / fs) / math.tan(math.pi * fc / fs)
    assert np.allclose(blockdem.butterworth_magnitude(fc, order, fs, band), 1.0 / np.sqrt(1.0 + warped ** (2 * order)),
                       rtol=0, atol=1e-12)
    # The running channel has that magnitude: a steady sine at fc and 2 fc comes out scaled by
    # the formula (least-squares amplitude over the last 10 periods, after 3.8 s of transient;
    # 1e-3 as the row).
    t = np.arange(int(4.0 * fs)) / fs
    for freq in (fc, 2 * fc):
        y = blockdem.butterworth_filter(fc, order, fs, np.sin(2 * math.pi * freq * t))
        tail = t >= 4.0 - 10 / freq
        basis = np.column_stack([np.sin(2 * math.pi * freq * t[tail]), np.cos(2 * math.pi * freq * t[tail])])
        coefficients, *_ = np.linalg.lstsq(basis, y[tail], rcond=None)
        assert np.hypot(*coefficients) == pytest.approx(1.0 / math.sqrt(1.0 + (freq / fc) ** (2 * order)), abs=1e-3)
    with pytest.raises(ValueError):
        blockdem.butterworth_magnitude(fs, order, fs, f)


def exact_highest_omega(kn, ks, m, inertia, b, h):
    """sqrt of the largest eigenvalue of M^-1 K of a 2b x 2h block on two corner springs (each
    kn normal, ks shear) of a fixed base: x, y, rotation about the centroid, by numpy."""
    K = np.zeros((3, 3))
    for corner_x in (-b, b):
        # shear spring along x at (corner_x, -h): g = (1, 0, h); normal along y: g = (0, 1, corner_x)
        for k, g in ((ks, np.array([1.0, 0.0, h])), (kn, np.array([0.0, 1.0, corner_x]))):
            K += k * np.outer(g, g)
    M = np.diag([m, m, inertia])
    return math.sqrt(np.linalg.eigvals(np.linalg.solve(M, K)).real.max())


@pytest.mark.parametrize("width,height", [(0.4, 1.6), (1.0, 0.5), (0.6, 0.6)])
def test_stable_step_of_a_block_on_two_corners(width, height):
    # Row "stable step of a block on two corners (3 shapes)": exact eigenvalue of M^-1 K, 0.1 %.
    # Undamped, the limit the tool prints (summary's critical_dt_s, the highest mode's) is
    # 2 / omega; the dt it derives at dt_safety = 1 is at most that (rounded down to a whole
    # number of steps per output interval).
    kn, ks, mass = 1e8, 5e7, 100.0
    s = blockdem.Scenario.from_dict({
        "simulation": {"duration": 1.0, "dt_safety": 1.0, "gravity": 9.81, "output_interval": 0.5},
        "contact": {"kn": kn, "ks": ks, "mu": 0.8, "h_n": 0.0, "h_s": 0.0},
        "bodies": [
            {"name": "base", "kind": "fixed", "shape": "rectangle", "width": 4.0, "height": 0.2,
             "center": [0.0, -0.1], "density": 1000.0},
            {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": width, "height": height,
             "center": [0.0, 0.5 * height], "density": mass / (width * height)},
        ],
    })
    sim = blockdem.Simulation(s, history=False)
    inertia = mass * (width ** 2 + height ** 2) / 12.0
    exact_dt = 2.0 / exact_highest_omega(kn, ks, mass, inertia, 0.5 * width, 0.5 * height)
    assert sim.summary()["critical_dt_s"] == pytest.approx(exact_dt, rel=1e-3)
    assert sim.dt <= sim.summary()["critical_dt_s"]


def test_law_histories_refuse_bad_arguments():
    # Arrays of different lengths, a step that is not positive, a negative dilation.
    with pytest.raises(ValueError, match="same length"):
        blockdem.contact_point_history(kn=1.0, ks=1.0, mu=0.5, dt=1e-3, overlap=[1e-3, 1e-3], normal_speed=[0.0],
                                       tangential_speed=[0.0, 0.0])
    with pytest.raises(ValueError, match="dt"):
        blockdem.contact_point_history(kn=1.0, ks=1.0, mu=0.5, dt=0.0, overlap=[1e-3], normal_speed=[0.0],
                                       tangential_speed=[0.0])
    with pytest.raises(ValueError, match="tan_dilation"):
        blockdem.joint_point_history(kn=1.0, ks=1.0, mu=0.5, tan_dilation=-0.1, dt=1e-3, overlap=[1e-3],
                                     normal_speed=[0.0], tangential_speed=[0.0])
    with pytest.raises(ValueError):
        blockdem.butterworth_filter(10.0, 0, 1000.0, [0.0, 1.0])
