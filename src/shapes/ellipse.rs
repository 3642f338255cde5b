//! The ellipse x = a cos E, y = b sin E (eq. 1), parametrised by its normal angle.
//!
//! φ is the angle of the outward normal N = (cos φ, sin φ). With h(φ) = √(a² cos² φ + b² sin² φ)
//! (the support function), the boundary point is eq. 4 applied to N:
//!
//! ```text
//! P(φ) = (a² cos φ, b² sin φ) / h(φ),
//! ```
//!
//! and the radius of curvature is ρ(φ) = a² b² / h³. The eccentric anomaly E of eq. 1 and the
//! normal angle are related by tan φ = (a/b) tan E ([`Ellipse::normal_angle_from_eccentric`],
//! [`Ellipse::eccentric_from_normal_angle`]); eq. 5's starting value is the eccentric anomaly of
//! the boundary point in a given direction. Using the normal angle keeps the tip of a 1:1000
//! ellipse as wide in φ as its flank, which removes the squeeze of the specification's
//! Appendix C.

use crate::curve::{ConvexCurve, CurvePoint, SupportJet};
use crate::error::{positive, ShapeError};
use crate::numerics::math::Vector;

/// An ellipse centred at the origin with semi-axes `half_x` (a) and `half_y` (b).
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "[f64; 2]", into = "[f64; 2]"))]
pub struct Ellipse {
    /// Semi-axis along x (a); finite and positive (checked by the constructors).
    half_x: f64,
    /// Semi-axis along y (b); finite and positive (checked by the constructors).
    half_y: f64,
}

impl TryFrom<[f64; 2]> for Ellipse {
    type Error = ShapeError;
    fn try_from(h: [f64; 2]) -> Result<Self, ShapeError> {
        Self::try_new(h[0], h[1])
    }
}

impl From<Ellipse> for [f64; 2] {
    fn from(e: Ellipse) -> Self {
        [e.half_x, e.half_y]
    }
}

impl Ellipse {
    /// The semi-axis along x (a).
    #[inline]
    pub fn half_x(&self) -> f64 {
        self.half_x
    }

    /// The semi-axis along y (b).
    #[inline]
    pub fn half_y(&self) -> f64 {
        self.half_y
    }

    /// The semi-axes `(a, b)` as a vector.
    #[inline]
    pub fn half_extents(&self) -> Vector {
        Vector::new(self.half_x, self.half_y)
    }

    /// An ellipse with semi-axes `half_x`, `half_y`.
    ///
    /// # Panics
    /// When a semi-axis is not finite and positive; the message names it. See [`Ellipse::try_new`].
    ///
    /// ```
    /// use smooth_ccd2d::{ConvexCurve, Ellipse, ShapeError};
    /// let e = Ellipse::new(0.5, 0.2);
    /// assert_eq!(e.bounding_radius(), 0.5);
    /// // As a parry shape: `SharedShape::new(e)`; bad sizes are refused by `try_new`.
    /// assert!(matches!(Ellipse::try_new(0.5, -1.0), Err(ShapeError::NotPositive { name: "half_y", .. })));
    /// ```
    pub fn new(half_x: f64, half_y: f64) -> Self {
        match Self::try_new(half_x, half_y) {
            Ok(e) => e,
            Err(e) => panic!("Ellipse::new: {e}"),
        }
    }

    /// An ellipse with semi-axes `half_x`, `half_y`, or why not (each must be finite, positive
    /// and within [[`crate::MIN_LENGTH`], [`crate::MAX_LENGTH`]]).
    pub fn try_new(half_x: f64, half_y: f64) -> Result<Self, ShapeError> {
        Ok(Self {
            half_x: positive("half_x", half_x)?,
            half_y: positive("half_y", half_y)?,
        })
    }

    /// The normal angle φ at eccentric anomaly E: φ = atan2(a sin E, b cos E).
    pub fn normal_angle_from_eccentric(&self, e: f64) -> f64 {
        (self.half_x * e.sin()).atan2(self.half_y * e.cos())
    }

