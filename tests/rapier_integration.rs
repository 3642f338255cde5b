//! rapier2d-f64 integration of `SmoothDispatcher` as the narrow phase's persistent query
//! dispatcher (contact manifolds, src/manifold.rs) and as the CCD's nonlinear cast.
//!
//! Run optimised (the crate's test profile is `opt-level = 3`); each test prints what it measures.

mod common;

use common::scenes::{
    head_on, shot_shape, wall_shot_at, Shot, ShotBody, ShotMethod, Wall, WALL_FACE, WALL_HALF, WALL_HALF_HEIGHT, WALL_X,
};
use common::world::{state_hash, World, GRAVITY};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{Ellipse, RoundedPolygon, SmoothDispatcher};
use std::sync::mpsc::{channel, Receiver};
use std::time::Instant;

/// A rapier scene driven by `PhysicsPipeline::step`, recording collision events.
struct Scene {
    gravity: Vector,
    world: World,
    events: ChannelEventCollector,
    collisions: Receiver<CollisionEvent>,
}

impl Scene {
    fn new(smooth: bool, gravity: Vector) -> Self {
        let (collision_send, collisions) = channel();
        let (force_send, _) = channel();
        let (tear_send, _) = channel();
        Scene {
            gravity,
            world: World::new(if smooth {
                NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
            } else {
                NarrowPhase::new()
            }),
            events: ChannelEventCollector::new(collision_send, force_send, tear_send),
            collisions,
        }
    }

    fn insert(&mut self, body: RigidBodyBuilder, collider: ColliderBuilder) -> RigidBodyHandle {
        self.world.insert(body, collider).0
    }

    fn insert_with_collider(
        &mut self,
        body: RigidBodyBuilder,
        collider: ColliderBuilder,
    ) -> (RigidBodyHandle, ColliderHandle) {
        self.world.insert(body, collider)
    }

    fn step(&mut self) {
        self.world.step(self.gravity, &self.events);
    }

    fn pose(&self, h: RigidBodyHandle) -> (Vector, f64) {
        let rb = &self.world.bodies[h];
        (rb.translation(), rb.rotation().angle())
    }
}

fn ground(scene: &mut Scene) {
    // Top face at y = 0.5.
    scene.insert(RigidBodyBuilder::fixed(), ColliderBuilder::cuboid(20.0, 0.5));
}

