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
use crate::error::ShapeError;
use crate::numerics::math::Vector;
use crate::parry_shape::{curve_quadrature, Core, MassQuadrature, Moments};
use crate::shapes::curve_checks::{check_area, check_curvature, check_curve};
use std::sync::Arc;

/// The mass quadrature's size is the curve's bounding radius, kept within this factor of the
/// farthest sampled point: a radius the user overstates (an upper bound is allowed) does not
/// loosen the tolerance beyond it (the built-in shapes' radii are within it, and keep their
/// mass to the bit).
const MASS_SCALE_SLACK: f64 = 4.0;

/// A user-defined convex curve as a parry shape (`ShapeType::Custom`).
///
/// Cloning is cheap (the curve is shared). Wrapping checks the curve's contract on a fixed
/// sample ([`CustomCurve::try_new`]), detects its flat pieces (pieces between two
/// [`ConvexCurve::breakpoints`] on which the normal does not turn: they give parry's
/// contact-manifold generation whole edges as features) and integrates its mass properties,
/// once.
#[derive(Clone, Debug)]
pub struct CustomCurve {
    curve: Arc<dyn ConvexCurve>,
    flats: Arc<[FlatPiece]>,
    /// Area, first moments and polar moment about the origin ([`crate::parry_shape`]).
    moments: Moments,
    quadrature: MassQuadrature,
    /// The disc about the centroid inside the curve, its radius the distance from the centroid
    /// to the curve (by point projection); `None` where that projection fails.
    core: Option<Core>,
}

impl CustomCurve {
    /// Wraps `curve`.
    ///
    /// # Panics
    /// When the curve breaks its contract where [`CustomCurve::try_new`] checks it, with the
    /// error's message (naming the method).
    pub fn new(curve: impl ConvexCurve) -> Self {
        Self::from_arc(Arc::new(curve))
    }

    /// Wraps an already shared curve.
    ///
    /// # Panics
    /// As [`CustomCurve::new`].
    pub fn from_arc(curve: Arc<dyn ConvexCurve>) -> Self {
        match Self::try_from_arc(curve) {
            Ok(c) => c,
            Err(e) => panic!("CustomCurve::new: {e}"),
        }
    }

    /// Wraps `curve`, or says which of its methods breaks the [`ConvexCurve`] contract: on a
    /// fixed sample of the curve (256 values of φ, and the start and middle of each piece), every
    /// number finite, the breakpoints sorted in [−π, π), the bounding radius a finite length in
    /// [[`crate::MIN_LENGTH`], 4·[`crate::MAX_LENGTH`]] at least the distance of every point, the
    /// normals unit and outward, the curve convex and counter-clockwise, φ wrapped,
    /// `phi_range_of_normal` and `support_point` giving support points, the radius-of-curvature
    /// bounds not contradicted by the sampled radii, and for a strictly convex curve
    /// `support_jet` present at every sampled normal; then the area of Green's theorem (on the
    /// points and their derivatives) positive and between the sampled polygon's and the
    /// bounding disc's. Each comparison has a tolerance of 1e-6 (relative; 1e-3 for the upper
    /// bounds on curvature), so a curve computed in f32 passes. The checks cost a few hundred
    /// evaluations of each method (milliseconds), once; the mass quadrature, integrated here
    /// too, up to 2¹⁷ evaluations more (plus 256 a piece).
    ///
    /// What no sample can check — that the bounds hold everywhere between the sampled points —
    /// is the curve's contract, stated on each method of [`ConvexCurve`] with what breaks when
    /// it does not hold.
    ///
    /// # Errors
    /// [`ShapeError::BrokenContract`] naming the method (with the φ or direction angle where it
    /// was found), or [`ShapeError::NotFinite`], [`ShapeError::NotPositive`],
    /// [`ShapeError::OutOfRange`] for a bounding radius that is not a length in the accepted
    /// range.
    ///
    /// ```
    /// use smooth_ccd2d::{ConvexCurve, CurvePoint, CustomCurve, Ellipse, ShapeError};
    /// # use parry2d_f64::math::Vector;
    /// /// An ellipse that understates its bounding radius.
    /// #[derive(Debug)]
    /// struct Understated(Ellipse);
    /// impl ConvexCurve for Understated {
    ///     fn eval(&self, phi: f64) -> CurvePoint { self.0.eval(phi) }
    ///     fn bounding_radius(&self) -> f64 { 0.2 * self.0.bounding_radius() }
    /// }
    /// let e = CustomCurve::try_new(Understated(Ellipse::new(0.6, 0.3)));
    /// assert!(matches!(e, Err(ShapeError::BrokenContract { method: "bounding_radius", .. })));
    /// assert!(CustomCurve::try_new(Ellipse::new(0.6, 0.3)).is_ok());
    /// ```
    pub fn try_new(curve: impl ConvexCurve) -> Result<Self, ShapeError> {
        Self::try_from_arc(Arc::new(curve))
    }

    /// [`CustomCurve::try_new`] for an already shared curve.
    pub fn try_from_arc(curve: Arc<dyn ConvexCurve>) -> Result<Self, ShapeError> {
        let checked = check_curve(&*curve)?;
        let br = curve.bounding_radius();
        let scale = br.min(MASS_SCALE_SLACK * checked.sampled_radius);
        let (moments, quadrature) = curve_quadrature(&*curve, scale);
        if !moments.iter().all(|m| m.is_finite()) {
            return Err(ShapeError::BrokenContract {
                method: "eval",
                reason: "Green's theorem on its points and derivatives gives non-finite moments",
                at: f64::NAN,
            });
        }
        check_area(moments[0], &checked)?;
        check_curvature(&*curve, &checked)?;
        let flats: Arc<[FlatPiece]> = flat_pieces(&*curve).into();
        let mut shape = Self {
            curve,
            flats,
            moments,
            quadrature,
            core: None,
        };
        shape.core = crate::parry_shape::curve_core(&shape);
        Ok(shape)
    }

    /// The shape's core (its centroid and the distance from it to the curve), computed when it
    /// was wrapped: the radius of its `ccd_thickness`, and the core contacts of its manifolds in
    /// rapier ([`crate::SmoothDispatcher`]).
    pub(crate) fn core(&self) -> Option<Core> {
        self.core
    }

    /// The wrapped curve.
    pub fn curve(&self) -> &dyn ConvexCurve {
        &*self.curve
    }

    /// The shared handle to the wrapped curve.
    pub fn curve_arc(&self) -> &Arc<dyn ConvexCurve> {
        &self.curve
    }

    /// How the mass properties were integrated: converged, or capped by the evaluation budget
    /// (a curve whose `eval` is too noisy for the tolerance: computed in f32, say), with the
    /// evaluations it took.
    pub fn mass_quadrature(&self) -> MassQuadrature {
        self.quadrature
    }

    /// The flat pieces detected at construction.
    pub(crate) fn flats(&self) -> &[FlatPiece] {
        &self.flats
    }

    /// Area, first moments and polar moment about the origin, integrated at construction.
    pub(crate) fn moments(&self) -> Moments {
        self.moments
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
    fn min_radius_of_curvature(&self) -> f64 {
        self.curve.min_radius_of_curvature()
    }
    #[inline]
    fn min_radius_of_curvature_near(&self, m: Vector, half_angle: f64) -> f64 {
        self.curve.min_radius_of_curvature_near(m, half_angle)
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
