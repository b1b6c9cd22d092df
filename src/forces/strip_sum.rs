//! The strip sum of the Morison drag (E&S 8, 9; physics.md section 6): over a column's
//! strips, sum_j w_j |w_j| with w_j = u_j - offset, u_j the strip's horizontal velocity read
//! from the stored rows ([`StripRows`]: one row on a sample, the cubic stencil's four rows
//! between samples) and |.| the horizontal norm sqrt(x^2 + y^2).
//!
//! Three loops compute it, all in double precision on the single-precision rows: the
//! scalar loop (any CPU), and two packed loops chosen at run time by
//! `is_x86_feature_detected!` ([`StripKernel::detect`]): AVX-512F (8 strips a vector) and
//! AVX2 with FMA (4 strips a vector). The packed loops take the same terms in another order
//! and with fused multiply-adds, so they agree with the scalar loop to round-off (the tests
//! bound it at 1e-13 relative).
//!
//! This is the one file of `forces` with `unsafe` code, in two kinds, each stated where it
//! is used: calling a `#[target_feature]` function, only after the runtime check that the
//! CPU has the feature (a [`StripKernel`] holding a packed loop is only made by
//! [`StripKernel::detect`]); and the `std::arch` loads from a row, at offsets inside it.
#![allow(unsafe_code)]

use super::kinematics::StripRows;
use rustfft::num_complex::{Complex32, Complex64};

/// Which loop computes the strip sums; chosen once (a model's), then used at every stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StripKernel(Kind);

/// Private, so that a packed loop is never named without the runtime feature check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Scalar,
    #[cfg(target_arch = "x86_64")]
    Avx2Fma,
    #[cfg(target_arch = "x86_64")]
    Avx512,
}

impl StripKernel {
    /// The scalar loop, on any CPU.
    pub const SCALAR: StripKernel = StripKernel(Kind::Scalar);

    /// The widest loop this CPU runs: AVX-512F, else AVX2 with FMA, else the scalar loop.
    pub fn detect() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            if is_x86_feature_detected!("avx512f") {
                return StripKernel(Kind::Avx512);
            }
            if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
                return StripKernel(Kind::Avx2Fma);
            }
        }
        StripKernel::SCALAR
    }

    /// Every loop this CPU runs, the scalar loop first (the tests compare them).
    #[cfg(test)]
    fn available() -> Vec<Self> {
        let mut kernels = vec![StripKernel::SCALAR];
        #[cfg(target_arch = "x86_64")]
        {
            if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
                kernels.push(StripKernel(Kind::Avx2Fma));
            }
            if is_x86_feature_detected!("avx512f") {
                kernels.push(StripKernel(Kind::Avx512));
            }
        }
        kernels
    }

    /// sum_j w_j |w_j| (x, y) over the strips of `rows`, w_j = u_j - offset.
    #[inline(always)]
    pub fn sum(self, rows: StripRows, offset: [f64; 2]) -> [f64; 2] {
        match rows {
            StripRows::Sample(row) => self.run([row], [1.0], offset),
            StripRows::Between { rows, weights } => self.run(rows, weights, offset),
        }
    }

    #[inline(always)]
    fn run<const R: usize>(
        self,
        rows: [&[Complex32]; R],
        weights: [f64; R],
        offset: [f64; 2],
    ) -> [f64; 2] {
        match self.0 {
            Kind::Scalar => scalar(rows, weights, offset),
            // SAFETY: `Kind::Avx2Fma` is only made after `is_x86_feature_detected!` found
            // avx2 and fma.
            #[cfg(target_arch = "x86_64")]
            Kind::Avx2Fma => unsafe { x86::avx2_fma(rows, weights, offset) },
            // SAFETY: `Kind::Avx512` is only made after `is_x86_feature_detected!` found
            // avx512f.
            #[cfg(target_arch = "x86_64")]
            Kind::Avx512 => unsafe { x86::avx512(rows, weights, offset) },
        }
    }
}

/// Strips handled at a time by the scalar loop: their velocities and norms sit in buffers of
/// this length on the stack.
const CHUNK: usize = 32;

