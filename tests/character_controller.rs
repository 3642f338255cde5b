//! rapier's scene queries and its `KinematicCharacterController` on this crate's shapes — what a
//! game does besides stepping the world: a player shape walked through a level by shape casts,
//! grounded by contact manifolds, pushing the bodies it meets; rays, point projections and shape
//! casts through `QueryPipeline`.
//!
//! The queries go through the dispatcher the narrow phase holds
//! (`narrow_phase.query_dispatcher()`, rapier's documented way to build a `QueryPipeline`), so
//! `SmoothDispatcher` answers the controller's casts exactly. rapier's controller computes its
//! ground and its pushes with parry's `DefaultQueryDispatcher` whatever the narrow phase holds (a
//! `TODO` in its source); that dispatcher reads this crate's shapes through their support maps,
//! so grounding and pushing work too, on parry's approximate manifold of the support maps.
//!
//! Each test names the behaviour it pins and checks it against the closed-form answer (where the
//! controller must stop: the wall minus the half width minus the controller's offset) and, where
//! no closed form exists, against the same scene on parry's own shapes.

#[path = "common/world.rs"]
mod world;

use rapier2d_f64::control::{CharacterAutostep, CharacterCollision, KinematicCharacterController};
use rapier2d_f64::parry::query::QueryDispatcher;
use rapier2d_f64::parry::query::{ShapeCastOptions, ShapeCastStatus};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{CapsuleEllipse, Ellipse, RoundedPolygon, SmoothDispatcher};
use world::World;

/// One step of the walks (60 Hz).
const DT: f64 = 1.0 / 60.0;
/// The walking speed, m/s.
const SPEED: f64 = 2.0;
/// Steps of each walk (10 s).
const STEPS: usize = 600;

/// The character shapes of the crate with their half width and half height: an ellipse, a
/// rounded box and a capsule-ellipse (the player shapes a game would take).
fn characters() -> Vec<(&'static str, SharedShape, f64, f64)> {
    let corner = 0.05;
    let (hw, hh) = (0.3, 0.5);
    let box_core = [
        Vector::new(-hw + corner, -hh + corner),
        Vector::new(hw - corner, -hh + corner),
        Vector::new(hw - corner, hh - corner),
        Vector::new(-hw + corner, hh - corner),
    ];
    vec![
        ("ellipse 0.3 × 0.5", SharedShape::new(Ellipse::new(hw, hh)), hw, hh),
        (
            "rounded box 0.6 × 1",
            SharedShape::new(RoundedPolygon::new(&box_core, corner)),
            hw,
            hh,
        ),
        // A half-ellipse 0.3 × 0.5 on the left, arcs of radius 0.3 and a 0.4 long upright flat
        // side on the right: 0.6 m wide, 1 m tall, centred.
        (
            "capsule-ellipse 0.6 × 1",
            SharedShape::new(CapsuleEllipse::new(0.3, 0.2, 0.3)),
            hw,
            hh,
        ),
    ]
}

/// A world of fixed colliders stepped once (the broad phase holds them), with `SmoothDispatcher`.
fn level(colliders: Vec<ColliderBuilder>) -> World {
    let mut w = World::new(narrow_phase(true));
    for c in colliders {
        w.colliders.insert(c);
    }
    w.step(world::GRAVITY, &());
    w
}

/// `SmoothDispatcher` as the narrow phase's dispatcher (`smooth`), or rapier's default.
fn narrow_phase(smooth: bool) -> NarrowPhase {
    if smooth {
        NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
    } else {
        NarrowPhase::new()
    }
}

/// The flat ground: its top at y = 0.
fn ground() -> ColliderBuilder {
    ColliderBuilder::cuboid(20.0, 0.5).translation(Vector::new(0.0, -0.5))
}

/// What a walk ended with.
struct Walk {
    pos: Vector,
    grounded_steps: usize,
    /// Whether any position along the walk was not finite.
    finite: bool,
    /// The largest |distance − offset| at the controller's converged cast hits.
    worst_gap_error: f64,
    /// The controller's converged cast hits.
    converged_hits: usize,
}

