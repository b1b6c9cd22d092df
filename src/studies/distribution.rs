//! Distributions of samples: histogram density, Gaussian density, box-plot statistics,
//! standard deviation, log-log slope.

use crate::error::numbers::written;
use crate::error::{require_finite, Error, Result};

/// A histogram normalised as a probability density.
#[derive(Debug, Clone, PartialEq)]
pub struct Histogram {
    /// Bin edges, `bins + 1` increasing values, in the units of the samples.
    pub edges: Vec<f64>,
    /// `count_b / (n * width_b)` per bin, with n all the samples (also those outside the
    /// edges): the integral over the bins is the share of samples inside them.
    pub density: Vec<f64>,
}

impl Histogram {
    /// The centre of bin `b`.
    pub fn centre(&self, b: usize) -> f64 {
        0.5 * (self.edges[b] + self.edges[b + 1])
    }
}

/// Histogram density of `values` over `bins` equal bins on `[lo, hi]` (the last bin
/// includes `hi`).
///
/// Errors: no values, a non-finite value, `bins` = 0, or not `lo < hi`.
pub fn histogram_pdf(values: &[f64], lo: f64, hi: f64, bins: usize) -> Result<Histogram> {
    require_samples("histogram.values", values)?;
    require_finite("histogram.lo", lo)?;
    require_finite("histogram.hi", hi)?;
    if bins == 0 {
        return Err(Error::invalid("histogram.bins", bins, "must be at least 1"));
    }
    if lo >= hi {
        return Err(Error::invalid(
            "histogram.hi",
            hi,
            format!("must exceed histogram.lo = {}", written(lo)),
        ));
    }
    let width = (hi - lo) / bins as f64;
    let mut counts = vec![0usize; bins];
    for &v in values {
        if (lo..=hi).contains(&v) {
            counts[(((v - lo) / width) as usize).min(bins - 1)] += 1;
        }
    }
    let n = values.len() as f64;
    Ok(Histogram {
        edges: (0..=bins).map(|b| lo + b as f64 * width).collect(),
        density: counts.iter().map(|&c| c as f64 / (n * width)).collect(),
    })
}

/// The Gaussian density with mean `mean` and standard deviation `std` at `x`.
pub fn gaussian_pdf(x: f64, mean: f64, std: f64) -> f64 {
    let z = (x - mean) / std;
    (-0.5 * z * z).exp() / (std * (2.0 * std::f64::consts::PI).sqrt())
}

/// Box-plot statistics of a sample (Tukey's box plot).
#[derive(Debug, Clone, PartialEq)]
pub struct BoxStats {
    pub n: usize,
    /// First quartile, median and third quartile: the sample quantiles at p = 0.25, 0.5,
    /// 0.75 by linear interpolation between order statistics, x_(1 + p (n - 1)) (Hyndman &
    /// Fan 1996 definition 7, the default of R and NumPy).
    pub q1: f64,
    pub median: f64,
    pub q3: f64,
    /// The whiskers: the smallest and largest samples within 1.5 interquartile ranges of
    /// the box (Tukey 1977).
    pub lower_whisker: f64,
    pub upper_whisker: f64,
    /// The samples beyond the whiskers, increasing.
    pub outliers: Vec<f64>,
}

impl BoxStats {
    /// The interquartile range q3 - q1.
    pub fn iqr(&self) -> f64 {
        self.q3 - self.q1
    }
}

/// Tukey whisker reach, in interquartile ranges beyond the box.
const WHISKER_REACH: f64 = 1.5;

/// Box-plot statistics of `values` (any order). Errors: no values or a non-finite value.
pub fn box_stats(values: &[f64]) -> Result<BoxStats> {
    require_samples("box_stats.values", values)?;
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let quantile = |p: f64| {
        let h = p * (sorted.len() - 1) as f64;
        let (i, frac) = (h.floor() as usize, h - h.floor());
        match sorted.get(i + 1) {
            Some(next) => sorted[i] + frac * (next - sorted[i]),
            None => sorted[i],
        }
    };
    let (q1, median, q3) = (quantile(0.25), quantile(0.5), quantile(0.75));
    let (fence_lo, fence_hi) = (
        q1 - WHISKER_REACH * (q3 - q1),
        q3 + WHISKER_REACH * (q3 - q1),
    );
    let inside = || {
        sorted
            .iter()
            .copied()
            .filter(|v| (fence_lo..=fence_hi).contains(v))
    };
    Ok(BoxStats {
        n: sorted.len(),
        q1,
        median,
        q3,
        lower_whisker: inside().fold(f64::INFINITY, f64::min),
        upper_whisker: inside().fold(f64::NEG_INFINITY, f64::max),
        outliers: sorted
            .iter()
            .copied()
            .filter(|v| !(fence_lo..=fence_hi).contains(v))
            .collect(),
    })
}

/// The sample standard deviation sqrt(sum (x - mean)^2 / (n - 1)). Errors: fewer than two
/// values or a non-finite value.
pub fn sample_std(values: &[f64]) -> Result<f64> {
    require_samples("sample_std.values", values)?;
    if values.len() < 2 {
        return Err(Error::invalid(
            "sample_std.values",
            values.len(),
            "needs at least 2 values",
        ));
    }
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    Ok((values.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt())
}

/// The least-squares slope b of ln y = a + b ln x (a power law y ~ x^b). Errors: fewer
/// than two points, lengths that differ, a value that is not positive and finite, or all
/// x equal.
pub fn log_log_slope(x: &[f64], y: &[f64]) -> Result<f64> {
    if x.len() != y.len() || x.len() < 2 {
        return Err(Error::invalid(
            "log_log_slope.points",
            format!("{} x, {} y", x.len(), y.len()),
            "needs at least 2 (x, y) pairs",
        ));
    }
    for (name, values) in [("log_log_slope.x", x), ("log_log_slope.y", y)] {
        if let Some(v) = values.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
            return Err(Error::invalid(name, v, "must be positive and finite"));
        }
    }
    let (lx, ly): (Vec<f64>, Vec<f64>) = x.iter().zip(y).map(|(a, b)| (a.ln(), b.ln())).unzip();
    let n = lx.len() as f64;
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxx: f64 = lx.iter().map(|a| (a - mx).powi(2)).sum();
    if sxx == 0.0 {
        return Err(Error::invalid("log_log_slope.x", x[0], "all x are equal"));
    }
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    Ok(sxy / sxx)
}

fn require_samples(field: &str, values: &[f64]) -> Result<()> {
    if values.is_empty() {
        return Err(Error::invalid(field, "[]", "is empty"));
    }
    match values.iter().position(|v| !v.is_finite()) {
        Some(i) => Err(Error::invalid(
            format!("{field}[{i}]"),
            values[i],
            "must be finite",
        )),
        None => Ok(()),
    }
}
