//! The pile with its narrow phase made almost free: a run records every `contact_manifolds`
//! answer of this crate's dispatcher, in call order; a second run of the same (deterministic)
//! pile hands the recorded manifolds back instead of computing them. What the replayed run still
//! costs per step is rapier's own work on these manifolds (its narrow-phase bookkeeping, the
//! solver, the broad phase, the islands), so the replayed step bounds what any dispatcher could
//! reach on this pile's physics.

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

/// Every `contact_manifolds` answer of a run, in call order.
type Recording = Vec<Vec<ContactManifold>>;

/// The dispatcher of a recording run ([`SmoothDispatcher`], its manifolds logged after each
/// call) or of a replay (the logged manifolds handed back in order).
pub struct Replay {
    inner: SmoothDispatcher,
    log: Arc<Mutex<Recording>>,
    /// `Some` in a replay: the recording, read from the call counter on.
    replay: Option<Arc<Recording>>,
    next: AtomicUsize,
}

impl Replay {
    /// A recording dispatcher writing into `log`.
    pub fn recorder(log: &Arc<Mutex<Recording>>) -> Self {
        Self {
            inner: SmoothDispatcher::default(),
            log: Arc::clone(log),
            replay: None,
            next: AtomicUsize::new(0),
        }
    }

    /// A dispatcher handing back `recording`'s manifolds in order.
    pub fn player(recording: &Arc<Recording>) -> Self {
        Self {
            inner: SmoothDispatcher::default(),
            log: Arc::default(),
            replay: Some(Arc::clone(recording)),
            next: AtomicUsize::new(0),
        }
    }
}

/// Only `contact_manifolds` is answered: the pile's rapier world asks nothing else of its
/// narrow phase (no CCD, no intersection pairs).
impl QueryDispatcher for Replay {
    fn intersection_test(&self, _: &Pose, _: &dyn Shape, _: &dyn Shape) -> Result<ShapeIntersection, Unsupported> {
        Err(Unsupported)
    }
    fn distance(&self, _: &Pose, _: &dyn Shape, _: &dyn Shape) -> Result<ShapeDistance, Unsupported> {
        Err(Unsupported)
    }
    fn contact(&self, _: &Pose, _: &dyn Shape, _: &dyn Shape, _: Real) -> Result<Option<Contact>, Unsupported> {
        Err(Unsupported)
    }
    fn closest_points(&self, _: &Pose, _: &dyn Shape, _: &dyn Shape, _: Real) -> Result<ClosestPoints, Unsupported> {
        Err(Unsupported)
    }
    fn cast_shapes(
        &self,
        _: &Pose,
        _: Vector,
        _: &dyn Shape,
        _: &dyn Shape,
        _: ShapeCastOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        Err(Unsupported)
    }
    fn cast_shapes_nonlinear(
        &self,
        _: &NonlinearRigidMotion,
        _: &dyn Shape,
        _: &NonlinearRigidMotion,
        _: &dyn Shape,
        _: Real,
        _: Real,
        _: bool,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        Err(Unsupported)
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
                .push(manifolds.clone());
            return answer;
        };
        let k = self.next.fetch_add(1, Ordering::Relaxed);
        let Some(recorded) = recording.get(k) else {
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
        _: &Pose,
        _: &dyn Shape,
        _: &dyn Shape,
        _: Option<&dyn parry2d_f64::query::details::NormalConstraints>,
        _: Option<&dyn parry2d_f64::query::details::NormalConstraints>,
        _: Real,
        _: &mut ContactManifold,
    ) -> Result<(), Unsupported> {
        Err(Unsupported)
    }
}

/// Mean step seconds over `steps` steps of the exact pile (contact recycling on or off) with the
/// manifolds of a recorded run of this crate's dispatcher handed back (the best of `runs`
/// replays), and whether every replay ended in the recording's state, bit for bit.
pub fn replayed_pile(recycling: bool, steps: usize, runs: usize) -> (f64, bool) {
    use std::time::Instant;
    let log = Arc::new(Mutex::new(Recording::new()));
    let mut pile = Pile::on(Replay::recorder(&log), recycling);
    for _ in 0..steps {
        pile.step();
    }
    let end_state = state_hash(pile.world(), &pile.bodies()).0;
    let recording = Arc::new(std::mem::take(&mut *log.lock().unwrap_or_else(|e| e.into_inner())));
    let (mut best, mut same) = (f64::INFINITY, true);
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
