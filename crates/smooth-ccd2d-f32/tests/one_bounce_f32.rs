//! `OneBounceHooks` in rapier2d (f32): two spinning flat-sided bullets shot head-on with the
//! f32 moving-pairs pass and restitution 1 gain no kinetic energy with the hooks, where
//! `CoreContactHooks` alone let Box2D's restitution on a flat side's two points add some.
//!
//! `cargo test --release -p smooth-ccd2d-f32 --test one_bounce_f32 -- --nocapture` prints the
//! counts.

use rapier2d::prelude::*;
use smooth_ccd2d_f32::{CoreContactHooks, MovingPairs, OneBounceHooks, RoundedPolygon};

mod uncapped;
use uncapped::uncapped_world;

/// A gain: kinetic energy after above before by more than this fraction (f32 rounding of the
/// solver's sums: about a hundred units in the last place of an f32).
const ROUNDING: f64 = 1e-5;

/// The shapes: a parry2d box, a rounded hexagon, a parry2d triangle.
fn shape(k: usize) -> SharedShape {
    match k % 3 {
        0 => SharedShape::cuboid(0.4, 0.15),
        1 => SharedShape::new(RoundedPolygon::regular(6, 0.4, 0.05)),
        _ => SharedShape::triangle(
            Vector::new(0.45, 0.0),
            Vector::new(-0.225, 0.39),
            Vector::new(-0.225, -0.39),
        ),
    }
}

/// Kinetic energy ½ m |v|² + ½ I ω² of every body, in f64.
fn energy(bodies: &RigidBodySet) -> f64 {
    bodies
        .iter()
        .map(|(_, rb)| {
            let inv_i = f64::from(rb.mass_properties().local_mprops.inv_principal_inertia);
            let spin = if inv_i > 0.0 {
                f64::from(rb.angvel()).powi(2) / inv_i
            } else {
                0.0
            };
            0.5 * (f64::from(rb.mass()) * f64::from(rb.linvel().length_squared()) + spin)
        })
        .sum()
}

/// Energy after over before of one head-on shot: shapes `a`, `b`, each at `speed` towards the
/// other, spins `spins`, initial angles `angles`, 20 steps of 1/60 s with the pass and `hooks`.
fn shot(a: usize, b: usize, speed: f32, spins: (f32, f32), angles: (f32, f32), hooks: &dyn PhysicsHooks) -> f64 {
    let mut w = uncapped_world();
    for (k, x, v, spin, angle) in [(a, -3.0, speed, spins.0, angles.0), (b, 3.0, -speed, spins.1, angles.1)] {
        let body = w.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, 0.0))
                .rotation(angle)
                .linvel(Vector::new(v, 0.0))
                .angvel(spin)
                .allow_fast_rotation(true)
                .ccd_enabled(true)
                .can_sleep(false),
        );
        let collider = ColliderBuilder::new(shape(k))
            .restitution(1.0)
            .friction(0.5)
            .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
        w.colliders.insert_with_parent(collider, body, &mut w.bodies);
    }
    let e0 = energy(&w.bodies);
    let mut pass = MovingPairs::default();
    for _ in 0..20 {
        pass.before_step(&w.bodies);
        w.step_with_events(hooks, &());
        pass.after_step(&w.integration_parameters, &mut w.bodies, &mut w.colliders, hooks, &());
    }
    energy(&w.bodies) / e0
}

/// Every pair of the three flat-sided shapes, four speeds, three spins: no gain with
/// `OneBounceHooks`; some with `CoreContactHooks` (the scene tests the rule).
#[test]
fn one_bounce_hooks_keep_flat_sided_head_on_collisions_from_gaining_energy_in_f32() {
    let (mut cases, mut worst, mut gained_core, mut worst_core) = (0, 0.0f64, 0, 0.0f64);
    for a in 0..3 {
        for b in a..3 {
            for speed in [100.0, 300.0, 1000.0, 3000.0] {
                for spins in [(0.0, 0.0), (150.0, -90.0), (-600.0, 600.0)] {
                    let angles = ((0.37 * cases as f32) % 3.1, (1.13 * cases as f32) % 3.1);
                    let r = shot(a, b, speed, spins, angles, &OneBounceHooks);
                    assert!(
                        r <= 1.0 + ROUNDING,
                        "shapes {a}/{b} at {speed} m/s, spins {spins:?}: ×{r}"
                    );
                    worst = worst.max(r);
                    let core = shot(a, b, speed, spins, angles, &CoreContactHooks);
                    gained_core += usize::from(core > 1.0 + ROUNDING);
                    worst_core = worst_core.max(core);
                    cases += 1;
                }
            }
        }
    }
    println!(
        "{cases} f32 head-on shots: largest energy after/before {worst:.9} with OneBounceHooks; with \
         CoreContactHooks {gained_core} gain, largest {worst_core:.4}"
    );
    assert_eq!(cases, 72);
    assert!(
        gained_core > 0,
        "CoreContactHooks gained in no shot: the scene does not test the rule"
    );
}
