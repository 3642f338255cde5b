//! The pile with its dispatcher made almost free: a run records every `contact_manifolds` and
//! `cast_shapes_nonlinear` answer of this crate's dispatcher (rapier's narrow phase and its CCD,
//! which sweeps the pile's fast bodies whether or not their CCD flag is set), in call order; later
//! runs of the same (deterministic) pile hand the recorded answers back instead of computing
//! them. What a replayed run still costs per step is rapier's own work (its narrow-phase
//! bookkeeping, the solver, the broad phase, the islands), so the replayed step bounds what any
//! dispatcher could reach on this pile's physics. A recording can also keep each manifold
//! call's inputs, to time the pile's calls again outside the simulation ([`pile_calls_table`]).

use super::pile::Pile;
use super::world::state_hash;
use parry2d_f64::math::{Pose, Real, Vector};
use parry2d_f64::query::{
    ClosestPoints, Contact, ContactManifoldsWorkspace, NonlinearRigidMotion, PersistentQueryDispatcher,
    QueryDispatcher, ShapeCastHit, ShapeCastOptions, ShapeDistance, ShapeIntersection, Unsupported,
};
use parry2d_f64::query::{ContactManifold as ParryManifold, TrackedContact};
use parry2d_f64::shape::Shape;
use rapier2d_f64::geometry::{ContactData, ContactManifold, ContactManifoldData};
use smooth_ccd2d::SmoothDispatcher;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// The answers of a run, each kind in call order, and (when asked) each manifold call's inputs.
#[derive(Default)]
pub struct Recording {
    manifolds: Vec<Vec<ContactManifold>>,
    casts: Vec<Result<Option<ShapeCastHit>, Unsupported>>,
    calls: Vec<Call>,
    shapes: Vec<Box<dyn Shape>>,
    addresses: Vec<usize>,
}

/// One `contact_manifolds` call's inputs: the shapes (indices into the recording's shapes,
/// each stored once), the pose, the prediction, the manifolds handed in (their geometry and ids,
/// without rapier's data) and the points the call returned.
pub struct Call {
    shapes: [usize; 2],
    pos12: Pose,
    prediction: Real,
    before: Vec<ParryManifold<(), ()>>,
    points_after: usize,
}

impl Recording {
    /// The index of `g` among the recorded shapes (stored on first sight).
    fn shape_index(&mut self, g: &dyn Shape) -> usize {
        let address = g as *const dyn Shape as *const u8 as usize;
        match self.addresses.iter().position(|a| *a == address) {
            Some(i) => i,
            None => {
                self.addresses.push(address);
                self.shapes.push(g.clone_dyn());
                self.shapes.len() - 1
            }
        }
    }
}

/// The geometry and ids of rapier's manifolds, without its data.
fn bare(manifolds: &[ContactManifold]) -> Vec<ParryManifold<(), ()>> {
    manifolds
        .iter()
        .map(|m| {
            let mut b = ParryManifold::<(), ()>::new();
            b.local_n1 = m.local_n1;
            b.local_n2 = m.local_n2;
            b.points = m
                .points
                .iter()
                .map(|p| TrackedContact::new(p.local_p1, p.local_p2, p.fid1, p.fid2, p.dist))
                .collect();
            b
        })
        .collect()
}

/// The dispatcher of a recording run ([`SmoothDispatcher`], its manifolds and nonlinear casts
/// logged after each call) or of a replay (the logged answers handed back in order).
pub struct Replay<D = SmoothDispatcher> {
    inner: D,
    log: Arc<Mutex<Recording>>,
    /// `Some` in a replay: the recording, read from the call counters on.
    replay: Option<Arc<Recording>>,
    next: AtomicUsize,
    next_cast: AtomicUsize,
    /// Whether a recording keeps each manifold call's inputs.
    inputs: bool,
}

impl Replay {
    /// A recording dispatcher writing into `log`.
    pub fn recorder(log: &Arc<Mutex<Recording>>) -> Self {
        Self::recorder_of(SmoothDispatcher::default(), log)
    }
}

impl<D> Replay<D> {
    /// A dispatcher recording `inner`'s answers into `log`.
    pub fn recorder_of(inner: D, log: &Arc<Mutex<Recording>>) -> Self {
        Self {
            inner,
            log: Arc::clone(log),
            replay: None,
            next: AtomicUsize::new(0),
            next_cast: AtomicUsize::new(0),
            inputs: false,
        }
    }

    /// A dispatcher recording `inner`'s answers and each manifold call's inputs into `log`.
    pub fn input_recorder(inner: D, log: &Arc<Mutex<Recording>>) -> Self {
        Self {
            inputs: true,
            ..Self::recorder_of(inner, log)
        }
    }
}

impl Replay {
    /// A dispatcher handing back `recording`'s manifolds and casts in order.
    pub fn player(recording: &Arc<Recording>) -> Self {
        Self {
            inner: SmoothDispatcher::default(),
            log: Arc::default(),
            replay: Some(Arc::clone(recording)),
            next: AtomicUsize::new(0),
            next_cast: AtomicUsize::new(0),
            inputs: false,
        }
    }
}

