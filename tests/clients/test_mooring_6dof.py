"""Mooring.fmu driven in six degrees of freedom: the inputs Z, roll, pitch (and their rates)
beside X, Y, theta; the outputs Fz, Mx, My beside Fx, Fy, Mz; one fairlead tension per line
(fairleadTension1..8) beside fairleadTensionMax.

The FMU's convention (mooring/src/motion.rs): inertial X, Y, Z with Z up at the platform's
reference point; theta the yaw about +Z; roll and pitch small rotations about the inertial
X and Y axes, the orientation (I + [(roll, pitch, 0)]x) Rz(theta) to first order. The FMU
hands the six numbers to MoorDyn as they are, whose rotation is Rx(roll) Ry(pitch) Rz(yaw)
(test_mooring_file.py checks it on MoorDyn 2.7.2), equal to the convention to first order;
the quasi-static lines use the same rotation. The force is the lines' on the platform,
inertial axes, moments about the reference point.

1. Quasi-static lines (mooringModel = 1) against MoorPy 1.3.0 (an independent catenary
   code) at poses with heave, roll, pitch and yaw together: all six force components and the
   eight fairlead tensions within 1e-7 (measured 1e-15 to 1e-12). MoorPy's Body turns its points by
   Rz(r6[5]) Ry(r6[4]) Rx(r6[3]) (moorpy.helpers.rotationMatrix), so the test gives it the
   z-y-x angles of the FMU's rotation Rx Ry Rz, computed here (moorpy_angles).
2. MoorDyn's dynamic lines (mooringModel = 0) held at the same poses for 1 s after its
   static solve, against MoorPy: within 1 % of the force (the lumped-mass lines of 10
   segments of 100 m on a seabed spring against the exact catenary; measured 0.24-0.34 %
   of the largest component, the lines' weight Fz of about 7.7 MN).
   MoorDyn's fairlead tension is its top segment's tension (GetLineFairTen: Line::getNodeTen
   at the end node, "the associated ending segment tension"), which the catenary has half a
   segment below the fairlead: sqrt(HF^2 + (VF - w s)^2) at s = 50 m of unstretched line
   from MoorPy's fairlead tension (HF, VF) and w, the suspended catenary's tension. Against
   it, within 1 % (measured 0.57-0.70 %); against the fairlead tension itself MoorDyn's is
   3-4 % lower (printed).
3. The FMU's dynamic lines equal MoorDyn's Python API given r6 = (X, Y, Z, roll, pitch,
   theta), bit for bit, all six components and the tensions; at a planar pose with the new
   inputs left at their start values as well (the planar outputs Fx, Fy, Mz are those of
   test_mooring_fmu.py's planar check, so a system that connects only the planar motion
   runs as before).
4. A mooringFile with another number of lines than the FMU's eight outputs is refused at
   initialisation, for both line models, naming mooringFile and the two counts.
"""

import shutil

import numpy as np
import pytest

from mooring_stiffness import DEFAULT_DAT, quiet
from test_mooring_fmu import Logged
from test_quasi_static_mooring import moorpy_system  # noqa: F401 (a fixture)

LINES = 8
TENSIONS = [f"fairleadTension{n}" for n in range(1, LINES + 1)]
FORCE = ["Fx", "Fy", "Fz", "Mx", "My", "Mz"]
POSE = ["X", "Y", "Z", "roll", "pitch", "theta"]
# (X, Y, Z, roll, pitch, theta): heave, roll, pitch alone, then all six together.
POSES = [(0.0, 0.0, 1.5, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.05, 0.0, 0.0),
         (0.0, 0.0, 0.0, 0.0, -0.04, 0.0), (6.0, -3.0, -1.0, 0.03, -0.02, 0.15),
         (-10.0, 5.0, 2.0, -0.06, 0.05, -0.3)]
PLANAR = (4.0, 3.0, 0.0, 0.0, 0.0, -0.02)
# A moment compares with a force through a lever of the platform's size (fairleads 50 m out).
LEVER = 50.0


