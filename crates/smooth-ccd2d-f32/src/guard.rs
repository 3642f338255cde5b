//! What the f32 dispatcher refuses before parry2d's composite helpers see it, as the f64
//! dispatcher does before parry2d-f64's (its `input_guard`): parry asserts that margins are
//! non-negative and otherwise passes NaN and infinities through. Pairs answered by the f64
//! crate are checked there, after widening; pairs with none of this package's shapes are
//! parry2d's own, untouched.
//!
//! Refused (`Err(Unsupported)`): a margin (prediction, `max_dist`) negative or NaN; a pose not
//! finite or whose rotation is not a unit complex number (to 1e-6); a shape whose local bounding
//! box is not finite or inverted (a half-space: whose normal is not finite); a cast's motion,
//! velocity or window not finite, or a reversed window. After the query: any non-finite number in
//! the answer.

use parry2d::math::{Pose, Real};
use parry2d::query::{
    ClosestPoints, Contact, NonlinearRigidMotion, ShapeCastHit, ShapeDistance, ShapeIntersection, Unsupported,
};
use parry2d::shape::{HalfSpace, Shape};

/// A pose parry can take: finite, with a unit rotation (to 1e-6).
pub(crate) fn pose_ok(p: &Pose) -> bool {
    let r = p.rotation;
    p.is_finite() && ((r.re * r.re + r.im * r.im) - 1.0).abs() <= 1e-6
}

/// A shape parry can take: a finite, non-inverted local box (a half-space: a finite normal).
pub(crate) fn shape_ok(g: &dyn Shape) -> bool {
    if let Some(hs) = g.as_shape::<HalfSpace>() {
        return hs.normal.is_finite();
    }
    let a = g.compute_local_aabb();
    a.mins.is_finite() && a.maxs.is_finite() && a.mins.x <= a.maxs.x && a.mins.y <= a.maxs.y
}

/// The inputs of a stationary query with margin `margin` (0 where there is none).
pub(crate) fn inputs_ok(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, margin: Real) -> bool {
    margin >= 0.0 && pose_ok(pos12) && shape_ok(g1) && shape_ok(g2)
}

/// The inputs of a nonlinear cast over [t0, t1].
pub(crate) fn cast_ok(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
) -> bool {
    let motion_ok = |m: &NonlinearRigidMotion| {
        m.local_center.is_finite()
            && m.linvel.is_finite()
            && m.angvel.is_finite()
            && pose_ok(&m.start)
            && pose_ok(&m.position_at_time(t0))
            && pose_ok(&m.position_at_time(t1))
    };
    t0.is_finite() && t1.is_finite() && t0 <= t1 && motion_ok(m1) && motion_ok(m2) && shape_ok(g1) && shape_ok(g2)
}

/// An answer with only finite numbers.
pub(crate) trait Finite {
    /// Every number in it is finite.
    fn finite(&self) -> bool;
}

impl Finite for ShapeIntersection {
    fn finite(&self) -> bool {
        true
    }
}

impl Finite for ShapeDistance {
    fn finite(&self) -> bool {
        self.distance.is_finite()
    }
}

impl Finite for Contact {
    fn finite(&self) -> bool {
        self.dist.is_finite()
            && self.point1.is_finite()
            && self.point2.is_finite()
            && self.normal1.is_finite()
            && self.normal2.is_finite()
    }
}

impl Finite for ClosestPoints {
    fn finite(&self) -> bool {
        match self {
            ClosestPoints::WithinMargin(a, b) => a.is_finite() && b.is_finite(),
            _ => true,
        }
    }
}

impl Finite for ShapeCastHit {
    fn finite(&self) -> bool {
        self.time_of_impact.is_finite()
            && self.witness1.is_finite()
            && self.witness2.is_finite()
            && self.normal1.is_finite()
            && self.normal2.is_finite()
    }
}

impl<T: Finite> Finite for Option<T> {
    fn finite(&self) -> bool {
        self.as_ref().is_none_or(T::finite)
    }
}

/// `query` when `ok`, its answer when finite; `Err(Unsupported)` otherwise.
pub(crate) fn guarded<T: Finite>(ok: bool, query: impl FnOnce() -> Result<T, Unsupported>) -> Result<T, Unsupported> {
    if !ok {
        return Err(Unsupported);
    }
    let r = query()?;
    if r.finite() {
        Ok(r)
    } else {
        Err(Unsupported)
    }
}