/// Walks `shape` from x = −4 (feet 0.7 m above the ground) right at [`SPEED`] for [`STEPS`]
/// steps under gravity, as a game's player loop does: the controller's effective translation is
/// applied, the fall speed reset when it reports the character grounded.
fn walk(w: &World, ctl: &KinematicCharacterController, shape: &dyn Shape, half_height: f64) -> Walk {
    let mut pos = Pose::from_translation(Vector::new(-4.0, half_height + 0.7));
    let mut vy = 0.0;
    let mut grounded_steps = 0;
    let mut finite = true;
    let (mut worst_gap_error, mut converged_hits) = (0.0f64, 0);
    for _ in 0..STEPS {
        let q = w.broad_phase.as_query_pipeline(
            w.narrow_phase.query_dispatcher(),
            &w.bodies,
            &w.colliders,
            QueryFilter::default(),
        );
        vy -= 9.81 * DT;
        let mut hits = vec![];
        let mv = ctl.move_shape(DT, &q, shape, &pos, Vector::new(SPEED * DT, vy * DT), |c| hits.push(c));
        // Every cast the controller made that came back converged: the character, at the pose
        // the controller moved it to, is the cast's target distance (the controller's offset)
        // from what it hit, exactly (the exact distance of `SmoothDispatcher`, to 1e-12 m).
        for c in hits.iter().filter(|c| c.hit.status == ShapeCastStatus::Converged) {
            let other = &w.colliders[c.handle];
            let pos12 = c.character_pos.inv_mul(other.position());
            let d = SmoothDispatcher::default()
                .distance(&pos12, shape, other.shape())
                .expect("a distance")
                .distance;
            worst_gap_error = worst_gap_error.max((d - offset(half_height)).abs());
            converged_hits += 1;
        }
        if mv.grounded {
            vy = 0.0;
            grounded_steps += 1;
        }
        pos.translation += mv.translation;
        finite &= pos.translation.is_finite();
    }
    Walk {
        pos: pos.translation,
        grounded_steps,
        finite,
        worst_gap_error,
        converged_hits,
    }
}

/// The checks every walk passes: finite positions throughout, and each converged cast hit of the
/// controller exactly its offset from what it hit (to 1e-12 m).
fn assert_exact_walk(end: &Walk, what: &str) {
    assert!(end.finite, "{what}: a position was not finite");
    assert!(
        end.converged_hits > 0 && end.worst_gap_error < 1e-12,
        "{what}: {} hits, gap off by {:e}",
        end.converged_hits,
        end.worst_gap_error
    );
}

/// How far the controller's nudge off a surface it slides on (`normal_nudge_factor`, 1e-4 by
/// default; without it the character sticks to the ground it walks on) may move it from the
/// exact stop, with the rounding of 600 steps.
const NUDGE: f64 = 1.5e-4;

/// Whether `x` lies between `exact` and `exact + band` (a band of either sign), to 1e-9.
fn in_band(x: f64, exact: f64, band: f64) -> bool {
    let (lo, hi) = if band < 0.0 {
        (exact + band, exact)
    } else {
        (exact, exact + band)
    };
    x >= lo - 1e-9 && x <= hi + 1e-9
}

/// The controller's gap to obstacles for a character `half_height` tall (its default offset,
/// 1 % of the character's height).
fn offset(half_height: f64) -> f64 {
    0.01 * 2.0 * half_height
}

