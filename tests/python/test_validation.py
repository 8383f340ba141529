"""README validation rows reproduced through Python: the module steps the same world as the CLI,
so the same tolerances hold. The references are computed here, independently of blockdem."""
import math

import numpy as np
import pytest

import blockdem


def newmark_relative_slip(amplitude_m_s2, mu, g, times_s, dt_s=1e-5):
    """Rigid-plastic block on a table shaken by a = A cos(2 pi t) (Newmark 1965): the block's
    displacement relative to the table at each of times_s, by explicit integration with the
    sticking instants found where the relative velocity changes sign."""
    capacity = mu * g
    v = u = t = 0.0
    out = []
    for end in times_s:
        while t < end - 0.5 * dt_s:
            a_table = amplitude_m_s2 * math.cos(2 * math.pi * t)
            if v == 0.0 and abs(a_table) <= capacity:
                a_rel = 0.0
            else:
                direction = math.copysign(1.0, v) if v != 0.0 else -math.copysign(1.0, a_table)
                a_rel = -a_table - capacity * direction
            v_new = v + a_rel * dt_s
            if v != 0.0 and v_new * v < 0.0:  # sticks within the step
                u += 0.5 * v * (v / -a_rel)
                v_new = 0.0
            else:
                u += 0.5 * (v + v_new) * dt_s
            v = v_new
            t += dt_s
        out.append(u)
    return out


def test_sliding_block_residual_slip_matches_newmark(source_dir):
    # README row "residual slip after 1 and 5 cycles": the paper's Fig. 5 block (mu = 0.3,
    # 350 gal cos(2 pi t), h_s = 1). Tolerance 2% + u_e, u_e = mu m g / (2 ks) = 74 um: the DEM
    # block rides on shear springs (tests/validation/test_sliding.cpp gives the reasons).
    scenario = blockdem.Scenario.from_file(source_dir / "examples/paper/sliding.toml")
    sim = blockdem.Simulation(scenario, history=False)
    block, table = sim.body_id("block"), sim.body_id("table")
    start = sim.positions.copy()
    slip = []

    def relative(s):
        d = s.positions - start
        slip.append(d[block, 0] - d[table, 0])

    sim.run(until=1.0, callback=relative, every=1.0)
    sim.run(until=5.0, callback=relative, every=4.0)
    reference = newmark_relative_slip(3.5, 0.3, 9.81, [1.0, 5.0])
    u_e = 0.3 * 1.0 * 9.81 / (2 * 2.0e4)
    print(f"slip after 1 and 5 cycles: DEM {slip}, Newmark {reference} m")
    for dem, ref in zip(slip, reference):
        assert dem == pytest.approx(ref, abs=0.02 * abs(ref) + u_e)


def test_rocking_impact_loses_housners_share():
    # README row "impact energy loss": a 0.4 x 1.6 m block released from alpha/2 about its left
    # corner; Housner's r = 1 - 1.5 sin^2 alpha = 0.9118, tolerance 0.005 (the DEM heel's
    # dashpot, e = 0.2, resolves the impact; tests/validation/test_rocking.cpp).
    b, h, g = 0.2, 0.8, 9.81
    alpha = math.atan(b / h)
    theta0 = alpha / 2
    # Centre of a block tilted by theta0 about its left corner (-b, 0).
    cx = -b + b * math.cos(theta0) - h * math.sin(theta0)
    cy = b * math.sin(theta0) + h * math.cos(theta0)
    scenario = blockdem.Scenario.from_dict({
        "simulation": {"duration": 1.6, "dt": 2e-5, "gravity": g, "output_interval": 2e-4},
        "contact": {"kn": 1e9, "ks": 1e9, "mu": 2.0, "e": 0.2, "e_meaning": "paper", "h_s": 1.0},
        "bodies": [
            {"name": "table", "kind": "driven", "shape": "rectangle", "width": 4.0, "height": 0.2,
             "center": [0.0, -0.1], "density": 1536.0},
            {"name": "block", "kind": "dynamic", "shape": "rectangle", "width": 2 * b, "height": 2 * h,
             "center": [cx, cy], "rotation": theta0, "density": 1536.0},
        ],
    })
    sim = blockdem.Simulation(scenario)
    sim.run()
    history = sim.history()
    rotation = theta0 + history["rot"][:, history["bodies"].index("block")]
    peaks = [rotation[i] for i in range(1, len(rotation) - 1)
             if abs(rotation[i]) > 1e-4 and abs(rotation[i]) >= abs(rotation[i - 1]) and abs(rotation[i]) > abs(rotation[i + 1])]
    assert len(peaks) >= 2 and peaks[0] * peaks[1] < 0  # one impact between them
    # Housner's energy between impacts turns two peaks into the velocity ratio of the impact.
    ratio = math.sqrt((math.cos(alpha - abs(peaks[1])) - math.cos(alpha)) /
                      (math.cos(alpha - abs(peaks[0])) - math.cos(alpha)))
    print(f"impact ratio {ratio:.4f}, Housner {1 - 1.5 * math.sin(alpha) ** 2:.4f}")
    assert ratio == pytest.approx(1 - 1.5 * math.sin(alpha) ** 2, abs=0.005)
