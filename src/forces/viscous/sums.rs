//! The drag's strip sum sum_j w_j |w_j| (w_j = u_j - offset) of one column at one instant,
//! in single precision: [`StripSums`] defines it, and every route computes that definition
//! bit for bit: one seed's row (the scalar code) and four seeds' rows side by side
//! ([`lane_sums`], the seeds in lanes), whichever instruction set runs them ([`Isa`]).

// The one unsafe call: the AVX2 build of the lanes' sums, made only where the CPU has AVX2.
#![allow(unsafe_code)]

use crate::forces::isa::Isa;
use crate::forces::viscous::LANES;

/// The strip sum sum_j w_j |w_j| (w_j = u_j - offset) in single precision, the one
/// definition every route computes:
/// - the offset (double) rounded to single precision once; each strip's velocity as stored
///   (single precision) or, between samples, interpolated in double and rounded;
/// - per strip, w = u - offset, |w| = sqrt(w_x * w_x + w_y * w_y) (two products, a sum, the
///   root) and the products w_x |w|, w_y |w|, each operation rounded to single precision
///   (no fused multiply-add, which Rust never makes on its own);
/// - the even strips (0, 2, ...) summed in one accumulator and the odd ones in another,
///   each in strip order, the two added (even + odd) at the end, then widened to double
///   (exactly).
///
/// Error against the exact sum of the same stored velocities and the double offset o, to
/// first order in u = 2^-24: each term's w within u (|o| + |u_j| + |w_j|) per component
/// (the offset's and an interpolated velocity's rounding, then the subtraction's), its norm
/// within sqrt(2) times that plus 2 u |w_j|, the product within u: each term within
/// 5.5 u |w_j| (|o| + |u_j| + |w_j|); each accumulator's at most ceil(n/2) terms within
/// (ceil(n/2) - 1) u of the sum of their sizes, the last addition within u. In all, at most
/// (ceil(n/2) + 6) u sum_j |w_j| (|o| + |u_j| + |w_j|): 16 u = 9.5e-7 of that size for the
/// default 20 strips, within the 1e-6 the depth kernel allows itself
/// (docs/theory.md#modelling-choices-stated-where-they-are-used-collected-here). No
/// division, double-precision root or conversion in the chain
/// (docs/benchmarks.md#the-drags-strip-sums-in-single-precision).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct StripSums {
    even: [f32; 2],
    odd: [f32; 2],
}

impl StripSums {
    /// Adds the strips `velocities`, the first of which is an even strip.
    #[inline]
    pub(super) fn add<V: Velocity>(&mut self, velocities: &[V], offset: [f32; 2]) {
        let mut pairs = velocities.chunks_exact(2);
        for pair in &mut pairs {
            self.even = add_term(self.even, pair[0].xy32(), offset);
            self.odd = add_term(self.odd, pair[1].xy32(), offset);
        }
        if let [last] = pairs.remainder() {
            self.even = add_term(self.even, last.xy32(), offset);
        }
    }

    /// even + odd, widened to double.
    #[inline]
    pub(super) fn total(self) -> [f64; 2] {
        [0, 1].map(|i| f64::from(self.even[i] + self.odd[i]))
    }
}

/// sum + w |w|, w = u - offset, in single precision.
#[inline(always)]
fn add_term(sum: [f32; 2], u: [f32; 2], offset: [f32; 2]) -> [f32; 2] {
    let (wx, wy) = (u[0] - offset[0], u[1] - offset[1]);
    let norm = (wx * wx + wy * wy).sqrt();
    [sum[0] + wx * norm, sum[1] + wy * norm]
}

/// A pair of doubles rounded to single precision (to nearest).
#[inline]
pub(super) fn single(v: [f64; 2]) -> [f32; 2] {
    v.map(|x| x as f32)
}

/// A strip's horizontal velocity (u_x, u_y) in single precision: the pair as stored (or
/// interpolated and rounded), or u_x alone in waves along x (u_y = 0).
pub(super) trait Velocity: Copy {
    fn xy32(&self) -> [f32; 2];

    /// Strips j to j + 3 of four lanes' rows, by lane in the elements (lane l in element
    /// l), as two pairs of an even strip and the odd one after it: each pair
    /// (x of strip j + 2p, x of strip j + 2p + 1, y of strip j + 2p, y of strip j + 2p + 1).
    /// Loaded a row's four floats at a time and transposed, not element by element.
    ///
    /// # Safety
    /// The CPU has AVX2 (only `lane_sums_avx2` calls it).
    #[cfg(target_arch = "x86_64")]
    unsafe fn block(rows: [&[Self]; LANES], j: usize) -> [[std::arch::x86_64::__m128; 4]; 2];
}

