//! Time of impact between two moving convex objects by tracking the zero level of
//! distanceSide(φ, t) ("Distance Between Two Moving Objects", "One step of the algorithm",
//! "Backtracking" and "Correction φ to let it zero" of the specification).
//!
//! ## The algorithm
//!
//! 1. At t₀ the stationary distance gives φ₀ and D₀ = F(φ₀, t₀) ([`crate::stationary_distance`]).
//! 2. Each step, at an accepted point (φₖ, tₖ) with S ≈ 0 and Dₖ = F(φₖ, tₖ) above the target δ:
//!    * the Taylor polynomial of S of order 2 (eqs. 7–8) gives the curve's slope φ' = −S_t/S_φ and
//!      bending φ'' = −(S_tt + 2S_φt φ' + S_φφ φ'²)/S_φ; along it D' = F_t and
//!      D'' = F_tt + F_φt φ' (F_φ = −ω₁S vanishes on the curve);
//!    * the step h is the smallest of the adaptive accuracy step, a φ-travel of one radian, the
//!      window's end, and the **guard** below (possibly lengthened by its two-sided form); the
//!      predictor moves to φₖ − S/S_φ + φ'h + φ''h²/2 at tₖ + h (the first term removes what is
//!      left of S at the accepted point);
//!    * the **corrector** solves S(φ, tₖ + h) = 0 by Halley's method at fixed t from the
//!      prediction, falling back to a bracketed solve when an iteration does not shrink |S|
//!      (derivatives jump at piece ends). Away from contact it accepts an |S| whose cost in F,
//!      ω₁S²/(2S_φ), is at most 2 % of the gap D − δ, or up to a tenth of the gap (and a Newton
//!      step |S/S_φ| of at most 0.3 rad, which the next prediction removes): F at such a φ is
//!      below the distance by at most 2 % of the gap, so most predictions are accepted as they
//!      are or after one iteration; the tolerance tightens by itself to the side tolerance as the
//!      contact nears;
//!    * when the corrector fails, or lands on a root that is not a maximum of F, the step is
//!      **backtracked**: h is halved and the step retried.
//! 3. It stops at contact (Dₖ − δ ≤ tol), when the bounding circles about the rotation centres
//!    can no longer meet before the window ends, or at the window's end. A miss is reported with
//!    the witnesses corrected to the side tolerance.
//!
//! φ is brought back into [−π, π) at every accepted point: left to grow with the turns of the
//! pair, it would lose the resolution the corrector needs (thin arcs against flat sides turn a
//! φ error of a few ulps at |φ| ≈ 6e3 into 7e-9·s of distance; `Tracker::rewrap`). The trace
//! records φ unwrapped.
//!
//! ## Why no impact is stepped over (the guard)
//!
//! For any unit axis n, the gap G(n, t) between the shapes along n (minus the two support values)
//! is a lower bound on the signed distance, and F(φ, t) = G(N(φ, t), t). Take the axis that is
//! object1's normal N(φₖ) at tₖ and turns at a constant rate λ in the world:
//! g(t) = G(R(λ(t − tₖ))nₖ, t) ≤ D(t), with g(tₖ) = F(φₖ, tₖ) and, since ∂G/∂θ = −S,
//! g'(tₖ) = F_t − (λ − ω₁)·S. With support functions h̃ᵢ about the rotation centres and ΔC the
//! offset of the centres, g = −ΔC·n − h̃₁(R(−α₁)n) − h̃₂(−R(−α₂)n), so
//!
//! ```text
//! |g''| ≤ M(λ) = λ²·max|ΔC| + 2|λ||ΔV| + (λ − ω₁)²·H₁ + (λ − ω₂)²·H₂,   Hᵢ ≥ max|h̃ᵢ''|,
//! ```
//!
//! with ΔV the relative velocity of the centres and max|ΔC| their largest distance over the step
//! (ΔC is affine in t, so its norm is convex and the maximum sits at an end). λ = ω₁ (the axis
//! fixed in object1; H₁ is not needed, which is what a polygon requires) gives the classical
//! M = ω²H₂ + 2|ω₁||ΔV| + ω₁²max|ΔC|; when object1 is strictly convex the λ minimising M is used
//! (a weighted mean of 0, ω₁ and ω₂). Hᵢ = |h''|-bound + |cᵢ|, where the |h''|-bound is
//! [`ConvexCurve::support_dd_bound_near`] over the directions the axis sweeps in the step (for
//! a thin ellipse far smaller than the global bound a²/b away from its flat sides).
//!
//! Then g(t) ≥ gₖ + g'ₖs − Ms²/2 on the step, and with Δ = Dₖ − δ the step
//! s_A = 2Δ / (−g'ₖ + √(g'ₖ² + 2MΔ)) keeps that bound above the target: D(t) ≥ δ on
//! [tₖ, tₖ + s_A]. No dip of the distance below the target can be stepped over, whatever the
//! spin, corner radius or grazing angle, and this does not rely on the corrector's accuracy (φₖ
//! need not be an exact root: any φ gives a lower bound). Approaching (D' < 0) the guard behaves
//! like a Newton step on D, so it also converges to the contact; when D' ≥ 0 it is at least
//! √(2Δ/M).
//!
//! **Two-sided form.** The same bound taken backwards from the end of a step, with the point
//! corrected there, covers [tₖ₊₁ − s_B, tₖ₊₁]; a step is safe when s_A + s_B ≥ tₖ₊₁ − tₖ. The
//! tracker proposes steps up to 2·s_A, checks s_A + s_B after the correction, and otherwise
//! retries with the plain guard step s_A.
//!
//! **Aiming at the contact.** Approaching, when the root h_m of the Taylor model of D
//! (Dₖ − δ + D'h + D''h²/2) lies beyond s_A but within the extension, the step goes exactly to
//! h_m: near contact the model is accurate to O(h³), so the corrected point usually meets the
//! contact test at once instead of closing in by guard steps. If the corrected point is below
//! the target by more than the contact floor (1e-12·s), the contact lies inside the step: the
//! tracker backs up from that far point along its own Taylor model of D to the target
//! (`Tracker::back_to_contact`), corrects there tightly and certifies that point instead; the
//! backward bound s_B of an aimed step is taken from the floor level, so the interval between
//! the two ends is covered by the guard from both sides. M is first taken with the global
//! curvature bounds; the bounds local to the step's directions (square roots and divisions) are
//! computed only when that M limits the step and does not already certify the aim with room to
//! spare (h_m < 2s_A and s_A + s_B/2 ≥ h_m, s_B estimated from the model's D' at h_m): near the
//! contact they could not change the step. The certification after the correction uses the M
//! the step was planned with, whichever it is.
//!
//! ## Contact at the start
//!
//! With `stop_at_penetration` the answer is t₀ with [`ToiStatus::PenetratingAtStart`]. Without
//! it (rapier's CCD for solid bodies), a contact that is separating (D' > 0) is ignored and the
//! answer is the first later time the distance comes back down to the target; if the shapes
//! keep approaching, the answer is t₀.

