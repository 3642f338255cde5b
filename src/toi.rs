//! Time of impact between two moving convex objects by tracking the zero level of
//! distanceSide(φ, t) ("Distance Between Two Moving Objects", "One step of the algorithm",
//! "Backtracking" and "Correction φ to let it zero" of the specification).
//!
//! ## The algorithm
//!
//! 1. At t₀ the stationary distance gives φ₀ and D₀ = F(φ₀, t₀) ([`crate::stationary`]).
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

use crate::curve::{wrap_phi, ConvexCurve};
use crate::distances::{eval_point, PairFrame, PairJet, PairPoint, RelativeMotion};
use crate::math::Vector;
use crate::stationary::{stationary_in_frame, DistanceOptions, QueryError, Solver};
use core::f64::consts::TAU;
use parry2d_f64::query::NonlinearRigidMotion;

/// The |S| a correction accepts.
#[derive(Copy, Clone)]
enum Tol {
    /// This |S| (the side tolerance).
    Fixed(f64),
    /// A fraction of the gap away from contact ([`Tracker::loose_side`]).
    Loose,
}

/// Halley iterations the corrector tries from the prediction before the bracketed solver.
const HALLEY_TRIES: usize = 4;
/// |S| accepted away from contact, as a fraction of the gap F − δ ([`Tracker::loose_side`]).
const LOOSE_SIDE: f64 = 0.1;
/// Largest F deficit ω₁S²/(2S_φ) an inexact root may cost away from contact, as a fraction of the
/// gap F − δ ([`Tracker::loose_side`]). 2 % took the fewest evaluations at the ellipse medians
/// (0.5 %: 12 at the ellipse–ball median, 2 %: 10; 5 %: shorter guard steps, slower ellipse pairs).
const LOOSE_DEFICIT: f64 = 2e-2;
/// Away from contact the residual's Newton step |S/S_φ| must also stay below this (radians):
/// on a flat piece S can be large while F is exact. The next prediction starts with that step.
const LOOSE_PHI: f64 = 3e-1;
/// Largest Halley step of the corrector (radians): beyond it, or when a step does not shrink |S|,
/// the bracketed solver takes over. 1 rad instead of 0.3 let the corrector converge from the
/// poorer predictions of long steps (5 % fewer instructions over the ellipse pairs' hits).
const HALLEY_MAX_STEP: f64 = 1.0;
/// How far below the target a reported contact may be, relative to the size (the `Hit`
/// contract: D ≥ δ − 1e-12·s).
const CONTACT_FLOOR: f64 = 1e-12;
/// The refinement of a contact ([`Tracker::refine_hit`]) stops when its next Newton step on D
/// would move the time by less than this fraction of the window: the time is then within about
/// that of the contact (the accuracy tests allow 1e-9; the worst measured is in the README).
const REFINE_TIME: f64 = 1e-13;
/// Largest φ-travel of one predictor step (radians).
const MAX_TRAVEL: f64 = 1.0;

/// Tolerances, caps and switches of [`time_of_impact`]. Distances are relative to the size s
/// of the pair: the larger bounding radius of the two shapes about their local origins.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct ToiOptions {
    /// Target distance δ ≥ 0 (absolute): contact is D(t) = δ. Default 0.
    pub target_distance: f64,
    /// Contact is accepted when δ ≤ D ≤ δ + `distance_tolerance`·s (default 1e-10).
    pub distance_tolerance: f64,
    /// |distanceSide| accepted by the corrector, relative to s (default 1e-10).
    pub side_tolerance: f64,
    /// Cap on accepted predictor steps (default 20 000).
    pub max_steps: usize,
    /// Cap on pair evaluations of one query, all steps together (default 1 000 000: tens of
    /// milliseconds; ordinary queries take tens to thousands). Reaching it ends the query with
    /// [`ToiStatus::OutOfIterations`]; it bounds the time of a query whatever the input.
    pub max_evaluations: usize,
    /// Cap on Halley iterations of one correction (default 30).
    pub max_corrector_iterations: usize,
    /// Report an initial contact immediately (true) or look past a separating one (false).
    pub stop_at_penetration: bool,
    /// Options of the stationary distance used at the start and to recover.
    pub distance: DistanceOptions,
}

impl Default for ToiOptions {
    fn default() -> Self {
        Self {
            target_distance: 0.0,
            distance_tolerance: 1e-10,
            side_tolerance: 1e-10,
            max_steps: 20_000,
            max_evaluations: 1_000_000,
            max_corrector_iterations: 30,
            stop_at_penetration: true,
            distance: DistanceOptions::default(),
        }
    }
}

/// How a time-of-impact query ([`time_of_impact`], [`crate::halfspace::time_of_impact_halfspace`])
/// ended. Whatever the status, `time` lies in `[start_time, end_time]` and every number of the
/// [`TimeOfImpact`] is finite; bad input is a [`QueryError`] instead. Below, δ is the target
/// distance, tol = `distance_tolerance`·s and s the larger bounding radius of the two shapes.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum ToiStatus {
    /// The shapes reach the target distance at `time` and not before:
    /// δ − 1e-12·s ≤ D(`time`) ≤ δ + tol, and D > δ − 1e-12·s on [start, `time`).
    ///
    /// One exception, with `stop_at_penetration = false` only: shapes in contact at the start
    /// and separating are followed until they part; if they approach again while still in
    /// contact, `time` is that moment and `distance` ≤ δ + tol (rapier's CCD for solid bodies).
    Hit,
    /// The shapes are within δ + tol at the start, and `stop_at_penetration` is set or they are
    /// approaching (D' ≤ 0 along the contact): `time` is the start time. Also the answer of an
    /// empty window (`start_time == end_time`) with the shapes in contact.
    PenetratingAtStart,
    /// No contact in the window: D > δ − 1e-12·s until `end_time` (a graze that comes within
    /// tol of δ without reaching it may end either way), or the bounding circles about the
    /// rotation centres part for good (`time` is where tracking stopped). Also: an empty window
    /// with the shapes apart, and, with `stop_at_penetration = false`, a contact at the start
    /// that keeps separating until the window ends.
    NoHit,
    /// A cap was reached before the window was covered: [`ToiOptions::max_steps`] predictor
    /// steps, [`ToiOptions::max_evaluations`] pair evaluations, or a step the guard allows is
    /// too short to advance `time` in floating point (a spin too fast for the window). No
    /// contact in [start, `time`); nothing is known after. Seen with thin ellipses (1:1e6)
    /// spinning for many turns, and beyond the supported scales and axis ratios (README, Limits).
    OutOfIterations,
}

impl ToiStatus {
    /// parry's status for a reported hit (`None` for [`ToiStatus::NoHit`]).
    pub fn to_parry(self) -> Option<parry2d_f64::query::ShapeCastStatus> {
        use parry2d_f64::query::ShapeCastStatus as S;
        match self {
            ToiStatus::Hit => Some(S::Converged),
            ToiStatus::PenetratingAtStart => Some(S::PenetratingOrWithinTargetDist),
            ToiStatus::OutOfIterations => Some(S::OutOfIterations),
            ToiStatus::NoHit => None,
        }
    }
}

/// What a query cost.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct ToiCost {
    /// Accepted predictor steps.
    pub predictor_steps: usize,
    /// Halley (and bisection) iterations of the corrector, all steps together.
    pub corrector_iterations: usize,
    /// Rejected steps retried with a shorter step.
    pub backtracks: usize,
    /// Evaluations of the pair (φ-only and full jets).
    pub evaluations: usize,
    /// Steps whose length was set by the guard.
    pub guard_limited_steps: usize,
}

/// The result of [`time_of_impact`]. Points and normals are at `time`, each in its own shape's
/// local frame, in the caller's order of the shapes.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct TimeOfImpact {
    /// How the query ended.
    pub status: ToiStatus,
    /// Impact time (`Hit`), start time (`PenetratingAtStart`), last safe time
    /// (`OutOfIterations`), or where tracking stopped (`NoHit`).
    pub time: f64,
    /// Signed distance at `time`.
    pub distance: f64,
    /// dD/dt at `time` along the contact (negative: approaching).
    pub distance_rate: f64,
    /// Witness point on shape 1 (its local frame).
    pub point1: Vector,
    /// Witness point on shape 2 (its local frame).
    pub point2: Vector,
    /// Shape 1's outward normal at its witness (its local frame).
    pub normal1: Vector,
    /// Shape 2's outward normal at its witness (its local frame).
    pub normal2: Vector,
    /// What it cost.
    pub cost: ToiCost,
}

