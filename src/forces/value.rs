//! The numbers the drag and the equations of motion are written in: one seed's `f64`, or
//! [`LANES`] seeds' side by side ([`Wide`]; docs/architecture.md#seeds-in-lanes). One
//! generic code takes both, so each lane's result is its seed's alone bit for bit: a
//! [`Wide`] operation is the same IEEE operation in each lane (no fused multiply-add, no
//! reordering).

use super::LANES;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A number of the drag and the equations of motion: one seed's, or several seeds' side by
/// side.
pub trait Value:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The seeds side by side.
    const WIDTH: usize;

    /// `x` in every lane.
    fn splat(x: f64) -> Self;

    /// Lane `l`'s number (`l` < [`Value::WIDTH`]).
    fn lane(self, l: usize) -> f64;

    /// `N` numbers, lane l's from `of(l)` (called once per lane, in lane order).
    fn gather<const N: usize>(of: impl FnMut(usize) -> [f64; N]) -> [Self; N];

    /// |x| in every lane.
    fn abs(self) -> Self;

    /// sqrt(x) in every lane.
    fn sqrt(self) -> Self;

    /// The larger of `self` and `other` in every lane, as `f64::max` takes them.
    fn max(self, other: Self) -> Self;
}

impl Value for f64 {
    const WIDTH: usize = 1;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }

    #[inline(always)]
    fn lane(self, _: usize) -> f64 {
        self
    }

    #[inline(always)]
    fn gather<const N: usize>(mut of: impl FnMut(usize) -> [f64; N]) -> [Self; N] {
        of(0)
    }

    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }

    #[inline(always)]
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }

    #[inline(always)]
    fn max(self, other: Self) -> Self {
        f64::max(self, other)
    }
}

/// [`LANES`] seeds' numbers side by side, lane l at `.0[l]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wide(pub [f64; LANES]);

impl Wide {
    #[inline(always)]
    fn each(self, rhs: Wide, op: impl Fn(f64, f64) -> f64) -> Wide {
        Wide(std::array::from_fn(|l| op(self.0[l], rhs.0[l])))
    }
}

impl Add for Wide {
    type Output = Wide;
    #[inline(always)]
    fn add(self, rhs: Wide) -> Wide {
        self.each(rhs, |a, b| a + b)
    }
}

impl Sub for Wide {
    type Output = Wide;
    #[inline(always)]
    fn sub(self, rhs: Wide) -> Wide {
        self.each(rhs, |a, b| a - b)
    }
}

impl Mul for Wide {
    type Output = Wide;
    #[inline(always)]
    fn mul(self, rhs: Wide) -> Wide {
        self.each(rhs, |a, b| a * b)
    }
}

impl Div for Wide {
    type Output = Wide;
    #[inline(always)]
    fn div(self, rhs: Wide) -> Wide {
        self.each(rhs, |a, b| a / b)
    }
}

impl Neg for Wide {
    type Output = Wide;
    #[inline(always)]
    fn neg(self) -> Wide {
        Wide(self.0.map(|a| -a))
    }
}

impl Value for Wide {
    const WIDTH: usize = LANES;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        Wide([x; LANES])
    }

    #[inline(always)]
    fn lane(self, l: usize) -> f64 {
        self.0[l]
    }

    #[inline(always)]
    fn gather<const N: usize>(mut of: impl FnMut(usize) -> [f64; N]) -> [Self; N] {
        let mut out = [Wide([0.0; LANES]); N];
        for l in 0..LANES {
            for (o, x) in out.iter_mut().zip(of(l)) {
                o.0[l] = x;
            }
        }
        out
    }

    #[inline(always)]
    fn abs(self) -> Self {
        Wide(self.0.map(f64::abs))
    }

    #[inline(always)]
    fn sqrt(self) -> Self {
        Wide(self.0.map(f64::sqrt))
    }

    #[inline(always)]
    fn max(self, other: Self) -> Self {
        self.each(other, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every operation of [`Wide`] is the `f64` operation in each lane, bit for bit, on
    /// numbers whose results round (and a negative zero, whose sign a product keeps).
    #[test]
    fn each_lane_is_the_f64_operation() {
        let a = Wide([0.1, -3.7e5, 1.0 / 3.0, -0.0]);
        let b = Wide([0.7, 2.9e-3, -5.5, 1.25]);
        let bits = |w: Wide| w.0.map(f64::to_bits);
        let each = |op: fn(f64, f64) -> f64| std::array::from_fn(|l| op(a.0[l], b.0[l]).to_bits());
        assert_eq!(bits(a + b), each(|x, y| x + y));
        assert_eq!(bits(a - b), each(|x, y| x - y));
        assert_eq!(bits(a * b), each(|x, y| x * y));
        assert_eq!(bits(a / b), each(|x, y| x / y));
        assert_eq!(bits(a.max(b)), each(f64::max));
        assert_eq!(bits(b.sqrt()), each(|_, y| y.sqrt()));
        assert_eq!(bits(-a), each(|x, _| -x));
        assert_eq!(bits(a.abs()), each(|x, _| x.abs()));
        assert_eq!(bits(Wide::splat(0.3)), [0.3f64.to_bits(); LANES]);
        let [x, y] = Wide::gather(|l| [l as f64, -(l as f64)]);
        assert_eq!(x, Wide([0.0, 1.0, 2.0, 3.0]));
        assert_eq!(y.lane(3), -3.0);
        assert_eq!(f64::gather(|l| [l as f64 + 1.0]), [1.0]);
    }
}
