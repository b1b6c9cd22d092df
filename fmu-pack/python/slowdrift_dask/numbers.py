"""Floating-point conventions shared with the Rust tool (src/stats.rs, src/montecarlo/), so
that both write the same bytes.

- `rust_display(x)`: Rust's `{}` for f64: the shortest decimal digits that read back to the
  same double (Python's `repr` digits), written without an exponent and without a trailing
  `.0` (`3`, `-0`, `0.30000000000000004`, `1000000000000000000000`).
- `total(values)`: Rust's `Iterator::sum::<f64>()`: left to right from -0.0 (Python's
  `sum` compensates rounding from 3.12 on and starts at integer 0).
- `fmax`, `fmin`: Rust's `f64::max` and `f64::min` on finite values: +0.0 is the larger zero.
"""

import math
from decimal import Decimal


def rust_display(x):
    """`format!("{}", x)` of a Rust f64."""
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    text = format(Decimal(repr(x)), "f")
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return text


def total(values):
    """Sum left to right starting from -0.0, as Rust's `Sum for f64`."""
    acc = -0.0
    for v in values:
        acc += v
    return acc


def fmax(a, b):
    """Rust's `f64::max` for finite values (of two equal zeros, +0.0)."""
    if a != b:
        return a if a > b else b
    return a if math.copysign(1.0, a) > 0 else b


def fmin(a, b):
    """Rust's `f64::min` for finite values (of two equal zeros, -0.0)."""
    if a != b:
        return a if a < b else b
    return a if math.copysign(1.0, a) < 0 else b
