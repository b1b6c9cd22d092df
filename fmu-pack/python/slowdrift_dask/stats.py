"""The statistics of `slowdrift montecarlo`, operation for operation (same roundings):

- `summarize` is `slowdrift::stats::summarize`: the samples at t = m dt >= transient
  (m = 0, 1, ... from the start of the run), their mean, the rms about the mean (population
  standard deviation, two passes), max and min.
- `run_statistics` is the end of `slowdrift::montecarlo::run_seed`: surge and sway in m,
  yaw converted from rad to deg by the factor 180 / pi.
- `seed_statistics` is `slowdrift::montecarlo::seed_statistics`: the mean over seeds and
  its standard error s / sqrt(n), s the sample standard deviation (n - 1); None for n < 2.
"""

import math

from .numbers import fmax, fmin, total

DEGREES_PER_RADIAN = 180.0 / math.pi


class StatisticsError(ValueError):
    """A record the statistics refuse (the Rust tool's `Error::InvalidValue` text)."""


def summarize(record, dt, transient):
    """(mean, rms, max, min) of `record` (sampled every dt s) after `transient` s."""
    for m, x in enumerate(record):
        if not math.isfinite(x):
            raise StatisticsError(f"invalid stats.record[{m}] = {x}: must be a finite number")
    first = next((m for m in range(len(record)) if m * dt >= transient), None)
    if first is None:
        raise StatisticsError(
            f"invalid stats.transient = {transient}: leaves no sample: the record has "
            f"{len(record)} samples at dt = {dt} s")
    kept = record[first:]
    n = float(len(kept))
    mean = total(kept) / n
    variance = total((x - mean) * (x - mean) for x in kept) / n
    high, low = -math.inf, math.inf
    for x in kept:
        high, low = fmax(high, x), fmin(low, x)
    return mean, math.sqrt(variance), high, low


def run_statistics(surge, sway, yaw, dt, transient):
    """The 12 numbers of one run, in the runs file's order: mean, rms, max, min of surge (m),
    sway (m) and yaw (deg; `yaw` in rad)."""
    out = list(summarize(surge, dt, transient)) + list(summarize(sway, dt, transient))
    out += [v * DEGREES_PER_RADIAN for v in summarize(yaw, dt, transient)]
    return out


def seed_statistics(values):
    """(mean, standard error or None) of one statistic over seeds; None when empty."""
    if not values:
        return None
    n = len(values)
    mean = total(values) / n
    if n < 2:
        return mean, None
    variance = total((x - mean) * (x - mean) for x in values) / (n - 1)
    return mean, math.sqrt(variance / n)
