#!/usr/bin/env python3
"""Static stiffness of the MoorDyn spread mooring about its neutral position.

The platform is MoorDyn's coupled body 1 (6 DOF: x, y, z, roll, pitch, yaw; angles in rad).
For each offset q = (X, Y, theta) the body is held there, MoorDyn's initial-condition solver
brings the lines to static equilibrium, and the lines are then run for one more second with
the body held still; the force MoorDyn returns for the body (inertial frame, about the body
reference point, the force the lines exert on the platform) is read. Central differences
give K_ij = -(F_i(q + d_j) - F_i(q - d_j)) / (2 d_j) in (surge, sway, yaw); the surge
restoring curve at larger offsets gives the cubic term used by the loop test's tolerance.

Usage: python3 tests/clients/mooring_stiffness.py [--dat FILE] [--json]
Deterministic (no random input; MoorDyn's static solve and fixed-step integration) and takes
a few seconds.
"""

import argparse
import contextlib
import ctypes
import json
import os
import sys

import numpy as np
import moordyn

HERE = os.path.dirname(os.path.abspath(__file__))
# The mooring FMU's default input file (packed into Mooring.fmu as resources/spread_mooring.dat).
DEFAULT_DAT = os.path.join(HERE, "..", "..", "mooring", "spread_mooring.dat")

# Finite-difference steps: 1 m in surge/sway, 0.01 rad (0.57 deg; 0.6 m at the fairleads) in
# yaw: small against the line geometry, large against the solver's force noise (~10 N).
D_TRANSLATION = 1.0
D_YAW = 0.01
# Surge offsets for the restoring curve (the loop sees a few metres, rarely more than 15 m).
CURVE_OFFSETS = (2.5, 5.0, 10.0, 15.0, 20.0)
# Hold time after the static solve, and the coupling step used for it.
HOLD = 1.0


@contextlib.contextmanager
def quiet():
    """Silence MoorDyn's console output (C++ stdout/stderr) unless MOORDYN_VERBOSE is set."""
    if os.environ.get("MOORDYN_VERBOSE"):
        yield
        return
    libc = ctypes.CDLL(None)
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        os.dup2(devnull, 2)
        yield
    finally:
        libc.fflush(None)
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in saved + [devnull]:
            os.close(fd)


def body6(q):
    """(X, Y, theta) -> MoorDyn's 6-DOF coupled-body vector (x, y, z, roll, pitch, yaw); a
    6-DOF vector (X, Y, Z, roll, pitch, yaw) as it is (roll and pitch small rotations about
    the inertial X and Y axes, which MoorDyn's Rx Ry Rz rotation takes unchanged to first
    order: mooring/src/motion.rs)."""
    if len(q) == 6:
        return [float(x) for x in q]
    return [float(q[0]), float(q[1]), 0.0, 0.0, 0.0, float(q[2])]


def planar(f6):
    """MoorDyn's 6 force components -> (Fx, Fy, Mz): indices 0, 1 and 5 (moment about z)."""
    return np.array([f6[0], f6[1], f6[5]], dtype=float)


class Mooring:
    """One MoorDyn instance of the spread mooring, driven in the horizontal plane.

    step(q, qdot, t, dt): the lines advance from t to t + dt while MoorDyn moves the
    fairleads from q along qdot (planar (X, Y, theta) or the 6-DOF pose of body6) (its coupled-body kinematics are linear over a step: the
    position given is the one at t); returns the line force on the platform at t + dt as
    (Fx, Fy, Mz), inertial frame, about the body reference point.
    """

    def __init__(self, dat=DEFAULT_DAT, q0=(0.0, 0.0, 0.0), qdot0=(0.0, 0.0, 0.0)):
        self.dat = dat
        with quiet():
            self.md = moordyn.Create(dat)
            ndof = moordyn.NCoupledDOF(self.md)
            if ndof != 6:
                moordyn.Close(self.md)
                raise ValueError(f"{dat}: expected one coupled 6-DOF body, got {ndof} coupled DOF")
            err = moordyn.Init(self.md, body6(q0), body6(qdot0))
        if err != 0:
            raise RuntimeError(f"moordyn.Init failed with code {err}")
        self.last6 = None

    def step(self, q, qdot, t, dt):
        with quiet():
            f6 = moordyn.Step(self.md, body6(q), body6(qdot), float(t), float(dt))
        self.last6 = np.array(f6, dtype=float)
        return planar(f6)

    def fairlead_tensions(self):
        n = moordyn.GetNumberLines(self.md)
        return np.array([moordyn.GetLineFairTen(moordyn.GetLine(self.md, i + 1)) for i in range(n)])

    def close(self):
        if self.md is not None:
            with quiet():
                moordyn.Close(self.md)
            self.md = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def static_force(q, dat=DEFAULT_DAT, with_tensions=False):
    """Line force (Fx, Fy, Mz) on the platform held at q = (X, Y, theta), in equilibrium."""
    with Mooring(dat, q0=q) as m:
        f = m.step(q, (0.0, 0.0, 0.0), 0.0, HOLD)
        if with_tensions:
            return f, m.last6.copy(), m.fairlead_tensions()
        return f


