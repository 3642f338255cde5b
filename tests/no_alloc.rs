//! No heap allocation on the hot paths: a counting global allocator (this test binary only)
//! checks that `time_of_impact` and `stationary_distance` on the crate's curves allocate nothing
//! for pairs that start separated, that recomputing a contact manifold rapier keeps allocates
//! nothing, and prints what penetrating stationary distances and the dispatcher (with parry
//! shapes converted on every query) allocate.
//!
//! The counter is per thread, so the test harness's parallel tests do not disturb each other.

mod common;

use common::{generate, Scenario, ScenarioClass};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{NonlinearRigidMotion, QueryDispatcher};
use parry2d_f64::shape::{Ball, Cuboid, Shape};
use smooth_ccd2d::{
    shape_time_of_impact, stationary_distance, time_of_impact, BallCurve, DistanceOptions, DistanceStatus, Ellipse,
    QueryError, RoundedPolygon, SmoothDispatcher, StationaryDistance, ToiOptions,
};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
    static BYTES: Cell<usize> = const { Cell::new(0) };
}

fn record(size: usize) {
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
    let _ = BYTES.try_with(|c| c.set(c.get() + size));
}

// SAFETY: every call forwards to the system allocator with the same arguments; the counters are
// plain thread-local cells without destructors.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        record(layout.size());
        System.alloc(layout)
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        record(layout.size());
        System.alloc_zeroed(layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        record(new_size);
        System.realloc(ptr, layout, new_size)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations (count, bytes) made on this thread by `f`, and its result.
fn counted<R>(f: impl FnOnce() -> R) -> (R, usize, usize) {
    let (a0, b0) = (ALLOCATIONS.with(Cell::get), BYTES.with(Cell::get));
    let r = std::hint::black_box(f());
    let (a1, b1) = (ALLOCATIONS.with(Cell::get), BYTES.with(Cell::get));
    (r, a1 - a0, b1 - b0)
}

const SEEDS: u64 = 300;

fn pos12_at(s: &Scenario, t: f64) -> Pose {
    s.motion1.position_at_time(t).inverse() * s.motion2.position_at_time(t)
}

/// The stationary distance at the window start with the centres' offset scaled by `shrink`
/// (counted), the strictly convex shape as object2 (`stationary_distance` does not swap roles).
fn distance_at_start(
    s: &Scenario,
    dopts: &DistanceOptions,
    shrink: f64,
) -> (Result<StationaryDistance, QueryError>, usize, usize) {
    let mut pos12 = pos12_at(s, s.t0);
    pos12.translation *= shrink;
    if s.curve2().is_strictly_convex() {
        counted(|| stationary_distance(s.curve1(), s.curve2(), &pos12, dopts))
    } else {
        let pos21 = pos12.inverse();
        counted(|| stationary_distance(s.curve2(), s.curve1(), &pos21, dopts))
    }
}

/// Classes whose shapes are `Ellipse`, `RoundedPolygon` (rounded and sharp) and `BallCurve`, and
/// the Appendix A shape.
const CLASSES: [ScenarioClass; 6] = ScenarioClass::STRICTLY_CONVEX;

#[test]
fn separated_time_of_impact_and_distance_allocate_nothing() {
    let dopts = DistanceOptions::default();
    let mut failures = Vec::new();
    let mut queries = 0usize;
    for class in CLASSES {
        for seed in 0..SEEDS {
            let s = generate(class, seed);
            let topts = ToiOptions::default().with_target_distance(s.target);
            let (r, n, bytes) =
                counted(|| time_of_impact(s.curve1(), &s.motion1, s.curve2(), &s.motion2, s.t0, s.t1, &topts));
            assert!(r.is_ok(), "{}", s.describe());
            if n > 0 {
                failures.push(format!("time_of_impact: {n} allocations ({bytes} B): {}", s.describe()));
            }
            // The start is separated by construction.
            let (r, n, bytes) = distance_at_start(&s, &dopts, 1.0);
            let r = r.expect("valid pose");
            assert_eq!(r.status, DistanceStatus::Separated, "{}", s.describe());
            if n > 0 {
                failures.push(format!(
                    "stationary_distance: {n} allocations ({bytes} B): {}",
                    s.describe()
                ));
            }
            queries += 2;
        }
    }
    println!("{queries} separated queries, {} allocating", failures.len());
    assert!(
        failures.is_empty(),
        "allocations on separated queries:\n{}",
        failures.join("\n")
    );
}

/// The gap tracker (pairs with no strictly convex side) allocates nothing either, through
/// `shape_time_of_impact` on parry shapes converted on the stack and on this crate's shapes.
#[test]
fn pairs_with_no_strictly_convex_side_allocate_nothing() {
    let mut failures = Vec::new();
    let mut queries = 0usize;
    for class in ScenarioClass::ALL.into_iter().filter(|c| !CLASSES.contains(c)) {
        for seed in 0..SEEDS {
            let s = generate(class, seed);
            let topts = ToiOptions::default().with_target_distance(s.target);
            let (g1, g2) = (s.shape1.parry_shape(), s.shape2.parry_shape());
            let (r, n, bytes) =
                counted(|| shape_time_of_impact(&*g1, &s.motion1, &*g2, &s.motion2, s.t0, s.t1, &topts));
            assert!(r.is_ok(), "{}", s.describe());
            if n > 0 {
                failures.push(format!(
                    "shape_time_of_impact: {n} allocations ({bytes} B): {}",
                    s.describe()
                ));
            }
            queries += 1;
        }
    }
    println!(
        "{queries} queries with no strictly convex side, {} allocating",
        failures.len()
    );
    assert!(failures.is_empty(), "allocations:\n{}", failures.join("\n"));
}

#[test]
fn hand_built_curves_allocate_nothing_when_separated() {
    let ellipse = Ellipse::new(1.0, 0.01);
    let poly = RoundedPolygon::regular(6, 0.8, 0.1);
    let sharp = RoundedPolygon::regular(3, 0.8, 0.0);
    let ball = BallCurve { radius: 0.3 };
    let m1 = NonlinearRigidMotion::new(Pose::rotation(0.3), Vector::ZERO, Vector::new(1.0, 0.0), 40.0);
    let m2 = NonlinearRigidMotion::new(Pose::translation(4.0, 0.1), Vector::ZERO, Vector::new(-2.0, 0.0), -3.0);
    let topts = ToiOptions::default();
    let dopts = DistanceOptions::default();
    let pairs: [(&str, &dyn smooth_ccd2d::ConvexCurve, &dyn smooth_ccd2d::ConvexCurve); 5] = [
        ("ellipse-ellipse", &ellipse, &ellipse),
        ("ellipse-ball", &ellipse, &ball),
        ("polygon-ellipse", &poly, &ellipse),
        ("sharp-ellipse", &sharp, &ellipse),
        ("polygon-ball", &poly, &ball),
    ];
    for (name, c1, c2) in pairs {
        let (r, n, _) = counted(|| time_of_impact(c1, &m1, c2, &m2, 0.0, 1.0, &topts));
        assert!(r.is_ok());
        assert_eq!(n, 0, "{name}: time_of_impact allocated");
        let pos12 = m1.start.inverse() * m2.start;
        let (r, n, _) = counted(|| stationary_distance(c1, c2, &pos12, &dopts));
        assert_eq!(r.unwrap().status, DistanceStatus::Separated);
        assert_eq!(n, 0, "{name}: stationary_distance allocated");
    }
}

/// Penetrating stationary distances run the global branch and bound on a fixed-size node stack:
/// no allocation either.
#[test]
fn penetrating_distances_allocate_nothing() {
    let dopts = DistanceOptions::default();
    println!("| class | penetrating queries | allocating | max allocations | max bytes |");
    println!("|---|---:|---:|---:|---:|");
    for class in CLASSES {
        let (mut total, mut allocating, mut max_n, mut max_b) = (0, 0, 0, 0);
        for seed in 0..SEEDS {
            let s = generate(class, seed);
            // Centres brought together: overlapping.
            for shrink in [0.0, 0.25, 0.5] {
                let (r, n, b) = distance_at_start(&s, &dopts, shrink);
                let Ok(r) = r else { continue };
                if r.distance >= 0.0 {
                    continue;
                }
                total += 1;
                if n > 0 {
                    allocating += 1;
                }
                max_n = max_n.max(n);
                max_b = max_b.max(b);
            }
        }
        println!("| {} | {total} | {allocating} | {max_n} | {max_b} |", class.name());
        assert!(total > 0, "no penetrating case generated for {}", class.name());
        assert_eq!(
            allocating,
            0,
            "{}: {allocating} penetrating queries allocated",
            class.name()
        );
    }
}

/// Prints what the dispatcher allocates per query, for its own shapes and for parry's `Ball` and
/// `Cuboid` (converted on every query to a `BallCurve` / `RoundedPolygon`).
#[test]
fn print_allocations_of_the_dispatcher() {
    let d = SmoothDispatcher::default();
    let ellipse = Ellipse::new(1.0, 0.25);
    let poly = RoundedPolygon::regular(5, 0.8, 0.1);
    let ball = Ball::new(0.5);
    let cuboid = Cuboid::new(Vector::new(0.5, 0.3));
    let m1 = NonlinearRigidMotion::new(Pose::rotation(0.3), Vector::ZERO, Vector::new(1.0, 0.0), 10.0);
    let m2 = NonlinearRigidMotion::new(Pose::translation(4.0, 0.1), Vector::ZERO, Vector::new(-2.0, 0.0), -3.0);
    let apart = m1.start.inverse() * m2.start;
    let overlapping = Pose::translation(0.5, 0.1);
    let others: [(&str, &dyn Shape); 4] = [
        ("Ellipse", &ellipse),
        ("RoundedPolygon", &poly),
        ("parry Ball", &ball),
        ("parry Cuboid", &cuboid),
    ];
    println!("| Ellipse vs | distance (apart) | distance (penetrating) | contact (penetrating) | cast_shapes_nonlinear (hit) |");
    println!("|---|---:|---:|---:|---:|");
    for (name, g2) in others {
        let (r, n_apart, b_apart) = counted(|| d.distance(&apart, &ellipse, g2));
        assert!(r.is_ok());
        let (r, n_pen, b_pen) = counted(|| d.distance(&overlapping, &ellipse, g2));
        assert!(r.is_ok());
        let (r, n_con, b_con) = counted(|| d.contact(&overlapping, &ellipse, g2, 0.0));
        assert!(r.is_ok());
        let (r, n_cast, b_cast) = counted(|| d.cast_shapes_nonlinear(&m1, &ellipse, &m2, g2, 0.0, 1.0, true));
        assert!(matches!(r, Ok(Some(_))), "{name}: expected a hit, got {r:?}");
        println!(
            "| {name} | {n_apart} ({b_apart} B) | {n_pen} ({b_pen} B) | {n_con} ({b_con} B) | {n_cast} ({b_cast} B) |"
        );
    }
}

/// Prints what `time_of_impact` allocates when the pair starts in contact (rapier's solid-body
/// CCD passes `stop_at_penetration = false`).
#[test]
fn print_allocations_of_time_of_impact_starting_in_contact() {
    let e1 = Ellipse::new(1.0, 0.3);
    let e2 = Ellipse::new(0.8, 0.5);
    let start2 = Pose::new(Vector::new(1.5, 0.2), 0.4);
    println!("| start | stop_at_penetration | status | allocations |");
    println!("|---|---|---|---:|");
    for (label, v) in [("overlapping, separating", 3.0), ("overlapping, approaching", -3.0)] {
        let m1 = NonlinearRigidMotion::new(Pose::rotation(0.1), Vector::ZERO, Vector::ZERO, 1.0);
        let m2 = NonlinearRigidMotion::new(start2, Vector::ZERO, Vector::new(v, 0.0), -2.0);
        for stop in [true, false] {
            let opts = ToiOptions::default().with_stop_at_penetration(stop);
            let (r, n, b) = counted(|| time_of_impact(&e1, &m1, &e2, &m2, 0.0, 1.0, &opts));
            let r = r.expect("valid query");
            println!("| {label} | {stop} | {:?} | {n} ({b} B) |", r.status);
        }
    }
}

/// The contact manifolds rapier asks for every step: once a pair's manifold exists (rapier keeps
/// it), recomputing it allocates nothing, shallow or deep, for every scenario class.
#[test]
fn recomputed_contact_manifolds_allocate_nothing() {
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
    let d = SmoothDispatcher::default();
    let mut failures = Vec::new();
    let mut queries = 0usize;
    for class in ScenarioClass::ALL {
        for seed in 0..SEEDS {
            let s = generate(class, seed);
            let (g1, g2) = (s.shape1.parry_shape(), s.shape2.parry_shape());
            let size = s.size();
            let start = pos12_at(&s, s.t0);
            for k in [0.9, 0.6, 0.3] {
                let mut pose = start;
                pose.translation *= k;
                let mut m: Vec<ContactManifold<(), ()>> = Vec::new();
                let mut ws = None;
                let _ = d.contact_manifolds(&pose, &*g1, &*g2, 0.01 * size, &mut m, &mut ws);
                let (r, n, bytes) = counted(|| d.contact_manifolds(&pose, &*g1, &*g2, 0.01 * size, &mut m, &mut ws));
                assert!(r.is_ok(), "{}", s.describe());
                if n > 0 {
                    failures.push(format!(
                        "contact_manifolds: {n} allocations ({bytes} B): {}",
                        s.describe()
                    ));
                }
                queries += 1;
            }
        }
    }
    println!("{queries} recomputed manifolds, {} allocating", failures.len());
    assert!(failures.is_empty(), "allocations:\n{}", failures.join("\n"));
}
