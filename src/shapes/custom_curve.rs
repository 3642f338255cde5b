//! A concrete parry shape wrapping a user-defined [`ConvexCurve`].
//!
//! parry and rapier hold shapes as `dyn Shape`, and [`crate::SmoothDispatcher`] recognises the
//! shapes it handles by downcasting to concrete types. A user's own curve therefore enters
//! parry/rapier through this wrapper: [`CustomCurve`] holds the curve behind an [`Arc`] and
//! implements parry's `Shape`, `RayCast`, `PointQuery`, `SupportMap` and
//! `PolygonalFeatureMap` (see [`crate::parry_shape`]) generically from the curve's
//! [`ConvexCurve`] methods. It also implements [`ConvexCurve`] itself by delegation.
//!
//! ```
//! use smooth_ccd2d::{ConvexCurve, CurvePoint, CustomCurve, Ellipse};
//! # use parry2d_f64::shape::Shape;
//! // Any `ConvexCurve` will do; an ellipse stands in for a user's curve here.
//! let shape = CustomCurve::new(Ellipse::new(2.0, 1.0));
//! let aabb = shape.compute_local_aabb();
//! assert!((aabb.maxs.x - 2.0).abs() < 1e-12);
//! ```

use crate::curve::pieces::{flat_pieces, FlatPiece};
use crate::curve::{ConvexCurve, CurvePoint, SupportJet};
use crate::numerics::math::Vector;
use std::sync::Arc;

/// A user-defined convex curve as a parry shape (`ShapeType::Custom`).
///
/// Cloning is cheap (the curve is shared). Flat pieces of the curve (pieces between two
/// [`ConvexCurve::breakpoints`] on which the normal does not turn) are detected once at
/// construction; they give parry's contact-manifold generation whole edges as features.
#[derive(Clone, Debug)]
pub struct CustomCurve {
    curve: Arc<dyn ConvexCurve>,
    flats: Arc<[FlatPiece]>,
}

impl CustomCurve {
    /// Wraps `curve`.
    pub fn new(curve: impl ConvexCurve) -> Self {
        Self::from_arc(Arc::new(curve))
    }

    /// Wraps an already shared curve.
    pub fn from_arc(curve: Arc<dyn ConvexCurve>) -> Self {
        let flats: Arc<[FlatPiece]> = flat_pieces(&*curve).into();
        Self { curve, flats }
    }

    /// The wrapped curve.
    pub fn curve(&self) -> &dyn ConvexCurve {
        &*self.curve
    }

    /// The shared handle to the wrapped curve.
    pub fn curve_arc(&self) -> &Arc<dyn ConvexCurve> {
        &self.curve
    }

    /// The flat pieces detected at construction.
    pub(crate) fn flats(&self) -> &[FlatPiece] {
        &self.flats
    }
}

impl ConvexCurve for CustomCurve {
    #[inline]
    fn eval(&self, phi: f64) -> CurvePoint {
        self.curve.eval(phi)
    }
    #[inline]
    fn breakpoints(&self) -> &[f64] {
        self.curve.breakpoints()
    }
    #[inline]
    fn bounding_radius(&self) -> f64 {
        self.curve.bounding_radius()
    }
    #[inline]
    fn phi_range_of_normal(&self, n: Vector) -> (f64, f64) {
        self.curve.phi_range_of_normal(n)
    }
    #[inline]
    fn support_jet(&self, m: Vector) -> Option<SupportJet> {
        self.curve.support_jet(m)
    }
    #[inline]
    fn is_strictly_convex(&self) -> bool {
        self.curve.is_strictly_convex()
    }
    #[inline]
    fn max_radius_of_curvature(&self) -> f64 {
        self.curve.max_radius_of_curvature()
    }
    #[inline]
    fn support_point(&self, n: Vector) -> Vector {
        self.curve.support_point(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};

    #[test]
    fn custom_curve_delegates_to_the_wrapped_curve() {
        let e = Ellipse::new(2.0, 0.5);
        let c = CustomCurve::new(e);
        for k in 0..16 {
            let phi = -3.0 + 0.37 * k as f64;
            assert_eq!(c.eval(phi), e.eval(phi));
        }
        assert_eq!(c.bounding_radius(), 2.0);
        assert!(c.is_strictly_convex());
        assert!(c.flats().is_empty());
        let shared: Arc<dyn ConvexCurve> = Arc::new(e);
        let c2 = CustomCurve::from_arc(shared.clone());
        assert!(Arc::ptr_eq(c2.curve_arc(), &shared));
        let _ = format!("{:?}", c2.clone());
    }

    #[test]
    fn custom_curve_detects_flat_pieces() {
        let c = CustomCurve::new(CapsuleEllipse::new(0.5, 1.0, 0.8));
        assert_eq!(c.flats().len(), 1);
        let f = c.flats()[0];
        assert!((f.normal - Vector::X).length() < 1e-12);
        assert!((f.start - Vector::new(0.5, -1.0)).length() < 1e-12);
        assert!((f.end - Vector::new(0.5, 1.0)).length() < 1e-12);
        let p = CustomCurve::new(RoundedPolygon::regular(5, 1.0, 0.1));
        assert_eq!(p.flats().len(), 5);
        let sharp = CustomCurve::new(RoundedPolygon::regular(4, 1.0, 0.0));
        assert_eq!(sharp.flats().len(), 4);
    }
}