    /// The eccentric anomaly E at normal angle φ: E = atan2(b sin φ, a cos φ).
    pub fn eccentric_from_normal_angle(&self, phi: f64) -> f64 {
        (self.half_y * phi.sin()).atan2(self.half_x * phi.cos())
    }

    /// Eq. 5: the eccentric anomaly of the boundary point in direction `dir` from the centre.
    pub fn eccentric_toward(&self, dir: Vector) -> f64 {
        (self.half_x * dir.y).atan2(self.half_y * dir.x)
    }

    /// Eq. 1: the point at eccentric anomaly E.
    pub fn point_at_eccentric(&self, e: f64) -> Vector {
        Vector::new(self.half_x * e.cos(), self.half_y * e.sin())
    }

    /// Eq. 2: the outward unit normal at eccentric anomaly E.
    pub fn normal_at_eccentric(&self, e: f64) -> Vector {
        Vector::new(e.cos() / self.half_x, e.sin() / self.half_y).normalize()
    }

    /// Eq. 4: the boundary point whose outward normal is the unit vector `n`.
    #[inline]
    pub fn point_with_normal(&self, n: Vector) -> Vector {
        let (a2, b2) = (self.half_x * self.half_x, self.half_y * self.half_y);
        let h = (a2 * n.x * n.x + b2 * n.y * n.y).sqrt();
        Vector::new(a2 * n.x, b2 * n.y) / h
    }
}

impl ConvexCurve for Ellipse {
    #[inline]
    fn eval(&self, phi: f64) -> CurvePoint {
        // With N = (c, s), H = h² = a²c² + b²s², H' = 2(b² − a²)sc, H'' = 2(b² − a²)(c² − s²) and
        // g = 1/h: g' = −H'g³/2, g'' = −H''g³/2 + 3H'²g⁵/4, and P = (a²c·g, b²s·g) differentiates
        // by the product rule (N' = (−s, c), N'' = −N). One square root and one division.
        let (a2, b2) = (self.half_x * self.half_x, self.half_y * self.half_y);
        let (s, c) = crate::numerics::math::sin_cos(phi);
        let g = 1.0 / (a2 * c * c + b2 * s * s).sqrt();
        let g3 = g * g * g;
        let k = b2 - a2;
        let hp = 2.0 * k * s * c;
        let hpp = 2.0 * k * (c * c - s * s);
        let gp = -0.5 * hp * g3;
        let gpp = -0.5 * hpp * g3 + 0.75 * hp * hp * g3 * g * g;
        CurvePoint {
            point: Vector::new(a2 * c * g, b2 * s * g),
            d_point: Vector::new(a2 * (c * gp - s * g), b2 * (c * g + s * gp)),
            dd_point: Vector::new(
                a2 * (c * gpp - 2.0 * s * gp - c * g),
                b2 * (s * gpp + 2.0 * c * gp - s * g),
            ),
            normal: Vector::new(c, s),
            d_normal: Vector::new(-s, c),
            dd_normal: Vector::new(-c, -s),
        }
    }

    #[inline]
    fn bounding_radius(&self) -> f64 {
        self.half_x.max(self.half_y)
    }

    #[inline]
    fn phi_range_of_normal(&self, n: Vector) -> (f64, f64) {
        let phi = n.y.atan2(n.x);
        (phi, phi)
    }

    #[inline]
    fn support_jet(&self, m: Vector) -> Option<SupportJet> {
        let (a2, b2) = (self.half_x * self.half_x, self.half_y * self.half_y);
        let h2 = a2 * m.x * m.x + b2 * m.y * m.y;
        let h = h2.sqrt();
        let inv_h = 1.0 / h;
        let rho = a2 * b2 * inv_h * inv_h * inv_h;
        let dh = (b2 - a2) * m.x * m.y * inv_h;
        Some(SupportJet {
            point: Vector::new(a2 * m.x * inv_h, b2 * m.y * inv_h),
            radius_of_curvature: rho,
            d_radius_of_curvature: -3.0 * rho * dh * inv_h,
        })
    }

