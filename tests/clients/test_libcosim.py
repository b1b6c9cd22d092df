"""SlowDrift.fmu in libcosim (the Open Simulation Platform's co-simulation library, common in
maritime co-simulation) through libcosimpy 0.0.6.

The FMU runs 600 s at a 1 s step with non-default parameters (routes.PARAMETERS, set as
initial values) in a libcosim execution, observed by a time-series observer; X, Y, theta,
Xdot, Ydot and thetadot at every step, and all 16 outputs at the end (last-value observer),
must equal fmpy's run of the same FMU with the same parameters bit for bit.

How libcosim maps time: the execution works in integer nanoseconds (libcosimpy's step_size
and target_time are nanoseconds): a 1 s step is 1_000_000_000 ns. libcosim converts its time
points to double seconds for fmi2DoStep, so step k starts at exactly k.0 s with
communicationStepSize 1.0 (both exact in binary), and the FMU's own time check
(currentCommunicationPoint within 1e-9 of its time) never sees a rounding difference.

What libcosim does differently from fmpy, found here (outside our control, libcosim 0.0.6's
libcosimc):
- it calls fmi2SetupExperiment without a stop time: the run is open-ended (the FMU's
  records stream without end) and the records are the same as with one, so the fmpy
  reference sets its stop time. test_libcosim_two_days runs 48 h (past ten joins of the
  record stream) and compares every minute with fmpy's 48 h.
- it ignores Enumeration variables ("FMI 2.0 Enumeration variable type not supported,
  variable with name dragModel will be ignored"): SlowDrift therefore has none, its modes
  (dragModel, driftDamping, interaction) are Integers with their codes in the description.
  test_libcosim_variables checks that libcosim registers every variable, and
  test_libcosim_sets_the_modes that the modes set there take effect (a master that skipped
  them would leave the drag and the drift damping on).
- it unpacks the FMU under its temporary directory (the first of $TMPDIR, $TMP, $TEMP,
  $TEMPDIR that is set) and fails (libcosimpy then crashes on the NULL slave) when that
  directory does not exist, where Python's tempfile (fmpy) quietly falls back to /tmp.
  run_clients.sh therefore gives the masters a TMPDIR of its own under the target directory.
- libcosimpy's time_series_real_samples trims its result by counting zero step numbers in
  the returned array, which also drops a real step 0; samples are therefore read from
  step 1 (the state after the first step) on.
"""

import numpy as np
import pytest

from routes import OUTPUTS, PARAMETERS

STEP_NS = 1_000_000_000  # 1 s in libcosim's nanoseconds
N_STEPS = 600
OBSERVED = ("X", "Y", "theta", "Xdot", "Ydot", "thetadot")


def execution(fmu, md):
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimSlave import CosimLocalSlave
    from libcosimpy._internal import get_last_error_message

    log_output_level(CosimLogLevel.WARNING)
    ex = CosimExecution.from_step_size(step_size=STEP_NS)
    slave = CosimLocalSlave(fmu_path=fmu, instance_name="slowdrift")
    # libcosimpy passes a NULL slave on to add_local_slave, which then crashes the process:
    # check it here so that a failed import is a test failure with libcosim's reason.
    assert slave.ptr(), f"libcosim could not import the FMU: {get_last_error_message()}"
    index = ex.add_local_slave(local_slave=slave)
    assert index >= 0, "libcosim could not load the FMU"
    return ex, slave, index


def set_parameters(ex, index, vr, parameters=PARAMETERS):
    """parameters (routes.PARAMETERS) as the slave's initial values."""
    for name, value in parameters.items():
        v = vr[name]
        if v.type == "Real":
            assert ex.real_initial_value(index, v.valueReference, float(value)), name
        else:
            assert v.type == "Integer", name
            assert ex.integer_initial_value(index, v.valueReference, int(value)), name


def test_libcosim_variables(fmu, md):
    """libcosim registers every variable (it would skip an FMI 2.0 Enumeration: there is
    none), each with the type of the model description."""
    from libcosimpy.CosimEnums import CosimVariableType

    ex, _slave, index = execution(fmu, md)
    seen = {v.name.decode(): v for v in ex.slave_variables(index)}
    declared = {v.name: v for v in md.modelVariables}
    assert set(seen) == set(declared)
    for name, v in declared.items():
        assert seen[name].type == CosimVariableType[v.type.upper()].value, name
        assert seen[name].reference == v.valueReference, name


def test_libcosim_sets_the_modes(fmu, md):
    """The modes set as libcosim initial values take effect: dragModel 0 (off) and
    driftDamping 0 (off) make the drag and drift-damping outputs zero, where the start
    values (combined drag, Aranha damping) make them non-zero, and the run equals fmpy's
    with the same start values bit for bit."""
    from fmpy import simulate_fmu
    from libcosimpy.CosimObserver import CosimObserver

    modes = dict(PARAMETERS, dragModel=0, driftDamping=0, interaction=4)
    steps = 120
    vr = {v.name: v for v in md.modelVariables}
    ex, _slave, index = execution(fmu, md)
    set_parameters(ex, index, vr, modes)
    last = CosimObserver.create_last_value()
    assert ex.add_observer(observer=last)
    assert ex.simulate_until(target_time=steps * STEP_NS)
    final = np.array(last.last_real_values(index, [vr[n].valueReference for n in OUTPUTS]))
    reference = simulate_fmu(fmu, start_time=0.0, stop_time=float(steps), output_interval=1.0,
                             start_values=modes, output=list(OUTPUTS))
    assert np.array_equal(final, np.array([reference[n][-1] for n in OUTPUTS]))
    off = [OUTPUTS.index(n) for n in OUTPUTS if n.endswith(("_drag", "_damping"))]
    assert np.all(final[off] == 0.0)
    on = simulate_fmu(fmu, start_time=0.0, stop_time=float(steps), output_interval=1.0,
                      start_values=PARAMETERS, output=["Fx_drag", "Fx_damping"])
    assert on["Fx_drag"][-1] != 0.0 and on["Fx_damping"][-1] != 0.0


