//! Time of impact between two moving convex objects by tracking the zero level of
//! distanceSide(φ, t) ("Distance Between Two Moving Objects", "One step of the algorithm",
//! "Backtracking" and "Correction φ to let it zero" of the specification).
//!
//! ## The algorithm
//!
//! 1. At t₀ the stationary distance gives φ₀ and D₀ = F(φ₀, t₀) ([`crate::stationary`]).
//! 2. Each step, at an accepted point (φₖ, tₖ) with S ≈ 0 and Dₖ = F(φₖ, tₖ) above the target δ:
//!    * the Taylor polynomial of S of order 2 (eqs. 7–8) gives the curve's slope φ' = −S_t/S_φ and
//! ```text
//!  bending φ'' = −(S_tt + 2S_φt φ' + S_φφ φ'²)/S_φ; along it D' = F_t and D'' = F_tt + F_φt φ'
//!  (F_φ = −ω₁S vanishes on the curve);
//! ```
//!    * the step h is the smallest of the adaptive accuracy step, the window's end, and the
//! ```text
//!  **guard** below; the predictor moves to φₖ + φ'h + φ''h²/2 at tₖ + h;
//! ```
//!    * the **corrector** solves S(φ, tₖ + h) = 0 by Halley's method at fixed t, reusing the
//! ```text
//!  positions at tₖ + h and safeguarded by a bracket (derivatives jump at piece ends);
//! ```
//!    * when the corrector fails or has to move φ far from the prediction the step is
//! ```text
//!  **backtracked**: h is halved and the step retried.
//! ```
//! 3. It stops at contact (Dₖ − δ ≤ tol), when the bounding circles about the rotation centres
//!    can no longer meet before the window ends, or at the window's end.
//!
//! ## Why no impact is stepped over (the guard)
//!
//! Keep φₖ fixed in object1's frame: g(t) = F(φₖ, t) is the gap between the shapes along a
//! body-fixed axis of object1, so g(t) ≤ D(t) for every t (every F is a lower bound on the
//! signed distance), with g(tₖ) = Dₖ and g'(tₖ) = F_t(φₖ, tₖ) = D'ₖ. Writing
//! g = −h₂(m(t)) − (C₁ − C₂)·R(α₁)N₁ − c₂·N − const (world rotation centres C, object2's local
//! centre c₂, m = −N turning at the relative spin ω = ω₁ − ω₂):
//!
//! ```text
//! |g''| ≤ M = ω²·max|h₂''| + 2|ω₁||ΔV| + ω₁²·max|ΔC| + ω²|c₂|,
//! ```
//!
//! with max|h₂''| = [`ConvexCurve::support_dd_bound`], ΔV the relative velocity of the rotation
//! centres and max|ΔC| their largest distance over the step (ΔC is affine in t, so its norm is
//! convex and the maximum sits at an end). Then g(t) ≥ Dₖ + D'ₖh − Mh²/2 on the step, and with
//! Δ = Dₖ − δ the step h = 2Δ / (−D'ₖ + √(D'ₖ² + 2MΔ)) keeps that bound above the target: D(t) ≥ δ
//! on [tₖ, tₖ + h]. No dip of the distance below the target can be stepped over, whatever the
//! spin, corner radius or grazing angle, and this does not rely on the corrector's accuracy (φₖ
//! need not be an exact root: any φ gives a lower bound). Approaching (D' < 0) the guard behaves
//! like a Newton step on D, so it also converges to the contact; when D' ≥ 0 it is at least
//! √(2Δ/M).
//!
//! ## Contact at the start
//!
//! With `stop_at_penetration` the answer is t₀ with [`ToiStatus::PenetratingAtStart`]. Without
//! it (rapier's CCD for solid bodies), a contact that is separating (D' > 0) is ignored and the
//! answer is the first later time the distance comes back down to the target; if the shapes
//! keep approaching, the answer is t₀.

use crate::curve::ConvexCurve;
use crate::distances::{eval_pair, PairFrame, PairJet, RelativeMotion};
use crate::math::Vector;
use crate::stationary::{stationary_in_frame, DistanceOptions, QueryError, Solver};
use parry2d_f64::query::NonlinearRigidMotion;

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
            max_corrector_iterations: 30,
            stop_at_penetration: true,
            distance: DistanceOptions::default(),
        }
    }
}

/// How a time-of-impact query ended.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum ToiStatus {
    /// The shapes reach the target distance at `time` (within the tolerances) and not before.
    Hit,
    /// The shapes are within the target distance at the start (`time` is the start time).
    PenetratingAtStart,
    /// No contact in the window (the window ended or the bounding circles parted for good).
    NoHit,
    /// The step cap was reached: no contact before `time`, nothing known after.
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
pub fn time_of_impact(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    toi_roles(
        shape1,
        motion1,
        shape2,
        motion2,
        start_time,
        end_time,
        options,
        &mut NoTrace,
    )
}

