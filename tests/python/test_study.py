"""blockdem.sweep and the analysis helpers (python/bind_study.cpp, bind_analysis.cpp, study.py):
the same table as `blockdem sweep`, the references against their closed forms, errors."""
import csv
import math
import os
import subprocess
import threading

import numpy as np
import pytest

import blockdem

G = 9.81  # [m/s^2]
RECORDS = "shared/data/ground-motions/peer-at2"


def cli(source_dir):
    path = os.environ.get("BLOCKDEM_CLI", str(source_dir / "build/blockdem"))
    if not os.path.exists(path):
        pytest.skip("the blockdem executable is not built")
    return path


def records_dir(source_dir):
    folder = source_dir.parent / RECORDS
    if not folder.is_dir():
        pytest.skip("../shared/data/ground-motions is not beside the repository")
    return folder


def test_sweep_gives_the_clis_results_table(tmp_path, source_dir):
    # The same plan through `blockdem sweep` and blockdem.sweep: every column of results.csv
    # equal (the rows are format_row's in both), wall_time_s aside.
    scenario = source_dir / "studies/scenarios/pulse_block.toml"
    vary = ["table_motion.horizontal.amplitude=3:6:1.5", "table_motion.horizontal.period=0.5,1"]
    subprocess.run([cli(source_dir), "sweep", str(scenario), "--out", str(tmp_path), "-q", "--threads", "2",
                    *sum((["--vary", v] for v in vary), [])], check=True, stdout=subprocess.DEVNULL)
    with open(tmp_path / "results.csv") as f:
        rows = list(csv.DictReader(f))
    table = blockdem.sweep(blockdem.Scenario.from_file(scenario),
                           vary={"table_motion.horizontal.amplitude": "3:6:1.5", "table_motion.horizontal.period": [0.5, 1]},
                           threads=2)
    assert list(table)[:-1] == list(rows[0]) and table["bodies"] == ["block"]
    assert len(table["case_id"]) == len(rows) == 6
    for name in rows[0]:
        if name == "wall_time_s":
            continue
        for i, row in enumerate(rows):
            value = table[name][i]
            if isinstance(value, (bool, np.bool_)):
                assert value == (row[name] == "1"), name
            elif isinstance(value, str):
                assert value == row[name], name
            elif row[name] == "":
                assert math.isnan(value), name
            else:
                assert value == float(row[name]), name
    assert table["block.overturned"].any() and not table["block.overturned"].all()


def test_sweep_case_list_records_and_levels(source_dir):
    folder = records_dir(source_dir)
    files = [folder / "IELC180.AT2", folder / "ARL360.at2"]
    table = blockdem.sweep(source_dir / "studies/scenarios/sine_block.toml", records=files, target_pga=[0.1, 0.3],
                           target_pga_unit="g", record_keys={"duration": 2}, threads=2)
    assert list(table["record"]) == ["IELC180.AT2", "IELC180.AT2", "ARL360.at2", "ARL360.at2"]
    assert list(table["target_pga_g"]) == [0.1, 0.3, 0.1, 0.3]
    # The record scaled to its target: the table's peak is the target (10 significant digits).
    np.testing.assert_allclose(table["table_pga_m_s2"], np.array([0.1, 0.3, 0.1, 0.3]) * 9.80665, rtol=1e-9)


def test_sweep_bad_cases_are_rows_and_bad_plans_raise(source_dir):
    scenario = source_dir / "studies/scenarios/pulse_block.toml"
    table = blockdem.sweep(scenario, cases=[{"contact.mu": 0.5, "simulation.duration": 0.1},
                                            {"contact.mu": -1, "simulation.duration": 0.1}], threads=1)
    assert list(table["status"]) == ["completed", "error"]
    assert "mu" in table["error"][1]
    with pytest.raises(ValueError, match="solver"):
        blockdem.sweep(scenario, vary={"contact.mu": [0.5]}, solver="opensees")
    with pytest.raises(ValueError, match="target-pga-unit"):
        blockdem.sweep(scenario, records=[scenario], target_pga=[0.1])
    with pytest.raises(ValueError, match="same keys"):
        blockdem.sweep(scenario, cases=[{"contact.mu": 0.5}, {"contact.kn": 1e9}])
    with pytest.raises(TypeError, match="cannot be a scenario value"):
        blockdem.sweep(scenario, vary={"contact.mu": [None]})
    # As the CLI's --threads (0 here: every core); 1e9 would start 1e9 threads.
    for threads in (10**9, -1):
        with pytest.raises(ValueError, match=f"threads must be 0 \\(all cores\\) or 1 to 4096, got {threads}"):
            blockdem.sweep(scenario, vary={"contact.mu": [0.5]}, threads=threads)


