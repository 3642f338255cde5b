//! What the f32 dispatcher refuses before parry2d's composite helpers, or parry2d's default
//! dispatcher with one of this package's shapes, see it, as the f64 dispatcher does before
//! parry2d-f64's (its `input_guard`): parry asserts that margins are
//! non-negative and otherwise passes NaN and infinities through. Pairs answered by the f64
//! crate are checked there, after widening; pairs with none of this package's shapes are
//! parry2d's own, untouched.
//!
//! Refused (`Err(Unsupported)`): a margin (prediction, `max_dist`) negative or NaN; a pose not
//! finite or whose rotation is not a unit complex number (to 1e-6); a shape whose local bounding
//! box is not finite or inverted (a half-space: whose normal is not finite); a cast's motion,
//! velocity or window not finite, or a reversed window. After the query: any non-finite number in
//! the answer.

use parry2d::math::{Pose, Real, Vector};
use parry2d::query::{NonlinearRigidMotion, ShapeCastOptions, Unsupported};
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

/// The inputs of a linear cast: those of a stationary query, a finite velocity, a finite
/// non-negative target distance and a time limit that is not NaN.
pub(crate) fn linear_cast_ok(
    pos12: &Pose,
    vel12: Vector,
    g1: &dyn Shape,
    g2: &dyn Shape,
    options: &ShapeCastOptions,
) -> bool {
    inputs_ok(pos12, g1, g2, 0.0)
        && vel12.is_finite()
        && !options.max_time_of_impact.is_nan()
        && options.target_distance.is_finite()
        && options.target_distance >= 0.0
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

/// An answer with only finite numbers (the f64 crate's trait of the same name, for parry2d's
/// answers; the impls are its text, `all_finite_impls!`).
pub(crate) trait AllFinite {
    /// Every number in it is finite.
    fn all_finite(&self) -> bool;
}

smooth_ccd2d::all_finite_impls!(parry2d, crate::guard::AllFinite);

/// `query` when `ok`, its answer when finite; `Err(Unsupported)` otherwise.
pub(crate) fn guarded<T: AllFinite>(
    ok: bool,
    query: impl FnOnce() -> Result<T, Unsupported>,
) -> Result<T, Unsupported> {
    if !ok {
        return Err(Unsupported);
    }
    let r = query()?;
    if r.all_finite() {
        Ok(r)
    } else {
        Err(Unsupported)
    }
}