#[test]
fn a_character_of_this_crates_shapes_walks_on_the_ground_and_stops_at_a_wall_at_the_controllers_offset() {
    let ctl = KinematicCharacterController::default();
    let wall_x = 2.0;
    let walls: [(&str, ColliderBuilder); 3] = [
        (
            "segment",
            ColliderBuilder::segment(Vector::new(wall_x, 0.0), Vector::new(wall_x, 3.0)),
        ),
        (
            "cuboid",
            ColliderBuilder::cuboid(0.05, 1.5).translation(Vector::new(wall_x + 0.05, 1.5)),
        ),
        (
            "rounded polygon",
            ColliderBuilder::new(SharedShape::new(RoundedPolygon::new(
                &[
                    Vector::new(wall_x + 0.02, 0.0),
                    Vector::new(wall_x + 0.08, 0.0),
                    Vector::new(wall_x + 0.08, 3.0),
                    Vector::new(wall_x + 0.02, 3.0),
                ],
                0.02,
            ))),
        ),
    ];
    for (wall_name, wall) in walls {
        let w = level(vec![ground(), wall]);
        for (name, shape, hw, hh) in characters() {
            let end = walk(&w, &ctl, &*shape, hh);
            let expected = Vector::new(wall_x - hw - offset(hh), hh + offset(hh));
            println!(
                "{name} against a {wall_name} wall: ends at ({:.9}, {:.9}), expected ({:.9}, {:.9}); grounded {} of {STEPS} steps; {} cast hits, gap off by {:.1e} at most",
                end.pos.x, end.pos.y, expected.x, expected.y, end.grounded_steps, end.converged_hits, end.worst_gap_error
            );
            assert_exact_walk(&end, &format!("{name}, {wall_name}"));
            // The controller stops at its offset from the wall and rests at its offset above the
            // ground, give or take the nudge it adds off a surface it slides on.
            assert!(
                in_band(end.pos.x, expected.x, -NUDGE),
                "{name}, {wall_name}: x {}",
                end.pos.x
            );
            assert!(
                in_band(end.pos.y, expected.y, NUDGE),
                "{name}, {wall_name}: y {}",
                end.pos.y
            );
            // Grounded from the landing on (about 0.4 s of fall) to the end.
            assert!(
                end.grounded_steps >= STEPS - 30,
                "{name}, {wall_name}: grounded {}",
                end.grounded_steps
            );
        }
    }
}

/// parry's shape closest to each of [`characters`]: a capsule for the ellipse, a rounded
/// cuboid for the rounded box and the capsule-ellipse.
fn parrys_characters() -> Vec<SharedShape> {
    vec![
        SharedShape::capsule_y(0.2, 0.3),
        SharedShape::round_cuboid(0.25, 0.45, 0.05),
        SharedShape::round_cuboid(0.25, 0.45, 0.05),
    ]
}

#[test]
fn a_character_of_this_crates_shapes_walks_on_flat_ground_and_climbs_a_step_as_far_as_parrys_own() {
    let step_height = 0.1;
    let ctl = KinematicCharacterController {
        autostep: Some(CharacterAutostep::default()),
        ..Default::default()
    };
    let stair = || ColliderBuilder::cuboid(10.0, step_height / 2.0).translation(Vector::new(12.0, step_height / 2.0));
    for with_step in [false, true] {
        let colliders = || {
            if with_step {
                vec![ground(), stair()]
            } else {
                vec![ground()]
            }
        };
        let ours = level(colliders());
        let mut parrys = World::new(narrow_phase(false));
        for c in colliders() {
            parrys.colliders.insert(c);
        }
        parrys.step(world::GRAVITY, &());
        for ((name, shape, _, hh), parry_shape) in characters().into_iter().zip(parrys_characters()) {
            let end = walk(&ours, &ctl, &*shape, hh);
            let theirs = walk(&parrys, &ctl, &*parry_shape, hh);
            let floor = if with_step { step_height } else { 0.0 };
            println!(
                "{name}, step {with_step}: ends at ({:.6}, {:.9}), grounded {} of {STEPS} steps; parry's closest shape ({:.6}, {:.9}), grounded {}",
                end.pos.x, end.pos.y, end.grounded_steps, theirs.pos.x, theirs.pos.y, theirs.grounded_steps
            );
            assert_exact_walk(&end, name);
            assert!(
                in_band(end.pos.y, floor + hh + offset(hh), NUDGE),
                "{name}, step {with_step}: y {}",
                end.pos.y
            );
            assert!(
                end.grounded_steps >= STEPS - 30,
                "{name}, step {with_step}: grounded {}",
                end.grounded_steps
            );
            // On the step when parry's shape is: past its edge at x = 2.
            assert!(
                end.pos.x > 2.0 && end.pos.x <= -4.0 + SPEED * DT * STEPS as f64 + 1e-9,
                "{name}: x {}",
                end.pos.x
            );
            assert!(
                end.pos.x >= theirs.pos.x - 0.05,
                "{name}, step {with_step}: x {} behind parry's {}",
                end.pos.x,
                theirs.pos.x
            );
        }
    }
}

