//! Property tests over random shapes, poses and motions, tolerances scaled to size.

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use proptest::prelude::*;
use proptest::test_runner::{TestCaseError, TestRunner};
use smooth_ccd2d::{
    stationary_distance, time_of_impact, ConvexCurve, DistanceOptions, Ellipse, RoundedPolygon, ToiOptions, ToiStatus,
};
use std::sync::atomic::{AtomicUsize, Ordering};

const CASES: u32 = 400;

fn shape(kind: u8, scale: f64, ratio: f64, sides: usize, r: f64) -> Box<dyn ConvexCurve> {
    match kind % 3 {
        0 => Box::new(Ellipse::new(scale, scale * ratio)),
        1 => Box::new(RoundedPolygon::regular(sides, scale, scale * r)),
        _ => Box::new(Ellipse::new(scale * ratio, scale)),
    }
}

fn gap_along(o1: &dyn ConvexCurve, o2: &dyn ConvexCurve, pos12: &Pose, th: f64) -> f64 {
    let n = Vector::new(th.cos(), th.sin());
    let h1 = o1.support_point(n).dot(n);
    let m = pos12.rotation.inverse_transform_vector(-n);
    let p2 = *pos12 * o2.support_point(m);
    p2.dot(n) - h1
}

/// Runs `CASES` cases of `strategy` through `test` and prints how many ran (all of them, or the
/// test fails with proptest's minimal failing input).
fn run_property<S: Strategy>(name: &str, strategy: S, test: impl Fn(S::Value) -> Result<(), TestCaseError>) {
    let mut runner = TestRunner::new(ProptestConfig {
        cases: CASES,
        failure_persistence: None,
        ..ProptestConfig::default()
    });
    let ran = AtomicUsize::new(0);
    let result = runner.run(&strategy, |v| {
        test(v)?;
        ran.fetch_add(1, Ordering::Relaxed);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{name}: {e}");
    }
    println!("{name}: {} cases passed", ran.load(Ordering::Relaxed));
}

/// The stationary distance is the maximum of the separating-axis gap: no sampled axis beats it.
#[test]
fn stationary_distance_is_the_largest_gap_over_all_axes() {
    let strategy = (
        0u8..3,
        -2.0f64..2.0,
        0.01f64..1.0,
        3usize..9,
        0.0f64..0.3,
        0.05f64..1.0,
        0.0f64..2.5,
        -3.2f64..3.2,
        -3.2f64..3.2,
    );
    run_property(
        "stationary distance is the largest gap",
        strategy,
        |(kind1, log_scale, ratio, sides, r, ratio2, dist, dir, angle)| {
            let s = 10f64.powf(log_scale);
            let o1 = shape(kind1, s, ratio, sides, r);
            let o2 = Ellipse::new(s * 0.8, s * 0.8 * ratio2);
            let reach = o1.bounding_radius() + o2.bounding_radius();
            let pos12 = Pose::new(Vector::new(dir.cos(), dir.sin()) * (dist * reach), angle);
            let d = stationary_distance(&*o1, &o2, &pos12, &DistanceOptions::default()).unwrap();
            prop_assert!(d.distance.is_finite());
            let size = reach;
            for k in 0..720 {
                let th = -std::f64::consts::PI + std::f64::consts::TAU * k as f64 / 720.0;
                prop_assert!(gap_along(&*o1, &o2, &pos12, th) <= d.distance + 1e-9 * size);
            }
            // The witnesses realise it.
            let w2 = pos12 * d.point2;
            prop_assert!(((w2 - d.point1).dot(d.normal1) - d.distance).abs() <= 1e-9 * size);
            Ok(())
        },
    );
}

/// At a reported impact the distance is at the target, it is positive at earlier sampled
/// times, and swapping the shapes gives the same time.
#[test]
fn impacts_are_on_target_first_and_symmetric() {
    let shapes = (0u8..3, -2.0f64..2.0, 0.01f64..1.0, 3usize..9, 0.0f64..0.3, 0.05f64..1.0);
    let motions = (
        -3.2f64..3.2,
        -3.2f64..3.2,
        -60.0f64..60.0,
        -10.0f64..10.0,
        0.5f64..6.0,
        -1.0f64..1.0,
    );
    run_property(
        "impacts are on target, first and symmetric",
        (shapes, motions),
        |((kind1, log_scale, ratio, sides, r, ratio2), (dir, a1, w1, w2, speed, aim))| {
            let s = 10f64.powf(log_scale);
            let o1 = shape(kind1, s, ratio, sides, r);
            let o2 = Ellipse::new(s * 0.8, s * 0.8 * ratio2);
            let reach = o1.bounding_radius() + o2.bounding_radius();
            let start = Vector::new(dir.cos(), dir.sin()) * (1.05 * reach);
            let toward = (-start).normalize();
            let v = (toward + Vector::new(-toward.y, toward.x) * aim) * (speed * s);
            let m1 = NonlinearRigidMotion::new(Pose::new(start, a1), Vector::ZERO, v, w1);
            let m2 = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::ZERO, w2);
            let opts = ToiOptions::default();
            let r1 = time_of_impact(&*o1, &m1, &o2, &m2, 0.0, 1.0, &opts).unwrap();
            let r2 = time_of_impact(&o2, &m2, &*o1, &m1, 0.0, 1.0, &opts).unwrap();
            prop_assert_eq!(r1.status, r2.status);
            let dist_at = |t: f64| {
                let pos12 = m1.position_at_time(t).inv_mul(&m2.position_at_time(t));
                stationary_distance(&*o1, &o2, &pos12, &DistanceOptions::default())
                    .unwrap()
                    .distance
            };
            if r1.status == ToiStatus::Hit {
                prop_assert!((r1.time - r2.time).abs() <= 1e-9);
                let d = dist_at(r1.time);
                prop_assert!(d >= -1e-11 * reach && d <= 1e-9 * reach, "distance at the hit {}", d);
                for k in 0..50 {
                    prop_assert!(dist_at(r1.time * k as f64 / 50.0) > 0.0);
                }
            } else if r1.status == ToiStatus::NoHit {
                for k in 0..=50 {
                    prop_assert!(dist_at(k as f64 / 50.0) > -1e-9 * reach);
                }
            }
            Ok(())
        },
    );
}