/// As [`time_of_impact`], recording every predictor step, correction and backtrack in `trace`
/// (in object1/object2 roles: φ is object1's parameter, where object1 is `shape1` unless only
/// `shape1` is strictly convex).
#[allow(clippy::too_many_arguments)]
pub fn time_of_impact_traced(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
    motion2: &NonlinearRigidMotion,
    start_time: f64,
    end_time: f64,
    options: &ToiOptions,
    trace: &mut Vec<TraceEvent>,
) -> Result<TimeOfImpact, QueryError> {
    toi_roles(shape1, motion1, shape2, motion2, start_time, end_time, options, trace)
}

#[allow(clippy::too_many_arguments)]
fn toi_roles<T: Tracer>(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
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
        Ok(TimeOfImpact {
            point1: r.point2,
            point2: r.point1,
            normal1: r.normal2,
            normal2: r.normal1,
            ..r
        })
    } else {
        Err(QueryError::NotStrictlyConvex)
    }
}

fn motion_is_finite(m: &NonlinearRigidMotion) -> bool {
    m.start.is_finite() && m.local_center.is_finite() && m.linvel.is_finite() && m.angvel.is_finite()
}

struct Tracker<'a> {
    obj1: &'a dyn ConvexCurve,
    obj2: &'a dyn ConvexCurve,
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
    h2dd: f64,
    c2_len: f64,
    cost: ToiCost,
}