    #[inline]
    fn is_strictly_convex(&self) -> bool {
        true
    }

    #[inline]
    fn max_radius_of_curvature(&self) -> f64 {
        let (a, b) = (self.half_x, self.half_y);
        (a * a / b).max(b * b / a)
    }

    #[inline]
    fn min_radius_of_curvature(&self) -> f64 {
        let (a, b) = (self.half_x, self.half_y);
        (a * a / b).min(b * b / a)
    }

    #[inline]
    fn support_dd_bound(&self) -> f64 {
        // h ∈ [small, big], ρ ∈ [small²/big, big²/small]: |ρ − h| ≤ big²/small − small.
        let (small, big) = (self.half_x.min(self.half_y), self.half_x.max(self.half_y));
        big * big / small - small
    }

    #[inline]
    fn min_radius_of_curvature_near(&self, m: Vector, half_angle: f64) -> f64 {
        // ρ = a²b²/h³ with h² = a²cos²ψ + b²sin²ψ: ρ is monotone in cos²ψ, so its least value
        // over an arc of directions is at one of the arc's extremes of cos²ψ. Each is taken as
        // the pair (cos²ψ, sin²ψ) of one vector, squared components (no 1 − cos²ψ, which
        // cancels along a thin ellipse's flat sides), and h² as a sum of positive terms: ρ to a
        // few ulps at every axis ratio.
        let Some((e1, e2)) = arc_ends(m, half_angle) else {
            return self.min_radius_of_curvature();
        };
        let sq = |e: Vector| (e.x * e.x, e.y * e.y);
        let ((c1, s1), (c2, s2)) = (sq(e1), sq(e2));
        let most_cos = if e1.y * e2.y <= 0.0 {
            (1.0, 0.0)
        } else if c1 >= c2 {
            (c1, s1)
        } else {
            (c2, s2)
        };
        let least_cos = if e1.x * e2.x <= 0.0 {
            (0.0, 1.0)
        } else if c1 <= c2 {
            (c1, s1)
        } else {
            (c2, s2)
        };
        let (a2, b2) = (self.half_x * self.half_x, self.half_y * self.half_y);
        // At (c, s) = |e|²·(cos²ψ, sin²ψ): ρ = a²b²·((c + s)/(a²c + b²s))^{3/2}.
        let rho = |(c, s): (f64, f64)| {
            let q = (c + s) / (a2 * c + b2 * s);
            a2 * b2 * q * q.sqrt()
        };
        // Rounding moves ρ by a few ulps: a hair below, still a lower bound.
        (rho(most_cos).min(rho(least_cos)) * (1.0 - 1e-12)).max(self.min_radius_of_curvature())
    }

    #[inline]
    fn support_dd_bound_near(&self, m: Vector, half_angle: f64) -> f64 {
        // h'' = ρ − h = a²b²/h³ − h decreases with h, so its extremes over an arc of directions
        // are at the arc's extremes of h² = b² + (a² − b²)·cos²ψ, i.e. of cos²ψ.
        let Some((c_min, c_max)) = cos2_range(m, half_angle) else {
            return self.support_dd_bound();
        };
        let (a2, b2) = (self.half_x * self.half_x, self.half_y * self.half_y);
        let f = |c2: f64| {
            let h = (b2 + (a2 - b2) * c2).sqrt();
            (a2 * b2 / (h * h * h) - h).abs()
        };
        f(c_min).max(f(c_max))
    }

    fn support_point(&self, n: Vector) -> Vector {
        self.point_with_normal(n.normalize_or(Vector::X))
    }
}

