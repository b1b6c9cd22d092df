"""Closed mooring loop: SlowDrift FMU (or any body with the same interface) + MoorDyn,
in the two explicit coupling schemes a co-simulation master uses.

One MoorDyn call and one body step per communication step, no iteration. At the
communication point t_n the body's state (X, Y, theta) and velocity (Xdot, Ydot, thetadot)
are read; MoorDyn advances its lines from t_n to t_n + dt while moving the fairleads from
that state along that velocity (MoorDyn's coupled-body kinematics are linear over a step),
and returns the line force at t_n + dt (Fx, Fy and Mz, the moment about z, index 5 of
MoorDyn's 6 components). The schemes differ in which force the body holds over its step
from t_n to t_n + dt:

- Gauss-Seidel (scheme="gauss-seidel", the default; the fmpy-glue loop of
  test_mooring_loop.py): the mooring steps first and the body holds the force it has just
  returned, the line force at t_n + dt. Holding the force computed for the end of the step
  is a lead of about dt / 2 on the average force over the step: for a linear spring K it
  adds a numerical damping K dt / 2 (7e4 N s/m here, a damping ratio of pi dt / (2 T_n),
  0.8 % of critical at the 207 s surge period), and it does not move the mean.
- Jacobi (scheme="jacobi"; libcosim, ecos and fmpy's SSP master, which step every model
  from the same communication point and pass the outputs on afterwards): both step from
  t_n, and the body holds the force the mooring returned at the end of the previous step,
  the line force at t_n (at t_0: the mooring's output after its initialisation). That is
  one step later than Gauss-Seidel: a lag of about dt / 2, a numerical damping of
  -K dt / 2, the same size with the opposite sign, and again no mean force.

The body interface: state() -> (q, qdot) as arrays (X, Y, theta), (Xdot, Ydot, thetadot);
set_force(F) with F = (Fx, Fy, Mz) in the inertial frame; do_step(t, dt); optionally
motion() -> (pose, rates), the 6-DOF whole motion the mooring follows (SlowDrift's totals:
slow drift plus wave-frequency motion), else the mooring follows state().
"""

import os
import shutil

import numpy as np

from mooring_stiffness import DEFAULT_DAT, Mooring

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DEFAULT_FMU = os.path.join(REPO, "target", "fmu", "SlowDrift.fmu")

STATE_NAMES = ("X", "Y", "theta")
RATE_NAMES = ("Xdot", "Ydot", "thetadot")
# SlowDrift's whole motion (slow drift plus wave-frequency motion) and the mooring FMU's
# inputs it drives, in MoorDyn's order (x, y, z, roll, pitch, yaw).
TOTAL_NAMES = ("X_total", "Y_total", "Z_total", "roll_total", "pitch_total", "yaw_total")
TOTAL_RATE_NAMES = ("Xdot_total", "Ydot_total", "Zdot_total", "rolldot_total",
                    "pitchdot_total", "yawdot_total")
POSE_NAMES = ("X", "Y", "Z", "roll", "pitch", "theta")
POSE_RATE_NAMES = ("Xdot", "Ydot", "Zdot", "rolldot", "pitchdot", "thetadot")
INPUT_NAMES = ("Fx_ext", "Fy_ext", "Mz_ext")

# Columns of the record returned by run_loop / run_free.
COLUMNS = ("t", "X", "Y", "theta", "Xdot", "Ydot", "thetadot", "Fx", "Fy", "Mz")


# SlowDrift's parameters that switch its internal linear mooring off (the system files set
# the same: its mooring is then the lines alone).
LINES_ONLY = {"stiffnessSurge": 0.0, "stiffnessSway": 0.0, "stiffnessYaw": 0.0}


def default_experiment(path):
    """(stop time, step size) of an FMU's DefaultExperiment (SlowDrift: three hours at 1 s)."""
    from fmpy import read_model_description

    de = read_model_description(path).defaultExperiment
    stop = float(de.stopTime) if de is not None and de.stopTime is not None else 10800.0
    step = float(de.stepSize) if de is not None and de.stepSize is not None else 1.0
    return stop, step


def fmu_path():
    return os.environ.get("SLOWDRIFT_FMU", DEFAULT_FMU)