impl<'a> Tracker<'a> {
    fn new(
        obj1: &'a dyn ConvexCurve,
        m1: &NonlinearRigidMotion,
        obj2: &'a dyn ConvexCurve,
        m2: &NonlinearRigidMotion,
        t0: f64,
        t1: f64,
        opts: &ToiOptions,
    ) -> Result<Self, QueryError> {
        if !(motion_is_finite(m1) && motion_is_finite(m2) && t0.is_finite() && t1.is_finite()) {
            return Err(QueryError::NonFinite);
        }
        if !(opts.target_distance.is_finite() && opts.target_distance >= 0.0) {
            return Err(QueryError::NonFinite);
        }
        if t1 < t0 {
            return Err(QueryError::EmptyWindow);
        }
        let rel = RelativeMotion::new(m1, m2);
        let size = obj1.bounding_radius().max(obj2.bounding_radius());
        let (c1, c2) = rel.centers();
        let reach = obj1.bounding_radius() + c1.length() + obj2.bounding_radius() + c2.length() + opts.target_distance;
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
            h2dd: obj2.support_dd_bound(),
            c2_len: c2.length(),
            cost: ToiCost::default(),
        })
    }

    /// True when the bounding circles about the rotation centres stay apart on [t, t1].
    fn parted_for_rest(&self, t: f64) -> bool {
        let p = self.rel.center_offset(t);
        let v = self.rel.center_velocity();
        let span = self.t1 - t;
        // min over s ∈ [0, span] of |p + v s|.
        let vv = v.length_squared();
        let s = if vv > 0.0 {
            (-p.dot(v) / vv).clamp(0.0, span)
        } else {
            0.0
        };
        (p + v * s).length() > self.reach * (1.0 + 1e-12)
    }

    /// M of the guard on [t, t + h] (module docs).
    fn guard_bound(&self, t: f64, h: f64) -> f64 {
        let w = self.rel.omega();
        let w1 = self.omega1;
        let dc = self
            .rel
            .center_offset(t)
            .length()
            .max(self.rel.center_offset(t + h).length());
        let dv = self.rel.center_velocity().length();
        w * w * (self.h2dd + self.c2_len) + 2.0 * w1.abs() * dv + w1 * w1 * dc
    }

    fn solver(&self, frame: PairFrame) -> Solver<'a> {
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
        TimeOfImpact {
            status,
            time: t,
            distance: j.fwd.v,
            distance_rate: j.fwd.t,
            point1: j.curve1.point,
            point2: j.support2.point,
            normal1: j.curve1.normal,
            normal2: -j.normal_in_2,
            cost: self.cost,
        }
    }

    /// Global stationary distance at t starting from φ: (φ, full jet).
    fn global_at(&mut self, t: f64, phi: f64) -> Result<(f64, PairJet), QueryError> {
        let frame = self.rel.frame(t);
        let r = stationary_in_frame(self.obj1, self.obj2, frame, phi, &self.opts.distance)?;
        self.cost.evaluations += r.evaluations;
        self.cost.corrector_iterations += r.newton_iterations;
        self.cost.evaluations += 1;
        let j = eval_pair(self.obj1, self.obj2, &frame, r.phi).ok_or(QueryError::Degenerate)?;
        Ok((r.phi, j))
    }

    /// Corrects φ at fixed t (Halley in a bracket); returns the root and its full jet.
    fn correct<T: Tracer>(&mut self, t: f64, phi: f64, trace: &mut T) -> Option<(f64, PairJet)> {
        let frame = self.rel.frame(t);
        let mut sv = self.solver(frame);
        let j0 = sv.eval(phi)?;
        let r = sv.local_root(phi, j0);
        self.cost.evaluations += sv.evaluations;
        // The first evaluation is the prediction itself; the rest are Halley/bisection steps.
        self.cost.corrector_iterations += sv.evaluations.saturating_sub(1);
        let (phi, j) = r?;
        trace.push(TraceEvent::Correct { phi, t, side: j.side.v });
        Some((phi, j))
    }

    fn run<T: Tracer>(mut self, trace: &mut T) -> Result<TimeOfImpact, QueryError> {
        let delta = self.opts.target_distance;
        let window = self.t1 - self.t0;
        let start_frame = self.rel.frame(self.t0);
        // Start φ: object1's normal pointing at object2's rotation centre.
        let dir2 = start_frame.unrotate(-start_frame.q);
        let dir2 = if dir2.length() > 0.0 {
            dir2.normalize()
        } else {
            Vector::X
        };
        let phi_start = self.obj1.phi_range_of_normal(dir2).0;
        let (mut phi, mut j) = self.global_at(self.t0, phi_start)?;
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
                    phi = phi2;
                    j = j2;
                }
                None => return Ok(self.result(ToiStatus::NoHit, self.t1, &j)),
            }
            if j.fwd.v <= delta + self.tol_d {
                // Still in contact and approaching again.
                return Ok(self.result(ToiStatus::Hit, t, &j));
            }
        }
        if self.parted_for_rest(t) {
            return Ok(self.result(ToiStatus::NoHit, t, &j));
        }

        let mut h_acc = (window / 8.0).max(f64::MIN_POSITIVE);
        let max_dphi = 0.35;
        loop {
            let gap = j.fwd.v - delta;
            if gap <= self.tol_d {
                let r = self.refine_hit(t, phi, j, trace);
                return Ok(r);
            }
            if self.cost.predictor_steps >= self.opts.max_steps {
                return Ok(self.result(ToiStatus::OutOfIterations, t, &j));
            }
            let h_max = self.t1 - t;
            if h_max <= 0.0 {
                return Ok(self.result(ToiStatus::NoHit, self.t1, &j));
            }
            // Taylor data of the curve S = 0 at (φ, t).
            let s = j.side;
            let (dphi, ddphi) = if s.p > 0.0 {
                let d1 = -s.t / s.p;
                let d2 = -(s.tt + 2.0 * s.pt * d1 + s.pp * d1 * d1) / s.p;
                (d1, d2)
            } else {
                (0.0, 0.0)
            };
            let d1 = j.fwd.t;
            let mut h = h_acc.min(h_max);
            // Limit the φ-travel of one step (the curve's bending, eq. 8): the largest h with
            // |φ'|h + |φ''|h²/2 ≤ max_dphi.
            let travel = dphi.abs() * h + 0.5 * ddphi.abs() * h * h;
            if travel > max_dphi {
                h = 2.0 * max_dphi / (dphi.abs() + (dphi * dphi + 2.0 * ddphi.abs() * max_dphi).sqrt());
            }
            // The guard (module docs).
            let m = self.guard_bound(t, h);
            let h_guard = 2.0 * gap / (-d1 + (d1 * d1 + 2.0 * m * gap).sqrt());
            let guard_limited = h_guard.is_finite() && h_guard < h;
            if guard_limited {
                h = h_guard;
            }
            if h.is_nan() || h <= 0.0 || t + h <= t {
                // No representable progress: the guard pins us at t.
                return Ok(self.result(ToiStatus::OutOfIterations, t, &j));
            }
            let t_new = if h >= h_max { self.t1 } else { t + h };
            let phi_pred = phi + dphi * h + 0.5 * ddphi * h * h;
            trace.push(TraceEvent::Predict {
                phi: phi_pred,
                t: t_new,
            });
            let corrected = self.correct(t_new, phi_pred, trace);
            let accept = match corrected {
                Some((phi_c, jc)) => {
                    // Reject when the corrector had to move far from the prediction, or landed on
                    // a root that is not a maximum of F.
                    let moved = (phi_c - phi_pred).abs();
                    let ok = jc.side.p > 0.0 && moved <= 0.25 && jc.fwd.v > delta - self.tol_d;
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
                    t = t_new;
                    phi = phi_c;
                    j = jc;
                    trace.push(TraceEvent::Accept {
                        phi,
                        t,
                        distance: j.fwd.v,
                    });
                    if !guard_limited || h >= h_acc * 0.99 {
                        // Adapt the accuracy step to how far the prediction was off.
                        if moved < 1e-3 {
                            h_acc *= 2.0;
                        } else if moved > 0.05 {
                            h_acc *= 0.5;
                        }
                    }
                    h_acc = h_acc.min(window).max(window * 1e-12);
                    if j.fwd.v > delta + self.tol_d && self.parted_for_rest(t) {
                        return Ok(self.result(ToiStatus::NoHit, t, &j));
                    }
                    if t >= self.t1 && j.fwd.v > delta + self.tol_d {
                        return Ok(self.result(ToiStatus::NoHit, self.t1, &j));
                    }
                }
                None => {
                    self.cost.backtracks += 1;
                    trace.push(TraceEvent::Backtrack {
                        phi: phi_pred,
                        t: t_new,
                    });
                    h_acc = h.min(h_acc) * 0.5;
                    if h_acc <= window * 1e-13 {
                        // Cannot make progress by tracking: recover with the global distance.
                        let t_try = t + h;
                        let (p2, j2) = self.global_at(t_try, phi_pred)?;
                        self.cost.predictor_steps += 1;
                        t = t_try;
                        phi = p2;
                        j = j2;
                        h_acc = window * 1e-6;
                    }
                }
            }
        }
    }

    /// At a safe point within tolerance of the target, sharpens the contact time: Newton steps
    /// on D from the safe side (a few, while they stay above the target), then, if one lands
    /// beyond the target, Illinois regula falsi on D(t) − δ between the last safe point and that
    /// point. The answer is the sample closest to the target among those with
    /// D ≥ δ − 1e-12·s (the safe point itself when nothing better is found). The bracket is
    /// ~gap/|D'| wide, far inside what the guard would step over, so the root found is the first.
    fn refine_hit<T: Tracer>(&mut self, t: f64, phi: f64, j: PairJet, trace: &mut T) -> TimeOfImpact {
        let delta = self.opts.target_distance;
        let floor = -1e-12 * self.size;
        let fine = 1e-15 * self.size;
        let mut best = (t, phi, j);
        let better = |best: &(f64, f64, PairJet), jj: &PairJet| {
            let g = jj.fwd.v - delta;
            g >= floor && g.abs() < (best.2.fwd.v - delta).abs() && jj.side.p > 0.0
        };
        // Newton from the safe side.
        let (mut ts, mut ps, mut js) = (t, phi, j);
        let mut beyond: Option<(f64, f64, f64)> = None;
        for _ in 0..8 {
            let gap = js.fwd.v - delta;
            let d1 = js.fwd.t;
            if gap <= fine || d1 >= 0.0 {
                break;
            }
            let t_n = (ts - gap / d1).min(self.t1);
            if t_n <= ts {
                break;
            }
            let Some((phi_n, jn)) = self.correct(t_n, ps, &mut NoTrace) else {
                break;
            };
            if better(&best, &jn) {
                best = (t_n, phi_n, jn);
            }
            let gn = jn.fwd.v - delta;
            if gn < 0.0 {
                beyond = Some((t_n, phi_n, gn));
                break;
            }
            (ts, ps, js) = (t_n, phi_n, jn);
        }
        if let Some((tb0, pb, gb0)) = beyond.filter(|b| b.2 < -fine) {
            // Illinois regula falsi between (ts, gap > 0) and (tb, gb < 0).
            let (mut ta, mut ga, mut tb, mut gb) = (ts, js.fwd.v - delta, tb0, gb0);
            let mut side = 0i8;
            let mut p = pb;
            for _ in 0..40 {
                let tm = (ta * gb - tb * ga) / (gb - ga);
                if !(tm > ta && tm < tb) {
                    break;
                }
                let Some((pm, jm)) = self.correct(tm, p, &mut NoTrace) else {
                    break;
                };
                p = pm;
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
        trace.push(TraceEvent::Impact { phi: best.1, t: best.0 });
        self.result(ToiStatus::Hit, best.0, &best.2)
    }

    /// From a separating contact at t, steps forward until the distance exceeds the target
    /// (returns that point), the shapes start approaching again while still in contact (returns
    /// that point, distance ≤ target), or the window ends (None).
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
            let (p2, j2) = self.global_at(t_new, phi)?;
            self.cost.predictor_steps += 1;
            t = t_new;
            phi = p2;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Pose;
    use crate::{BallCurve, Ellipse, RoundedPolygon};

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
