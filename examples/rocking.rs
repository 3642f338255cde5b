//! A smooth body rocking on a flat floor in rapier, headless: an ellipse 0.5 × 0.2 set down at
//! rest tilted by 0.1 rad on a box floor (friction 0.5, 60 Hz, 60 s), with this crate's
//! `Ellipse` and `SmoothDispatcher`, and with parry's inscribed 256-gon and 64-gon and rapier's
//! default narrow phase. Rocking without slipping conserves energy; a rigid-body solver that
//! corrects the penetration a rolling step leaves adds some. Prints, for each body and each
//! setting (rapier's defaults; contact recycling off; a smaller step; angular damping 0.2 and 1), the
//! largest tilt over each 10 s, the mechanical energy at the end of each 10 s (J, the floor's top
//! as the height's zero) and whether the body sleeps at the end.
//!
//! Run: `cargo run --release --example rocking` (a second).

#[path = "common/mod.rs"]
mod common;

use common::world::{World, GRAVITY};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{Ellipse, SmoothDispatcher};

/// The ellipse's semi-axes and its tilt at rest at the start.
const A: f64 = 0.5;
const B: f64 = 0.2;
const TILT: f64 = 0.1;
/// Seconds simulated, reported in windows of 10 s.
const SECONDS: usize = 60;
const WINDOW: usize = 10;

/// The body: the exact ellipse, or parry's convex polygon of `n` vertices on it.
#[derive(Clone, Copy)]
enum Body {
    Exact,
    Polygon(usize),
}

/// What differs from rapier's defaults.
#[derive(Clone, Copy)]
enum Setting {
    Defaults,
    NoRecycling,
    SmallStep,
    Damped(f64),
}

impl Setting {
    fn name(self) -> &'static str {
        match self {
            Setting::Defaults => "rapier's defaults",
            Setting::NoRecycling => "contact recycling off",
            Setting::SmallStep => "step 1/240 s",
            Setting::Damped(d) if d < 0.5 => "angular damping 0.2",
            Setting::Damped(_) => "angular damping 1",
        }
    }
}

/// The body's mechanical energy (J): kinetic, and potential with the floor's top as zero.
fn energy(rb: &RigidBody) -> f64 {
    let inertia = rb.mass_properties().effective_angular_inertia();
    0.5 * rb.mass() * rb.linvel().length_squared()
        + 0.5 * inertia * rb.angvel() * rb.angvel()
        + rb.mass() * 9.81 * rb.translation().y
}

/// The tilt and the energy at the start, then the largest tilt of each window, the energy at its end, and whether the body sleeps at the end.
fn rock(body: Body, setting: Setting) -> (Vec<f64>, Vec<f64>, bool) {
    let (shape, narrow_phase) = match body {
        Body::Exact => (
            SharedShape::new(Ellipse::new(A, B)),
            NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
        ),
        Body::Polygon(n) => {
            let points = (0..n)
                .map(|i| {
                    let t = core::f64::consts::TAU * i as f64 / n as f64;
                    Vector::new(A * t.cos(), B * t.sin())
                })
                .collect();
            (
                SharedShape::convex_polyline(points).expect("a convex polygon"),
                NarrowPhase::new(),
            )
        }
    };
    let mut w = World::new(narrow_phase);
    if let Setting::NoRecycling = setting {
        w.params.contact_recycling = false;
    }
    if let Setting::SmallStep = setting {
        w.params.dt = 1.0 / 240.0;
    }
    let damping = if let Setting::Damped(d) = setting { d } else { 0.0 };
    w.colliders
        .insert(ColliderBuilder::cuboid(20.0, 0.5).translation(Vector::new(0.0, -0.5)));
    // Resting on its lowest point: the support of the tilted ellipse along −y.
    let lowest = (A * A * TILT.sin().powi(2) + B * B * TILT.cos().powi(2)).sqrt();
    let (h, _) = w.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, lowest))
            .rotation(TILT)
            .angular_damping(damping),
        ColliderBuilder::new(shape).friction(0.5),
    );
    let steps_per_window = (WINDOW as f64 / w.params.dt).round() as usize;
    let (mut tilts, mut energies) = (vec![TILT], vec![energy(&w.bodies[h])]);
    for _ in 0..SECONDS / WINDOW {
        let mut tilt = 0.0f64;
        for _ in 0..steps_per_window {
            w.step(GRAVITY, &());
            tilt = tilt.max(w.bodies[h].rotation().angle().abs());
        }
        energies.push(energy(&w.bodies[h]));
        tilts.push(tilt);
    }
    (tilts, energies, w.bodies[h].is_sleeping())
}

fn main() {
    println!("An ellipse {A} × {B} set down at rest tilted by {TILT} rad on a flat floor, friction 0.5, {SECONDS} s.");
    println!("The tilt (rad) at the start, then the largest over each {WINDOW} s; the mechanical energy (J) at the start and");
    println!("at the end of each {WINDOW} s (the floor's top as zero); whether the body sleeps at the end.\n");
    println!(
        "| body | setting | tilt: start, largest per {WINDOW} s | energy: start, end of each {WINDOW} s | asleep |"
    );
    println!("|---|---|---|---|---|");
    let bodies = [
        (Body::Exact, "Ellipse, SmoothDispatcher"),
        (Body::Polygon(256), "256-gon, rapier's default"),
        (Body::Polygon(64), "64-gon, rapier's default"),
    ];
    for setting in [
        Setting::Defaults,
        Setting::NoRecycling,
        Setting::SmallStep,
        Setting::Damped(0.2),
        Setting::Damped(1.0),
    ] {
        for (body, name) in bodies {
            let (tilts, energies, asleep) = rock(body, setting);
            let list =
                |v: &[f64], digits: usize| v.iter().map(|x| format!("{x:.digits$}")).collect::<Vec<_>>().join(", ");
            println!(
                "| {name} | {} | {} | {} | {} |",
                setting.name(),
                list(&tilts, 3),
                list(&energies, 3),
                if asleep { "yes" } else { "no" }
            );
        }
    }
}
