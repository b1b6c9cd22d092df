"""Closed mooring loop (issue #4): SlowDrift.fmu with its internal stiffness switched off,
moored by MoorDyn (mooring/spread_mooring.dat) through Fx_ext, Fy_ext, Mz_ext,
for the FMU's default experiment (three hours, 1 s communication steps, default sea: JONSWAP
Hs 7 m, Tp 12 s, head seas). Coupling scheme: explicit, see mooring_loop.py.

Checks: the moored platform stays bounded, and its mean offset after the transient agrees
with a second FMU run whose internal linear stiffness is the mooring's measured static
stiffness diagonal (mooring_stiffness.py), within a tolerance built from
  - the catenary's nonlinearity over the offsets the loop visits: the mean satisfies
    k1 <X> + k3 <X^3> = <F_drift> instead of K <X> = <F_drift>, so the moored mean is lower by
    about k3 <X^3> / k1 (k1, k3 from the odd cubic fit of the measured restoring curve), plus the
    curve's departure from that fit (seabed nodes lifting off one by one) and the difference
    between the tangent K11 the linear run uses and k1;
  - the statistical scatter of a 3-hour mean: for a correlated record the standard deviation
    of the mean is about rms sqrt(2 T_corr / T) with T_corr ~ 1 / (zeta w_n). Both runs see the
    same wave record (same seed), so the scatter that matters is that of the difference of the
    two records, d = X_moored - X_linear (different damping and nonlinearity decorrelate them
    only partly); 3 standard deviations of mean(d) are allowed. zeta = 0.05 (E&S's slow-drift
    damping of a few percent plus MoorDyn's line drag, about 7 % at 10 m amplitude in surge);
    a smaller zeta means a longer T_corr and a wider tolerance. The unpaired estimate (rms of X
    itself) is printed for comparison.
The explicit coupling adds a numerical damping of about 0.7 % of critical and no mean force.
"""

import os
import time

import numpy as np
import pytest

from mooring_loop import COLUMNS, REPO, FmuBody, mean_scatter, run_free, run_loop

TRANSIENT = 2000.0  # s, discarded before the statistics (ten surge periods)
BOUND = 100.0  # m, |X| and |Y|: a physical bound (the 3-hour maximum is ~10-20 m)
BOUND_YAW = 0.5  # rad
ZETA = 0.05
# src/scenario/default.toml: surge mass + low-frequency added mass (for w_n = sqrt(K / M)).
M_SURGE = 9.9737e7 + 6.0417e7


def default_experiment(path):
    from fmpy import read_model_description

    de = read_model_description(path).defaultExperiment
    stop = float(de.stopTime) if de is not None and de.stopTime is not None else 10800.0
    step = float(de.stepSize) if de is not None and de.stepSize is not None else 1.0
    return stop, step


@pytest.fixture(scope="module")
def runs(fmu, stiffness):
    k = np.array(stiffness["K"])
    duration, dt = default_experiment(fmu)
    t0 = time.perf_counter()
    with FmuBody(fmu, {"stiffnessSurge": 0.0, "stiffnessSway": 0.0, "stiffnessYaw": 0.0},
                 instance_name="moored") as body:
        moored = run_loop(body, duration, dt)
    t1 = time.perf_counter()
    with FmuBody(fmu, {"stiffnessSurge": k[0, 0], "stiffnessSway": k[1, 1], "stiffnessYaw": k[2, 2]},
                 instance_name="linear") as body:
        linear = run_free(body, duration, dt)
    t2 = time.perf_counter()
    out = os.path.join(REPO, "target", "client-tests")
    os.makedirs(out, exist_ok=True)
    for name, rec in (("mooring_loop_moored.csv", moored), ("mooring_loop_linear.csv", linear)):
        np.savetxt(os.path.join(out, name), rec, delimiter=",", header=",".join(COLUMNS), comments="")
    print(f"\nmooring loop: {duration:.0f} s in steps of {dt:g} s; moored run {t1 - t0:.1f} s, "
          f"linear run {t2 - t1:.1f} s (records in {out})")
    return {"moored": moored, "linear": linear, "K": k, "dt": dt}


def test_loop_is_bounded(runs):
    rec = runs["moored"]
    assert np.all(np.isfinite(rec)), "NaN or infinity in the coupled run"
    assert np.max(np.abs(rec[:, 1])) < BOUND and np.max(np.abs(rec[:, 2])) < BOUND
    assert np.max(np.abs(rec[:, 3])) < BOUND_YAW
    # The loop is closed: the platform moves, and the mooring force follows it.
    x, fx = rec[:, 1], rec[:, 7]
    assert np.std(x) > 0.1
    assert np.corrcoef(x, fx)[0, 1] < -0.9, "mooring force not restoring (sign or index error?)"


def test_mean_offset_matches_linear_stiffness(runs, stiffness):
    dt, k = runs["dt"], runs["K"]
    keep = runs["moored"][:, 0] >= TRANSIENT
    xm = runs["moored"][keep, 1]
    xl = runs["linear"][keep, 1]
    assert len(xm) == len(xl) and len(xm) > 1000

    c = stiffness["surge_curve"]
    k1, k3 = c["k1"], c["k3"]
    xs, rs = np.array(c["X"]), np.array(c["restoring"])
    # Nonlinearity: bias of the mean, the curve's departure from the cubic fit over the
    # visited range, and tangent K11 (central difference at +-1 m) against k1.
    bias = k3 * np.mean(xm**3) / k1
    reach = max(np.max(np.abs(xm)), xs[0])
    resid = np.max(np.abs(rs - (k1 * xs + k3 * xs**3))[xs <= reach]) / k1
    tangent = abs(k[0, 0] - k1) / k1 * abs(np.mean(xl))
    # Statistics of the 3-hour mean.
    wn = np.sqrt(k[0, 0] / M_SURGE)
    t_corr = 1.0 / (ZETA * wn)
    sd_paired = mean_scatter(xm - xl, dt, t_corr)
    sd_unpaired = mean_scatter(xl, dt, t_corr)
    tol = abs(bias) + resid + tangent + 3.0 * sd_paired

    diff = np.mean(xm) - np.mean(xl)
    # For information: batch-means estimate of the scatter of mean(d) (8 blocks of ~1100 s).
    blocks = np.array([b.mean() for b in np.array_split(xm - xl, 8)])
    sd_batch = blocks.std(ddof=1) / np.sqrt(len(blocks))
    print(f"\nsurge after {TRANSIENT:.0f} s: moored mean {np.mean(xm):.3f} m (rms {np.std(xm):.3f} m), "
          f"linear mean {np.mean(xl):.3f} m (rms {np.std(xl):.3f} m)")
    print(f"difference {diff:+.3f} m; tolerance {tol:.3f} m = |nonlinear bias| {abs(bias):.3f} "
          f"(predicted shift {-bias:+.3f}) + fit residual {resid:.3f} + tangent/k1 {tangent:.3f} "
          f"+ 3 x {sd_paired:.3f} (paired scatter, T_corr {t_corr:.0f} s); "
          f"unpaired scatter of one mean {sd_unpaired:.3f} m; batch-means scatter of mean(d) {sd_batch:.3f} m")
    assert abs(diff) <= tol
    # Head seas: no sway and no yaw in either run.
    for rec in (runs["moored"], runs["linear"]):
        assert abs(np.mean(rec[keep, 2])) < 0.05 and abs(np.mean(rec[keep, 3])) < 1e-3