def test_libcosim_run_equals_fmpy(fmu, md):
    from fmpy import simulate_fmu
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimObserver import CosimObserver

    vr = {v.name: v for v in md.modelVariables}
    ex, _slave, index = execution(fmu, md)
    set_parameters(ex, index, vr)
    series = CosimObserver.create_time_series()
    last = CosimObserver.create_last_value()
    assert ex.add_observer(observer=series)
    assert ex.add_observer(observer=last)
    for name in OBSERVED:
        assert series.start_time_series(index, vr[name].valueReference, CosimVariableType.REAL)

    assert ex.simulate_until(target_time=N_STEPS * STEP_NS)
    status = ex.status()
    assert status.current_time == N_STEPS * STEP_NS
    assert status.error_code == 0

    reference = simulate_fmu(fmu, start_time=0.0, stop_time=float(N_STEPS), output_interval=1.0,
                             start_values=PARAMETERS, output=list(OUTPUTS))
    assert np.array_equal(reference["time"], np.arange(N_STEPS + 1, dtype=float))

    for name in OBSERVED:
        times, steps, values = series.time_series_real_samples(
            index, vr[name].valueReference, from_step=1, sample_count=N_STEPS)
        assert list(steps) == list(range(1, N_STEPS + 1)), name
        assert list(times) == [k * STEP_NS for k in range(1, N_STEPS + 1)], name
        assert np.array_equal(np.array(values), reference[name][1:]), (
            f"{name}: max |libcosim - fmpy| = "
            f"{np.max(np.abs(np.array(values) - reference[name][1:])):.3e}")

    final = last.last_real_values(index, [vr[n].valueReference for n in OUTPUTS])
    assert np.array_equal(np.array(final), np.array([reference[n][-1] for n in OUTPUTS]))
    # A real run: the oblique sea moved the platform in all three DOF.
    for name in ("X", "Y", "theta"):
        assert np.max(np.abs(reference[name])) > 0.0, name


def test_libcosim_two_days(fmu, md):
    """48 h in libcosim (no stop time, 172800 steps of 1 s) equal fmpy's 48 h with a stop
    time, sampled every minute, bit for bit."""
    from fmpy import simulate_fmu
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimObserver import CosimObserver

    steps = 48 * 3600
    vr = {v.name: v for v in md.modelVariables}
    ex, _slave, index = execution(fmu, md)
    set_parameters(ex, index, vr)
    series = CosimObserver.create_time_series(buffer_size=steps + 1)
    assert ex.add_observer(observer=series)
    assert series.start_time_series(index, vr["X"].valueReference, CosimVariableType.REAL)
    assert ex.simulate_until(target_time=steps * STEP_NS)
    assert ex.status().error_code == 0

    reference = simulate_fmu(fmu, start_time=0.0, stop_time=float(steps), output_interval=60.0,
                             start_values=PARAMETERS, output=["X"])
    _times, numbers, values = series.time_series_real_samples(
        index, vr["X"].valueReference, from_step=1, sample_count=steps)
    assert list(numbers[59::60]) == list(range(60, steps + 1, 60))
    assert np.array_equal(np.array(values)[59::60], reference["X"][1:])
    assert np.max(np.abs(reference["X"][reference["time"] > 16384.0])) > 0.0


LOG_SCRIPT = """
import sys
from libcosimpy.CosimExecution import CosimExecution
from libcosimpy.CosimSlave import CosimLocalSlave
ex = CosimExecution.from_step_size(step_size={step})
slave = CosimLocalSlave(fmu_path=sys.argv[1], instance_name="slowdrift")
index = ex.add_local_slave(local_slave=slave)
assert index >= 0
assert ex.simulate_until(target_time={steps} * {step})
print("simulated", flush=True)
"""


def test_libcosim_default_log_level_is_not_flooded(fmu):
    """Under libcosim's default log level (no log_output_level call) a run writes the FMU's
    events and nothing per step: libcosim instantiates with loggingOn and writes every line
    the FMU sends, so the per-call trace (logAll) stays off unless a master names it in
    fmi2SetDebugLogging. 600 steps: before, a line a step at least (fmi2DoStep: ok); now the
    events only (initialised, terminated)."""
    import subprocess
    import sys

    script = LOG_SCRIPT.format(step=STEP_NS, steps=N_STEPS)
    run = subprocess.run([sys.executable, "-c", script, fmu], capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    assert "simulated" in run.stdout
    # libcosim writes each line the FMU sends as "[FMI status=ok, category=logAll] ...".
    lines = (run.stdout + run.stderr).splitlines()
    fmu_lines = [line for line in lines if "[FMI status=" in line]
    assert 0 < len(fmu_lines) < 30, "\n".join(fmu_lines[:40])
    assert not any("category=logAll" in line for line in fmu_lines)
