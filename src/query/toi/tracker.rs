//! The tracker's state and its step loop ([`Tracker::run`]): the start, the planned step
//! (φ-travel cap, guard, two-sided extension, aim), the correction and its judgement, the
//! adaptation of the accuracy step and backtracking (module docs of `query::toi`).

use super::circles::{circles_reach, circles_stay_apart};
use super::corrector::Tol;
use super::endgame::Leave;
use super::guard::curve_taylor;
use super::{TimeOfImpact, ToiCost, ToiStatus, TraceEvent, Tracer, Tracker};
use crate::curve::ConvexCurve;
use crate::error::QueryError;
use crate::numerics::angle::wrap_phi;
use crate::numerics::clock::Clock;
use crate::numerics::math::{rotate_cs, sin_cos, Vector};
use crate::numerics::motion::{PairFrame, RelativeMotion};
use crate::query::pair::PairJet;
use crate::query::solver::Solver;
use crate::query::stepping::{
    check_window, parabola_step, CONTACT_FLOOR, EXTENSION, EXTENSION_MARGIN, EXTENSION_ROUNDS, MIN_EXTENSION,
};
use crate::query::toi::ToiOptions;
use core::f64::consts::TAU;
use core::ops::ControlFlow;
use parry2d_f64::query::NonlinearRigidMotion;

/// A point on the tracked curve at a known time: φ and the pair's jet there.
type PhiJet = (f64, PairJet);

/// Largest φ-travel of one predictor step (radians).
const MAX_TRAVEL: f64 = 1.0;
/// The curvature bounds local to a step's directions are taken over at most this many guard
/// steps s_A (the two-sided extension needs room beyond s_A; a longer span sweeps more
/// directions and loosens the bound).
const LOCAL_BOUND_SPAN: f64 = 2.5;
/// A corrected point that moved more than this (radians, the corrector's move plus what is left
/// of its Newton step) from the prediction is not trusted for a contact: it could be a local
/// maximum of F ≤ 0 on another branch of S = 0.
const FAR_MOVE: f64 = 0.25;
/// The accuracy step adapts only after steps that used it (nearly) whole, h ≥ this × h_acc,
/// or that the guard did not limit.
const ACCURACY_STEP_USED: f64 = 0.99;
/// A prediction off by less than this (radians) doubles the accuracy step …
const GOOD_PREDICTION: f64 = 1e-2;
/// … and one off by more than this halves it.
const POOR_PREDICTION: f64 = 0.3;
/// Factor by which a good prediction grows the accuracy step.
const STEP_GROWTH: f64 = 2.0;
/// Factor by which a poor prediction or a backtrack shrinks the accuracy step.
const STEP_SHRINK: f64 = 0.5;
/// Smallest accuracy step, as a fraction of the window.
const MIN_ACCURACY_STEP: f64 = 1e-12;
/// Backtracking that shrinks the accuracy step below this fraction of the window gives up on
/// tracking for one step: the global stationary distance at t + h restarts the path.
const RECOVER_BELOW: f64 = 1e-13;
/// The accuracy step after such a recovery, as a fraction of the window.
const RECOVERED_STEP: f64 = 1e-6;

/// The step the tracker tries from an accepted point ([`Tracker::plan_step`]).
pub(super) struct StepPlan {
    /// Its length.
    pub h: f64,
    /// The guard's bound M on |g''| and the rate λ at which its axis turns.
    pub m: f64,
    pub lam: f64,
    /// The guard set the length (a plain, two-sided or aimed guard step).
    pub guard_limited: bool,
    /// For a step longer than the guard step s_A (two-sided or aimed): s_A.
    pub extended: Option<f64>,
    /// The step aims at the contact of the Taylor model of D.
    pub aim: bool,
    /// Taylor data of S = 0 at the accepted point: the Newton correction of its residual, φ'
    /// and φ'' ([`curve_taylor`]).
    pub resid: f64,
    pub dphi: f64,
    pub ddphi: f64,
}

