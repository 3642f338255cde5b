//! A smooth body rocking on a flat floor in rapier, headless (`examples/rocking.rs` prints its
//! table, `tests/rocking_on_a_floor.rs` pins its facts): a body set down at rest tilted by
//! [`TILT`] on a box floor (friction 0.5, 60 Hz) — this crate's `Ellipse` [`A`] × [`B`] with
//! `SmoothDispatcher`, parry's inscribed polygons of it on rapier's default narrow phase, or a
//! disc whose centre of mass is below its centre (a weeble: this crate's disc, or parry's `Ball`)
//! — under rapier's defaults or one setting changed. Rocking without slipping conserves energy;
//! rapier's solver, which runs a step in substeps with each contact tracked by body-fixed points
//! and warm-started from substep to substep, adds energy where the contact point rolls along the
//! body.
#![allow(dead_code)]

use super::world::{World, GRAVITY};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{Ellipse, SmoothDispatcher};

/// The ellipse's semi-axes and the tilt every body starts from, at rest.
pub const A: f64 = 0.5;
pub const B: f64 = 0.2;
pub const TILT: f64 = 0.1;

/// The weeble: a disc of this radius with its centre of mass this far below its centre (mass 1,
/// angular inertia 0.02 about the centre of mass).
pub const WEEBLE_RADIUS: f64 = 0.25;
pub const WEEBLE_DROP: f64 = 0.1;

/// The rocking body.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum Body {
    /// This crate's `Ellipse` A × B with `SmoothDispatcher`.
    Exact,
    /// parry's convex polygon of `n` vertices on the ellipse, rapier's default narrow phase.
    Polygon(usize),
    /// The weeble: this crate's disc with `SmoothDispatcher`, or parry's `Ball` with rapier's
    /// default narrow phase (`parry`).
    Weeble { parry: bool },
}

impl Body {
    /// The body's name in tables.
    pub fn name(self) -> String {
        match self {
            Body::Exact => "Ellipse, SmoothDispatcher".into(),
            Body::Polygon(n) => format!("{n}-gon, rapier's default"),
            Body::Weeble { parry: false } => "weeble: disc, SmoothDispatcher".into(),
            Body::Weeble { parry: true } => "weeble: parry's Ball, rapier's default".into(),
        }
    }
}

/// What differs from rapier's defaults.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum Setting {
    Defaults,
    NoRecycling,
    /// A step of 1/240 s.
    SmallStep,
    /// Angular damping on the body.
    Damped(f64),
    /// `num_solver_iterations` (rapier's substeps; 4 by default).
    SolverIterations(usize),
    /// `warmstart_coefficient` 0.
    NoWarmStart,
}

impl Setting {
    /// The setting's name in tables.
    pub fn name(self) -> String {
        match self {
            Setting::Defaults => "rapier's defaults".into(),
            Setting::NoRecycling => "contact recycling off".into(),
            Setting::SmallStep => "step 1/240 s".into(),
            Setting::Damped(d) => format!("angular damping {d}"),
            Setting::SolverIterations(n) => format!("{n} solver iteration{}", if n == 1 { "" } else { "s" }),
            Setting::NoWarmStart => "no warm start".into(),
        }
    }
}

/// One run: the tilt at the start, then the largest tilt over each window; the mechanical energy
/// (J, kinetic and potential with the floor's top as zero) at the start and at the end of each
/// window; whether the body sleeps at the end.
pub struct Rock {
    pub tilts: Vec<f64>,
    pub energies: Vec<f64>,
    pub asleep: bool,
}

/// The body's mechanical energy (J): kinetic, and potential of its centre of mass with the
/// floor's top as zero.
fn energy(rb: &RigidBody) -> f64 {
    let inertia = rb.mass_properties().effective_angular_inertia();
    0.5 * rb.mass() * rb.linvel().length_squared()
        + 0.5 * inertia * rb.angvel() * rb.angvel()
        + rb.mass() * -GRAVITY.y * rb.center_of_mass().y
}

/// `body` rocking under `setting` for `seconds`, reported in windows of `window` seconds.
pub fn rock(body: Body, setting: Setting, seconds: usize, window: usize) -> Rock {
    let smooth = !matches!(body, Body::Polygon(_) | Body::Weeble { parry: true });
    let narrow_phase = if smooth {
        NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
    } else {
        NarrowPhase::new()
    };
    let mut w = World::new(narrow_phase);
    match setting {
        Setting::NoRecycling => w.params.contact_recycling = false,
        Setting::SmallStep => w.params.dt = 1.0 / 240.0,
        Setting::SolverIterations(n) => w.params.num_solver_iterations = n,
        Setting::NoWarmStart => w.params.warmstart_coefficient = 0.0,
        Setting::Defaults | Setting::Damped(_) => {}
    }
    let damping = if let Setting::Damped(d) = setting { d } else { 0.0 };
    w.colliders
        .insert(ColliderBuilder::cuboid(20.0, 0.5).translation(Vector::new(0.0, -0.5)));
    let weeble = MassProperties::new(Vector::new(0.0, -WEEBLE_DROP), 1.0, 0.02);
    let (collider, height) = match body {
        // Resting on its lowest point: the support of the tilted ellipse along −y.
        Body::Exact | Body::Polygon(_) => {
            let shape = match body {
                Body::Polygon(n) => {
                    let points = (0..n)
                        .map(|i| {
                            let t = core::f64::consts::TAU * i as f64 / n as f64;
                            Vector::new(A * t.cos(), B * t.sin())
                        })
                        .collect();
                    SharedShape::convex_polyline(points).expect("a convex polygon")
                }
                _ => SharedShape::new(Ellipse::new(A, B)),
            };
            let lowest = (A * A * TILT.sin().powi(2) + B * B * TILT.cos().powi(2)).sqrt();
            (ColliderBuilder::new(shape), lowest)
        }
        Body::Weeble { parry } => {
            let shape = if parry {
                SharedShape::ball(WEEBLE_RADIUS)
            } else {
                SharedShape::new(Ellipse::new(WEEBLE_RADIUS, WEEBLE_RADIUS))
            };
            (ColliderBuilder::new(shape).mass_properties(weeble), WEEBLE_RADIUS)
        }
    };
    let (h, _) = w.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, height))
            .rotation(TILT)
            .angular_damping(damping),
        collider.friction(0.5),
    );
    let steps_per_window = (window as f64 / w.params.dt).round() as usize;
    let (mut tilts, mut energies) = (vec![TILT], vec![energy(&w.bodies[h])]);
    for _ in 0..seconds / window {
        let mut tilt = 0.0f64;
        for _ in 0..steps_per_window {
            w.step(GRAVITY, &());
            tilt = tilt.max(w.bodies[h].rotation().angle().abs());
        }
        energies.push(energy(&w.bodies[h]));
        tilts.push(tilt);
    }
    Rock {
        tilts,
        energies,
        asleep: w.bodies[h].is_sleeping(),
    }
}

/// The body's mechanical energy lying at rest on the floor, upright (its centre of mass at its
/// lowest).
pub fn rest_energy(body: Body) -> f64 {
    match body {
        Body::Exact | Body::Polygon(_) => core::f64::consts::PI * A * B * -GRAVITY.y * B,
        Body::Weeble { .. } => -GRAVITY.y * (WEEBLE_RADIUS - WEEBLE_DROP),
    }
}
