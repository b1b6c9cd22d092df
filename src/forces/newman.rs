//! Slowly varying records by Newman's approximation, evaluated as products of single sums
//! with FFTs (E&S 3, 4; docs/theory.md#the-slowly-varying-force,
//! docs/theory.md#wave-drift-damping-and-current).
//!
//! The full low-frequency double sum is
//!   F(t) = Re sum_i sum_j a_i a_j* T_ij e^{i (omega_i - omega_j) t}.
//! Newman's approximation builds T_ij from the diagonal T_i = T(omega_i, omega_i):
//! - geometric (the paper's E&S 4): T_ij = sqrt(T_i T_j) where the signs agree and 0 where
//!   they differ, so F = |P+|^2 - |P-|^2 with P+- = sum_{+-T_i > 0} a_i sqrt(|T_i|) e^{i omega_i t};
//! - arithmetic: T_ij = (T_i + T_j)/2, so F = Re[Q eta_c*] with Q = sum a_i T_i e^{i omega_i t}
//!   and eta_c = sum a_i e^{i omega_i t}.
//!
//! Both have the mean sum |a_i|^2 T_i -> 2 integral S T d omega. The same construction gives
//! the time-varying damping B_ij(t) from b_ij(omega). For a spread sea this module builds
//! each direction's own double sum; the cross terms between directions are added by
//! `forces::directional`.

use super::synthesis::Synthesizer;
use super::transfer::DirectionTransfer;
use crate::model::NewmanForm;
use rustfft::num_complex::Complex64;

/// Scratch buffers for building slowly varying records, reused for every record.
#[derive(Clone)]
pub struct NewmanBuilder {
    coefficients: Vec<Complex64>,
    series: Vec<Complex64>,
}

/// One record's diagonal transfer T_i (at every component of the grid) prepared for
/// Newman's form once per case, so that a seed's build takes no square root (the same bits:
/// sqrt(|T_i|) is the root the geometric form took of sign T_i).
#[derive(Debug, Clone, PartialEq)]
pub enum Diagonal {
    /// T_i = 0 at every component: no record.
    Zero,
    /// The geometric form (E&S 4): sign(T_i) sqrt(|T_i|) at every component, and whether
    /// any T_i is positive (the series P+) or negative (P-).
    Geometric {
        roots: Vec<f64>,
        positive: bool,
        negative: bool,
    },
    /// The arithmetic form: T_i itself.
    Arithmetic(Vec<f64>),
}

impl Diagonal {
    /// `transfer` (T_i at every component) prepared for `form`.
    pub fn new(form: NewmanForm, transfer: &[f64]) -> Self {
        if transfer.iter().all(|&t| t == 0.0) {
            return Diagonal::Zero;
        }
        match form {
            NewmanForm::Geometric => Diagonal::Geometric {
                roots: transfer
                    .iter()
                    .map(|&t| t.abs().sqrt().copysign(t))
                    .collect(),
                positive: transfer.iter().any(|&t| t > 0.0),
                negative: transfer.iter().any(|&t| t < 0.0),
            },
            NewmanForm::Arithmetic => Diagonal::Arithmetic(transfer.to_vec()),
        }
    }
}

/// One wave direction's coefficients ([`DirectionTransfer`]) prepared for Newman's form:
/// the drift T_i (surge, sway, yaw) and, when wave-drift damping is on, the b_ij.
#[derive(Debug, Clone, PartialEq)]
pub struct NewmanTransfer {
    pub drift: [Diagonal; 3],
    pub damping: Option<[[Diagonal; 3]; 3]>,
}

impl NewmanTransfer {
    /// `transfer` prepared for `form`.
    pub fn new(form: NewmanForm, transfer: &DirectionTransfer) -> Self {
        NewmanTransfer {
            drift: transfer.drift.each_ref().map(|t| Diagonal::new(form, t)),
            damping: transfer.damping.as_ref().map(|b| {
                b.each_ref()
                    .map(|row| row.each_ref().map(|t| Diagonal::new(form, t)))
            }),
        }
    }

    /// Every direction's `transfers` prepared for `form`.
    pub fn all(form: NewmanForm, transfers: &[DirectionTransfer]) -> Vec<Self> {
        transfers.iter().map(|t| Self::new(form, t)).collect()
    }
}

impl NewmanBuilder {
    /// Buffers for a grid of `count` components; the arithmetic form's series is sized on
    /// its first use, to the synthesizer's output length (the geometric form needs none).
    pub fn new(count: usize) -> Self {
        NewmanBuilder {
            coefficients: vec![Complex64::default(); count],
            series: Vec::new(),
        }
    }

    /// Sizes the series buffer to `synth`'s output length.
    fn size_series(&mut self, synth: &Synthesizer) {
        self.series.resize(synth.output_len(), Complex64::default());
    }

