//! One-sided wave spectra S(omega) in m^2 s/rad (docs/theory.md#sea-state).

use crate::error::{require_finite, require_positive, Error, Result};
use crate::model::SpectrumKind;
use serde::Serialize;

/// A one-sided wave spectrum; m0 = integral of S d omega = Hs^2 / 16.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Spectrum {
    /// JONSWAP in the DNV-RP-C205 (sec. 3.5.5) form. `gamma = None` takes DNV's default.
    /// Not renormalised: A_gamma = 1 - 0.287 ln(gamma) is DNV's fit, so m0 differs from
    /// Hs^2/16 by up to about 2 % for 1 <= gamma <= 7.
    Jonswap {
        hs: f64,
        tp: f64,
        gamma: Option<f64>,
    },
    /// Pierson-Moskowitz: S = (5/16) Hs^2 wp^4 w^-5 exp(-(5/4)(w/wp)^-4).
    PiersonMoskowitz { hs: f64, tp: f64 },
    /// User table, linear interpolation, zero outside the table.
    Tabulated { omega: Vec<f64>, density: Vec<f64> },
}

impl Spectrum {
    /// Which of the spectra it is (`[sea] spectrum`).
    pub fn kind(&self) -> SpectrumKind {
        match self {
            Spectrum::Jonswap { .. } => SpectrumKind::Jonswap,
            Spectrum::PiersonMoskowitz { .. } => SpectrumKind::PiersonMoskowitz,
            Spectrum::Tabulated { .. } => SpectrumKind::Table,
        }
    }
}

/// Largest accepted peak enhancement factor: DNV-RP-C205 fits A_gamma for gamma up to 7;
/// 10 leaves room for narrow swell spectra while A_gamma stays well above zero (0.34).
const MAX_GAMMA: f64 = 10.0;

/// The steepest sea accepted, Hs / L_p: the deep-water breaking limit of a regular wave,
/// H / L = 1/7 (Michell 1893; 0.142). Measured irregular seas stay below about 1/10; a
/// steeper one is a mistake of units or digits (an Hs of 1e200 m overflows the force
/// records).
pub const MAX_STEEPNESS: f64 = 1.0 / 7.0;

/// DNV-RP-C205 3.5.5.5: gamma when none is given, from Tp / sqrt(Hs) (s / m^0.5).
pub fn dnv_default_gamma(hs: f64, tp: f64) -> f64 {
    let ratio = tp / hs.sqrt();
    if ratio <= 3.6 {
        5.0
    } else if ratio < 5.0 {
        (5.75 - 1.15 * ratio).exp()
    } else {
        1.0
    }
}

fn pierson_moskowitz(hs: f64, wp: f64, w: f64) -> f64 {
    if w <= 0.0 {
        return 0.0;
    }
    let r = wp / w;
    5.0 / 16.0 * hs * hs * wp.powi(4) * w.powi(-5) * (-1.25 * r.powi(4)).exp()
}

impl Spectrum {
    /// Spectral density at omega (rad/s), m^2 s/rad.
    pub fn density(&self, w: f64) -> f64 {
        match self {
            Spectrum::PiersonMoskowitz { hs, tp } => {
                pierson_moskowitz(*hs, 2.0 * std::f64::consts::PI / tp, w)
            }
            Spectrum::Jonswap { hs, tp, gamma } => {
                let wp = 2.0 * std::f64::consts::PI / tp;
                let gamma = gamma.unwrap_or_else(|| dnv_default_gamma(*hs, *tp));
                let sigma = if w <= wp { 0.07 } else { 0.09 };
                let a_gamma = 1.0 - 0.287 * gamma.ln();
                let peak = (-((w - wp).powi(2)) / (2.0 * sigma * sigma * wp * wp)).exp();
                a_gamma * pierson_moskowitz(*hs, wp, w) * gamma.powf(peak)
            }
            Spectrum::Tabulated { omega, density } => interpolate_table(omega, density, w),
        }
    }

