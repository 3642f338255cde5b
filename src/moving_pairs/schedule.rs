//! The pass's event loop ([`Schedule::run`]): the first times of impact of the pairs, earliest
//! first, each stopping its bodies, and the pairs of a stopped body checked again with its
//! shortened motion.
//!
//! # The loop and why it is exact
//!
//! Every body moves on its path ([`super::path::StepPath`]) until the time it stops (the step's
//! length `dt` while it does not). Each solid pair holds the first time of impact of its two
//! motions after the time it was last computed, or none.
//!
//! 1. Every pair's first time of impact over [0, dt].
//! 2. The earliest pending time t over all pairs (ties: the pair first in (a, b) order) is a
//!    first contact of the two bodies *on the motions they really have*: no body changed its
//!    motion before t (every stop so far was at or before the current time, and every pair
//!    involving a stopped body was recomputed from its stop on). Both bodies stop at t, unless
//!    already stopped or not stoppable (kinematic).
//! 3. A body that stops at t keeps its motion up to t, so the pending times of its other
//!    pairs remain valid up to t — and none is earlier than t. After t it stands still, so
//!    each of its other pairs is computed again over [t, dt] (a pair whose pending time is t
//!    itself is kept: that contact happens on the unchanged part of the motion). Pairs whose
//!    bodies both stand still have no time of impact.
//! 4. Repeat from 2 until no time is pending.
//!
//! So no two bodies of a solid pair ever overlap on the paths the pass leaves them (up to the
//! casts' tolerance), except where a kinematic body, which the pass does not stop, runs on
//! into a body stopped in its way. Each round retires the earliest pending time; a time is set
//! again only when a body stops, which happens once per body: the number of rounds is bounded
//! by the number of pairs plus the sum of the stopped bodies' pair counts, and the loop carries
//! that bound ([`PassStatus::OutOfEvents`] if ever reached).
//!
//! A cast that stops at a cap (`OutOfIterations` at time t: no contact before t) counts as a
//! contact at t, as rapier counts it; a cast the dispatcher cannot answer counts as none (and
//! is reported).

use super::records::{PassBody, PassCollider, PassPair};
use super::report::{MovingPairsReport, PassStatus};
use parry2d_f64::query::NonlinearRigidMotion;

/// What a cast of a pair found.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum CastOutcome {
    /// A first contact at this time.
    Hit(f64),
    /// No contact before this time; the cast stopped at a cap there.
    Capped(f64),
    /// No contact in the window.
    Miss,
    /// The dispatcher cannot answer the pair.
    Unsupported,
}

/// The time of impact of two colliders, answered by the adapter (which holds the shapes).
pub trait PairCast {
    /// The first time in [`t0`, `t1`] at which collider `c1` moving by `m1` touches collider
    /// `c2` moving by `m2` (collider indices into the pass's colliders). For a solid pair
    /// (`sensor` false) a contact at `t0` is answered as rapier's CCD answers one
    /// (`CastPolicy::RapierConstantSpin`); for a sensor pair any overlap counts.
    #[allow(clippy::too_many_arguments)]
    fn cast(
        &mut self,
        c1: u32,
        m1: &NonlinearRigidMotion,
        c2: u32,
        m2: &NonlinearRigidMotion,
        t0: f64,
        t1: f64,
        sensor: bool,
    ) -> CastOutcome;
}

/// The event loop's scratch: each body's pairs (kept by the pass: no allocation once warm).
#[derive(Clone, Debug, Default)]
pub struct Schedule {
    offsets: Vec<u32>,
    list: Vec<u32>,
}

impl Schedule {
    /// Runs the loop (module docs) over the solid `pairs` of `colliders` of `bodies`: sets the
    /// stop time of every body that has to stop, counting into `report`.
    pub fn run<C: PairCast>(
        &mut self,
        bodies: &mut [PassBody],
        colliders: &[PassCollider],
        pairs: &mut [PassPair],
        caster: &mut C,
        report: &mut MovingPairsReport,
    ) {
        let Some(dt) = bodies.first().map(|b| b.path.dt) else {
            return;
        };
        self.build(bodies.len(), colliders, pairs);
        for p in pairs.iter_mut().filter(|p| p.solid) {
            p.time = cast_pair(p, bodies, colliders, 0.0, dt, caster, report);
        }
        let bound = 2 * pairs.len() + bodies.len() + 1;
        for _ in 0..bound {
            let Some(k) = earliest(pairs) else {
                return;
            };
            let t = pairs[k].time;
            pairs[k].time = f64::INFINITY;
            for c in [pairs[k].a, pairs[k].b] {
                let b = colliders[c as usize].body as usize;
                if bodies[b].stoppable && !bodies[b].stopped() && t < dt {
                    bodies[b].stop = t;
                    report.stopped_bodies += 1;
                    self.recheck(b, k, t, bodies, colliders, pairs, caster, report);
                }
            }
        }
        report.status = PassStatus::OutOfEvents;
    }