impl TimeOfImpact {
    /// The same impact with the roles of the two shapes exchanged (witness points and normals
    /// swapped; time, distance and cost unchanged).
    pub fn swapped(self) -> Self {
        Self {
            point1: self.point2,
            point2: self.point1,
            normal1: self.normal2,
            normal2: self.normal1,
            ..self
        }
    }
}

/// One event of the tracked path, for figures and debugging ([`time_of_impact_traced`]).
///
/// φ is recorded unwrapped — continuous along the path, so it may leave [−π, π) after turns;
/// wrap it with [`crate::wrap_phi`] to evaluate or draw.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum TraceEvent {
    /// The starting point from the stationary distance.
    Start {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
        /// D.
        distance: f64,
    },
    /// A predictor step landed at (φ, t).
    Predict {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
    },
    /// A corrector iteration at fixed t moved to φ with distanceSide `side`.
    Correct {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
        /// distanceSide after the iteration.
        side: f64,
    },
    /// A step was rejected at t and retried shorter.
    Backtrack {
        /// φ of the rejected point.
        phi: f64,
        /// t of the rejected point.
        t: f64,
    },
    /// A step was accepted at (φ, t) with distance D.
    Accept {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
        /// D.
        distance: f64,
    },
    /// Contact.
    Impact {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
    },
}

trait Tracer {
    fn push(&mut self, e: TraceEvent);
}
struct NoTrace;
impl Tracer for NoTrace {
    #[inline(always)]
    fn push(&mut self, _: TraceEvent) {}
}
impl Tracer for Vec<TraceEvent> {
    fn push(&mut self, e: TraceEvent) {
        Vec::push(self, e)
    }
}

