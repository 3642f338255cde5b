//! A circle of radius r as a [`ConvexCurve`], so parry's `Ball` can be object1 or object2.
//! φ is the normal angle: P = r·(cos φ, sin φ), ρ = r.

use crate::curve::{ConvexCurve, CurvePoint, SupportJet};
use crate::numerics::math::{unit, Vector};

/// A circle centred at the origin: parry's `Ball` as a [`ConvexCurve`], for the free queries
/// ([`crate::time_of_impact`], [`crate::stationary_distance`], …). It is not a parry shape
/// itself (rapier's and parry's disc is `Ball`, or this crate's `Ellipse` with equal semi-axes).
///
/// The radius is a public field; the queries answer `Err(QueryError::Degenerate)` for a curve
/// whose bounding radius is not finite and positive (a `BallCurve` of radius 0, negative or
/// NaN). [`BallCurve::new`] and [`BallCurve::try_new`] check it as the other shapes'
/// constructors do.
///
/// ```
/// use smooth_ccd2d::{BallCurve, ShapeError};
/// assert_eq!(BallCurve::new(0.5).radius, 0.5);
/// assert!(matches!(BallCurve::try_new(-1.0), Err(ShapeError::NotPositive { .. })));
/// ```
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct BallCurve {
    /// Radius (> 0).
    pub radius: f64,
}

impl BallCurve {
    /// A circle of radius `radius`.
    ///
    /// # Panics
    /// When the radius is not finite, not positive or outside
    /// [[`crate::MIN_LENGTH`], [`crate::MAX_LENGTH`]] (see [`BallCurve::try_new`]).
    pub fn new(radius: f64) -> Self {
        match Self::try_new(radius) {
            Ok(b) => b,
            Err(e) => panic!("BallCurve::new: {e}"),
        }
    }

    /// A circle of radius `radius`, or why not (it must be finite, positive and within
    /// [[`crate::MIN_LENGTH`], [`crate::MAX_LENGTH`]]).
    pub fn try_new(radius: f64) -> Result<Self, crate::ShapeError> {
        Ok(Self {
            radius: crate::error::positive("radius", radius)?,
        })
    }
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
