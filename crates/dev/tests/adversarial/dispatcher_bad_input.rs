//! `SmoothDispatcher` on bad input, including the pairs it hands to parry.

use super::*;

fn no_nan_hit(h: &Option<parry2d_f64::query::ShapeCastHit>) -> bool {
    h.as_ref().is_none_or(|h| {
        h.time_of_impact.is_finite()
            && h.witness1.is_finite()
            && h.witness2.is_finite()
            && h.normal1.is_finite()
            && h.normal2.is_finite()
    })
}

/// parry's nonlinear cast of a pair in contact at the start walks its window with
/// `next_time += increment`, and with no relative spin (or two balls) the increment is
/// `end_time` itself: a window before time 0 never ended (found by the fuzz: two touching balls,
/// window [−2.69, −1.69]). The dispatcher moves the window to start at 0.
#[test]
fn parry_cast_in_a_window_before_time_zero_terminates() {
    let d = SmoothDispatcher::default();
    let (a, b) = (Ball::new(1.1e-6), Ball::new(1.14e-6));
    let m1 = still(0.0, 0.0, 0.3);
    let m2 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(-2.2e-6, 2.2e-7), 0.0),
        Vector::ZERO,
        Vector::new(-7e-7, -6e-7),
        0.8,
    );
    let t = Instant::now();
    for (t0, t1) in [(-2.69, -1.69), (-1.0, 0.0), (1e12, 1e12 + 1.0)] {
        let r = d.cast_shapes_nonlinear(&m1, &a, &m2, &b, t0, t1, false).unwrap();
        assert!(no_nan_hit(&r));
        if let Some(h) = r {
            assert!(h.time_of_impact >= t0 && h.time_of_impact <= t1, "{h:?}");
        }
        // Also for two rounded polygons (parry answers them) sliding without spin.
        let p = RoundedPolygon::regular(5, 0.8, 0.1);
        let mp = NonlinearRigidMotion::new(Pose::new(Vector::new(-0.5, 0.0), 0.0), Vector::ZERO, Vector::X, 0.0);
        let r = d
            .cast_shapes_nonlinear(&mp, &p, &still(0.0, 0.0, 0.0), &p, t0, t1, false)
            .unwrap();
        assert!(no_nan_hit(&r));
    }
    assert!(t.elapsed() < Duration::from_secs(1));
}

/// A spin of f64::MAX made parry's walk take 1e308 steps of 1e-308 s (found by the fuzz). Casts
/// whose window holds more than `PARRY_MAX_STEPS` of parry's steps are refused.
#[test]
fn parry_cast_with_an_absurd_spin_is_refused_not_hung() {
    let d = SmoothDispatcher::default();
    let p = RoundedPolygon::regular(9, 1.5e5, 4e4);
    let q = CapsuleEllipse::new(7e3, 1.5e4, 3.8e4);
    let t = Instant::now();
    for spin in [1e300, f64::MAX] {
        let m1 = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::new(-8.5e5, -7e4), spin);
        let m2 = still(-5.2e5, 4.7e4, 1.1);
        for stop in [true, false] {
            let r = d.cast_shapes_nonlinear(&m1, &p, &m2, &q, 2.0, 3.0, stop);
            assert!(r.is_err() || r.as_ref().is_ok_and(no_nan_hit), "{r:?}");
        }
    }
    assert!(t.elapsed() < Duration::from_secs(1), "{:?}", t.elapsed());
    assert_eq!(smooth_ccd2d::SmoothDispatcher::PARRY_MAX_STEPS, 1e4);
}

