//! SmoothDispatcher keeps parry's semantics: pos12, casts, `stop_at_penetration`, composite
//! shapes, half-spaces, and bad input.

use parry2d_f64::math::{Pose, Rotation, Vector};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{
    ContactManifold, DefaultQueryDispatcher, NonlinearRigidMotion, PersistentQueryDispatcher, QueryDispatcher,
    ShapeCastStatus,
};
use parry2d_f64::shape::{Ball, Compound, ConvexPolygon, Cuboid, HalfSpace, Segment, Shape, SharedShape, Triangle};
use smooth_ccd2d::{CastPolicy, Ellipse, RoundedPolygon, SmoothDispatcher};

#[path = "common/rng.rs"]
mod rng;

#[test]
fn dispatcher_is_send_sync_clone_default() {
    fn check<T: Send + Sync + Clone + Default + 'static>() {}
    check::<SmoothDispatcher>();
}

#[test]
fn smooth_shape_inside_a_compound_keeps_the_exact_distance() {
    let d = SmoothDispatcher::default();
    let e = Ellipse::new(0.5, 0.2);
    let child_pose = Pose::new(Vector::new(1.0, 0.5), 0.3);
    let compound = Compound::new(vec![(child_pose, SharedShape::new(e))]);
    let ball = Ball::new(0.25);
    let pos12 = Pose::new(Vector::new(3.0, 1.0), 0.0);
    let via_compound = d.distance(&pos12, &compound, &ball).unwrap().distance;
    let direct = d.distance(&child_pose.inv_mul(&pos12), &e, &ball).unwrap().distance;
    assert!((via_compound - direct).abs() < 1e-14, "{via_compound} vs {direct}");
    // And the nonlinear cast of a ball flying at the compound.
    let m1 = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let m2 = NonlinearRigidMotion::new(pos12, Vector::ZERO, Vector::new(-2.0, -0.25), 0.0);
    let hit = d
        .cast_shapes_nonlinear(&m1, &compound, &m2, &ball, 0.0, 2.0, true)
        .unwrap()
        .expect("hit");
    let p1 = m1.position_at_time(hit.time_of_impact);
    let p2 = m2.position_at_time(hit.time_of_impact);
    let gap = d.distance(&p1.inv_mul(&p2), &compound, &ball).unwrap().distance;
    assert!(gap <= 1e-9, "gap at the impact {gap}");
}

#[test]
fn linear_cast_of_an_ellipse_along_its_axis_hits_at_the_closed_form_time() {
    let d = SmoothDispatcher::default();
    let e = Ellipse::new(0.5, 0.2);
    let b = Ball::new(0.3);
    // Ball starts at x = 3 and moves at −2 (relative, in shape 1's frame): contact at x = 0.8.
    let opts = ShapeCastOptions::with_max_time_of_impact(5.0);
    let hit = d
        .cast_shapes(
            &Pose::new(Vector::new(3.0, 0.0), 0.0),
            Vector::new(-2.0, 0.0),
            &e,
            &b,
            opts,
        )
        .unwrap()
        .expect("hit");
    assert!((hit.time_of_impact - 1.1).abs() < 1e-10, "{}", hit.time_of_impact);
    assert_eq!(hit.status, ShapeCastStatus::Converged);
    assert!((hit.witness1 - Vector::new(0.5, 0.0)).length() < 1e-6);
    assert!((hit.normal1 - Vector::X).length() < 1e-6);
    // The same hit over parry's default window (`Real::MAX`) and over an infinite one (which
    // parry takes); a NaN window is refused.
    for max in [f64::MAX, f64::INFINITY] {
        let far = d
            .cast_shapes(
                &Pose::new(Vector::new(3.0, 0.0), 0.0),
                Vector::new(-2.0, 0.0),
                &e,
                &b,
                ShapeCastOptions::with_max_time_of_impact(max),
            )
            .unwrap()
            .expect("hit");
        assert!(
            (far.time_of_impact - 1.1).abs() < 1e-10,
            "window {max}: {}",
            far.time_of_impact
        );
        // A rounded box (no strictly convex side: the gap tracker) against a box, the same.
        let rounded = RoundedPolygon::new(
            &[
                Vector::new(-0.4, -0.1),
                Vector::new(0.4, -0.1),
                Vector::new(0.4, 0.1),
                Vector::new(-0.4, 0.1),
            ],
            0.1,
        );
        let boxed = d
            .cast_shapes(
                &Pose::new(Vector::new(3.0, 0.0), 0.0),
                Vector::new(-2.0, 0.0),
                &rounded,
                &Cuboid::new(Vector::new(0.3, 0.3)),
                ShapeCastOptions::with_max_time_of_impact(max),
            )
            .unwrap()
            .expect("hit");
        assert!(
            (boxed.time_of_impact - 1.1).abs() < 1e-10,
            "window {max}: {}",
            boxed.time_of_impact
        );
    }
    let nan = d.cast_shapes(
        &Pose::new(Vector::new(3.0, 0.0), 0.0),
        Vector::new(-2.0, 0.0),
        &e,
        &b,
        ShapeCastOptions::with_max_time_of_impact(f64::NAN),
    );
    assert!(nan.is_err(), "{nan:?}");
}