#[test]
fn ellipse_settles_on_its_short_semi_axis() {
    let mut scene = Scene::new(true, GRAVITY);
    ground(&mut scene);
    let h = scene.insert(
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
    let mut min_y = f64::INFINITY;
    let mut max_err: f64 = 0.0;
    let mut max_angle: f64 = 0.0;
    for i in 0..steps {
        scene.step();
        let (t, angle) = scene.pose(h);
        min_y = min_y.min(t.y);
        if i >= steps - watch {
            max_err = max_err.max((t.y - expected).abs());
            // Lying on its long side: the long axis horizontal (angle ≡ 0 mod π).
            let a = angle.rem_euclid(core::f64::consts::PI);
            max_angle = max_angle.max(a.min(core::f64::consts::PI - a));
        }
    }
    let (t, _) = scene.pose(h);
    let err = t.y - expected;
    println!(
        "ellipse settle: final y = {:.7} (expected {expected}), error = {err:.3e}; over the last {watch} \
         steps: max |height error| = {max_err:.3e}, residual rocking amplitude = {max_angle:.3e} rad; \
         lowest y during the run = {min_y:.6}",
        t.y
    );
    assert!(err.abs() < 1e-3, "settle height error {err}");
    assert!(max_err < 1e-3, "height error over the last steps {max_err}");
    assert!(max_angle < 0.1, "not lying on its long side: {max_angle}");
}

#[test]
fn rounded_polygon_resting_on_a_face_stays_still() {
    // On a box face (parry's polygonal path: neither side strictly convex) and on a half-space
    // (this crate's two-point manifold); both grounds have their surface at y = 0.5.
    for on_halfspace in [false, true] {
        let mut scene = Scene::new(true, GRAVITY);
        if on_halfspace {
            scene.insert(
                RigidBodyBuilder::fixed().translation(Vector::new(0.0, 0.5)),
                ColliderBuilder::new(SharedShape::halfspace(Vector::Y)),
            );
        } else {
            ground(&mut scene);
        }
        // A rounded square with an edge down: regular(4, ..) has its vertices at 0, π/2, …;
        // turn by π/4 (plus a little, so that it lands on a corner and tips over).
        let shape = RoundedPolygon::regular(4, 0.5, 0.05);
        let h = scene.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.3, 1.5))
                .rotation(core::f64::consts::FRAC_PI_4 + 0.05)
                .can_sleep(false),
            ColliderBuilder::new(SharedShape::new(shape)),
        );
        let (settle, watch) = (600, 100);
        for _ in 0..settle {
            scene.step();
        }
        let (t0, a0) = scene.pose(h);
        let mut drift: f64 = 0.0;
        let mut rot_drift: f64 = 0.0;
        for _ in 0..watch {
            scene.step();
            let (t, a) = scene.pose(h);
            drift = drift.max((t - t0).length());
            rot_drift = rot_drift.max((a - a0).abs());
        }
        // Half the side of the core square plus the border radius.
        let expected = 0.5 + 0.5 * core::f64::consts::FRAC_1_SQRT_2 + 0.05;
        let ground_name = if on_halfspace { "half-space" } else { "box face" };
        println!(
            "rounded polygon rest on a {ground_name}: y = {:.7} (expected {expected:.7}, error {:.3e}), \
             angle = {a0:.6}, drift over the last {watch} steps = {drift:.3e} (rotation {rot_drift:.3e})",
            t0.y,
            t0.y - expected
        );
        assert!(drift < 1e-4, "{ground_name}: drift {drift}");
        assert!(rot_drift < 1e-4, "{ground_name}: rotation drift {rot_drift}");
        assert!((t0.y - expected).abs() < 2e-3, "{ground_name}: height {}", t0.y);
    }
}

/// Shoots `body` from the origin at the wall (`common::scenes::wall_shot`) for 30 steps; true
/// when its centre crossed the wall: went past the wall's mid-plane within the wall's height
/// (a body that slides along the wall and past its end has not tunnelled).
fn shoot(body: ShotBody, method: ShotMethod, s: Shot) -> bool {
    shoot_at(body, method, s, Wall::Cuboid)
}

/// As [`shoot`] at the plank `wall`.
fn shoot_at(body: ShotBody, method: ShotMethod, s: Shot, wall: Wall) -> bool {
    let (mut world, h) = wall_shot_at(method, shot_shape(body, method), s, wall);
    for _ in 0..30 {
        let c0 = world.bodies[h].translation();
        world.step(Vector::ZERO, &());
        let c1 = world.bodies[h].translation();
        if c0.x <= WALL_X && c1.x > WALL_X {
            // Where the centre's straight path meets the mid-plane.
            let y = c0.y + (c1.y - c0.y) * (WALL_X - c0.x) / (c1.x - c0.x);
            if y.abs() <= WALL_HALF_HEIGHT {
                return true;
            }
        }
    }
    false
}

/// `n` shots: speeds 60–1060 m/s (1–18 m per step, against a 0.05 wall), spins up to ±600 rad/s
/// (10 rad per step), initial angles spread; every tenth shot has no spin.
fn shots(n: usize) -> Vec<Shot> {
    (0..n)
        .map(|i| {
            let u = (i as f64 * 0.618_033_988_749_895).fract();
            let v = (i as f64 * 0.754_877_666_246_693).fract();
            let spin = if i % 10 == 0 { 0.0 } else { 1200.0 * v - 600.0 };
            Shot {
                speed: 60.0 + 1000.0 * u,
                spin,
                angle0: 0.37 * i as f64,
            }
        })
        .collect()
}