/// The time of impact of `shape1` moving by `motion1` and `shape2` moving by `motion2` in
/// `[start_time, end_time]`. One of the shapes must be strictly convex (it plays object2; the
/// result is reported in the caller's order).
///
/// The shapes may be trait objects (`&dyn ConvexCurve`) or of known types; with known types the
/// query is compiled for that pair, and the curves' evaluations are inlined into it (about a
/// fifth faster for two ellipses). [`crate::SmoothDispatcher`] does so for ellipses and discs.
pub fn time_of_impact<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    shape1: &A,
    motion1: &NonlinearRigidMotion,
    shape2: &B,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    crate::error::finite_toi(toi_roles(
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
    crate::error::finite_toi(toi_roles(
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
    if shape2.is_strictly_convex() {
        Tracker::new(shape1, motion1, shape2, motion2, start_time, end_time, options)?.run(trace)
    } else if shape1.is_strictly_convex() {
        let r = Tracker::new(shape2, motion2, shape1, motion1, start_time, end_time, options)?.run(trace)?;
        Ok(r.swapped())
    } else {
        Err(QueryError::NotStrictlyConvex)
    }
}

/// Every number of the motion is finite.
pub(crate) fn motion_is_finite(m: &NonlinearRigidMotion) -> bool {
    m.start.is_finite() && m.local_center.is_finite() && m.linvel.is_finite() && m.angvel.is_finite()
}

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
}

impl<'a, A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized> Tracker<'a, A, B> {
    fn new(
        obj1: &'a A,
        m1: &NonlinearRigidMotion,
        obj2: &'a B,
        m2: &NonlinearRigidMotion,
        t0: f64,
        t1: f64,
        opts: &ToiOptions,
    ) -> Result<Self, QueryError> {
        if !(motion_is_finite(m1) && motion_is_finite(m2) && t0.is_finite() && t1.is_finite()) {
            return Err(QueryError::NonFinite);
        }
        if !opts.is_valid() {
            // A target or tolerance that is NaN, infinite or negative.
            return Err(QueryError::NonFinite);
        }
        if t1 < t0 {
            return Err(QueryError::EmptyWindow);
        }
        // A disc centred at its origin and spinning about it (support_dd_bound() = 0: h'' ≡ 0,
        // so h is constant) looks the same at every angle: track it without its spin (one
        // sine and cosine less per frame) and turn its witnesses back at the end.
        let spin2 = if obj2.support_dd_bound() == 0.0 && m2.local_center == Vector::ZERO {
            m2.angvel
        } else {
            0.0
        };
        let rel = if spin2 != 0.0 {
            RelativeMotion::new(m1, &NonlinearRigidMotion { angvel: 0.0, ..*m2 })
        } else {
            RelativeMotion::new(m1, m2)
        };
        let size = obj1.bounding_radius().max(obj2.bounding_radius());
        let (c1, c2) = rel.centers();
        let reach = circles_reach(
            obj1.bounding_radius(),
            c1,
            obj2.bounding_radius(),
            c2,
            opts.target_distance,
        );
        if !(size.is_finite() && size > 0.0 && reach.is_finite()) {
            return Err(QueryError::Degenerate);
        }
        Ok(Self {
            obj1,
            obj2,
            rel,
            omega1: m1.angvel,
            t0,
            t1,
            opts: *opts,
            size,
            reach,
            tol_d: opts.distance_tolerance * size,
            side_tol: opts.side_tolerance * size,
            c2_len: c2.length(),
            c1_len: c1.length(),
            dv_len: rel.center_velocity().length(),
            obj1_convex: obj1.is_strictly_convex() && obj1.support_dd_bound().is_finite(),
            h1_global: obj1.support_dd_bound(),
            h2_global: obj2.support_dd_bound(),
            turns: 0.0,
            spin2,
            cost: ToiCost::default(),
            last_frame: rel.frame(t0),
        })
    }

    /// True when the bounding circles about the rotation centres stay apart on [t, t1].
    fn parted_for_rest(&self, t: f64) -> bool {
        circles_stay_apart(
            self.rel.center_offset(t),
            self.rel.center_velocity(),
            self.t1 - t,
            self.reach,
        )
    }

    /// The guard's bound on [t, t + h] (module docs): the axis turns at λ in the world, and
    /// M(λ) = λ²·max|ΔC| + 2|λ||ΔV| + (λ − ω₁)²H₁ + (λ − ω₂)²H₂ bounds |g''| of the gap along
    /// it. λ = ω₁ (the axis fixed in object1, H₁ not needed) unless object1 is strictly convex,
    /// in which case the λ minimising M is taken; when neither shape spins, the gap along the fixed
    /// axis (λ = 0) is affine in t and M = 0 exactly. Returns (M, λ).
    fn guard_bound(&self, t: f64, h: f64, local: Option<&PairJet>) -> (f64, f64) {
        let (w1, w2) = (self.omega1, self.rel.omega2());
        if w1 == 0.0 && w2 == 0.0 {
            // Neither turns: along the fixed axis λ = 0 the gap is affine in t, g'' = 0.
            return (0.0, 0.0);
        }
        let w = w1 - w2;
        let dc = self
            .rel
            .center_offset(t)
            .length_squared()
            .max(self.rel.center_offset(t + h).length_squared())
            .sqrt();
        let dv = self.dv_len;
        // The axis turns at λ − ωᵢ against shape i; the optimal λ lies between 0, ω₁ and ω₂,
        // so over [t, t + h] the directions stay within these angles of the current ones.
        let sweep2 = if self.obj1_convex {
            w2.abs().max(w.abs())
        } else {
            w.abs()
        } * h;
        let h2 = match local {
            Some(j) => self.obj2.support_dd_bound_near(-j.normal_in_2, sweep2),
            None => self.h2_global,
        } + self.c2_len;
        let m_body = w * w * h2 + 2.0 * w1.abs() * dv + w1 * w1 * dc;
        let mut best = (m_body, w1);
        if self.obj1_convex {
            let sweep1 = w1.abs().max(w.abs()) * h;
            let h1 = match local {
                Some(j) => self.obj1.support_dd_bound_near(j.curve1.normal, sweep1),
                None => self.h1_global,
            } + self.c1_len;
            let m_at = |l: f64| l * l * dc + 2.0 * l.abs() * dv + (l - w1) * (l - w1) * h1 + (l - w2) * (l - w2) * h2;
            let den = dc + h1 + h2;
            if den > 0.0 {
                // M is a convex quadratic on each side of λ = 0: its minimiser on each side.
                for sign in [1.0, -1.0] {
                    let l = (w1 * h1 + w2 * h2 - sign * dv) / den;
                    let l = if l * sign >= 0.0 { l } else { 0.0 };
                    let m = m_at(l);
                    if m < best.0 {
                        best = (m, l);
                    }
                }
            }
        }
        best
    }

    /// φ of an accepted point brought back into [−π, π) (the whole turns removed are counted
    /// for the trace, [`Tracker::unwrapped`]).
    ///
    /// Why the tracked φ must not grow with the turns of the pair: the corrector can place a root
    /// only to the spacing of doubles near φ (the bracketed solver stops at 4ε(1 + |φ|)), and an
    /// error δφ costs about (ρ₁ + ρ₂ + F)·(ω₁δφ)²/2 in F, with ω₁ = dθ/dφ the turn rate of
    /// object1's normal. Both factors can be huge: a thin `CapsuleEllipse` packs each arc's
    /// quarter turn of normals into about r1/r2 radians of φ (ω₁ ≈ 3e5 for r1 = 5e-6·r2), and
    /// the flat side of a 1:3e-5 ellipse has ρ₂ = 1.3e10 ≈ 3e4·s. After 976 relative turns
    /// (|φ| ≈ 6e3) the best root the corrector could reach was 2.4e-12 from the true one, F
    /// there was 3.1e-3 = 7e-9·s below the distance, the contact test saw that low value and a
    /// `Hit` was reported early (`thin_capsule_arc_against_thin_ellipse_hit_is_on_target` in
    /// `tests/adversarial.rs`). F is a lower bound on the distance at any φ, so the error is
    /// always on the early side, and only its size depends on |φ|.
    ///
    /// Kept in [−π, π) at every accepted point (a step moves φ by a few radians at most: the
    /// predictor's travel cap plus the corrector's move), φ has the resolution of the stationary
    /// distance, which starts from [`ConvexCurve::phi_range_of_normal`] in [−π, π) and is itself
    /// exact to its tolerances: δφ ≤ 4ε(1 + |φ|) ≈ 1e-14 whatever the number of turns, hundreds
    /// of times finer here, and the loss in F, quadratic in δφ, 1e5 times smaller or more. The
    /// contact test then reads the distance itself (here the exact distance at the reported time
    /// is 1.5e-10 = 3.5e-16·s), so the `Hit` meets δ − 1e-12·s ≤ D ≤ δ + tol for the same reason
    /// a query that starts near that time does. Rewrapping moves φ by the rounding of a multiple
    /// of 2π (an ulp of φ, which the next correction absorbs) and costs one comparison per
    /// accepted step.
    #[inline]
    fn rewrap(&mut self, phi: f64) -> f64 {
        let w = wrap_phi(phi);
        if w != phi {
            self.turns += ((phi - w) / TAU).round();
        }
        w
    }

    /// φ continued across the whole turns removed by [`Tracker::rewrap`] (for the trace).
    #[inline]
    fn unwrapped(&self, phi: f64) -> f64 {
        phi + self.turns * TAU
    }

    /// The frame at t (two sines and cosines; the last one is kept, as the start, a miss's
    /// polish and the stationary distance after a failed step ask again for a time just seen).
    #[inline]
    fn frame(&mut self, t: f64) -> PairFrame {
        if self.last_frame.time != t {
            self.last_frame = self.rel.frame(t);
        }
        self.last_frame
    }

    fn solver(&self, frame: PairFrame) -> Solver<'a, A, B> {
        Solver {
            obj1: self.obj1,
            obj2: self.obj2,
            frame,
            side_tol: self.side_tol,
            max_iter: self.opts.max_corrector_iterations,
            evaluations: 0,
            newton: 0,
        }
    }

    fn result(&self, status: ToiStatus, t: f64, j: &PairJet) -> TimeOfImpact {
        let (mut point2, mut normal2) = (j.support2.point, -j.normal_in_2);
        if self.spin2 != 0.0 {
            // Object2 turned by ω₂t about its origin since the frame `rel` tracks it in.
            let (s, c) = crate::math::sin_cos(-self.spin2 * t);
            let rot = |v: Vector| crate::math::rotate_cs(c, s, v);
            (point2, normal2) = (rot(point2), rot(normal2));
        }
        TimeOfImpact {
            status,
            time: t,
            distance: j.fwd.v,
            distance_rate: j.fwd.t,
            point1: j.curve1.point,
            point2,
            normal1: j.curve1.normal,
            normal2,
            cost: self.cost,
        }
    }

    /// The result for a point tracked with the loose tolerance: corrected to the side tolerance
    /// first, so that the reported distance and witnesses are exact.
    // Once per query or rarer: kept out of the step loop, whose code it would bloat (4 % fewer
    // instructions at the ellipse–disc medians).
    #[inline(never)]
    fn finish(&mut self, status: ToiStatus, t: f64, phi: f64, j: PairJet) -> TimeOfImpact {
        let tight = Tol::Fixed(self.side_tol);
        if self.accepts(tight, &j.point()) {
            return self.result(status, t, &j);
        }
        let frame = self.frame(t);
        let mut sv = self.solver(frame);
        let mut p = j.point();
        let r = self.solve_from(&mut sv, phi, &mut p, tight);
        self.cost.evaluations += sv.evaluations;
        self.cost.corrector_iterations += sv.evaluations;
        match r.and_then(|_| p.jet(&frame)) {
            Some(jt) if jt.fwd.v >= j.fwd.v => self.result(status, t, &jt),
            _ => self.result(status, t, &j),
        }
    }

    /// Global stationary distance at t starting from φ: (φ, full jet). The local solve comes
    /// first, as in [`stationary_in_frame`]: a root of S with F > 0 is the global maximum, and its
    /// jet is kept; otherwise the full search runs.
    // Cold, out of the step loop (as `finish`).
    #[inline(never)]
    fn global_at(&mut self, t: f64, phi: f64, tol: Tol) -> Result<(f64, PairJet), QueryError> {
        let frame = self.frame(t);
        let mut sv = Solver {
            side_tol: self.opts.distance.side_tolerance * self.size,
            max_iter: self.opts.distance.max_local_iterations,
            ..self.solver(frame)
        };
        let local = self.solve(&mut sv, phi, tol);
        self.cost.evaluations += sv.evaluations;
        self.cost.corrector_iterations += sv.evaluations.saturating_sub(1);
        if let Some((p, j)) = local.filter(|(_, j)| j.fwd > 0.0) {
            if let Some(j) = j.jet(&frame) {
                return Ok((p, j));
            }
        }
        let r = stationary_in_frame(self.obj1, self.obj2, frame, phi, &self.opts.distance)?;
        self.cost.evaluations += r.evaluations;
        self.cost.corrector_iterations += r.newton_iterations;
        self.cost.evaluations += 1;
        let j = eval_point(self.obj1, self.obj2, &frame, r.phi)
            .and_then(|p| p.jet(&frame))
            .ok_or(QueryError::Degenerate)?;
        Ok((r.phi, j))
    }

    /// Whether the point `j` is accepted as a root of S under `tol` ([`Tol`]).
    #[inline]
    fn accepts(&self, tol: Tol, j: &PairPoint) -> bool {
        let (s, s1) = (j.side.abs(), j.side_p);
        s1 > 0.0
            && match tol {
                Tol::Fixed(x) => s <= x,
                Tol::Loose => s <= self.loose_side(j) && s <= LOOSE_PHI * s1,
            }
    }

    /// The |S| handed to the bracketed solver under `tol`, judged at the point `j`.
    #[inline]
    fn bracket_tol(&self, tol: Tol, j: &PairPoint) -> f64 {
        match tol {
            Tol::Fixed(x) => x,
            Tol::Loose => {
                if j.side_p > 0.0 {
                    self.loose_side(j).min(LOOSE_PHI * j.side_p).max(self.side_tol)
                } else {
                    self.side_tol
                }
            }
        }
    }

    /// The |S| accepted away from contact at the point `j`, never below the side tolerance.
    ///
    /// F_φ = −ω₁S (ω₁ = N × N'), so about the root φ* (S ≈ S_φ·(φ − φ*)) an inexact root costs
    /// F(φ) ≈ D − ω₁S²/(2S_φ). Away from contact (gap F − δ above twice the distance tolerance)
    /// |S| is accepted while that deficit stays below `LOOSE_DEFICIT` of the gap; always, |S| up
    /// to `LOOSE_SIDE` of the gap (the deficit is then ≤ S²/(2·gap) ≤ 0.5 % of the gap, since
    /// S_φ/ω₁ ≈ ρ₁ + ρ₂ + F ≥ gap). Within twice the distance tolerance only the second holds, so
    /// it tightens by itself to the side tolerance as the contact nears and the contact decisions
    /// are taken on nearly exact roots. A lower F only shortens the next guard step a little; the
    /// guard itself does not depend on it: F(φ, t) at any φ is a lower bound on the distance.
    #[inline]
    fn loose_side(&self, j: &PairPoint) -> f64 {
        let gap = j.fwd - self.opts.target_distance;
        let by_gap = LOOSE_SIDE * gap;
        let w = j.curve1.normal_turn_rate();
        let by_deficit = if gap > 2.0 * self.tol_d && w > 0.0 && j.side_p > 0.0 {
            (2.0 * LOOSE_DEFICIT * gap * j.side_p / w).sqrt()
        } else {
            0.0
        };
        by_gap.max(by_deficit).max(self.side_tol)
    }

    /// Solves S(φ) = 0 at the solver's fixed time from `phi`: Halley iterations (cubic
    /// convergence: none or one after an order-2 prediction), falling back to the bracketed
    /// solver of the stationary distance when an iteration does not shrink |S| or would move φ
    /// by more than `HALLEY_MAX_STEP`. Returns the root (S_φ > 0) and its evaluation.
    fn solve(&self, sv: &mut Solver<A, B>, phi: f64, tol: Tol) -> Option<(f64, PairPoint)> {
        let mut j = sv.eval(phi)?;
        let x = self.solve_from(sv, phi, &mut j, tol)?;
        Some((x, j))
    }

    /// As [`Tracker::solve`] from an already evaluated point `j` at `phi`, in place: on success
    /// `j` holds the root's evaluation and the root is returned. (In place because the points
    /// are large: passing them by value cost a copy per call and per iteration.)
    #[inline(never)]
    fn solve_from(&self, sv: &mut Solver<A, B>, phi: f64, j: &mut PairPoint, tol: Tol) -> Option<f64> {
        let mut x = phi;
        for _ in 0..HALLEY_TRIES {
            if self.accepts(tol, j) {
                return Some(x);
            }
            let (s, s1, s2) = (j.side, j.side_p, j.side_pp);
            if !(s1 > 0.0) {
                break;
            }
            let denom = 2.0 * s1 * s1 - s * s2;
            let step = if denom > 0.0 { -2.0 * s * s1 / denom } else { -s / s1 };
            if !(step.abs() <= HALLEY_MAX_STEP) {
                break;
            }
            let Some(jn) = sv.eval(x + step) else { break };
            if !(jn.side.abs() < s.abs()) {
                // Not converging (a piece end, a far root): bracket between the two if S
                // changes sign, otherwise start the bracketed solver from the better point.
                if (jn.side > 0.0) != (s > 0.0) {
                    sv.side_tol = self.bracket_tol(tol, if jn.fwd < j.fwd { &jn } else { j });
                    let r = if step > 0.0 {
                        sv.bracketed_root(x, *j, x + step, jn)
                    } else {
                        sv.bracketed_root(x + step, jn, x, *j)
                    };
                    let (xr, jr) = r?;
                    *j = jr;
                    return Some(xr);
                }
                break;
            }
            x += step;
            *j = jn;
        }
        if self.accepts(tol, j) {
            return Some(x);
        }
        sv.side_tol = self.bracket_tol(tol, j);
        let (xr, jr) = sv.local_root(x, *j)?;
        *j = jr;
        Some(xr)
    }

    /// Corrects φ at fixed t ([`Tracker::solve`]); returns the root and its full jet.
    ///
    /// Always inlined: the library's own copy of the step loop otherwise calls it and moves
    /// its large answer through memory (through `SmoothDispatcher`, 2.5 % more time per
    /// ellipse–disc query; the direct generic call, compiled in the caller's crate, is about
    /// 1.5 % faster without it).
    #[inline(always)]
    fn correct<T: Tracer>(&mut self, t: f64, phi: f64, tol: Tol, trace: &mut T) -> Option<(f64, PairJet)> {
        let frame = self.frame(t);
        let mut sv = self.solver(frame);
        let mut p = sv.eval(phi);
        let root = p.as_mut().and_then(|p| self.solve_from(&mut sv, phi, p, tol));
        self.cost.evaluations += sv.evaluations;
        // The first evaluation is the prediction itself; the rest are Halley/bisection steps.
        self.cost.corrector_iterations += sv.evaluations.saturating_sub(1);
        let phi = root?;
        let j = p.as_ref()?.jet(&frame)?;
        trace.push(TraceEvent::Correct {
            phi: self.unwrapped(phi),
            t,
            side: j.side.v,
        });
        Some((phi, j))
    }

    fn run<T: Tracer>(mut self, trace: &mut T) -> Result<TimeOfImpact, QueryError> {
        let delta = self.opts.target_distance;
        let window = self.t1 - self.t0;
        let start_frame = self.frame(self.t0);
        // Start φ: object1's normal pointing at object2's rotation centre.
        let dir2 = start_frame.unrotate(-start_frame.q);
        let dir2 = if dir2.length() > 0.0 {
            dir2.normalize()
        } else {
            Vector::X
        };
        let phi_start = self.obj1.phi_range_of_normal(dir2).0;
        // Loose is enough at the start when tracking follows: it is tight within the tolerance
        // of the target, and a miss reported later is polished ([`Tracker::finish`]). When the
        // bounding circles never meet, the answer is this distance: tight at once.
        let parted = self.parted_for_rest(self.t0);
        let tol0 = if parted { Tol::Fixed(self.side_tol) } else { Tol::Loose };
        let (mut phi, mut j) = self.global_at(self.t0, phi_start, tol0)?;
        let mut t = self.t0;
        trace.push(TraceEvent::Start {
            phi,
            t,
            distance: j.fwd.v,
        });

        if j.fwd.v <= delta + self.tol_d {
            if self.opts.stop_at_penetration || j.fwd.t <= 0.0 {
                return Ok(self.result(ToiStatus::PenetratingAtStart, t, &j));
            }
            // Separating contact: move on until the distance is above the target.
            match self.leave_contact(t, phi, &j)? {
                Some((t2, phi2, j2)) => {
                    t = t2;
                    phi = self.rewrap(phi2);
                    j = j2;
                }
                None => return Ok(self.result(ToiStatus::NoHit, self.t1, &j)),
            }
            if j.fwd.v <= delta + self.tol_d {
                // Still in contact and approaching again.
                return Ok(self.result(ToiStatus::Hit, t, &j));
            }
        }
        if parted || self.parted_for_rest(t) {
            return Ok(self.finish(ToiStatus::NoHit, t, phi, j));
        }

        let mut h_acc = window.max(f64::MIN_POSITIVE);
        // How far below the target a reported contact may be (`ToiStatus::Hit`).
        let floor = -CONTACT_FLOOR * self.size;
        // After a failed two-sided step, the next try is the plain guard step.
        let mut retry_plain = false;
        // The accepted point before t: no contact lies before it.
        let mut t_prev = t;
        loop {
            let gap = j.fwd.v - delta;
            if gap <= self.tol_d {
                let r = self.refine_hit(t_prev, t, phi, j, trace);
                return Ok(r);
            }
            if self.cost.predictor_steps >= self.opts.max_steps || self.cost.evaluations >= self.opts.max_evaluations {
                return Ok(self.finish(ToiStatus::OutOfIterations, t, phi, j));
            }
            let h_max = self.t1 - t;
            if h_max <= 0.0 {
                return Ok(self.finish(ToiStatus::NoHit, self.t1, phi, j));
            }
            // Taylor data of the curve S = 0 at (φ, t).
            let (resid, dphi, ddphi) = curve_taylor(&j);
            let mut h = h_acc.min(h_max);
            // Limit the φ-travel of one step (the curve's bending, eq. 8): the largest h with
            // |φ'|h + |φ''|h²/2 ≤ max_dphi.
            let travel = dphi.abs() * h + 0.5 * ddphi.abs() * h * h;
            if travel > MAX_TRAVEL {
                h = 2.0 * MAX_TRAVEL / (dphi.abs() + (dphi * dphi + 2.0 * ddphi.abs() * MAX_TRAVEL).sqrt());
            }
            // The guard (module docs): along an axis turning at λ, g(t_k) = F and
            // g'(t_k) = F_t − (λ − ω₁)·S.
            // M holds on [t, t + span]; the curvature bounds are local to the directions the
            // span sweeps, so a shorter span (with room for the two-sided extension) may allow
            // a longer guard step.
            let mut span = h;
            let (mut m, mut lam) = self.guard_bound(t, span, None);
            let slope_at = |lam: f64| j.fwd.t - (lam - self.omega1) * j.side.v;
            let mut h_guard = guard_step(gap, slope_at(lam), m);
            // The Taylor model of D along the curve: D'' and where it reaches the target (NaN or
            // infinite if it does not). A loosely accepted point lies `resid` off the root: D
            // and D' there are F and F_t carried to the root along φ (F_φ = −ω₁S ≠ 0 off it),
            // which keeps the aim as accurate as from an exact root.
            let d2 = j.fwd.tt + j.fwd.pt * dphi;
            let gap_m = gap + resid * (j.fwd.p + 0.5 * j.fwd.pp * resid);
            let d1_m = j.fwd.t + j.fwd.pt * resid;
            // (Only needed when the guard limits the step: the aim below is taken only then.)
            let h_model = if h_guard < h {
                guard_step(gap_m, d1_m, -d2)
            } else {
                f64::NAN
            };
            // Near the contact the global bound already certifies an aim at the model's contact
            // with room to spare (s_A + s_B/2 ≥ h_m, s_B ≈ 2|D'|/M from the target level): the
            // local bounds could not change the step, skip them. (They could only make its
            // certification, with a smaller M, pass where the global one fails: the step is
            // then retried as a plain guard step, which computes them.)
            // A step aims at the model's contact when it lies beyond the guard step s_A but within
            // the two-sided extension (2·s_A, and the span its bound holds on).
            let aims = |s_a: f64, span: f64| h_model > s_a && h_model < (2.0 * s_a).min(span);
            let aim_sure = !retry_plain && aims(h_guard, span) && (h_model - h_guard) * m <= -(d1_m + d2 * h_model);
            if h_guard < h && !aim_sure {
                // Limited with the global curvature bounds: try the local ones.
                let span2 = (2.5 * h_guard).min(span);
                let (m2, lam2) = self.guard_bound(t, span2, Some(&j));
                let hg2 = guard_step(gap, slope_at(lam2), m2).min(span2);
                if hg2 > h_guard {
                    (m, lam, h_guard, span) = (m2, lam2, hg2, span2);
                }
            }
            let guard_limited = h_guard.is_finite() && h_guard < h;
            // Two-sided guard: a step longer than h_guard is safe when the bound taken backwards
            // from its end covers the rest, s_A + s_B ≥ h (checked after the correction). The
            // length is chosen from the Taylor model of D along the curve.
            let mut extended = None;
            let mut aim = false;
            if guard_limited && !retry_plain {
                let mut he = (2.0 * h_guard).min(span);
                if aims(h_guard, span) {
                    // Approaching: aim at the model's contact itself.
                    he = h_model;
                    aim = true;
                } else {
                    for _ in 0..3 {
                        let g_end = gap + he * (j.fwd.t + 0.5 * d2 * he);
                        if !(g_end > 0.0) {
                            he = h_guard;
                            break;
                        }
                        let s_b = guard_step(g_end, -(j.fwd.t + d2 * he), m);
                        he = ((h_guard + s_b) / 1.1).min(span);
                    }
                }
                if aim || he > 1.05 * h_guard {
                    extended = Some(h_guard);
                    h = he;
                }
            }
            if guard_limited && extended.is_none() {
                h = h_guard;
            }
            retry_plain = false;
            if h.is_nan() || h <= 0.0 || t + h <= t {
                // No representable progress: the guard pins us at t.
                return Ok(self.finish(ToiStatus::OutOfIterations, t, phi, j));
            }
            let mut t_new = if h >= h_max { self.t1 } else { t + h };
            // The accepted point may leave a residual S (loose tolerance away from contact):
            // its Newton correction joins the Taylor step.
            let phi_pred = phi + resid + h * (dphi + 0.5 * ddphi * h);
            trace.push(TraceEvent::Predict {
                phi: self.unwrapped(phi_pred),
                t: t_new,
            });
            let mut corrected = self.correct(t_new, phi_pred, Tol::Loose, trace);
            if aim {
                // An aimed step that landed beyond the contact: back up to the model's contact
                // from the far side, and certify that point instead.
                if let Some((phi_c, jc)) = corrected.filter(|(_, jc)| jc.fwd.v - delta < floor) {
                    corrected = self.back_to_contact(t, t_new, phi_c, &jc, trace).map(|(tb, pb, jb)| {
                        t_new = tb;
                        h = tb - t;
                        (pb, jb)
                    });
                }
            }
            let accept = match corrected {
                Some((phi_c, jc)) => {
                    // Reject when the corrector had to move far from the prediction, or landed on
                    // a root that is not a maximum of F.
                    // How far the prediction was from the curve: the corrector's move plus the
                    // Newton estimate of what is left.
                    let moved = (phi_c - phi_pred).abs()
                        + if jc.side.p > 0.0 {
                            (jc.side.v / jc.side.p).abs()
                        } else {
                            0.0
                        };
                    // Far moves are harmless away from contact (a root of S with S_φ > 0 and
                    // F > 0 is the global maximum wherever it is), but a contact claimed after
                    // one is not trusted: it could be a local maximum of F ≤ 0 of another branch.
                    let gap_c = jc.fwd.v - delta;
                    let mut ok = jc.side.p > 0.0 && gap_c > -self.tol_d && (moved <= 0.25 || gap_c > self.tol_d);
                    if aim && !(gap_c >= floor) {
                        ok = false;
                    }
                    if let Some(s_a) = extended.filter(|_| ok) {
                        // Backward bound from the new point: g(t_new − s) ≥ gap_B − g'·s − M s²/2
                        // (an aimed step may end a hair below the target: its bound is taken
                        // from the floor the contact allows).
                        let gap_b = jc.fwd.v - delta - if aim { floor } else { 0.0 };
                        let slope_b = jc.fwd.t - (lam - self.omega1) * jc.side.v;
                        let s_b = if gap_b > 0.0 {
                            guard_step(gap_b, -slope_b, m)
                        } else {
                            0.0
                        };
                        if !(s_a + s_b >= h) {
                            ok = false;
                        }
                    }
                    if ok {
                        Some((phi_c, jc, moved))
                    } else {
                        None
                    }
                }
                None => None,
            };
            match accept {
                Some((phi_c, jc, moved)) => {
                    self.cost.predictor_steps += 1;
                    if guard_limited {
                        self.cost.guard_limited_steps += 1;
                    }
                    // The corrector's root is a local maximum of F; with F > 0 it is the global
                    // one. With F ≤ 0 we are at contact anyway. Its jet is already full.
                    t_prev = t;
                    t = t_new;
                    phi = self.rewrap(phi_c);
                    j = jc;
                    trace.push(TraceEvent::Accept {
                        phi: self.unwrapped(phi),
                        t,
                        distance: j.fwd.v,
                    });
                    if !guard_limited || h >= h_acc * 0.99 {
                        // Adapt the accuracy step to how far the prediction was off.
                        if moved < 1e-2 {
                            h_acc *= 2.0;
                        } else if moved > 0.3 {
                            h_acc *= 0.5;
                        }
                    }
                    h_acc = h_acc.min(window).max(window * 1e-12);
                    if j.fwd.v > delta + self.tol_d && self.parted_for_rest(t) {
                        return Ok(self.finish(ToiStatus::NoHit, t, phi, j));
                    }
                    if t >= self.t1 && j.fwd.v > delta + self.tol_d {
                        return Ok(self.finish(ToiStatus::NoHit, self.t1, phi, j));
                    }
                }
                None => {
                    self.cost.backtracks += 1;
                    trace.push(TraceEvent::Backtrack {
                        phi: self.unwrapped(phi_pred),
                        t: t_new,
                    });
                    if extended.is_some() {
                        // A two-sided step that failed (or whose correction failed): retry with the
                        // plain guard step, which is safe by itself.
                        retry_plain = true;
                        continue;
                    }
                    h_acc = h.min(h_acc) * 0.5;
                    if h_acc <= window * 1e-13 {
                        // Cannot make progress by tracking: recover with the global distance.
                        let t_try = t + h;
                        let (p2, j2) = self.global_at(t_try, phi_pred, Tol::Fixed(self.side_tol))?;
                        self.cost.predictor_steps += 1;
                        t_prev = t;
                        t = t_try;
                        phi = self.rewrap(p2);
                        j = j2;
                        h_acc = window * 1e-6;
                    }
                }
            }
        }
    }

    /// From a point (t_b, φ_b) of an aimed step that landed beyond the contact (D < δ), back to
    /// where the order-2 Taylor model of D about it reaches the target (Newton when the model has
    /// no root there), corrected to the side tolerance: (t, φ, jet). None when the distance is
    /// not decreasing there or the point would not lie in (t, t_b).
    // Cold, out of the step loop (as `finish`).
    #[inline(never)]
    fn back_to_contact<T: Tracer>(
        &mut self,
        t: f64,
        t_b: f64,
        phi_b: f64,
        jb: &PairJet,
        trace: &mut T,
    ) -> Option<(f64, f64, PairJet)> {
        let over = self.opts.target_distance - jb.fwd.v;
        let d1 = jb.fwd.t;
        if !(over > 0.0 && d1 < 0.0) {
            return None;
        }
        let (_, dphi, _) = curve_taylor(jb);
        let d2 = jb.fwd.tt + jb.fwd.pt * dphi;
        // gap + D'u + D''u²/2 = 0 for the u < 0 nearest 0; with v = −u:
        // (D''/2)v² − D'v − over = 0, v = 2·over/(−D' + √(D'² + 2D''·over)).
        let disc = d1 * d1 + 2.0 * d2 * over;
        let v = if disc >= 0.0 {
            2.0 * over / (-d1 + disc.sqrt())
        } else {
            over / -d1
        };
        let tc = t_b - v;
        if !(tc > t && tc < t_b) {
            return None;
        }
        let (p, j) = self.correct(tc, predict_phi(phi_b, jb, -v), Tol::Fixed(self.side_tol), trace)?;
        Some((tc, p, j))
    }

    /// The point at time `t_n` corrected to the side tolerance, predicted from the corrected
    /// point (t, φ, jet) ([`predict_phi`]); untraced (the refinement of a contact).
    fn correct_tight_from(&mut self, t: f64, phi: f64, j: &PairJet, t_n: f64) -> Option<(f64, PairJet)> {
        self.correct(
            t_n,
            predict_phi(phi, j, t_n - t),
            Tol::Fixed(self.side_tol),
            &mut NoTrace,
        )
    }

    /// At a point within tolerance of the target, sharpens the contact time: Newton steps on D
    /// from the safe side (a few, while they stay above the target), then, if one lands beyond
    /// the target, Illinois regula falsi on D(t) − δ between the last safe point and that point.
    /// A start a hair below the target (an aimed step, D ≥ δ − 1e-12·s) first takes Newton steps
    /// backwards, never before `t_lo` (the previous accepted point), until one is above it. The
    /// answer is the sample closest to the target among those with D ≥ δ − 1e-12·s (the start
    /// itself when nothing better is found). The bracket is ~gap/|D'| wide, far inside what the
    /// guard would step over, so the root found is the first.
    // Cold, out of the step loop (as `finish`).
    #[inline(never)]
    fn refine_hit<T: Tracer>(&mut self, t_lo: f64, t: f64, phi: f64, j: PairJet, trace: &mut T) -> TimeOfImpact {
        let delta = self.opts.target_distance;
        let floor = -CONTACT_FLOOR * self.size;
        let fine = 1e-15 * self.size;
        let mut best = (t, phi, j);
        let better = |best: &(f64, f64, PairJet), jj: &PairJet| {
            let g = jj.fwd.v - delta;
            g >= floor && g.abs() < (best.2.fwd.v - delta).abs() && jj.side.p > 0.0
        };
        let (mut ts, mut ps, mut js) = (t, phi, j);
        let mut beyond: Option<(f64, f64, f64, PairJet)> = None;
        if j.fwd.v - delta < -fine {
            // An aimed step accepted a hair beyond the target: Newton on D backwards (not before
            // the previous accepted point) until a point above the target brackets the contact.
            let mut safe = None;
            beyond = Some((t, phi, j.fwd.v - delta, j));
            for _ in 0..4 {
                let (g, d1) = (js.fwd.v - delta, js.fwd.t);
                let t_n = (ts - g / d1).max(t_lo);
                if !(d1 < 0.0 && t_n < ts) {
                    break;
                }
                let Some((phi_n, jn)) = self.correct_tight_from(ts, ps, &js, t_n) else {
                    break;
                };
                if better(&best, &jn) {
                    best = (t_n, phi_n, jn);
                }
                let gn = jn.fwd.v - delta;
                if gn >= -fine {
                    if gn > fine {
                        safe = Some((t_n, phi_n, jn));
                    } else {
                        beyond = None;
                    }
                    break;
                }
                beyond = Some((t_n, phi_n, gn, jn));
                (ts, ps, js) = (t_n, phi_n, jn);
            }
            match safe {
                Some(sp) => (ts, ps, js) = sp,
                None => beyond = None,
            }
        }
        // Newton from the safe side, while its step is above the time resolution.
        let t_fine = REFINE_TIME * (self.t1 - self.t0);
        for _ in 0..if beyond.is_some() { 0 } else { 8 } {
            let gap = js.fwd.v - delta;
            let d1 = js.fwd.t;
            if gap <= fine || d1 >= 0.0 || gap <= t_fine * -d1 {
                break;
            }
            let t_n = (ts - gap / d1).min(self.t1);
            if t_n <= ts {
                break;
            }
            let Some((phi_n, jn)) = self.correct_tight_from(ts, ps, &js, t_n) else {
                break;
            };
            if better(&best, &jn) {
                best = (t_n, phi_n, jn);
            }
            let gn = jn.fwd.v - delta;
            if gn < 0.0 {
                beyond = Some((t_n, phi_n, gn, jn));
                break;
            }
            (ts, ps, js) = (t_n, phi_n, jn);
        }
        if let Some((tb0, pb, gb0, jb)) = beyond.filter(|b| b.2 < -fine) {
            // Illinois regula falsi between (ts, gap > 0) and (tb, gb < 0).
            let (mut ta, mut ga, mut tb, mut gb) = (ts, js.fwd.v - delta, tb0, gb0);
            let mut side = 0i8;
            // The last corrected point, to predict φ at the next sample.
            let mut last = (tb0, pb, jb);
            for _ in 0..40 {
                let tm = (ta * gb - tb * ga) / (gb - ga);
                if !(tm > ta && tm < tb) {
                    break;
                }
                let Some((pm, jm)) = self.correct_tight_from(last.0, last.1, &last.2, tm) else {
                    break;
                };
                last = (tm, pm, jm);
                if better(&best, &jm) {
                    best = (tm, pm, jm);
                }
                let gm = jm.fwd.v - delta;
                if gm.abs() <= fine {
                    break;
                }
                if gm > 0.0 {
                    (ta, ga) = (tm, gm);
                    if side == 1 {
                        gb *= 0.5;
                    }
                    side = 1;
                } else {
                    (tb, gb) = (tm, gm);
                    if side == -1 {
                        ga *= 0.5;
                    }
                    side = -1;
                }
            }
        }
        trace.push(TraceEvent::Impact {
            phi: self.unwrapped(best.1),
            t: best.0,
        });
        self.result(ToiStatus::Hit, best.0, &best.2)
    }

    /// From a separating contact at t, steps forward until the distance exceeds the target
    /// (returns that point), the shapes start approaching again while still in contact (returns
    /// that point, distance ≤ target), or the window ends (None).
    // Cold, out of the step loop (as `finish`).
    #[inline(never)]
    fn leave_contact(
        &mut self,
        mut t: f64,
        mut phi: f64,
        j0: &PairJet,
    ) -> Result<Option<(f64, f64, PairJet)>, QueryError> {
        let delta = self.opts.target_distance;
        let window = self.t1 - self.t0;
        let mut j = *j0;
        let mut h = window / 64.0;
        // A first step that roughly clears the target by the tolerance.
        if j.fwd.t > 0.0 {
            h = h.min(((delta + 2.0 * self.tol_d - j.fwd.v) / j.fwd.t).max(window * 1e-9));
        }
        for _ in 0..self.opts.max_steps {
            if t >= self.t1 {
                return Ok(None);
            }
            let t_new = (t + h).min(self.t1);
            if !(t_new > t) {
                // A window below the resolution of time (h = 0): as an empty window, no hit.
                return Ok(None);
            }
            let (p2, j2) = self.global_at(t_new, phi, Tol::Fixed(self.side_tol))?;
            self.cost.predictor_steps += 1;
            t = t_new;
            phi = self.rewrap(p2);
            j = j2;
            if j.fwd.v > delta + self.tol_d {
                return Ok(Some((t, phi, j)));
            }
            if j.fwd.t <= 0.0 {
                return Ok(Some((t, phi, j)));
            }
            h *= 2.0;
        }
        Ok(Some((t, phi, j)))
    }
}

/// The distance below which the bounding circles about the rotation centres `c1`, `c2` (each
/// in its shape's local frame) come within `target` of each other: the two radii (bounding radius
/// plus the centre's offset from the local origin) plus the target.
#[inline]
fn circles_reach(radius1: f64, c1: Vector, radius2: f64, c2: Vector, target: f64) -> f64 {
    radius1 + c1.length() + radius2 + c2.length() + target
}

/// Whether two circles whose centres are `offset` apart and move apart at the relative velocity
/// `velocity` stay farther apart than `reach` (the sum of their radii plus the target distance)
/// for a time `span`: min over s ∈ [0, span] of |offset + velocity·s| > reach (with a relative
/// margin of 1e-12 against rounding). False for NaN input.
#[inline]
fn circles_stay_apart(offset: Vector, velocity: Vector, span: f64, reach: f64) -> bool {
    let vv = velocity.length_squared();
    let s = if vv > 0.0 {
        (-offset.dot(velocity) / vv).clamp(0.0, span.max(0.0))
    } else {
        0.0
    };
    (offset + velocity * s).length() > reach * (1.0 + 1e-12)
}

/// The specification's inexpensive test ("Algorithm usage"): true when the bounding circles of
/// the two shapes — each about its rotation centre (`local_center`), with radius the shape's
/// bounding radius plus the centre's distance from the local origin — stay farther apart than
/// `target_distance` throughout `[start_time, end_time]`. No impact is then possible, and
/// [`time_of_impact`] would answer [`ToiStatus::NoHit`]; callers that need no witnesses for a
/// miss (parry's casts report none) can skip the query. The circles move with the rotation
/// centres, whose relative motion is linear, so the test is the closest approach of two points.
///
/// False whenever anything is non-finite or the window is reversed: the query itself then
/// reports the error.
pub fn bounding_circles_part(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    target_distance: f64,
) -> bool {
    if !(motion_is_finite(motion1) && motion_is_finite(motion2) && start_time <= end_time) {
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

/// The largest h with gap + slope·h − M h²/2 ≥ 0 (the guard; infinite when M = 0 ≤ slope).
#[inline]
fn guard_step(gap: f64, slope: f64, m: f64) -> f64 {
    2.0 * gap / (-slope + (slope * slope + 2.0 * m * gap).sqrt())
}

/// Taylor data of the curve S = 0 through a corrected point (eqs. 7–8): the Newton correction
/// −S/S_φ of a residual S, the slope φ' = −S_t/S_φ and the bending
/// φ'' = −(S_tt + 2S_φt φ' + S_φφ φ'²)/S_φ (all zero when S_φ ≤ 0).
#[inline]
fn curve_taylor(j: &PairJet) -> (f64, f64, f64) {
    let s = j.side;
    if s.p > 0.0 {
        let d1 = -s.t / s.p;
        let d2 = -(s.tt + 2.0 * s.pt * d1 + s.pp * d1 * d1) / s.p;
        (-s.v / s.p, d1, d2)
    } else {
        (0.0, 0.0, 0.0)
    }
}

/// φ on the curve S = 0 at time offset h from the corrected point (φ, j) (order-2 Taylor).
#[inline]
fn predict_phi(phi: f64, j: &PairJet, h: f64) -> f64 {
    let (resid, d1, d2) = curve_taylor(j);
    phi + resid + d1 * h + 0.5 * d2 * h * h
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distances::eval_pair;
    use crate::math::Pose;
    use crate::{BallCurve, Ellipse, RoundedPolygon};

    /// A small deterministic generator for the randomised checks below.
    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.next()
        }
    }

    /// A random motion: start within `reach` of the origin at any angle, rotation centre within
    /// 0.2 of the local origin, speed up to 4·√2, spin up to `spin` rad/s.
    fn random_motion(rng: &mut Lcg, reach: f64, spin: f64) -> NonlinearRigidMotion {
        NonlinearRigidMotion::new(
            Pose::new(
                Vector::new(rng.range(-reach, reach), rng.range(-reach, reach)),
                rng.range(-3.0, 3.0),
            ),
            Vector::new(rng.range(-0.2, 0.2), rng.range(-0.2, 0.2)),
            Vector::new(rng.range(-4.0, 4.0), rng.range(-4.0, 4.0)),
            rng.range(-spin, spin),
        )
    }

    /// World support value max over shape of x·u at pose.
    fn world_support(c: &dyn ConvexCurve, pose: &Pose, u: Vector) -> f64 {
        let local = pose.rotation.inverse_transform_vector(u);
        (*pose * c.support_point(local)).dot(u)
    }

    #[test]
    fn guard_parabola_bounds_the_gap_along_the_turning_axis() {
        // For random pairs, motions, points φ (roots or not) and steps: along the axis that
        // starts at object1's normal N(φ) and turns at the guard's λ, the gap G(t) stays above
        // F + g'·s − M s²/2 with g' = F_t − (λ − ω₁)S, M from `guard_bound` (global and local
        // curvature bounds) — the inequality the guard and its two-sided check rest on.
        let shapes: Vec<Box<dyn ConvexCurve>> = vec![
            Box::new(Ellipse::new(1.0, 0.05)),
            Box::new(Ellipse::new(0.3, 0.7)),
            Box::new(BallCurve { radius: 0.4 }),
            Box::new(RoundedPolygon::regular(5, 0.8, 0.1)),
            Box::new(RoundedPolygon::regular(3, 0.6, 0.0)),
        ];
        let mut rng = Lcg(7);
        let (mut checked, mut spin_free, mut spun_disc) = (0, 0, 0);
        for case in 0..400 {
            let o1 = &*shapes[case % shapes.len()];
            let o2 = &*shapes[(case / shapes.len()) % 3];
            let (mut m1, mut m2) = (random_motion(&mut rng, 3.0, 40.0), random_motion(&mut rng, 3.0, 40.0));
            if case % 4 == 3 {
                // Neither spins as tracked: `guard_bound` answers M = 0 along the fixed axis at
                // once. A disc turning about its centre keeps its spin (it is tracked without it).
                m1.angvel = 0.0;
                if o2.support_dd_bound() == 0.0 {
                    m2.local_center = Vector::ZERO;
                } else {
                    m2.angvel = 0.0;
                }
            } else if case % 4 == 2 {
                // Only object2 turns: a bound is needed (M = 0 here would be wrong).
                m1.angvel = 0.0;
            }
            let tr = Tracker::new(o1, &m1, o2, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
            spin_free += usize::from(tr.omega1 == 0.0 && tr.rel.omega2() == 0.0);
            spun_disc += usize::from(tr.spin2 != 0.0);
            let t = rng.range(0.0, 0.5);
            let phi = rng.range(-3.1, 3.1);
            let Some(j) = eval_pair(o1, o2, &tr.rel.frame(t), phi) else {
                continue;
            };
            let h = rng.range(1e-3, 0.3);
            for local in [None, Some(&j)] {
                let (m, lam) = tr.guard_bound(t, h, local);
                let slope = j.fwd.t - (lam - m1.angvel) * j.side.v;
                let n0 = m1.position_at_time(t).rotation * j.curve1.normal;
                for k in 1..=20 {
                    let s = h * k as f64 / 20.0;
                    let (p1, p2) = (m1.position_at_time(t + s), m2.position_at_time(t + s));
                    let n = crate::math::rotate_cs((lam * s).cos(), (lam * s).sin(), n0);
                    let gap = -world_support(o1, &p1, n) - world_support(o2, &p2, -n);
                    let bound = j.fwd.v + slope * s - 0.5 * m * s * s;
                    assert!(
                        gap >= bound - 1e-9 * (1.0 + bound.abs()),
                        "case {case}: gap {gap} below the bound {bound} at s = {s} (h = {h}, λ = {lam}, local {})",
                        local.is_some()
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 10_000);
        assert!(
            spin_free >= 100 && spun_disc >= 20,
            "{spin_free} spin-free pairs, {spun_disc} spun discs"
        );
    }

    #[test]
    fn local_curvature_bound_of_the_ellipse_covers_its_arc() {
        let mut rng = Lcg(11);
        for _ in 0..300 {
            let e = Ellipse::new(rng.range(0.01, 2.0), rng.range(0.01, 2.0));
            let psi0 = rng.range(-4.0, 4.0);
            let w = rng.range(0.0, 1.2) * rng.next();
            let bound = e.support_dd_bound_near(crate::math::unit(psi0), w);
            assert!(bound <= e.support_dd_bound() * (1.0 + 1e-12));
            for k in 0..=200 {
                let psi = psi0 - w + 2.0 * w * k as f64 / 200.0;
                let u = crate::math::unit(psi);
                let sj = e.support_jet(u).unwrap();
                let hdd = sj.radius_of_curvature - sj.point.dot(u);
                assert!(
                    hdd.abs() <= bound * (1.0 + 1e-9),
                    "{hdd} > {bound} at ψ = {psi}, arc {psi0} ± {w}"
                );
            }
        }
    }

    fn still(x: f64, y: f64, a: f64) -> NonlinearRigidMotion {
        NonlinearRigidMotion::constant_position(Pose::new(Vector::new(x, y), a))
    }

    #[test]
    fn head_on_discs_hit_at_the_closed_form_time() {
        let (a, b) = (BallCurve { radius: 0.5 }, BallCurve { radius: 0.25 });
        let m1 = NonlinearRigidMotion::new(
            Pose::new(Vector::new(-2.0, 0.0), 0.0),
            Vector::ZERO,
            Vector::new(1.5, 0.0),
            3.0,
        );
        let m2 = still(1.0, 0.0, 0.0);
        let r = time_of_impact(&a, &m1, &b, &m2, 0.0, 4.0, &ToiOptions::default()).unwrap();
        assert_eq!(r.status, ToiStatus::Hit);
        let exact = (3.0 - 0.75) / 1.5;
        assert!((r.time - exact).abs() < 1e-9 * 4.0, "{} vs {exact}", r.time);
        assert!(r.distance >= -1e-12 && r.distance <= 1e-10);
    }

    /// Distance from the disc (centre (0, 0.8), radius 0.1) to the ellipse a=1, b=0.2 turned by
    /// θ, by dense sampling of the ellipse (error ~1e-12).
    fn disc_gap(theta: f64) -> f64 {
        let c = Vector::new(0.0, 0.8);
        let mut best = f64::INFINITY;
        let n = 400_000;
        for k in 0..n {
            let e = 2.0 * core::f64::consts::PI * k as f64 / n as f64;
            let p = crate::math::rotate_cs(theta.cos(), theta.sin(), Vector::new(e.cos(), 0.2 * e.sin()));
            best = best.min((p - c).length());
        }
        best - 0.1
    }

    #[test]
    fn spinning_ellipse_reaches_a_disc_when_dense_sampling_says_so() {
        let (e, d) = (Ellipse::new(1.0, 0.2), BallCurve { radius: 0.1 });
        let w = 5.0;
        let m1 = NonlinearRigidMotion::new(Pose::new(Vector::ZERO, 0.0), Vector::ZERO, Vector::ZERO, w);
        let m2 = still(0.0, 0.8, 0.0);
        let r = time_of_impact(&e, &m1, &d, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
        assert_eq!(r.status, ToiStatus::Hit);
        assert!(disc_gap(w * r.time).abs() < 1e-8, "gap {}", disc_gap(w * r.time));
        for k in 0..20 {
            let t = r.time * k as f64 / 20.0;
            assert!(disc_gap(w * t) > 0.0);
        }
        // 1e-6 earlier the gap is still positive: the hit is not late.
        assert!(disc_gap(w * (r.time - 1e-6)) > 0.0);
    }

    #[test]
    fn passing_shapes_report_no_hit() {
        let (a, b) = (Ellipse::new(0.5, 0.2), Ellipse::new(0.3, 0.6));
        let m1 = NonlinearRigidMotion::new(
            Pose::new(Vector::new(-3.0, 2.0), 0.0),
            Vector::ZERO,
            Vector::new(6.0, 0.0),
            10.0,
        );
        let m2 = still(0.0, 0.0, 0.3);
        let r = time_of_impact(&a, &m1, &b, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
        assert_eq!(r.status, ToiStatus::NoHit);
    }

    #[test]
    fn bounding_circles_part_only_when_no_impact_is_possible() {
        // Closed form: unit discs 10 apart closing at speed 1 come within 2 (touch) at t = 8.
        let disc = BallCurve { radius: 1.0 };
        let at = |x: f64, v: f64| {
            NonlinearRigidMotion::new(
                Pose::new(Vector::new(x, 0.0), 0.0),
                Vector::ZERO,
                Vector::new(v, 0.0),
                0.0,
            )
        };
        let (m1, m2) = (at(0.0, 0.0), at(10.0, -1.0));
        assert!(bounding_circles_part(&disc, &m1, &disc, &m2, 0.0, 7.9, 0.0));
        assert!(!bounding_circles_part(&disc, &m1, &disc, &m2, 0.0, 8.1, 0.0));
        assert!(
            !bounding_circles_part(&disc, &m1, &disc, &m2, 0.0, 7.9, 0.2),
            "target counts"
        );
        assert!(
            !bounding_circles_part(&disc, &m1, &disc, &m2, 1.0, 0.0, 0.0),
            "reversed window"
        );
        assert!(
            !bounding_circles_part(&disc, &m1, &disc, &m2, 0.0, f64::NAN, 0.0),
            "NaN window"
        );
        // Random pairs: whenever the circles part, the full query finds no impact either.
        let shapes: Vec<Box<dyn ConvexCurve>> = vec![
            Box::new(Ellipse::new(1.0, 0.05)),
            Box::new(Ellipse::new(0.3, 0.7)),
            Box::new(BallCurve { radius: 0.4 }),
            Box::new(RoundedPolygon::regular(5, 0.8, 0.1)),
        ];
        let mut rng = Lcg(11);
        let (mut parted, mut cases) = (0, 0);
        for case in 0..2000 {
            let o1 = &*shapes[case % shapes.len()];
            let o2 = &*shapes[(case / shapes.len()) % 3];
            let (m1, m2) = (random_motion(&mut rng, 4.0, 20.0), random_motion(&mut rng, 4.0, 20.0));
            let target = rng.range(0.0, 0.1);
            let o = ToiOptions {
                target_distance: target,
                ..ToiOptions::default()
            };
            let Ok(r) = time_of_impact(o1, &m1, o2, &m2, 0.0, 1.0, &o) else {
                continue;
            };
            cases += 1;
            if bounding_circles_part(o1, &m1, o2, &m2, 0.0, 1.0, target) {
                parted += 1;
                assert_eq!(r.status, ToiStatus::NoHit, "case {case}");
                assert!(r.distance > target);
            }
        }
        assert!(parted > 200 && parted < cases - 200, "{parted} of {cases} parted");
    }

    #[test]
    fn appendix_d_heptagon_hits_the_ellipse_after_about_half_a_turn() {
        let hept = RoundedPolygon::regular(7, 1.0, 0.15);
        let ell = Ellipse::new(0.5, 1.5);
        let m1 = NonlinearRigidMotion::new(
            Pose::new(Vector::new(-1.85, 0.0), 0.0),
            Vector::ZERO,
            Vector::new(2.0, 0.0),
            30.0,
        );
        let m2 = still(0.0, 0.0, 0.0);
        let r = time_of_impact(&hept, &m1, &ell, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
        assert_eq!(r.status, ToiStatus::Hit);
        let turns = 30.0 * r.time / (2.0 * core::f64::consts::PI);
        assert!(turns > 0.2 && turns < 1.0, "time {} turns {turns}", r.time);
    }
}