/// The ends of the arc of directions within `half_angle` of the unit vector `m`, widened a hair
/// against rounding (to a half-angle asin(w) ≥ w, w = `half_angle`·(1 + 1e-9) + 1e-12, with no
/// trigonometry); `None` for an arc of half-angle 0.99 or more (or NaN): the callers take their
/// global bounds then. The arc is shorter than π, so it contains a direction with cos ψ = 0
/// (sin ψ = 0) exactly when the ends' x (y) components differ in sign.
#[inline]
fn arc_ends(m: Vector, half_angle: f64) -> Option<(Vector, Vector)> {
    let w = half_angle * (1.0 + 1e-9) + 1e-12;
    if w.is_nan() || w >= 0.99 {
        return None;
    }
    // Callers pass unit normals: normalise only what is not one already (a length within
    // 1e-14 of 1 moves cos²ψ by far less than the 1e-12 the arc is widened by).
    let n2 = m.length_squared();
    let m = if (n2 - 1.0).abs() <= 1e-14 {
        m
    } else {
        m.normalize_or(Vector::X)
    };
    let (sw, cw) = (w, (1.0 - w * w).sqrt());
    let e1 = Vector::new(m.x * cw + m.y * sw, m.y * cw - m.x * sw);
    let e2 = Vector::new(m.x * cw - m.y * sw, m.y * cw + m.x * sw);
    Some((e1, e2))
}

