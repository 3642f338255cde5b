//! Unit tests of the nonlinear cast's fast path (`super`).

use super::*;
use crate::dispatcher::route::RouteScratch;
use crate::dispatcher::support_shape::exact_contact;
use crate::numerics::math::{Pose, Vector};
use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};
use parry2d_f64::shape::{Ball, Cuboid};

/// The route's own signed distance of a cast's pair (the curves' stationary distance or the
/// gap tracker's), `None` for the other routes.
fn route_distance(g1: &dyn Shape, g2: &dyn Shape, pos12: &Pose) -> Option<(&'static str, Real)> {
    let mut scratch = RouteScratch::default();
    match route_cast(g1, g2, &mut scratch) {
        Route::Curves { c1, c2, swapped } => pair_distance(&c1, &c2, swapped, pos12, &Default::default())
            .ok()
            .map(|d| ("curves", d.distance)),
        Route::Gap { c1, c2 } => {
            let (p1, p2) = (c1.gap_side()?, c2.gap_side()?);
            gap_distance(p1, p2, pos12).map(|d| ("gap", d.0))
        }
        _ => None,
    }
}

/// The rapier rule's samples take the exact contact query's signed distance in place of the
/// route's: the same number to rounding, apart and overlapping, on both routes.
#[test]
fn exact_contact_is_each_routes_signed_distance() {
    let shapes: Vec<Box<dyn Shape>> = vec![
        Box::new(Ellipse::new(0.5, 0.2)),
        Box::new(CapsuleEllipse::new(0.3, 0.2, 0.4)),
        Box::new(RoundedPolygon::regular(5, 0.4, 0.05)),
        Box::new(Cuboid::new(Vector::new(0.6, 0.25))),
        Box::new(Ball::new(0.3)),
    ];
    let mut rng = crate::numerics::test_rng::Lcg(0x2545_F491_4F6C_DD1Du64);
    let mut uniform = |lo: f64, hi: f64| rng.range(lo, hi);
    let (mut compared, mut routes) = (0, std::collections::BTreeSet::new());
    for g1 in &shapes {
        for g2 in &shapes {
            let size = g1.compute_local_bounding_sphere().radius + g2.compute_local_bounding_sphere().radius;
            for _ in 0..300 {
                let (a, r) = (uniform(-3.2, 3.2), uniform(0.2, 1.3) * size);
                let pos12 = Pose::new(Vector::new(a.cos(), a.sin()) * r, uniform(-3.2, 3.2));
                let (Some(exact), Some((route, own))) = (
                    exact_contact(&pos12, &**g1, &**g2, None),
                    route_distance(&**g1, &**g2, &pos12),
                ) else {
                    continue;
                };
                assert!(
                    (exact.dist - own).abs() <= 1e-12 * size,
                    "{route}: {:?} / {:?} at {pos12:?}: {} against {own}",
                    g1.shape_type(),
                    g2.shape_type(),
                    exact.dist
                );
                compared += 1;
                routes.insert(route);
            }
        }
    }
    println!("{compared} poses compared on the routes {routes:?}");
    assert!(compared > 5000 && routes.len() == 2, "{compared} {routes:?}");
}