/// Tunnelled shots out of `shots`, and the seconds taken.
fn tunnelled(body: ShotBody, method: ShotMethod, shots: &[Shot]) -> (usize, f64) {
    let t = Instant::now();
    let n = shots.iter().filter(|&&s| shoot(body, method, s)).count();
    (n, t.elapsed().as_secs_f64())
}

/// No tunnelling over 1,000 shots of a fast-spinning ellipse at a thin wall, at speeds where the
/// polygon approximation (a 32-gon swept by rapier's own CCD) and parry's default dispatcher
/// tunnel. rapier's CCD (`fallback_nonlinear_fraction` in rapier's `dynamics/ccd/sweeps.rs`)
/// discards a solid hit unless `0 < fraction`; `SmoothDispatcher` answers a contact at the start
/// that gets deeper within the step after the start (its module docs).
#[test]
fn thousand_spinning_ellipse_shots_do_not_tunnel_through_a_thin_wall() {
    let shots = shots(1000);
    let (smooth, t_smooth) = tunnelled(ShotBody::Ellipse, ShotMethod::Smooth, &shots);
    let (polygon, t_polygon) = tunnelled(ShotBody::Ellipse, ShotMethod::Polygon, &shots);
    let (parry, t_parry) = tunnelled(ShotBody::Ellipse, ShotMethod::ParryDefault, &shots);
    println!(
        "ellipse shots: {} cases (60-1060 m/s, spins up to 600 rad/s, wall 0.05 thick, 30 steps each); tunnelled: \
         SmoothDispatcher {smooth} ({t_smooth:.2} s), 32-gon polygon approximation {polygon} ({t_polygon:.2} s), \
         parry's DefaultQueryDispatcher {parry} ({t_parry:.2} s)",
        shots.len()
    );
    assert!(polygon > 0, "the polygon approximation should tunnel at these speeds");
    assert_eq!(smooth, 0);
}

/// The rounded heptagon (no strictly convex side against the box wall: parry's route) with and
/// without spin. Without the dispatcher's rule for parry's pairs, the zero-spin shots tunnelled:
/// rapier's CCD clamps the heptagon 1e-10 from the wall with parallel faces, where parry's GJK/EPA
/// report no contact, so neither the solver nor the next step's cast saw the wall.
#[test]
fn rounded_heptagon_shots_do_not_tunnel_through_a_thin_wall() {
    let shots = shots(300);
    let zero_spin = shots.iter().filter(|s| s.spin == 0.0).count();
    let (smooth, t_smooth) = tunnelled(ShotBody::Heptagon, ShotMethod::Smooth, &shots);
    let (polygon, _) = tunnelled(ShotBody::Heptagon, ShotMethod::Polygon, &shots);
    let (parry, _) = tunnelled(ShotBody::Heptagon, ShotMethod::ParryDefault, &shots);
    println!(
        "rounded heptagon shots: {} cases ({zero_spin} without spin); tunnelled: SmoothDispatcher {smooth} \
         ({t_smooth:.2} s), RoundConvexPolygon under rapier's own sweeps {polygon}, parry's DefaultQueryDispatcher {parry}",
        shots.len()
    );
    assert_eq!(smooth, 0);
}

/// Pairs with no strictly convex side in rapier (the gap tracker through
/// `SmoothDispatcher::cast_shapes_nonlinear`): rounded and sharp polygons and capsule-ellipses
/// shot at a thin box (parry's `Cuboid`) and at a thin rounded plank (this crate's
/// `RoundedPolygon`), spins to ±600 rad/s, speeds to 1,060 m/s: none tunnels.
#[test]
fn polygons_and_capsule_ellipses_do_not_tunnel_through_thin_walls() {
    let shots = shots(300);
    for wall in [Wall::Cuboid, Wall::Rounded] {
        for body in [ShotBody::Heptagon, ShotBody::Square, ShotBody::CapsuleEllipse] {
            let t = Instant::now();
            let smooth = shots
                .iter()
                .filter(|&&s| shoot_at(body, ShotMethod::Smooth, s, wall))
                .count();
            let seconds = t.elapsed().as_secs_f64();
            let polygon = shots
                .iter()
                .filter(|&&s| shoot_at(body, ShotMethod::Polygon, s, wall))
                .count();
            let parry = shots
                .iter()
                .filter(|&&s| shoot_at(body, ShotMethod::ParryDefault, s, wall))
                .count();
            println!(
                "{body:?} shots at a {wall:?} plank: {} cases; tunnelled: SmoothDispatcher {smooth} ({seconds:.2} s), \
                 parry's polygons under rapier's own sweeps {polygon}, parry's DefaultQueryDispatcher {parry}",
                shots.len()
            );
            assert_eq!(smooth, 0, "{body:?} at a {wall:?} plank");
        }
    }
}

