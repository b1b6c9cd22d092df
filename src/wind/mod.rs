//! The wind field's physics (docs/theory.md#wind): the one-sided gust spectra of the wind
//! speed ([`GustSpectrum`], m^2/s^2 per Hz, and per rad/s as the wave spectra) and the mean
//! wind profile to the height of the wind force ([`WindProfile`]), each with the mean speed
//! it is defined for (averaging period and height) and its source.
//!
//! Direction convention (docs/theory.md#conventions): the wind's direction is the one it
//! blows towards, from +X counter-clockwise, as the waves' and the current's. The gust
//! records, the wind force and the `[wind]` configuration come later; the settings named by
//! the errors here (`wind.speed`, `wind.height`, ...) are the keys that section will have.

mod field;
mod load;
mod profile;
mod spectrum;

pub use field::{WindField, DEFAULT_AIR_DENSITY, DEFAULT_DRAG_COEFFICIENT};
pub use load::{CoefficientTable, WindArea, WindCoefficients, WindForce, WindLoad};

pub use profile::{
    npd_mean, npd_turbulence_intensity, WindProfile, NPD_REFERENCE_HEIGHT, NPD_REFERENCE_PERIOD,
};
pub use spectrum::{
    api_turbulence_intensity, iec_length_scale, GustSpectrum, API_PEAK_CONSTANT, DAVENPORT_LENGTH,
    HARRIS_LENGTH, NPD_EXPONENT,
};
