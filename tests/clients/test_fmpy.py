"""SlowDrift.fmu through fmpy 0.3.32, an independent FMI 2.0 master.

1. fmpy.validate_fmu finds no problem (and does find one in a deliberately broken copy).
2. fmpy.simulate_fmu with start values, an input signal (ramp and constants on Fx_ext,
   Fy_ext, Mz_ext) and output intervals 1 s, 2 s and 0.5 s runs to the stop time with every
   output present and finite; a constant Fy_ext shifts the mean sway by about F / k22.
3. simulate_fmu with zero external force equals the native CLI (`slowdrift simulate`, an
   independent route: no FMI layer, its own TOML reader, CSV at 17 significant digits) for the
   same parameters, seed and duration, sample by sample, bit for bit: every output at every
   time. Interval 2 s with stepSize 1 s compares every second native sample (the FMU splits a
   communication step into whole RK4 steps); interval 0.5 s uses stepSize 0.5 s against a
   native run at h = 0.5 s.
4. Three FMU2Slave instances in threads (seeds 1, 2, 3), then seed 5 twice: equal seeds give
   identical arrays, different seeds different arrays, and every threaded run equals the same
   run done alone.
5. getFMUstate / setFMUstate: roll back and re-step gives identical outputs;
   serializeFMUstate / deSerializeFMUstate into a fresh instance continues identically.
6. fmi2Reset reproduces the first run.
7. An open-ended run: 48 h without a stop time (set_stop_time=False) runs past ten joins of
   the record stream and equals, bit for bit, the same 48 h with the stop time set (the
   records do not depend on the run's duration).
"""

import concurrent.futures
import os
import shutil
import tempfile
import zipfile

import numpy as np
import pytest

from routes import INPUTS, OUTPUTS, PARAMETERS, Slave, run_native

STOP = 1800.0  # s: 30 min runs, long enough for several 200 s surge periods


@pytest.fixture(scope="module")
def workdir():
    d = tempfile.mkdtemp(prefix="slowdrift-fmpy-")
    yield d
    shutil.rmtree(d, ignore_errors=True)


# ------------------------------------------------------------------------------ validation

def test_validate_fmu(fmu):
    from fmpy.validation import validate_fmu

    problems = validate_fmu(fmu)
    assert problems == [], "\n".join(problems)


def test_every_real_has_its_unit(md):
    """fmpy reads a variable's unit from its own attribute only, as OMSimulator does (neither
    inherits it from a declaredType): every Real must carry it, and the coupling variables
    are in SI units and radians."""
    defined = {u.name for u in md.unitDefinitions}
    reals = [v for v in md.modelVariables if v.type == "Real"]
    missing = [v.name for v in reals if v.unit is None]
    assert missing == [], f"Reals without their own unit: {missing}"
    assert all(v.unit in defined for v in reals)
    units = {v.name: v.unit for v in reals}
    expected = {"X": "m", "Y": "m", "theta": "rad", "Xdot": "m/s", "Ydot": "m/s",
                "thetadot": "rad/s", "Fx_ext": "N", "Fy_ext": "N", "Mz_ext": "N.m",
                "waveDirection": "rad", "stiffnessSurge": "N/m", "stiffnessYaw": "N.m/rad"}
    assert {n: units[n] for n in expected} == expected
    assert not any(v.type == "Enumeration" for v in md.modelVariables)


def test_validate_fmu_sees_a_broken_copy(fmu, workdir):
    """Control: the same call reports a problem in a copy whose first Real has an attribute
    the FMI 2.0 schema does not allow (so an empty list above means something)."""
    from fmpy.validation import validate_fmu

    broken = os.path.join(workdir, "broken.fmu")
    with zipfile.ZipFile(fmu) as src, zipfile.ZipFile(broken, "w") as dst:
        for item in src.infolist():
            data = src.read(item.filename)
            if item.filename == "modelDescription.xml":
                data = data.replace(b'start="7"/>', b'start="7" bogus="1"/>', 1)
            dst.writestr(item, data)
    problems = validate_fmu(broken)
    assert any("bogus" in p for p in problems), problems


# ------------------------------------------------------------------------- simulate_fmu