/// Shoots `a` and `b` at each other (`common::scenes::head_on`) for 30 steps; true when their
/// centres swapped sides while less than `HEAD_ON_BAND` apart across the line of fire, which
/// two solid bodies cannot do without passing through each other.
fn head_on_passes(a: ShotBody, b: ShotBody, method: ShotMethod, sa: Shot, sb: Shot) -> bool {
    let (mut world, ha, hb) = head_on(method, shot_shape(a, method), shot_shape(b, method), sa, sb);
    for _ in 0..30 {
        world.step(Vector::ZERO, &());
        let (pa, pb) = (world.bodies[ha].translation(), world.bodies[hb].translation());
        if pa.x > pb.x && (pa.y - pb.y).abs() < HEAD_ON_BAND {
            return true;
        }
    }
    false
}

/// Twice a radius of a disc inside each of the shot bodies (the square's inradius is 0.25,
/// the capsule-ellipse's 0.12): centres closer than this across the line of fire overlap.
const HEAD_ON_BAND: f64 = 0.2;

/// The target's speed in [`polygons_and_capsule_ellipses_shot_at_each_other_do_not_pass_through`]:
/// slow enough (1/6 m a step) that the target, not a CCD body itself, never skips over the
/// bullet on its own.
const TARGET_SPEED: f64 = 10.0;

/// Pairs with no strictly convex side shot at each other in rapier: a CCD body (to 1,060 m/s,
/// ±600 rad/s) at a free body coming the other way at [`TARGET_SPEED`] and spinning to ±600
/// rad/s: none passes through the other under `SmoothDispatcher`.
#[test]
fn polygons_and_capsule_ellipses_shot_at_each_other_do_not_pass_through() {
    let shots = shots(200);
    let pairs = [
        (ShotBody::Heptagon, ShotBody::Heptagon),
        (ShotBody::Heptagon, ShotBody::Square),
        (ShotBody::CapsuleEllipse, ShotBody::Heptagon),
        (ShotBody::CapsuleEllipse, ShotBody::Square),
        (ShotBody::CapsuleEllipse, ShotBody::CapsuleEllipse),
    ];
    for (a, b) in pairs {
        // Pair shot i with a different shot for the other body.
        let passes = |method| {
            (0..shots.len())
                .filter(|&i| {
                    let target = Shot {
                        speed: TARGET_SPEED,
                        ..shots[(i * 7 + 3) % shots.len()]
                    };
                    head_on_passes(a, b, method, shots[i], target)
                })
                .count()
        };
        let t = Instant::now();
        let smooth = passes(ShotMethod::Smooth);
        let seconds = t.elapsed().as_secs_f64();
        let polygon = passes(ShotMethod::Polygon);
        let parry = passes(ShotMethod::ParryDefault);
        println!(
            "{a:?} and {b:?} shot at each other: {} cases; passed through: SmoothDispatcher {smooth} \
             ({seconds:.2} s), parry's polygons under rapier's own sweeps {polygon}, parry's \
             DefaultQueryDispatcher {parry}",
            shots.len()
        );
        assert_eq!(smooth, 0, "{a:?} and {b:?}");
    }
}

