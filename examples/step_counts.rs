//! Where a step of the CCD scene suite goes: per family and method (this crate's shapes with
//! `SmoothDispatcher`, rapier's default narrow phase on parry's closest shapes), the mean step
//! time and, after every step, rapier's solver work read off the narrow phase — manifolds,
//! manifolds with solver contacts (each a constraint of rapier's solver), solver contacts — and,
//! with `--watch`, the dispatcher's `contact_manifolds` calls and CCD casts (the time inside
//! each call, by a wrapper that reads a clock around it; rapier's default CCD sweeps its shapes
//! itself, so its casts do not show there).
//!
//! Run: `cargo run --release --example step_counts -- [family] [--watch]` (a family name with dashes
//! for spaces runs only it); environment: `ONLY=smooth` or `ONLY=rapier` runs one method (for a
//! profiler: `ONLY=smooth valgrind --tool=callgrind target/release/examples/step_counts
//! chain-box`, then `callgrind_annotate --inclusive=yes` for rapier's stages), `REPS=n` runs the
//! cases n times. `step_counts pile` runs the first 400 steps of the exact pile instead
//! (`PILE_RECYCLING=on` or `off` for one of rapier's contact-recycling settings), each step in
//! the function `pile_step`.

#[path = "common/mod.rs"]
mod common;

use common::ccd_scenes::{all_cases, build, drive, Case, Family, Method};
use common::watched::{Watched, Watcher};
use common::world::World;
use parry2d_f64::query::DefaultQueryDispatcher;
use parry2d_f64::shape::Shape;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::SmoothDispatcher;
use std::sync::Mutex;
use std::time::Instant;

/// The dispatcher's calls: seconds, count and points of `contact_manifolds`; seconds and count
/// of the CCD casts.
#[derive(Default)]
struct Calls {
    manifold_seconds: f64,
    manifold_calls: usize,
    manifold_points: usize,
    cast_seconds: f64,
    casts: usize,
}

/// A [`Watcher`] adding every call to its [`Calls`].
#[derive(Default)]
struct Tally(Mutex<Calls>);

impl Watcher for &'static Tally {
    fn manifolds(&self, _g1: &dyn Shape, _g2: &dyn Shape, seconds: f64, points: usize) {
        let mut c = self.0.lock().unwrap();
        c.manifold_seconds += seconds;
        c.manifold_calls += 1;
        c.manifold_points += points;
    }
    fn cast(&self, _g1: &dyn Shape, _g2: &dyn Shape, seconds: f64) {
        let mut c = self.0.lock().unwrap();
        c.cast_seconds += seconds;
        c.casts += 1;
    }
}

/// What the steps of one method on one family added up to.
#[derive(Default)]
struct Sums {
    seconds: f64,
    steps: usize,
    manifolds: usize,
    active_manifolds: usize,
    solver_contacts: usize,
}

/// Runs `cases` under `method` (`reps` times), counting the narrow phase after each step.
fn run(cases: &[&Case], method: Method, reps: usize, watch: Option<&'static Tally>) -> Sums {
    let mut s = Sums::default();
    for _ in 0..reps {
        for c in cases {
            let mut scene = build(c, method);
            if let Some(w) = watch {
                scene.world.narrow_phase = match method {
                    Method::Smooth => NarrowPhase::with_query_dispatcher(Watched {
                        inner: SmoothDispatcher::default(),
                        watcher: w,
                    }),
                    Method::Rapier => NarrowPhase::with_query_dispatcher(Watched {
                        inner: DefaultQueryDispatcher,
                        watcher: w,
                    }),
                };
            }
            for step in 0..scene.steps {
                drive(&mut scene, step);
                let t = Instant::now();
                scene.world.step(scene.gravity, &());
                s.seconds += t.elapsed().as_secs_f64();
                s.steps += 1;
                for pair in scene.world.narrow_phase.contact_pairs() {
                    for m in pair.manifolds() {
                        let n = m.data.solver_contacts.len();
                        s.manifolds += 1;
                        s.active_manifolds += (n > 0) as usize;
                        s.solver_contacts += n;
                    }
                }
            }
        }
    }
    s
}

/// One step of the pile (a function of its own, for a profiler to find).
#[inline(never)]
fn pile_step(world: &mut World) {
    world.step(common::world::GRAVITY, &());
}

/// The first 400 steps of the exact pile, with contact recycling on and off (or as
/// `PILE_RECYCLING` says).
fn pile() {
    use common::scenes::{insert_pile, pile_bodies, PileShape};
    let wanted = std::env::var("PILE_RECYCLING").ok();
    for recycling in [true, false] {
        if wanted.as_deref().is_some_and(|w| (w == "on") != recycling) {
            continue;
        }
        let mut world = World::new(NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()));
        world.params.contact_recycling = recycling;
        let bodies = insert_pile(&mut world, &pile_bodies(), PileShape::shared);
        let t = Instant::now();
        for _ in 0..400 {
            pile_step(&mut world);
        }
        let ms = t.elapsed().as_secs_f64() * 1e3 / 400.0;
        let (hash, _) = common::world::state_hash(&world, &bodies);
        println!(
            "exact pile, contact recycling {recycling}: {ms:.3} ms a step (first 400 steps), final state {hash:#018x}"
        );
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let filter = args.iter().find(|a| !a.starts_with("--"));
    if filter.is_some_and(|f| f == "pile") {
        return pile();
    }
    let watch = args.iter().any(|a| a == "--watch");
    let reps: usize = std::env::var("REPS").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    let only = std::env::var("ONLY").ok();
    let cases: Vec<Case> = all_cases()
        .into_iter()
        .filter(|c| filter.is_none_or(|f| c.family.name().replace(' ', "-") == *f))
        .collect();
    println!("per step: mean step time; manifolds, manifolds with solver contacts, solver contacts after the step");
    for family in Family::ALL {
        let of_family: Vec<&Case> = cases.iter().filter(|c| c.family == family).collect();
        if of_family.is_empty() {
            continue;
        }
        for method in Method::BOTH {
            if only
                .as_deref()
                .is_some_and(|o| (o == "smooth") != (method == Method::Smooth))
            {
                continue;
            }
            let tally: Option<&'static Tally> = watch.then(|| &*Box::leak(Box::default()));
            let s = run(&of_family, method, reps, tally);
            let per = |x: usize| x as f64 / s.steps.max(1) as f64;
            let mut line = format!(
                "{:<18} {:<17} step {:6.2} us  manifolds {:5.2}  with solver contacts {:5.2}  solver contacts {:5.2}",
                family.name(),
                method.name(),
                1e6 * s.seconds / s.steps.max(1) as f64,
                per(s.manifolds),
                per(s.active_manifolds),
                per(s.solver_contacts),
            );
            if let Some(t) = tally {
                let c = t.0.lock().unwrap();
                let us = |x: f64| 1e6 * x / s.steps.max(1) as f64;
                line += &format!(
                    "  | dispatcher: manifolds {:.2} us ({:.2} calls, {:.2} points each), casts {:.2} us ({:.3} calls)",
                    us(c.manifold_seconds),
                    per(c.manifold_calls),
                    c.manifold_points as f64 / c.manifold_calls.max(1) as f64,
                    us(c.cast_seconds),
                    per(c.casts),
                );
            }
            println!("{line}");
        }
    }
}
