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
//! And `contacts_on_parts_with_pseudo_normals_stay_finite_on_hostile_bodies`: the bodies of both
//! batches against an oriented polyline and a compound with fixed internal edges, where the
//! dispatcher re-derives a contact along the normal the parts' pseudo-normals turned.
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

// ---------------------------------------------------------------------------------------------
// Contacts on parts with pseudo-normals
// ---------------------------------------------------------------------------------------------

/// Bodies of the hostile and the ordinary batches (lying user curves, 10⁵-vertex polygons,
/// poses far from the origin, sizes 1e-6…1e6 and wild ones), each against an oriented polyline
/// zigzagging under it (convex and concave inner vertices) and a compound of three boxes with
/// fixed internal edges, at the case's scale and pose, both orders: parts whose pseudo-normals
/// move the contact normal, where the dispatcher re-derives the contact along it
/// (`dispatcher::constrained`). Every manifold `Ok` or `Unsupported`, its points and normals
/// finite, no panic, each case within [`CASE_LIMIT`]. Prints its counts.
#[test]
fn contacts_on_parts_with_pseudo_normals_stay_finite_on_hostile_bodies() {
    use parry2d_f64::shape::{CompoundFlags, Polyline, PolylineFlags};
    let (hostile_cases, ordinary_cases) = (200u64, 400u64);
    let (mut manifolds, mut points, mut failures) = (0usize, 0usize, Vec::new());
    let cases = (0..hostile_cases)
        .map(|i| reliability::hostile::hostile(0x5EED_C0DE, i).0)
        .chain((0..ordinary_cases).map(|i| reliability::generate(0x5EED_C0DE, i)));
    for case in cases {
        let Ok(body) = reliability::build(&case.s1) else {
            continue;
        };
        if body.halfspace.is_some() {
            continue;
        }
        let (s, pos12, prediction) = (case.scale, case.pos12, case.prediction);
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                // Vertices right to left (facing up), zigzag with convex and concave inner vertices.
                let zigzag: Vec<Vector> = (-4..=4)
                    .rev()
                    .map(|i| Vector::new(0.5 * s * i as f64, 0.1 * s * (i % 2) as f64 - s))
                    .collect();
                let chain = Polyline::with_flags(zigzag, None, PolylineFlags::ORIENTED);
                let boxes = Compound::with_flags(
                    (-1..=1)
                        .map(|i| {
                            (
                                Pose::translation(s * i as f64, -1.5 * s),
                                SharedShape::cuboid(0.5 * s, 0.5 * s),
                            )
                        })
                        .collect(),
                    CompoundFlags::FIX_INTERNAL_EDGES,
                    None,
                );
                let d = SmoothDispatcher::default();
                let mut found = (0usize, 0usize, Vec::new());
                for floor in [&chain as &dyn Shape, &boxes as &dyn Shape] {
                    for flip in [false, true] {
                        let mut ms: Vec<ContactManifold<(), ()>> = Vec::new();
                        let r = if flip {
                            d.contact_manifolds(&pos12.inverse(), &*body.shape, floor, prediction, &mut ms, &mut None)
                        } else {
                            d.contact_manifolds(&pos12, floor, &*body.shape, prediction, &mut ms, &mut None)
                        };
                        if let Err(e) = r {
                            let _: Unsupported = e;
                        }
                        for m in &ms {
                            found.0 += 1;
                            let finite_normal =
                                m.points.is_empty() || (m.local_n1.is_finite() && m.local_n2.is_finite());
                            if !finite_normal {
                                found.2.push(format!("normal {:?} {:?}", m.local_n1, m.local_n2));
                            }
                            for p in &m.points {
                                found.1 += 1;
                                if !(p.local_p1.is_finite() && p.local_p2.is_finite() && p.dist.is_finite()) {
                                    found.2.push(format!("point {p:?}"));
                                }
                            }
                        }
                    }
                }
                found
            }));
            let _ = tx.send(run.map_err(|_| ()));
        });
        match rx.recv_timeout(CASE_LIMIT) {
            Ok(Ok((m, p, bad))) => {
                manifolds += m;
                points += p;
                if !bad.is_empty() {
                    failures.push(format!("{}: {}", reliability::describe(&case), bad.join("; ")));
                }
            }
            Ok(Err(())) => failures.push(format!("PANIC {}", reliability::describe(&case))),
            Err(_) => panic!("HANG: {}", reliability::describe(&case)),
        }
    }
    println!(
        "pseudo-normal parts: {} cases, {manifolds} manifolds, {points} points, {} broken",
        hostile_cases + ordinary_cases,
        failures.len()
    );
    for f in failures.iter().take(10) {
        println!("  FAIL {f}");
    }
    assert!(failures.is_empty(), "{} cases broke a promise", failures.len());
}
