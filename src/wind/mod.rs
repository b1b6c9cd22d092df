//! The wind field's physics (docs/theory.md#wind): the one-sided gust spectra of the wind
//! speed ([`GustSpectrum`], m^2/s^2 per Hz, and per rad/s as the wave spectra) and the mean
//! wind profile to the height of the wind force ([`WindProfile`]), each with the mean speed
//! it is defined for (averaging period and height) and its source.
//!
//! Direction convention (docs/theory.md#conventions): the wind's direction is the one it
//! blows towards, from +X counter-clockwise, as the waves' and the current's. The settings
//! named by the errors here (`wind.speed`, `wind.drag_coefficient`, ...) are the keys of the
//! `[wind]` section (docs/configuration.md#wind); `wind.height` is the height of the wind
//! force. The gust records and the wind force come later.

mod field;
mod load;
mod profile;
mod spectrum;

pub use field::{WindField, DEFAULT_AIR_DENSITY, DEFAULT_DRAG_COEFFICIENT};
pub use load::{CoefficientTable, WindArea, WindCoefficients, WindForce, WindLoad};

pub use profile::{
    npd_mean, npd_turbulence_intensity, WindProfile, DEFAULT_POWER_LAW_EXPONENT,
    DEFAULT_ROUGHNESS_LENGTH, NPD_REFERENCE_HEIGHT, NPD_REFERENCE_PERIOD,
};
pub use spectrum::{
    api_turbulence_intensity, iec_length_scale, GustSpectrum, API_PEAK_CONSTANT, DAVENPORT_LENGTH,
    HARRIS_LENGTH, NPD_EXPONENT,
};
