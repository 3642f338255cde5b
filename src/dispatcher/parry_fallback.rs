//! parry's answers for the pairs handed to it, made robust: a contact for shapes that nearly
//! touch (where GJK/EPA give up), a nonlinear cast whose window does not start at 0 (where
//! parry's walk would not end), and the input guards around both.

use super::input_guard;
use crate::numerics::math::{Pose, Real, Vector};
use parry2d_f64::query::{
    Contact, DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit, Unsupported,
};
use parry2d_f64::shape::Shape;

/// Relative depths by which [`parry_contact`] pushes touching shapes into each other.
pub(crate) const TOUCH_PUSH: [Real; 3] = [1e-8, 1e-6, 1e-4];

/// `pos12` with shape 2 moved towards shape 1 (along the line of their origins) by `push`.
pub(crate) fn pushed_together(pos12: &Pose, push: Real) -> Pose {
    let u = pos12.translation.try_normalize().unwrap_or(Vector::X);
    Pose::from_parts(pos12.translation - u * push, pos12.rotation)
}

/// The size of a pair: the sum of the bounding radii (of the bounded shapes: a half-space
/// counts for nothing).
pub(crate) fn pair_size(g1: &dyn Shape, g2: &dyn Shape) -> Real {
    let r = |g: &dyn Shape| {
        let r = g.compute_local_bounding_sphere().radius;
        if r.is_finite() && r < 0.5 * Real::MAX {
            r
        } else {
            0.0
        }
    };
    r(g1) + r(g2)
}

/// Whether parry's distance (GJK) puts the shapes within `prediction` of each other.
pub(crate) fn parry_within(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, prediction: Real) -> bool {
    DefaultQueryDispatcher
        .distance(pos12, g1, g2)
        .is_ok_and(|d| d.distance <= prediction)
}

/// parry's contact, robust to shapes that (nearly) touch.
///
/// parry's support-map contact sometimes reports no contact at all for shapes its own distance
/// puts within the prediction: when the shapes touch or nearly touch (a gap of 1e-10, two
/// parallel faces), GJK stops on a degenerate simplex and EPA gives up. This is exactly how
/// rapier's CCD leaves a body after clamping it at an impact, so both the next step's contact and
/// its cast would miss the wall. Then the contact is computed with the shapes pushed into each
/// other by a tiny fraction of their size ([`TOUCH_PUSH`]), and its distance recomputed at the
/// true pose from the witnesses.
pub(crate) fn parry_contact(
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    prediction: Real,
) -> Result<Option<Contact>, Unsupported> {
    if let Some(c) = DefaultQueryDispatcher.contact(pos12, g1, g2, prediction)? {
        return Ok(Some(c));
    }
    if !parry_within(pos12, g1, g2, prediction) {
        return Ok(None);
    }
    let size = pair_size(g1, g2);
    for push in TOUCH_PUSH {
        let deeper = pushed_together(pos12, push * size);
        if let Ok(Some(c)) = DefaultQueryDispatcher.contact(&deeper, g1, g2, prediction + push * size) {
            let dist = (pos12.transform_point(c.point2) - c.point1).dot(c.normal1);
            return Ok((dist <= prediction && dist.is_finite())
                .then(|| Contact::new(c.point1, c.point2, c.normal1, c.normal2, dist)));
        }
    }
    Ok(None)
}

/// parry's nonlinear cast with the window moved to start at time 0 (both motions re-based at
/// `t0`, the hit moved back by `t0`). parry's cast of a pair in contact at the start walks the
/// window with `next_time += increment` and, when the increment is 0 (no relative spin, or two
/// balls), uses `end_time` itself as the increment: with `end_time ≤ 0` (a window before time 0)
/// it never ends, and far from 0 a small increment is lost to rounding. From 0 the walk always
/// moves forward. `t0 = 0` (rapier's CCD) calls parry unchanged.
///
/// That walk takes one contact query per step of min(ccd thickness sum / relative speed,
/// (π − angular thickness) / relative spin, window / 10), and parry's conservative advancement
/// steps of about a distance over an approach speed: a window holding more than
/// [`crate::SmoothDispatcher::PARRY_MAX_STEPS`] such steps, relative turns, or travels of the pair's size (a spin of
/// 1e300 rad/s, a window of 1e160 s) would run for hours, so it is refused with `Unsupported`,
/// as are non-finite motions
/// and times; poses and shapes go through the guards of `input_guard` (`Unsupported` for a
/// non-unit rotation, a non-finite bounding box or a non-finite answer), and a reversed window
/// has no hit.
#[allow(clippy::too_many_arguments)]
pub(crate) fn parry_cast_nonlinear(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
    stop: bool,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    if !input_guard::cast_window_ok(m1, g1, m2, g2, t0, t1)? {
        // A reversed window holds no time: no hit, as for the crate's own casts.
        return Ok(None);
    }
    let hit = if t0 == 0.0 {
        DefaultQueryDispatcher.cast_shapes_nonlinear(m1, g1, m2, g2, t0, t1, stop)?
    } else {
        let at_t0 = |m: &NonlinearRigidMotion| {
            NonlinearRigidMotion::new(m.position_at_time(t0), m.local_center, m.linvel, m.angvel)
        };
        DefaultQueryDispatcher
            .cast_shapes_nonlinear(&at_t0(m1), g1, &at_t0(m2), g2, 0.0, t1 - t0, stop)?
            .map(|h| ShapeCastHit {
                time_of_impact: t0 + h.time_of_impact,
                ..h
            })
    };
    if input_guard::AllFinite::all_finite(&hit) {
        Ok(hit)
    } else {
        Err(Unsupported)
    }
}
