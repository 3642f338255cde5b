//! rapier2d (f32) integration of the f32 `SmoothDispatcher` as the narrow phase's query
//! dispatcher: contact manifolds, and rapier's CCD (which casts through the same dispatcher).
//! The f32 counterparts of the f64 crate's `tests/rapier_integration.rs` scenes, self-contained.
//!
//! Run optimised (the workspace's test profile is `opt-level = 3`); each test prints what it
//! measures (`-- --nocapture`).

use rapier2d::prelude::*;
use smooth_ccd2d_f32::{Ellipse, RoundedPolygon, SmoothDispatcher};
use std::f32::consts::{PI, TAU};
use std::time::Instant;

/// Gravity of the scenes that have one: 9.81 m/s² down the y axis.
const GRAVITY: Vector = Vector::new(0.0, -9.81);

/// The shots' wall: a fixed parry2d `Cuboid` 0.04 thick and 6 tall, centred at x = `WALL_X`.
const WALL_X: f32 = 5.0;
/// The wall's half-thickness.
const WALL_HALF: f32 = 0.02;
/// The wall's half-height.
const WALL_HALF_HEIGHT: f32 = 3.0;
/// Steps per shot (0.5 s at 60 Hz: the slowest shot, 50 m/s, reaches the wall at step 6).
const SHOT_STEPS: usize = 30;

/// A 60 Hz rapier2d (f32) world under `gravity`, with the `SmoothDispatcher` as the narrow
/// phase's query dispatcher (`smooth`) or rapier's default narrow phase (parry's dispatcher).
fn world(smooth: bool, gravity: Vector) -> PhysicsWorld {
    let mut w = PhysicsWorld {
        gravity,
        narrow_phase: if smooth {
            NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
        } else {
            NarrowPhase::new()
        },
        ..PhysicsWorld::default()
    };
    w.integration_parameters.dt = 1.0 / 60.0;
    w
}

/// What is shot at the wall.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Body {
    /// Ellipse 0.5 × 0.2.
    Ellipse,
    /// Rounded regular heptagon: circumradius 0.5, corner radius 0.05.
    Heptagon,
}

/// One shot from the origin along +x: its body, speed (m/s), spin (rad/s), initial angle (rad).
#[derive(Clone, Copy, Debug)]
struct Shot {
    body: Body,
    speed: f32,
    spin: f32,
    angle0: f32,
}

/// The 40 shots: even ones ellipses, odd ones heptagons; speeds 50–300 m/s, spin magnitudes
/// 20–60 rad/s with both signs for each shape, initial angles over a full turn, spread by
/// golden-ratio and plastic-number fractions (deterministic).
fn shots() -> Vec<Shot> {
    (0..40)
        .map(|i| {
            let f = |alpha: f64| (i as f64 * alpha).fract() as f32;
            let sign = if (i / 2) % 2 == 0 { 1.0 } else { -1.0 };
            Shot {
                body: if i % 2 == 0 { Body::Ellipse } else { Body::Heptagon },
                speed: 50.0 + 250.0 * f(0.618_033_988_749_895),
                spin: sign * (20.0 + 40.0 * f(0.754_877_666_246_693)),
                angle0: TAU * f(0.569_840_290_998_053),
            }
        })
        .collect()
}

/// The collider shape of `body`: this package's exact shape (`smooth`) or parry's polygon
/// approximation (a 64-gon inscribed in the ellipse; the heptagon as a `RoundConvexPolygon`).
fn shot_shape(body: Body, smooth: bool) -> SharedShape {
    match (body, smooth) {
        (Body::Ellipse, true) => SharedShape::new(Ellipse::new(0.5, 0.2)),
        (Body::Heptagon, true) => SharedShape::new(RoundedPolygon::regular(7, 0.5, 0.05)),
        (Body::Ellipse, false) => {
            let pts = (0..64)
                .map(|k| {
                    let a = TAU * k as f32 / 64.0;
                    Vector::new(0.5 * a.cos(), 0.2 * a.sin())
                })
                .collect();
            SharedShape::convex_polyline(pts).expect("a convex 64-gon")
        }
        (Body::Heptagon, false) => {
            let h = RoundedPolygon::regular(7, 0.5, 0.05);
            SharedShape::round_convex_polyline(h.vertices(), h.corner_radius()).expect("a convex heptagon")
        }
    }
}

