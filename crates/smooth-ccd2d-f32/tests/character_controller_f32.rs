//! rapier2d's (f32) `KinematicCharacterController` with this package's shapes — the controller
//! bevy_rapier2d drives — the f32 counterpart of the root crate's
//! `tests/character_controller.rs`: a character walked along the ground into a wall stops at the
//! controller's offset from it, each of the controller's converged cast hits is that offset from
//! what it hit (to f32 rounding), and it is grounded from its landing on.

use rapier2d::control::KinematicCharacterController;
use rapier2d::parry::query::{QueryDispatcher, ShapeCastStatus};
use rapier2d::prelude::*;
use smooth_ccd2d_f32::{CapsuleEllipse, Ellipse, RoundedPolygon, SmoothDispatcher};

/// One step (60 Hz), the walking speed (m/s) and the steps of the walk (10 s).
const DT: f32 = 1.0 / 60.0;
const SPEED: f32 = 2.0;
const STEPS: usize = 600;

#[test]
fn an_f32_character_of_this_packages_shapes_stops_at_a_wall_at_the_controllers_offset() {
    let corner = 0.05;
    let (hw, hh) = (0.3f32, 0.5f32);
    let box_core = [
        Vector::new(-hw + corner, -hh + corner),
        Vector::new(hw - corner, -hh + corner),
        Vector::new(hw - corner, hh - corner),
        Vector::new(-hw + corner, hh - corner),
    ];
    let characters: [(&str, SharedShape); 3] = [
        ("ellipse 0.3 × 0.5", SharedShape::new(Ellipse::new(hw, hh))),
        (
            "rounded box 0.6 × 1",
            SharedShape::new(RoundedPolygon::new(&box_core, corner)),
        ),
        (
            "capsule-ellipse 0.6 × 1",
            SharedShape::new(CapsuleEllipse::new(0.3, 0.2, 0.3)),
        ),
    ];
    let wall_x = 2.0f32;
    let mut w = PhysicsWorld {
        narrow_phase: NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
        ..PhysicsWorld::default()
    };
    w.colliders
        .insert(ColliderBuilder::cuboid(20.0, 0.5).translation(Vector::new(0.0, -0.5)));
    w.colliders.insert(ColliderBuilder::segment(
        Vector::new(wall_x, 0.0),
        Vector::new(wall_x, 3.0),
    ));
    w.step();
    let ctl = KinematicCharacterController::default();
    // The controller's offset: 1 % of the character's height.
    let offset = 0.01 * 2.0 * hh;
    for (name, shape) in characters {
        let mut pos = Pose::from_translation(Vector::new(-4.0, hh + 0.7));
        let (mut vy, mut grounded, mut hits, mut worst) = (0.0f32, 0, 0, 0.0f32);
        for _ in 0..STEPS {
            let q = w.broad_phase.as_query_pipeline(
                w.narrow_phase.query_dispatcher(),
                &w.bodies,
                &w.colliders,
                QueryFilter::default(),
            );
            vy -= 9.81 * DT;
            let mut collisions = vec![];
            let mv = ctl.move_shape(DT, &q, &*shape, &pos, Vector::new(SPEED * DT, vy * DT), |c| {
                collisions.push(c)
            });
            for c in collisions.iter().filter(|c| c.hit.status == ShapeCastStatus::Converged) {
                let other = &w.colliders[c.handle];
                let gap = SmoothDispatcher::default()
                    .distance(&c.character_pos.inv_mul(other.position()), &*shape, other.shape())
                    .expect("a distance")
                    .distance;
                worst = worst.max((gap - offset).abs());
                hits += 1;
            }
            if mv.grounded {
                vy = 0.0;
                grounded += 1;
            }
            pos.translation += mv.translation;
            assert!(pos.translation.is_finite(), "{name}");
        }
        let expected = Vector::new(wall_x - hw - offset, hh + offset);
        println!(
            "{name}: ends at ({:.6}, {:.6}), expected ({:.6}, {:.6}); grounded {grounded} of {STEPS}; {hits} cast hits, the gap off by {worst:.1e} at most",
            pos.translation.x, pos.translation.y, expected.x, expected.y
        );
        // The controller's nudge off a surface it slides on (1e-4) and f32 rounding at 2 m.
        assert!((pos.translation - expected).abs().max_element() < 2e-4, "{name}");
        assert!(hits > 0 && worst < 1e-5, "{name}: the gap off by {worst}");
        assert!(grounded >= STEPS - 30, "{name}: grounded {grounded}");
    }
}