def test_the_gil_is_released_during_a_sweep(source_dir):
    scenario = blockdem.Scenario.from_file(source_dir / "studies/scenarios/pulse_block.toml")
    worker = threading.Thread(target=blockdem.sweep, args=(scenario,),
                              kwargs={"vary": {"table_motion.horizontal.amplitude": [2.0, 2.5]}, "threads": 1})
    ticks = 0
    worker.start()
    while worker.is_alive():
        ticks += 1
    worker.join()
    assert ticks > 1000  # this thread ran while the cases ran


def test_housner_rocking_quarter_cycle_and_energy():
    # Free rocking from theta0 = alpha/2 at rest. Closed form of the linearised equation
    # (Housner 1963): the block reaches theta = 0 at t = arccosh(1 / (1 - theta0/alpha)) / p.
    # Tolerance 2%: the solver integrates the full (nonlinear) equation, whose sin and cos
    # differ from the linear terms by about alpha^2 / 6 = 1% for alpha = 0.245 rad.
    r = blockdem.housner_rocking(0.2, 0.8, blockdem.Motion.rest(), end=3.0, dt=1e-4, theta0=0.1225)
    alpha, p = r["alpha"], r["p"]
    assert alpha == pytest.approx(math.atan(0.25), rel=1e-15)
    assert p == pytest.approx(math.sqrt(3 * G / (4 * math.hypot(0.2, 0.8))), rel=1e-15)
    assert r["impact_times"][0] == pytest.approx(math.acosh(1 / (1 - 0.1225 / alpha)) / p, rel=0.02)
    # Between impacts the energy m g R (cos(alpha - |theta|) - cos alpha) + I omega^2 / 2 is kept
    # (RK4 at dt = 1e-4: 1e-6 relative).
    first = r["t"] < r["impact_times"][0]
    R, theta, omega = math.hypot(0.2, 0.8), r["theta"][first], r["omega"][first]
    energy = G * R * (np.cos(alpha - np.abs(theta)) - math.cos(alpha)) + (2.0 / 3.0) * R ** 2 * omega ** 2
    np.testing.assert_allclose(energy, energy[0], rtol=1e-6)
    assert r["restitution"] == pytest.approx(1 - 1.5 * math.sin(alpha) ** 2)
    # Below g tan(alpha) the block does not lift off (statics).
    still = blockdem.housner_rocking(0.2, 0.8, blockdem.Motion.one_sine(0.95 * G * 0.25, 1.0), end=2.0)
    assert still["peak_theta"] == 0.0 and not still["overturned"]


def test_rigid_plastic_sliding_under_constant_acceleration():
    # A table accelerating at a = 5 m/s^2 > mu g = 2.943 from t = 0: the block lags by
    # (a - mu g) t^2 / 2. The integrator's first step starts the slip half a step late (the jump
    # of a at t = 0 is seen at the step's end), so the error is a dt t / 2, first order in dt.
    a, mu = 5.0, 0.3
    for dt in (1e-3, 1e-4):
        r = blockdem.rigid_plastic_sliding(blockdem.Motion.series(np.full(201, a), 0.01), mu, end=1.0, dt=dt)
        error = np.abs(r["displacement"] + (a - mu * G) * r["t"] ** 2 / 2)
        assert (error <= a * dt * r["t"] / 2 * (1 + 1e-6) + 1e-15).all()
        assert error[-1] > 0.99 * a * dt / 2  # the bound is the error, not a loose cap
    # On an incline steeper than atan(mu), a still table: g (sin - mu cos) down the slope.
    slope = math.radians(30)
    r = blockdem.rigid_plastic_sliding(blockdem.Motion.rest(), 0.5, end=0.5, dt=1e-3, slope=slope)
    expected = -G * (math.sin(slope) - 0.5 * math.cos(slope)) * 0.5 ** 2 / 2
    assert r["displacement"][-1] == pytest.approx(expected, rel=1e-9)