/// The number of strips every row has (the rows of one column all have the same).
#[inline]
fn strips<const R: usize>(rows: &[&[Complex32]; R]) -> usize {
    rows.iter().map(|r| r.len()).min().unwrap_or(0)
}

/// Strip j's velocity: the row's value on a sample (R = 1, exact), else
/// sum_r weights[r] rows[r][j] in stencil order (as `SamplePoint::interpolate_with`).
#[inline]
fn velocity<const R: usize>(rows: &[&[Complex32]; R], weights: &[f64; R], j: usize) -> Complex64 {
    let widen = |v: Complex32| Complex64::new(v.re.into(), v.im.into());
    if R == 1 {
        return widen(rows[0][j]);
    }
    let mut u = widen(rows[0][j]) * weights[0];
    for r in 1..R {
        u += widen(rows[r][j]) * weights[r];
    }
    u
}

/// The scalar loop: the strips' velocities and norms by chunks of [`CHUNK`], the norms in a
/// loop of their own that the compiler packs (sqrtpd), the terms summed in strip order.
fn scalar<const R: usize>(
    rows: [&[Complex32]; R],
    weights: [f64; R],
    offset: [f64; 2],
) -> [f64; 2] {
    let n = strips(&rows);
    let mut sum = [0.0; 2];
    let mut norms = [0.0; CHUNK];
    for first in (0..n).step_by(CHUNK) {
        let count = CHUNK.min(n - first);
        let w = |j: usize| {
            let u = velocity(&rows, &weights, first + j);
            [u.re - offset[0], u.im - offset[1]]
        };
        // sqrt(x^2 + y^2), not `hypot`: velocities cannot overflow the squares, and libm's
        // hypot is several times slower.
        for (j, n) in norms[..count].iter_mut().enumerate() {
            let [x, y] = w(j);
            *n = (x * x + y * y).sqrt();
        }
        for (j, n) in norms[..count].iter().enumerate() {
            let [x, y] = w(j);
            sum[0] += x * n;
            sum[1] += y * n;
        }
    }
    sum
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use super::{scalar, strips, Complex32};
    use std::arch::x86_64::*;

    /// The AVX-512F loop: 8 strips a vector, the last vector masked.
    #[target_feature(enable = "avx512f")]
    pub(super) fn avx512<const R: usize>(
        rows: [&[Complex32]; R],
        weights: [f64; R],
        offset: [f64; 2],
    ) -> [f64; 2] {
        let n = strips(&rows);
        // Lanes 0, 2, .. 14 (the x) and 1, 3, .. 15 (the y) of two vectors of 4 strips.
        let even = _mm512_set_epi64(14, 12, 10, 8, 6, 4, 2, 0);
        let odd = _mm512_set_epi64(15, 13, 11, 9, 7, 5, 3, 1);
        let (ox, oy) = (_mm512_set1_pd(offset[0]), _mm512_set1_pd(offset[1]));
        let (mut sx, mut sy) = (_mm512_setzero_pd(), _mm512_setzero_pd());
        for first in (0..n).step_by(8) {
            let count = (n - first).min(8);
            // The strips' 2 count floats, and the count strips.
            let floats = (((1u32 << (2 * count)) - 1) & 0xffff) as __mmask16;
            let lanes = ((1u32 << count) - 1) as __mmask8;
            let (mut ux, mut uy) = (_mm512_setzero_pd(), _mm512_setzero_pd());
            for r in 0..R {
                // SAFETY: `first < n <= rows[r].len()`, so the pointer is inside the row, and
                // the masked load reads only its next `count` strips (Complex32 is two f32,
                // `repr(C)`); masked-off lanes are not read and are zero.
                let v = unsafe {
                    _mm512_maskz_loadu_ps(floats, rows[r].as_ptr().add(first).cast::<f32>())
                };
                let lo = _mm512_cvtps_pd(_mm512_castps512_ps256(v));
                let hi = _mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd::<1>(
                    _mm512_castps_pd(v),
                )));
                let x = _mm512_permutex2var_pd(lo, even, hi);
                let y = _mm512_permutex2var_pd(lo, odd, hi);
                if R == 1 {
                    (ux, uy) = (x, y);
                } else {
                    let w = _mm512_set1_pd(weights[r]);
                    (ux, uy) = (_mm512_fmadd_pd(w, x, ux), _mm512_fmadd_pd(w, y, uy));
                }
            }
            let (wx, wy) = (_mm512_sub_pd(ux, ox), _mm512_sub_pd(uy, oy));
            let square = _mm512_fmadd_pd(wx, wx, _mm512_mul_pd(wy, wy));
            let norm = norm(square, lanes);
            sx = _mm512_fmadd_pd(wx, norm, sx);
            sy = _mm512_fmadd_pd(wy, norm, sy);
        }
        [_mm512_reduce_add_pd(sx), _mm512_reduce_add_pd(sy)]
    }

    /// sqrt(s) in the lanes of `lanes` whose s is not zero, else zero (so the lanes beyond
    /// the last strip add nothing), to within about an ulp, without the divider:
    /// y ~ 1/sqrt(s) to 2^-14 (vrsqrt14pd); one Goldschmidt step on r = s y ~ sqrt(s) and
    /// h = y/2 (r e, h e with e = 1/2 - r h: relative error ~2^-27); then Newton's step
    /// r + h (s - r^2) with the residual s - r^2 from one fused multiply-add (error
    /// ~2^-54 before the last rounding). A zero s gives y = 0, then r = 0 exactly. For the
    /// finite, normal velocities of a simulation (the state's bounds: simulation/bounds.rs).
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn norm(s: __m512d, lanes: __mmask8) -> __m512d {
        let positive = _mm512_mask_cmp_pd_mask::<_CMP_NEQ_OQ>(lanes, s, _mm512_setzero_pd());
        let y = _mm512_maskz_rsqrt14_pd(positive, s);
        let half = _mm512_set1_pd(0.5);
        let (r, h) = (_mm512_mul_pd(s, y), _mm512_mul_pd(half, y));
        let e = _mm512_fnmadd_pd(r, h, half);
        let (r, h) = (_mm512_fmadd_pd(r, e, r), _mm512_fmadd_pd(h, e, h));
        _mm512_fmadd_pd(h, _mm512_fnmadd_pd(r, r, s), r)
    }

    /// The AVX2 + FMA loop: 4 strips a vector, the last n mod 4 strips by the scalar loop.
    #[target_feature(enable = "avx2,fma")]
    pub(super) fn avx2_fma<const R: usize>(
        rows: [&[Complex32]; R],
        weights: [f64; R],
        offset: [f64; 2],
    ) -> [f64; 2] {
        let n = strips(&rows);
        let packed = n - n % 4;
        let (ox, oy) = (_mm256_set1_pd(offset[0]), _mm256_set1_pd(offset[1]));
        let (mut sx, mut sy) = (_mm256_setzero_pd(), _mm256_setzero_pd());
        for first in (0..packed).step_by(4) {
            let (mut ux, mut uy) = (_mm256_setzero_pd(), _mm256_setzero_pd());
            for r in 0..R {
                // SAFETY: `first + 4 <= packed <= rows[r].len()`: the 8 floats of strips
                // first..first + 4 are inside the row (Complex32 is two f32, `repr(C)`).
                let v = unsafe { _mm256_loadu_ps(rows[r].as_ptr().add(first).cast::<f32>()) };
                // (x0 y0 x1 y1), (x2 y2 x3 y3) -> (x0 x2 x1 x3), (y0 y2 y1 y3): the same strip
                // order for x and y.
                let lo = _mm256_cvtps_pd(_mm256_castps256_ps128(v));
                let hi = _mm256_cvtps_pd(_mm256_extractf128_ps::<1>(v));
                let (x, y) = (_mm256_unpacklo_pd(lo, hi), _mm256_unpackhi_pd(lo, hi));
                if R == 1 {
                    (ux, uy) = (x, y);
                } else {
                    let w = _mm256_set1_pd(weights[r]);
                    (ux, uy) = (_mm256_fmadd_pd(w, x, ux), _mm256_fmadd_pd(w, y, uy));
                }
            }
            let (wx, wy) = (_mm256_sub_pd(ux, ox), _mm256_sub_pd(uy, oy));
            let norm = _mm256_sqrt_pd(_mm256_fmadd_pd(wx, wx, _mm256_mul_pd(wy, wy)));
            sx = _mm256_fmadd_pd(wx, norm, sx);
            sy = _mm256_fmadd_pd(wy, norm, sy);
        }
        let tail = scalar(rows.map(|r| &r[packed..n]), weights, offset);
        [add_lanes(sx) + tail[0], add_lanes(sy) + tail[1]]
    }

    /// The sum of a vector's four lanes.
    #[target_feature(enable = "avx2")]
    fn add_lanes(v: __m256d) -> f64 {
        let pair = _mm_add_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd::<1>(v));
        _mm_cvtsd_f64(_mm_add_sd(pair, _mm_unpackhi_pd(pair, pair)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows of made-up velocities (a few m/s, both signs, some strips exactly at the offset
    /// so that |w| = 0), stored in single precision like the records.
    fn rows(strips: usize, seed: u32) -> Vec<Complex32> {
        (0..strips)
            .map(|j| {
                let a = (j as f32 + 1.0) * 0.37 + seed as f32;
                if j % 11 == 5 {
                    // w = 0 exactly with the offset below.
                    Complex32::new(0.5, -0.25)
                } else {
                    Complex32::new(3.0 * a.sin(), 2.0 * (1.7 * a).cos())
                }
            })
            .collect()
    }

    /// Every packed loop this CPU runs equals the scalar loop to round-off, on a sample and
    /// between samples, with the combined model's offset (w = u - U) and the separate model's
    /// (none), for strip counts below, at and above a vector (4, 8) and the scalar loop's
    /// chunk (32); and the scalar loop equals the sum written out strip by strip.
    #[test]
    fn packed_loops_equal_the_scalar_loop() {
        let kernels = StripKernel::available();
        assert_eq!(kernels[0], StripKernel::SCALAR);
        println!("strip kernels on this CPU: {kernels:?}");
        let counts = [
            0, 1, 3, 4, 5, 7, 8, 9, 15, 16, 17, 20, 31, 32, 33, 40, 64, 69,
        ];
        for strips in counts {
            let data: Vec<Vec<Complex32>> = (0..4).map(|r| rows(strips, r)).collect();
            let weights = [-0.0625, 0.5625, 0.5625, -0.0625];
            let cases = [
                StripRows::Sample(&data[0]),
                StripRows::Between {
                    rows: [&data[0], &data[1], &data[2], &data[3]],
                    weights,
                },
            ];
            for rows in cases {
                for offset in [[0.5, -0.25], [0.0, 0.0]] {
                    // Written out: u_j, w_j, |w_j| with hypot, strip by strip.
                    let mut want = [0.0; 2];
                    let mut scale = 0.0;
                    for j in 0..strips {
                        let u = match rows {
                            StripRows::Sample(row) => [row[j].re as f64, row[j].im as f64],
                            StripRows::Between { rows, weights } => {
                                let mut u = [0.0; 2];
                                for (row, w) in rows.iter().zip(weights) {
                                    u[0] += w * row[j].re as f64;
                                    u[1] += w * row[j].im as f64;
                                }
                                u
                            }
                        };
                        let w = [u[0] - offset[0], u[1] - offset[1]];
                        let m = w[0].hypot(w[1]);
                        want[0] += w[0] * m;
                        want[1] += w[1] * m;
                        scale += m * m;
                    }
                    let reference = StripKernel::SCALAR.sum(rows, offset);
                    for i in 0..2 {
                        assert!(
                            (reference[i] - want[i]).abs() <= 1e-13 * scale,
                            "scalar, {strips} strips, {rows:?}: {reference:?} vs {want:?}"
                        );
                    }
                    for kernel in &kernels {
                        let got = kernel.sum(rows, offset);
                        for i in 0..2 {
                            assert!(
                                (got[i] - reference[i]).abs() <= 1e-13 * scale,
                                "{kernel:?}, {strips} strips, offset {offset:?}, {rows:?}: \
                                 {got:?} vs {reference:?}"
                            );
                        }
                    }
                }
            }
        }
    }

    /// The detected loop is the widest the CPU runs, and never a loop it cannot run.
    #[test]
    fn the_detected_loop_is_the_widest_available() {
        assert_eq!(
            Some(&StripKernel::detect()),
            StripKernel::available().last()
        );
    }
}
