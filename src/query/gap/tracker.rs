//! The gap tracker's step loop: exact distance at each accepted time, guarded steps, the aim at
//! the contact of the distance's Taylor model certified from both ends, and the refinement of
//! the contact by guarded Newton steps (module docs of `query::gap`).

// The negated comparisons (`!(x > 0.0)`) are deliberate: they are true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::frame::{GapFrame, GapMotion};
use super::maxgap::{Contact, GapMax, Pair};
use super::side::Side;
use crate::error::QueryError;
use crate::numerics::clock::Clock;
use crate::numerics::math::{direction, rotate_cs, sin_cos, Vector};
use crate::query::stepping::{
    check_window, parabola_step, LeaveWalk, CONTACT_FLOOR, EXTENSION, EXTENSION_MARGIN, EXTENSION_ROUNDS, FINE,
    MIN_EXTENSION,
};
use crate::query::toi::circles::{circles_reach, circles_stay_apart};
use crate::query::toi::{TimeOfImpact, ToiCost, ToiOptions, ToiStatus};
use parry2d_f64::query::NonlinearRigidMotion;

/// A guard bound is retaken over this many of its steps when the step falls well inside its span
/// (a shorter span sweeps fewer directions: a tighter bound, with room for the two-sided
/// extension), and over this factor squared times its span when the step fills the span.
const LOCAL_SPAN: f64 = 2.5;
/// Rounds of the span adaptation of each guard bound ([`GapTracker::best_step`]).
const SPAN_ROUNDS: usize = 4;
/// The refinement stops when the gap is below [`FINE`] of the size, or its next step below this
/// fraction of the window …
const REFINE_TIME: f64 = 1e-13;
/// … or after this many steps.
const REFINE_STEPS: usize = 24;
/// Newton steps backwards from a point accepted a hair beyond the target, at most.
const BACKWARD_STEPS: usize = 4;

/// A point of the path: its time, frame and the distance's maximum there.
#[derive(Copy, Clone, Debug)]
struct Point {
    fr: GapFrame,
    at: GapMax,
}

/// The state of one query.
pub(crate) struct GapTracker<'a> {
    pair: Pair<'a>,
    t0: f64,
    t1: f64,
    opts: ToiOptions,
    /// The larger bounding radius of the two shapes about their local origins.
    size: f64,
    tol_d: f64,
    /// The circles' reach (module docs of `query::toi::circles`).
    reach: f64,
    /// Each body's radius about its rotation centre.
    radius: [f64; 2],
    /// The turn rates λ the guard tries: ω₁, ω₂ and 0 (without repeats).
    lambdas: [f64; 2],
    n_lambdas: usize,
    cost: ToiCost,
}

