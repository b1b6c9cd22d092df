"""Mooring.fmu: MoorDyn's lines as an FMU that a master connects to
SlowDrift.fmu (docs/coupling.md).

1. fmpy's validate_fmu and fmu-manipulation-toolbox's checker find nothing; every Real has
   its own unit, and no output depends directly on an input.
2. Frame and signs: held at offsets in surge, sway, yaw and all three for 1 s from static
   equilibrium, the FMU returns the force that MoorDyn through its own Python API returns
   for the same offsets (mooring_stiffness.static_force: an independent route to the same
   library, with the DOF order and sign conventions checked by test_mooring_file.py), bit for
   bit; the surge force restores (Fx < 0 for X > 0).
3. The loop: SlowDrift.fmu moored by Mooring.fmu in the Gauss-Seidel loop of
   mooring_loop.run_loop equals, bit for bit, the same loop with MoorDyn's Python API, for
   30 minutes of the default sea (the fmpy-glue loop of test_mooring_loop.py, which runs it
   three hours).
4. Bad input: a mooringFile that does not exist makes fmi2ExitInitializationMode fail with a
   message naming mooringFile and the path; a NaN position is refused naming the input; a
   file that couples no body is refused saying what the FMU needs.
"""

import math

import numpy as np
import pytest

from mooring_loop import FmuBody, MooringFmu, run_loop
from mooring_stiffness import DEFAULT_DAT, Mooring, static_force
from test_fmutool import run_fmutool

OFFSETS = [(10.0, 0.0, 0.0), (0.0, -7.5, 0.0), (0.0, 0.0, 0.03), (4.0, 3.0, -0.02)]


def test_carries_moordyns_licence_text(mooring_fmu):
    """MoorDyn's BSD-3-Clause licence requires its text with a redistributed binary: the
    FMU's documentation/licenses/MoorDyn.txt holds it (not an empty entry)."""
    import zipfile

    with zipfile.ZipFile(mooring_fmu) as z:
        text = z.read("documentation/licenses/MoorDyn.txt").decode()
    assert "Redistribution and use in source and binary forms" in text, text[:200]
    assert "Copyright" in text and "Neither the name" in text, text[:200]


def test_validate_and_check(mooring_fmu):
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    assert validate_fmu(mooring_fmu) == []
    status, lines, levels = run_fmutool(mooring_fmu)
    text = "\n".join(lines)
    assert status == 0 and set(levels) <= {"INFO"}, text
    assert "This FMU seems to be compliant with FMI-2.0." in text
    assert "No semantic error against the FMI-2 standard." in text
    md = read_model_description(mooring_fmu)
    units = {v.name: v.unit for v in md.modelVariables if v.type == "Real"}
    assert units == {"X": "m", "Y": "m", "theta": "rad", "Xdot": "m/s", "Ydot": "m/s",
                     "thetadot": "rad/s", "Fx": "N", "Fy": "N", "Mz": "N.m",
                     "fairleadTensionMax": "N", "Z": "m", "roll": "rad", "pitch": "rad",
                     "Zdot": "m/s", "rolldot": "rad/s", "pitchdot": "rad/s", "Fz": "N",
                     "Mx": "N.m", "My": "N.m",
                     **{f"fairleadTension{n}": "N" for n in range(1, 9)}}
    assert all(u.dependencies == [] for u in md.outputs)


@pytest.mark.parametrize("q", OFFSETS)
def test_static_force_equals_moordyn_python_api(mooring_fmu, q):
    with MooringFmu(None, q0=q) as m:
        f = m.step(q, (0.0, 0.0, 0.0), 0.0, 1.0)
    expected = static_force(q)
    print(f"\nq = {q}: FMU {f}, MoorDyn's Python API {expected}")
    assert np.array_equal(f, expected)
    if q[0] > 0 and q[1] == q[2] == 0:
        assert f[0] < 0 and abs(f[1]) < 1e-6 * abs(f[0])


def test_loop_equals_the_python_api_loop(fmu, mooring_fmu):
    off = {"stiffnessSurge": 0.0, "stiffnessSway": 0.0, "stiffnessYaw": 0.0}
    with FmuBody(fmu, off, instance_name="python-api") as body:
        python_api = run_loop(body, 1800.0, 1.0, mooring=Mooring)
    with FmuBody(fmu, off, instance_name="mooring-fmu") as body:
        mooring_fmu_loop = run_loop(body, 1800.0, 1.0, dat=None, mooring=MooringFmu)
    assert np.max(np.abs(python_api[:, 1])) > 1.0, "the platform moves"
    assert np.array_equal(python_api, mooring_fmu_loop), (
        f"max |difference| {np.max(np.abs(python_api - mooring_fmu_loop), axis=0)}")


class Logged:
    """Mooring.fmu with a logger that keeps the discard and error lines."""

    def __init__(self, path):
        from fmpy import extract, read_model_description
        from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE

        self.errors = []

        def logger(env, instance, status, category, message):
            if status >= 2:
                self.errors.append(message.decode().replace("%%", "%"))

        self._logger = fmi2CallbackLoggerTYPE(logger)
        callbacks = fmi2CallbackFunctions()
        callbacks.logger = self._logger
        md = read_model_description(path)
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.unzipdir = extract(path)
        self.fmu = FMU2Slave(guid=md.guid, unzipDirectory=self.unzipdir,
                             modelIdentifier=md.coSimulation.modelIdentifier,
                             instanceName="logged")
        self.fmu.instantiate(callbacks=callbacks)
        self.fmu.setupExperiment(startTime=0.0)


def test_bad_input_is_named(mooring_fmu, tmp_path):
    from fmpy.fmi1 import FMICallException

    missing = str(tmp_path / "no_such_mooring.dat")
    m = Logged(mooring_fmu)
    m.fmu.setString([m.vr["mooringFile"]], [missing])
    m.fmu.enterInitializationMode()
    with pytest.raises(FMICallException):
        m.fmu.exitInitializationMode()
    assert any("mooringFile" in e and missing in e for e in m.errors), m.errors

    m = Logged(mooring_fmu)
    m.fmu.enterInitializationMode()
    with pytest.raises(FMICallException):
        m.fmu.setReal([m.vr["theta"]], [math.nan])
    assert any("theta" in e and "finite" in e for e in m.errors), m.errors

    # A step longer than an hour is discarded at once, naming the bound (1e308 s of MoorDyn
    # steps would never return), and the instance's time stays where it was.
    m = Logged(mooring_fmu)
    m.fmu.enterInitializationMode()
    m.fmu.exitInitializationMode()
    with pytest.raises(FMICallException):
        m.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1e308)
    assert any("communicationStepSize = 1e308" in e and "3600 s" in e for e in m.errors), m.errors

    # A MoorDyn file whose body is fixed, not coupled: nothing for the platform to drive.
    text = open(DEFAULT_DAT).read().replace("1    coupled     0", "1    fixed       0")
    assert "fixed       0" in text
    fixed = tmp_path / "fixed_body.dat"
    fixed.write_text(text)
    m = Logged(mooring_fmu)
    m.fmu.setString([m.vr["mooringFile"]], [str(fixed)])
    m.fmu.enterInitializationMode()
    with pytest.raises(FMICallException):
        m.fmu.exitInitializationMode()
    assert any("couples 0 degrees of freedom" in e and "mooringFile" in e for e in m.errors), (
        m.errors)
