//! rapier's `parallel` pipeline with `SmoothDispatcher` (issue 7): the mixed pile of the root's
//! `tests/common/scenes.rs` stepped on thread pools of 1, 2 and 4 workers, against the same scene
//! run twice on one worker. The final states are hashed (FNV-1a over the bits of every body's
//! pose and velocities) and printed; a spy around the dispatcher counts the threads that call it.
//!
//! Run with `cargo test -p smooth-ccd2d-parallel-tests -- --nocapture` to see the hashes.

#[path = "../../../tests/common/mod.rs"]
mod common;

use common::scenes::{mixed_pile, MIXED_PILE_BODIES};
use common::watched::{Watched, Watcher};
use common::world::{state_hash, World, GRAVITY};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::SmoothDispatcher;
use std::collections::BTreeMap;
use std::collections::HashSet;
use std::sync::{Arc, Mutex};
use std::thread::ThreadId;

/// The threads that call the watched dispatcher (to show that rapier's parallel narrow phase
/// and CCD really call `SmoothDispatcher` from several threads at once).
struct Threads(Arc<Mutex<HashSet<ThreadId>>>);

impl Watcher for Threads {
    fn query(&self) {
        self.0.lock().unwrap().insert(std::thread::current().id());
    }
}

struct Scene {
    world: World,
    handles: Vec<RigidBodyHandle>,
    threads: Arc<Mutex<HashSet<ThreadId>>>,
}

impl Scene {
    /// [`mixed_pile`] with `SmoothDispatcher` (behind a spy) as the narrow phase, on
    /// `threads` workers.
    fn new(threads: usize) -> Self {
        let seen = Arc::new(Mutex::new(HashSet::new()));
        let spy = Watched {
            inner: SmoothDispatcher::default(),
            watcher: Threads(seen.clone()),
        };
        let mut world = World::new(NarrowPhase::with_query_dispatcher(spy));
        world.pipeline.configure_thread_pool(threads).expect("thread pool");
        let handles = mixed_pile(&mut world);
        Scene {
            world,
            handles,
            threads: seen,
        }
    }

    fn step(&mut self) {
        self.world.step(GRAVITY, &());
    }

    /// FNV-1a over the bits of every body's pose and velocities, and those numbers.
    fn state(&self) -> (u64, Vec<[f64; 7]>) {
        state_hash(&self.world, &self.handles)
    }
}

/// The final state's hash and words, and how many threads called the dispatcher.
fn run_scene(threads: usize, steps: usize) -> (u64, Vec<[f64; 7]>, usize) {
    let mut s = Scene::new(threads);
    for _ in 0..steps {
        s.step();
    }
    let (hash, words) = s.state();
    let callers = s.threads.lock().unwrap().len();
    (hash, words, callers)
}

fn max_position_gap(a: &[[f64; 7]], b: &[[f64; 7]]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| ((x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2)).sqrt())
        .fold(0.0, f64::max)
}

/// rapier's `parallel` pipeline with `SmoothDispatcher`: the same scene on 1, 2 and 4 workers.
#[test]
fn rapier_parallel_pipeline_with_the_smooth_dispatcher() {
    const STEPS: usize = 250;
    let mut hashes: BTreeMap<String, u64> = BTreeMap::new();
    let (one_a, state1, callers1) = run_scene(1, STEPS);
    let (one_b, _, _) = run_scene(1, STEPS);
    hashes.insert("1 worker, run 1".into(), one_a);
    hashes.insert("1 worker, run 2".into(), one_b);
    let mut gaps = Vec::new();
    for n in [2, 4] {
        let (a, sa, callers) = run_scene(n, STEPS);
        let (b, _, _) = run_scene(n, STEPS);
        hashes.insert(format!("{n} workers, run 1"), a);
        hashes.insert(format!("{n} workers, run 2"), b);
        gaps.push((n, a == one_a, a == b, max_position_gap(&state1, &sa), callers));
    }
    println!(
        "rapier parallel, {STEPS} steps, {} bodies, final-state hashes (1 worker: the dispatcher called from {callers1} thread):",
        MIXED_PILE_BODIES + 3
    );
    for (k, v) in &hashes {
        println!("  {k}: {v:016x}");
    }
    for (n, same_as_one, same_twice, gap, callers) in &gaps {
        println!(
            "  {n} workers: dispatcher called from {callers} threads; identical to 1 worker: {same_as_one}; identical run twice: {same_twice}; largest position gap to 1 worker {gap:.3e}"
        );
    }
    // What holds (README, Limits): one worker is deterministic; more workers are compared with it.
    assert_eq!(one_a, one_b, "one worker twice differs");
    for (n, same_as_one, _, _, _) in &gaps {
        assert!(same_as_one, "{n} workers differ from one worker");
    }
    // rayon may run every task of a 2-worker pool on one thread when the machine is busy (the
    // other tests of this file run beside this one); across the pools, more than one must call.
    assert!(
        gaps.iter().any(|g| g.4 > 1),
        "the dispatcher was never called from more than one thread"
    );
}

/// The moving-pairs pass in rapier's parallel pipeline: the closed box of
/// `tests/moving_pairs.rs` on 1 and 2 workers gives the bits recorded there (rapier without its
/// `parallel` feature), so the pass is deterministic across the feature and the workers.
#[test]
fn the_moving_pairs_box_gives_the_same_bits_on_the_parallel_pipeline() {
    use common::moving_scenes::{pass_options, run_box_with};
    /// `MOVING_BOX_STATE` of `tests/moving_pairs.rs` (re-recorded with it: 0x5D6D_7629_28D5_B33F
    /// before a user's curve's default normal search took Newton's steps, 0x8FD4_1313_E65A_719E
    /// before a user's curve's manifolds got core contacts, 0x742D_69D8_E573_0169
    /// before rule 3's core time took its closed form, 0x3E34_D514_B540_7A8D
    /// before rapier's casts apart at the start began from the target's face normal,
    /// 0xF3F6_02C6_477A_25F5 before `MovingPairsOptions::fixed_targets` swept the spun bodies
    /// against the walls, 0x7050_0CD2_101B_AE60 before the pass measured a start contact with a
    /// fixed wall on the translation alone, 0x193D_948B_7B79_EA1C before a core contact acted
    /// only where both its bodies are).
    const MOVING_BOX_STATE: u64 = 0x20BC_590B_46F7_0E65;
    for workers in [1, 2] {
        let pool = |w: &mut World| w.pipeline.configure_thread_pool(workers).expect("thread pool");
        let hash = run_box_with(150, Some(pass_options()), true, &pool).hash;
        println!("moving-pairs box, {workers} workers: {hash:016x}");
        assert_eq!(hash, MOVING_BOX_STATE, "{workers} workers");
    }
}
