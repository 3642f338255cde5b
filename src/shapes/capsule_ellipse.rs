//! Shape1 of the specification's Appendix A: half an ellipse glued to a "D" made of two circular
//! arcs and a vertical segment, parametrised exactly as the specification does:
//!
//! * |φ| > π/2 — ellipse (eq. 1) with a = r3, b = r1 + r2: P = (r3 cos φ, (r1+r2) sin φ);
//! * arctan(r2/r1) ≤ |φ| ≤ π/2 — circle of radius r1 centred at (0, ±r2) (eqs. 9, 10):
//!   d = r2 |sin φ| + √(r1² − r2² cos² φ), P = d·(cos φ, sin φ), N = (x/r1, sgn(y)(|y| − r2)/r1);
//! * |φ| < arctan(r2/r1) — the segment x = r1 (eqs. 11, 12): P = (r1, r1 tan φ), N = (1, 0).
//!
//! (The specification's second condition reads "∨"; it is "∧".) Point and normal are continuous;
//! derivatives jump at ±arctan(r2/r1) and ±π/2. They are computed by forward automatic
//! differentiation ([`crate::numerics::jet::Dual2`]).

use crate::curve::pieces::FlatPiece;
use crate::curve::{ConvexCurve, CurvePoint};
use crate::error::{positive, ShapeError};
use crate::numerics::angle::wrap_phi;
use crate::numerics::jet::Dual2;
use crate::numerics::math::Vector;
use core::f64::consts::FRAC_PI_2;

/// Shape1 of Appendix A with parameters r1, r2, r3.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "[f64; 3]", into = "[f64; 3]"))]
pub struct CapsuleEllipse {
    r1: f64,
    r2: f64,
    r3: f64,
    breakpoints: [f64; 4],
    /// The segment x = r1, its one flat piece.
    flat: [FlatPiece; 1],
}

impl TryFrom<[f64; 3]> for CapsuleEllipse {
    type Error = ShapeError;
    fn try_from(r: [f64; 3]) -> Result<Self, ShapeError> {
        Self::try_new(r[0], r[1], r[2])
    }
}

impl From<CapsuleEllipse> for [f64; 3] {
    fn from(c: CapsuleEllipse) -> Self {
        [c.r1, c.r2, c.r3]
    }
}

impl CapsuleEllipse {
    /// Shape1 with radius `r1` of the arcs, half-length `r2` of the segment, and semi-axis `r3`
    /// of the half-ellipse.
    ///
    /// # Panics
    /// When a parameter is not finite and positive; the message names it.
    ///
    /// ```
    /// use smooth_ccd2d::CapsuleEllipse;
    /// // The specification's Appendix A shape.
    /// let shape1 = CapsuleEllipse::new(0.5, 1.0, 0.8);
    /// assert!((shape1.segment_end_angle() - (1.0f64 / 0.5).atan()).abs() < 1e-15);
    /// ```
    pub fn new(r1: f64, r2: f64, r3: f64) -> Self {
        match Self::try_new(r1, r2, r3) {
            Ok(c) => c,
            Err(e) => panic!("CapsuleEllipse::new: {e}"),
        }
    }

    /// Shape1 with parameters r1, r2, r3, or why not (each must be finite, positive and within
    /// [[`crate::MIN_LENGTH`], [`crate::MAX_LENGTH`]], and r1 ≥ 1e-6·r2: on
    /// thinner arcs r1² − r2²cos²φ of eq. 9 is lost to rounding at the arcs' ends and the
    /// boundary evaluates to NaN).
    pub fn try_new(r1: f64, r2: f64, r3: f64) -> Result<Self, ShapeError> {
        let (r1, r2, r3) = (positive("r1", r1)?, positive("r2", r2)?, positive("r3", r3)?);
        if r1 < 1e-6 * r2 {
            return Err(ShapeError::Invalid("parameter `r1` must be at least 1e-6·r2"));
        }
        let a = (r2 / r1).atan();
        Ok(Self {
            r1,
            r2,
            r3,
            breakpoints: [-FRAC_PI_2, -a, a, FRAC_PI_2],
            flat: [FlatPiece {
                normal: Vector::X,
                start: Vector::new(r1, -r2),
                end: Vector::new(r1, r2),
                // Pieces: 0 = lower arc, 1 = segment, 2 = upper arc, 3 = half ellipse (wrapping).
                index: 1,
            }],
        })
    }