/// Continuous collision against half-space ground (parry has no nonlinear cast against a
/// half-space; `SmoothDispatcher` has an exact one): fast ellipses and rounded pentagons fired
/// down at a `HalfSpace` never get their centre below it.
#[test]
fn fast_bodies_fired_at_half_space_ground_do_not_pass_through() {
    let t = Instant::now();
    let mut cases = 0;
    let mut through = [0usize; 2];
    let mut lowest = f64::INFINITY;
    for (k, smooth) in [true, false].into_iter().enumerate() {
        for i in 0..40 {
            let shape = if i % 2 == 0 {
                SharedShape::new(Ellipse::new(0.5, 0.2))
            } else {
                SharedShape::new(RoundedPolygon::regular(5, 0.4, 0.05))
            };
            let mut scene = Scene::new(smooth, GRAVITY);
            scene.insert(
                RigidBodyBuilder::fixed(),
                ColliderBuilder::new(SharedShape::halfspace(Vector::Y)),
            );
            let h = scene.insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(0.0, 20.0))
                    .rotation(0.41 * i as f64)
                    .linvel(Vector::new(3.0, -(100.0 + 25.0 * i as f64)))
                    .angvel(if i % 3 == 0 { 0.0 } else { 15.0 * i as f64 - 300.0 })
                    // Up to 300 rad/s (5 rad a step): above rapier's cap of π/4 a step, lifted.
                    .allow_fast_rotation(true)
                    .ccd_enabled(true)
                    .can_sleep(false),
                ColliderBuilder::new(shape),
            );
            let mut min_y = f64::INFINITY;
            for _ in 0..60 {
                scene.step();
                min_y = min_y.min(scene.pose(h).0.y);
            }
            if smooth {
                cases += 1;
                lowest = lowest.min(min_y);
            }
            // Below the ground with its centre: passed through.
            if min_y < 0.0 {
                through[k] += 1;
            }
        }
    }
    println!(
        "half-space ground: {cases} fast bodies (100-1075 m/s down, spins up to 300 rad/s); passed through: \
         SmoothDispatcher {}, parry's DefaultQueryDispatcher {}; lowest centre with SmoothDispatcher {lowest:.4} \
         ({:.2} s)",
        through[0],
        through[1],
        t.elapsed().as_secs_f64()
    );
    assert_eq!(through[0], 0);
    // (The ellipse's short semi-axis is 0.2: a body bouncing off at 60 m/s with a 300 rad/s spin
    // sinks in by up to a quarter of its ccd_thickness per step, which rapier's solver pushes
    // out over the following steps.)
    assert!(lowest > 0.0, "{lowest}");
}

