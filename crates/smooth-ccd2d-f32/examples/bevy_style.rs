//! A Bevy-style scene in f32, headless: a rapier2d (f32, the build bevy_rapier2d uses) world
//! stepped at 60 Hz under gravity −9.81, with the crate adopted in one line — the narrow phase
//! `NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())` (in a Bevy app, the narrow
//! phase of the rapier context, set before colliders are added). Exact ellipses and rounded
//! heptagons are dropped on a ground, and a fast spinning ellipse (CCD on, as bevy_rapier2d's
//! `Ccd::enabled()`) is shot at a wall 0.04 thick. Prints where each body came to rest, the rest
//! heights against the shapes' exact dimensions, and that the shot did not pass the wall.
//!
//! Run: `cargo run --release -p smooth-ccd2d-f32 --example bevy_style`

use rapier2d::prelude::*;
use smooth_ccd2d_f32::{Ellipse, RoundedPolygon, SmoothDispatcher};

/// The wall's centre x (it is 0.04 thick and stands on the ground, whose top face is at y = 0).
const WALL_X: f32 = 6.0;
/// The wall's half-thickness.
const WALL_HALF: f32 = 0.02;
/// The wall's half-height.
const WALL_HALF_HEIGHT: f32 = 1.5;
/// Simulated time: 20 s at 60 Hz.
const STEPS: usize = 1200;

/// What was dropped, for the report: a name and the height its centre should rest at.
struct Dropped {
    handle: RigidBodyHandle,
    name: String,
    rest_height: f32,
    why: &'static str,
}

/// Builds the scene, runs it for [`STEPS`] steps and prints the report.
fn main() {
    let mut world = PhysicsWorld {
        gravity: Vector::new(0.0, -9.81),
        // The one line that adopts the crate.
        narrow_phase: NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = 1.0 / 60.0;

    // Ground (top face at y = 0) and the thin wall standing on it.
    world.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(0.0, -0.5)),
        ColliderBuilder::cuboid(30.0, 0.5),
    );
    world.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(WALL_X, WALL_HALF_HEIGHT)),
        ColliderBuilder::cuboid(WALL_HALF, WALL_HALF_HEIGHT),
    );

    // Three ellipses and three rounded heptagons, dropped with small tilts.
    let mut dropped = Vec::new();
    for (i, (a, b)) in [(0.5f32, 0.2f32), (0.4, 0.25), (0.3, 0.15)].into_iter().enumerate() {
        let body = RigidBodyBuilder::dynamic()
            .translation(Vector::new(-14.0 + 3.0 * i as f32, 1.0))
            .rotation(0.2 + 0.1 * i as f32)
            // Rolling without slipping barely dissipates in rapier: damp the rocking.
            .angular_damping(2.0);
        let collider = ColliderBuilder::new(SharedShape::new(Ellipse::new(a, b))).friction(0.6);
        dropped.push(Dropped {
            handle: world.insert(body, collider).0,
            name: format!("ellipse {a}x{b}"),
            rest_height: b,
            why: "short semi-axis",
        });
    }
    let (circumradius, corner) = (0.35f32, 0.05f32);
    // Lying on a face: the core heptagon's apothem plus the corner radius.
    let apothem = circumradius * (std::f32::consts::PI / 7.0).cos() + corner;
    for i in 0..3 {
        let body = RigidBodyBuilder::dynamic()
            .translation(Vector::new(-4.0 + 3.0 * i as f32, 1.0))
            .rotation(0.3 * i as f32);
        let collider = ColliderBuilder::new(SharedShape::new(RoundedPolygon::regular(7, circumradius, corner)));
        dropped.push(Dropped {
            handle: world.insert(body, collider).0,
            name: format!("heptagon #{i}"),
            rest_height: apothem,
            why: "apothem + corner radius",
        });
    }

    // The shot, from the far side of the wall: a spinning ellipse at 240 m/s (4 m a step, a
    // hundred times the wall's thickness).
    let (shot, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(20.0, 1.0))
            .rotation(0.7)
            .linvel(Vector::new(-240.0, 0.0))
            .angvel(45.0)
            .ccd_enabled(true),
        ColliderBuilder::new(SharedShape::new(Ellipse::new(0.3, 0.12))),
    );

    // The shot comes from +x: it passed the wall if its centre got left of the far face.
    let far_face = WALL_X - WALL_HALF;
    let mut shot_min_x = f32::INFINITY;
    let t = std::time::Instant::now();
    for _ in 0..STEPS {
        world.step();
        shot_min_x = shot_min_x.min(world.bodies[shot].translation().x);
    }
    let seconds = t.elapsed().as_secs_f64();

    println!(
        "{STEPS} steps at 60 Hz ({:.1} s simulated) in {seconds:.3} s",
        STEPS as f32 / 60.0
    );
    println!("where each body came to rest (ground top face at y = 0):");
    for d in &dropped {
        let rb = &world.bodies[d.handle];
        let (p, angle) = (rb.translation(), rb.rotation().angle());
        println!(
            "  {:<16} x = {:7.3}, y = {:.4} (expected {:.4}, {}: error {:+.1e}), angle {angle:+.3} rad, {}",
            d.name,
            p.x,
            p.y,
            d.rest_height,
            d.why,
            p.y - d.rest_height,
            if rb.is_sleeping() { "asleep" } else { "awake" }
        );
    }
    let rb = &world.bodies[shot];
    println!(
        "shot (ellipse 0.3x0.12 from x = 20, 240 m/s towards -x, 45 rad/s, CCD): leftmost centre x = {shot_min_x:.3}, \
         now at ({:.3}, {:.3}); wall faces at x = {:.2} (hit) and {far_face:.2}: {}",
        rb.translation().x,
        rb.translation().y,
        WALL_X + WALL_HALF,
        if shot_min_x > far_face {
            "did not pass the wall"
        } else {
            "PASSED THROUGH THE WALL"
        }
    );
}