def input_signal(stop, fx_end=2.0e5, fy=1.0e5, mz=5.0e7):
    """Fx_ext ramps 0 -> fx_end over the run; Fy_ext and Mz_ext are constant."""
    t = np.array([0.0, stop])
    sig = np.zeros(2, dtype=[("time", np.float64)] + [(n, np.float64) for n in INPUTS])
    sig["time"] = t
    sig["Fx_ext"] = [0.0, fx_end]
    sig["Fy_ext"] = fy
    sig["Mz_ext"] = mz
    return sig


def simulate(fmu, interval, start_values, signal, stop=STOP, **kw):
    from fmpy import simulate_fmu

    return simulate_fmu(fmu, start_time=0.0, stop_time=stop, output_interval=interval,
                        start_values=start_values, input=signal, output=list(OUTPUTS), **kw)


@pytest.mark.parametrize("interval", [1.0, 2.0, 0.5])
def test_simulate_fmu_with_inputs(fmu, interval):
    start = dict(PARAMETERS, stepSize=min(1.0, interval))
    res = simulate(fmu, interval, start, input_signal(STOP))
    n = int(round(STOP / interval))
    assert len(res) == n + 1
    assert res["time"][-1] == STOP
    assert np.array_equal(res["time"], np.arange(n + 1) * interval)
    for name in OUTPUTS:
        assert name in res.dtype.names
        assert np.all(np.isfinite(res[name])), name
    # The oblique sea moves all three DOF.
    for name in ("X", "Y", "theta"):
        assert np.max(np.abs(res[name])) > 0.0, name


def test_open_ended_run_equals_the_bounded_one(fmu):
    hours = 48.0
    stop = hours * 3600.0
    zero = np.zeros(2, dtype=[("time", np.float64)] + [(n, np.float64) for n in INPUTS])
    zero["time"] = [0.0, stop]
    # Output every 60 s: each communication step is 60 whole RK4 steps of 1 s.
    bounded = simulate(fmu, 60.0, dict(PARAMETERS), zero, stop=stop)
    open_ended = simulate(fmu, 60.0, dict(PARAMETERS), zero, stop=stop, set_stop_time=False)
    assert open_ended["time"][-1] == stop
    for name in OUTPUTS:
        assert np.all(np.isfinite(open_ended[name])), name
        assert np.array_equal(open_ended[name], bounded[name]), name
    # The platform keeps moving after the first join (16384 s) as before it.
    late = open_ended["time"] > 16384.0
    for name in ("X", "Y", "theta"):
        early_std = np.std(open_ended[name][~late])
        late_std = np.std(open_ended[name][late])
        assert 0.3 < late_std / early_std < 3.0, (name, early_std, late_std)


def test_constant_sway_force_offsets_by_f_over_k(fmu):
    """Fy_ext = F held constant adds a mean sway F / k22 (static equilibrium of the linear
    mooring): the mean of Y(F) - Y(0) after ten sway periods, within 5 % (drag and drift
    damping are velocity-dependent, not position-dependent, so they do not move the mean;
    the slow transient decays with a few percent of critical damping)."""
    f = 1.8e5  # N: 1 m at k22 = 1.8e5 N/m
    start = dict(PARAMETERS)
    zero = np.zeros(2, dtype=[("time", np.float64)] + [(n, np.float64) for n in INPUTS])
    zero["time"] = [0.0, STOP]
    push = zero.copy()
    push["Fy_ext"] = f
    base = simulate(fmu, 1.0, start, zero)
    pushed = simulate(fmu, 1.0, start, push)
    late = base["time"] >= 900.0
    offset = np.mean(pushed["Y"][late] - base["Y"][late])
    expected = f / PARAMETERS["stiffnessSway"]
    print(f"\nmean sway offset {offset:.4f} m, F/k22 = {expected:.4f} m")
    assert abs(offset - expected) < 0.05 * expected


@pytest.fixture(scope="module")
def native(workdir):
    """Native CLI runs at h = 1 s and h = 0.5 s, same parameters and duration as the FMU."""
    return {h: run_native(workdir, PARAMETERS, STOP, h) for h in (1.0, 0.5)}