/// Every query but the manifolds and the nonlinear casts is the inner dispatcher's, computed in
/// the replay too (the pile asks none).
impl<D: QueryDispatcher> QueryDispatcher for Replay<D> {
    forward_plain_queries!(inner);

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

impl<D> PersistentQueryDispatcher<ContactManifoldData, ContactData> for Replay<D>
where
    D: PersistentQueryDispatcher<ContactManifoldData, ContactData>,
{
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
            let before = if self.inputs { bare(manifolds) } else { Vec::new() };
            let answer = self
                .inner
                .contact_manifolds(pos12, g1, g2, prediction, manifolds, workspace);
            let mut log = self.log.lock().unwrap_or_else(|e| e.into_inner());
            log.manifolds.push(manifolds.clone());
            if self.inputs {
                let shapes = [log.shape_index(g1), log.shape_index(g2)];
                log.calls.push(Call {
                    shapes,
                    pos12: *pos12,
                    prediction,
                    before,
                    points_after: manifolds.iter().map(|m| m.points.len()).sum(),
                });
            }
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

/// Each pile's `contact_manifolds` calls over its first `steps` steps (contact recycling on and
/// off; the exact pile with this crate's dispatcher, parry's stand-ins with parry's), recorded
/// with their inputs and timed again outside the simulation, by pair kind and by the number of
/// points the call returned: the calls' own cost, without the simulation around them or a clock
/// reading per call (each group run in call order, the best of 5 rounds; a round restores every
/// call's previous manifold first, which is timed apart and taken off)
/// (`cargo bench --bench ratios -- pile-calls`).
pub fn pile_calls_table(steps: usize) {
    println!("\n### The pile's calls, replayed\n");
    println!(
        "Each pile's `contact_manifolds` calls over its first {steps} steps, recorded with their inputs (shapes, pose, prediction, the previous manifold's points and normals) and run again outside the simulation with the same dispatcher, by pair kind and by the points the call returned (0: apart); per call, the best of 5 rounds in call order, the restoring of each previous manifold timed apart and taken off:\n"
    );
    println!("| contact recycling | narrow phase | pair kind | points | calls per step | µs per call | ms per step |");
    println!("|---|---|---|---:|---:|---:|---:|");
    let mut totals = Vec::new();
    for recycling in [true, false] {
        let ours = replayed_calls(SmoothDispatcher::default(), true, recycling, steps);
        let parry = replayed_calls(parry2d_f64::query::DefaultQueryDispatcher, false, recycling, steps);
        totals.push((recycling, ours, parry));
    }
    println!();
    for (recycling, ours, parry) in totals {
        println!(
            "Recycling {}: the dispatcher's calls take {:.4} ms per step with the exact shapes, {:.4} with parry's stand-ins: ratio {:.2}.",
            if recycling { "on" } else { "off" },
            ours * 1e3,
            parry * 1e3,
            parry / ours
        );
    }
}

/// The rows of [`pile_calls_table`] for one pile (`exact`: this crate's shapes) and dispatcher
/// `d`; returns the seconds per step of all its calls.
fn replayed_calls<D>(d: D, exact: bool, recycling: bool, steps: usize) -> f64
where
    D: PersistentQueryDispatcher<ContactManifoldData, ContactData>
        + PersistentQueryDispatcher<(), ()>
        + Clone
        + 'static,
{
    use super::pile::pair_kind;
    use std::collections::BTreeMap;
    use std::time::Instant;
    let log = Arc::new(Mutex::new(Recording::default()));
    let mut pile = Pile::on_shapes(Replay::input_recorder(d.clone(), &log), exact, recycling);
    for _ in 0..steps {
        pile.step();
    }
    let rec = std::mem::take(&mut *log.lock().unwrap_or_else(|e| e.into_inner()));
    let mut groups: BTreeMap<(String, usize), Vec<&Call>> = BTreeMap::new();
    for c in &rec.calls {
        let kind = pair_kind(&*rec.shapes[c.shapes[0]], &*rec.shapes[c.shapes[1]]);
        groups.entry((kind, c.points_after)).or_default().push(c);
    }
    let mut scratch: Vec<ParryManifold<(), ()>> = Vec::new();
    let mut time = |calls: &[&Call], solve: bool| {
        let mut best = f64::INFINITY;
        for _ in 0..5 {
            let start = Instant::now();
            for c in calls {
                scratch.clone_from(&c.before);
                if solve {
                    let (g1, g2) = (&*rec.shapes[c.shapes[0]], &*rec.shapes[c.shapes[1]]);
                    let _ = PersistentQueryDispatcher::<(), ()>::contact_manifolds(
                        &d,
                        &c.pos12,
                        g1,
                        g2,
                        c.prediction,
                        &mut scratch,
                        &mut None,
                    );
                }
                std::hint::black_box(&scratch);
            }
            best = best.min(start.elapsed().as_secs_f64());
        }
        best / calls.len().max(1) as f64
    };
    let on = if recycling { "on" } else { "off" };
    let label = if exact {
        "SmoothDispatcher, exact shapes"
    } else {
        "parry, polygon approximations"
    };
    for ((kind, points), calls) in &groups {
        let per_call = time(calls, true) - time(calls, false);
        println!(
            "| {on} | {label} | {kind} | {points} | {:.1} | {:.2} | {:.4} |",
            calls.len() as f64 / steps as f64,
            per_call * 1e6,
            per_call * calls.len() as f64 / steps as f64 * 1e3
        );
    }
    let all: Vec<&Call> = rec.calls.iter().collect();
    let per_call = time(&all, true) - time(&all, false);
    let per_step = per_call * all.len() as f64 / steps as f64;
    println!(
        "| {on} | {label} | **all**, in call order | | {:.1} | {:.2} | {:.4} |",
        all.len() as f64 / steps as f64,
        per_call * 1e6,
        per_step * 1e3
    );
    per_step
}
