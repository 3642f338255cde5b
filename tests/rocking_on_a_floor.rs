//! A smooth body rocking on a floor in rapier 2D 0.36 (`docs/rapier.md`, Pitfalls;
//! `cargo run --release --example rocking` prints the table; the scene is
//! `tests/common/rocking.rs`). Its contact point rolls along its boundary as it rocks, and
//! rapier's solver — a step in substeps, each contact tracked by body-fixed points and
//! warm-started from substep to substep — feeds energy into the rocking: an ellipse set down
//! tilted on a flat floor rocks wider and never sleeps. parry's own `Ball` with its centre of mass
//! below its centre does the same, to the digit with this crate's disc in its place: the crate's
//! contacts add nothing of their own. These tests pin that, the solver's part (one solver
//! iteration: no gain), and the remedy the docs give (angular damping 5: asleep).

mod common;

use common::rocking::{rest_energy, rock, Body, Setting};

/// Seconds of each run, reported in windows of 10 s.
const SECONDS: usize = 60;
const WINDOW: usize = 10;

#[test]
fn a_disc_with_its_centre_of_mass_off_centre_rocks_as_parry_s_ball_does() {
    let ours = rock(Body::Weeble { parry: false }, Setting::Defaults, SECONDS, WINDOW);
    let ball = rock(Body::Weeble { parry: true }, Setting::Defaults, SECONDS, WINDOW);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs().max(1.0);
    for k in 0..ours.energies.len() {
        assert!(
            close(ours.energies[k], ball.energies[k]) && close(ours.tilts[k], ball.tilts[k]),
            "window {k}: this crate's disc {} J, tilt {}; parry's ball {} J, tilt {}",
            ours.energies[k],
            ours.tilts[k],
            ball.energies[k],
            ball.tilts[k]
        );
    }
    assert_eq!(ours.asleep, ball.asleep);
}

#[test]
fn rapier_s_substeps_add_energy_to_a_rocking_ellipse_as_to_parry_s_own_ball() {
    // rapier's behaviour, which the docs describe: if this fails, rapier changed, and the docs'
    // paragraph and the example's table are to be measured again.
    for body in [Body::Exact, Body::Weeble { parry: true }] {
        let r = rock(body, Setting::Defaults, SECONDS, WINDOW);
        let rest = rest_energy(body);
        let (start, end) = (r.energies[0] - rest, r.energies[SECONDS / WINDOW] - rest);
        assert!(
            end > 2.0 * start && !r.asleep,
            "{body:?}: {start} J above rest at the start, {end} J after {SECONDS} s, asleep {}",
            r.asleep
        );
    }
    // One solver iteration (no substeps): the rocking loses energy (slowly: still awake).
    let r = rock(Body::Exact, Setting::SolverIterations(1), SECONDS, WINDOW);
    let (start, end) = (r.energies[0], r.energies[SECONDS / WINDOW]);
    assert!(
        end < start,
        "one solver iteration: {start} J at the start, {end} J after {SECONDS} s"
    );
}

#[test]
fn an_ellipse_with_angular_damping_5_comes_to_rest_and_sleeps() {
    let r = rock(Body::Exact, Setting::Damped(5.0), SECONDS, WINDOW);
    // Asleep within the first window, within about a degree of lying flat (the damping slows its
    // last roll back below rapier's sleep threshold: 0.010 rad short of flat).
    let last = r.tilts[SECONDS / WINDOW];
    assert!(
        r.asleep && last < 0.02,
        "angular damping 5: tilt {last} rad at the end, asleep {}",
        r.asleep
    );
    let rest = rest_energy(Body::Exact);
    let end = r.energies[SECONDS / WINDOW];
    // Lying flat to 1 mm of its centre's height (the soft contact sinks it a little).
    let mm = rest / common::rocking::B * 1e-3;
    assert!((end - rest).abs() < mm, "{end} J at the end, {rest} J at rest");
}
