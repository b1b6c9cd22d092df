//! The computations behind the paper's studies (E&S 1996, section 5, Figs 7-15), apart
//! from any plotting: what `slowdrift study` draws.
//!
//! - [`distribution`]: histogram estimate of a probability density, the Gaussian density,
//!   box-plot statistics (quartiles, Tukey whiskers), the sample standard deviation and the
//!   least-squares slope of a log-log law (the scatter of a record-length statistic falls
//!   like `L^-1/2`).
//! - [`waves`]: the wave elevation record of a configuration (Figs 7, 8).
//! - [`motion_spectra`]: the slow drift's and the wave-frequency motion's spectra in the
//!   frequency domain, and a run's motion record (`slowdrift study motion`).
//! - [`blocks`]: statistics per consecutive block of a record (the transient, Fig. 11).
//! - [`parallel_map`]: runs independent simulations on the crate's thread pool.

pub mod blocks;
pub mod distribution;
pub mod motion_spectra;
pub mod waves;

/// `f(0), ..., f(count - 1)` on `threads` threads, in index order (the crate's pool,
/// [`crate::parallel::map`]): the independent simulations of a study.
pub use crate::parallel::map as parallel_map;
