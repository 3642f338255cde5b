//! Headless Bevy app (bevy 0.20, `MinimalPlugins`, bevy_rapier2d 0.37): fast-spinning ellipses and
//! rounded heptagons shot with CCD at a wall 5 cm thick, with smooth-ccd2d-f32's
//! `SmoothDispatcher` in the rapier context and without it (rapier's default narrow phase, the
//! same shapes). Prints how many shots tunnel through the wall each way.
//!
//! Run (needs rustc ≥ 1.97.1, bevy 0.20's minimum): `cargo run --release` in this folder. It
//! exits with an error if a shot tunnels with the dispatcher. The three lines a Bevy game needs
//! are marked `// (1)`, `// (2)` and `// (3)`.
//!
//! Output (rustc 1.97.0-nightly 2026-05-19 with `--ignore-rust-version`, bevy 0.20.1,
//! bevy_rapier2d 0.37.0; "rapier's default" is the same shapes under parry's default
//! dispatcher):
//!
//! ```text
//! shape                    narrow phase                  shots  tunnelled
//! ellipse 0.5 x 0.2        SmoothDispatcher                 49          0
//! ellipse 0.5 x 0.2        rapier's default                 49         16
//! rounded heptagon r 0.4   SmoothDispatcher                 49          0
//! rounded heptagon r 0.4   rapier's default                 49          1
//! ```

use bevy::prelude::*;
use bevy_rapier2d::prelude::*;
use bevy_rapier2d::rapier::geometry::SharedShape;
use smooth_ccd2d_f32::{Ellipse, RoundedPolygon, SmoothDispatcher};

/// The wall's centre (x), half-thickness and half-height: its face is at x = 4.975.
const WALL_X: f32 = 5.0;
const WALL_HALF: f32 = 0.025;
const WALL_HALF_HEIGHT: f32 = 3.0;
/// Steps of 1/60 s per shot: 1/3 s, enough for the slowest shot (100 m/s) to reach the wall.
const STEPS: usize = 20;
/// Launch speeds (m/s, up to rapier's cap of 400 m/s at a length unit of 1) and spins (rad/s).
const SPEEDS: [f32; 7] = [100.0, 150.0, 200.0, 250.0, 300.0, 350.0, 400.0];
const SPINS: [f32; 7] = [0.0, 50.0, -100.0, 200.0, -300.0, 450.0, -600.0];

#[derive(Clone, Copy, Debug, PartialEq)]
enum Body {
    Ellipse,
    Heptagon,
}

/// One shot: what is shot, how, and with which narrow phase.
#[derive(Resource, Clone, Copy, Debug)]
struct Shot {
    body: Body,
    smooth: bool,
    speed: f32,
    spin: f32,
    angle0: f32,
}

/// Startup: the rapier context's narrow phase answers with the smooth dispatcher (before any
/// collider exists: bevy_rapier inserts them later in the frame), and no gravity.
fn set_up_context(mut contexts: Query<(&mut RapierContextSimulation, &mut RapierConfiguration)>, shot: Res<Shot>) {
    let (mut simulation, mut config) = contexts.single_mut().expect("the default rapier context");
    if shot.smooth {
        simulation.set_query_dispatcher(SmoothDispatcher::default()); // (1)
    }
    config.gravity = Vec2::ZERO;
}

/// Startup: the wall and the shot body.
fn spawn_scene(mut commands: Commands, shot: Res<Shot>) {
    commands.spawn((
        Transform::from_xyz(WALL_X, 0.0, 0.0),
        RigidBody::Fixed,
        Collider::cuboid(WALL_HALF, WALL_HALF_HEIGHT),
    ));
    let shape = match shot.body {
        Body::Ellipse => SharedShape::new(Ellipse::new(0.5, 0.2)),
        Body::Heptagon => SharedShape::new(RoundedPolygon::regular(7, 0.4, 0.06)),
    };
    commands.spawn((
        Transform::from_rotation(Quat::from_rotation_z(shot.angle0)),
        RigidBody::Dynamic,
        Collider::from(shape), // (2)
        Velocity {
            linear: Vec2::new(shot.speed, 0.0),
            angular: shot.spin,
        },
        Ccd::enabled(),
        AllowFastRotation, // (3): rapier caps a body's spin at about π/4 a step otherwise
        Sleeping::disabled(),
    ));
}

/// Runs one shot headless for [`STEPS`] fixed steps; returns whether it tunnelled: whether the
/// body's centre crossed the wall's mid-plane (x = [`WALL_X`]) within the wall's height (a body
/// deflected past the wall's end does not count).
fn run(shot: Shot) -> bool {
    let mut app = App::new();
    app.add_plugins((
        MinimalPlugins,
        TransformPlugin,
        RapierPhysicsPlugin::<NoUserData>::default(),
    ))
    .insert_resource(TimestepMode::Fixed {
        dt: 1.0 / 60.0,
        substeps: 1,
    })
    .insert_resource(shot)
    .add_systems(Startup, (set_up_context, spawn_scene).chain());
    app.finish();
    app.cleanup();
    let mut bodies = app.world_mut().query_filtered::<&Transform, With<Velocity>>();
    let mut before = Vec2::ZERO;
    for _ in 0..STEPS {
        app.update();
        let now = bodies
            .single(app.world())
            .expect("one shot body")
            .translation
            .truncate();
        if before.x < WALL_X && now.x >= WALL_X && before.y.abs().min(now.y.abs()) <= WALL_HALF_HEIGHT {
            return true;
        }
        before = now;
    }
    false
}

fn main() {
    println!(
        "Bevy {} headless, bevy_rapier2d 0.37: shots at a wall {} thick (face at x = {}), {} speeds {}-{} m/s x {} spins up to {} rad/s, CCD on, {} steps of 1/60 s",
        "0.20",
        2.0 * WALL_HALF,
        WALL_X - WALL_HALF,
        SPEEDS.len(),
        SPEEDS[0],
        SPEEDS[SPEEDS.len() - 1],
        SPINS.len(),
        SPINS.iter().fold(0.0f32, |m, s| m.max(s.abs())),
        STEPS
    );
    println!("tunnelled = the body's centre crosses the wall's mid-plane (x = {WALL_X}) within its height");
    println!(
        "{:<24} {:<28} {:>6} {:>10}",
        "shape", "narrow phase", "shots", "tunnelled"
    );
    let mut through_smooth = 0;
    for body in [Body::Ellipse, Body::Heptagon] {
        for smooth in [true, false] {
            let (mut shots, mut through) = (0, 0);
            for (i, &speed) in SPEEDS.iter().enumerate() {
                for (j, &spin) in SPINS.iter().enumerate() {
                    let angle0 = 0.37 * (i * SPINS.len() + j) as f32;
                    shots += 1;
                    if run(Shot {
                        body,
                        smooth,
                        speed,
                        spin,
                        angle0,
                    }) {
                        through += 1;
                    }
                }
            }
            if smooth {
                through_smooth += through;
            }
            let name = match body {
                Body::Ellipse => "ellipse 0.5 x 0.2",
                Body::Heptagon => "rounded heptagon r 0.4",
            };
            let phase = if smooth { "SmoothDispatcher" } else { "rapier's default" };
            println!("{name:<24} {phase:<28} {shots:>6} {through:>10}");
        }
    }
    if through_smooth > 0 {
        eprintln!("{through_smooth} shots tunnelled with SmoothDispatcher");
        std::process::exit(1);
    }
}
