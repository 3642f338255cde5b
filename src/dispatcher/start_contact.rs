//! [`StartContactPolicy`]: what `SmoothDispatcher::cast_shapes_nonlinear` answers with
//! `stop_at_penetration = false` for shapes in contact at the start (module docs of
//! `dispatcher`), and the rapier rule itself.

use super::parry_fallback::{pair_size, parry_cast_nonlinear, parry_contact};
use super::SmoothDispatcher;
use crate::numerics::math::{perp, Pose, Real, Vector};
use crate::numerics::motion::PairFrame;
use crate::query::stationary::StationaryDistance;
use crate::query::toi::{TimeOfImpact, ToiStatus};
use parry2d_f64::query::{NonlinearRigidMotion, ShapeCastHit, ShapeCastStatus, Unsupported};
use parry2d_f64::shape::Shape;

/// What `SmoothDispatcher::cast_shapes_nonlinear` answers with `stop_at_penetration = false`
/// (rapier's CCD of solid bodies) for shapes in contact at the start of the window. With
/// `stop_at_penetration = true` both answer the start time with
/// `PenetratingOrWithinTargetDist`, as parry does.
///
/// rapier discards a hit at exactly the start time, so answering the start time for an
/// approaching contact would let a fast body in shallow contact pass through a thin wall;
/// answering just after it freezes a body that spins against a wall (rapier keeps its velocity,
/// its one-point contact does not see the spin, and the next step freezes it again); answering
/// "no hit" for a contact that approaches slowly at the start lets a spinning ellipse turn its
/// tip deep into the wall within the step. The allowance rule bounds the penetration a step adds
/// and lets the body move on.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub enum StartContactPolicy {
    /// rapier's rule (the default, for `NarrowPhase::with_query_dispatcher`): for shapes in
    /// contact at the start (penetrating, or within [`Self::START_CONTACT_GAP`] of the pair's
    /// size), the first time the contact gets deeper than the *allowance*, [`Self::ALLOWANCE`]
    /// of the thinner shape's `ccd_thickness` — or, for a contact already about that deep,
    /// [`Self::DEEPER_FRACTION`] of the allowance deeper than at the start — and no hit when it
    /// does not within the window (at the earliest [`Self::START_NUDGE`] of the window after the
    /// start). The deepening is found on the signed distance along the motions (16 samples, then
    /// bisection), and for a fast approach no later than when the start rate alone reaches the
    /// target. A separating contact at the start is looked past, with the same bound on a later
    /// deepening. The same rule covers the pairs parry answers.
    #[default]
    RapierAllowance,
    /// parry's plain semantics: the answer of [`crate::time_of_impact`] with
    /// `stop_at_penetration = false` (a separating contact at the start is looked past; an
    /// approaching one is reported at the start time), and parry's own answer for the pairs it
    /// answers.
    Plain,
}

impl StartContactPolicy {
    /// The earliest a contact at the start is reported to rapier, as a fraction of the window:
    /// far below any motion rapier resolves, yet strictly after the start time.
    pub const START_NUDGE: f64 = 1e-9;

    /// The penetration a cast for rapier lets a contact at the start reach within the step, as
    /// a fraction of the thinner shape's `ccd_thickness`.
    pub const ALLOWANCE: Real = 0.25;

    /// Once a contact at the start is about as deep as the allowance, a cast for rapier lets it
    /// get deeper by this fraction of the allowance.
    pub const DEEPER_FRACTION: Real = 0.1;

    /// Shapes closer than this fraction of the pair's size (the sum of the bounding radii) at
    /// the start of a cast for rapier are in contact there: rapier's CCD leaves a body clamped
    /// at an impact about 10⁻¹⁰ from the other shape.
    pub const START_CONTACT_GAP: Real = 1e-6;
}

/// Samples on which [`deepening_time`] looks for the penetration getting deeper.
const DEEPENING_SAMPLES: usize = 16;

/// Most bisection steps of [`deepening_time`] (it stops at 10⁻⁹ of the window).
const DEEPENING_BISECTIONS: usize = 48;

/// [`deepening_time`]'s bisection stops at this fraction of the window.
const DEEPENING_RESOLUTION: f64 = 1e-9;

