//! The elastic catenary of one mooring line in still water, resting on a frictionless seabed
//! where it touches it: the fairlead tension's horizontal and vertical components (HF, VF)
//! from the fairlead's horizontal and vertical distance to the anchor (XF, ZF).
//!
//! The equations are the classic quasi-static line of MAP, FAST's quasi-static mooring and
//! MoorPy (Jonkman, "Dynamics modeling and loads analysis of an offshore floating wind
//! turbine", NREL/TP-500-41958, 2007, eqs. 2-1 to 2-4, with the seabed friction
//! coefficient 0). With L the unstretched length, EA the axial stiffness and W the weight
//! per length in water:
//!
//! - fully suspended (VF >= W L):
//!   XF = HF/W [asinh(VF/HF) - asinh((VF - W L)/HF)] + HF L / EA,
//!   ZF = HF/W [sqrt(1 + (VF/HF)^2) - sqrt(1 + ((VF - W L)/HF)^2)] + (VF L - W L^2 / 2) / EA;
//! - resting on the seabed over L_B = L - VF/W (VF < W L):
//!   XF = L_B + HF/W asinh(VF/HF) + HF L / EA,
//!   ZF = HF/W [sqrt(1 + (VF/HF)^2) - 1] + VF^2 / (2 EA W).
//!
//! The two agree at VF = W L. Newton's method with the analytic Jacobian, from the starting
//! point of Peyrot and Goulois (1979) that MAP uses, solves them for (HF, VF). A line slack
//! enough to reach its anchor with no horizontal tension at all (XF <= L - s, with s the
//! stretched vertical part that hangs from the fairlead) has HF = 0 and VF = W s: it hangs
//! straight down and the rest lies on the seabed.

/// One line's properties (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    /// Unstretched length L (m).
    pub length: f64,
    /// Axial stiffness EA (N).
    pub ea: f64,
    /// Weight per unit length in water W (N/m), positive (the line sinks).
    pub weight: f64,
}

/// The fairlead tension's components: HF horizontal (towards the anchor, N), VF vertical
/// (downward on the fairlead, N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tension {
    pub horizontal: f64,
    pub vertical: f64,
}

/// Newton's tolerance on the spans, relative to the line's length.
const TOLERANCE: f64 = 1e-12;
const MAX_ITERATIONS: usize = 100;

impl Line {
    /// The spans (XF, ZF) of the line under the fairlead tension (hf, vf), and their
    /// Jacobian [[dXF/dHF, dXF/dVF], [dZF/dHF, dZF/dVF]].
    pub fn spans(&self, hf: f64, vf: f64) -> ((f64, f64), [[f64; 2]; 2]) {
        let (l, ea, w) = (self.length, self.ea, self.weight);
        let a = vf / hf;
        let sa = (1.0 + a * a).sqrt();
        if vf >= w * l {
            let b = (vf - w * l) / hf;
            let sb = (1.0 + b * b).sqrt();
            let xf = hf / w * (a.asinh() - b.asinh()) + hf * l / ea;
            let zf = hf / w * (sa - sb) + (vf * l - w * l * l / 2.0) / ea;
            let dx_dh = (a.asinh() - b.asinh() - a / sa + b / sb) / w + l / ea;
            let dx_dv = (1.0 / sa - 1.0 / sb) / w;
            let dz_dh = dx_dv;
            let dz_dv = (a / sa - b / sb) / w + l / ea;
            ((xf, zf), [[dx_dh, dx_dv], [dz_dh, dz_dv]])
        } else {
            let xf = l - vf / w + hf / w * a.asinh() + hf * l / ea;
            let zf = hf / w * (sa - 1.0) + vf * vf / (2.0 * ea * w);
            let dx_dh = (a.asinh() - a / sa) / w + l / ea;
            let dx_dv = (1.0 / sa - 1.0) / w;
            let dz_dh = dx_dv;
            let dz_dv = a / sa / w + vf / (ea * w);
            ((xf, zf), [[dx_dh, dx_dv], [dz_dh, dz_dv]])
        }
    }