    /// The pairs of each body, as offsets into one list.
    fn build(&mut self, n: usize, colliders: &[PassCollider], pairs: &[PassPair]) {
        self.offsets.clear();
        self.offsets.resize(n + 2, 0);
        let body = |c: u32| colliders[c as usize].body as usize;
        for p in pairs.iter().filter(|p| p.solid) {
            self.offsets[body(p.a) + 2] += 1;
            self.offsets[body(p.b) + 2] += 1;
        }
        for i in 2..self.offsets.len() {
            self.offsets[i] += self.offsets[i - 1];
        }
        self.list.clear();
        self.list.resize(self.offsets[n + 1] as usize, 0);
        for (k, p) in pairs.iter().enumerate().filter(|(_, p)| p.solid) {
            for b in [body(p.a), body(p.b)] {
                let slot = &mut self.offsets[b + 1];
                self.list[*slot as usize] = k as u32;
                *slot += 1;
            }
        }
    }

    /// Step 3 of the loop for body `b`, stopped at `t` by pair `k`.
    #[allow(clippy::too_many_arguments)]
    fn recheck<C: PairCast>(
        &self,
        b: usize,
        k: usize,
        t: f64,
        bodies: &[PassBody],
        colliders: &[PassCollider],
        pairs: &mut [PassPair],
        caster: &mut C,
        report: &mut MovingPairsReport,
    ) {
        let dt = bodies[b].path.dt;
        let (from, to) = (self.offsets[b] as usize, self.offsets[b + 1] as usize);
        for &q in &self.list[from..to] {
            let q = q as usize;
            if q != k && pairs[q].time != t {
                pairs[q].time = cast_pair(&pairs[q], bodies, colliders, t, dt, caster, report);
            }
        }
    }
}

/// The pending pair with the earliest time (ties: the first), if any.
fn earliest(pairs: &[PassPair]) -> Option<usize> {
    let mut best: Option<usize> = None;
    for (k, p) in pairs.iter().enumerate() {
        if p.time.is_finite() && best.is_none_or(|b| p.time < pairs[b].time) {
            best = Some(k);
        }
    }
    best
}

/// The two colliders of `p` in the order of the cast (the one that moves more over the window
/// first: the rapier rule's fast body), with their motions from `t0`.
fn cast_order(
    p: &PassPair,
    bodies: &[PassBody],
    colliders: &[PassCollider],
    t0: f64,
) -> [(u32, NonlinearRigidMotion); 2] {
    let side = |c: u32| {
        let co = &colliders[c as usize];
        let body = &bodies[co.body as usize];
        ((c, co.motion_from(body, t0)), body.travel_from(t0))
    };
    let ((a, ta), (b, tb)) = (side(p.a), side(p.b));
    if tb > ta {
        [b, a]
    } else {
        [a, b]
    }
}

/// The first time of impact of the solid pair `p` over [`t0`, `dt`], infinite when none (or
/// when neither body moves after `t0`).
#[allow(clippy::too_many_arguments)]
fn cast_pair<C: PairCast>(
    p: &PassPair,
    bodies: &[PassBody],
    colliders: &[PassCollider],
    t0: f64,
    dt: f64,
    caster: &mut C,
    report: &mut MovingPairsReport,
) -> f64 {
    let moves = |c: u32| bodies[colliders[c as usize].body as usize].moves_after(t0);
    if !(moves(p.a) || moves(p.b)) {
        return f64::INFINITY;
    }
    let [(c1, m1), (c2, m2)] = cast_order(p, bodies, colliders, t0);
    report.casts += 1;
    match caster.cast(c1, &m1, c2, &m2, t0, dt, false) {
        CastOutcome::Hit(t) if t < dt => {
            report.hits += 1;
            t.max(t0)
        }
        CastOutcome::Capped(t) if t < dt => {
            report.out_of_iterations += 1;
            t.max(t0)
        }
        CastOutcome::Unsupported => {
            report.unsupported += 1;
            f64::INFINITY
        }
        _ => f64::INFINITY,
    }
}

