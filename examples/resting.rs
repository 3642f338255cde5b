//! Resting quality in rapier, headless: a stack of 10 rounded boxes, a stack of 10 ellipses lying
//! flat and a rounded hexagon on a 20° slope, each started at rest and stepped for 10 s (friction
//! 0.5, 60 Hz), with the exact shapes and `SmoothDispatcher` and with parry's
//! `RoundConvexPolygon` / inscribed 64-gons and parry's default dispatcher (with the exact
//! shapes' mass properties, and with parry's own) (`tests/common/resting.rs`). Prints a markdown
//! table of drift, slope slide, penetration (from the manifolds and exact), speed at the end and
//! toppling, with rapier's contact recycling on (its default) and off; then when the 200-body box
//! pile of `examples/pile.rs` comes to rest, in each variant, contact recycling on and off, over
//! a few trials (the pile is chaotic).
//!
//! Run: `cargo run --release --example resting` (under a minute on two cores, the pile most of it);
//! `-- scenes` skips the pile; `-- trials N` sets the pile's trials (default 3).

#[path = "common/mod.rs"]
mod common;

use common::resting::{
    pile_rest, pile_table, rest_table, run_scene, RestScene, RestVariant, FRICTION, PILE_REST_SPEED, PILE_REST_WINDOW,
    PILE_TIMED_STEPS, PILE_TRIAL_TURN, REST_STEPS,
};
use std::time::Instant;

/// The most steps a pile run takes (60 s).
const PILE_MAX_STEPS: usize = 3600;

/// Every scene in every variant, recycling as given.
fn scene_reports(recycling: bool) -> Vec<common::resting::RestReport> {
    RestScene::ALL
        .into_iter()
        .flat_map(|scene| RestVariant::ALL.map(|variant| run_scene(scene, variant, REST_STEPS, recycling)))
        .collect()
}

fn main() {
    let started = Instant::now();
    let args: Vec<String> = std::env::args().skip(1).collect();
    let pile = !args.iter().any(|a| a == "scenes");
    let trials = args
        .iter()
        .position(|a| a == "trials")
        .and_then(|i| args.get(i + 1))
        .map_or(3, |n| n.parse::<usize>().expect("trials N: a number"));
    println!(
        "## Resting scenes: {REST_STEPS} steps of 1/60 s from rest, friction {FRICTION}, sleeping off\n\n\
         Drift: final minus starting position (the stacks start exactly touching, so it includes the sinking \
         into rapier's soft contacts). Penetration: the most negative contact `dist` of the narrow phase's \
         manifolds (stale while rapier recycles a pair), and the exact signed distance of the touching pairs' \
         shapes at the end-of-step poses. Toppled: a body displaced by more than half its width.\n"
    );
    println!("### rapier defaults (contact recycling on)\n");
    print!("{}", rest_table(&scene_reports(true)));
    println!("\n### contact recycling off (every manifold recomputed every step)\n");
    print!("{}", rest_table(&scene_reports(false)));
    println!("\n({:.2} s so far)", started.elapsed().as_secs_f64());
    if pile {
        println!(
            "\n## The box pile at rest\n\n`examples/pile.rs`'s 200 bodies dropped into a box (sleeping on), \
             {trials} trials (trial k turns every starting angle by k·{PILE_TRIAL_TURN} rad). At rest: every \
             body's point speed (|v| + |ω|·bounding radius) below {PILE_REST_SPEED} m/s for {PILE_REST_WINDOW} \
             consecutive steps (the first of them is given); asleep: rapier's sleeping; – : not within \
             {PILE_MAX_STEPS} steps. A run stops once the pile is both at rest and asleep, after at least \
             {PILE_TIMED_STEPS} steps. Step times: wall time of `PhysicsPipeline::step`, mean over the trials; \
             the first {PILE_TIMED_STEPS} steps (falling, piling up) are before any run comes to rest.\n"
        );
        let mut runs = Vec::new();
        for recycling in [true, false] {
            for variant in RestVariant::ALL {
                for trial in 0..trials {
                    runs.push(pile_rest(variant, recycling, trial, PILE_MAX_STEPS));
                }
            }
        }
        print!("{}", pile_table(&runs));
    }
    println!("\n({:.2} s in all)", started.elapsed().as_secs_f64());
}