/// Collision events of sensor colliders with an ellipse: a slow ellipse passing 10⁻³ outside a
/// sensor disc reports nothing and 10⁻³ inside reports a start and a stop (the exact distance
/// decides); a fast ellipse crossing a thin sensor strip within one step is not missed (rapier's
/// CCD reports the crossing through the dispatcher's cast).
#[test]
fn sensors_report_intersections_with_an_ellipse() {
    let sensor_events = |scene: &Scene| {
        scene
            .collisions
            .try_iter()
            .filter(|e| e.sensor())
            .map(|e| if e.started() { 'S' } else { 'E' })
            .collect::<String>()
    };
    // Grazing: the ellipse (0.5 × 0.2, long axis along x) slides along y = 0 at 2 m/s past a
    // sensor disc of radius 0.3 centred at (3, 0.5 ± 1e-3).
    let mut outcomes = Vec::new();
    for offset in [1e-3, -1e-3] {
        let mut scene = Scene::new(true, Vector::ZERO);
        scene.insert(
            RigidBodyBuilder::fixed().translation(Vector::new(3.0, 0.5 + offset)),
            ColliderBuilder::ball(0.3)
                .sensor(true)
                .active_events(ActiveEvents::COLLISION_EVENTS),
        );
        scene.insert(
            RigidBodyBuilder::dynamic()
                .linvel(Vector::new(2.0, 0.0))
                .can_sleep(false),
            ColliderBuilder::new(SharedShape::new(Ellipse::new(0.5, 0.2)))
                .active_events(ActiveEvents::COLLISION_EVENTS),
        );
        let mut events = String::new();
        for _ in 0..240 {
            scene.step();
            events += &sensor_events(&scene);
        }
        outcomes.push(events);
    }
    // Fast: 600 m/s (10 m per step) through a 0.05-thick sensor strip at x = 5 (rapier's linear
    // cap of 400 m/s lifted).
    let mut scene = Scene::new(true, Vector::ZERO);
    scene.world.params.normalized_max_linear_velocity = f64::MAX;
    scene.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(WALL_X, 0.0)),
        ColliderBuilder::cuboid(WALL_HALF, WALL_HALF_HEIGHT)
            .sensor(true)
            .active_events(ActiveEvents::COLLISION_EVENTS),
    );
    let (h, _) = scene.insert_with_collider(
        RigidBodyBuilder::dynamic()
            .linvel(Vector::new(600.0, 0.0))
            .angvel(100.0)
            // Above rapier's caps (400 m/s, π/4 a step): lifted, with the world's linear cap.
            .allow_fast_rotation(true)
            .ccd_enabled(true)
            .can_sleep(false),
        ColliderBuilder::new(SharedShape::new(Ellipse::new(0.5, 0.2))).active_events(ActiveEvents::COLLISION_EVENTS),
    );
    let mut fast = String::new();
    for _ in 0..3 {
        scene.step();
        fast += &sensor_events(&scene);
    }
    let crossed = scene.pose(h).0.x > WALL_FACE + 1.0;
    println!(
        "sensor events (S start, E stop): ellipse passing 1e-3 outside a sensor disc {:?}, 1e-3 inside {:?}; \
         crossing a 0.05 sensor strip at 600 m/s in one step {fast:?} (crossed: {crossed})",
        outcomes[0], outcomes[1]
    );
    assert_eq!(outcomes[0], "");
    assert_eq!(outcomes[1], "SE");
    assert!(crossed, "a sensor does not stop the body");
    assert_eq!(fast, "SE");
}

fn deterministic_scene() -> Vec<u64> {
    let mut scene = Scene::new(true, GRAVITY);
    ground(&mut scene);
    let mut handles = Vec::new();
    for i in 0..6 {
        let x = -4.0 + 1.3 * i as f64;
        let shape = if i % 2 == 0 {
            SharedShape::new(Ellipse::new(0.5, 0.2))
        } else {
            SharedShape::new(RoundedPolygon::regular(3 + i, 0.4, 0.03))
        };
        handles.push(
            scene.insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(x, 1.5 + 0.7 * i as f64))
                    .rotation(0.4 * i as f64)
                    .angvel(3.0 - i as f64)
                    .ccd_enabled(true),
                ColliderBuilder::new(shape),
            ),
        );
    }
    // A fast CCD shot into the pile.
    handles.push(
        scene.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(-10.0, 1.0))
                .linvel(Vector::new(200.0, 0.0))
                .angvel(150.0)
                // 2.5 rad a step: above rapier's rotation cap of π/4, lifted.
                .allow_fast_rotation(true)
                .ccd_enabled(true),
            ColliderBuilder::new(SharedShape::new(Ellipse::new(0.3, 0.1))),
        ),
    );
    for _ in 0..400 {
        scene.step();
    }
    let (_, words) = state_hash(&scene.world, &handles);
    words.iter().flatten().map(|x| x.to_bits()).collect()
}

#[test]
fn same_scene_twice_is_bit_identical() {
    let a = deterministic_scene();
    let b = deterministic_scene();
    let same = a.iter().zip(&b).filter(|(x, y)| x == y).count();
    println!("determinism: {same}/{} state words bit-identical", a.len());
    assert_eq!(a, b);
}