/// rapier's cast of a body that does not turn (an ellipse or a polygon, sharp or rounded, the
/// closed forms of `SmoothDispatcher`) against a target at rest (a box, a segment, a ball, a
/// capsule), at scales 1e-3 to 1e3: at a hit the exact distance is within the tolerance of 0 and
/// positive at every earlier sampled time; at no hit it never goes below the tolerance's band.
/// The distances from the dispatcher's `distance` query (the exact contact, not the cast).
#[test]
fn casts_of_bodies_that_do_not_turn_touch_first_at_every_scale() {
    use parry2d_f64::query::QueryDispatcher;
    use parry2d_f64::shape::{Ball, Capsule, Cuboid, Segment, Shape};
    use smooth_ccd2d::SmoothDispatcher;
    let (hits, misses) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let bodies = (0u8..3, -3.0f64..3.0, 0.02f64..1.0, 3usize..9, 0.0f64..0.3, -3.2f64..3.2);
    let motions = (
        0u8..4,
        -3.2f64..3.2,
        -3.2f64..3.2,
        1.05f64..3.0,
        -1.2f64..1.2,
        0.2f64..2.0,
    );
    run_property(
        "casts of bodies that do not turn touch first at every scale",
        (bodies, motions),
        |((kind, log_scale, ratio, sides, r, angle), (target_kind, dir, target_angle, away, aim, reach_factor))| {
            let s = 10f64.powf(log_scale);
            let body: Box<dyn Shape> = match kind {
                0 => Box::new(Ellipse::new(s, s * ratio)),
                1 => Box::new(Ellipse::new(s * ratio, s)),
                _ => Box::new(RoundedPolygon::regular(sides, s, s * r)),
            };
            let target: Box<dyn Shape> = match target_kind {
                0 => Box::new(Cuboid::new(Vector::new(1.5 * s, 0.1 * s))),
                1 => Box::new(Segment::new(Vector::new(-s, 0.2 * s), Vector::new(s, -0.3 * s))),
                2 => Box::new(Ball::new(0.6 * s)),
                _ => Box::new(Capsule::new(
                    Vector::new(-0.5 * s, 0.0),
                    Vector::new(0.7 * s, 0.3 * s),
                    0.2 * s,
                )),
            };
            let reach = body.compute_local_bounding_sphere().radius + target.compute_local_bounding_sphere().radius;
            let start = Vector::new(dir.cos(), dir.sin()) * (away * reach);
            let aim_at = Vector::new(-start.y, start.x).normalize() * (aim * reach);
            let dt = 1.0 / 60.0;
            let v = (aim_at - start) * (reach_factor / dt);
            let m1 = NonlinearRigidMotion::new(Pose::new(start, angle), Vector::ZERO, v, 0.0);
            let pose2 = Pose::new(Vector::ZERO, target_angle);
            let m2 = NonlinearRigidMotion::constant_position(pose2);
            let d = SmoothDispatcher::default();
            let hit = d
                .cast_shapes_nonlinear(&m1, &*body, &m2, &*target, 0.0, dt, false)
                .unwrap();
            let dist_at = |t: f64| {
                let pos12 = m1.position_at_time(t).inv_mul(&pose2);
                d.distance(&pos12, &*body, &*target).unwrap().distance
            };
            let tol = 1e-9 * reach;
            match hit {
                Some(h) => {
                    hits.fetch_add(1, Ordering::Relaxed);
                    let t = h.time_of_impact;
                    prop_assert!((0.0..=dt).contains(&t), "time {}", t);
                    prop_assert!(dist_at(t) <= tol, "distance at the hit {} (size {})", dist_at(t), reach);
                    for k in 0..50 {
                        prop_assert!(dist_at(t * k as f64 / 50.0) > 0.0, "an earlier contact");
                    }
                }
                None => {
                    misses.fetch_add(1, Ordering::Relaxed);
                    for k in 0..=100 {
                        prop_assert!(dist_at(dt * k as f64 / 100.0) > -tol, "a missed contact");
                    }
                }
            }
            Ok(())
        },
    );
    let (hits, misses) = (hits.into_inner(), misses.into_inner());
    println!("  {hits} hits, {misses} misses");
    assert!(hits >= 100 && misses >= 100, "{hits} hits, {misses} misses");
}

