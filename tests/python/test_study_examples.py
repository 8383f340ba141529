"""The two studies of examples/python/, run in their --quick configurations (seconds each), with
what they must show asserted."""
import importlib.util
import math
import sys
import time

import numpy as np
import pytest

G = 9.81  # [m/s^2]


def run_example(source_dir, name, args):
    spec = importlib.util.spec_from_file_location(name, source_dir / "examples" / "python" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    saved = sys.argv
    sys.argv = [name, *args]
    try:
        started = time.perf_counter()
        result = module.main()
        return module, result, time.perf_counter() - started
    finally:
        sys.argv = saved


@pytest.mark.parametrize("motions", ["records", "synthetic"])
def test_fragility_of_the_drum_column(tmp_path, source_dir, motions):
    args = ["--quick", "--out", str(tmp_path), "--threads", "2"] + (["--synthetic"] if motions == "synthetic" else [])
    module, (table, theta_g, beta), wall_s = run_example(source_dir, "fragility_drum_column", args)
    completed = table["status"] == "completed"
    assert completed.all(), table["error"][~completed]
    _, failed = module.failures(table)
    pga_g = table["table_pga_m_s2"] / 9.80665
    # Statics: the column (0.6 m wide, 2.7 m tall) cannot lift off below g b / H = 0.222 g, nor
    # slide below mu g = 0.7 g; so no case fails at 0.15 g, and the median exceeds 0.222 g.
    assert not failed[np.isclose(pga_g, 0.15)].any()
    assert theta_g > 0.6 / 2.7
    assert failed.any(), "no failure even at 1 g: the study would fit nothing"
    assert failed[np.isclose(pga_g, 1.0)].mean() >= failed[np.isclose(pga_g, 0.3)].mean()
    assert 0.01 < beta < 2.0
    assert (tmp_path / "fragility.png").stat().st_size > 10000 and (tmp_path / "fragility.csv").exists()
    print(f"{motions}: theta {theta_g:.3f} g, beta {beta:.3f}, {int(failed.sum())}/{len(failed)} failed, {wall_s:.1f} s")
    assert wall_s < 60


def test_overturning_spectrum_against_housner(tmp_path, source_dir):
    _, (dem, housner, dem_step), wall_s = run_example(source_dir, "overturning_spectrum",
                                                      ["--quick", "--out", str(tmp_path), "--threads", "2"])
    for ratio in dem:
        # Each minimum on its own grid: the DEM's is found to one DEM step (0.125 g tan alpha),
        # so it must lie within a step of Housner's (0.02 step). The DEM contact is the one that
        # matched Housner's r within 0.001 (README, impact energy loss). Statics: at least 1.
        print(f"w/p = {ratio}: DEM {dem[ratio]}, Housner {housner[ratio]}")
        assert not math.isnan(dem[ratio]) and not math.isnan(housner[ratio])
        assert abs(dem[ratio] - housner[ratio]) <= dem_step
        assert dem[ratio] >= 1.0 and housner[ratio] >= 1.0
    # The spectrum rises with the pulse frequency (a short pulse must be stronger).
    ratios = sorted(housner)
    assert all(housner[a] < housner[b] for a, b in zip(ratios, ratios[1:]))
    assert (tmp_path / "overturning_spectrum.png").stat().st_size > 10000
    assert wall_s < 60
