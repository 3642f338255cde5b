//! The pile with its dispatcher made almost free: a run records every `contact_manifolds` and
//! `cast_shapes_nonlinear` answer of this crate's dispatcher (rapier's narrow phase and its CCD,
//! which sweeps the pile's fast bodies whether or not their CCD flag is set), in call order; later
//! runs of the same (deterministic) pile hand the recorded answers back instead of computing
//! them. What a replayed run still costs per step is rapier's own work (its narrow-phase
//! bookkeeping, the solver, the broad phase, the islands), so the replayed step bounds what any
//! dispatcher could reach on this pile's physics.

use super::pile::Pile;
use super::world::state_hash;
use parry2d_f64::math::{Pose, Real, Vector};
use parry2d_f64::query::{
    ClosestPoints, Contact, ContactManifoldsWorkspace, NonlinearRigidMotion, PersistentQueryDispatcher,
    QueryDispatcher, ShapeCastHit, ShapeCastOptions, ShapeDistance, ShapeIntersection, Unsupported,
};
use parry2d_f64::shape::Shape;
use rapier2d_f64::geometry::{ContactData, ContactManifold, ContactManifoldData};
use smooth_ccd2d::SmoothDispatcher;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// The answers of a run, each kind in call order.
#[derive(Default)]
pub struct Recording {
    manifolds: Vec<Vec<ContactManifold>>,
    casts: Vec<Result<Option<ShapeCastHit>, Unsupported>>,
}

/// The dispatcher of a recording run ([`SmoothDispatcher`], its manifolds and nonlinear casts
/// logged after each call) or of a replay (the logged answers handed back in order).
pub struct Replay {
    inner: SmoothDispatcher,
    log: Arc<Mutex<Recording>>,
    /// `Some` in a replay: the recording, read from the call counters on.
    replay: Option<Arc<Recording>>,
    next: AtomicUsize,
    next_cast: AtomicUsize,
}

impl Replay {
    /// A recording dispatcher writing into `log`.
    pub fn recorder(log: &Arc<Mutex<Recording>>) -> Self {
        Self {
            inner: SmoothDispatcher::default(),
            log: Arc::clone(log),
            replay: None,
            next: AtomicUsize::new(0),
            next_cast: AtomicUsize::new(0),
        }
    }

    /// A dispatcher handing back `recording`'s manifolds and casts in order.
    pub fn player(recording: &Arc<Recording>) -> Self {
        Self {
            inner: SmoothDispatcher::default(),
            log: Arc::default(),
            replay: Some(Arc::clone(recording)),
            next: AtomicUsize::new(0),
            next_cast: AtomicUsize::new(0),
        }
    }
}