/// The polygon gap is a lower bound of the exact signed distance of a body and a still
/// polygonal target (a long wall, whose bounding sphere holds every body near it), and it
/// sees bodies apart that the bounding spheres cannot: random poses and local centres of
/// every body kind against segments, a thin box and a capsule.
#[test]
fn the_polygon_gap_bounds_the_distance_where_the_spheres_do_not() {
    use parry2d_f64::shape::{Capsule, Segment};
    let bodies: Vec<Box<dyn Shape>> = vec![
        Box::new(Ellipse::new(0.5, 0.2)),
        Box::new(Ellipse::new(0.3, 0.3)),
        Box::new(CapsuleEllipse::new(0.3, 0.2, 0.4)),
        Box::new(RoundedPolygon::regular(5, 0.4, 0.05)),
        Box::new(RoundedPolygon::regular(4, 0.35, 0.0)),
    ];
    let targets: Vec<Box<dyn Shape>> = vec![
        Box::new(Segment::new(Vector::new(-5.0, 0.0), Vector::new(5.0, 0.0))),
        Box::new(Segment::new(Vector::new(-0.2, -3.0), Vector::new(0.3, 4.0))),
        Box::new(Cuboid::new(Vector::new(4.0, 0.025))),
        Box::new(Capsule::new(Vector::new(-3.0, 0.5), Vector::new(3.0, -0.5), 0.1)),
    ];
    let mut rng = crate::numerics::test_rng::Lcg(0x5DEE_CE66_D1CE_4E5Bu64);
    let mut uniform = |lo: f64, hi: f64| rng.range(lo, hi);
    let (mut cases, mut seen_apart, mut spheres_blind) = (0, 0, 0);
    for body in &bodies {
        for target in &targets {
            for _ in 0..400 {
                let lc = Vector::new(uniform(-0.1, 0.1), uniform(-0.1, 0.1));
                let start = Pose::new(Vector::new(uniform(-5.0, 5.0), uniform(-2.0, 2.0)), uniform(-3.2, 3.2));
                let m1 = NonlinearRigidMotion::new(
                    start,
                    lc,
                    Vector::new(uniform(-9.0, 9.0), uniform(-9.0, 9.0)),
                    uniform(-9.0, 9.0),
                );
                let pose2 = Pose::new(Vector::new(uniform(-0.5, 0.5), uniform(-0.5, 0.5)), uniform(-0.3, 0.3));
                let m2 = NonlinearRigidMotion::constant_position(pose2);
                let c = NonlinearCast::new(&m1, &**body, &m2, &**target, (0.0, 1.0 / 60.0), false);
                let (mut st1, mut st2) = (SupportScratch::default(), SupportScratch::default());
                let s1 = support_shape(&**body, &mut st1).unwrap();
                let s2 = support_shape(&**target, &mut st2).unwrap();
                let pos12 = pos12_at(&m1, &m2, 0.0);
                let gap = polygon_gap(&c, s1, s2, &pos12);
                let d = exact_contact(&pos12, &**body, &**target, None).unwrap().dist;
                assert!(
                    gap <= d + 1e-12,
                    "{:?}: gap {gap} above the distance {d}",
                    body.shape_type()
                );
                cases += 1;
                if gap > 0.0 {
                    seen_apart += 1;
                    if sphere_gap(&c) <= 0.0 {
                        spheres_blind += 1;
                    }
                }
            }
        }
    }
    println!("{cases} poses: {seen_apart} seen apart by the polygon gap, {spheres_blind} of them not by the spheres");
    assert!(spheres_blind * 4 > cases, "{spheres_blind} of {cases}");
}

#[test]
fn two_turning_bodies_cast_with_stop_at_penetration_go_to_the_trackers_with_the_same_answer() {
    use crate::SmoothDispatcher;
    use parry2d_f64::query::QueryDispatcher;
    let rapier = SmoothDispatcher::default();
    let plain = SmoothDispatcher::default().with_cast_policy(crate::CastPolicy::Plain);
    let e = Ellipse::new(0.5, 0.2);
    let p = RoundedPolygon::regular(5, 0.4, 0.05);
    let mut hits = 0;
    for k in 0..40 {
        let s = k as Real / 40.0;
        let m1 = NonlinearRigidMotion::new(
            Pose::new(Vector::new(-1.5, 0.2 * s), 0.3),
            Vector::ZERO,
            Vector::new(2.0, 0.0),
            3.0 + s,
        );
        let m2 = NonlinearRigidMotion::new(
            Pose::new(Vector::new(0.8, -0.1), -0.4),
            Vector::ZERO,
            Vector::new(-0.5, 0.1),
            -2.0,
        );
        let c = NonlinearCast::new(&m1, &e, &m2, &p, (0.0, 1.0), true);
        let (opts, rule) = rapier.cast_setup(&c);
        assert!(rule.rapier && !rule.start_contact);
        // Both bodies turn and no start-contact rule applies: the fast path declines at once.
        assert!(rapier_fast_path(&c, &opts, rule).is_none(), "case {k}");
        let a = rapier.cast_shapes_nonlinear(&m1, &e, &m2, &p, 0.0, 1.0, true).unwrap();
        let b = plain.cast_shapes_nonlinear(&m1, &e, &m2, &p, 0.0, 1.0, true).unwrap();
        assert_eq!(a.is_some(), b.is_some(), "case {k}");
        if let (Some(a), Some(b)) = (a, b) {
            assert!((a.time_of_impact - b.time_of_impact).abs() <= 1e-9, "case {k}");
            hits += 1;
        }
    }
    assert!(hits > 20, "{hits} hits");
}
