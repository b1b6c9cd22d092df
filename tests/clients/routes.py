"""Shared routes of the client tests: the native CLI (an independent route for the FMU's
numbers) and a plain fmpy FMU2Slave run.

Native route: `slowdrift simulate --config FILE.toml --out FILE.csv` on a TOML file written
from src/scenario/default.toml with the same sea, seed, stiffness, step and duration as the FMU
parameters and stop time. The CLI writes 17 significant digits (`{:.16e}`), which read back
bit for bit, so the two routes can be compared exactly.
"""

import csv
import functools
import json
import math
import os
import shutil
import subprocess
import threading

import numpy as np

from mooring_loop import REPO

DEFAULT_TOML = os.path.join(REPO, "src", "scenario", "default.toml")

# The FMU's outputs in the order of the native CSV's columns after time_s.
OUTPUTS = ("X", "Y", "theta", "Xdot", "Ydot", "thetadot", "eta",
           "Fx_wave", "Fy_wave", "Mz_wave", "Fx_damping", "Fy_damping", "Mz_damping",
           "Fx_drag", "Fy_drag", "Mz_drag",
           "X_wf", "Y_wf", "Z_wf", "roll_wf", "pitch_wf", "yaw_wf",
           "X_total", "Y_total", "Z_total", "roll_total", "pitch_total", "yaw_total",
           "Xdot_total", "Ydot_total", "Zdot_total", "rolldot_total", "pitchdot_total",
           "yawdot_total", "windVelocity", "Fx_wind", "Fy_wind", "Mz_wind")
INPUTS = ("Fx_ext", "Fy_ext", "Mz_ext")

# Non-default FMU parameters used by the comparisons: an oblique sea (30 deg) so that sway and
# yaw move too, a non-default spectrum, seed and stiffness. waveDirection is math.radians(30),
# which is what the TOML reader computes from direction_deg = 30 (x * (pi / 180) in both).
PARAMETERS = {
    "Hs": 6.0,
    "Tp": 11.0,
    "gamma": 2.0,
    "waveDirection": math.radians(30.0),
    "seed": 7,
    "stiffnessSurge": 2.0e5,
    "stiffnessSway": 1.8e5,
    "stiffnessYaw": 1.5e9,
}


def _replace_once(text, old, new):
    if text.count(old) != 1:
        raise AssertionError(f"{DEFAULT_TOML}: expected exactly one {old!r}")
    return text.replace(old, new)


def native_config(parameters, duration, step):
    """default.toml with the FMU parameters of PARAMETERS' kind applied, as TOML text."""
    p = dict(parameters)
    text = open(DEFAULT_TOML).read()
    text = _replace_once(text, "hs = 7.0\n", f"hs = {p['Hs']!r}\n")
    line = next(l for l in text.splitlines(keepends=True) if l.startswith("tp = 12.0 "))
    text = _replace_once(text, line, f"tp = {p['Tp']!r}\ngamma = {p['gamma']!r}\n")
    direction = math.degrees(p["waveDirection"])
    assert math.radians(round(direction)) == p["waveDirection"], "use whole degrees"
    text = _replace_once(text, 'spreading = "long-crested"\ndirection_deg = 0.0\nseed = 1\n',
                         f'spreading = "long-crested"\ndirection_deg = {float(round(direction))!r}\n'
                         f"seed = {int(p['seed'])}\n")
    text = _replace_once(text, "duration = 10800.0", f"duration = {float(duration)!r}")
    text = _replace_once(text, "time_step = 1.0 ", f"time_step = {float(step)!r} ")
    text = _replace_once(
        text,
        "stiffness = [[1.5807e5, 0.0, 0.0], [0.0, 1.5807e5, 0.0], [0.0, 0.0, 1.0019e9]]",
        f"stiffness = [[{p['stiffnessSurge']!r}, 0.0, 0.0], [0.0, {p['stiffnessSway']!r}, 0.0], "
        f"[0.0, 0.0, {p['stiffnessYaw']!r}]]")
    return text