/// The least and greatest cos²ψ over the directions ψ within `half_angle` of the unit vector `m`
/// ([`arc_ends`]).
#[inline]
fn cos2_range(m: Vector, half_angle: f64) -> Option<(f64, f64)> {
    let (e1, e2) = arc_ends(m, half_angle)?;
    let (c1, c2) = (e1.x * e1.x, e2.x * e2.x);
    let c_max = if e1.y * e2.y <= 0.0 { 1.0 } else { c1.max(c2).min(1.0) };
    let c_min = if e1.x * e2.x <= 0.0 { 0.0 } else { c1.min(c2) };
    Some((c_min, c_max))
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn normal_angle_and_eccentric_anomaly_are_inverse() {
        let e = Ellipse::new(0.5, 2.0);
        for k in -10..10 {
            let ecc = k as f64 * 0.3;
            let phi = e.normal_angle_from_eccentric(ecc);
            let back = e.eccentric_from_normal_angle(phi);
            assert!((e.point_at_eccentric(ecc) - e.point_at_eccentric(back)).length() < 1e-14);
            let cp = e.eval(phi);
            assert!((cp.point - e.point_at_eccentric(ecc)).length() < 1e-14);
            assert!((cp.normal - e.normal_at_eccentric(ecc)).length() < 1e-14);
        }
    }

    #[test]
    fn eval_derivatives_match_dual_number_arithmetic() {
        // The closed-form derivatives of `eval` against the same point computed in `Dual2`
        // arithmetic from P = (a²c, b²s)/√(a²c² + b²s²), on round and thin ellipses.
        use crate::numerics::jet::Dual2;
        for (a, b) in [(1.0, 1.0), (0.3, 1.7), (2.0, 0.5), (1.0, 1e-3), (1e-3, 1.0)] {
            let e = Ellipse::new(a, b);
            let (a2, b2) = (a * a, b * b);
            for k in 0..64 {
                let phi = -3.2 + 0.1 * k as f64;
                let x = Dual2::var(phi);
                let (s, c) = x.sin_cos();
                let inv_h = ((c * c).scale(a2) + (s * s).scale(b2)).sqrt().recip();
                let (px, py) = ((c * inv_h).scale(a2), (s * inv_h).scale(b2));
                let cp = e.eval(phi);
                // Both round differently where P'' cancels (a thin ellipse's flank: 7.8e-14 and
                // 5.4e-14 relative off a 40-digit value at φ = −1.6 of 1×0.001).
                let close = |u: Vector, v: Vector| (u - v).length() <= 1e-12 * (1.0 + v.length());
                assert!(close(cp.point, Vector::new(px.v, py.v)), "point at {phi} of {a}×{b}");
                assert!(close(cp.d_point, Vector::new(px.d, py.d)), "P' at {phi} of {a}×{b}");
                assert!(
                    close(cp.dd_point, Vector::new(px.dd, py.dd)),
                    "P'' at {phi} of {a}×{b}: {:?} vs {:?}",
                    cp.dd_point,
                    Vector::new(px.dd, py.dd)
                );
                assert!(close(cp.normal, Vector::new(c.v, s.v)));
                assert!(close(cp.d_normal, Vector::new(c.d, s.d)));
                assert!(close(cp.dd_normal, Vector::new(c.dd, s.dd)));
            }
        }
    }

    #[test]
    fn support_jet_curvature_matches_finite_differences() {
        let e = Ellipse::new(0.3, 1.7);
        for k in 0..20 {
            let psi = -3.0 + 0.3 * k as f64;
            let m = Vector::new(psi.cos(), psi.sin());
            let j = e.support_jet(m).unwrap();
            let h = 1e-5;
            let sp = |a: f64| e.support_jet(Vector::new(a.cos(), a.sin())).unwrap();
            let ds = (sp(psi + h).point - sp(psi - h).point) / (2.0 * h);
            let tangent = Vector::new(-m.y, m.x);
            assert!((ds - tangent * j.radius_of_curvature).length() < 1e-6 * j.radius_of_curvature.max(1.0));
            let drho = (sp(psi + h).radius_of_curvature - sp(psi - h).radius_of_curvature) / (2.0 * h);
            assert!((drho - j.d_radius_of_curvature).abs() < 1e-5 * (1.0 + drho.abs()));
        }
    }

    #[test]
    fn min_radius_near_is_a_lower_bound_over_its_arc() {
        // Arcs about random directions, round to 1:1e6 ellipses both ways: ρ sampled densely over
        // the arc (its ends included) is never below the bound, and the bound is the least sampled
        // ρ to a hair on short arcs (it is attained at an end or at an axis inside).
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for (a, b) in [
            (1.0, 1.0),
            (2.0, 0.5),
            (0.3, 1.7),
            (1.0, 1e-3),
            (1e-6, 1.0),
            (2.2e-16, 1.4e-4),
            (1.0, 1e-12),
        ] {
            let e = Ellipse::new(a, b);
            for _ in 0..200 {
                let psi0 = -PI + 2.0 * PI * next();
                let half = [0.0, 1e-9, 1e-3, 0.1, 0.5, 0.98][(next() * 6.0) as usize];
                let bound = e.min_radius_of_curvature_near(Vector::new(psi0.cos(), psi0.sin()), half);
                let mut least = f64::INFINITY;
                for k in 0..=400 {
                    let psi = psi0 - half + 2.0 * half * k as f64 / 400.0;
                    let rho = e
                        .support_jet(Vector::new(psi.cos(), psi.sin()))
                        .unwrap()
                        .radius_of_curvature;
                    assert!(
                        rho >= bound,
                        "{a}×{b} at {psi} (arc {psi0} ± {half}): ρ {rho} < {bound}"
                    );
                    least = least.min(rho);
                }
                assert!(bound >= e.min_radius_of_curvature());
                if half <= 1e-3 {
                    assert!(
                        bound >= least * (1.0 - 1e-6),
                        "{a}×{b} arc {psi0} ± {half}: {bound} vs {least}"
                    );
                }
            }
        }
    }

    #[test]
    fn try_new_rejects_bad_semi_axes() {
        assert!(matches!(
            Ellipse::try_new(0.0, 1.0),
            Err(ShapeError::NotPositive { name: "half_x", .. })
        ));
        assert!(matches!(
            Ellipse::try_new(1.0, f64::NAN),
            Err(ShapeError::NotFinite { name: "half_y", .. })
        ));
        assert!(matches!(
            Ellipse::try_new(-1.0, 1.0),
            Err(ShapeError::NotPositive { .. })
        ));
        assert!(Ellipse::try_new(f64::INFINITY, 1.0).is_err());
    }

    #[test]
    #[should_panic(expected = "half_y")]
    fn new_panics_naming_the_parameter() {
        let _ = Ellipse::new(1.0, -2.0);
    }
}