/// Bodies already in the floor when rapier's CCD sweeps them (`stop_at_penetration = false`,
/// recorded in the box pile) are reported by rapier's rule (`CastPolicy::Rapier`): at the
/// earlier of the translation alone (the motion without its spin) taking the contact an
/// allowance A = ¼·r deeper than min(0, its start depth) and the core, the disc of ¼·r about
/// the rotation centre, reaching the floor (r the body's inradius about that centre), or not
/// at all when neither happens within the step. Checked against independent references: the
/// signed distance by dense sampling of the translating body, parry's distance from the centre
/// to the floor box, and r by parry's point projection; both stay above their levels on 400
/// times before the answer (the whole step for no hit) and one reaches its level there.
#[test]
fn bodies_resting_in_the_floor_are_swept_by_their_translation_and_core() {
    use common::reference::{pair_size, reference_distance_at};
    use common::scenes::resting_sweeps;
    use parry2d_f64::query::{NonlinearRigidMotion, PointQuery, QueryDispatcher};
    use smooth_ccd2d::CastPolicy;
    let d = SmoothDispatcher::default();
    let dt = 1.0 / 60.0;
    for s in resting_sweeps() {
        let h = s.floor.half_extents;
        let floor_curve = RoundedPolygon::new(
            &[
                Vector::new(-h.x, -h.y),
                Vector::new(h.x, -h.y),
                h,
                Vector::new(-h.x, h.y),
            ],
            0.0,
        );
        let body = s.body.shared();
        let sliding = NonlinearRigidMotion {
            angvel: 0.0,
            ..s.motion
        };
        let signed =
            |t: f64| reference_distance_at(s.body.curve(), &sliding, &floor_curve, &s.floor_motion, t).distance;
        let c = s.motion.local_center;
        let r = (body.project_local_point(c, false).point - c).length();
        let core = |t: f64| {
            let centre = s.motion.position_at_time(t) * c;
            s.floor.distance_to_point(&s.floor_motion.start, centre, true) - CastPolicy::CORE * r
        };
        let size = pair_size(s.body.curve(), &floor_curve);
        let tol = 1e-12 * size;
        let allowance = CastPolicy::ALLOWANCE * r;
        let d0 = signed(0.0);
        let target = (-allowance).min(d0 - allowance);
        assert!(d0 < 0.0, "{}: in the floor at the start ({d0})", s.name);
        let hit = d
            .cast_shapes_nonlinear(&s.motion, &*body, &s.floor_motion, &s.floor, 0.0, dt, false)
            .expect("answered");
        assert_eq!(hit.is_some(), s.deepens, "{}: {hit:?}", s.name);
        // Above both levels until the answer (the whole step for no hit).
        let until = hit.map_or(dt, |h| h.time_of_impact - 2e-9 * dt);
        for k in 0..=400 {
            let t = until * k as f64 / 400.0;
            assert!(signed(t) >= target - tol, "{}: below the target at {t}", s.name);
            assert!(core(t) >= -tol, "{}: the core in the floor at {t}", s.name);
        }
        match hit {
            Some(hit) => {
                let t = hit.time_of_impact;
                let (at, core_at) = (signed(t), core(t));
                println!(
                    "{}: depth {d0:.4e} at the start, hit at {:.6} of the step, D there {at:.6e} \
                     (target {target:.6e}), the core {core_at:.3e} from the floor",
                    s.name,
                    t / dt
                );
                assert!(t > 0.0 && t <= dt, "{}: {t}", s.name);
                assert!(
                    at < target + tol || core_at < tol,
                    "{}: {at} {core_at} at the answer",
                    s.name
                );
            }
            None => {
                let lowest = (0..=400)
                    .map(|k| signed(dt * k as f64 / 400.0))
                    .fold(f64::INFINITY, f64::min);
                println!(
                    "{}: depth {d0:.4e} at the start, no hit (the translation down to {lowest:.6e}, target {target:.6e})",
                    s.name
                )
            }
        }
    }
}