/// Constructors never panic through `try_*` and never yield a shape from bad numbers.
#[test]
fn try_constructors_reject_bad_numbers_without_panicking() {
    let strategy = (
        prop_oneof![
            Just(f64::NAN),
            Just(f64::INFINITY),
            Just(-1.0),
            Just(0.0),
            1e-300f64..1e300
        ],
        prop_oneof![Just(f64::NAN), Just(f64::NEG_INFINITY), Just(-0.5), 1e-300f64..1e300],
        0usize..12,
    );
    run_property("try constructors reject bad numbers", strategy, |(a, b, n)| {
        // Lengths must be finite, positive and within [MIN_LENGTH, MAX_LENGTH].
        let ok = |x: f64| (smooth_ccd2d::MIN_LENGTH..=smooth_ccd2d::MAX_LENGTH).contains(&x);
        let e = Ellipse::try_new(a, b);
        prop_assert_eq!(e.is_ok(), ok(a) && ok(b));
        let p = RoundedPolygon::try_regular(n, a, b.abs());
        if p.is_ok() {
            prop_assert!(n >= 3 && ok(a));
        }
        let c = smooth_ccd2d::CapsuleEllipse::try_new(a, b, 1.0);
        prop_assert_eq!(c.is_ok(), ok(a) && ok(b));
        Ok(())
    });
}

