//! A circle of radius r as a [`ConvexCurve`], so parry's `Ball` can be object1 or object2.
//! φ is the normal angle: P = r·(cos φ, sin φ), ρ = r.

use crate::curve::{ConvexCurve, CurvePoint, SupportJet};
use crate::numerics::math::{unit, Vector};

/// A circle centred at the origin.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct BallCurve {
    /// Radius (> 0).
    pub radius: f64,
}

impl ConvexCurve for BallCurve {
    #[inline]
    fn eval(&self, phi: f64) -> CurvePoint {
        let n = unit(phi);
        let t = Vector::new(-n.y, n.x);
        CurvePoint {
            point: n * self.radius,
            d_point: t * self.radius,
            dd_point: -n * self.radius,
            normal: n,
            d_normal: t,
            dd_normal: -n,
        }
    }
    #[inline]
    fn bounding_radius(&self) -> f64 {
        self.radius
    }
    #[inline]
    fn phi_range_of_normal(&self, n: Vector) -> (f64, f64) {
        let p = n.y.atan2(n.x);
        (p, p)
    }
    #[inline]
    fn support_jet(&self, m: Vector) -> Option<SupportJet> {
        Some(SupportJet {
            point: m * self.radius,
            radius_of_curvature: self.radius,
            d_radius_of_curvature: 0.0,
        })
    }
    #[inline]
    fn is_strictly_convex(&self) -> bool {
        true
    }
    #[inline]
    fn max_radius_of_curvature(&self) -> f64 {
        self.radius
    }
    #[inline]
    fn min_radius_of_curvature(&self) -> f64 {
        self.radius
    }
    #[inline]
    fn support_dd_bound(&self) -> f64 {
        0.0
    }
    #[inline]
    fn support_dd_bound_near(&self, _m: Vector, _half_angle: f64) -> f64 {
        0.0
    }
    fn support_point(&self, n: Vector) -> Vector {
        n.normalize_or(Vector::X) * self.radius
    }
}