    /// The parameters (r1, r2, r3).
    pub fn params(&self) -> (f64, f64, f64) {
        (self.r1, self.r2, self.r3)
    }

    /// The flat pieces: the segment.
    pub(crate) fn flats(&self) -> &[FlatPiece] {
        &self.flat
    }

    /// arctan(r2/r1): where the segment meets the arcs.
    pub fn segment_end_angle(&self) -> f64 {
        self.breakpoints[2]
    }

    /// Which piece φ lies on: 0 the half-ellipse, 1 an arc, 2 the segment.
    pub fn piece_index(&self, phi: f64) -> usize {
        let a = wrap_phi(phi).abs();
        if a > FRAC_PI_2 {
            0
        } else if a >= self.breakpoints[2] {
            1
        } else {
            2
        }
    }
}

impl ConvexCurve for CapsuleEllipse {
    fn eval(&self, phi: f64) -> CurvePoint {
        let phi = wrap_phi(phi);
        let x = Dual2::var(phi);
        let (r1, r2, r3) = (self.r1, self.r2, self.r3);
        let mut piece = self.piece_index(phi);
        if piece == 1 {
            // The breakpoint arctan(r2/r1) is rounded, and eq. 9 just below the true one gives
            // the circle's point behind the segment (inside the shape, normal turned the wrong
            // way; with r1 ≪ r2 by up to √ε·r2/r1, so that distanceFwd overestimates the gap):
            // the arc starts where |sin φ|·r1 ≥ r2·cos φ, the segment before.
            let (s, c) = crate::numerics::math::sin_cos(phi);
            let on_arc = s.abs() * r1 >= r2 * c;
            if !on_arc {
                piece = 2;
            }
        }
        let (px, py, nx, ny) = match piece {
            0 => {
                let (s, c) = x.sin_cos();
                let (a, b) = (r3, r1 + r2);
                let (gx, gy) = (c.scale(1.0 / a), s.scale(1.0 / b));
                let inv = (gx * gx + gy * gy).sqrt().recip();
                (c.scale(a), s.scale(b), gx * inv, gy * inv)
            }
            1 => {
                let (s, c) = x.sin_cos();
                let sg = if phi >= 0.0 { 1.0 } else { -1.0 };
                // Eq. 9 with r1² − r2²cos²φ factored as (r1 − r2 cos φ)(r1 + r2 cos φ): at the
                // arcs' ends r2 cos φ ≈ r1, and the unfactored difference of squares loses
                // √ε·r2 in the point and √ε·r2/r1 in the normal (2e-3 rad for r1 = 1e-5·r2).
                let q = ((Dual2::cst(r1) - c.scale(r2)) * (Dual2::cst(r1) + c.scale(r2))).sqrt();
                let d = s.scale(r2 * sg) + q;
                let (px, py) = (d * c, d * s);
                let nx = px.scale(1.0 / r1);
                // y − sg·r2 = q sin φ − sg·r2 cos²φ, without the cancellation of d sin φ − sg·r2.
                let ny = (q * s - (c * c).scale(sg * r2)).scale(1.0 / r1);
                (px, py, nx, ny)
            }
            _ => (Dual2::cst(r1), x.tan().scale(r1), Dual2::cst(1.0), Dual2::cst(0.0)),
        };
        CurvePoint {
            point: Vector::new(px.v, py.v),
            d_point: Vector::new(px.d, py.d),
            dd_point: Vector::new(px.dd, py.dd),
            normal: Vector::new(nx.v, ny.v),
            d_normal: Vector::new(nx.d, ny.d),
            dd_normal: Vector::new(nx.dd, ny.dd),
        }
    }

    fn breakpoints(&self) -> &[f64] {
        &self.breakpoints
    }

    fn bounding_radius(&self) -> f64 {
        // Arcs and segment lie within r1 + r2 of the origin; the half-ellipse within max(r3, b).
        (self.r1 + self.r2).max(self.r3)
    }

    fn min_radius_of_curvature(&self) -> f64 {
        // Arcs of radius r1, a flat segment, and half of the ellipse with semi-axes r3, r1 + r2
        // (both of its vertices: radii small²/big and big²/small).
        let (a, b) = (self.r3, self.r1 + self.r2);
        self.r1.min(a.min(b).powi(2) / a.max(b))
    }

