//! The CCD scene suite (`tests/common/ccd_scenes.rs`, judged by `tests/common/ccd_judge.rs`):
//! game-like continuous-collision scenes — segment and chain walls, thin posts and planks,
//! funnels and an acute wedge, a slide into a corner, bullets into a stack, a flipper, bouncing
//! boxes — with every shape family of the crate as the moving body, 10 to 3000 m/s and spins to
//! 600 rad/s (rapier's caps lifted where a case is above them), in rapier2d-f64 with
//! `SmoothDispatcher`, side by side with rapier's default narrow phase on parry's closest
//! shapes. `cargo run --release --example ccd_scenes` prints the same table.
//!
//! What it pins for `SmoothDispatcher`: no body through a wall, no NaN, no panic in any case; no
//! body frozen but at most [`MAX_FROZEN`] cases of the one class [`may_freeze`] names
//! (docs/rapier.md says why). The table
//! it prints has the deepest penetration after a step in which rapier's CCD swept a body.

mod common;

use common::ccd_judge::{run_all, table};
use common::ccd_scenes::{all_cases, Case};

/// The one class of cases in which a body may stay frozen for `FROZEN_STEPS` steps: a thin body
/// (the 8:1 thin ellipse, the sliver) at 1000 m/s or more, jammed against two walls at once —
/// rapier's contact recycling keeps a pair's last full-update contacts while the CCD's clamp
/// barely moves the body, and the contacts that were separating then are not solved
/// (docs/rapier.md, "What is left"). At most [`MAX_FROZEN`] such cases; none of any other body
/// or speed.
fn may_freeze(c: &Case) -> bool {
    matches!(c.body.name(), "thin ellipse" | "sliver") && c.speed >= 1000.0
}

/// The most cases of the [`may_freeze`] class that may freeze.
const MAX_FROZEN: usize = 5;

#[test]
fn no_body_goes_through_a_wall_nor_freezes_in_the_ccd_scene_suite() {
    let cases = all_cases();
    let outcomes = run_all(&cases);
    println!("CCD scene suite: {} cases", cases.len());
    print!("{}", table(&cases, &outcomes));
    let mut failures = Vec::new();
    for (c, o) in cases.iter().zip(&outcomes) {
        let o = &o[0];
        let what = format!("{} {} {} m/s {} rad/s", c.family.name(), c.body.name(), c.speed, c.spin);
        if let Some(t) = &o.through {
            failures.push(format!("{what}: through at step {} ({})", t.0, t.1));
        }
        if let Some(step) = o.nan {
            failures.push(format!("{what}: NaN at step {step}"));
        }
        if let Some(p) = &o.panicked {
            failures.push(format!("{what}: panicked ({p})"));
        }
        if o.frozen.is_some() && !may_freeze(c) {
            failures.push(format!("{what}: frozen at step {:?}", o.frozen));
        }
    }
    let frozen: Vec<String> = cases
        .iter()
        .zip(&outcomes)
        .filter(|(_, o)| o[0].frozen.is_some())
        .map(|(c, _)| format!("{} {} {} m/s {} rad/s", c.family.name(), c.body.name(), c.speed, c.spin))
        .collect();
    println!(
        "SmoothDispatcher: {} frozen (at most {MAX_FROZEN}): {frozen:?}",
        frozen.len()
    );
    if frozen.len() > MAX_FROZEN {
        failures.push(format!("{} frozen cases, more than {MAX_FROZEN}", frozen.len()));
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