/// A contact manifold's deepest point is the signed distance (the gap along its normal, which no
/// sampled axis beats), every point's distance is measured along its manifold's normal, and a
/// core contact (a disc inside its body, in a manifold of its own) is never closer than the
/// bodies, for random polygons (sharp or rounded), ellipses, capsule-ellipses, discs and boxes.
#[test]
fn manifold_depth_is_the_largest_gap_over_all_axes() {
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
    use parry2d_f64::shape::{Ball, Cuboid, Shape};
    use smooth_ccd2d::{CapsuleEllipse, SmoothDispatcher};
    let strategy = (
        (0u8..5, 0u8..5),
        -1.0f64..1.0,
        (0.01f64..1.0, 3usize..9, 0.0f64..0.3),
        (0.0f64..1.2, -3.2f64..3.2, -3.2f64..3.2),
    );
    run_property(
        "manifold depth is the largest gap",
        strategy,
        |((k1, k2), log_scale, (ratio, sides, r), (dist, dir, angle))| {
            let s = 10f64.powf(log_scale);
            // Each shape as parry sees it and as a curve (for the sampled gap).
            let make = |k: u8| -> (Box<dyn Shape>, Box<dyn ConvexCurve>) {
                match k {
                    0 => (
                        Box::new(Ellipse::new(s, s * ratio)),
                        Box::new(Ellipse::new(s, s * ratio)),
                    ),
                    1 => {
                        let p = RoundedPolygon::regular(sides, s, s * r);
                        (Box::new(p.clone()), Box::new(p))
                    }
                    2 => {
                        let c = CapsuleEllipse::new(0.3 * s, 0.4 * s, s * (0.2 + ratio));
                        (Box::new(c.clone()), Box::new(c))
                    }
                    3 => (
                        Box::new(Ball::new(0.5 * s)),
                        Box::new(smooth_ccd2d::BallCurve { radius: 0.5 * s }),
                    ),
                    _ => {
                        let h = Vector::new(s, s * (0.1 + ratio));
                        let core = [
                            Vector::new(-h.x, -h.y),
                            Vector::new(h.x, -h.y),
                            h,
                            Vector::new(-h.x, h.y),
                        ];
                        (Box::new(Cuboid::new(h)), Box::new(RoundedPolygon::new(&core, 0.0)))
                    }
                }
            };
            // One of this crate's shapes at least (parry's own pairs are parry's).
            let k1 = if k1 >= 3 && k2 >= 3 { 1 } else { k1 };
            let ((g1, c1), (g2, c2)) = (make(k1), make(k2));
            let reach = c1.bounding_radius() + c2.bounding_radius();
            let pos12 = Pose::new(Vector::new(dir.cos(), dir.sin()) * (dist * reach), angle);
            let mut m: Vec<ContactManifold<(), ()>> = Vec::new();
            SmoothDispatcher::default()
                .contact_manifolds(&pos12, &*g1, &*g2, 2.0 * reach, &mut m, &mut None)
                .unwrap();
            let points: Vec<_> = m.iter().flat_map(|m| m.points.iter().map(move |p| (m, p))).collect();
            prop_assert!(!points.is_empty());
            let deepest = points.iter().map(|(_, p)| p.dist).fold(f64::INFINITY, f64::min);
            for k in 0..720 {
                let th = -std::f64::consts::PI + std::f64::consts::TAU * k as f64 / 720.0;
                prop_assert!(gap_along(&*c1, &*c2, &pos12, th) <= deepest + 1e-9 * reach);
            }
            for (mf, p) in &points {
                let n = mf.local_n1;
                prop_assert!((n.length() - 1.0).abs() < 1e-12);
                prop_assert!(((pos12 * p.local_p2 - p.local_p1).dot(n) - p.dist).abs() <= 1e-9 * reach);
                if smooth_ccd2d::__is_core_feature(p.fid1.0) {
                    // A core contact (a disc inside its body, along its own normal): never closer
                    // than the bodies themselves.
                    prop_assert!(p.dist >= deepest - 1e-9 * reach);
                } else {
                    // The gap along the normal is the deepest distance (the normal is the optimum).
                    let th = n.y.atan2(n.x);
                    prop_assert!((gap_along(&*c1, &*c2, &pos12, th) - deepest).abs() <= 1e-9 * reach);
                }
            }
            Ok(())
        },
    );
}