/// For a contact at the start (signed distance `d0`, rate `distance_rate`): the first time in
/// `(t0, t1]` at which the signed distance `signed(t)` drops below the target (at least
/// [`StartContactPolicy::START_NUDGE`] of the window after `t0`), or `None` when it does not within the window.
///
/// The target is minus the *allowance* ([`StartContactPolicy::ALLOWANCE`] of the thinner shape's `ccd_thickness`)
/// or, for a contact already about that deep, [`StartContactPolicy::DEEPER_FRACTION`] of the allowance below `d0`:
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
    let allowance = StartContactPolicy::ALLOWANCE * thickness;
    let target = (-allowance).min(d0 - StartContactPolicy::DEEPER_FRACTION * allowance);
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
    Some(t.max(t0 + StartContactPolicy::START_NUDGE * window))
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
    pub(crate) fn from_distance(d: &StationaryDistance) -> Self {
        StartContact {
            distance: d.distance,
            point1: d.point1,
            point2: d.point2,
            normal1: d.normal1,
        }
    }

    /// The rate of the signed distance at `t0`: the relative velocity of the witness points
    /// along the normal (negative: approaching).
    pub(crate) fn rate(&self, m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion, t0: Real) -> Real {
        let (p1, p2) = (m1.position_at_time(t0), m2.position_at_time(t0));
        let normal = p1.rotation * self.normal1;
        (point_velocity(m2, t0, p2 * self.point2) - point_velocity(m1, t0, p1 * self.point1)).dot(normal)
    }
}

/// The rapier rule (module docs) for a cast with `stop_at_penetration = false` whose answer is
/// `r` (this crate's time of impact, in the caller's order); `start()` is the pair's contact at
/// `t0` (`None` when surely further than `gap` apart) and `signed(t)` its signed distance at `t`.
///
/// * Penetrating and approaching at the start ([`ToiStatus::PenetratingAtStart`]): the
///   answer is [`deepening_time`] (no hit when the contact does not get a quarter of the thinner
///   `ccd_thickness` deeper within the window).
/// * Within `gap` at the start and approaching: the same (it replaces a hit that only closes
///   the gap, which would clamp the body a hair further every step).
/// * Within `gap` at the start and separating: the earlier of a hit from a separated state
///   (`r` with its distance at the target) and [`deepening_time`]; a hit that came while still
///   in contact (the time of impact reports the contact turning back to approach) is replaced.
/// * Otherwise `r`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn rapier_rule(
    r: TimeOfImpact,
    m1: &NonlinearRigidMotion,
    m2: &NonlinearRigidMotion,
    t0: Real,
    t1: Real,
    thickness: Real,
    gap: Real,
    start: impl Fn() -> Option<StartContact>,
    signed: impl Fn(Real) -> Option<Real>,
) -> Option<TimeOfImpact> {
    if r.status == ToiStatus::PenetratingAtStart {
        return deepening_time(r.distance, r.distance_rate, t0, t1, thickness, signed)
            .map(|time| TimeOfImpact { time, ..r });
    }
    if !is_window(t0, t1) {
        return Some(r);
    }
    let Some(c) = start().filter(|c| c.distance <= gap) else {
        return Some(r);
    };
    let rate = c.rate(m1, m2, t0);
    // A deepening contact is a penetrating one whatever `r` was (parry's
    // `PenetratingOrWithinTargetDist`).
    let deeper = deepening_time(c.distance, rate, t0, t1, thickness, signed).map(|time| TimeOfImpact {
        time,
        status: ToiStatus::PenetratingAtStart,
        ..r
    });
    if rate < 0.0 {
        return deeper;
    }
    let hit = r.status.to_parry().is_some() && r.time > t0;
    let from_separated = hit && r.distance >= -gap;
    match (from_separated, deeper) {
        (true, Some(d)) if d.time < r.time => Some(d),
        (true, _) => Some(r),
        (false, Some(d)) => Some(d),
        (false, None) if hit => None,
        (false, None) => Some(r),
    }
}

/// Whether `[t0, t1]` is a non-empty finite window (false for NaN).
pub(crate) fn is_window(t0: Real, t1: Real) -> bool {
    t1 > t0 && (t1 - t0).is_finite()
}

/// Shape 2's pose in shape 1's frame at time `t`.
pub(crate) fn pos12_at(m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion, t: Real) -> Pose {
    // From the pair's relative motion, as the trackers place it (issue 32): the world poses
    // of two bodies 1e15 from the origin carry 0.1 of rounding each.
    PairFrame::at_time(m1, m2, t).pos12()
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
/// [`parry_contact`] with a gap of at most [`StartContactPolicy::START_CONTACT_GAP`] of the size) is reported at [`StartContactPolicy::START_NUDGE`] of the window when the approach over the
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
    let gap = StartContactPolicy::START_CONTACT_GAP * pair_size(g1, g2);
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