def held(path, model, pose, planar_only=False, hold=1.0):
    """Mooring.fmu (mooringModel = model) initialised at pose and held there for hold
    seconds: {output name: value}. planar_only: set X, Y, theta only (the others keep their
    start values)."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    md = read_model_description(path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    outputs = [v.name for v in md.modelVariables if v.causality == "output"]
    unzipdir = extract(path)
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="6dof")
    try:
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        fmu.setInteger([vr["mooringModel"]], [model])
        fmu.enterInitializationMode()
        names = [n for n, x in zip(POSE, pose) if not planar_only or n in ("X", "Y", "theta")]
        fmu.setReal([vr[n] for n in names], [float(pose[POSE.index(n)]) for n in names])
        fmu.exitInitializationMode()
        fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=hold)
        out = dict(zip(outputs, fmu.getReal([vr[n] for n in outputs])))
        fmu.terminate()
        fmu.freeInstance()
    finally:
        shutil.rmtree(unzipdir, ignore_errors=True)
    return out


def rotation(roll, pitch, yaw):
    """The FMU's (MoorDyn's) rotation Rx(roll) Ry(pitch) Rz(yaw)."""
    c, s = np.cos, np.sin
    rx = np.array([[1, 0, 0], [0, c(roll), -s(roll)], [0, s(roll), c(roll)]])
    ry = np.array([[c(pitch), 0, s(pitch)], [0, 1, 0], [-s(pitch), 0, c(pitch)]])
    rz = np.array([[c(yaw), -s(yaw), 0], [s(yaw), c(yaw), 0], [0, 0, 1]])
    return rx @ ry @ rz


def moorpy_angles(roll, pitch, yaw):
    """MoorPy's (r6[3], r6[4], r6[5]) for the rotation Rx(roll) Ry(pitch) Rz(yaw): MoorPy's
    matrix is Rz(r6[5]) Ry(r6[4]) Rx(r6[3]), whose third row is (-sin p, cos p sin r,
    cos p cos r) and first column (cos p cos y, cos p sin y, -sin p)."""
    r = rotation(roll, pitch, yaw)
    return (np.arctan2(r[2, 1], r[2, 2]), -np.arcsin(r[2, 0]), np.arctan2(r[1, 0], r[0, 0]))


def moorpy_solution(ms, pose):
    """MoorPy's line force on the body at pose (Fx, Fy, Fz, Mx, My, Mz; inertial axes, about
    the body's reference point) and its fairlead tensions (end B of each line)."""
    from moorpy.helpers import rotationMatrix

    angles = moorpy_angles(*pose[3:])
    assert np.allclose(rotationMatrix(*angles), rotation(*pose[3:]), atol=1e-14)
    ms.bodyList[0].setPosition([*pose[:3], *angles])
    for line in ms.lineList:
        line.staticSolve(tol=1e-12)
    f = ms.bodyList[0].getForces(lines_only=True)
    return np.array(f), np.array([np.linalg.norm(line.fB) for line in ms.lineList])


def scale(f):
    """The size of a 6-DOF force, the moments through LEVER, at least 1e5 N."""
    return max(1e5, *np.abs(f[:3]), *(np.abs(f[3:]) / LEVER))


def half_segment_tensions(ms):
    """MoorPy's catenary tension half a segment below each fairlead (after moorpy_solution):
    sqrt(HF^2 + (VF - w s)^2), s = L / (2 segments), the line suspended there."""
    out = []
    for line in ms.lineList:
        s = line.L / (2 * (line.nNodes - 1))
        hf, vf = np.hypot(*line.fB[:2]), -line.fB[2]
        assert vf > line.type["w"] * s
        out.append(np.hypot(hf, vf - line.type["w"] * s))
    return np.array(out)


