"""The moored platform's mean offset against its mooring's static stiffness, one
check shared by the fmpy-glue loop (test_mooring_loop.py) and the masters that run the
coupled system (test_system_masters.py).

A moored run (SlowDrift with its internal stiffness off, moored by MoorDyn's lines) and a
linear run (SlowDrift with its internal stiffness set to the lines' measured static
stiffness diagonal, mooring_stiffness.py) see the same wave record (same seed). After the
transient their mean surge offsets must agree within a tolerance built from
  - the catenary's nonlinearity over the offsets the loop visits: the mean satisfies
    k1 <X> + k3 <X^3> = <F_drift> instead of K <X> = <F_drift>, so the moored mean is lower by
    about k3 <X^3> / k1 (k1, k3 from the odd cubic fit of the measured restoring curve), plus the
    curve's departure from that fit (seabed nodes lifting off one by one) and the difference
    between the tangent K11 the linear run uses and k1;
  - the statistical scatter of a 3-hour mean: for a correlated record the standard deviation
    of the mean is about rms sqrt(2 T_corr / T) with T_corr ~ 1 / (zeta w_n). Both runs see the
    same wave record, so the scatter that matters is that of the difference of the two
    records, d = X_moored - X_linear (different damping and nonlinearity decorrelate them
    only partly); 3 standard deviations of mean(d) are allowed. zeta = 0.05 (E&S's slow-drift
    damping of a few percent plus MoorDyn's line drag, about 7 % at 10 m amplitude in surge);
    a smaller zeta means a longer T_corr and a wider tolerance.
"""

import numpy as np

from mooring_loop import mean_scatter

TRANSIENT = 2000.0  # s, discarded before the statistics (ten surge periods)
ZETA = 0.05
# src/scenario/default.toml: surge mass + low-frequency added mass (for w_n = sqrt(K / M)).
M_SURGE = 9.9737e7 + 6.0417e7


def correlation_time(k11):
    """T_corr = 1 / (zeta w_n) of the surge response for the stiffness k11 (N/m)."""
    return 1.0 / (ZETA * np.sqrt(k11 / M_SURGE))


def check(moored, linear, k, stiffness, dt, label="moored"):
    """Compares the mean surge of two records (columns t, X, ... as mooring_loop.COLUMNS)
    after TRANSIENT. Returns (difference, tolerance, report)."""
    keep = moored[:, 0] >= TRANSIENT
    xm = moored[keep, 1]
    xl = linear[linear[:, 0] >= TRANSIENT, 1]
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
    t_corr = correlation_time(k[0, 0])
    sd_paired = mean_scatter(xm - xl, dt, t_corr)
    sd_unpaired = mean_scatter(xl, dt, t_corr)
    tol = abs(bias) + resid + tangent + 3.0 * sd_paired

    diff = np.mean(xm) - np.mean(xl)
    # For information: batch-means estimate of the scatter of mean(d) (8 blocks of ~1100 s).
    blocks = np.array([b.mean() for b in np.array_split(xm - xl, 8)])
    sd_batch = blocks.std(ddof=1) / np.sqrt(len(blocks))
    report = (
        f"surge after {TRANSIENT:.0f} s: {label} mean {np.mean(xm):.3f} m (rms {np.std(xm):.3f} m), "
        f"linear mean {np.mean(xl):.3f} m (rms {np.std(xl):.3f} m)\n"
        f"difference {diff:+.3f} m; tolerance {tol:.3f} m = |nonlinear bias| {abs(bias):.3f} "
        f"(predicted shift {-bias:+.3f}) + fit residual {resid:.3f} + tangent/k1 {tangent:.3f} "
        f"+ 3 x {sd_paired:.3f} (paired scatter, T_corr {t_corr:.0f} s); "
        f"unpaired scatter of one mean {sd_unpaired:.3f} m; batch-means scatter of mean(d) {sd_batch:.3f} m")
    return diff, tol, report