/// A user's curve spinning into a wall moves on as the crate's own shape does (found by a hunt
/// through hostile rapier scenes): `CustomCurve::new(Ellipse::new(0.5, 0.2))` launched at
/// (300, −50) m/s and spinning at 300–10⁴ rad/s onto a segment or a box sat 0.175 deep with its
/// centre an eighth of its inradius off the wall for 109–113 of 120 steps, while
/// `Ellipse::new(0.5, 0.2)` moved on: its manifold had no core contacts (the exact contact query
/// does not read user curves), so the solver held nothing while the spin carried the contact
/// points off the wall, and rapier's CCD stopped the translation at the start of every step.
/// Now both bodies' cores come from the manifold's normal and deepest point
/// (`core_disc::core_manifold_of`), and against a polyline's segments the smaller body's core
/// contact joins each part's points (`core_disc::add_part_core`), as for the crate's shapes. Frozen: ten steps in a row at 1 m/s or more moving less than
/// 0.1 % of |v|·dt (the CCD scene suite's judge).
#[test]
fn a_user_curve_spinning_into_a_wall_moves_on_as_the_shape_it_wraps() {
    use smooth_ccd2d::CustomCurve;
    let run = |custom: bool, ground: SharedShape, ground_y: f64, w: f64| -> (usize, f64) {
        let mut world = World::new(NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()));
        world.params.normalized_max_linear_velocity = f64::MAX;
        let g = world
            .bodies
            .insert(RigidBodyBuilder::fixed().translation(Vector::new(0.0, ground_y)));
        world
            .colliders
            .insert_with_parent(ColliderBuilder::new(ground).build(), g, &mut world.bodies);
        let shape = if custom {
            SharedShape::new(CustomCurve::new(Ellipse::new(0.5, 0.2)))
        } else {
            SharedShape::new(Ellipse::new(0.5, 0.2))
        };
        let body = RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.3))
            .linvel(Vector::new(300.0, -50.0))
            .angvel(w)
            .ccd_enabled(true)
            .allow_fast_rotation(true);
        let h = world.bodies.insert(body);
        world
            .colliders
            .insert_with_parent(ColliderBuilder::new(shape).build(), h, &mut world.bodies);
        let (mut still, mut longest, mut lowest) = (0, 0, f64::INFINITY);
        for _ in 0..120 {
            let before = world.bodies[h].translation();
            world.step(Vector::new(0.0, -9.81), &());
            let rb = &world.bodies[h];
            lowest = lowest.min(rb.translation().y);
            let speed = rb.linvel().length();
            if speed > 1.0 && (rb.translation() - before).length() < 1e-3 * speed * world.params.dt {
                still += 1;
                longest = longest.max(still);
            } else {
                still = 0;
            }
        }
        (longest, lowest)
    };
    for (name, ground, ground_y) in [
        (
            "segment",
            SharedShape::segment(Vector::new(-1e4, 0.0), Vector::new(1e4, 0.0)),
            0.0,
        ),
        ("box", SharedShape::cuboid(1e4, 1.0), -1.0),
        (
            "polyline",
            SharedShape::polyline(
                vec![
                    Vector::new(-1e4, 0.0),
                    Vector::new(-1.0, 0.0),
                    Vector::new(1.0, 0.0),
                    Vector::new(1e4, 0.0),
                ],
                None,
            ),
            0.0,
        ),
    ] {
        for w in [300.0, 1e3, 1e4] {
            let (own, custom) = (
                run(false, ground.clone(), ground_y, w),
                run(true, ground.clone(), ground_y, w),
            );
            println!(
                "{name}, {w} rad/s: Ellipse longest still {} steps, lowest {:.4}; CustomCurve {} steps, lowest {:.4}",
                own.0, own.1, custom.0, custom.1
            );
            for (what, (longest, lowest)) in [("Ellipse", own), ("CustomCurve", custom)] {
                assert!(
                    longest < 10,
                    "{what} on the {name} at {w} rad/s: still for {longest} steps"
                );
                // The top face of the wall at 0: the centre stays above it (its core never reaches it).
                assert!(lowest > 0.0, "{what} on the {name} at {w} rad/s: centre at {lowest}");
            }
        }
    }
}
