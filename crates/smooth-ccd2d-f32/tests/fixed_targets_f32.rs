//! `MovingPairsOptions::fixed_targets` in rapier2d (f32): a parry2d cuboid spun past rapier's
//! rotation cap and shot at a fixed thin wall stays on its side with the f32 moving-pairs pass;
//! with the option off, rapier's own sweep (which nlerps the turn the short way round) lets some
//! shots cross.
//!
//! `cargo test --release -p smooth-ccd2d-f32 --test fixed_targets_f32 -- --nocapture` prints the
//! counts.

use rapier2d::prelude::*;
use smooth_ccd2d_f32::{MovingPairs, MovingPairsOptions};

mod uncapped;
use uncapped::uncapped_world;

/// The wall's centre (x, m) and half-thickness.
const WALL_X: f32 = 3.0;
const WALL_HALF: f32 = 0.05;

/// Whether the cuboid's centre ever reached the wall's middle in 40 steps of 1/60 s: shot from
/// x = −3 at `velocity`, spinning at `spin`, turned by `angle`, with the pass of `options`.
fn crossed(velocity: Vector, spin: f32, angle: f32, options: MovingPairsOptions) -> bool {
    let mut w = uncapped_world();
    let wall = w
        .bodies
        .insert(RigidBodyBuilder::fixed().translation(Vector::new(WALL_X, 0.0)));
    let wall_collider = ColliderBuilder::cuboid(WALL_HALF, 40.0).restitution(1.0).friction(0.0);
    w.colliders.insert_with_parent(wall_collider, wall, &mut w.bodies);
    let body = w.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(-3.0, 0.0))
            .rotation(angle)
            .linvel(velocity)
            .angvel(spin)
            .allow_fast_rotation(true)
            .ccd_enabled(true)
            .can_sleep(false),
    );
    let collider = ColliderBuilder::cuboid(0.4, 0.15).restitution(1.0).friction(0.0);
    w.colliders.insert_with_parent(collider, body, &mut w.bodies);
    let mut pass = MovingPairs::new(options);
    let mut through = false;
    for _ in 0..40 {
        pass.before_step(&w.bodies);
        w.step_with_events(&(), &());
        pass.after_step(&w.integration_parameters, &mut w.bodies, &mut w.colliders, &(), &());
        let x = w.bodies[body].center_of_mass().x;
        assert!(x.is_finite(), "NaN");
        through |= x >= WALL_X;
    }
    through
}

/// 48 shots (60–1000 m/s, ±2,500 rad/s, six angles and aims): none crosses with
/// `fixed_targets` (the default); some do without it (the scene tests the option).
#[test]
fn a_cuboid_spun_past_rapiers_cap_stays_on_its_side_of_a_fixed_thin_wall_in_f32() {
    let (mut with, mut without, mut shots) = (0, 0, 0);
    for &speed in &[60.0f32, 150.0, 330.0, 1000.0] {
        for &spin in &[2500.0f32, -2500.0] {
            for k in 0..6 {
                let velocity = Vector::new(speed, 0.2 * speed * (k as f32 - 2.5) / 2.5);
                let angle = 0.53 * k as f32;
                let on = MovingPairsOptions::default();
                let off = MovingPairsOptions {
                    fixed_targets: false,
                    ..on
                };
                with += usize::from(crossed(velocity, spin, angle, on));
                without += usize::from(crossed(velocity, spin, angle, off));
                shots += 1;
            }
        }
    }
    println!("f32 spun cuboid at a thin wall: {with} of {shots} crossed with fixed_targets, {without} without");
    assert_eq!(with, 0, "{with} of {shots} shots crossed the wall with fixed_targets");
    assert!(
        without > 0,
        "no shot crossed without fixed_targets: the scene tests nothing"
    );
}