impl<'a> GapTracker<'a> {
    /// A query of `side1` moving by `m1` against `side2` moving by `m2` over `[t0, t1]`.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        side1: Side<'a>,
        m1: &NonlinearRigidMotion,
        side2: Side<'a>,
        m2: &NonlinearRigidMotion,
        t0: f64,
        t1: f64,
        opts: &ToiOptions,
        clock: Option<Clock>,
    ) -> Result<Self, QueryError> {
        check_window(m1, m2, t0, t1, opts)?;
        let size = side1.radius_about(Vector::ZERO).max(side2.radius_about(Vector::ZERO));
        let radius = [side1.radius_about(m1.local_center), side2.radius_about(m2.local_center)];
        let reach = circles_reach(
            side1.radius_about(Vector::ZERO),
            m1.local_center,
            side2.radius_about(Vector::ZERO),
            m2.local_center,
            opts.target_distance,
        );
        if !(size.is_finite() && size > 0.0 && reach.is_finite() && radius.iter().all(|r| r.is_finite())) {
            return Err(QueryError::Degenerate);
        }
        // The axis turns with one body or the other: with the body whose face holds the contact
        // that body's term is exact (a fixed axis, rate 0, is one of them when a body does not
        // spin; with both spinning it is never the better bound near a contact, and trying it
        // cost a third of the query).
        let lambdas = [m1.angvel, m2.angvel];
        let n_lambdas = if m2.angvel == m1.angvel { 1 } else { 2 };
        Ok(GapTracker {
            pair: Pair {
                sides: [side1, side2],
                motion: GapMotion::new(m1, m2).with_clock(clock),
            },
            t0,
            t1,
            opts: *opts,
            size,
            tol_d: opts.distance_tolerance * size,
            reach,
            radius,
            lambdas,
            n_lambdas,
            cost: ToiCost::default(),
        })
    }

    /// Tracks the signed distance down to `level` instead of the options' target distance: any
    /// sign, a negative level being a penetration depth (the distance at each time is the exact
    /// signed distance, and the guard's bound holds at any level).
    pub(crate) fn with_level(mut self, level: f64) -> Self {
        self.reach += level - self.opts.target_distance;
        self.opts.target_distance = level;
        self
    }

    /// The exact maximum at time `t`, walking from the axis `u` with the supports `hint`.
    fn eval(&mut self, t: f64, u: Vector, hint: (usize, usize)) -> Result<Point, QueryError> {
        self.cost.evaluations += 1;
        let fr = self.pair.motion.frame(t);
        let at = self.pair.max_gap(&fr, u, hint).ok_or(QueryError::Degenerate)?;
        Ok(Point { fr, at })
    }

    /// The exact maximum at `t` predicted from the point `p` (its axis turned by the rate of its
    /// configuration).
    fn eval_from(&mut self, p: &Point, t: f64) -> Result<Point, QueryError> {
        let rate = match p.at.kind {
            Contact::Smooth => {
                let j = &p.at.jet;
                if j.g_thth < 0.0 {
                    -j.g_tht / j.g_thth
                } else {
                    0.0
                }
            }
            Contact::Face1 | Contact::Faces => self.pair.motion.omega[0],
            Contact::Face2 => self.pair.motion.omega[1],
        };
        let (s, c) = sin_cos(rate * (t - p.fr.time));
        let u = rotate_cs(c, s, p.at.u);
        let u = if u.is_finite() { u } else { p.at.u };
        self.eval(t, u, (p.at.i, p.at.j))
    }

    /// True when the bounding circles about the rotation centres stay apart on [t, t1].
    fn parted_for_rest(&self, t: f64) -> bool {
        let mo = &self.pair.motion;
        let offset = mo.dc(t);
        // On a clock the centres still cover their straight segment from t to t1, only unevenly.
        let velocity = match mo.clock {
            None => mo.dv,
            Some(_) if self.t1 > t => (mo.dc(self.t1) - offset) / (self.t1 - t),
            Some(_) => Vector::ZERO,
        };
        circles_stay_apart(offset, velocity, self.t1 - t, self.reach)
    }

    /// The longest guard step from `p` with gap `gap` (to the level the guard keeps) within
    /// `h_max` in the time direction `dir`, over the turn rates tried: (step, the span its
    /// bound holds on, the bound M on its parabola's curvature).
    ///
    /// For each rate the span is adapted over a few rounds: a bound over a shorter span sweeps
    /// fewer directions (tighter near faces), so a step limited well inside its span is tried
    /// again over [`LOCAL_SPAN`] steps, and a step that fills its span over a longer one.
    fn best_step(&mut self, p: &Point, gap: f64, h_max: f64, dir: f64) -> (f64, f64, f64) {
        let mut best = (0.0, h_max, f64::INFINITY);
        for k in 0..self.n_lambdas {
            let lam = self.lambdas[k];
            // Start over the span on which the bound is exact, when there is one.
            let exact = self.pair.exact_span(&p.fr, &p.at, lam, dir);
            let mut span = if exact > 0.0 { exact.min(h_max) } else { h_max };
            let mut last = -1.0;
            for _ in 0..SPAN_ROUNDS {
                let bound = self.pair.guard(&p.fr, &p.at, lam, span, dir, self.radius);
                let s = bound.step(gap, span);
                if s > best.0 || (best.2.is_infinite() && s >= best.0) {
                    best = (s, span, bound.curvature(span));
                }
                if !(s > last) {
                    // The new span did not lengthen this rate's step: stop adapting it (a
                    // heuristic; every span's step is safe).
                    break;
                }
                last = s;
                let next = if s >= span {
                    LOCAL_SPAN * LOCAL_SPAN * span
                } else {
                    LOCAL_SPAN * s
                }
                .min(h_max);
                if !(next > 0.0) || next == span {
                    break;
                }
                span = next;
            }
        }
        best
    }

    /// The plain guard step from `p` within `h_max` ([`GapTracker::best_step`] forwards).
    fn guard_step(&mut self, p: &Point, gap: f64, h_max: f64) -> (f64, f64, f64) {
        self.best_step(p, gap, h_max, 1.0)
    }

    /// The distance's D' and D'' at `p`.
    fn rates(&self, p: &Point) -> (f64, f64) {
        self.pair.rates(&p.at)
    }

    /// The query (module docs of `query::gap`).
    pub(crate) fn run(mut self) -> Result<TimeOfImpact, QueryError> {
        let delta = self.opts.target_distance;
        let dc = self.pair.motion.dc(self.t0);
        let u0 = if dc == Vector::ZERO { Vector::X } else { -direction(dc) };
        let mut p = self.eval(self.t0, u0, (0, 0))?;
        if p.at.d <= delta + self.tol_d {
            let (d1, _) = self.rates(&p);
            if self.opts.stop_at_penetration || d1 <= 0.0 {
                return Ok(self.result(ToiStatus::PenetratingAtStart, &p));
            }
            match self.leave_contact(p)? {
                Some(q) => p = q,
                None => {
                    let end = self.eval_from(&p, self.t1)?;
                    return Ok(self.result(ToiStatus::NoHit, &end));
                }
            }
            if p.at.d <= delta + self.tol_d {
                return Ok(self.result(ToiStatus::Hit, &p));
            }
        }
        if self.parted_for_rest(p.fr.time) {
            return Ok(self.result(ToiStatus::NoHit, &p));
        }
        self.track(p)
    }

    /// The step loop from the accepted point `p` (above the target).
    fn track(mut self, mut p: Point) -> Result<TimeOfImpact, QueryError> {
        let delta = self.opts.target_distance;
        let floor = -CONTACT_FLOOR * self.size;
        let mut retry_plain = false;
        // The accepted point before p: no contact lies before it.
        let mut t_prev = p.fr.time;
        loop {
            let t = p.fr.time;
            let gap = p.at.d - delta;
            if gap <= self.tol_d {
                return self.refine(p, t_prev);
            }
            if self.cost.predictor_steps >= self.opts.max_steps || self.cost.evaluations >= self.opts.max_evaluations {
                return Ok(self.result(ToiStatus::OutOfIterations, &p));
            }
            let h_max = self.t1 - t;
            if h_max <= 0.0 {
                return Ok(self.result(ToiStatus::NoHit, &p));
            }
            let (s_a, span, m) = self.guard_step(&p, gap, h_max);
            let guard_limited = s_a < h_max;
            let (d1, d2) = self.rates(&p);
            let mut h = s_a;
            let mut extended = false;
            let mut aim = false;
            if guard_limited && !retry_plain {
                let h_model = parabola_step(gap, d1, -d2);
                let cap = (EXTENSION * s_a).min(span);
                if d1 < 0.0 && h_model > s_a && h_model < cap {
                    (h, aim, extended) = (h_model, true, true);
                } else {
                    let mut he = cap;
                    for _ in 0..EXTENSION_ROUNDS {
                        let g_end = gap + he * (d1 + 0.5 * d2 * he);
                        if !(g_end > 0.0) {
                            he = s_a;
                            break;
                        }
                        let s_b = parabola_step(g_end, -(d1 + d2 * he), m).min(he);
                        he = ((s_a + s_b) / EXTENSION_MARGIN).min(cap);
                    }
                    if he > MIN_EXTENSION * s_a {
                        (h, extended) = (he, true);
                    }
                }
            }
            retry_plain = false;
            if h.is_nan() || h <= 0.0 || t + h <= t {
                return Ok(self.result(ToiStatus::OutOfIterations, &p));
            }
            let t_new = if h >= h_max { self.t1 } else { (t + h).min(self.t1) };
            let mut q = self.eval_from(&p, t_new)?;
            if aim && q.at.d - delta < floor {
                // Aimed beyond the contact: back up along the far point's Taylor model of D.
                match self.back_up(&p, &q)? {
                    Some(b) => q = b,
                    None => {
                        self.cost.backtracks += 1;
                        retry_plain = true;
                        continue;
                    }
                }
            }
            if extended {
                let h_q = q.fr.time - t;
                let level = q.at.d - delta - if aim { floor } else { 0.0 };
                let s_b = if level > 0.0 {
                    self.best_step(&q, level, h_q, -1.0).0
                } else {
                    0.0
                };
                if !(s_a + s_b >= h_q) {
                    self.cost.backtracks += 1;
                    retry_plain = true;
                    continue;
                }
            }
            self.cost.predictor_steps += 1;
            if guard_limited {
                self.cost.guard_limited_steps += 1;
            }
            t_prev = p.fr.time;
            p = q;
            let t = p.fr.time;
            if p.at.d > delta + self.tol_d && self.parted_for_rest(t) {
                return Ok(self.result(ToiStatus::NoHit, &p));
            }
            if t >= self.t1 && p.at.d > delta + self.tol_d {
                return Ok(self.result(ToiStatus::NoHit, &p));
            }
        }
    }

    /// From the point `q` of an aimed step that landed beyond the contact (D < δ), back to where
    /// its order-2 Taylor model of D reaches the target, if that lies after `p` and is not below
    /// the contact floor there.
    fn back_up(&mut self, p: &Point, q: &Point) -> Result<Option<Point>, QueryError> {
        let over = self.opts.target_distance - q.at.d;
        let (d1, d2) = self.rates(q);
        if !(over > 0.0 && d1 < 0.0) {
            return Ok(None);
        }
        let disc = d1 * d1 + 2.0 * d2 * over;
        let v = if disc >= 0.0 {
            2.0 * over / (-d1 + disc.sqrt())
        } else {
            over / -d1
        };
        let tb = q.fr.time - v;
        if !(tb > p.fr.time && tb < q.fr.time) {
            return Ok(None);
        }
        let b = self.eval_from(q, tb)?;
        let floor = -CONTACT_FLOOR * self.size;
        Ok((b.at.d - self.opts.target_distance >= floor).then_some(b))
    }

    /// Sharpens a contact found within the tolerance: guarded Newton steps (the guard step from
    /// a gap this small is the Newton step on D up to O(gap²), and never passes the contact)
    /// until the gap or the step is at the resolution.
    ///
    /// A point accepted a hair beyond the target (an aimed step, within the contact floor) is
    /// first brought back by Newton steps on D backwards — never before `t_prev`, the accepted
    /// point before it: the interval between them is certified down to the floor — so that the
    /// time does not carry the floor's error divided by the approach speed.
    fn refine(mut self, mut p: Point, t_prev: f64) -> Result<TimeOfImpact, QueryError> {
        let delta = self.opts.target_distance;
        let floor = -CONTACT_FLOOR * self.size;
        let fine = FINE * self.size;
        for _ in 0..BACKWARD_STEPS {
            let gap = p.at.d - delta;
            let (d1, _) = self.rates(&p);
            if !(gap < -fine && d1 < 0.0) {
                break;
            }
            let t_n = (p.fr.time - gap / d1).max(t_prev);
            if !(t_n < p.fr.time) {
                break;
            }
            let q = self.eval_from(&p, t_n)?;
            self.cost.corrector_iterations += 1;
            let g = q.at.d - delta;
            if !(g >= floor && g.abs() < gap.abs()) {
                break;
            }
            p = q;
        }
        let t_fine = REFINE_TIME * (self.t1 - self.t0);
        for _ in 0..REFINE_STEPS {
            let gap = p.at.d - delta;
            let (d1, _) = self.rates(&p);
            let h_max = self.t1 - p.fr.time;
            if gap <= FINE * self.size || d1 >= 0.0 || h_max <= 0.0 {
                break;
            }
            let (s, _, _) = self.guard_step(&p, gap, h_max);
            if !(s > t_fine) || p.fr.time + s <= p.fr.time {
                break;
            }
            let q = self.eval_from(&p, p.fr.time + s)?;
            self.cost.corrector_iterations += 1;
            if !(q.at.d - delta >= -CONTACT_FLOOR * self.size) {
                break;
            }
            p = q;
        }
        Ok(self.result(ToiStatus::Hit, &p))
    }

    /// From a separating contact at the start, steps forward until the distance exceeds the
    /// target (that point), the shapes approach again while still in contact (that point), or
    /// the window ends (`None`).
    fn leave_contact(&mut self, p: Point) -> Result<Option<Point>, QueryError> {
        let walk = LeaveWalk::new(self.t0, self.t1, &self.opts, self.tol_d);
        let (t, d, d1) = (p.fr.time, p.at.d, self.rates(&p).0);
        walk.run(p, t, (d, d1), |p, t_new| {
            let q = self.eval_from(p, t_new)?;
            self.cost.predictor_steps += 1;
            let (d, d1) = (q.at.d, self.rates(&q).0);
            Ok((q, d, d1))
        })
    }

    /// The answer at the point `p`: witnesses on each shape in its local frame.
    fn result(&self, status: ToiStatus, p: &Point) -> TimeOfImpact {
        let (w1, w2) = self.pair.witnesses(&p.fr, &p.at);
        let (d1, _) = self.rates(p);
        TimeOfImpact {
            status,
            time: p.fr.time,
            distance: p.at.d,
            distance_rate: d1,
            point1: w1,
            point2: w2,
            normal1: p.fr.to_body(0, p.at.u),
            normal2: p.fr.to_body(1, -p.at.u),
            cost: self.cost,
        }
    }
}