/// Found by `tests/character_controller.rs`: linear casts of pairs with no strictly convex side
/// (a rounded box over the ground) were parry's GJK cast, which stopped short of the target
/// distance by up to 3e-8 m (8e-5 of the window) on a 1 m body. They now take the gap tracker.
/// On random such pairs — `RoundedPolygon`s sharp and rounded and `CapsuleEllipse`s against
/// parry's boxes, segments, triangles and polygons and against each other, translating at each
/// other, passing by or stopping short, with a target distance of 0 or 1 % of the size — a hit
/// is at the target distance (the exact distance of the dispatcher, to 1e-12 of the size below,
/// the tracker's tolerance above) and above it at 4,000 times before; a miss stays above it at
/// 4,000 times over the window. A hit is the same with parry's default window, `Real::MAX` (where
/// the gap tracker answered `OutOfIterations` at 0 before the window was bounded by the shapes'
/// bounding circles).
#[test]
fn linear_cast_of_a_pair_with_no_strictly_convex_side_is_exact() {
    let mut rng = rng::Rng::new(0x11_4EA2);
    let d = SmoothDispatcher::default();
    let (mut hits, mut parry_short, mut worst, mut starts_within) = (0, 0, 0.0f64, 0);
    let cases = 300;
    for case in 0..cases {
        let size = rng.log_uniform(0.1, 10.0);
        let polygon = |rng: &mut rng::Rng, n: usize| -> Vec<Vector> {
            let mut angles: Vec<f64> = (0..n).map(|_| rng.angle()).collect();
            angles.sort_by(f64::total_cmp);
            angles.dedup_by(|a, b| (*a - *b).abs() < 0.3);
            if angles.len() < 3 {
                angles = vec![0.0, 2.1, 4.2];
            }
            let points: Vec<Vector> = angles
                .iter()
                .map(|a| Vector::new(a.cos(), a.sin()) * size * rng.uniform(0.5, 1.0))
                .collect();
            // Their convex hull, counter-clockwise.
            ConvexPolygon::from_convex_hull(&points)
                .expect("a hull")
                .points()
                .to_vec()
        };
        let g1: Box<dyn Shape> = match case % 3 {
            0 => Box::new(RoundedPolygon::new(&polygon(&mut rng, 6), 0.0)),
            1 => Box::new(RoundedPolygon::new(
                &polygon(&mut rng, 5),
                size * rng.uniform(0.02, 0.3),
            )),
            _ => Box::new(smooth_ccd2d::CapsuleEllipse::new(
                size * 0.4,
                size * rng.uniform(0.1, 1.0),
                size * rng.uniform(0.2, 1.0),
            )),
        };
        let g2: Box<dyn Shape> = match (case / 3) % 5 {
            0 => Box::new(Cuboid::new(Vector::new(
                size * rng.uniform(0.05, 3.0),
                size * rng.uniform(0.05, 3.0),
            ))),
            1 => Box::new(Segment::new(
                Vector::new(-2.0 * size, 0.0),
                Vector::new(2.0 * size, rng.uniform(-1.0, 1.0) * size),
            )),
            2 => {
                let p = polygon(&mut rng, 3);
                Box::new(Triangle::new(p[0], p[1], p[2]))
            }
            3 => Box::new(ConvexPolygon::from_convex_polyline(polygon(&mut rng, 7)).expect("a polygon")),
            _ => Box::new(RoundedPolygon::new(&polygon(&mut rng, 4), size * rng.uniform(0.0, 0.2))),
        };
        let from = Vector::new(rng.angle().cos(), rng.angle().sin()).normalize() * size * rng.uniform(3.0, 6.0);
        let pos12 = Pose::new(from, rng.angle());
        // Towards shape 1's centre give or take up to 1.5 sizes; a window reaching past it or not.
        let aim = Vector::new(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)) * size;
        let vel12 = (aim - from) * rng.uniform(0.3, 1.5);
        let delta = if rng.chance(0.5) { 0.0 } else { 0.01 * size };
        let options = ShapeCastOptions {
            max_time_of_impact: 1.0,
            target_distance: delta,
            stop_at_penetration: false,
            compute_impact_geometry_on_penetration: true,
        };
        let gap_at = |dispatcher: &dyn QueryDispatcher, t: f64| {
            let p = Pose::from_parts(pos12.translation + vel12 * t, pos12.rotation);
            dispatcher.distance(&p, &*g1, &*g2).unwrap().distance
        };
        let ours = d.cast_shapes(&pos12, vel12, &*g1, &*g2, options).unwrap();
        // parry's default window, `Real::MAX`, gives the same answer.
        let unbounded = ShapeCastOptions {
            max_time_of_impact: f64::MAX,
            ..options
        };
        let whole = d.cast_shapes(&pos12, vel12, &*g1, &*g2, unbounded).unwrap();
        if let Some(h) = ours {
            assert_eq!(whole.map(|w| w.time_of_impact), Some(h.time_of_impact), "case {case}");
        }
        if gap_at(&d, 0.0) <= delta {
            // Within the target at the start (a long segment or a large box reaching shape 1):
            // parry's rule, a hit at 0 when approaching, none when leaving.
            starts_within += 1;
            assert!(
                ours.is_none_or(
                    |h| h.time_of_impact == 0.0 && h.status == ShapeCastStatus::PenetratingOrWithinTargetDist
                ),
                "case {case}: {ours:?}"
            );
            continue;
        }
        let end = ours.map_or(1.0, |h| h.time_of_impact);
        let n = 4_000;
        for i in 0..n {
            let t = end * i as f64 / n as f64;
            let gap = gap_at(&d, t);
            assert!(
                gap > delta,
                "case {case}: at {t}, before the answer {ours:?}, the gap {gap} is within {delta}"
            );
        }
        if let Some(h) = ours {
            hits += 1;
            assert_eq!(h.status, ShapeCastStatus::Converged, "case {case}");
            let error = gap_at(&d, h.time_of_impact) - delta;
            worst = worst.max(error.abs() / size);
            // The guarantee of a hit: δ − 1e-12·s ≤ D ≤ δ + 1e-10·s (README, "Guarantees").
            assert!(
                error >= -1e-12 * size && error <= 1e-10 * size,
                "case {case}: the gap at the hit is off by {error:e}"
            );
            if let Ok(Some(p)) = DefaultQueryDispatcher.cast_shapes(&pos12, vel12, &*g1, &*g2, options) {
                parry_short += usize::from(gap_at(&d, p.time_of_impact) - delta > 1e-9 * size);
            }
        }
    }
    println!(
        "{cases} linear casts ({starts_within} starting within the target), {hits} hits, the gap at a hit off by {worst:.1e} of the size at most; parry's cast of the same pairs more than 1e-9 of the size short on {parry_short}"
    );
    assert!(hits > cases / 4, "{hits} hits");
}