// The negated comparisons (`!(x > 0.0)`) are deliberate: they are true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub(crate) mod circles;
mod corrector;
mod endgame;
mod guard;
#[cfg(test)]
mod tests;
mod tracker;
mod types;

pub use circles::bounding_circles_part;
pub(crate) use types::{NoTrace, Tracer};
pub use types::{TimeOfImpact, ToiCost, ToiOptions, ToiStatus, TraceEvent};

use crate::curve::ConvexCurve;
use crate::error::{finite, QueryError};
use crate::numerics::motion::{PairFrame, RelativeMotion};
use crate::query::path::OnPath;
use crate::query::time_scale::{rescaled, Rescaled, ScaledTrace};
use parry2d_f64::query::NonlinearRigidMotion;

/// The time of impact of `shape1` moving by `motion1` and `shape2` moving by `motion2` in
/// `[start_time, end_time]`. One of the shapes must be strictly convex (it plays object2; the
/// result is reported in the caller's order); for two shapes with flat faces on both sides
/// (polygons, boxes, capsule-ellipses) use [`crate::shape_time_of_impact`], which takes any two
/// convex parry shapes.
///
/// The shapes may be trait objects (`&dyn ConvexCurve`) or of known types; with known types the
/// query is compiled for that pair, and the curves' evaluations are inlined into it (about a
/// fifth faster for two ellipses). [`crate::SmoothDispatcher`] does so for ellipses and discs.
///
/// Two discs of radius 1 closing head-on at 2 m/s from 4 apart touch when the gap of 2 is
/// closed, at t = 1:
///
/// ```
/// use parry2d_f64::math::{Pose, Vector};
/// use parry2d_f64::query::NonlinearRigidMotion;
/// use smooth_ccd2d::{time_of_impact, Ellipse, ToiOptions, ToiStatus};
///
/// let disc = Ellipse::new(1.0, 1.0);
/// let m1 = NonlinearRigidMotion::new(Pose::translation(-2.0, 0.0), Vector::ZERO, Vector::new(1.0, 0.0), 0.0);
/// let m2 = NonlinearRigidMotion::new(Pose::translation(2.0, 0.0), Vector::ZERO, Vector::new(-1.0, 0.0), 5.0);
/// let r = time_of_impact(&disc, &m1, &disc, &m2, 0.0, 3.0, &ToiOptions::default()).unwrap();
/// assert_eq!(r.status, ToiStatus::Hit);
/// assert!((r.time - 1.0).abs() < 1e-12);
/// assert!((r.normal1 - Vector::X).length() < 1e-9);
/// ```
pub fn time_of_impact<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    shape1: &A,
    motion1: &NonlinearRigidMotion,
    shape2: &B,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    finite(toi_roles(
        shape1,
        motion1,
        shape2,
        motion2,
        start_time,
        end_time,
        options,
        &mut NoTrace,
    ))
}

