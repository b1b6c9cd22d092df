"""The coupled system (target/fmu/system/) run by co-simulation masters:
libcosim (libcosimpy) on OspSystemStructure.xml, ecos (ecospy) and fmpy on
MooredPlatform.ssp. Each runner returns a Run:

- states: (n, 6) X, Y, theta, Xdot, Ydot, thetadot of SlowDrift at t_1 .. t_n;
- forces: (n, 3) Fx_ext, Fy_ext, Mz_ext that SlowDrift held over its step k, from t_(k-1)
  to t_k (k = 1 .. n);
- stiffness: SlowDrift's stiffnessSurge, stiffnessSway, stiffnessYaw as the master reports
  them after initialisation (None where the master cannot tell).

Each master is called as a user calls it, with no parameter set named: the system's
SlowDrift.fmu has no internal mooring by construction (fmu-pack packs it from the default
configuration with zero stiffness), so nothing depends on a binding a master may skip.
Where each master shows these values, and how its time stamps line up, is documented in
each runner; test_system_masters.py compares the runs with the fmpy-glue loop.
"""

import os
from dataclasses import dataclass

import numpy as np

from mooring_loop import COLUMNS, INPUT_NAMES, LINES_ONLY, RATE_NAMES, STATE_NAMES
from system_files import SSP_FILE

STEP_NS = 1_000_000_000  # 1 s in libcosim's nanoseconds
OBSERVED = STATE_NAMES + RATE_NAMES
STIFFNESS = tuple(LINES_ONLY)


@dataclass
class Run:
    states: np.ndarray
    forces: np.ndarray
    stiffness: tuple = None

    @classmethod
    def from_record(cls, rec):
        """From a mooring_loop record (row n: state at t_n, force held over the step from t_n)."""
        state = [COLUMNS.index(n) for n in OBSERVED]
        force = [COLUMNS.index(n) for n in ("Fx", "Fy", "Mz")]
        return cls(rec[1:, state], rec[:-1, force])

    def record(self):
        """As a mooring_loop record (the platform at rest at the origin at t_0, as SlowDrift
        starts; the last row's force repeats the one before), for mean_offset.check."""
        n = len(self.states)
        rec = np.zeros((n + 1, len(COLUMNS)))
        rec[:, 0] = np.arange(n + 1, dtype=float)
        rec[1:, 1:7] = self.states
        rec[:-1, 7:10] = self.forces
        rec[-1, 7:10] = self.forces[-1]
        return rec


def libcosim(system, steps):
    """libcosim runs system/OspSystemStructure.xml (CosimExecution.from_osp_config_file): it
    reads the initial values and the variable-group connections (the OSP model descriptions
    beside the FMUs), and steps at its BaseStepSize, 1 s. A time-series observer gives the
    values after each step from step 1 on (libcosimpy drops step 0); an input's value at step
    k is the one it held during step k (libcosim sets inputs before a step), so the observed
    Fx_ext are the held forces. The stiffness parameters are read with a last-value
    observer after the run."""
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver

    log_output_level(CosimLogLevel.WARNING)
    ex = CosimExecution.from_osp_config_file(osp_path=system)
    index = {s.name.decode(): s.index for s in ex.slave_infos()}
    assert sorted(index) == ["mooring", "slowdrift"], index
    sd = index["slowdrift"]
    vr = {v.name.decode(): v.reference for v in ex.slave_variables(sd)}
    series = CosimObserver.create_time_series(buffer_size=steps + 1)
    last = CosimObserver.create_last_value()
    assert ex.add_observer(observer=series) and ex.add_observer(observer=last)
    for name in OBSERVED + INPUT_NAMES:
        assert series.start_time_series(sd, vr[name], CosimVariableType.REAL), name
    assert ex.simulate_until(target_time=steps * STEP_NS)
    assert ex.status().error_code == 0

    def samples(name):
        _t, numbers, values = series.time_series_real_samples(sd, vr[name], from_step=1,
                                                             sample_count=steps)
        assert list(numbers) == list(range(1, steps + 1)), name
        return np.array(values)

    states = np.column_stack([samples(n) for n in OBSERVED])
    forces = np.column_stack([samples(n) for n in INPUT_NAMES])
    stiffness = tuple(last.last_real_values(sd, [vr[n] for n in STIFFNESS]))
    return Run(states, forces, stiffness)