/// Every query but the manifolds and the nonlinear casts is [`SmoothDispatcher`]'s, computed in
/// the replay too (the pile asks none).
impl QueryDispatcher for Replay {
    fn intersection_test(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeIntersection, Unsupported> {
        self.inner.intersection_test(pos12, g1, g2)
    }
    fn distance(&self, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> Result<ShapeDistance, Unsupported> {
        self.inner.distance(pos12, g1, g2)
    }
    fn contact(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
    ) -> Result<Option<Contact>, Unsupported> {
        self.inner.contact(pos12, g1, g2, prediction)
    }
    fn closest_points(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        max_dist: Real,
    ) -> Result<ClosestPoints, Unsupported> {
        self.inner.closest_points(pos12, g1, g2, max_dist)
    }
    fn cast_shapes(
        &self,
        pos12: &Pose,
        vel12: Vector,
        g1: &dyn Shape,
        g2: &dyn Shape,
        options: ShapeCastOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        self.inner.cast_shapes(pos12, vel12, g1, g2, options)
    }
    fn cast_shapes_nonlinear(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let Some(recording) = &self.replay else {
            let answer =
                self.inner
                    .cast_shapes_nonlinear(motion1, g1, motion2, g2, start_time, end_time, stop_at_penetration);
            self.log.lock().unwrap_or_else(|e| e.into_inner()).casts.push(answer);
            return answer;
        };
        let k = self.next_cast.fetch_add(1, Ordering::Relaxed);
        recording.casts.get(k).copied().unwrap_or(Err(Unsupported))
    }
}

impl PersistentQueryDispatcher<ContactManifoldData, ContactData> for Replay {
    fn contact_manifolds(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
        manifolds: &mut Vec<ContactManifold>,
        workspace: &mut Option<ContactManifoldsWorkspace>,
    ) -> Result<(), Unsupported> {
        let Some(recording) = &self.replay else {
            let answer = self
                .inner
                .contact_manifolds(pos12, g1, g2, prediction, manifolds, workspace);
            self.log
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .manifolds
                .push(manifolds.clone());
            return answer;
        };
        let k = self.next.fetch_add(1, Ordering::Relaxed);
        let Some(recorded) = recording.manifolds.get(k) else {
            return Err(Unsupported);
        };
        // The same call of the same run: the manifolds' rapier data are already the recorded
        // ones, only the geometry is copied (no allocation once a manifold has its points; the
        // pile's shapes are all convex, so no sub-shape poses).
        manifolds.truncate(recorded.len());
        for (k, r) in recorded.iter().enumerate() {
            match manifolds.get_mut(k) {
                Some(m) => {
                    m.points.clone_from(&r.points);
                    m.local_n1 = r.local_n1;
                    m.local_n2 = r.local_n2;
                    m.subshape1 = r.subshape1;
                    m.subshape2 = r.subshape2;
                }
                None => manifolds.push(r.clone()),
            }
        }
        Ok(())
    }

    fn contact_manifold_convex_convex(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        normal_constraints1: Option<&dyn parry2d_f64::query::details::NormalConstraints>,
        normal_constraints2: Option<&dyn parry2d_f64::query::details::NormalConstraints>,
        prediction: Real,
        manifold: &mut ContactManifold,
    ) -> Result<(), Unsupported> {
        // rapier asks for whole pairs (`contact_manifolds`); a direct call is computed.
        self.inner.contact_manifold_convex_convex(
            pos12,
            g1,
            g2,
            normal_constraints1,
            normal_constraints2,
            prediction,
            manifold,
        )
    }
}

/// Mean step seconds over `steps` steps of the exact pile (contact recycling on or off) with the
/// manifolds and casts of a recorded run of this crate's dispatcher handed back (the best of `runs`
/// replays), and whether the recording and every replay ended in the state of a run with
/// [`SmoothDispatcher`] alone, bit for bit.
pub fn replayed_pile(recycling: bool, steps: usize, runs: usize) -> (f64, bool) {
    use std::time::Instant;
    let log = Arc::new(Mutex::new(Recording::default()));
    let mut pile = Pile::on(Replay::recorder(&log), recycling);
    for _ in 0..steps {
        pile.step();
    }
    let end_state = state_hash(pile.world(), &pile.bodies()).0;
    let mut plain = Pile::on(SmoothDispatcher::default(), recycling);
    for _ in 0..steps {
        plain.step();
    }
    let mut same = state_hash(plain.world(), &plain.bodies()).0 == end_state;
    let recording = Arc::new(std::mem::take(&mut *log.lock().unwrap_or_else(|e| e.into_inner())));
    println!(
        "(recorded: {} manifold calls, {} casts)",
        recording.manifolds.len(),
        recording.casts.len()
    );
    let mut best = f64::INFINITY;
    for _ in 0..runs {
        let mut pile = Pile::on(Replay::player(&recording), recycling);
        let start = Instant::now();
        for _ in 0..steps {
            pile.step();
        }
        best = best.min(start.elapsed().as_secs_f64() / steps as f64);
        same &= state_hash(pile.world(), &pile.bodies()).0 == end_state;
    }
    (best, same)
}
