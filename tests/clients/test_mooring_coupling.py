"""The coupling code of the mooring loop, checked with a Python rigid body in place of the
FMU (the FMU loop itself is test_mooring_loop.py): free decay of the default platform's
surge and yaw inertia on the MoorDyn mooring must oscillate with the period the measured
static stiffness predicts, and decay (mooring-line drag), which fails if a sign, an index
or the DOF order in the coupling were wrong."""

import numpy as np

from mooring_loop import run_loop

# src/scenario/default.toml: mass + low-frequency added mass; yaw inertia + added inertia.
M_SURGE = 9.9737e7 + 6.0417e7
I_YAW = 1.8898e11 + 6.4807e10


class RigidBody:
    """Planar rigid body, force held constant over a step (exact for a constant force),
    no hydrodynamic damping: only the mooring acts on it."""

    def __init__(self, q0):
        self.q = np.array(q0, dtype=float)
        self.qd = np.zeros(3)
        self.f = np.zeros(3)
        self.m = np.array([M_SURGE, M_SURGE, I_YAW])

    def state(self):
        return self.q.copy(), self.qd.copy()

    def set_force(self, f):
        self.f = np.array(f, dtype=float)

    def do_step(self, t, dt):
        a = self.f / self.m
        self.q += self.qd * dt + 0.5 * a * dt * dt
        self.qd += a * dt


def crossing_period(t, x):
    """Mean period between the first and last upward zero crossings (linear interpolation)."""
    i = np.nonzero((x[:-1] < 0.0) & (x[1:] >= 0.0))[0]
    tc = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
    assert len(tc) >= 3, "fewer than two full cycles"
    return (tc[-1] - tc[0]) / (len(tc) - 1)


def test_surge_free_decay(stiffness):
    k = stiffness["K"][0][0]
    rec = run_loop(RigidBody((5.0, 0.0, 0.0)), duration=900.0)
    t, x = rec[:, 0], rec[:, 1]
    assert np.all(np.isfinite(rec))
    t_pred = 2 * np.pi * np.sqrt(M_SURGE / k)
    t_meas = crossing_period(t, x)
    print(f"surge: period {t_meas:.1f} s, predicted {t_pred:.1f} s from K11 = {k:.4e} N/m")
    assert abs(t_meas - t_pred) < 0.03 * t_pred
    # Decays (line drag), never grows: the last cycle's amplitude is below the initial 5 m.
    assert np.max(np.abs(x[t > t[-1] - t_pred])) < 5.0
    assert np.max(np.abs(x)) <= 5.0 + 1e-9
    assert np.max(np.abs(rec[:, 2])) < 1e-6 and np.max(np.abs(rec[:, 3])) < 1e-8


def test_yaw_free_decay(stiffness):
    k = stiffness["K"][2][2]
    th0 = 0.02
    rec = run_loop(RigidBody((0.0, 0.0, th0)), duration=600.0)
    t, th = rec[:, 0], rec[:, 3]
    assert np.all(np.isfinite(rec))
    t_pred = 2 * np.pi * np.sqrt(I_YAW / k)
    t_meas = crossing_period(t, th)
    print(f"yaw: period {t_meas:.1f} s, predicted {t_pred:.1f} s from K66 = {k:.4e} N m/rad")
    assert abs(t_meas - t_pred) < 0.03 * t_pred
    assert np.max(np.abs(th)) <= th0 + 1e-12
    assert np.max(np.abs(rec[:, 1])) < 1e-3 and np.max(np.abs(rec[:, 2])) < 1e-3
