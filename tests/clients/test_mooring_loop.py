"""Closed mooring loop: SlowDrift.fmu with its internal stiffness switched off,
moored by MoorDyn (mooring/spread_mooring.dat) through Fx_ext, Fy_ext, Mz_ext,
for the FMU's default experiment (three hours, 1 s communication steps, default sea: JONSWAP
Hs 7 m, Tp 12 s, head seas). Coupling scheme: explicit Gauss-Seidel, see mooring_loop.py.
The runs are the session fixture glue_runs (conftest.py), which test_system_masters.py
compares the co-simulation masters with.

Checks: the moored platform stays bounded, and its mean offset after the transient agrees
with a second FMU run whose internal linear stiffness is the mooring's measured static
stiffness diagonal (mooring_stiffness.py), within the tolerance of mean_offset.py (the
catenary's nonlinearity and the scatter of a 3-hour mean).
The explicit coupling adds a numerical damping of about 0.7 % of critical and no mean force.
"""

import numpy as np

import mean_offset
from mooring_loop import slow_part

BOUND = 100.0  # m, |X| and |Y|: a physical bound (the 3-hour maximum is ~10-20 m)
BOUND_YAW = 0.5  # rad


def test_loop_is_bounded(glue_runs):
    rec = glue_runs["moored"]
    assert np.all(np.isfinite(rec)), "NaN or infinity in the coupled run"
    assert np.max(np.abs(rec[:, 1])) < BOUND and np.max(np.abs(rec[:, 2])) < BOUND
    assert np.max(np.abs(rec[:, 3])) < BOUND_YAW
    # The loop is closed: the platform moves, and the mooring force's slow part (the
    # fairleads also follow the wave-frequency motion) follows it.
    x, fx = rec[:, 1], slow_part(rec[:, 7], glue_runs["dt"])
    assert np.std(x) > 0.1
    assert np.corrcoef(x, fx)[0, 1] < -0.9, "mooring force not restoring (sign or index error?)"


def test_mean_offset_matches_linear_stiffness(glue_runs, stiffness):
    diff, tol, report = mean_offset.check(glue_runs["moored"], glue_runs["linear"],
                                          glue_runs["K"], stiffness, glue_runs["dt"])
    print("\n" + report)
    assert abs(diff) <= tol
    # Head seas: no sway and no yaw in either run.
    keep = glue_runs["moored"][:, 0] >= mean_offset.TRANSIENT
    for rec in (glue_runs["moored"], glue_runs["linear"]):
        assert abs(np.mean(rec[keep, 2])) < 0.05 and abs(np.mean(rec[keep, 3])) < 1e-3