/// parry asserts that margins are non-negative (closest points of two balls, composite shapes)
/// and that GJK's support points are finite: through the dispatcher these are `Unsupported`,
/// and parry answers holding a NaN are `Unsupported` too.
#[test]
fn bad_margins_shapes_and_poses_are_unsupported_not_a_panic_or_nan() {
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
    use parry2d_f64::shape::{Compound, Cuboid, SharedShape};
    let d = SmoothDispatcher::default();
    let e = Ellipse::new(0.5, 0.2);
    let p = RoundedPolygon::regular(5, 0.5, 0.05);
    let compound = Compound::new(vec![
        (Pose::IDENTITY, SharedShape::new(e)),
        (Pose::IDENTITY, SharedShape::ball(0.1)),
    ]);
    let pose = Pose::new(Vector::new(0.8, 0.1), 0.2);
    let shapes: [(&dyn parry2d_f64::shape::Shape, &dyn parry2d_f64::shape::Shape); 5] = [
        (&e, &Ball::new(0.3)),
        (&p, &Cuboid::new(Vector::new(0.3, 0.2))),
        (&Ball::new(0.3), &Ball::new(0.2)),
        (&compound, &Ball::new(0.2)),
        (&p, &HalfSpace::new(Vector::Y)),
    ];
    for (g1, g2) in shapes {
        for m in [-1.0, -f64::MAX, f64::NEG_INFINITY, f64::NAN] {
            assert!(d.contact(&pose, g1, g2, m).is_err());
            assert!(d.closest_points(&pose, g1, g2, m).is_err());
            let mut mf: Vec<ContactManifold<(), ()>> = Vec::new();
            assert!(d.contact_manifolds(&pose, g1, g2, m, &mut mf, &mut None).is_err());
        }
        // Non-finite or non-unit poses.
        for bad in [
            Pose::new(Vector::new(f64::NAN, 0.0), 0.0),
            Pose::new(Vector::new(f64::INFINITY, 0.0), 0.0),
            Pose::from_parts(
                Vector::X,
                parry2d_f64::math::Rotation::from_cos_sin_unchecked(-f64::MAX, 0.5),
            ),
        ] {
            if let Ok(r) = d.distance(&bad, g1, g2) {
                assert!(r.distance.is_finite());
            }
            if let Ok(Some(c)) = d.contact(&bad, g1, g2, 0.1) {
                assert!(c.dist.is_finite() && c.point1.is_finite() && c.point2.is_finite());
            }
            let mut mf: Vec<ContactManifold<(), ()>> = Vec::new();
            if d.contact_manifolds(&bad, g1, g2, 0.1, &mut mf, &mut None).is_ok() {
                assert!(mf
                    .iter()
                    .all(|m| m.points.iter().all(|c| c.dist.is_finite() && c.local_p1.is_finite())));
            }
            let opts = ShapeCastOptions::with_max_time_of_impact(1.0);
            if let Ok(h) = d.cast_shapes(&bad, -Vector::X, g1, g2, opts) {
                assert!(no_nan_hit(&h));
            }
        }
    }
    // A parry shape with NaN or infinite sizes against one of ours: parry's GJK would assert.
    for x in [f64::NAN, f64::INFINITY] {
        let bad_box = Cuboid::new(Vector::new(x, 0.2));
        assert!(d.distance(&pose, &p, &bad_box).is_err());
        assert!(d.contact(&pose, &p, &bad_box, 0.1).is_err());
        assert!(d.intersection_test(&pose, &p, &bad_box).is_err());
        let m = NonlinearRigidMotion::identity();
        assert!(d
            .cast_shapes_nonlinear(&m, &p, &still(0.8, 0.1, 0.0), &bad_box, 0.0, 1.0, false)
            .is_err());
        if let Ok(r) = d.distance(&pose, &e, &Ball::new(x)) {
            assert!(r.distance.is_finite());
        }
    }
}

/// An ellipse's projection of a point 1e50 sizes away (Eberly's scaled coordinates overflowed
/// to NaN): the boundary point whose normal points at it.
#[test]
fn ellipse_projection_of_a_far_point_is_finite() {
    let e = Ellipse::new(1.4, 0.0033);
    for p in [
        Vector::new(f64::MAX, 2.6),
        Vector::new(-1e300, 1e300),
        Vector::new(1e60, -1.0),
        Vector::new(3.0, 1e200),
    ] {
        let pr = e.project_local_point(p, false);
        assert!(pr.point.is_finite() && !pr.is_inside, "{p:?}: {pr:?}");
        let n = p / p.x.abs().max(p.y.abs());
        let support = e.support_point(n.normalize());
        assert!((pr.point - support).length() <= 1e-12, "{:?} vs {support:?}", pr.point);
    }
}

/// One time-of-impact query is bounded by `ToiOptions::max_evaluations` (found by the fuzz: two
/// 1:1e25 ellipses spinning took 1.3 s and 9 million evaluations before the step cap).
#[test]
fn time_of_impact_evaluation_cap_bounds_a_query() {
    let e1 = Ellipse::new(7.841288157459043e-14, 1e12);
    let e2 = Ellipse::new(9.780583938460041e-14, 1033899656768.5364);
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(1110390238649.5881, 109792426533.83656),
        14.641318882921553,
    );
    let m2 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(-601612943757.2524, -444621230676.48834), 2.734),
        Vector::new(-289268787196.99084, -28659810273.720108),
        Vector::new(9859440092410.965, 4645061266106.172),
        -38.941440575250624,
    );
    let o = ToiOptions::default().with_stop_at_penetration(false);
    let t = Instant::now();
    let r = time_of_impact(&e1, &m1, &e2, &m2, 0.0, 0.16588369270313294, &o).unwrap();
    let dt = t.elapsed();
    println!(
        "1:1e25 ellipses: {:?} at {} after {:?} ({:?})",
        r.status, r.time, dt, r.cost
    );
    assert!(r.cost.evaluations <= o.max_evaluations + 20_000, "{:?}", r.cost);
    assert!(r.time.is_finite() && r.distance.is_finite());
}
