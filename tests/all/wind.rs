//! The wind's gust records against their spectra, each through the public API: the Welch
//! spectrum of a long stream of gust records in bands against the integral of the gust
//! spectrum (docs/theory.md#wind), for spectra of three shapes.

use crate::common::{simpson, welch_bands_match};
use slowdrift::forces::{plan_inverse_fft, GustStream, Record, Segments};
use slowdrift::sea_state::FrequencyGrid;
use slowdrift::wind::GustSpectrum;

/// 96 joined segments of 2048 samples at 0.5 s (27 hours): the Welch estimate (segments of
/// 1024 samples, Hann, 50 % overlap) in bands of 8 bins from 0.05 to 2.5 rad/s within five
/// standard deviations of Welch's scatter (plus 3 % for the join's ramps and the bins' own
/// width) of the integral of S_u per rad/s over each band, for NPD, Kaimal and Harris.
#[test]
fn gust_records_have_their_spectrum() {
    let segments = Segments {
        block: 2048,
        ramp: 256,
    };
    let dt = 0.5;
    let grid = FrequencyGrid::new(0.0, segments.span() as f64 * dt, dt, (0.3, 1.0)).unwrap();
    let spectra = [
        GustSpectrum::Npd {
            speed: 25.0,
            height: 40.0,
        },
        GustSpectrum::Kaimal {
            speed: 15.0,
            turbulence_intensity: 0.12,
            length_scale: 340.0,
        },
        GustSpectrum::Harris {
            speed: 20.0,
            drag_coefficient: 0.002,
        },
    ];
    for spectrum in spectra {
        let mut gusts = GustStream::new(&spectrum, &grid, segments, plan_inverse_fft(&grid));
        let mut record = Record::zero();
        let mut samples = Vec::new();
        for k in 0..96 {
            gusts.build(21, k, k > 0, &mut record);
            samples.extend_from_slice(&record.samples()[1..1 + segments.block]);
        }
        let (checked, worst) =
            welch_bands_match(&samples, dt, 1024, 8, (0.05, 2.5), 0.03, |a, b| {
                simpson(|w| spectrum.density_per_rad(w), a, b, 64)
            });
        assert!(checked >= 20, "{spectrum:?}: {checked} bands");
        println!("{spectrum:?}: {checked} bands, worst {worst:.2} sd");
    }
}