#[test]
fn a_character_pushes_a_dynamic_body_of_this_crates_shapes_as_it_pushes_parrys_own() {
    // The same push on parry's shapes (a capsule pushing a ball) and on this crate's (an ellipse
    // pushing a disc-ellipse): the controller's impulses go through parry's default dispatcher,
    // which reads this crate's shapes by their support maps.
    let mut moved = vec![];
    for smooth in [false, true] {
        let np = narrow_phase(smooth);
        let mut w = World::new(np);
        w.colliders.insert(ground());
        let crate_shape = if smooth {
            SharedShape::new(Ellipse::new(0.3, 0.3))
        } else {
            SharedShape::ball(0.3)
        };
        let (h, _) = w.insert(
            RigidBodyBuilder::dynamic().translation(Vector::new(1.0, 0.3)),
            ColliderBuilder::new(crate_shape).friction(0.1),
        );
        let character = if smooth {
            SharedShape::new(Ellipse::new(0.3, 0.5))
        } else {
            SharedShape::capsule_y(0.2, 0.3)
        };
        let ctl = KinematicCharacterController::default();
        let mut pos = Pose::from_translation(Vector::new(-2.0, 0.51));
        for _ in 0..240 {
            w.step(world::GRAVITY, &());
            let mut collisions: Vec<CharacterCollision> = vec![];
            let mv = {
                let q = w.broad_phase.as_query_pipeline(
                    w.narrow_phase.query_dispatcher(),
                    &w.bodies,
                    &w.colliders,
                    QueryFilter::default(),
                );
                ctl.move_shape(DT, &q, &*character, &pos, Vector::new(SPEED * DT, -0.1 * DT), |c| {
                    collisions.push(c)
                })
            };
            let mut q = w.broad_phase.as_query_pipeline_mut(
                w.narrow_phase.query_dispatcher(),
                &mut w.bodies,
                &mut w.colliders,
                QueryFilter::default(),
            );
            ctl.solve_character_collision_impulses(DT, &mut q, &*character, 70.0, &collisions);
            pos.translation += mv.translation;
        }
        let body = w.bodies[h].translation();
        let collider = &w.colliders[w.bodies[h].colliders()[0]];
        let gap = w
            .narrow_phase
            .query_dispatcher()
            .contact(&pos.inv_mul(collider.position()), &*character, collider.shape(), 1.0)
            .expect("a contact query")
            .map_or(1.0, |c| c.dist);
        println!(
            "smooth {smooth}: the character ends at x {:.4}, the body at ({:.4}, {:.4}), {gap:.2e} m apart",
            pos.translation.x, body.x, body.y
        );
        assert!(body.is_finite() && pos.translation.is_finite());
        // Never inside the body, to the solver's resolution.
        assert!(gap > -1e-3, "smooth {smooth}: {gap}");
        moved.push(body.x - 1.0);
    }
    // Both pushed the body metres along; this crate's within a quarter of parry's.
    assert!(moved[0] > 2.0 && moved[1] > 2.0, "{moved:?}");
    assert!((moved[1] - moved[0]).abs() < 0.25 * moved[0], "{moved:?}");
}

