//! Issue 32, "Hostile input": the nine broken promises a hostile-input pass found, each pinned
//! by the reproduction it was found with, run under a time limit of one second per call (a
//! regression that hangs fails instead of stalling the suite), and the checks of a user's
//! curve at [`CustomCurve::try_new`] (one broken part of the contract at a time, each refused
//! naming its method).
//!
//! And the fuzz over the same kinds of input, `hostile_fuzz_of_every_query_keeps_its_promises`
//! (the hostile batch of `tests/reliability/hostile.rs`: user curves breaking each part of the
//! contract, polygons of 10⁵ vertices, poses far from the origin, extreme motions), every query
//! through the fuzz's checks of `crates/dev/tests/adversarial.rs` (`reliability::run_case`, with its limit
//! per call). f32 sizes are in `crates/smooth-ccd2d-f32/tests/f32_sizes.rs`.
//!
//! The reproductions sit in three modules: `user_curves` (a user's curve breaking its contract,
//! and the checks that refuse it), `far_and_fast` (far poses, extreme speeds and time scales) and
//! `odd_shapes` (10⁵ vertices, balls of no size, needle arcs, flat triangles, non-finite poses).
//!
//! Run with `cargo test --test hostile_input -- --nocapture` to see the counts.

mod common;
#[path = "hostile_input/far_and_fast.rs"]
mod far_and_fast;
#[path = "hostile_input/odd_shapes.rs"]
mod odd_shapes;
mod reliability;
#[path = "hostile_input/user_curves.rs"]
mod user_curves;

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{
    ClosestPoints, ContactManifold, NonlinearRigidMotion, PersistentQueryDispatcher, QueryDispatcher, Ray, RayCast,
    ShapeCastHit, Unsupported,
};
use parry2d_f64::shape::{Ball, Capsule, Compound, Cuboid, HalfSpace, Shape, SharedShape, Triangle};
use smooth_ccd2d::{
    shape_time_of_impact, stationary_distance, time_of_impact, time_of_impact_halfspace, CapsuleEllipse, ConvexCurve,
    CurvePoint, CustomCurve, DistanceOptions, Ellipse, QuadratureStatus, RoundedPolygon, ShapeError, SmoothDispatcher,
    SupportJet, ToiOptions, ToiStatus, MAX_VERTICES,
};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// The time limit of one call.
const CALL_LIMIT: Duration = Duration::from_secs(1);

/// `f()` run on its own thread, or a failure naming `what` when it takes longer than
/// [`CALL_LIMIT`] (the thread is left behind: a hang fails the test instead of stalling it).
fn within<T: Send + 'static>(what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    let start = Instant::now();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    match rx.recv_timeout(CALL_LIMIT) {
        Ok(v) => v,
        Err(_) => panic!("{what}: no answer after {:?}", start.elapsed()),
    }
}

// ---------------------------------------------------------------------------------------------
// The hostile fuzz
// ---------------------------------------------------------------------------------------------

/// Cases of the hostile batch (a quarter of each class; about 9 s at opt-level 3, the polygons
/// of 10⁵ vertices taking most of it).
const HOSTILE_CASES: u64 = 400;
/// A case (every query of it, and the comparison) running longer than this is a hang.
const CASE_LIMIT: Duration = Duration::from_secs(30);

/// The hostile batch of `reliability::hostile` — user curves breaking each part of the contract
/// (refused naming the method when the checks can see the lie, queried when they cannot),
/// polygons of 10⁵ vertices, poses 1e4 … 1e15 from the origin (the same answers as at the origin,
/// half-spaces included), time scaled by 2^−1000 … 2^1000 (the same answers in scaled time) —
/// every query of each case through `reliability::run_case` (no panic, no NaN, the documented
/// errors, each call within `reliability::CALL_LIMIT`), each case on its own thread under
/// [`CASE_LIMIT`]. Prints its counts (`HOSTILE_SEED`, `HOSTILE_CASES` explore others).
#[test]
fn hostile_fuzz_of_every_query_keeps_its_promises() {
    use reliability::hostile::{compare, hostile, Expect, HOSTILE_CLASSES};
    let env = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<u64>().ok());
    let (seed, n) = (
        env("HOSTILE_SEED").unwrap_or(0x0007_5EED),
        env("HOSTILE_CASES").unwrap_or(HOSTILE_CASES),
    );
    let start = Instant::now();
    let mut failures: Vec<(u64, Vec<String>)> = Vec::new();
    let mut per_class: BTreeMap<&str, (usize, Duration)> = BTreeMap::new();
    let mut refused: BTreeMap<&str, usize> = BTreeMap::new();
    let (mut far, mut scaled, mut slowest) = (0usize, 0usize, (Duration::ZERO, "", 0u64));
    for i in 0..n {
        let (case, expect) = hostile(seed, i);
        let t = Instant::now();
        let (c, e) = (case.clone(), expect.clone());
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                let mut out = reliability::run_case(&c);
                out.violations.extend(compare(&c, &e));
                out
            }));
            let _ = tx.send(run.map_err(|_| ()));
        });
        let out = match rx.recv_timeout(CASE_LIMIT) {
            Ok(Ok(out)) => out,
            Ok(Err(())) => {
                failures.push((i, vec!["PANIC".into()]));
                continue;
            }
            Err(_) => panic!("HANG: case {i} still running after {CASE_LIMIT:?}"),
        };
        let dt = t.elapsed();
        let e = per_class.entry(case.class).or_insert((0, Duration::ZERO));
        e.0 += 1;
        e.1 = e.1.max(dt);
        if out.slowest.0 > slowest.0 {
            slowest = (out.slowest.0, out.slowest.1, i);
        }
        match &expect {
            Expect::Refused(m) => *refused.entry(m).or_default() += 1,
            Expect::SameAs(_) => far += 1,
            Expect::Scaled(..) => scaled += 1,
            Expect::Nothing | Expect::Documented => {}
        }
        if !out.violations.is_empty() {
            failures.push((i, out.violations));
        }
    }
    println!(
        "hostile fuzz: {n} cases (seed {seed:#x}) in {:.1} s; slowest call {:.1} ms ({}, case {})",
        start.elapsed().as_secs_f64(),
        slowest.0.as_secs_f64() * 1e3,
        slowest.1,
        slowest.2
    );
    for class in HOSTILE_CLASSES {
        let (k, w) = per_class.get(class).copied().unwrap_or_default();
        println!(
            "  class {class:<15} {k:>5} cases, worst case {:>8.1} ms",
            w.as_secs_f64() * 1e3
        );
    }
    let refusals: Vec<String> = refused.iter().map(|(k, v)| format!("{k} {v}")).collect();
    println!("  lies refused at wrapping, by method: {}", refusals.join(", "));
    println!("  answers compared: far poses against the origin {far}, scaled time against unscaled {scaled}");
    println!("  cases with a broken promise: {}", failures.len());
    for (i, v) in failures.iter().take(15) {
        let (case, _) = hostile(seed, *i);
        println!("  FAIL {}\n      {}", reliability::describe(&case), v.join("\n      "));
    }
    assert!(
        failures.is_empty(),
        "{} of {n} hostile cases broke a promise",
        failures.len()
    );
}