#[test]
fn plain_policy_follows_parrys_stop_at_penetration_semantics() {
    let d = SmoothDispatcher::default().with_cast_policy(CastPolicy::Plain);
    let e = Ellipse::new(0.5, 0.2);
    let b = Ball::new(0.3);
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    // Overlapping at the start and separating.
    let leaving = NonlinearRigidMotion::new(
        Pose::new(Vector::new(0.7, 0.0), 0.0),
        Vector::ZERO,
        Vector::new(1.0, 0.0),
        0.0,
    );
    let hit = d
        .cast_shapes_nonlinear(&still, &e, &leaving, &b, 0.0, 1.0, true)
        .unwrap()
        .unwrap();
    assert_eq!(hit.status, ShapeCastStatus::PenetratingOrWithinTargetDist);
    assert_eq!(hit.time_of_impact, 0.0);
    // Solid bodies (false): a separating contact is ignored, and nothing comes back.
    assert!(d
        .cast_shapes_nonlinear(&still, &e, &leaving, &b, 0.0, 1.0, false)
        .unwrap()
        .is_none());
    // Separating, then coming back: a thin spinning ellipse leaves the ball with one tip and
    // returns with the other; the answer is that return, not the start.
    let thin = Ellipse::new(1.0, 0.05);
    let w = 3.0;
    let spin = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::ZERO, w);
    let ball_at = NonlinearRigidMotion::constant_position(Pose::new(Vector::new(0.9, 0.0), 0.0));
    let hit = d
        .cast_shapes_nonlinear(&spin, &thin, &ball_at, &b, 0.0, 2.0, false)
        .unwrap()
        .expect("the other tip");
    assert!(
        hit.time_of_impact > std::f64::consts::FRAC_PI_2 / w,
        "{}",
        hit.time_of_impact
    );
    let p1 = spin.position_at_time(hit.time_of_impact);
    let gap = d.distance(&p1.inv_mul(&ball_at.start), &thin, &b).unwrap().distance;
    let before = spin.position_at_time(hit.time_of_impact - 1e-6);
    assert!(gap <= 1e-9 && d.distance(&before.inv_mul(&ball_at.start), &thin, &b).unwrap().distance > 0.0);
    // Approaching while overlapping: the start time, whether stopping at penetration or not.
    let coming = NonlinearRigidMotion::new(
        Pose::new(Vector::new(0.7, 0.0), 0.0),
        Vector::ZERO,
        Vector::new(-1.0, 0.0),
        0.0,
    );
    for stop in [true, false] {
        let hit = d
            .cast_shapes_nonlinear(&still, &e, &coming, &b, 0.0, 1.0, stop)
            .unwrap()
            .unwrap();
        assert_eq!(hit.time_of_impact, 0.0);
    }
}