    /// Significant wave height Hs, m: the parameter of the parametric spectra; for a table
    /// 4 sqrt(m0), m0 by the trapezoidal rule over the table.
    pub fn significant_height(&self) -> f64 {
        match self {
            Spectrum::Jonswap { hs, .. } | Spectrum::PiersonMoskowitz { hs, .. } => *hs,
            Spectrum::Tabulated { omega, density } => {
                let m0: f64 = omega
                    .windows(2)
                    .zip(density.windows(2))
                    .map(|(w, s)| 0.5 * (s[0] + s[1]) * (w[1] - w[0]))
                    .sum();
                4.0 * m0.sqrt()
            }
        }
    }

    /// Steepness Hs / L_p of the sea, L_p = 2 pi g / wp^2 the deep-water length of the peak
    /// wave (docs/theory.md#sea-state), for gravity `g` in m/s^2.
    pub fn steepness(&self, g: f64) -> f64 {
        let wp = self.peak_frequency();
        self.significant_height() * wp * wp / (2.0 * std::f64::consts::PI * g)
    }

    /// Peak frequency wp, rad/s (for a table: the frequency of the largest entry).
    pub fn peak_frequency(&self) -> f64 {
        match self {
            Spectrum::Jonswap { tp, .. } | Spectrum::PiersonMoskowitz { tp, .. } => {
                2.0 * std::f64::consts::PI / tp
            }
            Spectrum::Tabulated { omega, density } => {
                let (i, _) = density
                    .iter()
                    .enumerate()
                    .fold(
                        (0, f64::MIN),
                        |best, (i, &s)| if s > best.1 { (i, s) } else { best },
                    );
                omega[i]
            }
        }
    }

    /// Checks ranges and finiteness; the error names the field.
    pub fn validate(&self) -> Result<()> {
        match self {
            Spectrum::Jonswap { hs, tp, gamma } => {
                require_positive("sea.hs", *hs)?;
                require_positive("sea.tp", *tp)?;
                if let Some(g) = gamma {
                    require_finite("sea.gamma", *g)?;
                    if *g < 1.0 {
                        return Err(Error::invalid("sea.gamma", g, "must be at least 1"));
                    }
                    if *g > MAX_GAMMA {
                        return Err(Error::invalid(
                            "sea.gamma",
                            g,
                            format!(
                                "must be at most {MAX_GAMMA}: DNV's normalisation A_gamma = \
                                 1 - 0.287 ln(gamma) is fitted for 1 <= gamma <= 7 and is not \
                                 positive above 32.6"
                            ),
                        ));
                    }
                }
                Ok(())
            }
            Spectrum::PiersonMoskowitz { hs, tp } => {
                require_positive("sea.hs", *hs)?;
                require_positive("sea.tp", *tp)
            }
            Spectrum::Tabulated { omega, density } => validate_table(omega, density),
        }
    }
}

fn validate_table(omega: &[f64], density: &[f64]) -> Result<()> {
    if omega.len() < 2 {
        return Err(Error::invalid(
            "sea.omega",
            omega.len(),
            "a table needs at least 2 rows",
        ));
    }
    if omega.len() != density.len() {
        return Err(Error::invalid(
            "sea.density",
            density.len(),
            format!(
                "has a different length from sea.spectrum.omega ({})",
                omega.len()
            ),
        ));
    }
    for (i, (&w, &s)) in omega.iter().zip(density).enumerate() {
        require_positive(&format!("sea.omega[{i}]"), w)?;
        require_finite(format_args!("sea.density[{i}]"), s)?;
        if s < 0.0 {
            return Err(Error::invalid(
                format!("sea.density[{i}]"),
                s,
                "must not be negative",
            ));
        }
        if i > 0 && w <= omega[i - 1] {
            return Err(Error::invalid(
                format!("sea.omega[{i}]"),
                w,
                "frequencies must be strictly increasing",
            ));
        }
    }
    if density.iter().all(|&s| s == 0.0) {
        return Err(Error::invalid(
            "sea.density",
            "all zero",
            "the spectrum holds no energy",
        ));
    }
    Ok(())
}

/// Linear interpolation in a strictly increasing table; zero outside it.
fn interpolate_table(x: &[f64], y: &[f64], at: f64) -> f64 {
    if at < x[0] || at > x[x.len() - 1] {
        return 0.0;
    }
    let i = x.partition_point(|&v| v <= at).clamp(1, x.len() - 1);
    let s = (at - x[i - 1]) / (x[i] - x[i - 1]);
    y[i - 1] + s * (y[i] - y[i - 1])
}