@pytest.mark.parametrize("interval,step", [(1.0, 1.0), (2.0, 1.0), (0.5, 0.5)])
def test_simulate_fmu_equals_native_cli(fmu, native, interval, step):
    start = dict(PARAMETERS, stepSize=step)
    zero = np.zeros(2, dtype=[("time", np.float64)] + [(n, np.float64) for n in INPUTS])
    zero["time"] = [0.0, STOP]
    res = simulate(fmu, interval, start, zero)
    t_native, y_native = native[step]
    every = int(round(interval / step))
    t_native, y_native = t_native[::every], y_native[::every]
    assert len(res) == len(t_native) == int(round(STOP / interval)) + 1
    assert np.array_equal(res["time"], t_native)
    fmu_out = np.column_stack([res[n] for n in OUTPUTS])
    for j, name in enumerate(OUTPUTS):
        diff = fmu_out[:, j] - y_native[:, j]
        scale = np.max(np.abs(y_native[:, j]))
        assert np.array_equal(fmu_out[:, j], y_native[:, j]), (
            f"{name}: max |FMU - native| = {np.max(np.abs(diff)):.3e} (max |native| {scale:.3e}) "
            f"at t = {res['time'][np.argmax(np.abs(diff))]}")
    # Not a trivially zero comparison: the oblique sea moves surge, sway and yaw.
    assert np.all(np.max(np.abs(y_native[:, :3]), axis=0) > 0.0)


# ------------------------------------------------------------------ several instances

def run_seed(fmu, md, unzipdir, seed, name, n=1200):
    with Slave(fmu, md, unzipdir, dict(PARAMETERS, seed=seed), name, stop_time=float(n)) as s:
        return s.run(0.0, n, 1.0)


def test_instances_in_threads(fmu, md, unzipdir):
    with concurrent.futures.ThreadPoolExecutor(max_workers=3) as pool:
        futures = [pool.submit(run_seed, fmu, md, unzipdir, seed, f"thread{seed}")
                   for seed in (1, 2, 3)]
        different = [f.result() for f in futures]
        futures = [pool.submit(run_seed, fmu, md, unzipdir, 5, f"same{i}") for i in range(2)]
        same = [f.result() for f in futures]
    for i in range(3):
        for j in range(i + 1, 3):
            assert not np.array_equal(different[i][:, 0], different[j][:, 0]), (i, j)
    assert np.array_equal(same[0], same[1])
    # Reproducible: each threaded run equals the same run alone, in this thread.
    for seed, rec in zip((1, 2, 3), different):
        assert np.array_equal(rec, run_seed(fmu, md, unzipdir, seed, f"alone{seed}")), seed
    assert np.array_equal(same[0], run_seed(fmu, md, unzipdir, 5, "alone5"))


# ------------------------------------------------------------- FMU state and reset

def test_get_set_and_serialized_state(fmu, md, unzipdir):
    stop = 1200.0
    with Slave(fmu, md, unzipdir, PARAMETERS, "original", stop_time=stop) as a:
        a.run(0.0, 600, 1.0, force=(3.0e4, -2.0e4, 1.0e7))
        state = a.fmu.getFMUstate()
        serialized = a.fmu.serializeFMUstate(state)
        first = a.run(600.0, 600, 1.0, force=(-1.0e4, 5.0e4, 0.0))
        a.fmu.setFMUstate(state)
        again = a.run(600.0, 600, 1.0, force=(-1.0e4, 5.0e4, 0.0))
        a.fmu.freeFMUstate(state)
    assert np.array_equal(first, again)

    with Slave(fmu, md, unzipdir, PARAMETERS, "fresh", stop_time=stop) as b:
        restored = b.fmu.deSerializeFMUstate(serialized)
        b.fmu.setFMUstate(restored)
        b.fmu.freeFMUstate(restored)
        continued = b.run(600.0, 600, 1.0, force=(-1.0e4, 5.0e4, 0.0))
    assert np.array_equal(first, continued)
    assert np.max(np.abs(first[:, 0])) > 0.0


def test_reset_reproduces_first_run(fmu, md, unzipdir):
    forces = (2.0e4, 1.0e4, -5.0e6)
    with Slave(fmu, md, unzipdir, PARAMETERS, "reset", stop_time=900.0) as s:
        initial = s.outputs()
        first = s.run(0.0, 900, 1.0, force=forces)
        s.fmu.reset()
        # Reset restores the start values: parameters and inputs are set again.
        s.initialise()
        assert np.array_equal(s.outputs(), initial)
        second = s.run(0.0, 900, 1.0, force=forces)
    assert np.array_equal(first, second)