/// rapier's rule (`CastPolicy::Rapier`, the default) for solid bodies in contact at the start
/// of a step: the answer is the earlier of the fast body's core (a quarter of its inradius
/// about its rotation centre) reaching the target and its translation taking the contact an
/// allowance (a quarter of that inradius) deeper; never the start itself, which rapier
/// discards. The ball (0.3) at x = 0.7 overlaps the ellipse's tip (x = 0.5) by 0.1.
#[test]
fn rapier_policy_answers_a_start_contact_by_its_translation_and_core() {
    let d = SmoothDispatcher::default();
    assert_eq!(d.cast_policy, CastPolicy::Rapier);
    let e = Ellipse::new(0.5, 0.2);
    let b = Ball::new(0.3);
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let at = |v: Vector| NonlinearRigidMotion::new(Pose::new(Vector::new(0.7, 0.0), 0.0), Vector::ZERO, v, 0.0);
    let allowance = CastPolicy::ALLOWANCE * 0.3;
    // Approaching at 1 m/s: 0.1 + 0.075 deep at t = 0.075 (the core, 0.075 about the ball's
    // centre, would reach the tip at t = 0.125).
    let hit = d
        .cast_shapes_nonlinear(&still, &e, &at(Vector::new(-1.0, 0.0)), &b, 0.0, 1.0, false)
        .unwrap()
        .expect("driven in");
    assert!((hit.time_of_impact - allowance).abs() < 1e-9, "{}", hit.time_of_impact);
    // Stopping at penetration: the start.
    let hit = d
        .cast_shapes_nonlinear(&still, &e, &at(Vector::new(-1.0, 0.0)), &b, 0.0, 1.0, true)
        .unwrap()
        .unwrap();
    assert_eq!(hit.time_of_impact, 0.0);
    // Leaving, sliding along the tip, or creeping in (1 mm/s, 1 mm over the window): no hit.
    for v in [Vector::new(1.0, 0.0), Vector::new(0.0, 1.0), Vector::new(-1e-3, 0.0)] {
        assert!(
            d.cast_shapes_nonlinear(&still, &e, &at(v), &b, 0.0, 1.0, false)
                .unwrap()
                .is_none(),
            "{v}"
        );
    }
    // A thin spinning ellipse turning its other tip into the ball: the spin of a start contact
    // is the solver's (the manifold's core contact), not the cast's.
    let thin = Ellipse::new(1.0, 0.05);
    let spin = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::ZERO, 3.0);
    let ball_at = NonlinearRigidMotion::constant_position(Pose::new(Vector::new(0.9, 0.0), 0.0));
    assert!(d
        .cast_shapes_nonlinear(&spin, &thin, &ball_at, &b, 0.0, 2.0, false)
        .unwrap()
        .is_none());
    // Apart at the start: the exact time of impact, on the path rapier's clamp applies.
    let far = NonlinearRigidMotion::new(
        Pose::new(Vector::new(1.8, 0.0), 0.0),
        Vector::ZERO,
        Vector::new(-1.0, 0.0),
        0.0,
    );
    let hit = d
        .cast_shapes_nonlinear(&still, &e, &far, &b, 0.0, 2.0, false)
        .unwrap()
        .expect("a hit");
    assert!((hit.time_of_impact - 1.0).abs() < 1e-10, "{}", hit.time_of_impact);
}

/// The signed distance (this crate's, or parry's contact for polygonal pairs) along two motions.
fn signed_at(
    d: &SmoothDispatcher,
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t: f64,
) -> f64 {
    let pos12 = m1.position_at_time(t).inv_mul(&m2.position_at_time(t));
    d.contact(&pos12, g1, g2, 10.0).unwrap().expect("within 10").dist
}