#[test]
fn scene_queries_on_discs_of_this_crate_answer_the_closed_forms_and_as_parry_on_balls() {
    // Three discs of radius 0.5 at (−3, 0), (0, 0.3), (3, 0.6) and a polyline floor at y = −1,
    // once as this crate's `Ellipse::new(r, r)` with `SmoothDispatcher`, once as parry's `Ball`
    // with rapier's default narrow phase; a probe disc of radius 0.2 for the shape queries.
    let build = |smooth: bool| {
        let np = narrow_phase(smooth);
        let mut w = World::new(np);
        for (x, y) in [(-3.0, 0.0), (0.0, 0.3), (3.0, 0.6)] {
            let shape = if smooth {
                SharedShape::new(Ellipse::new(0.5, 0.5))
            } else {
                SharedShape::ball(0.5)
            };
            w.insert(
                RigidBodyBuilder::fixed().translation(Vector::new(x, y)),
                ColliderBuilder::new(shape),
            );
        }
        w.colliders.insert(ColliderBuilder::polyline(
            vec![Vector::new(-5.0, -1.0), Vector::new(5.0, -1.0)],
            None,
        ));
        w.step(Vector::ZERO, &());
        w
    };
    // The closed forms, in the order the queries below answer them.
    let closed = {
        // The ray from (−6, 0.3) along +x meets the first disc where (x + 3)² + 0.3² = 0.5².
        let ray_t = 3.0 - 0.4;
        // The probe (0.2, gap 0.01) along the same line: centres 0.71 apart.
        let cast_t = 3.0 - (0.71f64 * 0.71 - 0.09).sqrt();
        let n = Vector::new(-6.0 + cast_t + 3.0, 0.3) / 0.71;
        let w = Vector::new(-3.0, 0.0) + n * 0.5;
        vec![
            ray_t,
            -0.8,
            0.6, // ray: time, normal
            0.0,
            0.8, // projection of (0, 2) on the second disc
            cast_t,
            n.x,
            n.y,
            w.x,
            w.y, // cast: time, normal and witness on the disc hit
            3.0 - 0.2 + 1.0 - 0.01,
            0.0,
            1.0,
            1.5,
            -1.0, // cast down onto the floor
            1.0,
            1.0, // shapes meeting the probe at (0, 0.9), colliders holding (3, 0.6)
        ]
    };
    let mut answers: Vec<Vec<f64>> = vec![];
    for smooth in [false, true] {
        let w = build(smooth);
        let q = w.broad_phase.as_query_pipeline(
            w.narrow_phase.query_dispatcher(),
            &w.bodies,
            &w.colliders,
            QueryFilter::default(),
        );
        let probe = if smooth {
            SharedShape::new(Ellipse::new(0.2, 0.2))
        } else {
            SharedShape::ball(0.2)
        };
        let mut a = vec![];
        let ray = Ray::new(Vector::new(-6.0, 0.3), Vector::new(1.0, 0.0));
        let (_, hit) = q
            .cast_ray_and_get_normal(&ray, 100.0, true)
            .expect("the ray hits the first disc");
        a.extend([hit.time_of_impact, hit.normal.x, hit.normal.y]);
        let (_, p) = q
            .project_point(Vector::new(0.0, 2.0), 10.0, true)
            .expect("a projection");
        a.extend([p.point.x, p.point.y]);
        let options = ShapeCastOptions {
            max_time_of_impact: 100.0,
            target_distance: 0.01,
            stop_at_penetration: false,
            compute_impact_geometry_on_penetration: true,
        };
        for (start, dir) in [
            (Vector::new(-6.0, 0.3), Vector::new(1.0, 0.0)),
            (Vector::new(1.5, 3.0), Vector::new(0.0, -1.0)),
        ] {
            let (_, hit) = q
                .cast_shape(&Pose::from_translation(start), dir, &*probe, options)
                .expect("the cast hits");
            assert_eq!(hit.status, ShapeCastStatus::Converged, "smooth {smooth}");
            a.extend([
                hit.time_of_impact,
                hit.normal1.x,
                hit.normal1.y,
                hit.witness1.x,
                hit.witness1.y,
            ]);
        }
        a.push(
            q.intersect_shape(Pose::from_translation(Vector::new(0.0, 0.9)), &*probe)
                .count() as f64,
        );
        a.push(q.intersect_point(Vector::new(3.0, 0.6)).count() as f64);
        answers.push(a);
    }
    println!(
        "closed form: {closed:?}\nparry:       {:?}\nours:        {:?}",
        answers[0], answers[1]
    );
    for (i, ((c, p), o)) in closed.iter().zip(&answers[0]).zip(&answers[1]).enumerate() {
        // This crate's answers are the closed forms to rounding; parry's within its GJK's
        // tolerance (its witness on the floor is 1.5e-11 off).
        assert!((o - c).abs() <= 1e-12, "answer {i}: closed form {c}, ours {o}");
        assert!((p - c).abs() <= 1e-9, "answer {i}: closed form {c}, parry {p}");
    }
}
