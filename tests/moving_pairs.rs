//! The moving-pairs pass in rapier (issue 30): two bodies that both move fast never pass through
//! each other with `MovingPairs` around `PhysicsPipeline::step`, where rapier alone lets them;
//! the closed box of 50 fast bouncing bodies has no pair through and no body out, and gives the
//! same bits on every run.
//!
//! `cargo test --release --test moving_pairs -- --nocapture` prints the counts. The scenes are
//! those of `cargo run --release --example moving_pairs` (`tests/common/moving_scenes.rs`).

mod common;

use common::moving_pairs::Family;
use common::moving_scenes::{
    crossing_shots, head_on_shots, pass_options, plank_shots, run_box, run_shot, run_shot_with, HEAD_ON_STEPS,
};

/// The final state of the closed box after [`DETERMINISM_STEPS`] steps with the pass: FNV-1a of
/// every body's pose and velocities. The same constant is checked by `crates/parallel-tests`
/// on rapier's parallel pipeline (1 and 2 workers). Re-recorded only with the reason in the
/// CHANGELOG (0xB7D8_7452_1F0F_256E before the rapier casts' face-following axis and
/// sphere bound of issue 29 item 3 changed cast answers within their tolerance; 0x2AE1_1BF4_F65A_DC63 before the box ran with
/// `CoreContactHooks`).
const MOVING_BOX_STATE: u64 = 0x0959_51B3_1525_47E8;
/// Steps of the determinism runs.
const DETERMINISM_STEPS: usize = 150;

/// Every head-on shot (27 family pairs × 4 speeds to 3000 m/s × 3 spins to 600 rad/s × 2 sizes):
/// none through with the pass, no NaN; rapier alone lets most through (the scene tests
/// something).
#[test]
fn head_on_bullets_never_pass_through_each_other_with_the_pass() {
    let shots = head_on_shots();
    let (mut through, mut alone, mut nan) = (0, 0, 0);
    for s in &shots {
        let r = run_shot(&s.launches(), HEAD_ON_STEPS, 0.5, Some(pass_options()));
        through += usize::from(r.through());
        nan += usize::from(!r.finite);
        alone += usize::from(run_shot(&s.launches(), HEAD_ON_STEPS, 0.5, None).through());
    }
    println!(
        "head-on: {through} through of {} shots with the pass, {nan} with NaN; rapier alone: {alone}",
        shots.len()
    );
    assert_eq!((through, nan), (0, 0));
    assert!(alone > shots.len() / 2, "rapier alone let only {alone} through");
}

/// With `CoreContactHooks`, a head-on collision of two smooth bodies (one contact point: no flat
/// side) gains no energy at any speed or spin, and none passes through: the core contacts still
/// hold the centres, the bounce is the exact point's alone. Without the hooks rapier's
/// restitution on the exact point and a core contact adds energy (printed).
#[test]
fn core_contact_hooks_keep_smooth_collisions_from_gaining_energy() {
    let smooth = [Family::Ellipse, Family::UserCurve, Family::Ball];
    let shots: Vec<_> = head_on_shots()
        .into_iter()
        .filter(|s| smooth.contains(&s.a) && smooth.contains(&s.b))
        .collect();
    let (mut worst, mut worst_without) = (0.0f64, 0.0f64);
    for s in &shots {
        let r = run_shot_with(&s.launches(), HEAD_ON_STEPS, 0.5, Some(pass_options()), true);
        assert!(!r.through() && r.finite, "{s:?}");
        assert!(r.e1 <= r.e0 * (1.0 + 1e-9), "{s:?}: energy {} -> {}", r.e0, r.e1);
        assert!(
            (r.p1 - r.p0).length() <= 1e-9 * r.e0.sqrt(),
            "{s:?}: momentum {:?} -> {:?}",
            r.p0,
            r.p1
        );
        worst = worst.max(r.e1 / r.e0);
        let plain = run_shot(&s.launches(), HEAD_ON_STEPS, 0.5, Some(pass_options()));
        worst_without = worst_without.max(plain.e1 / plain.e0);
    }
    println!(
        "{} smooth head-on shots: largest energy after/before {worst:.9} with CoreContactHooks, {worst_without:.9} without",
        shots.len()
    );
    assert!(shots.len() >= 48);
}

/// Crossing paths and a fast plank: none through with the pass.
#[test]
fn crossing_bullets_and_a_fast_plank_are_never_passed_through() {
    let mut cases = 0;
    for l in crossing_shots()
        .iter()
        .map(|s| s.launches())
        .chain(plank_shots().iter().map(|s| s.launches()))
    {
        let r = run_shot(&l, 20, 0.5, Some(pass_options()));
        assert!(!r.through() && r.finite, "{l:?}");
        cases += 1;
    }
    println!("{cases} crossing and plank shots: none through");
}

/// The closed box over 10 s, with `CoreContactHooks` as docs/rapier.md advises for bouncing
/// bodies: no pair through each other, no body out of the box, no NaN, no panic with the pass.
/// (Without the hooks, restitution on the core contacts spins bodies up to thousands of rad/s
/// and rapier's own CCD lets some into and out through the walls: the example prints it.)
#[test]
fn the_closed_box_has_no_pair_through_and_no_body_out() {
    let with = run_box(common::moving_scenes::BOX_STEPS, Some(pass_options()), true);
    println!(
        "box with the pass: {} through, {} out, {} into a wall, energy after/before {:.3}, casts {}, stops {}",
        with.verdicts.through,
        with.out_of_box,
        with.in_wall,
        with.energy_ratio,
        with.totals.casts,
        with.totals.stopped_bodies
    );
    assert_eq!(with.verdicts.through, 0);
    assert_eq!(with.out_of_box, 0);
    assert!(!with.nan && !with.panicked);
    assert_eq!(with.totals.not_done, 0, "a pass ran out of events");
}

/// Two runs of the box give the same bits, and the recorded ones (with and without rapier's
/// `parallel` feature: `cargo test --workspace` builds rapier with it, `cargo test -p
/// smooth-ccd2d` without; `crates/parallel-tests` checks 1 and 2 workers).
#[test]
fn the_closed_box_is_deterministic_to_the_bit() {
    let a = run_box(DETERMINISM_STEPS, Some(pass_options()), true).hash;
    let b = run_box(DETERMINISM_STEPS, Some(pass_options()), true).hash;
    println!("box after {DETERMINISM_STEPS} steps: {a:016x} {b:016x}");
    assert_eq!(a, b, "two runs differ");
    assert_eq!(a, MOVING_BOX_STATE, "the box's final state changed: {a:#018x}");
}