/// An ellipse 0.5 × 0.2 standing on end, drifting at 0.1 m/s into a 0.05 wall and spinning at
/// 40 rad/s, the wall's face at x = 0.199, 10⁻³ into the ellipse (which the spin takes 0.14
/// deeper within the step): the ellipse, its motion, the wall, the wall's (still) motion, the step.
fn spinning_ellipse_at_a_wall() -> (Ellipse, NonlinearRigidMotion, Cuboid, NonlinearRigidMotion, f64) {
    let m1 = NonlinearRigidMotion::new(
        Pose::new(Vector::ZERO, std::f64::consts::FRAC_PI_2),
        Vector::ZERO,
        Vector::new(0.1, 0.0),
        40.0,
    );
    let wall = NonlinearRigidMotion::constant_position(Pose::translation(0.224, 0.0));
    (
        Ellipse::new(0.5, 0.2),
        m1,
        Cuboid::new(Vector::new(0.025, 3.0)),
        wall,
        1.0 / 60.0,
    )
}

/// An ellipse standing on its flank 10⁻³ deep in a thin wall, drifting at 0.1 m/s towards it
/// and spinning at 40 rad/s: within the step the tip turns 0.15 into the wall. rapier's rule
/// leaves what a spin does to a start contact to the solver (the contact manifold's core
/// contact), since rapier's clamp would turn the body along another path than its solver's:
/// the drift (0.0017 over the step) is far below the allowance (a quarter of the ellipse's
/// inradius 0.2) and the core (0.05 about the centre, 0.199 from the face) stays out, so no hit.
/// A plain cast reports the approaching contact at the start.
#[test]
fn a_spinning_start_contact_is_left_to_the_solver() {
    let d = SmoothDispatcher::default();
    let (e, m1, wall, m2, dt) = spinning_ellipse_at_a_wall();
    let d0 = signed_at(&d, &m1, &e, &m2, &wall, 0.0);
    let d_end = signed_at(&d, &m1, &e, &m2, &wall, dt);
    assert!((d0 + 1e-3).abs() < 1e-12 && d_end < -0.14, "{d0} {d_end}");
    assert!(d
        .cast_shapes_nonlinear(&m1, &e, &m2, &wall, 0.0, dt, false)
        .unwrap()
        .is_none());
    // Driven in at 10 m/s instead: stopped where the translation alone is 0.05 deeper.
    let driven = NonlinearRigidMotion {
        linvel: Vector::new(10.0, 0.0),
        ..m1
    };
    let hit = d
        .cast_shapes_nonlinear(&driven, &e, &m2, &wall, 0.0, dt, false)
        .unwrap()
        .expect("driven in");
    assert!(
        (hit.time_of_impact - 0.05 / 10.0).abs() < 1e-9,
        "{}",
        hit.time_of_impact
    );
    // Plain, or stopping at penetration: the start.
    let plain = SmoothDispatcher::default().with_cast_policy(CastPolicy::Plain);
    for (disp, stop) in [(&plain, false), (&d, true)] {
        let hit = disp
            .cast_shapes_nonlinear(&m1, &e, &m2, &wall, 0.0, dt, stop)
            .unwrap()
            .unwrap();
        assert_eq!(hit.time_of_impact, 0.0);
    }
}

/// The moving-pairs pass's policy (`CastPolicy::RapierConstantSpin`) at a start contact: against
/// a body standing still (a wall) the deepening is the translation's, as rapier's own rule
/// measures it, so the spin that digs the ellipse into the wall is left to the solver; between
/// two moving bodies it is the whole motions', spin included, so the same contact with the wall
/// drifting at 1 mm/s along its face is stopped where the spin has taken it the allowance deeper.
#[test]
fn the_moving_pairs_policy_takes_the_whole_motions_only_between_two_moving_bodies() {
    let d = SmoothDispatcher::default().with_cast_policy(CastPolicy::RapierConstantSpin);
    let (e, m1, wall, still, dt) = spinning_ellipse_at_a_wall();
    let d_end = signed_at(&d, &m1, &e, &still, &wall, dt);
    assert!(d_end < -0.14, "{d_end}");
    assert!(d
        .cast_shapes_nonlinear(&m1, &e, &still, &wall, 0.0, dt, false)
        .unwrap()
        .is_none());
    let drifting = NonlinearRigidMotion {
        linvel: Vector::new(0.0, 1e-3),
        ..still
    };
    let hit = d
        .cast_shapes_nonlinear(&m1, &e, &drifting, &wall, 0.0, dt, false)
        .unwrap()
        .expect("the whole motions take the contact deeper");
    // Where the whole motions have taken it the allowance deeper: a quarter of the ellipse's
    // inradius (0.2) below the start's 10⁻³.
    let at_hit = signed_at(&d, &m1, &e, &drifting, &wall, hit.time_of_impact);
    assert!(
        hit.time_of_impact < dt && (at_hit + 1e-3 + 0.05).abs() < 1e-6,
        "{} {at_hit}",
        hit.time_of_impact
    );
}

