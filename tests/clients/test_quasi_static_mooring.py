"""The quasi-static line model of Mooring.fmu (mooringModel = 1): every line an
elastic catenary on a frictionless seabed (mooring/src/catenary.rs), read from the same
MoorDyn input file as the dynamic model.

1. Against MoorPy (PyPI, NREL's quasi-static mooring code; an independent implementation of
   the same catenary equations): held at offsets in surge, sway, yaw and combinations, up to
   20 m and 0.1 rad, the FMU's Fx, Fy, Mz and largest fairlead tension equal MoorPy's for the
   same file within 1e-7 of the force (MoorPy's lines solved to its tolerance 1e-12; MoorPy
   computes a line's weight in water with g = 9.81 before it reads the file's g =
   9.80665, so the test recomputes it with the file's g and rho, MoorPy's own formula).
2. Against MoorDyn's static solution of the same lines (its lumped-mass lines, 10 segments of
   100 m, on a seabed spring that lets them sink 4 cm): within 2 % of the force, the
   difference of the two discretisations (measured: 0.2 % in surge at 10 m, 0.4 % in sway,
   1.0 % of the yaw moment at 0.03 rad, whose transverse line stiffness the 100 m segments
   resolve least).
3. In a master: libcosim runs the system's OspSystemStructure.xml with mooringModel = 1 set
   as an Integer initial value, three hours: bounded, and the mean offset matches the lines'
   static stiffness as the dynamic lines' does (mean_offset.check). The quasi-static lines
   have no drag: the surge rms is larger than with MoorDyn's lines.
4. Bad input: mooringModel = 2 refused naming it; a file with a free point refused naming
   the file and line.
"""

import shutil

import numpy as np
import pytest

import mean_offset
import system_masters as sm
from mooring_stiffness import DEFAULT_DAT, static_force
from system_files import system_dir
from test_mooring_fmu import Logged

OFFSETS = [(0.0, 0.0, 0.0), (10.0, 0.0, 0.0), (0.0, -7.5, 0.0), (0.0, 0.0, 0.03),
           (4.0, 3.0, -0.02), (20.0, 0.0, 0.0), (0.0, 0.0, 0.1), (-15.0, 12.0, 0.05)]
QUASI_STATIC = 1
# A moment compares with a force through a lever of the platform's size (fairleads 50 m out).
LEVER = 50.0


