//! Reliability under random and adversarial input (issue 7): nothing the crate is given may
//! crash it, hang it or make it lie.
//!
//! * [`fuzz_every_query_with_random_and_adversarial_inputs`]: a seeded, deterministic batch over
//!   the scenario classes of `reliability::CLASSES` (random pairs, parry pairs, wild numbers,
//!   coincident and concentric shapes, contact exactly at t0, grazing passes within 1e-12,
//!   scales beyond 1e-6..1e6, ellipses to 1:1e6). Every case runs every query inside
//!   `catch_unwind`, with a watchdog for hangs; it prints its case count, the worst time of one
//!   case and the statuses returned.
//! * proptest properties over adversarial strategies (NaN, infinities, zeros, extremes).
//! * Targeted tests: the documented error of each query for each kind of bad input, empty and
//!   reversed windows, coincident, concentric and touching shapes, grazing passes, and the
//!   accuracy measured across scales and axis ratios (the numbers of the README's Limits).
//!
//! Run with `cargo test --test adversarial -- --nocapture` to see the measurements.

#[path = "adversarial/accuracy.rs"]
mod accuracy;
#[path = "adversarial/bad_input.rs"]
mod bad_input;
#[path = "../../../tests/common/mod.rs"]
mod common;
#[path = "adversarial/dispatcher_bad_input.rs"]
mod dispatcher_bad_input;
#[path = "adversarial/proptests.rs"]
mod proptests;
#[path = "../../../tests/reliability/mod.rs"]
mod reliability;
#[path = "adversarial/touching.rs"]
mod touching;

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{NonlinearRigidMotion, PointQuery, QueryDispatcher};
use parry2d_f64::shape::{Ball, HalfSpace};
use proptest::prelude::*;
use reliability::{describe, generate, run_case, Case, ShapeSpec, WILD};
use smooth_ccd2d::{halfspace_distance, time_of_impact_halfspace};
use smooth_ccd2d::{
    stationary_distance, time_of_impact, BallCurve, CapsuleEllipse, ConvexCurve, DistanceOptions, DistanceStatus,
    Ellipse, QueryError, RoundedPolygon, ShapeError, SmoothDispatcher, ToiOptions, ToiStatus,
};
use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};
use std::time::{Duration, Instant};

const SEED: u64 = 0x0007_5EED;
/// Cases of the fuzz batch (about 4,400 of each class; about 25 s at opt-level 3).
const FUZZ_CASES: u64 = 40_000;
/// A case running longer than this is a hang: the watchdog prints it and aborts the process.
const HANG: Duration = Duration::from_secs(20);

fn panic_message(e: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = e.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = e.downcast_ref::<String>() {
        s.clone()
    } else {
        "non-string panic".into()
    }
}

/// Runs one case under `catch_unwind` (its violations, or the panic as one) and under the
/// watchdog.
fn guarded(case: &Case) -> reliability::Outcome {
    let _watch = watch(case);
    match catch_unwind(AssertUnwindSafe(|| run_case(case))) {
        Ok(o) => o,
        Err(e) => reliability::Outcome {
            violations: vec![format!("PANIC: {}", panic_message(&*e))],
            ..Default::default()
        },
    }
}

/// The cases running now, per thread: when one has run longer than [`HANG`], the watchdog prints
/// it and aborts the process (a hang would otherwise stall the whole test run).
static RUNNING: Mutex<BTreeMap<u64, (Instant, String)>> = Mutex::new(BTreeMap::new());
static NEXT_SLOT: AtomicU64 = AtomicU64::new(0);

/// Registers `case` with the watchdog (started once) until the guard is dropped.
fn watch(case: &Case) -> impl Drop {
    static DOG: OnceLock<()> = OnceLock::new();
    DOG.get_or_init(|| {
        std::thread::spawn(|| loop {
            std::thread::sleep(Duration::from_millis(250));
            let running = RUNNING.lock().unwrap_or_else(|e| e.into_inner());
            if let Some((t, what)) = running.values().find(|(t, _)| t.elapsed() > HANG) {
                eprintln!("HANG: case still running after {:?}: {what}", t.elapsed());
                std::process::abort();
            }
        });
    });
    struct Slot(u64);
    impl Drop for Slot {
        fn drop(&mut self) {
            RUNNING.lock().unwrap_or_else(|e| e.into_inner()).remove(&self.0);
        }
    }
    let slot = NEXT_SLOT.fetch_add(1, Ordering::Relaxed);
    RUNNING
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .insert(slot, (Instant::now(), describe(case)));
    Slot(slot)
}