/// A rounded square 10⁻³ into a thin wall at 100 m/s (neither side strictly convex: the gap
/// tracker): parry answers the approaching contact with `time_of_impact = 0`, which rapier
/// discards (the square would pass the wall); the dispatcher reports it where the translation
/// has taken it an allowance deeper, a quarter of the square's inradius.
#[test]
fn polygonal_contact_at_the_start_is_reported_after_the_start() {
    let d = SmoothDispatcher::default();
    let sq = RoundedPolygon::regular(4, 0.5, 0.05);
    let wall = Cuboid::new(Vector::new(0.025, 3.0));
    let dt = 1.0 / 60.0;
    // A flat side facing +x (the square turned by π/4), 10⁻³ into the wall's face at x = 0.
    let inradius = 0.5 * std::f64::consts::FRAC_1_SQRT_2 + 0.05;
    let m2 = NonlinearRigidMotion::constant_position(Pose::translation(0.025, 0.0));
    let at = |v: f64| {
        NonlinearRigidMotion::new(
            Pose::new(Vector::new(-inradius + 1e-3, 0.0), std::f64::consts::FRAC_PI_4),
            Vector::ZERO,
            Vector::new(v, 0.0),
            0.0,
        )
    };
    let fast = at(100.0);
    let parry = DefaultQueryDispatcher
        .cast_shapes_nonlinear(&fast, &sq, &m2, &wall, 0.0, dt, false)
        .unwrap();
    let hit = d
        .cast_shapes_nonlinear(&fast, &sq, &m2, &wall, 0.0, dt, false)
        .unwrap()
        .expect("a hit");
    println!(
        "rounded square 1e-3 into a wall at 100 m/s: parry's hit at {:?}, the dispatcher's at {:.3e} s",
        parry.map(|h| h.time_of_impact),
        hit.time_of_impact
    );
    let allowance = CastPolicy::ALLOWANCE * inradius;
    assert!(
        (hit.time_of_impact - allowance / 100.0).abs() < 1e-12,
        "{}",
        hit.time_of_impact
    );
    let deeper = signed_at(&d, &fast, &sq, &m2, &wall, hit.time_of_impact);
    assert!((deeper + 1e-3 + allowance).abs() < 1e-9, "{deeper}");
    // Slow (0.1 m/s: 0.0017 over the step) or leaving: no hit.
    for v in [0.1, -100.0] {
        assert!(d
            .cast_shapes_nonlinear(&at(v), &sq, &m2, &wall, 0.0, dt, false)
            .unwrap()
            .is_none());
    }
    // Stopping at penetration: the start, as parry's.
    let stop = d.cast_shapes_nonlinear(&fast, &sq, &m2, &wall, 0.0, dt, true).unwrap();
    let parry_stop = DefaultQueryDispatcher
        .cast_shapes_nonlinear(&fast, &sq, &m2, &wall, 0.0, dt, true)
        .unwrap();
    assert_eq!(stop.map(|h| h.time_of_impact), parry_stop.map(|h| h.time_of_impact));
}

