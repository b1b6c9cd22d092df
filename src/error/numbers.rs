//! How messages write numbers, one rule for every message of the crate and the tool:
//!
//! - [`written`]: a value a user gave (a setting, an input), in the shortest form that reads
//!   back to the same double, plain from 0.001 to a million and with an exponent beyond:
//!   `3`, `0.25`, `16384`, `1e308`, `1e-300`, `2e7` (never 300 digits, and 1e308 is not
//!   `inf`).
//! - [`readable`]: a value the code computed (a time, a period, a ratio, a limit), rounded to
//!   six significant digits and then written as [`written`] writes: `4047.97`,
//!   `2.81029e-150`, `0.0748`.
//! - [`typable_below`]: a value a user can type that is just under a strict bound, for
//!   advice (`time_step = 3.14 or less` under 2 pi / 2 rad/s).
//! - [`Shown`]: what [`crate::error::Error::invalid`] takes as the value it names: a number
//!   [`written`], text as it is.

/// `v` as a user wrote it: the shortest decimal that reads back to the same double, plain
/// for 0 and 0.001 <= |v| < 1e6, else with an exponent.
pub fn written(v: f64) -> String {
    if v == 0.0 || !v.is_finite() || (1e-3..1e6).contains(&v.abs()) {
        v.to_string()
    } else {
        format!("{v:e}")
    }
}

/// `v` to six significant digits, written as [`written`] writes.
pub fn readable(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return written(v);
    }
    let rounded = format!("{v:.5e}").parse().unwrap_or(v);
    written(rounded)
}

/// A value with three significant digits a user can type, strictly below the positive
/// `bound` (the largest such one): the advice for a setting that must stay under it.
pub fn typable_below(bound: f64) -> String {
    if !(bound.is_finite() && bound > 0.0) {
        return written(bound);
    }
    // The text is what the user types: it must read back below the bound.
    let below = |unit: f64| {
        let mut steps = (bound / unit).floor();
        while readable(steps * unit)
            .parse::<f64>()
            .is_ok_and(|v| v >= bound)
        {
            steps -= 1.0;
        }
        steps
    };
    let mut unit = 10f64.powi(bound.log10().floor() as i32 - 2);
    let mut steps = below(unit);
    if steps < 100.0 {
        // Under a power of ten: three digits of the decade below (99.9 under 100).
        unit /= 10.0;
        steps = below(unit);
    }
    readable(steps * unit)
}

/// A list of values, each as [`written`] writes it: `[0, 1e308, NaN]`.
pub fn written_list(values: &[f64]) -> String {
    let entries: Vec<String> = values.iter().map(|v| written(*v)).collect();
    format!("[{}]", entries.join(", "))
}

/// A 3 x 3 matrix, its entries as [`written`] writes them: `[[1, 0, 0], [0, 2e7, 0], ...]`.
pub fn written_matrix(m: &[[f64; 3]; 3]) -> String {
    let rows: Vec<String> = m.iter().map(|row| written_list(row)).collect();
    format!("[{}]", rows.join(", "))
}

/// The complex number `re + i im`, its parts as [`written`] writes them: `0.5 - 2e-7i`.
pub fn written_complex(re: f64, im: f64) -> String {
    let sign = if im.is_sign_negative() { '-' } else { '+' };
    format!("{} {sign} {}i", written(re), written(im.abs()))
}

/// A value as an error message names it.
pub trait Shown {
    fn shown(&self) -> String;
}

impl Shown for f64 {
    fn shown(&self) -> String {
        written(*self)
    }
}

impl Shown for str {
    fn shown(&self) -> String {
        self.to_string()
    }
}

impl Shown for String {
    fn shown(&self) -> String {
        self.clone()
    }
}

impl<T: Shown + ?Sized> Shown for &T {
    fn shown(&self) -> String {
        (**self).shown()
    }
}

macro_rules! shown_as_text {
    ($($t:ty),*) => {
        $(impl Shown for $t {
            fn shown(&self) -> String {
                self.to_string()
            }
        })*
    };
}

shown_as_text!(usize, u64, u32, i64, i32, bool);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_users_value_reads_as_written() {
        for (v, text) in [
            (3.0, "3"),
            (0.25, "0.25"),
            (-1.0, "-1"),
            (16384.0, "16384"),
            (89500.0, "89500"),
            (123456789.0, "1.23456789e8"),
            (1e-4, "1e-4"),
            (2e7, "2e7"),
            (1e308, "1e308"),
            (f64::MAX, "1.7976931348623157e308"),
            (1e-300, "1e-300"),
            (0.001, "0.001"),
            (0.1 + 0.2, "0.30000000000000004"),
            (0.0, "0"),
            (f64::INFINITY, "inf"),
            (f64::NAN, "NaN"),
        ] {
            assert_eq!(written(v), text, "{v:e}");
            assert_eq!(v.shown(), text, "{v:e}");
        }
    }

    #[test]
    fn a_matrix_reads_as_written() {
        let m = [[8e4, 0.0, -0.5], [0.0, 1e308, 0.0], [0.0, 0.0, 7.7e7]];
        assert_eq!(
            written_matrix(&m),
            "[[80000, 0, -0.5], [0, 1e308, 0], [0, 0, 7.7e7]]"
        );
    }

    #[test]
    fn a_complex_value_reads_as_written() {
        assert_eq!(written_complex(0.5, -2e-7), "0.5 - 2e-7i");
        assert_eq!(written_complex(-1.0, 3.0), "-1 + 3i");
    }

    #[test]
    fn a_computed_value_reads_to_six_digits() {
        for (v, text) in [
            (4047.972558331423, "4047.97"),
            (2.810292e-150, "2.81029e-150"),
            (2.0 * std::f64::consts::PI, "6.28319"),
            (0.07479999999999999, "0.0748"),
            (10800.0, "10800"),
            (3.288402e7, "3.2884e7"),
            (4.503599627370496e9, "4.5036e9"),
            (7.909957934414479e305, "7.90996e305"),
            (-0.5, "-0.5"),
            (0.0, "0"),
        ] {
            assert_eq!(readable(v), text, "{v:e}");
        }
    }

    #[test]
    fn advice_is_a_value_under_the_bound() {
        for (bound, text) in [
            (std::f64::consts::PI, "3.14"),
            (3.0, "2.99"),
            (0.07479, "0.0747"),
            (100.0, "99.9"),
            (2.5e-5, "2.49e-5"),
        ] {
            assert_eq!(typable_below(bound), text, "{bound}");
            assert!(text.parse::<f64>().unwrap() < bound);
        }
    }
}