def stiffness_matrix(dat=DEFAULT_DAT, d=D_TRANSLATION, dtheta=D_YAW):
    """3x3 static stiffness in (surge, sway, yaw) about the neutral position, N/m, N, N m/rad."""
    steps = (d, d, dtheta)
    k = np.zeros((3, 3))
    for j, h in enumerate(steps):
        dq = np.zeros(3)
        dq[j] = h
        k[:, j] = -(static_force(dq, dat) - static_force(-dq, dat)) / (2.0 * h)
    return k


def surge_curve(dat=DEFAULT_DAT, offsets=CURVE_OFFSETS):
    """Surge restoring force -Fx(X) at the given offsets (and its odd cubic fit)."""
    x = np.array(offsets, dtype=float)
    r = np.array([-static_force((xi, 0.0, 0.0), dat)[0] for xi in x])
    # Odd fit R(X) = k1 X + k3 X^3 (the mooring is symmetric about X = 0, so R is odd).
    a = np.column_stack([x, x**3])
    (k1, k3), *_ = np.linalg.lstsq(a, r, rcond=None)
    return x, r, k1, k3


def measure(dat=DEFAULT_DAT):
    f0, f6, tens = static_force((0.0, 0.0, 0.0), dat, with_tensions=True)
    k = stiffness_matrix(dat)
    x, r, k1, k3 = surge_curve(dat)
    return {
        "dat": os.path.abspath(dat),
        "K": k.tolist(),
        "force_at_zero": f0.tolist(),
        "force6_at_zero": f6.tolist(),
        "fairlead_tensions": tens.tolist(),
        "surge_curve": {"X": x.tolist(), "restoring": r.tolist(), "k1": k1, "k3": k3},
    }


def report(res):
    k = np.array(res["K"])
    lines = []
    lines.append(f"MoorDyn file: {res['dat']}")
    lines.append("static stiffness about the neutral position (rows: Fx, Fy, Mz; columns: X, Y, theta)")
    lines.append("  units: N/m, N/m, N/rad (row Fx, Fy); N m/m, N m/m, N m/rad (row Mz)")
    for row in k:
        lines.append("  " + "  ".join(f"{v:12.4e}" for v in row))
    t = np.array(res["fairlead_tensions"])
    f6 = res["force6_at_zero"]
    lines.append(f"pretension at the mean position: fairlead tension {t.mean():.4e} N per line "
                 f"(min {t.min():.4e}, max {t.max():.4e}, {len(t)} lines)")
    lines.append(f"net line force at the mean position: Fx {f6[0]:.3e} N, Fy {f6[1]:.3e} N, "
                 f"Fz {f6[2]:.4e} N, Mz {f6[5]:.3e} N m")
    c = res["surge_curve"]
    lines.append("surge restoring curve R(X) = -Fx(X, 0, 0):")
    for xi, ri in zip(c["X"], c["restoring"]):
        lines.append(f"  X = {xi:5.1f} m  R = {ri:.4e} N  secant R/X = {ri / xi:.4e} N/m")
    lines.append(f"  odd cubic fit R = k1 X + k3 X^3: k1 = {c['k1']:.4e} N/m, k3 = {c['k3']:.4e} N/m^3")
    return "\n".join(lines)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--dat", default=DEFAULT_DAT, help="MoorDyn input file")
    p.add_argument("--json", action="store_true", help="print the results as JSON")
    a = p.parse_args(argv)
    res = measure(a.dat)
    print(json.dumps(res, indent=2) if a.json else report(res))
    return 0


if __name__ == "__main__":
    sys.exit(main())
