"""The moored platform run by co-simulation masters from the system files:
libcosim on OspSystemStructure.xml, ecos and fmpy on MooredPlatform.ssp, three hours each
(SlowDrift's default experiment, 1 s macro step, default sea, seed 1), against the fmpy-glue
loop of mooring_loop.py (the same FMUs, the same sea: SlowDrift's records depend on the
seed, not on the stop time, so a master that passes the SSD's stop time of 10800 s and one
that passes none, as libcosim and the glue loop, run the same sea).

How the schemes differ, and what agreement they allow:
- libcosim, ecos and fmpy's SSP master are Jacobi masters: every model steps from the same
  communication point t_n with the inputs set at t_n, and the outputs are passed on after
  the step. SlowDrift therefore holds over its step the line force at t_n (the mooring's
  output after the previous step, at t_0 its output after initialisation), where the
  Gauss-Seidel glue loop of test_mooring_loop.py gives it the force at t_n + dt (the mooring
  steps first). The Jacobi variant of the glue loop (run_loop(scheme="jacobi"), with the
  mooring FMU) makes the same calls with the same values as these masters, so each master's
  run must equal it bit for bit: every state and every held force, all 10800 steps. Any
  difference (a parameter or a connection the master ignored, another ordering, a step
  stamped differently) fails. fmpy's SSP master starts every connector at 0, so the mooring
  it runs starts from the origin at rest rather than from the platform's whole motion at
  t_0 (which has wave-frequency heave and pitch): its reference is the Jacobi loop started
  so (run_loop(zero_start=True)).
- The Jacobi and Gauss-Seidel loops differ by one step of delay in the force: for the lines'
  surge stiffness K the Gauss-Seidel loop's force leads the mid-step force by dt / 2 (a
  numerical damping + K dt / 2), the Jacobi loop's lags by dt / 2 (- K dt / 2): damping
  ratios of +- zeta_c = +- pi dt / (2 T_n) = +- 0.76 % at the 207 s surge period. Neither
  moves the mean, so the two means agree within the scatter of the mean of their paired
  difference (3 standard deviations, mean_offset.py's estimate). The Jacobi loop is the less
  damped: its surge rms is larger, by at most sqrt((zeta + zeta_c) / (zeta - zeta_c)) for a
  resonant response of total damping zeta; with zeta of at least 5 % (E&S's slow-drift
  damping of a few percent plus the lines' drag; mean_offset.ZETA) that is 1.17, and the
  quasi-static part of the response, which the delay does not change, makes it smaller.
- Each master's run stays bounded and its mean offset matches the lines' static stiffness
  as the glue loop's does (mean_offset.check against the same linear run).
- Every master is called as a user calls it, with no parameter set named (#27 part 3):
  ecos applies an SSD parameter set only when told its name, and fmpy's simulate_ssp never
  applies an SSD's parameter bindings, so the system relies on none. Its SlowDrift.fmu has
  no internal mooring by construction (the reference loop gets the same by setting the
  default FMU's stiffness to 0: a second route); a platform moored twice would fail the
  comparison (its mean surge would halve: 2.45 m instead of 4.91 m before this was fixed).
"""

import time

import numpy as np
import pytest

import mean_offset
import system_masters as sm
from mooring_loop import (LINES_ONLY, FmuBody, MooringFmu, default_experiment, mean_scatter,
                          run_loop, slow_part)
from system_files import system_dir

MASTERS = ("libcosim", "ecos", "fmpy")
BOUND = 100.0  # m, as test_mooring_loop.py
BOUND_YAW = 0.5  # rad
# The lower bound of the total surge damping ratio (mean_offset.ZETA) and the natural period
# of the platform on the lines (measured stiffness 1.469e5 N/m, mass + added mass 1.60e8 kg).
T_SURGE = 2.0 * np.pi * np.sqrt(mean_offset.M_SURGE / 1.4686e5)


@pytest.fixture(scope="module")
def steps(fmu):
    duration, dt = default_experiment(fmu)
    assert dt == 1.0
    return int(round(duration / dt))


@pytest.fixture(scope="module")
def jacobi(fmu, mooring_fmu, steps):
    """The glue loop in the Jacobi scheme, SlowDrift moored by Mooring.fmu through fmpy."""
    with FmuBody(fmu, LINES_ONLY, instance_name="jacobi") as body:
        return run_loop(body, float(steps), 1.0, dat=None, mooring=MooringFmu, scheme="jacobi")


