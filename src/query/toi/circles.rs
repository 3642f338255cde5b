//! The specification's inexpensive test: bounding circles about the rotation centres, whose
//! relative motion is linear, so that "never within the target in the window" is the closest
//! approach of two points.

use crate::curve::ConvexCurve;
use crate::numerics::math::Vector;
use crate::numerics::motion::motion_is_finite;
use parry2d_f64::query::NonlinearRigidMotion;

/// Relative margin of [`circles_stay_apart`] against rounding.
const CIRCLES_MARGIN: f64 = 1e-12;

/// The distance below which the bounding circles about the rotation centres `c1`, `c2` (each
/// in its shape's local frame) come within `target` of each other: the two radii (bounding radius
/// plus the centre's offset from the local origin) plus the target.
#[inline]
pub(crate) fn circles_reach(radius1: f64, c1: Vector, radius2: f64, c2: Vector, target: f64) -> f64 {
    radius1 + c1.length() + radius2 + c2.length() + target
}

/// Whether two circles whose centres are `offset` apart and move apart at the relative velocity
/// `velocity` stay farther apart than `reach` (the sum of their radii plus the target distance)
/// for a time `span`: min over s ∈ [0, span] of |offset + velocity·s| > reach (with a relative
/// margin of 1e-12 against rounding). False for NaN input.
///
/// The time of closest approach is −offset·v/|v|²; when |v|² leaves the normal range of f64
/// (speeds below about 1e-154 or above 1e154, whose squares underflow to 0 or overflow to ∞)
/// it is taken with v scaled by its largest component, so that a slow approach over a long
/// window is not a pair at rest, nor a fast one a pair that never moves (issue 32).
#[inline]
pub(crate) fn circles_stay_apart(offset: Vector, velocity: Vector, span: f64, reach: f64) -> bool {
    let vv = velocity.length_squared();
    let s = if vv.is_normal() {
        (-offset.dot(velocity) / vv).clamp(0.0, span.max(0.0))
    } else {
        let k = velocity.x.abs().max(velocity.y.abs());
        if k > 0.0 && k.is_finite() {
            let v = velocity / k;
            (-offset.dot(v) / v.length_squared() / k).clamp(0.0, span.max(0.0))
        } else {
            0.0
        }
    };
    (offset + velocity * s).length() > reach * (1.0 + CIRCLES_MARGIN)
}

/// The specification's inexpensive test ("Algorithm usage"): true when the bounding circles of
/// the two shapes — each about its rotation centre (`local_center`), with radius the shape's
/// bounding radius plus the centre's distance from the local origin — stay farther apart than
/// `target_distance` throughout `[start_time, end_time]`. No impact is then possible, and
/// [`crate::time_of_impact`] would answer [`crate::ToiStatus::NoHit`]; callers that need no witnesses for a
/// miss (parry's casts report none) can skip the query. The circles move with the rotation
/// centres, whose relative motion is linear, so the test is the closest approach of two points.
///
/// False whenever anything is non-finite, a bounding radius is not positive or the window is
/// reversed: the query itself then reports the error.
pub fn bounding_circles_part(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    target_distance: f64,
) -> bool {
    let sized = crate::error::curves_sized(&[shape1.bounding_radius(), shape2.bounding_radius()]).is_ok();
    if !(sized && motion_is_finite(motion1) && motion_is_finite(motion2) && start_time <= end_time) {
        return false;
    }
    let reach = circles_reach(
        shape1.bounding_radius(),
        motion1.local_center,
        shape2.bounding_radius(),
        motion2.local_center,
        target_distance,
    );
    if !(reach.is_finite() && target_distance >= 0.0 && (end_time - start_time).is_finite()) {
        return false;
    }
    let centre = |m: &NonlinearRigidMotion| m.start * m.local_center + m.linvel * start_time;
    let offset = centre(motion1) - centre(motion2);
    circles_stay_apart(offset, motion1.linvel - motion2.linvel, end_time - start_time, reach)
}
