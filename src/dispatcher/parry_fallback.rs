//! parry's answers for the pairs handed to it, made robust: a contact for shapes that nearly
//! touch (where GJK/EPA give up), a nonlinear cast whose window does not start at 0 (where
//! parry's walk would not end), and the input guards around both.

use super::cast::{is_window, pos12_at};
use super::input_guard;
use super::rapier_rule::CastPolicy;
use super::SmoothDispatcher;
use crate::numerics::math::{perp, Pose, Real, Vector};
use parry2d_f64::query::{
    Contact, DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit, ShapeCastStatus, Unsupported,
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
    size_of_radii(
        g1.compute_local_bounding_sphere().radius,
        g2.compute_local_bounding_sphere().radius,
    )
}

/// [`pair_size`] of two shapes of bounding radii `r1` and `r2`.
pub(crate) fn size_of_radii(r1: Real, r2: Real) -> Real {
    let r = |r: Real| if r.is_finite() && r < 0.5 * Real::MAX { r } else { 0.0 };
    r(r1) + r(r2)
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
    // Positions that rounding resolves (`input_guard::resolved_motions`).
    let Some((m1, m2)) = input_guard::resolved_motions(m1, g1, m2, g2, t0, t1)? else {
        return Ok(None);
    };
    let (m1, m2) = (&m1, &m2);
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

/// Once a contact at the start is about as deep as the allowance, [`deepening_time`] lets it
/// get deeper by this fraction of the allowance.
const DEEPER_FRACTION: Real = 0.1;

/// Samples on which [`deepening_time`] looks for the penetration getting deeper.
const DEEPENING_SAMPLES: usize = 16;

/// Most bisection steps of [`deepening_time`] (it stops at 10⁻⁹ of the window).
const DEEPENING_BISECTIONS: usize = 48;

/// [`deepening_time`]'s bisection stops at this fraction of the window.
const DEEPENING_RESOLUTION: f64 = 1e-9;

/// For a contact at the start (signed distance `d0`, rate `distance_rate`): the first time in
/// `(t0, t1]` at which the signed distance `signed(t)` drops below the target (at least
/// [`CastPolicy::START_NUDGE`] of the window after `t0`), or `None` when it does not within the window.
///
/// The target is minus the *allowance* ([`CastPolicy::ALLOWANCE`] of the thinner shape's `ccd_thickness`)
/// or, for a contact already about that deep, [`DEEPER_FRACTION`] of the allowance below `d0`:
/// a step adds at most the allowance to a shallow contact, and a deep one (rapier's solver
/// pushes a one-point contact out slowly while a spin keeps turning the body in) still moves on
/// a little each step rather than freezing. The search runs up to `t_lin`, when the start rate
/// alone would have reached the target (or the end of the window): [`DEEPENING_SAMPLES`]
/// samples, then bisection (to 10⁻⁹ of the window) between the last sample above and the first
/// below. A spinning body whose contact approaches slowly at the start can dive deep within the
/// step (an ellipse's tip turning into a wall), which the samples see; a fast body that would
/// pass a thin wall within one sample interval is stopped at `t_lin`.
pub(crate) fn deepening_time(
    d0: Real,
    distance_rate: Real,
    t0: Real,
    t1: Real,
    thickness: Real,
    signed: impl Fn(Real) -> Option<Real>,
) -> Option<Real> {
    let window = t1 - t0;
    let allowance = CastPolicy::ALLOWANCE * thickness;
    let target = (-allowance).min(d0 - DEEPER_FRACTION * allowance);
    let t_lin = if distance_rate < 0.0 {
        t0 + (d0 - target) / -distance_rate
    } else {
        Real::INFINITY
    };
    let end = t_lin.min(t1);
    let below = |t: Real| signed(t).is_some_and(|d| d < target);
    let mut lo = t0;
    let mut hit = None;
    for k in 1..=DEEPENING_SAMPLES {
        let t = t0 + (end - t0) * k as Real / DEEPENING_SAMPLES as Real;
        if below(t) {
            hit = Some(t);
            break;
        }
        lo = t;
    }
    let t = match hit {
        Some(mut hi) => {
            for _ in 0..DEEPENING_BISECTIONS {
                if hi - lo <= DEEPENING_RESOLUTION * window {
                    break;
                }
                let mid = 0.5 * (lo + hi);
                if below(mid) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            hi
        }
        None if t_lin <= t1 => t_lin,
        None => return None,
    };
    Some(t.max(t0 + CastPolicy::START_NUDGE * window))
}

/// The contact of a pair at the start of a cast: signed distance, witnesses in each shape's
/// frame and shape 1's normal.
#[derive(Clone, Copy)]
pub(crate) struct StartContact {
    pub(crate) distance: Real,
    pub(crate) point1: Vector,
    pub(crate) point2: Vector,
    pub(crate) normal1: Vector,
}

impl StartContact {
    /// The rate of the signed distance at `t0`: the relative velocity of the witness points
    /// along the normal (negative: approaching).
    pub(crate) fn rate(&self, m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion, t0: Real) -> Real {
        let (p1, p2) = (m1.position_at_time(t0), m2.position_at_time(t0));
        let normal = p1.rotation * self.normal1;
        (point_velocity(m2, t0, p2 * self.point2) - point_velocity(m1, t0, p1 * self.point1)).dot(normal)
    }
}

/// Velocity at time `t` of the body-fixed point that is at world position `p` then.
fn point_velocity(m: &NonlinearRigidMotion, t: Real, p: Vector) -> Vector {
    let centre = m.position_at_time(t) * m.local_center;
    m.linvel + perp(p - centre) * m.angvel
}

/// parry's nonlinear cast with `stop_at_penetration = false`, under the same start-contact rule
/// as this crate's own casts (module docs), for pairs of this crate's shapes that parry answers
/// (no strictly convex side: a rounded polygon against a box, …).
///
/// parry answers a pair in contact at the start and approaching faster than the sum of the
/// `ccd_thickness`es with `time_of_impact = start_time`, which rapier discards: the body would
/// pass through a thin wall; and when the shapes touch exactly (after rapier's CCD clamped the
/// body at the previous step's impact), parry's contact fails and the cast answers no hit at
/// all. Here a contact at the start (parry's hit at the start time, or a contact from
/// [`parry_contact`] with a gap of at most [`CastPolicy::START_CONTACT_GAP`] of the size) is reported at [`CastPolicy::START_NUDGE`] of the window when the approach over the
/// window, from the relative velocity of the witness points along the normal, exceeds a quarter
/// of the thinner shape's `ccd_thickness`; otherwise the cast answers no hit, as the crate's own
/// casts do. A later hit of parry's is returned unchanged.
#[allow(clippy::too_many_arguments)]
pub(crate) fn parry_nonlinear_without_stop(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    let hit = parry_cast_nonlinear(m1, g1, m2, g2, t0, t1, false)?;
    // Reversed, empty or non-finite windows: parry's answer.
    if !is_window(t0, t1) {
        return Ok(hit);
    }
    // parry's answer, but a hit at the start (which rapier discards) only through the rule.
    let later = hit.filter(|h| h.time_of_impact > t0);
    let pos12 = pos12_at(m1, m2, t0);
    let gap = CastPolicy::START_CONTACT_GAP * pair_size(g1, g2);
    let start = if SmoothDispatcher::far_apart(&pos12, g1, g2, gap) {
        None
    } else {
        parry_contact(&pos12, g1, g2, gap).ok().flatten().map(|c| StartContact {
            distance: c.dist,
            point1: c.point1,
            point2: c.point2,
            normal1: c.normal1,
        })
    };
    // parry's hit at the start says the shapes touch even if the contact could not be had.
    let start = start.or_else(|| {
        hit.filter(|h| h.time_of_impact <= t0).map(|h| StartContact {
            distance: 0.0,
            point1: h.witness1,
            point2: h.witness2,
            normal1: h.normal1,
        })
    });
    let Some(c) = start else {
        return Ok(later);
    };
    let rate = c.rate(m1, m2, t0);
    let thickness = g1.ccd_thickness().min(g2.ccd_thickness());
    let signed = |t: Real| {
        parry_contact(&pos12_at(m1, m2, t), g1, g2, 0.0)
            .ok()
            .flatten()
            .map(|c| c.dist)
    };
    let deeper = deepening_time(c.distance, rate, t0, t1, thickness, signed);
    // The hit at a deepening of the start contact: its witnesses, at time `t`.
    let deepening_hit = |t: Real| ShapeCastHit {
        time_of_impact: t,
        witness1: c.point1,
        witness2: c.point2,
        normal1: c.normal1,
        normal2: pos12.rotation.inverse() * -c.normal1,
        status: ShapeCastStatus::PenetratingOrWithinTargetDist,
        subshape1: 0,
        subshape2: 0,
    };
    // Separating at the start: the earlier of parry's later hit and a deepening of the contact.
    if rate.is_nan() || rate >= 0.0 {
        return Ok(match (later, deeper) {
            (Some(h), Some(t)) if t >= h.time_of_impact => Some(h),
            (Some(h), None) => Some(h),
            (_, Some(t)) => Some(deepening_hit(t)),
            (None, None) => None,
        });
    }
    Ok(deeper.map(deepening_hit))
}