def ecos(system, steps):
    """ecos runs system/MooredPlatform.ssp (EcosSimulation(ssp_path=...), step 1 s), with
    init() as a user calls it (ecos would apply an SSD parameter set only when init names
    it; the system has none). Values are read by name ("slowdrift::X"): the states after each step; SlowDrift's inputs before
    each step (ecos passes the outputs on after a step, so they then hold what the next step
    uses)."""
    from ecospy import EcosSimulation
    from ecospy.lib import EcosLib

    EcosLib.set_log_level("warn")
    states = np.empty((steps, len(OBSERVED)))
    forces = np.empty((steps, len(INPUT_NAMES)))
    with EcosSimulation(ssp_path=os.path.join(system, SSP_FILE), step_size=1.0) as sim:
        assert sim.init(), EcosLib.get_last_error()
        stiffness = tuple(sim.get_real(f"slowdrift::{n}") for n in STIFFNESS)
        for k in range(steps):
            forces[k] = [sim.get_real(f"slowdrift::{n}") for n in INPUT_NAMES]
            sim.step()
            states[k] = [sim.get_real(f"slowdrift::{n}") for n in OBSERVED]
        assert sim.get_time() == float(steps)
        sim.terminate()
    return Run(states, forces, stiffness)


def fmpy_ssp(system, steps):
    """fmpy runs system/MooredPlatform.ssp (fmpy.ssp.simulation.simulate_ssp, step 1 s) as a
    user calls it, with no parameter set (simulate_ssp never applies an SSD's parameter
    bindings itself: the system relies on none). fmpy starts
    every connector at 0 (not at the outputs after initialisation; the mooring's force at the
    origin is 0, so nothing differs here), steps every component from the same point, then
    passes the outputs on; its result row stamped t_k holds the values after the step from
    t_k, and SlowDrift's input connectors there hold the force of the next step. It reports
    no parameter values."""
    from fmpy.ssp.simulation import simulate_ssp

    ssp = os.path.join(system, SSP_FILE)
    result = simulate_ssp(ssp, stop_time=float(steps), step_size=1.0)
    assert np.array_equal(result["time"], np.arange(steps, dtype=float))
    states = np.column_stack([result[f"slowdrift.{n}"] for n in OBSERVED])
    held = np.column_stack([result[f"slowdrift.{n}"] for n in INPUT_NAMES])
    forces = np.vstack([np.zeros((1, len(INPUT_NAMES))), held[:-1]])
    return Run(states, forces, None)


def differences(run, reference):
    """Problems of a master's run against the reference run (the Jacobi glue loop): every
    state and every held force bit for bit, and no internal stiffness in the platform, as
    the system's SlowDrift.fmu is built."""
    problems = []
    if run.stiffness is not None and any(k != 0.0 for k in run.stiffness):
        problems.append(f"the master runs SlowDrift with internal stiffness {run.stiffness}: "
                        "the platform is moored twice")
    for what, a, b in (("states", run.states, reference.states),
                       ("forces", run.forces, reference.forces)):
        if a.shape != b.shape:
            problems.append(f"{what}: shape {a.shape}, reference {b.shape}")
        elif not np.array_equal(a, b):
            d = np.abs(a - b)
            first = int(np.argmax(np.any(d > 0, axis=1)))
            problems.append(f"{what} differ from step {first + 1} on; max |difference| per "
                            f"column {d.max(axis=0)}")
    return problems