    fn phi_range_of_normal(&self, n: Vector) -> (f64, f64) {
        let (r1, r2, r3) = (self.r1, self.r2, self.r3);
        if n.x < 0.0 {
            // Ellipse piece: N ∝ (cos φ / a, sin φ / b) ⇒ φ = atan2(b n_y, a n_x).
            let phi = ((r1 + r2) * n.y).atan2(r3 * n.x);
            return (phi, phi);
        }
        if n.y == 0.0 {
            let a = self.breakpoints[2];
            return (-a, a);
        }
        if n.x == 0.0 {
            let phi = FRAC_PI_2.copysign(n.y);
            return (phi, phi);
        }
        let c = Vector::new(0.0, r2.copysign(n.y));
        let p = c + n * r1;
        let phi = p.y.atan2(p.x);
        (phi, phi)
    }

    fn support_point(&self, n: Vector) -> Vector {
        let n = n.normalize_or(Vector::X);
        let (lo, hi) = self.phi_range_of_normal(n);
        self.eval(0.5 * (lo + hi)).point
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn appendix_a_piece_ends_are_at_arctan_and_half_pi_with_continuous_point_and_normal() {
        let c = CapsuleEllipse::new(0.5, 1.0, 0.8);
        let b = c.breakpoints();
        assert!((b[2] - 1.10715).abs() < 1e-5 && (b[1] + 1.10715).abs() < 1e-5);
        assert_eq!(b[0], -FRAC_PI_2);
        assert_eq!(b[3], FRAC_PI_2);
        for &x in b {
            let (l, r) = (c.eval(x - 1e-13), c.eval(x + 1e-13));
            assert!((l.point - r.point).length() < 1e-9, "point jumps at {x}");
            assert!((l.normal - r.normal).length() < 1e-9, "normal jumps at {x}");
        }
        // Across the wrap at ±π (inside the ellipse piece).
        let (l, r) = (c.eval(PI - 1e-13), c.eval(-PI));
        assert!((l.point - r.point).length() < 1e-9);
        // Segment end is (r1, r2); top of the arcs is (0, r1 + r2).
        assert!((c.eval(b[2]).point - Vector::new(0.5, 1.0)).length() < 1e-12);
        assert!((c.eval(FRAC_PI_2).point - Vector::new(0.0, 1.5)).length() < 1e-12);
    }

    #[test]
    fn derivatives_match_finite_differences_on_every_piece() {
        let c = CapsuleEllipse::new(0.5, 1.0, 0.8);
        for phi in [-2.5, -1.3, -0.5, 0.3, 1.3, 2.9] {
            let h = 1e-6;
            let (a, b, m) = (c.eval(phi - h), c.eval(phi + h), c.eval(phi));
            assert!(((b.point - a.point) / (2.0 * h) - m.d_point).length() < 1e-6);
            assert!(((b.normal - a.normal) / (2.0 * h) - m.d_normal).length() < 1e-6);
            assert!(((b.d_point - a.d_point) / (2.0 * h) - m.dd_point).length() < 1e-5);
            assert!(((b.d_normal - a.d_normal) / (2.0 * h) - m.dd_normal).length() < 1e-5);
            assert!((m.normal.length() - 1.0).abs() < 1e-14);
            assert!(m.normal_turn_rate() >= 0.0 && m.speed() >= 0.0);
        }
    }

    #[test]
    fn phi_range_of_normal_inverts_the_normal_map() {
        let c = CapsuleEllipse::new(0.5, 1.0, 0.8);
        for k in 0..64 {
            let phi = -PI + 2.0 * PI * (k as f64 + 0.5) / 64.0;
            let cp = c.eval(phi);
            let (lo, hi) = c.phi_range_of_normal(cp.normal);
            let q = c.eval(0.5 * (lo + hi)).point;
            if lo == hi {
                assert!((q - cp.point).length() < 1e-12, "φ = {phi}");
            } else {
                assert!(lo <= phi && phi <= hi);
            }
        }
    }

    #[test]
    fn try_new_names_the_bad_parameter() {
        assert!(matches!(
            CapsuleEllipse::try_new(0.5, 0.0, 0.8),
            Err(ShapeError::NotPositive { name: "r2", .. })
        ));
        assert!(matches!(
            CapsuleEllipse::try_new(f64::NAN, 1.0, 0.8),
            Err(ShapeError::NotFinite { name: "r1", .. })
        ));
    }
}