/// As [`time_of_impact`], recording every predictor step, correction and backtrack in `trace`
/// (in object1/object2 roles: φ is object1's parameter, where object1 is `shape1` unless only
/// `shape1` is strictly convex).
#[allow(clippy::too_many_arguments)]
pub fn time_of_impact_traced<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    shape1: &A,
    motion1: &NonlinearRigidMotion,
    shape2: &B,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    options: &ToiOptions,
    trace: &mut Vec<TraceEvent>,
) -> Result<TimeOfImpact, QueryError> {
    finite(toi_roles(
        shape1, motion1, shape2, motion2, start_time, end_time, options, trace,
    ))
}

#[allow(clippy::too_many_arguments)]
fn toi_roles<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized, T: Tracer>(
    shape1: &A,
    motion1: &NonlinearRigidMotion,
    shape2: &B,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    options: &ToiOptions,
    trace: &mut T,
) -> Result<TimeOfImpact, QueryError> {
    // Rates beyond 2^±64 per second: the same query on a time scale where they are about 1
    // (`query::time_scale`, issue 32).
    let size = shape1.bounding_radius().max(shape2.bounding_radius());
    if let Some(r) = rescaled(motion1, motion2, start_time, end_time, size) {
        return toi_rescaled(shape1, shape2, options, trace, &r);
    }
    toi_roles_at_scale(shape1, motion1, shape2, motion2, start_time, end_time, options, trace)
}

/// [`toi_roles`] of a rescaled query, its answer and trace on the original time scale. Out of
/// line: the ordinary queries' path stays as short as it was.
#[cold]
#[inline(never)]
fn toi_rescaled<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized, T: Tracer>(
    shape1: &A,
    shape2: &B,
    options: &ToiOptions,
    trace: &mut T,
    r: &Rescaled,
) -> Result<TimeOfImpact, QueryError> {
    let mut scaled = ScaledTrace {
        inner: trace,
        scale: r.scale,
    };
    let a = toi_roles_at_scale(shape1, &r.m1, shape2, &r.m2, r.t0, r.t1, options, &mut scaled)?;
    Ok(r.answer(a))
}

/// [`toi_roles`] on the query's own time scale.
#[allow(clippy::too_many_arguments)]
fn toi_roles_at_scale<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized, T: Tracer>(
    shape1: &A,
    motion1: &NonlinearRigidMotion,
    shape2: &B,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    options: &ToiOptions,
    trace: &mut T,
) -> Result<TimeOfImpact, QueryError> {
    if !(shape2.is_strictly_convex() || shape1.is_strictly_convex()) {
        return Err(QueryError::NotStrictlyConvex);
    }
    let p = OnPath::new(motion1, motion2, start_time, end_time, options.path)?;
    let (m1, m2) = (&p.m1, &p.m2);
    if shape2.is_strictly_convex() {
        let r = Tracker::new(shape1, m1, shape2, m2, start_time, end_time, options, p.clock)?.run(trace)?;
        Ok(p.answer(r))
    } else {
        let r = Tracker::new(shape2, m2, shape1, m1, start_time, end_time, options, p.clock)?.run(trace)?;
        Ok(p.answer(r.swapped()))
    }
}

/// The state of one query (module docs): the shapes in object1/object2 roles, their relative
/// motion, the options and what the step loop keeps between steps. Its methods are spread over
/// the modules of this folder by concern: `tracker` (the step loop), `corrector`, `guard`,
/// `endgame`.
struct Tracker<'a, A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized> {
    obj1: &'a A,
    obj2: &'a B,
    rel: RelativeMotion,
    omega1: f64,
    t0: f64,
    t1: f64,
    opts: ToiOptions,
    size: f64,
    /// Radius about the rotation centres that contains each shape, summed, plus δ.
    reach: f64,
    tol_d: f64,
    side_tol: f64,
    /// |c₂|, |c₁|: the rotation centres' distances from the local origins (support functions
    /// about the rotation centres: |h̃''| ≤ |h''| + |c|).
    c2_len: f64,
    c1_len: f64,
    /// |ΔV|: the speed of object1's rotation centre relative to object2's.
    dv_len: f64,
    /// Object1 is strictly convex (its support function has a bounded h'').
    obj1_convex: bool,
    /// The global bounds on |h''| of each ([`ConvexCurve::support_dd_bound`]).
    h1_global: f64,
    h2_global: f64,
    /// Whole turns taken out of φ by [`Tracker::rewrap`], to record φ unwrapped in the trace.
    turns: f64,
    /// Object2's angular velocity when it is tracked without it (a disc spinning about its
    /// centre, [`Tracker::new`]); 0 otherwise. Object2's frame of `rel` is then its frame at
    /// t = 0, and [`Tracker::result`] turns the witnesses into its frame at the reported time.
    spin2: f64,
    cost: ToiCost,
    /// The frame at the last time asked for ([`Tracker::frame`]).
    last_frame: PairFrame,
    /// The rotation centres run on a clock (the nlerp path, `numerics::clock`).
    clock: bool,
}