    /// Adds one direction's slowly varying record for the diagonal transfer `diagonal` to
    /// `out`, which takes the first contribution's samples as they are and stays empty if
    /// the transfer is zero. `amplitudes` are the direction's a_i and `eta_c` its complex
    /// elevation series sum a_i e^{i omega_i t_m} (used by the arithmetic form).
    pub fn accumulate(
        &mut self,
        synth: &mut Synthesizer,
        amplitudes: &[Complex64],
        eta_c: &[Complex64],
        diagonal: &Diagonal,
        out: &mut Vec<f64>,
    ) {
        match diagonal {
            Diagonal::Zero => {}
            Diagonal::Geometric {
                roots,
                positive,
                negative,
            } => {
                for (sign, present) in [(1.0, positive), (-1.0, negative)] {
                    if *present {
                        self.fill_signed(amplitudes, roots, sign);
                        // sign |P|^2 added as the transform's joined samples come.
                        let to = AddTo::new(out);
                        let mut sink = AddSquares { sign, to };
                        synth.complex_series_into(&self.coefficients, &mut sink);
                    }
                }
            }
            Diagonal::Arithmetic(transfer) => {
                for ((c, a), t) in self.coefficients.iter_mut().zip(amplitudes).zip(transfer) {
                    *c = a * t;
                }
                self.size_series(synth);
                synth.complex_series(&self.coefficients, &mut self.series);
                let products = self
                    .series
                    .iter()
                    .zip(eta_c)
                    .map(|(q, e)| (q * e.conj()).re);
                AddTo::new(out).extend(products);
            }
        }
    }

    /// Adds one direction's force records D_i (surge, sway, yaw) for its transfer's T_i.
    pub fn accumulate_force(
        &mut self,
        synth: &mut Synthesizer,
        amplitudes: &[Complex64],
        eta_c: &[Complex64],
        transfer: &NewmanTransfer,
        force: &mut [Vec<f64>; 3],
    ) {
        for (out, t) in force.iter_mut().zip(&transfer.drift) {
            self.accumulate(synth, amplitudes, eta_c, t, out);
        }
    }

    /// Adds one direction's damping records B_ij for its transfer's b_ij (nothing when the
    /// transfer has no damping).
    pub fn accumulate_damping(
        &mut self,
        synth: &mut Synthesizer,
        amplitudes: &[Complex64],
        eta_c: &[Complex64],
        transfer: &NewmanTransfer,
        damping: &mut [[Vec<f64>; 3]; 3],
    ) {
        let Some(b) = &transfer.damping else {
            return;
        };
        for (out_row, b_row) in damping.iter_mut().zip(b) {
            for (out, t) in out_row.iter_mut().zip(b_row) {
                self.accumulate(synth, amplitudes, eta_c, t, out);
            }
        }
    }

    /// Coefficients a_i sqrt(sign T_i) where sign T_i > 0, else 0, from the signed roots
    /// sign(T_i) sqrt(|T_i|).
    fn fill_signed(&mut self, amplitudes: &[Complex64], roots: &[f64], sign: f64) {
        for ((c, a), &r) in self.coefficients.iter_mut().zip(amplitudes).zip(roots) {
            let root = sign * r;
            *c = if root > 0.0 {
                a * root
            } else {
                Complex64::default()
            };
        }
    }
}

/// A sink that adds the samples it takes to a record, in order: a record with no
/// contribution yet (empty) takes them as they are, without first being filled with zeros.
struct AddTo<'a> {
    out: &'a mut Vec<f64>,
    /// Whether `out` had no contribution before this record.
    first: bool,
    /// The next sample's index.
    at: usize,
}

impl<'a> AddTo<'a> {
    fn new(out: &'a mut Vec<f64>) -> Self {
        let first = out.is_empty();
        AddTo { out, first, at: 0 }
    }
}

impl Extend<f64> for AddTo<'_> {
    fn extend<I: IntoIterator<Item = f64>>(&mut self, samples: I) {
        if self.first {
            self.out.extend(samples);
        } else {
            let mut taken = 0;
            for (o, v) in self.out[self.at..].iter_mut().zip(samples) {
                *o += v;
                taken += 1;
            }
            self.at += taken;
        }
    }
}

/// A sink that adds `sign` |p|^2 of each complex sample p it takes to a record ([`AddTo`]).
struct AddSquares<'a> {
    sign: f64,
    to: AddTo<'a>,
}

impl Extend<Complex64> for AddSquares<'_> {
    fn extend<I: IntoIterator<Item = Complex64>>(&mut self, values: I) {
        let sign = self.sign;
        self.to
            .extend(values.into_iter().map(|p| sign * p.norm_sqr()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The geometric form's signed roots and signs present, by hand; a zero transfer makes
    /// no record in either form; the arithmetic form keeps T_i.
    #[test]
    fn a_diagonal_is_prepared_for_its_form() {
        let t = [4.0, -9.0, 0.0, 2.25, -0.0];
        assert_eq!(
            Diagonal::new(NewmanForm::Geometric, &t),
            Diagonal::Geometric {
                roots: vec![2.0, -3.0, 0.0, 1.5, -0.0],
                positive: true,
                negative: true,
            }
        );
        assert_eq!(
            Diagonal::new(NewmanForm::Geometric, &[0.0, 1e-300, 0.25]),
            Diagonal::Geometric {
                roots: vec![0.0, 1e-150, 0.5],
                positive: true,
                negative: false,
            }
        );
        for form in [NewmanForm::Geometric, NewmanForm::Arithmetic] {
            assert_eq!(Diagonal::new(form, &[0.0, -0.0]), Diagonal::Zero);
        }
        assert_eq!(
            Diagonal::new(NewmanForm::Arithmetic, &t),
            Diagonal::Arithmetic(t.to_vec())
        );
    }
}