/// Fires `shot` at the wall (no gravity, CCD on, never asleep) for [`SHOT_STEPS`] steps: the
/// first step after which the body's centre is past the wall's far face, if any (tunnelled), and
/// the deepest the body reached into the wall after a step (its support point along +x past the
/// near face: the body stays well within the wall's height).
fn fire(shot: Shot, smooth: bool) -> (Option<usize>, f32) {
    let mut w = world(smooth, Vector::ZERO);
    w.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(WALL_X, 0.0)),
        ColliderBuilder::cuboid(WALL_HALF, WALL_HALF_HEIGHT),
    );
    let (h, c) = w.insert(
        RigidBodyBuilder::dynamic()
            .rotation(shot.angle0)
            .linvel(Vector::new(shot.speed, 0.0))
            .angvel(shot.spin)
            // Spins above π/4 a step (47 rad/s at 60 Hz) are rapier's cap: lifted for the spin
            // claimed to be the spin simulated.
            .allow_fast_rotation(shot.spin.abs() / 60.0 > core::f32::consts::FRAC_PI_4)
            .ccd_enabled(true)
            .can_sleep(false),
        ColliderBuilder::new(shot_shape(shot.body, smooth)),
    );
    let mut deepest = 0.0f32;
    let through = (1..=SHOT_STEPS).find(|_| {
        w.step();
        let co = &w.colliders[c];
        let support = co.shape().as_support_map().expect("a convex shot");
        deepest = deepest.max(support.support_point(co.position(), Vector::X).x - (WALL_X - WALL_HALF));
        w.bodies[h].translation().x > WALL_X + WALL_HALF
    });
    (through, deepest)
}

/// Pins rapier's CCD through the f32 `SmoothDispatcher`: none of 40 fast spinning shots (20
/// ellipses, 20 rounded heptagons; 50–300 m/s, i.e. 0.8–5 m a step, against a 0.04 wall; spins
/// 20–60 rad/s of both signs) gets its centre past the wall's far face. The same shots with
/// parry's polygons under rapier's default narrow phase are counted, not asserted.
#[test]
fn forty_fast_spinning_shots_do_not_tunnel_through_a_thin_wall() {
    let shots = shots();
    let t = Instant::now();
    let runs: Vec<_> = shots.iter().map(|&s| fire(s, true)).collect();
    let t_smooth = t.elapsed().as_secs_f64();
    let polygon = shots.iter().filter(|&&s| fire(s, false).0.is_some()).count();
    let tunnelled: Vec<_> = shots
        .iter()
        .zip(&runs)
        .filter_map(|(s, r)| r.0.map(|k| (*s, k)))
        .collect();
    let (deep_at, deepest) = runs
        .iter()
        .enumerate()
        .fold((0, 0.0f32), |a, (i, r)| if r.1 > a.1 { (i, r.1) } else { a });
    println!(
        "f32 wall shots: {} cases (20 ellipses 0.5x0.2, 20 rounded heptagons; 50-300 m/s, spins 20-60 rad/s, \
         wall 0.04 thick, {SHOT_STEPS} steps at 60 Hz); tunnelled: SmoothDispatcher {} ({t_smooth:.2} s; deepest into \
         the wall {deepest:.4}, shot {deep_at}: {:?} {:.1} m/s {:.1} rad/s), parry's polygons (64-gon, \
         RoundConvexPolygon) under NarrowPhase::new() {polygon}",
        shots.len(),
        tunnelled.len(),
        shots[deep_at].body,
        shots[deep_at].speed,
        shots[deep_at].spin
    );
    for (s, step) in &tunnelled {
        println!(
            "  tunnelled: {:?} speed {} m/s, spin {} rad/s, angle0 {} rad, past the far face after step {step}",
            s.body, s.speed, s.spin, s.angle0
        );
    }
    assert!(tunnelled.is_empty(), "tunnelled with SmoothDispatcher: {tunnelled:?}");
}