/// A body at rest at (x, y), angle a.
fn still(x: f64, y: f64, a: f64) -> NonlinearRigidMotion {
    NonlinearRigidMotion::constant_position(Pose::new(Vector::new(x, y), a))
}

/// A violation message with its numbers replaced by `#`, to count violations by kind.
fn kind_of(msg: &str) -> String {
    let mut out = String::new();
    let mut in_num = false;
    for c in msg.chars() {
        let numeric = c.is_ascii_digit() || (in_num && matches!(c, '.' | 'e' | '-' | '+'));
        if numeric {
            if !in_num {
                out.push('#');
            }
            in_num = true;
        } else {
            in_num = false;
            out.push(c);
        }
    }
    out.chars().take(100).collect()
}

#[test]
fn fuzz_every_query_with_random_and_adversarial_inputs() {
    // FUZZ_SEED and FUZZ_CASES explore other batches; the suite runs the fixed one.
    let env = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<u64>().ok());
    let (seed, n) = (
        env("FUZZ_SEED").unwrap_or(SEED),
        env("FUZZ_CASES").unwrap_or(FUZZ_CASES),
    );
    let start = Instant::now();
    let mut failures: Vec<(u64, Vec<String>)> = Vec::new();
    let mut tags: BTreeMap<String, usize> = BTreeMap::new();
    let mut per_class: BTreeMap<&str, (usize, Duration, u64)> = BTreeMap::new();
    let mut worst = (Duration::ZERO, 0u64);
    for i in 0..n {
        let case = generate(seed, i);
        let t = Instant::now();
        let out = guarded(&case);
        let dt = t.elapsed();
        if dt > worst.0 {
            worst = (dt, i);
        }
        let e = per_class.entry(case.class).or_insert((0, Duration::ZERO, 0));
        e.0 += 1;
        if dt > e.1 {
            *e = (e.0, dt, i);
        }
        for t in out.tags {
            if t.ends_with("OutOfIterations") {
                *tags.entry(format!("{t} [{}]", case.class)).or_default() += 1;
            }
            *tags.entry(t).or_default() += 1;
        }
        if !out.violations.is_empty() {
            failures.push((i, out.violations));
        }
    }
    let elapsed = start.elapsed();
    println!(
        "adversarial fuzz: {n} cases (seed {seed:#x}) in {:.1} s; worst case {:.2} ms (case {}, {})",
        elapsed.as_secs_f64(),
        worst.0.as_secs_f64() * 1e3,
        worst.1,
        generate(seed, worst.1).class
    );
    for (class, (n, w, i)) in &per_class {
        println!(
            "  class {class:<15} {n:>6} cases, worst {:>8.3} ms (case {i})",
            w.as_secs_f64() * 1e3
        );
    }
    let summary: Vec<String> = tags.iter().map(|(k, v)| format!("{k} {v}")).collect();
    println!("  outcomes: {}", summary.join(", "));
    println!("  cases with a broken promise: {}", failures.len());
    // Kinds of broken promises: the message with its numbers and vectors left out.
    let mut kinds: BTreeMap<String, (usize, u64)> = BTreeMap::new();
    for (i, v) in &failures {
        for msg in v {
            let key = kind_of(msg);
            let c = generate(seed, *i);
            let class = if c.class == "extreme-scale" {
                format!("extreme-scale {:.0e}", c.scale)
            } else {
                c.class.to_string()
            };
            let e = kinds.entry(format!("[{class}] {key}")).or_insert((0, *i));
            e.0 += 1;
        }
    }
    for (k, (n, i)) in &kinds {
        println!("  {n:>6} × {k} (first: case {i})");
    }
    for (i, v) in failures.iter().take(15) {
        println!("  FAIL {}\n      {}", describe(&generate(seed, *i)), v.join("\n      "));
    }
    assert!(
        failures.is_empty(),
        "{} of {FUZZ_CASES} cases broke a promise",
        failures.len()
    );
    // Every query of one case together; the worst measured is 0.7 s (1:1e25 ellipses hitting
    // `max_evaluations`), ordinary cases take milliseconds. A hang is the watchdog's.
    assert!(worst.0 < Duration::from_secs(5), "worst case took {:?}", worst.0);
}
