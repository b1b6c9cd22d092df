//! Brackets on a sorted grid of headings (rad, increasing, within one turn), shared by the
//! drift table and the bi-directional drift table: linear interpolation between nodes,
//! across the closing gap last -> first + 2 pi when the grid covers the circle, never
//! beyond the grid otherwise.

use std::f64::consts::PI;

/// Two headings this close (rad) are the same node.
pub(crate) const SAME_NODE: f64 = 1e-9;

/// A point between two nodes: lo, hi and the weight of hi.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bracket {
    pub lo: usize,
    pub hi: usize,
    pub frac: f64,
}

/// Whether the headings wrap around: they cover the full circle up to at most one regular
/// step (the widest gap between neighbours).
pub(crate) fn is_periodic(headings: &[f64]) -> bool {
    let n = headings.len();
    if n < 2 {
        return false;
    }
    let span = headings[n - 1] - headings[0];
    let widest = headings.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
    2.0 * PI - span <= widest * (1.0 + 1e-6)
}

/// The bracket of `heading` (any number of turns) on `headings`; `None` when the grid does
/// not reach it (it is not periodic and the heading falls in the closing gap).
pub(crate) fn heading_bracket(headings: &[f64], heading: f64) -> Option<Bracket> {
    let h = headings;
    let first = h[0];
    // Bring the heading into [first, first + 2 pi).
    let mut rel = (heading - first).rem_euclid(2.0 * PI);
    if 2.0 * PI - rel < SAME_NODE {
        rel = 0.0;
    }
    let at = first + rel;
    let last = h[h.len() - 1];
    if at <= last + SAME_NODE {
        if h.len() == 1 {
            return Some(Bracket {
                lo: 0,
                hi: 0,
                frac: 0.0,
            });
        }
        let at = at.min(last);
        let i = h.partition_point(|&v| v <= at).clamp(1, h.len() - 1);
        return Some(Bracket {
            lo: i - 1,
            hi: i,
            frac: (at - h[i - 1]) / (h[i] - h[i - 1]),
        });
    }
    is_periodic(h).then(|| Bracket {
        lo: h.len() - 1,
        hi: 0,
        frac: (at - last) / (first + 2.0 * PI - last),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brackets_inside_across_the_closing_gap_and_outside() {
        let circle: Vec<f64> = (0..4).map(|j| j as f64 * PI / 2.0).collect();
        assert!(is_periodic(&circle));
        let b = heading_bracket(&circle, PI / 4.0).unwrap();
        assert_eq!((b.lo, b.hi), (0, 1));
        assert!((b.frac - 0.5).abs() < 1e-15);
        let b = heading_bracket(&circle, -PI / 4.0 + 4.0 * PI).unwrap();
        assert_eq!((b.lo, b.hi), (3, 0));
        assert!((b.frac - 0.5).abs() < 1e-12);
        let half = [0.0, PI / 4.0, PI / 2.0];
        assert!(!is_periodic(&half));
        assert!(heading_bracket(&half, PI).is_none());
        assert_eq!(heading_bracket(&half, PI / 2.0).unwrap().frac, 1.0);
        assert_eq!(heading_bracket(&[0.3], 0.3).unwrap().frac, 0.0);
    }
}