/// A small pile: ellipses and rounded polygons dropped on a ground box (top face at y = 0.5),
/// plus one fast CCD ellipse shot into it, 400 steps; the bodies' poses and velocities as bits.
fn pile_run() -> Vec<u32> {
    let mut w = world(true, GRAVITY);
    w.insert(RigidBodyBuilder::fixed(), ColliderBuilder::cuboid(20.0, 0.5));
    let mut handles = Vec::new();
    for i in 0..6 {
        let shape = if i % 2 == 0 {
            SharedShape::new(Ellipse::new(0.5, 0.2))
        } else {
            SharedShape::new(RoundedPolygon::regular(3 + i, 0.4, 0.03))
        };
        let body = RigidBodyBuilder::dynamic()
            .translation(Vector::new(-4.0 + 1.3 * i as f32, 1.5 + 0.7 * i as f32))
            .rotation(0.4 * i as f32)
            .angvel(3.0 - i as f32)
            .ccd_enabled(true);
        handles.push(w.insert(body, ColliderBuilder::new(shape)).0);
    }
    let shot = RigidBodyBuilder::dynamic()
        .translation(Vector::new(-10.0, 1.0))
        .linvel(Vector::new(200.0, 0.0))
        .angvel(150.0)
        .ccd_enabled(true);
    handles.push(
        w.insert(shot, ColliderBuilder::new(SharedShape::new(Ellipse::new(0.3, 0.1))))
            .0,
    );
    for _ in 0..400 {
        w.step();
    }
    handles
        .iter()
        .flat_map(|&h| {
            let rb = &w.bodies[h];
            let (t, r, v) = (rb.translation(), rb.rotation(), rb.linvel());
            [t.x, t.y, r.re, r.im, v.x, v.y, rb.angvel()].map(f32::to_bits)
        })
        .collect()
}

/// Pins determinism in f32: the same pile with a fast CCD shot (`pile_run`), run twice in one
/// process, ends with every body's position, rotation and velocities bit for bit the same.
#[test]
fn same_f32_scene_twice_is_bit_identical() {
    let t = Instant::now();
    let (a, b) = (pile_run(), pile_run());
    let same = a.iter().zip(&b).filter(|(x, y)| x == y).count();
    println!(
        "determinism: {same}/{} state words bit-identical ({:.2} s)",
        a.len(),
        t.elapsed().as_secs_f64()
    );
    assert_eq!(a, b);
}

/// Pins the f32 contact manifold against a box: an ellipse 0.5 × 0.2 dropped with a small tilt
/// onto a ground box settles lying on its long side, its centre 0.2 (the short semi-axis) above
/// the ground face, within 1e-3 (as the f64 crate's test).
#[test]
fn ellipse_settles_on_its_short_semi_axis_in_f32() {
    let mut w = world(true, GRAVITY);
    // Top face at y = 0.5.
    w.insert(RigidBodyBuilder::fixed(), ColliderBuilder::cuboid(20.0, 0.5));
    let (h, _) = w.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 1.5))
            .rotation(0.3)
            // Rolling without slipping dissipates almost nothing in rapier: damp the rocking.
            .angular_damping(1.0)
            .can_sleep(false),
        ColliderBuilder::new(SharedShape::new(Ellipse::new(0.5, 0.2))),
    );
    let expected = 0.5 + 0.2;
    let (steps, watch) = (3000, 300);
    let (mut min_y, mut max_err, mut max_angle) = (f32::INFINITY, 0.0f32, 0.0f32);
    for i in 0..steps {
        w.step();
        let rb = &w.bodies[h];
        let y = rb.translation().y;
        min_y = min_y.min(y);
        if i >= steps - watch {
            max_err = max_err.max((y - expected).abs());
            // Lying on its long side: the long axis horizontal (angle ≡ 0 mod π).
            let a = rb.rotation().angle().rem_euclid(PI);
            max_angle = max_angle.max(a.min(PI - a));
        }
    }
    let y = w.bodies[h].translation().y;
    let err = y - expected;
    println!(
        "f32 ellipse settle: final y = {y:.6} (expected {expected}), error = {err:.3e}; over the last {watch} steps: \
         max |height error| = {max_err:.3e}, residual rocking amplitude = {max_angle:.3e} rad; lowest y during the \
         run = {min_y:.5}"
    );
    assert!(err.abs() < 1e-3, "settle height error {err}");
    assert!(max_err < 1e-3, "height error over the last steps {max_err}");
    assert!(max_angle < 0.1, "not lying on its long side: {max_angle}");
}
