//! Threads and determinism (issue 7).
//!
//! * The dispatcher, the shapes and the results are `Send + Sync` (checked at compile time).
//! * The same batch of queries (every query of the crate on the cases of
//!   `tests/reliability`) gives bit-identical answers run twice on one thread and run from
//!   several threads at once, in another order; one dispatcher and one set of shapes shared by
//!   threads answer as on one thread.
//!
//! rapier's `parallel` pipeline with the dispatcher on 1, 2 and 4 workers is tested by the
//! workspace's test-only package `crates/parallel-tests` (its own dev-dependency enables rapier's
//! `parallel` feature, which this package's benches and examples do not build).
//!
//! Run with `cargo test --test threads -- --nocapture` to see the digests.

mod common;
mod reliability;

use parry2d_f64::query::{NonlinearRigidMotion, QueryDispatcher};
use parry2d_f64::shape::{Ball, Cuboid, SharedShape};
use rapier2d_f64::prelude::*;
use reliability::{generate, run_case};
use smooth_ccd2d::{
    BallCurve, CapsuleEllipse, CustomCurve, DistanceOptions, Ellipse, RoundedPolygon, SmoothDispatcher,
    StationaryDistance, TimeOfImpact, ToiOptions,
};

/// Compile-time: everything a user shares between threads is `Send + Sync`.
const _: () = {
    const fn send_sync<T: Send + Sync>() {}
    send_sync::<SmoothDispatcher>();
    send_sync::<Ellipse>();
    send_sync::<RoundedPolygon>();
    send_sync::<CapsuleEllipse>();
    send_sync::<CustomCurve>();
    send_sync::<BallCurve>();
    send_sync::<StationaryDistance>();
    send_sync::<TimeOfImpact>();
    send_sync::<DistanceOptions>();
    send_sync::<ToiOptions>();
    send_sync::<smooth_ccd2d::QueryError>();
    send_sync::<smooth_ccd2d::ShapeError>();
};

#[test]
fn dispatcher_and_shapes_are_send_and_sync() {
    fn check<T: Send + Sync + 'static>() {}
    check::<SmoothDispatcher>();
    check::<Ellipse>();
    check::<RoundedPolygon>();
    check::<CapsuleEllipse>();
    check::<CustomCurve>();
    check::<BallCurve>();
    // As rapier holds them: a shared shape and a dispatcher behind the narrow phase.
    check::<SharedShape>();
    check::<NarrowPhase>();
}

const SEED: u64 = 0x7EAD_5EED;
const BATCH: u64 = 3000;
const THREADS: usize = 4;

/// Digests of every case of the batch, on one thread.
fn batch_digests() -> Vec<u64> {
    (0..BATCH).map(|i| run_case(&generate(SEED, i)).digest).collect()
}

#[test]
fn queries_are_bit_identical_across_runs_and_threads() {
    let reference = batch_digests();
    let again = batch_digests();
    assert_eq!(reference, again, "the same queries on one thread twice differ");
    // THREADS threads at once, each taking every THREADS-th case, in reverse order.
    let mut from_threads = vec![0u64; BATCH as usize];
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..THREADS)
            .map(|k| {
                scope.spawn(move || {
                    (0..BATCH)
                        .rev()
                        .filter(|i| *i as usize % THREADS == k)
                        .map(|i| (i, run_case(&generate(SEED, i)).digest))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        for h in handles {
            for (i, d) in h.join().expect("a query thread panicked") {
                from_threads[i as usize] = d;
            }
        }
    });
    let same = reference.iter().zip(&from_threads).filter(|(a, b)| a == b).count();
    println!(
        "threads: {BATCH} cases × every query: run twice on one thread bit-identical; on {THREADS} threads {same}/{BATCH} bit-identical"
    );
    assert_eq!(reference, from_threads);
}

/// One `SmoothDispatcher` and one set of shapes (`SharedShape`, an `Arc`) used by several threads
/// at once answer bit for bit as on one thread.
#[test]
fn one_dispatcher_and_shapes_shared_by_threads_answer_as_one_thread() {
    let dispatcher = SmoothDispatcher::default();
    let shapes = [
        SharedShape::new(Ellipse::new(0.5, 0.2)),
        SharedShape::new(RoundedPolygon::regular(6, 0.4, 0.05)),
        SharedShape::new(CapsuleEllipse::new(0.2, 0.3, 0.4)),
        SharedShape::new(CustomCurve::new(Ellipse::new(0.3, 0.6))),
        SharedShape::new(Ball::new(0.25)),
        SharedShape::new(Cuboid::new(parry2d_f64::math::Vector::new(0.3, 0.2))),
    ];
    let run = |d: &SmoothDispatcher| -> Vec<u64> {
        let mut bits = Vec::new();
        let mut rng = reliability::Rng::mixed(77);
        for _ in 0..400 {
            let (i, j) = (rng.int(0, shapes.len() - 1), rng.int(0, shapes.len() - 1));
            let (g1, g2) = (&*shapes[i], &*shapes[j]);
            let pos12 = parry2d_f64::math::Pose::new(rng.direction() * rng.uniform(0.2, 1.5), rng.angle());
            if let Ok(r) = d.distance(&pos12, g1, g2) {
                bits.push(r.distance.to_bits());
            }
            if let Ok(Some(c)) = d.contact(&pos12, g1, g2, 0.5) {
                bits.extend([c.dist, c.point1.x, c.point1.y, c.normal1.x, c.normal1.y].map(f64::to_bits));
            }
            let m1 = NonlinearRigidMotion::new(
                parry2d_f64::math::Pose::IDENTITY,
                parry2d_f64::math::Vector::ZERO,
                rng.direction() * 2.0,
                rng.uniform(-30.0, 30.0),
            );
            let m2 = NonlinearRigidMotion::constant_position(pos12);
            if let Ok(Some(h)) = d.cast_shapes_nonlinear(&m1, g1, &m2, g2, 0.0, 1.0, rng.chance(0.5)) {
                bits.extend([h.time_of_impact, h.witness1.x, h.witness1.y].map(f64::to_bits));
            }
        }
        bits
    };
    let one = run(&dispatcher);
    let results: Vec<Vec<u64>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..THREADS).map(|_| scope.spawn(|| run(&dispatcher))).collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("thread panicked"))
            .collect()
    });
    for r in &results {
        assert_eq!(&one, r);
    }
    println!(
        "shared dispatcher: {} answer words, identical on {THREADS} threads",
        one.len()
    );
}