def quasi_static_force(path, q):
    """Mooring.fmu with mooringModel = 1 held at q for 1 s: (Fx, Fy, Mz, fairleadTensionMax)."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    md = read_model_description(path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    unzipdir = extract(path)
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="quasi-static")
    try:
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        fmu.setInteger([vr["mooringModel"]], [QUASI_STATIC])
        fmu.enterInitializationMode()
        fmu.setReal([vr[n] for n in ("X", "Y", "theta")], [float(x) for x in q])
        fmu.exitInitializationMode()
        fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1.0)
        out = np.array(fmu.getReal([vr[n] for n in ("Fx", "Fy", "Mz", "fairleadTensionMax")]))
        fmu.terminate()
        fmu.freeInstance()
    finally:
        shutil.rmtree(unzipdir, ignore_errors=True)
    return out


@pytest.fixture(scope="module")
def moorpy_system():
    import moorpy

    ms = moorpy.System(file=DEFAULT_DAT)
    for lt in ms.lineTypes.values():
        lt["w"] = (lt["m"] - np.pi / 4 * lt["d_vol"] ** 2 * ms.rho) * ms.g
    ms.initialize()
    return ms


def moorpy_force(ms, q):
    ms.bodyList[0].setPosition([q[0], q[1], 0.0, 0.0, 0.0, q[2]])
    for line in ms.lineList:
        line.staticSolve(tol=1e-12)
    f = ms.bodyList[0].getForces(lines_only=True)
    tension = max(np.linalg.norm(line.fB) for line in ms.lineList)
    return np.array([f[0], f[1], f[5], tension])


def scale(f):
    """The size of a planar force (Fx, Fy, Mz), the moment through LEVER, at least 1e5 N."""
    return max(1e5, abs(f[0]), abs(f[1]), abs(f[2]) / LEVER)


@pytest.mark.parametrize("q", OFFSETS)
def test_forces_equal_moorpy(mooring_fmu, moorpy_system, q):
    ours = quasi_static_force(mooring_fmu, q)
    theirs = moorpy_force(moorpy_system, q)
    print(f"\nq = {q}: FMU {ours}, MoorPy {theirs}")
    s = scale(theirs)
    assert np.all(np.abs(ours[:2] - theirs[:2]) <= 1e-7 * s)
    assert abs(ours[2] - theirs[2]) <= 1e-7 * s * LEVER
    assert abs(ours[3] - theirs[3]) <= 1e-7 * theirs[3]


@pytest.mark.parametrize("q", OFFSETS[1:5])
def test_quasi_static_near_moordyn_static(mooring_fmu, q):
    ours = quasi_static_force(mooring_fmu, q)[:3]
    moordyn = static_force(q)
    s = scale(moordyn)
    print(f"\nq = {q}: quasi-static {ours}, MoorDyn static {moordyn}: "
          f"{np.max(np.abs(ours - moordyn) / np.array([s, s, s * LEVER])):.2e} of the force")
    assert np.all(np.abs(ours - moordyn) <= 0.02 * np.array([s, s, s * LEVER]))


def test_loop_in_libcosim(fmu, mooring_fmu, glue_runs, stiffness):
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimObserver import CosimObserver

    steps = len(glue_runs["moored"]) - 1
    ex = CosimExecution.from_osp_config_file(osp_path=system_dir(fmu))
    index = {s.name.decode(): s.index for s in ex.slave_infos()}
    mvr = {v.name.decode(): v for v in ex.slave_variables(index["mooring"])}
    assert mvr["mooringModel"].type == CosimVariableType.INTEGER.value
    assert ex.integer_initial_value(index["mooring"], mvr["mooringModel"].reference, QUASI_STATIC)
    vr = {v.name.decode(): v.reference for v in ex.slave_variables(index["slowdrift"])}
    series = CosimObserver.create_time_series(buffer_size=steps + 1)
    assert ex.add_observer(observer=series)
    for name in sm.OBSERVED + sm.INPUT_NAMES:
        assert series.start_time_series(index["slowdrift"], vr[name], CosimVariableType.REAL)
    assert ex.simulate_until(target_time=steps * sm.STEP_NS)

    def samples(name):
        return np.array(series.time_series_real_samples(index["slowdrift"], vr[name], from_step=1,
                                                        sample_count=steps)[2])

    run = sm.Run(np.column_stack([samples(n) for n in sm.OBSERVED]),
                 np.column_stack([samples(n) for n in sm.INPUT_NAMES]))
    rec = run.record()
    assert np.all(np.isfinite(rec)) and np.max(np.abs(rec[:, 1:3])) < 100.0
    assert np.corrcoef(rec[:-1, 1], rec[:-1, 7])[0, 1] < -0.9
    diff, tol, report = mean_offset.check(rec, glue_runs["linear"], glue_runs["K"], stiffness,
                                          glue_runs["dt"], label="quasi-static")
    print("\n" + report)
    assert abs(diff) <= tol
    keep = rec[:, 0] >= mean_offset.TRANSIENT
    dynamic = glue_runs["moored"][keep, 1]
    print(f"surge rms: quasi-static {np.std(rec[keep, 1]):.3f} m, MoorDyn's lines "
          f"{np.std(dynamic):.3f} m (their drag damps)")
    assert np.std(rec[keep, 1]) > np.std(dynamic)


def test_bad_input_is_named(mooring_fmu, tmp_path):
    from fmpy.fmi1 import FMICallException

    m = Logged(mooring_fmu)
    with pytest.raises(FMICallException):
        m.fmu.setInteger([m.vr["mooringModel"]], [2])
    assert any("mooringModel = 2" in e for e in m.errors), m.errors

    text = open(DEFAULT_DAT).read()
    free = text.replace("9    Body1", "9    Free ")
    path = tmp_path / "free_point.dat"
    path.write_text(free)
    m = Logged(mooring_fmu)
    m.fmu.setInteger([m.vr["mooringModel"]], [QUASI_STATIC])
    m.fmu.setString([m.vr["mooringFile"]], [str(path)])
    m.fmu.enterInitializationMode()
    with pytest.raises(FMICallException):
        m.fmu.exitInitializationMode()
    line = next(i + 1 for i, row in enumerate(free.splitlines()) if row.startswith("9    Free"))
    assert any(f"{path}:{line}:" in e and "mooringFile" in e for e in m.errors), m.errors