def differences(ours, force, tensions):
    """(largest force difference as a fraction of scale(force), largest relative tension
    difference) of the FMU's outputs against a (force, tensions) solution."""
    f = np.array([ours[n] for n in FORCE])
    t = np.array([ours[n] for n in TENSIONS])
    lever = np.array([1, 1, 1, LEVER, LEVER, LEVER])
    return (np.max(np.abs(f - force) / lever) / scale(force),
            np.max(np.abs(t - tensions) / tensions))


@pytest.mark.parametrize("pose", POSES)
def test_quasi_static_equals_moorpy(mooring_fmu, moorpy_system, pose):  # noqa: F811
    ours = held(mooring_fmu, 1, pose)
    force, tensions = moorpy_solution(moorpy_system, pose)
    df, dt = differences(ours, force, tensions)
    print(f"\npose {pose}: MoorPy {force}; force {df:.1e} of its size, tensions {dt:.1e}")
    assert df <= 1e-7 and dt <= 1e-7
    assert ours["fairleadTensionMax"] == max(ours[n] for n in TENSIONS)


@pytest.mark.parametrize("pose", POSES)
def test_dynamic_near_moorpy(mooring_fmu, moorpy_system, pose):  # noqa: F811
    ours = held(mooring_fmu, 0, pose)
    force, tensions = moorpy_solution(moorpy_system, pose)
    df, dt = differences(ours, force, half_segment_tensions(moorpy_system))
    _, at_fairlead = differences(ours, force, tensions)
    print(f"\npose {pose}: MoorDyn {[ours[n] for n in FORCE]}, MoorPy {force}: "
          f"force {df:.2e} of its size, tensions {dt:.2e} (at the fairlead {at_fairlead:.2e})")
    assert df <= 0.01 and dt <= 0.01


def moordyn_python_api(pose, hold=1.0):
    """MoorDyn through its Python API with the coupled body at r6 = pose, held for hold
    seconds after its static solve: (the 6 force components, the fairlead tensions)."""
    import moordyn

    with quiet():
        md = moordyn.Create(DEFAULT_DAT)
        moordyn.Init(md, list(pose), [0.0] * 6)
        f = moordyn.Step(md, list(pose), [0.0] * 6, 0.0, hold)
        n = moordyn.GetNumberLines(md)
        t = [moordyn.GetLineFairTen(moordyn.GetLine(md, i + 1)) for i in range(n)]
        moordyn.Close(md)
    return np.array(f), np.array(t)


@pytest.mark.parametrize("pose", POSES[3:] + [PLANAR])
def test_dynamic_equals_moordyn_python_api(mooring_fmu, pose):
    ours = held(mooring_fmu, 0, pose, planar_only=pose == PLANAR)
    force, tensions = moordyn_python_api(pose)
    assert [ours[n] for n in FORCE] == list(force)
    assert [ours[n] for n in TENSIONS] == list(tensions)
    assert ours["fairleadTensionMax"] == max(tensions)


@pytest.mark.parametrize("model", [0, 1])
def test_another_number_of_lines_is_refused(mooring_fmu, tmp_path, model):
    from fmpy.fmi1 import FMICallException

    # The spread mooring without its line 8 (its two points stay, joined to nothing:
    # MoorDyn wants the points numbered 1, 2, ... too).
    rows = open(DEFAULT_DAT).read().splitlines()
    path = tmp_path / "seven_lines.dat"
    path.write_text("\n".join(r for r in rows if not r.startswith("8    chain84")) + "\n")
    m = Logged(mooring_fmu)
    m.fmu.setInteger([m.vr["mooringModel"]], [model])
    m.fmu.setString([m.vr["mooringFile"]], [str(path)])
    m.fmu.enterInitializationMode()
    with pytest.raises(FMICallException):
        m.fmu.exitInitializationMode()
    assert any(f"mooringFile = {path}" in e and "has 7 mooring lines" in e
               and "8 fairlead tension outputs" in e for e in m.errors), m.errors
