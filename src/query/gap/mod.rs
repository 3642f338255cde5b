//! Time of impact for pairs with no strictly convex side: two convex polygons, each dilated by a
//! radius ≥ 0 (rounded or sharp polygons, segments, capsules, parry's boxes, triangles and
//! polygons).
//!
//! The φ–t tracker of `query::toi` needs one strictly convex side (object2): its contact point
//! comes from the normal. Here neither side has one — a support point jumps across a whole edge
//! when the axis passes the edge's normal — so this module tracks the maximum of the gap itself.
//!
//! ## The distance at one time
//!
//! For a unit axis u the gap G(u) between the shapes along u is a lower bound on their signed
//! distance D, and D = max over u of G (docs/theory.md § 3). For two dilated polygons G is, on
//! each interval between consecutive edge normals (of either body), the gap between two fixed
//! core vertices minus the radii, (b − a)·u − r₁ − r₂: its maximum is closed-form, and the
//! maximum of G is a vertex–vertex direction inside its interval or a face–vertex kink. Where G
//! is positive it is concave (§ 4), so a walk over the intervals from the last step's axis finds
//! it and certifies it; overlapping cores take every candidate axis (`maxgap`). The distance is
//! exact to rounding at every accepted time, and so are D' and D'' (`frame`).
//!
//! ## Why no impact is stepped over
//!
//! From an accepted time tₖ, the gap along an axis that starts at the maximum's axis and turns at
//! a constant rate λ is a lower bound on D. Bounding each body's support function over the
//! directions the axis sweeps in the step — exactly, by the sinusoid of its support vertex, when
//! a polygon's vertex keeps its cone; otherwise by the support point at the far end of the
//! sweep, which pays for a face the sweep crosses, and |p − c| for the curvature of each point's
//! term — gives g(s) ≥ D(tₖ) + a₁s + a₂s²/2 − a₃s³/6 on the step (`guard`). Its first root s_A
//! above the target keeps D above it on [tₖ, tₖ + s_A] whatever the spins, corner radii (0
//! included) or grazing angle. λ is ω₁ or ω₂, whichever gives the longer step: near a
//! face–vertex contact the face's own spin keeps the face still (exact bound), and the steps
//! converge like Newton's on D.
//!
//! A longer step is taken when the same bound taken backwards from its end covers the rest
//! (s_A + s_B ≥ h, after the end's exact distance is known); approaching, the step aims at the
//! root of the Taylor model D + D'h + D''h²/2 = δ and, landing beyond the contact, backs up to
//! the far point's model contact — certified the same way. Near the contact, guarded steps
//! (each safe by itself) refine the time until the gap is below 1e-15·s or the step below
//! 1e-13 of the window; every reported `Hit` is at a time the guard reached, so no earlier
//! contact exists.
//!
//! ## Semantics
//!
//! Those of [`crate::time_of_impact`]: statuses, tolerances, `stop_at_penetration`, the
//! bounding-circle test, the caps of [`crate::ToiOptions`] (`max_steps` on accepted steps,
//! `max_evaluations` on exact distance evaluations). The results are in the caller's order
//! (the method is symmetric: no roles).

mod frame;
mod guard;
mod maxgap;
mod side;
#[cfg(test)]
mod tests;
mod tracker;

pub(crate) use side::{CurveSide, PolySide, Side};

use crate::error::{finite, QueryError};
use crate::numerics::math::{direction, Vector};
use crate::query::path::OnPath;
use crate::query::time_scale::rescaled;
use crate::query::toi::{TimeOfImpact, ToiOptions};
use parry2d_f64::query::NonlinearRigidMotion;
use tracker::GapTracker;

/// The time of impact of `side1` moving by `motion1` and `side2` moving by `motion2` over
/// `[start_time, end_time]` (module docs).
pub(crate) fn gap_time_of_impact(
    side1: Side<'_>,
    motion1: &NonlinearRigidMotion,
    side2: Side<'_>,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    gap_time_at_level(side1, motion1, side2, motion2, start_time, end_time, None, options)
}

/// The first time in `[start_time, end_time]` at which the signed distance of `side1` moving by
/// `motion1` and `side2` moving by `motion2` comes down to `level`, of any sign (a negative
/// level: the shapes interpenetrate by −level), as [`gap_time_of_impact`] with that target. The
/// rest of `options` (tolerances, caps, `stop_at_penetration`) applies as there.
#[allow(clippy::too_many_arguments)]
pub(crate) fn gap_time_to_level(
    side1: Side<'_>,
    motion1: &NonlinearRigidMotion,
    side2: Side<'_>,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    level: f64,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    gap_time_at_level(
        side1,
        motion1,
        side2,
        motion2,
        start_time,
        end_time,
        Some(level),
        options,
    )
}

/// [`gap_time_of_impact`] (no `level`) or [`gap_time_to_level`]: rates beyond 2^±64 per second
/// are run on a time scale where they are about 1 (`query::time_scale`), the motions on the
/// options' path.
#[allow(clippy::too_many_arguments)]
fn gap_time_at_level(
    side1: Side<'_>,
    motion1: &NonlinearRigidMotion,
    side2: Side<'_>,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    level: Option<f64>,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    let size = side1.radius_about(Vector::ZERO).max(side2.radius_about(Vector::ZERO));
    if let Some(r) = rescaled(motion1, motion2, start_time, end_time, size) {
        let a = on_path(side1, &r.m1, side2, &r.m2, r.t0, r.t1, level, options)?;
        return finite(Ok(r.answer(a)));
    }
    finite(on_path(
        side1, motion1, side2, motion2, start_time, end_time, level, options,
    ))
}

/// The gap tracker of the pair on the options' path, down to `level` if given.
#[allow(clippy::too_many_arguments)]
fn on_path(
    side1: Side<'_>,
    motion1: &NonlinearRigidMotion,
    side2: Side<'_>,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    level: Option<f64>,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    let p = OnPath::new(motion1, motion2, start_time, end_time, options.path)?;
    let mut tracker = GapTracker::new(side1, &p.m1, side2, &p.m2, start_time, end_time, options, p.clock)?;
    if let Some(l) = level {
        tracker = tracker.with_level(l);
    }
    tracker.run().map(|r| p.answer(r))
}

/// The signed distance of `side1` and `side2` with `side2` at `pos12` in `side1`'s frame
/// (parry's convention): (distance, witness on side 1 and on side 2 in their own frames, side
/// 1's outward normal). `None` for non-finite input.
pub(crate) fn gap_distance(
    side1: Side<'_>,
    side2: Side<'_>,
    pos12: &parry2d_f64::math::Pose,
) -> Option<(f64, Vector, Vector, Vector)> {
    let m1 = NonlinearRigidMotion::identity();
    let m2 = NonlinearRigidMotion::new(*pos12, Vector::ZERO, Vector::ZERO, 0.0);
    let pair = maxgap::Pair {
        sides: [side1, side2],
        motion: frame::GapMotion::new(&m1, &m2),
    };
    let fr = pair.motion.frame(0.0);
    let t = pos12.translation;
    let u0 = direction(t);
    let at = pair.max_gap(&fr, u0, (0, 0))?;
    let (w1, w2) = pair.witnesses(&fr, &at);
    Some((at.d, w1, w2, fr.to_body(0, at.u)))
}
