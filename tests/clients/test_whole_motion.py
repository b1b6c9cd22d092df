"""The mooring driven by the platform's whole motion (issue #29 section 4), measured in
libcosim on target/fmu/system/OspSystemStructure.xml: the default platform in the default
sea (seed 1), three hours at 1 s, MoorDyn's dynamic lines, with SlowDrift's wave-frequency
motion on (waveFrequencyMotion = 1, the start value) and off (0, set as an initial value).

Printed (pytest -s): the largest fairlead tension's mean, standard deviation and maximum
after the transient, the most loaded line's, and the slow-drift surge mean and rms, for
both runs. Asserted, each from an independent route:
- off, the totals are the slow drift: X_total = X and Z_total = 0 at every step (the
  mooring then sees the planar motion, as before the totals existed);
- on, the mooring follows the wave-frequency motion: Z_total moves with the heave of the
  default platform's RAOs, whose rms is set by its spectrum; the fairleads' wave-frequency
  motion stretches the lines at wave frequencies, so the tension's standard deviation grows
  (dynamic tension, absent from a mooring that follows the slow drift alone);
- the lines' drag under the fairleads' wave-frequency motion damps the slow drift (Huse's
  mooring-line damping): in the same sea the slow-drift surge varies less about its mean;
- the slow drift's mean offset stays the lines' static one within the scatter of a mean:
  the wave-frequency motion has zero mean and the slow-drift equations take the lines'
  horizontal force as before.

Reproduce the numbers of docs/coupling.md:
    SLOWDRIFT_FMU=$PWD/target/fmu/SlowDrift.fmu bash tests/clients/run_clients.sh -k whole_motion -s
"""

import numpy as np
import pytest

import mean_offset
from mooring_loop import mean_scatter
from system_files import system_dir
from system_masters import STEP_NS

STEPS = 10800
TRANSIENT = int(mean_offset.TRANSIENT)  # samples at 1 s
# Correlation time of the slow-drift surge (the lines' 207 s period, 5 % damping).
T_CORR = mean_offset.correlation_time(1.4686e5)
LINES = 8
TENSIONS = [f"fairleadTension{n}" for n in range(1, LINES + 1)]
SLOW = ("X", "Y", "theta")
TOTAL = ("X_total", "Z_total", "pitch_total")


def run(system, motion):
    """(SlowDrift's series, the mooring's series) of a libcosim run with waveFrequencyMotion
    = motion (None: as the FMU starts)."""
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver

    log_output_level(CosimLogLevel.WARNING)
    ex = CosimExecution.from_osp_config_file(osp_path=system)
    index = {s.name.decode(): s.index for s in ex.slave_infos()}
    vr = {sim: {v.name.decode(): v.reference for v in ex.slave_variables(i)}
          for sim, i in index.items()}
    if motion is not None:
        assert ex.integer_initial_value(index["slowdrift"],
                                        vr["slowdrift"]["waveFrequencyMotion"], motion)
    series = CosimObserver.create_time_series(buffer_size=STEPS + 1)
    assert ex.add_observer(observer=series)
    observed = {"slowdrift": SLOW + TOTAL, "mooring": tuple(TENSIONS) + ("fairleadTensionMax",)}
    for sim, names in observed.items():
        for name in names:
            assert series.start_time_series(index[sim], vr[sim][name], CosimVariableType.REAL)
    assert ex.simulate_until(target_time=STEPS * STEP_NS)
    assert ex.status().error_code == 0

    def samples(sim, name):
        _t, numbers, values = series.time_series_real_samples(
            index[sim], vr[sim][name], from_step=1, sample_count=STEPS)
        assert list(numbers) == list(range(1, STEPS + 1)), name
        return np.array(values)

    return ({n: samples("slowdrift", n) for n in observed["slowdrift"]},
            {n: samples("mooring", n) for n in observed["mooring"]})


@pytest.fixture(scope="module")
def runs(fmu):
    system = system_dir(fmu)
    return {"on": run(system, None), "off": run(system, 0)}


def statistics(x):
    kept = x[TRANSIENT:]
    return kept.mean(), kept.std(), kept.max()


def test_the_whole_motion_drives_the_lines(runs):
    (on, lines_on), (off, lines_off) = runs["on"], runs["off"]
    # Off: the totals are the slow drift.
    assert np.array_equal(off["X_total"], off["X"])
    assert np.all(off["Z_total"] == 0.0)
    # On: the platform heaves (its RAOs on the default sea) and the lines see it.
    heave = on["Z_total"][TRANSIENT:].std()
    assert heave > 0.1, f"heave rms {heave} m"
    rows = []
    for label, slow, lines in (("with", on, lines_on), ("without", off, lines_off)):
        busiest = max(TENSIONS, key=lambda n: lines[n][TRANSIENT:].mean())
        surge = slow["X"][TRANSIENT:]
        rows.append((label, statistics(lines["fairleadTensionMax"]), busiest,
                     statistics(lines[busiest]), surge.mean(), np.sqrt(np.mean(surge ** 2)),
                     surge.std()))
    print("\nwave-frequency motion | largest fairlead tension mean, std, max (MN) | "
          "most loaded line: mean, std, max (MN) | slow-drift surge mean, rms, std (m)")
    for label, (m, s, x), busiest, (bm, bs, bx), mean, rms, std in rows:
        print(f"{label:<8} | {m / 1e6:.3f} {s / 1e6:.3f} {x / 1e6:.3f} | {busiest}: "
              f"{bm / 1e6:.3f} {bs / 1e6:.3f} {bx / 1e6:.3f} | {mean:.3f} {rms:.3f} {std:.3f}")
    print(f"heave rms with the motion {heave:.3f} m")
    with_std, without_std = rows[0][1][1], rows[1][1][1]
    # Dynamic tension from the fairleads' wave-frequency motion.
    assert with_std > without_std, (with_std, without_std)
    # The lines' drag under the wave-frequency motion damps the slow drift (Huse's
    # mooring-line damping): the same sea, less slow-drift surge about its mean.
    assert rows[0][6] < rows[1][6], (rows[0][6], rows[1][6])
    # The mean offset: the same static lines, within the scatter of the mean of each run.
    scatter = [mean_scatter(x["X"][TRANSIENT:], 1.0, T_CORR) for x in (on, off)]
    assert abs(rows[0][4] - rows[1][4]) < 3.0 * np.hypot(*scatter), (rows, scatter)