@functools.lru_cache(maxsize=None)
def native_tool():
    """Path of the native CLI: $SLOWDRIFT_CLI when set (tests/run_all.sh sets it to the
    executable `cargo test` built), else built by cargo once per session (its path from
    cargo's own report); run directly from then on: a `cargo run` of it would rebuild the
    crate after fmu-pack's build of the FMU's library (another feature set, the same output
    file). conftest.py resolves it before any test runs."""
    given = os.environ.get("SLOWDRIFT_CLI")
    if given:
        assert os.path.isfile(given), f"SLOWDRIFT_CLI={given} is not a file"
        return given
    cargo = shutil.which("cargo") or "cargo"
    done = subprocess.run([cargo, "build", "--release", "--bin", "slowdrift",
                           "--message-format=json"], cwd=REPO, check=True,
                          capture_output=True, text=True)
    for line in done.stdout.splitlines():
        message = json.loads(line)
        if message.get("reason") == "compiler-artifact" and message.get("executable") and \
                message["target"]["name"] == "slowdrift":
            return message["executable"]
    raise AssertionError("cargo did not report the slowdrift executable")


def run_native(workdir, parameters, duration, step):
    """Runs the native CLI; returns (time, outputs) with outputs[:, j] = OUTPUTS[j]."""
    config = os.path.join(workdir, f"native_h{step}.toml")
    out = os.path.join(workdir, f"native_h{step}.csv")
    with open(config, "w") as f:
        f.write(native_config(parameters, duration, step))
    subprocess.run([native_tool(), "simulate", "--config", config, "--out", out],
                   cwd=REPO, check=True, stdout=subprocess.DEVNULL)
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    assert header[0] == "time_s" and len(header) == 1 + len(OUTPUTS), header
    # Python's float() rounds correctly: 17 significant digits give the same double back.
    data = np.array([[float(v) for v in row] for row in body])
    return data[:, 0], data[:, 1:]


def set_parameters(slave, md, parameters):
    """Sets FMU parameters by name on an fmpy slave (Real, Integer)."""
    by_name = {v.name: v for v in md.modelVariables}
    for name, value in parameters.items():
        v = by_name[name]
        if v.type == "Real":
            slave.setReal([v.valueReference], [float(value)])
        elif v.type == "Integer":
            slave.setInteger([v.valueReference], [int(value)])
        else:
            raise TypeError(f"{name}: type {v.type} not handled")


# fmpy's FMU2Slave constructor changes the process's working directory to the FMU's binaries
# folder and back around loading the library; two threads constructing at once can leave it
# in that folder (the second one saves the first one's chdir as "back"), which the fixture
# then deletes, and every later test that calls os.getcwd() fails. Construct one at a time.
_CONSTRUCT = threading.Lock()


class Slave:
    """One FMU2Slave instance initialised with parameters; outputs read by name."""

    def __init__(self, fmu, md, unzipdir, parameters, name, stop_time=None):
        from fmpy.fmi2 import FMU2Slave

        self.md = md
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.out_vr = [self.vr[n] for n in OUTPUTS]
        self.in_vr = [self.vr[n] for n in INPUTS]
        self.parameters = parameters
        self.stop_time = stop_time
        with _CONSTRUCT:
            self.fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                                 modelIdentifier=md.coSimulation.modelIdentifier,
                                 instanceName=name)
        self.fmu.instantiate()
        self.initialise()

    def initialise(self):
        self.fmu.setupExperiment(startTime=0.0, stopTime=self.stop_time)
        set_parameters(self.fmu, self.md, self.parameters)
        self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()

    def outputs(self):
        return np.array(self.fmu.getReal(self.out_vr))

    def run(self, t0, n, dt, force=(0.0, 0.0, 0.0)):
        """n steps of dt from t0; returns the outputs after each step, shape (n, 16)."""
        rec = np.empty((n, len(OUTPUTS)))
        self.fmu.setReal(self.in_vr, list(force))
        for k in range(n):
            self.fmu.doStep(currentCommunicationPoint=t0 + k * dt, communicationStepSize=dt)
            rec[k] = self.fmu.getReal(self.out_vr)
        return rec

    def close(self):
        if self.fmu is not None:
            self.fmu.terminate()
            self.fmu.freeInstance()
            self.fmu = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