impl Velocity for [f32; 2] {
    #[inline(always)]
    fn xy32(&self) -> [f32; 2] {
        *self
    }

    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn block(rows: [&[Self]; LANES], j: usize) -> [[std::arch::x86_64::__m128; 4]; 2] {
        // Row floats x_j, y_j, x_(j+1), y_(j+1), ...
        let floats = rows.map(|r| r.as_flattened());
        [0, 1].map(|p| {
            // SAFETY: the CPU has AVX2 (this function's contract).
            let [x_even, y_even, x_odd, y_odd] = unsafe { transposed(floats, 2 * (j + 2 * p)) };
            [x_even, x_odd, y_even, y_odd]
        })
    }
}

impl Velocity for f32 {
    #[inline(always)]
    fn xy32(&self) -> [f32; 2] {
        [*self, 0.0]
    }

    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn block(rows: [&[Self]; LANES], j: usize) -> [[std::arch::x86_64::__m128; 4]; 2] {
        use std::arch::x86_64::_mm_setzero_ps;
        // SAFETY: the CPU has AVX2 (this function's contract).
        let ([x0, x1, x2, x3], zero) = unsafe { (transposed(rows, j), _mm_setzero_ps()) };
        [[x0, x1, zero, zero], [x2, x3, zero, zero]]
    }
}

/// Floats i to i + 3 of four lanes' rows, float i + k of every lane in register k (lane l
/// in element l): each row's four floats loaded at once, then transposed.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn transposed(rows: [&[f32]; LANES], i: usize) -> [std::arch::x86_64::__m128; 4] {
    use std::arch::x86_64::{
        _mm_loadu_ps, _mm_movehl_ps, _mm_movelh_ps, _mm_unpackhi_ps, _mm_unpacklo_ps,
    };
    // SAFETY: each slice is four floats long (the indexing checks it), and `_mm_loadu_ps`
    // reads four floats from any alignment.
    let [a, b, c, d] = rows.map(|r| unsafe { _mm_loadu_ps(r[i..i + 4].as_ptr()) });
    // (a0 b0 a1 b1), (c0 d0 c1 d1), (a2 b2 a3 b3), (c2 d2 c3 d3)
    let (ab01, cd01) = (_mm_unpacklo_ps(a, b), _mm_unpacklo_ps(c, d));
    let (ab23, cd23) = (_mm_unpackhi_ps(a, b), _mm_unpackhi_ps(c, d));
    [
        _mm_movelh_ps(ab01, cd01),
        _mm_movehl_ps(cd01, ab01),
        _mm_movelh_ps(ab23, cd23),
        _mm_movehl_ps(cd23, ab23),
    ]
}

/// [`StripSums`] of each lane's row (the rows of one length), compiled for `isa`.
#[inline(always)]
pub(super) fn lane_sums<V: Velocity>(
    isa: Isa,
    rows: [&[V]; LANES],
    offsets: [[f64; 2]; LANES],
) -> [[f64; 2]; LANES] {
    match isa {
        Isa::Baseline => std::array::from_fn(|l| {
            let mut sums = StripSums::default();
            sums.add(rows[l], single(offsets[l]));
            sums.total()
        }),
        #[cfg(target_arch = "x86_64")]
        // SAFETY: `Isa::Avx2` is only made where the CPU reports AVX2 (`Isa::detect`,
        // `Isa::available`).
        Isa::Avx2 => unsafe { lane_sums_avx2(rows, offsets.map(single)) },
    }
}