/// The first time the bodies of the sensor pair `p` overlap on the motions the pass left them
/// (each on its path until it stops, then still), if any: over [0, the earlier stop] both
/// move, then the other alone.
pub fn sensor_crossing<C: PairCast>(
    p: &PassPair,
    bodies: &[PassBody],
    colliders: &[PassCollider],
    caster: &mut C,
    report: &mut MovingPairsReport,
) -> Option<f64> {
    let stop = |c: u32| bodies[colliders[c as usize].body as usize].stop;
    let (first, last) = (stop(p.a).min(stop(p.b)), stop(p.a).max(stop(p.b)));
    for (t0, t1) in [(0.0, first), (first, last)] {
        if t1 <= t0 {
            continue;
        }
        let [(c1, m1), (c2, m2)] = cast_order(p, bodies, colliders, t0);
        report.casts += 1;
        match caster.cast(c1, &m1, c2, &m2, t0, t1, true) {
            CastOutcome::Hit(t) | CastOutcome::Capped(t) => return Some(t),
            CastOutcome::Unsupported => {
                report.unsupported += 1;
                return None;
            }
            CastOutcome::Miss => {}
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::super::path::StepPath;
    use super::*;
    use crate::numerics::math::{Pose, Vector};

    /// Discs of radius 1 on straight paths (exact closed-form casts), for the loop's logic.
    struct Discs;

    impl PairCast for Discs {
        fn cast(
            &mut self,
            _: u32,
            m1: &NonlinearRigidMotion,
            _: u32,
            m2: &NonlinearRigidMotion,
            t0: f64,
            t1: f64,
            _: bool,
        ) -> CastOutcome {
            // |d + v t| = 2, first root at or after t0.
            let (x1, x2) = (m1.start.translation, m2.start.translation);
            let (d, v) = (x2 - x1, m2.linvel - m1.linvel);
            let (a, b, c) = (v.dot(v), 2.0 * d.dot(v), d.dot(d) - 4.0);
            let disc = b * b - 4.0 * a * c;
            if a == 0.0 || disc < 0.0 {
                return CastOutcome::Miss;
            }
            let t = (-b - disc.sqrt()) / (2.0 * a);
            if t >= t0 && t <= t1 {
                CastOutcome::Hit(t)
            } else {
                CastOutcome::Miss
            }
        }
    }

    fn body(x0: f64, x1: f64) -> PassBody {
        let path = StepPath::new(
            &Pose::translation(x0, 0.0),
            &Pose::translation(x1, 0.0),
            Vector::ZERO,
            Vector::new(x1 - x0, 0.0),
            0.0,
            1.0,
        )
        .unwrap();
        PassBody::new(path, true, true, 1.0)
    }

    /// Three discs on a line: the middle one stopped by the first contact (with the left one),
    /// the right one, which would have met the middle one's path later, then stops against its
    /// new pose — found only by the recheck of step 3.
    #[test]
    fn a_stopped_body_is_met_on_its_stopped_pose() {
        let mut bodies = vec![body(-10.0, 10.0), body(0.0, 0.5), body(4.0, 2.0)];
        let colliders: Vec<PassCollider> = (0..3)
            .map(|i| PassCollider::new(i, &bodies[i as usize], Pose::IDENTITY, 1.0, false))
            .collect();
        let mut pairs = vec![PassPair::new(0, 1), PassPair::new(0, 2), PassPair::new(1, 2)];
        let mut report = MovingPairsReport::default();
        Schedule::default().run(&mut bodies, &colliders, &mut pairs, &mut Discs, &mut report);
        // Left meets middle when −10 + 20t + 2 = 0.5t: t = 8/19.5.
        let t01 = 8.0 / 19.5;
        assert!((bodies[0].stop - t01).abs() < 1e-12 && (bodies[1].stop - t01).abs() < 1e-12);
        // Right (4 − 2t) meets the middle stopped at 0.5·t01 when 4 − 2t − 0.5·t01 = 2.
        let t2 = (2.0 - 0.5 * t01) / 2.0;
        assert!((bodies[2].stop - t2).abs() < 1e-12, "{}", bodies[2].stop);
        assert_eq!(report.stopped_bodies, 3);
        assert_eq!(report.status, PassStatus::Done);
    }

    /// Bodies that never meet are not stopped.
    #[test]
    fn apart_bodies_are_left_alone() {
        let mut bodies = vec![body(-10.0, -5.0), body(10.0, 5.0)];
        let colliders: Vec<PassCollider> = (0..2)
            .map(|i| PassCollider::new(i, &bodies[i as usize], Pose::IDENTITY, 1.0, false))
            .collect();
        let mut pairs = vec![PassPair::new(0, 1)];
        let mut report = MovingPairsReport::default();
        Schedule::default().run(&mut bodies, &colliders, &mut pairs, &mut Discs, &mut report);
        assert!(!bodies[0].stopped() && !bodies[1].stopped());
        assert_eq!((report.casts, report.hits, report.stopped_bodies), (1, 0, 0));
    }
}
