//! A body rolling or spinning on a long fixed box, against parry's `Ball` under rapier's default
//! narrow phase (the oracle: a frictionless disc keeps its spin, a disc rolling on a floor keeps
//! rolling). A core contact (`dispatcher::core_disc`) acts where both bodies are: the core disc
//! against the other body's nearest point. Taken along the pair's contact normal, with its point
//! on the disc's supporting line opposite the box's centre, the box's core contact pushed the disc
//! at a point metres beside it (rapier's solver acts on a contact at the middle of its two
//! points): a lever of metres that stopped the disc's spin within a step.

mod common;

use common::world::{World, GRAVITY};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{Ellipse, SmoothDispatcher};

/// A disc of radius 0.2 (this crate's `Ellipse` with `SmoothDispatcher`, or parry's `Ball` with
/// rapier's default narrow phase) resting at `x` on a fixed 10 × 0.05 box, started with this
/// spin and velocity along the box, friction `friction` on both; its spin and x after 2 s.
fn run(smooth: bool, x: f64, spin: f64, vx: f64, friction: f64) -> (f64, f64) {
    let narrow_phase = if smooth {
        NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
    } else {
        NarrowPhase::new()
    };
    let mut w = World::new(narrow_phase);
    let floor = w.bodies.insert(RigidBodyBuilder::fixed());
    w.colliders.insert_with_parent(
        ColliderBuilder::cuboid(5.0, 0.025).friction(friction),
        floor,
        &mut w.bodies,
    );
    let disc = if smooth {
        ColliderBuilder::new(SharedShape::new(Ellipse::new(0.2, 0.2)))
    } else {
        ColliderBuilder::ball(0.2)
    };
    let (h, _) = w.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(x, 0.225))
            .angvel(spin)
            .linvel(Vector::new(vx, 0.0))
            .can_sleep(false),
        disc.friction(friction),
    );
    for _ in 0..120 {
        w.step(GRAVITY, &());
    }
    (w.bodies[h].angvel(), w.bodies[h].translation().x)
}

#[test]
fn a_frictionless_disc_spinning_on_a_long_box_keeps_its_spin_as_parry_s_ball_does() {
    for x in [0.0, 1.0, 4.0, -4.0] {
        let (exact, _) = run(true, x, 20.0, 0.0, 0.0);
        let (ball, _) = run(false, x, 20.0, 0.0, 0.0);
        assert!((ball - 20.0).abs() < 1e-9, "parry's ball at x = {x}: {ball} rad/s");
        assert!(
            (exact - ball).abs() < 1e-6,
            "at x = {x}: {exact} rad/s, parry's ball {ball}"
        );
    }
}

#[test]
fn a_disc_rolling_across_a_long_box_keeps_rolling_as_parry_s_ball_does() {
    for (x, v) in [(-2.0, 2.0), (2.0, -2.0), (2.0, 2.0)] {
        let (exact_spin, exact_x) = run(true, x, -v / 0.2, v, 0.5);
        let (ball_spin, ball_x) = run(false, x, -v / 0.2, v, 0.5);
        assert!(
            (exact_x - ball_x).abs() < 1e-3 && (exact_spin - ball_spin).abs() < 1e-2,
            "from x = {x} at {v} m/s: x {exact_x}, spin {exact_spin}; parry's ball x {ball_x}, spin {ball_spin}"
        );
    }
}