/// [`StripSums`] of four lanes in AVX2: a register of 8 floats holds strip j (even) of
/// lanes 0-3 in elements 0-3 and strip j + 1 (odd) in elements 4-7, so its two halves are
/// each lane's even and odd accumulators; an odd last strip goes to the even half alone,
/// and the halves are added (even + odd) at the end. The rows are read four floats at a
/// time and transposed into these registers ([`Velocity::block`]: for each four floats of
/// the four lanes, 4 loads and 8 shuffles instead of 16 element inserts); the pairs left
/// over are gathered element by element. Per element, the operations of
/// `add_term` in its order, each a separate instruction (`_mm256_mul_ps` and
/// `_mm256_add_ps` are never contracted); each lane's sum is the one-seed sum bit for bit.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn lane_sums_avx2<V: Velocity>(
    rows: [&[V]; LANES],
    offsets: [[f32; 2]; LANES],
) -> [[f64; 2]; LANES] {
    use std::arch::x86_64::{
        _mm256_add_ps, _mm256_castps256_ps128, _mm256_cvtps_pd, _mm256_extractf128_ps,
        _mm256_mul_ps, _mm256_set_m128, _mm256_setr_ps, _mm256_setzero_ps, _mm256_sqrt_ps,
        _mm256_sub_ps, _mm_add_ps, _mm_mul_ps, _mm_setr_ps, _mm_sqrt_ps, _mm_sub_ps,
    };
    let n = rows[0].len();
    // Sliced one by one: `array::map` is a call here, once per column and instant.
    let (r0, r1, r2, r3) = (&rows[0][..n], &rows[1][..n], &rows[2][..n], &rows[3][..n]);
    let o = offsets;
    let (off_x, off_y) = (
        _mm_setr_ps(o[0][0], o[1][0], o[2][0], o[3][0]),
        _mm_setr_ps(o[0][1], o[1][1], o[2][1], o[3][1]),
    );
    let (off_x8, off_y8) = (_mm256_set_m128(off_x, off_x), _mm256_set_m128(off_y, off_y));
    let (mut sum_x, mut sum_y) = (_mm256_setzero_ps(), _mm256_setzero_ps());
    // Adds a pair's terms, (x, y) of the even strip in the low half and of the odd one in
    // the high half.
    let mut add_pair = |x, y| {
        let (wx, wy) = (_mm256_sub_ps(x, off_x8), _mm256_sub_ps(y, off_y8));
        let norm = _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(wx, wx), _mm256_mul_ps(wy, wy)));
        sum_x = _mm256_add_ps(sum_x, _mm256_mul_ps(wx, norm));
        sum_y = _mm256_add_ps(sum_y, _mm256_mul_ps(wy, norm));
    };
    // Four strips at a time (two pairs, in strip order), then the pairs left one by one.
    let blocks = n - n % 4;
    for j in (0..blocks).step_by(4) {
        // SAFETY: this function runs only where the CPU has AVX2.
        for [x_even, x_odd, y_even, y_odd] in unsafe { V::block([r0, r1, r2, r3], j) } {
            add_pair(
                _mm256_set_m128(x_odd, x_even),
                _mm256_set_m128(y_odd, y_even),
            );
        }
    }
    for j in (blocks..n - n % 2).step_by(2) {
        let [a, b, c, d] = [r0[j].xy32(), r1[j].xy32(), r2[j].xy32(), r3[j].xy32()];
        let [e, f, g, h] = [
            r0[j + 1].xy32(),
            r1[j + 1].xy32(),
            r2[j + 1].xy32(),
            r3[j + 1].xy32(),
        ];
        add_pair(
            _mm256_setr_ps(a[0], b[0], c[0], d[0], e[0], f[0], g[0], h[0]),
            _mm256_setr_ps(a[1], b[1], c[1], d[1], e[1], f[1], g[1], h[1]),
        );
    }
    let (mut even_x, mut even_y) = (_mm256_castps256_ps128(sum_x), _mm256_castps256_ps128(sum_y));
    if n % 2 == 1 {
        let j = n - 1;
        let [a, b, c, d] = [r0[j].xy32(), r1[j].xy32(), r2[j].xy32(), r3[j].xy32()];
        let wx = _mm_sub_ps(_mm_setr_ps(a[0], b[0], c[0], d[0]), off_x);
        let wy = _mm_sub_ps(_mm_setr_ps(a[1], b[1], c[1], d[1]), off_y);
        let norm = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(wx, wx), _mm_mul_ps(wy, wy)));
        even_x = _mm_add_ps(even_x, _mm_mul_ps(wx, norm));
        even_y = _mm_add_ps(even_y, _mm_mul_ps(wy, norm));
    }
    let total_x = _mm_add_ps(even_x, _mm256_extractf128_ps::<1>(sum_x));
    let total_y = _mm_add_ps(even_y, _mm256_extractf128_ps::<1>(sum_y));
    let xs = elements(_mm256_cvtps_pd(total_x));
    let ys = elements(_mm256_cvtps_pd(total_y));
    std::array::from_fn(|l| [xs[l], ys[l]])
}

/// The 4 doubles of an AVX register, element 0 first.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn elements(v: std::arch::x86_64::__m256d) -> [f64; LANES] {
    use std::arch::x86_64::{
        _mm256_castpd256_pd128, _mm256_extractf128_pd, _mm_cvtsd_f64, _mm_unpackhi_pd,
    };
    let (low, high) = (_mm256_castpd256_pd128(v), _mm256_extractf128_pd::<1>(v));
    [
        _mm_cvtsd_f64(low),
        _mm_cvtsd_f64(_mm_unpackhi_pd(low, low)),
        _mm_cvtsd_f64(high),
        _mm_cvtsd_f64(_mm_unpackhi_pd(high, high)),
    ]
}