/// Where rapier's CCD clamped a rounded heptagon flying at a box wall (zero spin, a flat side
/// parallel to the wall's face, 8.2e-11 away; recorded from `examples/wall_shots.rs`), parry's
/// support-map contact and contact manifold come back empty although parry's own distance is
/// 8.2e-11 (GJK/EPA give up on the nearly touching parallel faces); rapier's solver then gets no
/// contact and the next step's cast answers the start time (rapier discards it) or nothing: the
/// heptagon passed through the wall in 3 of 100 shots. The dispatcher
/// computes the contact on the shapes pushed 10⁻⁸ of their size into each other and measures the
/// distance at the true pose; the manifold and the cast see the wall.
#[test]
fn nearly_touching_polygonal_pair_is_not_lost_to_parrys_gjk() {
    let d = SmoothDispatcher::default();
    let wall = Cuboid::new(Vector::new(0.025, 3.0));
    let hept = RoundedPolygon::regular(7, 0.4, 0.06);
    let pos12 = Pose::from_parts(
        Vector::new(-0.48259960463207285, 0.0),
        Rotation::from_cos_sin_unchecked(-0.848100031710408, -0.5298361409084934),
    );
    let gap = DefaultQueryDispatcher.distance(&pos12, &wall, &hept).unwrap().distance;
    let parry = DefaultQueryDispatcher.contact(&pos12, &wall, &hept, 0.02).unwrap();
    let mut parry_manifold = ContactManifold::<(), ()>::new();
    DefaultQueryDispatcher
        .contact_manifold_convex_convex(&pos12, &wall, &hept, None, None, 0.02, &mut parry_manifold)
        .unwrap();
    println!(
        "nearly touching heptagon: parry's distance {gap:.3e}, parry's contact {:?}, parry's manifold {} points",
        parry.map(|c| c.dist),
        parry_manifold.points.len()
    );
    let c = d.contact(&pos12, &wall, &hept, 0.02).unwrap().expect("a contact");
    assert!((c.dist - gap).abs() < 1e-12, "{} vs {gap}", c.dist);
    assert!((c.normal1 + Vector::X).length() < 1e-9, "{}", c.normal1);
    for (g1, g2, pose) in [
        (&wall as &dyn Shape, &hept as &dyn Shape, pos12),
        (&hept, &wall, pos12.inverse()),
    ] {
        let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
        d.contact_manifolds(&pose, g1, g2, 0.02, &mut manifolds, &mut None)
            .unwrap();
        let points: Vec<f64> = manifolds.iter().flat_map(|m| m.points.iter().map(|p| p.dist)).collect();
        assert!(!points.is_empty(), "no contact point");
        assert!(points.iter().all(|&p| (p - gap).abs() < 1e-9 || p > gap), "{points:?}");
    }
    // rapier's CCD of the next step: the heptagon flying on at 200 m/s.
    let m1 = NonlinearRigidMotion::new(pos12, Vector::ZERO, Vector::new(200.0, 0.0), 0.0);
    let m2 = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let dt = 1.0 / 60.0;
    let parry = DefaultQueryDispatcher
        .cast_shapes_nonlinear(&m1, &hept, &m2, &wall, 0.0, dt, false)
        .unwrap();
    let hit = d
        .cast_shapes_nonlinear(&m1, &hept, &m2, &wall, 0.0, dt, false)
        .unwrap()
        .expect("the wall");
    println!(
        "  next step's cast: parry {:?}, the dispatcher {:.3e} s",
        parry.map(|h| h.time_of_impact),
        hit.time_of_impact
    );
    // Stopped where the translation has taken it an allowance deep, a quarter of the
    // heptagon's inradius 0.4·cos(π/7) + 0.06 (its core, as far again, is 0.3 further).
    let allowance = CastPolicy::ALLOWANCE * (0.4 * (std::f64::consts::PI / 7.0).cos() + 0.06);
    assert!(
        (hit.time_of_impact - allowance / 200.0).abs() < 1e-9,
        "{}",
        hit.time_of_impact
    );
}

#[test]
fn nonlinear_cast_against_a_half_space_is_answered_where_parry_has_none() {
    let d = SmoothDispatcher::default();
    let p = RoundedPolygon::regular(5, 1.0, 0.1);
    let hs = HalfSpace::new(Vector::Y);
    let ground = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let falling = NonlinearRigidMotion::new(
        Pose::new(Vector::new(0.0, 3.0), 0.2),
        Vector::ZERO,
        Vector::new(0.5, -4.0),
        20.0,
    );
    let parry = DefaultQueryDispatcher.cast_shapes_nonlinear(&falling, &p, &ground, &hs, 0.0, 1.0, false);
    assert!(
        parry.is_err() || parry.unwrap().is_none(),
        "parry has no nonlinear half-space cast"
    );
    let hit = d
        .cast_shapes_nonlinear(&falling, &p, &ground, &hs, 0.0, 1.0, false)
        .unwrap()
        .expect("it lands");
    // At the hit the lowest point is on the ground; just before, above it.
    let low = |t: f64| {
        let pose = falling.position_at_time(t);
        let n = -pose.rotation.inverse_transform_vector(Vector::Y);
        (pose * smooth_ccd2d::ConvexCurve::support_point(&p, n)).y
    };
    assert!(low(hit.time_of_impact).abs() < 1e-9, "{}", low(hit.time_of_impact));
    for k in 0..200 {
        assert!(low(hit.time_of_impact * k as f64 / 200.0) > 0.0);
    }
    // Same answer with the order of the shapes swapped.
    let hit2 = d
        .cast_shapes_nonlinear(&ground, &hs, &falling, &p, 0.0, 1.0, false)
        .unwrap()
        .unwrap();
    assert!((hit2.time_of_impact - hit.time_of_impact).abs() < 1e-15);
    assert!((hit2.witness2 - hit.witness1).length() < 1e-12);
}