def test_response_spectrum_and_intensity_measures_of_a_sine():
    # a = A sin(w t) for 60 whole periods of 0.5 s.
    A, T, dt = 2.0, 0.5, 0.005
    t = np.arange(0, 60 * T + dt / 2, dt)
    a = A * np.sin(2 * math.pi * t / T)
    im = blockdem.intensity_measures(a, dt)
    w = 2 * math.pi / T
    assert im["pga"] == pytest.approx(A, rel=1e-12)
    assert im["pgv"] == pytest.approx(2 * A / w, rel=1e-3)   # v = (A/w)(1 - cos w t); trapezoid rule
    assert im["arias"] == pytest.approx(math.pi / (2 * 9.80665) * A ** 2 / 2 * t[-1], rel=1e-3)
    # Resonance, 5% damping: the steady amplitude A / (2 zeta wn^2); the start-up has decayed by
    # exp(-zeta wn 60 T) = 7e-9. Tolerance 0.5%: the start-up's beat over the first periods.
    s = blockdem.response_spectrum(a, dt, periods=[T, 0.001], damping=0.05)
    assert s["sd"][0] == pytest.approx(A / (2 * 0.05 * w ** 2), rel=5e-3)
    assert s["psa"][1] == pytest.approx(A, rel=1e-3)   # a rigid oscillator follows the ground
    k = blockdem.integrate_record(a, dt)
    assert k["velocity"][-1] == pytest.approx(0.0, abs=1e-9)


def test_records_read_and_processed(source_dir):
    folder = records_dir(source_dir)
    rec = blockdem.read_record(folder / "IELC180.AT2")
    # The data set's README: 4000 samples at 0.01 s, PGA 0.3129 g at 2.150 s.
    assert len(rec["accelerations"]) == 4000 and rec["dt"] == 0.01 and rec["format"] == "peer-at2"
    im = blockdem.intensity_measures(rec["accelerations"], rec["dt"])
    assert im["pga"] / 9.80665 == pytest.approx(0.3129, abs=5e-5) and im["pga_time"] == pytest.approx(2.15)
    scaled = blockdem.process_record(rec["accelerations"], rec["dt"], duration=15, taper=0.5, baseline="polynomial",
                                     target_pga=0.5 * 9.80665)
    assert np.abs(scaled).max() == pytest.approx(0.5 * 9.80665, rel=1e-12)
    k = blockdem.integrate_record(scaled, rec["dt"])
    assert abs(k["velocity"][-1]) < 1e-9 and abs(k["displacement"][-1]) < 1e-9  # the table ends at rest
    with pytest.raises(blockdem.InputError) as e:
        blockdem.read_record(source_dir / "README.md")
    assert e.value.file is not None


def test_analysis_argument_errors():
    with pytest.raises(ValueError, match="sample 2 is not finite"):
        blockdem.intensity_measures(np.array([0.0, 1.0, np.nan]), 0.01)
    with pytest.raises(ValueError, match="1-D"):
        blockdem.response_spectrum(np.zeros((3, 2)), 0.01)
    with pytest.raises(ValueError, match="dt must be positive"):
        blockdem.Motion.series(np.zeros(4), 0.0)
    with pytest.raises(ValueError, match="period"):
        blockdem.Motion.one_sine(1.0, -1.0)
    with pytest.raises(ValueError, match="baseline"):
        blockdem.process_record(np.zeros(10), 0.01, baseline="cubic")
    with pytest.raises(TypeError):
        blockdem.housner_rocking("wide", 0.8, blockdem.Motion.rest(), end=1.0)
    assert "one-sine pulse" in repr(blockdem.Motion.one_sine(3.0, 1.0))


def test_studies_and_helpers_do_not_leak(source_dir):
    # 1e4 calls of each kind of helper and 300 small sweeps (600 cases) after a warm-up: the
    # resident set grows by less than 2 MiB (allocator pools settle in the warm-up).
    scenario = blockdem.Scenario.from_file(source_dir / "studies/scenarios/pulse_block.toml")
    a = np.sin(np.arange(200) * 0.05)

    def rss_kb():
        with open("/proc/self/status") as f:
            return next(int(line.split()[1]) for line in f if line.startswith("VmRSS"))

    def work(n, sweeps):
        for _ in range(n):
            blockdem.housner_rocking(0.2, 0.8, blockdem.Motion.one_sine(3.0, 1.0), end=0.02, dt=1e-3)
            blockdem.intensity_measures(a, 0.01)
            blockdem.response_spectrum(a, 0.01, periods=[0.5])
        for _ in range(sweeps):
            blockdem.sweep(scenario, vary={"simulation.duration": [1e-3, 2e-3]}, solver="housner", threads=1)

    work(1000, 30)
    before = rss_kb()
    work(10000, 300)
    assert rss_kb() - before < 2048, "memory grew by more than 2 MiB"