impl<'a, A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized> Tracker<'a, A, B> {
    /// The query of `obj1` moving by `m1` against `obj2` moving by `m2` over [`t0`, `t1`], the
    /// rotation centres running on `clock` (the nlerp path; `None`: parry's motions).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn new(
        obj1: &'a A,
        m1: &NonlinearRigidMotion,
        obj2: &'a B,
        m2: &NonlinearRigidMotion,
        t0: f64,
        t1: f64,
        opts: &ToiOptions,
        clock: Option<Clock>,
    ) -> Result<Self, QueryError> {
        check_window(m1, m2, t0, t1, opts)?;
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
        }
        .with_clock(clock);
        // Each curve's bounding radius finite and positive (a `BallCurve` of radius −1 beside a
        // positive one passed a test of the larger alone), after the window's checks.
        crate::error::curves_sized(&[obj1.bounding_radius(), obj2.bounding_radius()])?;
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
            clock: clock.is_some(),
        })
    }

    /// True when the bounding circles about the rotation centres stay apart on [t, t1].
    pub(super) fn parted_for_rest(&self, t: f64) -> bool {
        let offset = self.rel.center_offset(t);
        // On a clock the centres still cover their straight segment from t to t1, only unevenly.
        let velocity = if self.clock {
            let span = self.t1 - t;
            if span > 0.0 {
                (self.rel.center_offset(self.t1) - offset) / span
            } else {
                Vector::ZERO
            }
        } else {
            self.rel.center_velocity()
        };
        circles_stay_apart(offset, velocity, self.t1 - t, self.reach)
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
    /// `crates/dev/tests/adversarial.rs`). F is a lower bound on the distance at any φ, so the error is
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
    pub(super) fn rewrap(&mut self, phi: f64) -> f64 {
        let w = wrap_phi(phi);
        if w != phi {
            self.turns += ((phi - w) / TAU).round();
        }
        w
    }

    /// φ continued across the whole turns removed by [`Tracker::rewrap`] (for the trace).
    #[inline]
    pub(super) fn unwrapped(&self, phi: f64) -> f64 {
        phi + self.turns * TAU
    }

    /// The frame at t (two sines and cosines; the last one is kept, as the start, a miss's
    /// polish and the stationary distance after a failed step ask again for a time just seen).
    #[inline]
    pub(super) fn frame(&mut self, t: f64) -> PairFrame {
        if self.last_frame.time != t {
            self.last_frame = self.rel.frame(t);
        }
        self.last_frame
    }

    pub(super) fn solver(&self, frame: PairFrame) -> Solver<'a, A, B> {
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

    pub(super) fn result(&self, status: ToiStatus, t: f64, j: &PairJet) -> TimeOfImpact {
        let (mut point2, mut normal2) = (j.support2.point, -j.normal_in_2);
        if self.spin2 != 0.0 {
            // Object2 turned by ω₂t about its origin since the frame `rel` tracks it in.
            let (s, c) = sin_cos(-self.spin2 * t);
            let rot = |v: Vector| rotate_cs(c, s, v);
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
    pub(super) fn finish(&mut self, status: ToiStatus, t: f64, phi: f64, j: PairJet) -> TimeOfImpact {
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

    /// The query: the start (contact at the start, bounding circles), then the tracked path.
    pub(super) fn run<T: Tracer>(mut self, trace: &mut T) -> Result<TimeOfImpact, QueryError> {
        match self.start(trace)? {
            ControlFlow::Break(r) => Ok(r),
            ControlFlow::Continue((t, phi, j)) => self.track(t, phi, j, trace),
        }
    }

    /// The stationary distance at t₀ and what it decides: a contact at the start
    /// ([`ToiStatus::PenetratingAtStart`], or a separating contact looked past), circles that
    /// never meet ([`ToiStatus::NoHit`]), or the accepted point (t, φ, jet) tracking starts from.
    fn start<T: Tracer>(
        &mut self,
        trace: &mut T,
    ) -> Result<ControlFlow<TimeOfImpact, (f64, f64, PairJet)>, QueryError> {
        let delta = self.opts.target_distance;
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
                return Ok(ControlFlow::Break(self.result(ToiStatus::PenetratingAtStart, t, &j)));
            }
            // Separating contact: move on until the distance is above the target.
            match self.leave_contact(t, phi, &j)? {
                Leave::At(t2, phi2, j2) => {
                    t = t2;
                    phi = self.rewrap(phi2);
                    j = j2;
                }
                // The distance and witnesses at the window's end, where `time` is.
                Leave::End(j_end) => return Ok(ControlFlow::Break(self.result(ToiStatus::NoHit, self.t1, &j_end))),
            }
            if j.fwd.v <= delta + self.tol_d {
                // Still in contact and approaching again.
                return Ok(ControlFlow::Break(self.result(ToiStatus::Hit, t, &j)));
            }
        }
        if parted || self.parted_for_rest(t) {
            return Ok(ControlFlow::Break(self.finish(ToiStatus::NoHit, t, phi, j)));
        }
        Ok(ControlFlow::Continue((t, phi, j)))
    }

    /// Tracks the zero level of S from the accepted point (t, φ, j) until contact, the circles
    /// part for good, the window ends or a cap is reached (module docs, "The algorithm").
    fn track<T: Tracer>(
        mut self,
        mut t: f64,
        mut phi: f64,
        mut j: PairJet,
        trace: &mut T,
    ) -> Result<TimeOfImpact, QueryError> {
        let delta = self.opts.target_distance;
        let window = self.t1 - self.t0;
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
                // F at φ is a lower bound on the distance, equal to it only at a root of S: a
                // contact is claimed only from a point corrected to the side tolerance, else
                // the global distance at t decides (`certified_contact`).
                match self.certified_contact(t, phi, j)? {
                    ControlFlow::Break((phi_c, jc)) => return Ok(self.refine_hit(t_prev, t, phi_c, jc, trace)),
                    ControlFlow::Continue((phi_c, jc)) => {
                        phi = self.rewrap(phi_c);
                        j = jc;
                        continue;
                    }
                }
            }
            if self.cost.predictor_steps >= self.opts.max_steps || self.cost.evaluations >= self.opts.max_evaluations {
                return Ok(self.finish(ToiStatus::OutOfIterations, t, phi, j));
            }
            let h_max = self.t1 - t;
            if h_max <= 0.0 {
                return Ok(self.finish(ToiStatus::NoHit, self.t1, phi, j));
            }
            let plan = self.plan_step(t, &j, gap, h_acc.min(h_max), retry_plain);
            let mut h = plan.h;
            retry_plain = false;
            if h.is_nan() || h <= 0.0 || t + h <= t {
                // No representable progress: the guard pins us at t.
                return Ok(self.finish(ToiStatus::OutOfIterations, t, phi, j));
            }
            let mut t_new = if h >= h_max { self.t1 } else { (t + h).min(self.t1) };
            // The accepted point may leave a residual S (loose tolerance away from contact):
            // its Newton correction joins the Taylor step.
            let phi_pred = phi + plan.resid + h * (plan.dphi + 0.5 * plan.ddphi * h);
            trace.push(TraceEvent::Predict {
                phi: self.unwrapped(phi_pred),
                t: t_new,
            });
            let mut corrected = self.correct(t_new, phi_pred, Tol::Loose, trace);
            if plan.aim {
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
            let accept = corrected.and_then(|(phi_c, jc)| self.judge(&plan, h, phi_pred, phi_c, jc));
            match accept {
                Some((phi_c, jc, moved)) => {
                    self.cost.predictor_steps += 1;
                    if plan.guard_limited {
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
                    if !plan.guard_limited || h >= h_acc * ACCURACY_STEP_USED {
                        // Adapt the accuracy step to how far the prediction was off.
                        if moved < GOOD_PREDICTION {
                            h_acc *= STEP_GROWTH;
                        } else if moved > POOR_PREDICTION {
                            h_acc *= STEP_SHRINK;
                        }
                    }
                    h_acc = h_acc.min(window).max(window * MIN_ACCURACY_STEP);
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
                    if plan.extended.is_some() {
                        // A two-sided step that failed (or whose correction failed): retry with the
                        // plain guard step, which is safe by itself.
                        retry_plain = true;
                        continue;
                    }
                    h_acc = h.min(h_acc) * STEP_SHRINK;
                    if h_acc <= window * RECOVER_BELOW {
                        // Cannot make progress by tracking: recover with the global distance.
                        // Within the window: t + h rounds past its end where |t| is far
                        // above |t1| (fuzz seed 777, case 6968: t = −1.1e287 and a window
                        // ending at −1 gave t + h = 0).
                        let t_try = if h >= self.t1 - t {
                            self.t1
                        } else {
                            (t + h).min(self.t1)
                        };
                        let (p2, j2) = self.global_at(t_try, phi_pred, Tol::Fixed(self.side_tol))?;
                        self.cost.predictor_steps += 1;
                        t_prev = t;
                        t = t_try;
                        phi = self.rewrap(p2);
                        j = j2;
                        h_acc = window * RECOVERED_STEP;
                    }
                }
            }
        }
    }

    /// A point (t, φ, j) whose F is within the distance tolerance of the target, certified as a
    /// contact: `Break` with the point to refine the hit from, or `Continue` with the global
    /// distance's point at t when the shapes are in fact further apart. F(φ, t) is only a lower
    /// bound on the distance unless φ is a root of S; a point accepted loosely (its |S| above the
    /// side tolerance) near the tip of a thin shape can sit far below the distance (fuzz seed
    /// 31337, case 157490: a thin `CapsuleEllipse` against a 1:8000 ellipse claimed a contact
    /// with |S| = 0.42, the distance there 4.3e-4 of a size of 0.23). Such a point is replaced by
    /// the global distance at t (certified, [`Tracker::global_at`]), which decides.
    #[inline(never)]
    fn certified_contact(&mut self, t: f64, phi: f64, j: PairJet) -> Result<ControlFlow<PhiJet, PhiJet>, QueryError> {
        if self.accepts(Tol::Fixed(self.side_tol), &j.point()) {
            return Ok(ControlFlow::Break((phi, j)));
        }
        let (p, jg) = self.global_at(t, phi, Tol::Fixed(self.side_tol))?;
        self.cost.predictor_steps += 1;
        Ok(if jg.fwd.v - self.opts.target_distance <= self.tol_d {
            ControlFlow::Break((p, jg))
        } else {
            ControlFlow::Continue((p, jg))
        })
    }

    /// The step from the accepted point (t, j) with gap D − δ = `gap`, at most `h` long (the
    /// accuracy step, within the window): the φ-travel cap, the guard (global curvature bounds,
    /// then the local ones when those limit it), and the two-sided extension or the aim at the
    /// Taylor model's contact (module docs). `retry_plain`: the last two-sided step failed, take
    /// the plain guard step.
    #[inline(always)]
    fn plan_step(&self, t: f64, j: &PairJet, gap: f64, mut h: f64, retry_plain: bool) -> StepPlan {
        // Taylor data of the curve S = 0 at (φ, t).
        let (resid, dphi, ddphi) = curve_taylor(j);
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
        let mut h_guard = parabola_step(gap, slope_at(lam), m);
        // The Taylor model of D along the curve: D'' and where it reaches the target (NaN or
        // infinite if it does not). A loosely accepted point lies `resid` off the root: D
        // and D' there are F and F_t carried to the root along φ (F_φ = −ω₁S ≠ 0 off it),
        // which keeps the aim as accurate as from an exact root.
        let d2 = j.fwd.tt + j.fwd.pt * dphi;
        let gap_m = gap + resid * (j.fwd.p + 0.5 * j.fwd.pp * resid);
        let d1_m = j.fwd.t + j.fwd.pt * resid;
        // (Only needed when the guard limits the step: the aim below is taken only then.)
        let h_model = if h_guard < h {
            parabola_step(gap_m, d1_m, -d2)
        } else {
            f64::NAN
        };
        // Near the contact the global bound already certifies an aim at the model's contact
        // with room to spare (s_A + s_B/2 ≥ h_m, s_B ≈ 2|D'|/M from the target level): the
        // local bounds could not change the step, skip them. (They could only make its
        // certification, with a smaller M, pass where the global one fails: the step is
        // then retried as a plain guard step, which computes them.)
        // A step aims at the model's contact when it lies beyond the guard step s_A but within
        // the two-sided extension (EXTENSION·s_A, and the span its bound holds on).
        let aims = |s_a: f64, span: f64| h_model > s_a && h_model < (EXTENSION * s_a).min(span);
        let aim_sure = !retry_plain && aims(h_guard, span) && (h_model - h_guard) * m <= -(d1_m + d2 * h_model);
        if h_guard < h && !aim_sure {
            // Limited with the global curvature bounds: try the local ones.
            let span2 = (LOCAL_BOUND_SPAN * h_guard).min(span);
            let (m2, lam2) = self.guard_bound(t, span2, Some(j));
            let hg2 = parabola_step(gap, slope_at(lam2), m2).min(span2);
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
            let mut he = (EXTENSION * h_guard).min(span);
            if aims(h_guard, span) {
                // Approaching: aim at the model's contact itself.
                he = h_model;
                aim = true;
            } else {
                for _ in 0..EXTENSION_ROUNDS {
                    let g_end = gap + he * (j.fwd.t + 0.5 * d2 * he);
                    if !(g_end > 0.0) {
                        he = h_guard;
                        break;
                    }
                    let s_b = parabola_step(g_end, -(j.fwd.t + d2 * he), m);
                    he = ((h_guard + s_b) / EXTENSION_MARGIN).min(span);
                }
            }
            if aim || he > MIN_EXTENSION * h_guard {
                extended = Some(h_guard);
                h = he;
            }
        }
        if guard_limited && extended.is_none() {
            h = h_guard;
        }
        StepPlan {
            h,
            m,
            lam,
            guard_limited,
            extended,
            aim,
            resid,
            dphi,
            ddphi,
        }
    }

    /// Whether the corrected point (φ_c, jc) at the end of a step of length `h` planned as
    /// `plan` (predicted at `phi_pred`) is accepted: returns it with how far the prediction was
    /// off. Rejected when the corrector had to move far from the prediction and claims a
    /// contact, landed on a root that is not a maximum of F, an aimed step ended below the
    /// contact floor, or the two-sided bound does not cover the step.
    #[inline(always)]
    fn judge(&self, plan: &StepPlan, h: f64, phi_pred: f64, phi_c: f64, jc: PairJet) -> Option<(f64, PairJet, f64)> {
        let delta = self.opts.target_distance;
        let floor = -CONTACT_FLOOR * self.size;
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
        let mut ok = jc.side.p > 0.0 && gap_c > -self.tol_d && (moved <= FAR_MOVE || gap_c > self.tol_d);
        if plan.aim && !(gap_c >= floor) {
            ok = false;
        }
        if let Some(s_a) = plan.extended.filter(|_| ok) {
            // Backward bound from the new point: g(t_new − s) ≥ gap_B − g'·s − M s²/2
            // (an aimed step may end a hair below the target: its bound is taken
            // from the floor the contact allows).
            let gap_b = jc.fwd.v - delta - if plan.aim { floor } else { 0.0 };
            let slope_b = jc.fwd.t - (plan.lam - self.omega1) * jc.side.v;
            let s_b = if gap_b > 0.0 {
                parabola_step(gap_b, -slope_b, plan.m)
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
}