#[test]
fn bad_input_never_panics_or_returns_nan() {
    let d = SmoothDispatcher::default();
    let e = Ellipse::new(0.5, 0.2);
    let b = Ball::new(0.3);
    let nan_pose = Pose::new(Vector::new(f64::NAN, 0.0), 0.0);
    let inf_pose = Pose::new(Vector::new(f64::INFINITY, 0.0), 0.3);
    for pose in [nan_pose, inf_pose] {
        if let Ok(r) = d.distance(&pose, &e, &b) {
            assert!(!r.distance.is_nan());
        }
        if let Ok(Some(c)) = d.contact(&pose, &e, &b, 0.1) {
            assert!(c.dist.is_finite());
        }
        let _ = d.intersection_test(&pose, &e, &b);
        let _ = d.closest_points(&pose, &e, &b, 1.0);
        let m = NonlinearRigidMotion::constant_position(pose);
        if let Ok(Some(h)) = d.cast_shapes_nonlinear(&m, &e, &NonlinearRigidMotion::identity(), &b, 0.0, 1.0, true) {
            assert!(h.time_of_impact.is_finite());
        }
    }
    // Reversed and empty windows: no hit.
    let m2 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(3.0, 0.0), 0.0),
        Vector::ZERO,
        Vector::new(-1.0, 0.0),
        0.0,
    );
    let id = NonlinearRigidMotion::identity();
    assert!(d
        .cast_shapes_nonlinear(&id, &e, &m2, &b, 1.0, 0.0, true)
        .unwrap()
        .is_none());
    assert!(d
        .cast_shapes_nonlinear(&id, &e, &m2, &b, 0.5, 0.5, true)
        .unwrap()
        .is_none());
}

/// Under `CastPolicy::Rapier` a cast whose shapes start in contact answers by the rule for
/// start contacts (the body's translation and its core); that answer is the same, shifted, for
/// a window that does not start at 0. A flat 0.8 × 0.2 rounded bar resting 0.001 deep on a
/// floor, driven down at 2 m/s while it slides and spins at 7.9 rad/s: cast over [0, dt] from
/// its pose, and over [0.3, 0.3 + dt] on the same motion started 0.3 s earlier (turned back by
/// 2.37 rad). The rule's translation once started from the rotation at t = 0, not at the
/// window's start: the second cast translated a bar turned by 2.37 rad from its real pose.
#[test]
fn start_contact_answers_do_not_depend_on_where_the_window_starts() {
    let dt = 1.0 / 60.0;
    let bar = RoundedPolygon::new(
        &[
            Vector::new(-0.4, -0.1),
            Vector::new(0.4, -0.1),
            Vector::new(0.4, 0.1),
            Vector::new(-0.4, 0.1),
        ],
        0.02,
    );
    let floor = Cuboid::new(Vector::new(5.0, 0.5));
    let still = NonlinearRigidMotion::constant_position(Pose::new(Vector::new(0.0, -0.5), 0.0));
    // The default policy is `CastPolicy::Rapier`.
    let d = SmoothDispatcher::default().with_cast_policy(CastPolicy::Rapier);
    for (v, w) in [
        (Vector::new(3.0, -2.0), 7.9),
        (Vector::new(-1.0, -2.0), -7.9),
        (Vector::new(0.5, -2.5), 3.0),
    ] {
        let rest = Pose::new(Vector::new(0.2, 0.119), 0.0);
        let from_zero = NonlinearRigidMotion::new(rest, Vector::ZERO, v, w);
        let t0 = 0.3;
        let earlier = Pose::new(rest.translation - v * t0, -w * t0);
        let from_earlier = NonlinearRigidMotion::new(earlier, Vector::ZERO, v, w);
        let a = d
            .cast_shapes_nonlinear(&from_zero, &bar, &still, &floor, 0.0, dt, false)
            .expect("supported")
            .expect("driven 2 m/s into the floor over the step: a hit");
        let b = d
            .cast_shapes_nonlinear(&from_earlier, &bar, &still, &floor, t0, t0 + dt, false)
            .expect("supported")
            .expect("the same motion, later: a hit");
        assert!(a.time_of_impact > 0.0 && a.time_of_impact < dt, "{a:?}");
        assert!(
            (b.time_of_impact - t0 - a.time_of_impact).abs() < 1e-9 * dt,
            "v {v:?} ω {w}: {} from 0, {} from {t0}",
            a.time_of_impact,
            b.time_of_impact - t0
        );
        assert_eq!(a.status, b.status);
    }
}