    /// The fairlead tension for the fairlead xf (m) from its anchor horizontally and zf (m)
    /// above it; an error (naming the spans) when there is no catenary solution: a line
    /// that cannot reach, the fairlead straight above or below its anchor, or Newton's method
    /// not converging.
    pub fn solve(&self, xf: f64, zf: f64) -> Result<Tension, String> {
        let (l, ea, w) = (self.length, self.ea, self.weight);
        if !(l > 0.0 && ea > 0.0 && w > 0.0 && l.is_finite() && ea.is_finite() && w.is_finite()) {
            return Err(format!(
                "a line of length {l} m, EA {ea} N and weight {w} N/m in water: all must be \
                 positive (the quasi-static model needs a line that sinks)"
            ));
        }
        if !(xf > 0.0 && xf.is_finite() && zf >= 0.0 && zf.is_finite()) {
            return Err(format!(
                "a fairlead {xf} m from its anchor horizontally and {zf} m above it: the \
                 quasi-static model needs it above the anchor and away from the vertical"
            ));
        }
        // Slack: the vertical part s, stretched by its own weight (zf = s + W s^2 / (2 EA)),
        // and the rest of the line on the seabed reach the anchor without tension.
        let hanging = ea / w * ((1.0 + 2.0 * w * zf / ea).sqrt() - 1.0);
        if xf <= l - hanging {
            return Ok(Tension {
                horizontal: 0.0,
                vertical: w * hanging,
            });
        }
        // Peyrot and Goulois's starting point.
        let lambda = if (xf * xf + zf * zf).sqrt() >= l {
            0.2
        } else {
            (3.0 * ((l * l - zf * zf) / (xf * xf) - 1.0)).sqrt()
        };
        let mut hf = (w * xf / (2.0 * lambda)).abs().max(TOLERANCE * w * l);
        let mut vf = w / 2.0 * (zf / lambda.tanh() + l);
        for _ in 0..MAX_ITERATIONS {
            let ((x, z), [[a, b], [c, d]]) = self.spans(hf, vf);
            let (rx, rz) = (x - xf, z - zf);
            if rx.abs().max(rz.abs()) <= TOLERANCE * l {
                return Ok(Tension {
                    horizontal: hf,
                    vertical: vf,
                });
            }
            let det = a * d - b * c;
            let (dh, dv) = ((d * rx - b * rz) / det, (a * rz - c * rx) / det);
            if !(dh.is_finite() && dv.is_finite()) {
                break;
            }
            // Keep HF positive and VF non-negative: halve a step that would leave them.
            let mut s = 1.0;
            while (hf - s * dh <= 0.0 || vf - s * dv < 0.0) && s > 1e-12 {
                s *= 0.5;
            }
            hf -= s * dh;
            vf -= s * dv;
        }
        Err(format!(
            "no catenary found for a line of {l} m (EA {ea} N, {w} N/m in water) with its \
             fairlead {xf} m from its anchor horizontally and {zf} m above it"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CHAIN: Line = Line {
        length: 1000.0,
        ea: 6.03e8,
        weight: 1196.37,
    };

    /// The solution reproduces its spans, on both branches.
    #[test]
    fn solution_satisfies_the_equations() {
        for (xf, zf) in [
            (935.0, 280.0),
            (960.0, 280.0),
            (905.0, 100.0),
            (1005.0, 100.0),
        ] {
            let t = CHAIN.solve(xf, zf).unwrap();
            let ((x, z), _) = CHAIN.spans(t.horizontal, t.vertical);
            assert!(
                (x - xf).abs() < 1e-8 && (z - zf).abs() < 1e-8,
                "{xf} {zf}: {t:?}"
            );
        }
        // A taut line (1005 m across, 100 m up: fully suspended), one on the seabed, and a
        // slack one hanging straight down (no horizontal tension, the weight of 100 m).
        assert!(CHAIN.solve(1005.0, 100.0).unwrap().vertical > CHAIN.weight * CHAIN.length);
        assert!(CHAIN.solve(905.0, 100.0).unwrap().vertical < CHAIN.weight * CHAIN.length);
        let slack = CHAIN.solve(700.0, 100.0).unwrap();
        assert_eq!(slack.horizontal, 0.0);
        assert!((slack.vertical - CHAIN.weight * 100.0).abs() < 1e-3 * CHAIN.weight * 100.0);
    }

    /// The Jacobian against central differences on both branches.
    #[test]
    fn jacobian_is_the_derivative() {
        for (hf, vf) in [(1.2e6, 5.0e5), (1.2e6, 1.5e6)] {
            let (_, j) = CHAIN.spans(hf, vf);
            for (k, dh, dv) in [(0, 1.0, 0.0), (1, 0.0, 1.0)] {
                let ((xp, zp), _) = CHAIN.spans(hf + dh, vf + dv);
                let ((xm, zm), _) = CHAIN.spans(hf - dh, vf - dv);
                let (dx, dz) = ((xp - xm) / 2.0, (zp - zm) / 2.0);
                assert!(
                    (dx - j[0][k]).abs() <= 1e-6 * j[0][k].abs().max(1e-9),
                    "{hf} {vf} {k}"
                );
                assert!(
                    (dz - j[1][k]).abs() <= 1e-6 * j[1][k].abs().max(1e-9),
                    "{hf} {vf} {k}"
                );
            }
        }
    }

    /// A line lying on the seabed but for its vertical part: with EA -> infinity, the
    /// suspended part of a catenary hanging from height h with horizontal tension H has
    /// length s = sqrt(h^2 + 2 h H / W) and horizontal reach (H/W) asinh(s W / H); a
    /// closed form independent of the equations above.
    #[test]
    fn inextensible_limit_matches_the_closed_form() {
        let line = Line { ea: 1e18, ..CHAIN };
        let (h, hf) = (280.0, 1.2e6);
        let s = (h * h + 2.0 * h * hf / line.weight).sqrt();
        let xf = line.length - s + hf / line.weight * (s * line.weight / hf).asinh();
        let t = line.solve(xf, h).unwrap();
        assert!((t.horizontal - hf).abs() < 1e-6 * hf, "{t:?}");
        assert!((t.vertical - line.weight * s).abs() < 1e-6 * hf, "{t:?}");
    }

    #[test]
    fn impossible_lines_are_errors() {
        assert!(CHAIN.solve(0.0, 280.0).unwrap_err().contains("vertical"));
        assert!(CHAIN.solve(900.0, -5.0).is_err());
        assert!(Line {
            weight: -1.0,
            ..CHAIN
        }
        .solve(900.0, 280.0)
        .unwrap_err()
        .contains("sinks"));
        assert!(CHAIN.solve(f64::NAN, 280.0).is_err());
    }
}
