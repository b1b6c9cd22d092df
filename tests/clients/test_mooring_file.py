"""Independent checks of mooring/spread_mooring.dat (the mooring FMU's default) and of the MoorDyn API
conventions the loop relies on (DOF order, yaw sign, force indices)."""

import numpy as np
import moordyn

from mooring_stiffness import DEFAULT_DAT, Mooring, body6, quiet, static_force

# Design target: the default platform's internal stiffness (src/scenario/default.toml).
DEFAULT_K_SURGE = 1.5807e5
DEFAULT_K_YAW = 1.0019e9


def test_zero_offset_force_is_vertical():
    """Symmetric pretension: at the neutral position the lines pull only downwards."""
    f, f6, tens = static_force((0.0, 0.0, 0.0), with_tensions=True)
    fz = f6[2]
    assert fz < 0.0, "the chain's weight must pull the platform down"
    assert abs(f[0]) < 1e-6 * abs(fz) and abs(f[1]) < 1e-6 * abs(fz)
    assert abs(f[2]) < 1e-6 * abs(fz) * 35.0
    # Every line carries the same pretension (the layout is symmetric).
    assert np.ptp(tens) < 1e-6 * tens.mean()
    assert 1.0e6 < tens.mean() < 2.0e6  # design: about 1.5 MN at each fairlead


def test_stiffness_matrix(stiffness):
    k = np.array(stiffness["K"])
    assert np.all(np.isfinite(k))
    # Symmetric about both axes and under X <-> Y: diagonal, K11 = K22.
    assert abs(k[0, 0] - k[1, 1]) < 1e-6 * k[0, 0]
    off = k - np.diag(np.diag(k))
    scale = np.sqrt(np.outer(np.diag(k), np.diag(k)))
    assert np.all(np.abs(off) < 1e-6 * scale)
    # Of the order of the default platform's internal stiffness (within a factor 2).
    assert 0.5 * DEFAULT_K_SURGE < k[0, 0] < 2.0 * DEFAULT_K_SURGE
    assert 0.2 * DEFAULT_K_YAW < k[2, 2] < 5.0 * DEFAULT_K_YAW
    # The restoring curve hardens moderately: secant at 10 m within 10 % of the tangent.
    c = stiffness["surge_curve"]
    i10 = c["X"].index(10.0)
    assert 1.0 <= c["restoring"][i10] / 10.0 / k[0, 0] < 1.10


def test_coupled_body_dof_order_and_yaw_sign():
    """MoorDyn's coupled body: (x, y, z, roll, pitch, yaw), yaw in rad counter-clockwise about
    +z like SlowDrift's theta; the position given to Step is the one at the start of the step
    and MoorDyn moves the body along the given velocity; the returned Mz (index 5) restores."""
    th = 0.01
    with Mooring(DEFAULT_DAT, q0=(0.0, 0.0, th)) as m:
        # Point 9 is the fairlead at (45, 35, -20) in the body frame.
        p = np.array(moordyn.GetPointPos(moordyn.GetPoint(m.md, 9)))
        c, s = np.cos(th), np.sin(th)
        assert np.allclose(p, (45.0 * c - 35.0 * s, 45.0 * s + 35.0 * c, -20.0), atol=1e-9)
        f = m.step((0.0, 0.0, th), (0.5, 0.0, 0.0), 0.0, 1.0)
        body = moordyn.GetBody(m.md, 1)
        assert np.allclose(moordyn.GetBodyPos(body), (0.5, 0.0, 0.0), atol=1e-12)
        assert np.isclose(moordyn.GetBodyAngle(body)[2], th, atol=1e-12)
        assert f[2] < 0.0  # restoring yaw moment for a positive yaw
        assert np.allclose(f, m.last6[[0, 1, 5]])
    assert body6((1.0, 2.0, 3.0)) == [1.0, 2.0, 0.0, 0.0, 0.0, 3.0]


def test_coupled_body_rotation_is_rx_ry_rz():
    """MoorDyn 2.7.2 turns a coupled body's points by Rx(roll) Ry(pitch) Rz(yaw) of its r6
    (source/Misc.hpp, Euler2Quat; mooring/src/motion.rs relies on it): a fairlead lands at
    x + Rx Ry Rz p, not at x + Rz Ry Rx p, which differs by centimetres at these angles."""
    r6 = [1.0, 2.0, -0.5, 0.05, -0.04, 0.3]
    with quiet():
        md = moordyn.Create(DEFAULT_DAT)
        moordyn.Init(md, r6, [0.0] * 6)
        p = np.array(moordyn.GetPointPos(moordyn.GetPoint(md, 9)))
        moordyn.Close(md)

    def rot(axis, a):
        c, s = np.cos(a), np.sin(a)
        i, j = [k for k in range(3) if k != axis]
        m = np.eye(3)
        m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
        return m if axis != 1 else m.T  # about Y: z x -> x (right-handed)

    rel = np.array([45.0, 35.0, -20.0])  # point 9 in the body frame
    xyz = np.array(r6[:3]) + rot(0, r6[3]) @ rot(1, r6[4]) @ rot(2, r6[5]) @ rel
    zyx = np.array(r6[:3]) + rot(2, r6[5]) @ rot(1, r6[4]) @ rot(0, r6[3]) @ rel
    assert np.allclose(p, xyz, atol=1e-9), (p, xyz)
    assert np.max(np.abs(p - zyx)) > 0.05


def test_quiet_restores_stdout(capfd):
    """quiet() hides what MoorDyn's C++ code writes to file descriptors 1 and 2, and only that."""
    import os

    with quiet():
        os.write(1, b"hidden\n")
        os.write(2, b"hidden\n")
    os.write(1, b"shown\n")
    out = capfd.readouterr().out
    assert "shown" in out and "hidden" not in out