@pytest.fixture(scope="module")
def jacobi_from_zero(fmu, mooring_fmu, steps):
    """The Jacobi glue loop with the mooring started from inputs 0, as fmpy's SSP master
    starts every connector (the platform's whole motion at t_0 is not 0: its wave-frequency
    heave and pitch)."""
    with FmuBody(fmu, LINES_ONLY, instance_name="jacobi-zero") as body:
        return run_loop(body, float(steps), 1.0, dat=None, mooring=MooringFmu, scheme="jacobi",
                        zero_start=True)


@pytest.fixture(scope="module")
def runs(fmu, mooring_fmu, steps):
    system = system_dir(fmu)
    out = {}
    for name, runner in (("libcosim", sm.libcosim), ("ecos", sm.ecos), ("fmpy", sm.fmpy_ssp)):
        t0 = time.perf_counter()
        out[name] = runner(system, steps)
        print(f"\n{name}: {steps} steps of 1 s in {time.perf_counter() - t0:.1f} s")
    return out


@pytest.mark.parametrize("master", MASTERS)
def test_master_equals_the_jacobi_glue_loop(runs, jacobi, jacobi_from_zero, master):
    reference = jacobi_from_zero if master == "fmpy" else jacobi
    assert sm.differences(runs[master], sm.Run.from_record(reference)) == []
    assert np.max(np.abs(runs[master].states[:, 0])) > 1.0, "the platform moves"


@pytest.mark.parametrize("master", MASTERS)
def test_master_bounded_with_the_static_stiffness_offset(runs, glue_runs, stiffness, master):
    rec = runs[master].record()
    assert np.all(np.isfinite(rec))
    assert np.max(np.abs(rec[:, 1:3])) < BOUND and np.max(np.abs(rec[:, 3])) < BOUND_YAW
    slow_force = slow_part(rec[:-1, 7], glue_runs["dt"])
    assert np.corrcoef(rec[:-1, 1], slow_force)[0, 1] < -0.9, "the line force restores"
    diff, tol, report = mean_offset.check(rec, glue_runs["linear"], glue_runs["K"], stiffness,
                                          glue_runs["dt"], label=master)
    print(f"\n{master}: {report}")
    assert abs(diff) <= tol


def test_gauss_seidel_and_jacobi_differ_by_one_step_of_delay(jacobi, glue_runs):
    dt = glue_runs["dt"]
    keep = jacobi[:, 0] >= mean_offset.TRANSIENT
    xj, xg = jacobi[keep, 1], glue_runs["moored"][keep, 1]
    sd = mean_scatter(xj - xg, dt, mean_offset.correlation_time(glue_runs["K"][0, 0]))
    zeta_c = np.pi * dt / (2.0 * T_SURGE)
    z = mean_offset.ZETA
    ratio, bound = np.std(xj) / np.std(xg), np.sqrt((z + zeta_c) / (z - zeta_c))
    # The total damping a purely resonant response would need for the measured ratio.
    implied = zeta_c * (ratio**2 + 1) / (ratio**2 - 1) if ratio > 1 else float("inf")
    print(f"\nsurge after {mean_offset.TRANSIENT:.0f} s: Jacobi mean {xj.mean():.3f} m rms "
          f"{np.std(xj):.3f} m, Gauss-Seidel mean {xg.mean():.3f} m rms {np.std(xg):.3f} m; "
          f"mean difference {xj.mean() - xg.mean():+.4f} m (3 sd = {3 * sd:.3f} m); rms ratio "
          f"{ratio:.4f} (1 < ratio <= {bound:.3f}: coupling damping +-{100 * zeta_c:.2f} % on a "
          f"total of at least {100 * z:.0f} %; a purely resonant response would imply "
          f"{100 * implied:.1f} %)")
    assert abs(xj.mean() - xg.mean()) <= 3.0 * sd
    assert 1.0 < ratio <= bound


def test_the_masters_report_no_internal_stiffness(runs):
    """libcosim and ecos report the system's SlowDrift stiffness as 0 with nothing set (fmpy
    reports no parameter values)."""
    for master in ("libcosim", "ecos"):
        assert runs[master].stiffness == (0.0, 0.0, 0.0), master
