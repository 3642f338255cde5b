//! A smooth body rocking on a flat floor in rapier, headless (`tests/common/rocking.rs`): an
//! ellipse 0.5 × 0.2 set down at rest tilted by 0.1 rad on a box floor (friction 0.5, 60 Hz,
//! 60 s), with this crate's `Ellipse` and `SmoothDispatcher`, and with parry's inscribed 256-gon
//! and 64-gon and rapier's default narrow phase; and a weeble (a disc of radius 0.25 whose centre
//! of mass is 0.1 below its centre), this crate's disc and parry's `Ball`. Rocking without
//! slipping conserves energy; rapier's solver adds some where the contact point rolls along the
//! body. Prints, for each body and each setting (rapier's defaults; contact recycling off; a
//! smaller step; 1 and 8 solver iterations; no warm start; angular damping 0.2, 1 and 5), the
//! largest tilt over each 10 s, the mechanical energy at the end of each 10 s (J, the floor's top
//! as the height's zero) and whether the body sleeps at the end.
//!
//! Run: `cargo run --release --example rocking` (a second or two).

#[path = "common/mod.rs"]
mod common;

use common::rocking::{rock, Body, Setting, A, B, TILT};

/// Seconds simulated, reported in windows of 10 s.
const SECONDS: usize = 60;
const WINDOW: usize = 10;

fn main() {
    println!("An ellipse {A} × {B} (or a weeble) set down at rest tilted by {TILT} rad on a flat floor, friction 0.5, {SECONDS} s.");
    println!("The tilt (rad) at the start, then the largest over each {WINDOW} s; the mechanical energy (J) at the start and");
    println!("at the end of each {WINDOW} s (the floor's top as zero); whether the body sleeps at the end.\n");
    println!(
        "| body | setting | tilt: start, largest per {WINDOW} s | energy: start, end of each {WINDOW} s | asleep |"
    );
    println!("|---|---|---|---|---|");
    let ellipses = [Body::Exact, Body::Polygon(256), Body::Polygon(64)];
    let weebles = [Body::Weeble { parry: false }, Body::Weeble { parry: true }];
    let mut rows: Vec<(Body, Setting)> = Vec::new();
    for setting in [
        Setting::Defaults,
        Setting::NoRecycling,
        Setting::SmallStep,
        Setting::SolverIterations(1),
        Setting::SolverIterations(8),
        Setting::NoWarmStart,
        Setting::Damped(0.2),
        Setting::Damped(1.0),
        Setting::Damped(5.0),
    ] {
        rows.extend(ellipses.iter().map(|b| (*b, setting)));
    }
    rows.extend(weebles.iter().map(|b| (*b, Setting::Defaults)));
    for (body, setting) in rows {
        let r = rock(body, setting, SECONDS, WINDOW);
        let list = |v: &[f64]| v.iter().map(|x| format!("{x:.3}")).collect::<Vec<_>>().join(", ");
        println!(
            "| {} | {} | {} | {} | {} |",
            body.name(),
            setting.name(),
            list(&r.tilts),
            list(&r.energies),
            if r.asleep { "yes" } else { "no" }
        );
    }
}