def mooring_fmu_path():
    """Mooring.fmu: $MOORING_FMU, else beside SlowDrift.fmu (fmu-pack writes both)."""
    return os.environ.get("MOORING_FMU",
                          os.path.join(os.path.dirname(fmu_path()), "Mooring.fmu"))


class FmuBody:
    """SlowDrift as a co-simulation slave through fmpy, variables found by name only."""

    def __init__(self, path, parameters=None, instance_name="slowdrift", start_time=0.0):
        from fmpy import extract, read_model_description
        from fmpy.fmi2 import FMU2Slave

        self.md = read_model_description(path)
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.types = {v.name: v.type for v in self.md.modelVariables}
        missing = [n for n in STATE_NAMES + RATE_NAMES + INPUT_NAMES if n not in self.vr]
        if missing:
            raise KeyError(f"{path}: modelDescription.xml has no variable(s) {missing}")
        self.unzipdir = extract(path)
        self.fmu = FMU2Slave(
            guid=self.md.guid,
            unzipDirectory=self.unzipdir,
            modelIdentifier=self.md.coSimulation.modelIdentifier,
            instanceName=instance_name,
        )
        self.fmu.instantiate()
        self.fmu.setupExperiment(startTime=start_time)
        # Parameters (variability fixed, initial exact) are set before initialization.
        for name, value in (parameters or {}).items():
            kind = self.types[name]
            if kind == "Real":
                self.fmu.setReal([self.vr[name]], [float(value)])
            elif kind == "Integer":
                self.fmu.setInteger([self.vr[name]], [int(value)])
            else:
                raise TypeError(f"parameter {name} of type {kind} not supported here")
        self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()
        self.state_vr = [self.vr[n] for n in STATE_NAMES + RATE_NAMES]
        self.input_vr = [self.vr[n] for n in INPUT_NAMES]

    def state(self):
        v = np.array(self.fmu.getReal(self.state_vr), dtype=float)
        return v[:3], v[3:]

    def motion(self):
        """The whole motion a mooring follows: (pose, rates), 6 DOF each, SlowDrift's
        totals (the slow drift alone where they are absent)."""
        if not all(n in self.vr for n in TOTAL_NAMES + TOTAL_RATE_NAMES):
            return self.state()
        v = np.array(self.fmu.getReal([self.vr[n] for n in TOTAL_NAMES + TOTAL_RATE_NAMES]))
        return v[:6], v[6:]

    def set_force(self, f):
        self.fmu.setReal(self.input_vr, [float(x) for x in f])

    def do_step(self, t, dt):
        # fmpy raises FMICallException on any status worse than fmi2Warning.
        self.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=dt)

    def close(self):
        if self.fmu is not None:
            try:
                self.fmu.terminate()
            finally:
                self.fmu.freeInstance()
                self.fmu = None
                shutil.rmtree(self.unzipdir, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


class MooringFmu:
    """Mooring.fmu through fmpy with the interface of mooring_stiffness.Mooring:
    step(q, qdot, t, dt) sets the inputs X..thetadot (or, for a 6-DOF q, X, Y, Z, roll,
    pitch, theta and their rates) to the motion at t, steps the FMU from t
    to t + dt and returns its outputs (Fx, Fy, Mz), the line force at t + dt."""

    def __init__(self, dat=None, q0=(0.0, 0.0, 0.0), qdot0=(0.0, 0.0, 0.0), path=None,
                 instance_name="mooring"):
        from fmpy import extract, read_model_description
        from fmpy.fmi2 import FMU2Slave

        path = path or mooring_fmu_path()
        self.md = read_model_description(path)
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.unzipdir = extract(path)
        self.fmu = FMU2Slave(guid=self.md.guid, unzipDirectory=self.unzipdir,
                             modelIdentifier=self.md.coSimulation.modelIdentifier,
                             instanceName=instance_name)
        self.in_vr = [self.vr[n] for n in STATE_NAMES + RATE_NAMES]
        self.in_vr6 = [self.vr[n] for n in POSE_NAMES + POSE_RATE_NAMES]
        self.out_vr = [self.vr[n] for n in ("Fx", "Fy", "Mz")]
        self.fmu.instantiate()
        self.fmu.setupExperiment(startTime=0.0)
        if dat is not None:
            self.fmu.setString([self.vr["mooringFile"]], [dat])
        self.fmu.enterInitializationMode()
        self.fmu.setReal(self._inputs(q0), [float(x) for x in (*q0, *qdot0)])
        self.fmu.exitInitializationMode()

    def _inputs(self, q):
        """The inputs a planar state (3) or a whole motion (6) sets."""
        return self.in_vr6 if len(q) == 6 else self.in_vr

    def initial_force(self):
        """The outputs (Fx, Fy, Mz) after initialisation: the static line force at q0."""
        return np.array(self.fmu.getReal(self.out_vr))

    def step(self, q, qdot, t, dt):
        self.fmu.setReal(self._inputs(q), [float(x) for x in (*q, *qdot)])
        self.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=dt)
        return np.array(self.fmu.getReal(self.out_vr))

    def close(self):
        if self.fmu is not None:
            try:
                self.fmu.terminate()
            finally:
                self.fmu.freeInstance()
                self.fmu = None
                shutil.rmtree(self.unzipdir, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def run_loop(body, duration, dt=1.0, dat=DEFAULT_DAT, mooring=Mooring, scheme="gauss-seidel",
             zero_start=False):
    """Couple body and the MoorDyn mooring explicitly for duration seconds of steps dt.
    mooring: the class of the mooring model (MoorDyn through its Python API, Mooring, or
    through the mooring FMU, MooringFmu; the Jacobi scheme needs MooringFmu's
    initial_force). scheme: "gauss-seidel" or "jacobi" (module docstring).

    zero_start: the mooring starts from inputs 0 (initialised, and given for its first step,
    at the origin at rest) as fmpy's SSP master starts every connector at 0, instead of the
    body's motion at t_0.

    Returns an array with COLUMNS: row n holds the state at t_n and the force applied over
    the step from t_n (the last row's force is the last one MoorDyn returned).
    """
    if scheme not in ("gauss-seidel", "jacobi"):
        raise ValueError(f"scheme must be gauss-seidel or jacobi, not {scheme!r}")
    n = int(round(duration / dt))
    rec = np.empty((n + 1, len(COLUMNS)))
    moving = getattr(body, "motion", body.state)
    pose, rates = moving()
    if zero_start:
        pose, rates = np.zeros_like(pose), np.zeros_like(rates)
    with mooring(dat, q0=pose, qdot0=rates) as mooring:
        held = mooring.initial_force() if scheme == "jacobi" else None
        for k in range(n):
            t = k * dt
            q, qd = body.state()
            if k > 0 or not zero_start:
                pose, rates = moving()
            f = mooring.step(pose, rates, t, dt)
            if scheme == "gauss-seidel":
                held = f
            rec[k] = (t, *q, *qd, *held)
            body.set_force(held)
            body.do_step(t, dt)
            held = f
        q, qd = body.state()
        rec[n] = (n * dt, *q, *qd, *f)
    return rec


def run_free(body, duration, dt=1.0):
    """The body alone (external force zero), recorded like run_loop."""
    n = int(round(duration / dt))
    rec = np.zeros((n + 1, len(COLUMNS)))
    body.set_force((0.0, 0.0, 0.0))
    for k in range(n):
        q, qd = body.state()
        rec[k, :7] = (k * dt, *q, *qd)
        body.do_step(k * dt, dt)
    q, qd = body.state()
    rec[n, :7] = (n * dt, *q, *qd)
    return rec


def slow_part(x, dt, window=60.0):
    """The moving average of x over `window` seconds (edges shrink the window): the slow
    part of a record whose wave-frequency part (periods below 20 s, from the fairleads'
    wave-frequency motion) the average removes."""
    n = max(1, int(round(window / dt)))
    kernel = np.ones(n)
    return np.convolve(x, kernel, mode="same") / np.convolve(np.ones(len(x)), kernel, mode="same")


def mean_scatter(x, dt, t_corr):
    """Standard deviation of the mean of a correlated record of length len(x) dt.

    About rms * sqrt(2 T_corr / T) for a record much longer than its correlation time.
    """
    x = np.asarray(x, dtype=float)
    rms = np.sqrt(np.mean((x - x.mean()) ** 2))
    return rms * np.sqrt(2.0 * t_corr / (len(x) * dt))
