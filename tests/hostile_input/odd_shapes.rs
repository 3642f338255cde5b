//! Shapes at the edges of what the crate takes: polygons of 10⁵ vertices, balls of no size,
//! needle arcs, flat triangles, non-finite poses.

use super::*;

/// Item 3: the exact distance of a penetrating pair with no strictly convex side scanned the
/// other polygon once per face: 229 ms at 30,000 vertices, 2.5 s at 100,000, 245 s at 10⁶. The
/// faces and vertex pairs are now swept once (O(n + m)): every query of the pair at
/// 100,000 vertices, and of two such polygons overlapping, in well under a second each.
#[test]
fn queries_on_a_polygon_of_a_hundred_thousand_vertices_take_under_a_second() {
    let n = 100_000;
    let p = RoundedPolygon::regular(n, 1.0, 0.01);
    let q = RoundedPolygon::regular(n, 0.8, 0.0);
    let pose = Pose::new(Vector::new(1.3, 0.2), 0.3);
    let deep = Pose::new(Vector::new(0.3, 0.2), 0.3);
    let others: Vec<(&str, SharedShape, Pose)> = vec![
        ("box", SharedShape::new(Cuboid::new(Vector::new(0.5, 0.2))), pose),
        ("polygon", SharedShape::new(q), deep),
        ("ellipse", SharedShape::new(Ellipse::new(0.5, 0.2)), deep),
    ];
    let p = SharedShape::new(p);
    for (name, other, pose) in others {
        let (p, other) = (p.clone(), other.clone());
        let t = Instant::now();
        let (inter, dist, contact, closest, manifold) = within(name, move || {
            let d = SmoothDispatcher::default();
            let mut m: Vec<ContactManifold<(), ()>> = Vec::new();
            (
                d.intersection_test(&pose, &*p, &*other).expect("answered").intersecting,
                d.distance(&pose, &*p, &*other).expect("answered").distance,
                d.contact(&pose, &*p, &*other, 0.1).expect("answered"),
                d.closest_points(&pose, &*p, &*other, 0.1).expect("answered"),
                d.contact_manifolds(&pose, &*p, &*other, 0.1, &mut m, &mut None)
                    .map(|_| m),
            )
        });
        println!("{name}: five queries on 100,000 vertices in {:?}", t.elapsed());
        // The pairs overlap: the exact answers say so.
        assert!(inter && dist == 0.0, "{name}");
        assert!(contact.is_some_and(|c| c.dist < 0.0), "{name}");
        assert_eq!(closest, ClosestPoints::Intersecting, "{name}");
        assert!(manifold.is_ok(), "{name}");
    }
    // A time of impact: a spinning 100,000-gon against the box.
    let m1 = NonlinearRigidMotion::new(Pose::translation(-3.0, 0.0), Vector::ZERO, Vector::new(1.2, 0.0), 20.0);
    let m2 = NonlinearRigidMotion::identity();
    let r = within("time of impact", move || {
        let p = RoundedPolygon::regular(n, 1.0, 0.01);
        shape_time_of_impact(
            &p,
            &m1,
            &Cuboid::new(Vector::new(0.5, 0.2)),
            &m2,
            0.0,
            2.0,
            &ToiOptions::default(),
        )
    });
    assert_eq!(r.map(|r| r.status), Ok(ToiStatus::Hit));
}

/// Found by the fuzz with another seed (`FUZZ_SEED=3004`, case 157457): two parry balls of
/// radius −0 and 1e-300 (points) passing each other at about 100 m/s. The pair's rates, 1e302
/// sizes a second, sent rapier's policy to a time scale where they are about 1 — and parry's own
/// cast, which answers the pair, to a window of 1e302 s, where its conservative advancement
/// with absolute time tolerances never ended. parry's own pairs now keep the caller's time
/// scale: the call answers at once (parry itself, on the same input, answers no hit in 10 µs).
#[test]
fn parry_balls_of_no_size_passing_each_other_are_answered_at_once() {
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(38.78496442129538, 101.40148917307064),
        -6.083702193247845,
    );
    let start2 = Pose::from_parts(
        Vector::new(0.0, 47.28740043084232),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.8807951589750529, 0.4734975057232205),
    );
    let m2 = NonlinearRigidMotion::new(
        start2,
        Vector::ZERO,
        Vector::new(-11.563600781145531, -78.24517107232525),
        0.0,
    );
    for (r1, r2) in [(-0.0, 1e-300), (1e-300, -0.0)] {
        let r = within("cast_shapes_nonlinear", move || {
            SmoothDispatcher::default().cast_shapes_nonlinear(
                &m1,
                &Ball::new(r1),
                &m2,
                &Ball::new(r2),
                0.0,
                1.1502567991219912,
                false,
            )
        });
        if let Ok(Some(h)) = r {
            assert!(h.time_of_impact.is_finite() && (0.0..=1.1502567991219912).contains(&h.time_of_impact));
        }
    }
}

/// Item 7: `RoundedPolygon::try_regular(usize::MAX, …)` panicked (capacity overflow) and
/// `try_regular(1 << 40, …)` aborted the process (17 TB): documented to return `ShapeError`.
/// The count is checked against `MAX_VERTICES` before anything is allocated.
#[test]
fn regular_polygon_of_too_many_sides_is_refused_before_it_allocates() {
    for sides in [usize::MAX, 1 << 40, MAX_VERTICES + 1] {
        let r = within("try_regular", move || {
            RoundedPolygon::try_regular(sides, 1.0, 0.1).map(|_| ())
        });
        assert_eq!(r, Err(ShapeError::TooManyVertices { count: sides }));
        assert!(r.unwrap_err().to_string().contains("vertices"));
    }
    // The limit itself is accepted.
    let big = within("try_regular at the limit", || {
        RoundedPolygon::try_regular(MAX_VERTICES, 1.0, 0.0).map(|p| p.vertices().len())
    });
    assert_eq!(big, Ok(MAX_VERTICES));
    let too_many = vec![Vector::ZERO; MAX_VERTICES + 1];
    assert_eq!(
        RoundedPolygon::try_new(&too_many, 0.0),
        Err(ShapeError::TooManyVertices {
            count: MAX_VERTICES + 1
        })
    );
}

/// Item 9: an infinite pose made intersection, contact, closest points and manifolds answer
/// `Ok(false / None / Disjoint / empty)` (the bounding-circle rejection took the infinite
/// distance as apart); the documented answer, given for NaN, is `Err(Unsupported)`. Every pair
/// kind, every query, every non-finite number in the translation or the rotation.
#[test]
fn non_finite_pose_is_unsupported_in_every_dispatcher_query() {
    let shapes: Vec<SharedShape> = vec![
        SharedShape::new(Ellipse::new(0.5, 0.2)),
        SharedShape::new(RoundedPolygon::regular(5, 0.5, 0.1)),
        SharedShape::new(CapsuleEllipse::new(0.3, 0.5, 0.4)),
        SharedShape::new(CustomCurve::new(Ellipse::new(0.3, 0.6))),
        SharedShape::new(Cuboid::new(Vector::new(0.5, 0.2))),
        SharedShape::new(Ball::new(0.3)),
        SharedShape::new(HalfSpace::new(Vector::Y)),
        SharedShape::new(Compound::new(vec![(
            Pose::IDENTITY,
            SharedShape::new(Ellipse::new(0.2, 0.1)),
        )])),
    ];
    let d = SmoothDispatcher::default();
    let mut checked = 0;
    for x in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
        let poses = [
            Pose::new(Vector::new(x, 0.0), 0.0),
            Pose::new(Vector::new(0.0, x), 0.0),
            Pose::from_parts(
                Vector::new(1.0, 0.0),
                parry2d_f64::math::Rotation::from_cos_sin_unchecked(x, 0.0),
            ),
        ];
        for pose in poses {
            for (i, g1) in shapes.iter().enumerate() {
                for (j, g2) in shapes.iter().enumerate() {
                    if i >= 6 && j >= 6 {
                        continue; // two half-spaces or compounds without a shape of ours
                    }
                    let what = format!("shapes {i}, {j}, pose {pose:?}");
                    assert!(d.intersection_test(&pose, &**g1, &**g2).is_err(), "intersection {what}");
                    assert!(d.distance(&pose, &**g1, &**g2).is_err(), "distance {what}");
                    assert!(d.contact(&pose, &**g1, &**g2, 0.1).is_err(), "contact {what}");
                    assert!(d.closest_points(&pose, &**g1, &**g2, 0.1).is_err(), "closest {what}");
                    let mut m: Vec<ContactManifold<(), ()>> = Vec::new();
                    let r = d.contact_manifolds(&pose, &**g1, &**g2, 0.1, &mut m, &mut None);
                    assert!(r.is_err(), "manifolds {what}");
                    checked += 5;
                }
            }
        }
    }
    println!("non-finite poses: {checked} queries, each Err(Unsupported)");
}

/// Hostile seed 5105, case 1153: a rounded 100,000-gon (radius 169, corners 29) turning at
/// −52 rad/s against a `CapsuleEllipse` turning at 38 rad/s over a window of 9.3 s, 140 turns
/// of one relative to the other. Each exact distance of the gap tracker walked from the last
/// axis across the polygon's tiny normal cones one at a time, about 19,000 of them a call: 3.8 s
/// for a time of impact, past the fuzz's 2 s limit. The walk now jumps ahead where it is long
/// (O(log n) support searches): every query of the case well within the limit, its promises
/// kept.
#[test]
fn a_cast_of_a_many_sided_polygon_turning_many_times_answers_well_within_the_call_limit() {
    use reliability::hostile::{compare, hostile};
    let (case, expect) = hostile(5105, 1153);
    assert_eq!(case.class, "huge-polygon");
    let mut out = reliability::run_case(&case);
    out.violations.extend(compare(&case, &expect));
    assert!(out.violations.is_empty(), "{:?}", out.violations);
    println!(
        "hostile 5105/1153: slowest call {:?} ({})",
        out.slowest.0, out.slowest.1
    );
    assert!(
        out.slowest.0 < reliability::CALL_LIMIT / 4,
        "slowest call {:?} ({})",
        out.slowest.0,
        out.slowest.1
    );
}

/// Hostile seed 5106, case 1659: a capsule-ellipse (1153, 248, 1626) turning at −1.8e302 rad/s
/// and moving at 8.3e306 m/s against a half-space turning at −6.0e302 rad/s and moving at
/// 5.3e306 m/s, over a window of 8.3e-304 s (3.4e-301 s after 0): the steps' bounds overflowed
/// and the cast answered `Degenerate`, where the same motion on a time scale 2^−1000 slower
/// answers `NoHit`. The half-space cast now asks such rates on a rescaled time, as
/// `time_of_impact` does: the same answer on both scales.
/// Adversarial fuzz seed 5014, case 44828: a `CapsuleEllipse` of r1 : r2 = 1 : 9.3e5 (the edge
/// of the supported axis ratios) touching a 1 : 7,900 ellipse's flank with the end of its arc
/// beside the segment, where its normal turns by about 1e-5 rad per unit in the last place of φ.
/// The stationary distance ended there on two adjacent floats of φ with distanceSide at 5e-8
/// and jittered between −3.4e-13 and +2.5e-16 over picoseconds of the motion (2e-8 of the size,
/// 1e-12 promised); Newton's steps over the normal angle (`query::polish`) now give the exact
/// contact query's distance and witnesses (an independent method: the minimum of the support
/// functions over the normal angle) at every time, and the status of its sign.
#[test]
fn a_needle_arc_that_phi_cannot_resolve_gets_the_exact_stationary_distance() {
    let a = CapsuleEllipse::new(1.1756974580030133e-11, 1.0970018038101628e-5, 8.246317336479094e-6);
    let b = Ellipse::new(2.197602988639123e-9, 1.733767065333242e-5);
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(-4.8034450365496056e-8, 7.722378964231305e-6),
        -53.2243525344351,
    );
    let m2 = NonlinearRigidMotion::new(
        Pose::from_parts(
            Vector::new(6.4870460886455655e-6, 3.7645466842405977e-5),
            parry2d_f64::math::Rotation::from_cos_sin_unchecked(0.8219896066645191, -0.5695024903681363),
        ),
        Vector::ZERO,
        Vector::new(4.964741239889841e-6, -5.7094652291015695e-6),
        -32.796748176138856,
    );
    let size = a.bounding_radius().max(b.bounding_radius());
    let d = SmoothDispatcher::default();
    // The fuzz's hit time, and picoseconds around it: the pair moves by 1e-15 m a picosecond.
    let hit = 0.9523974931482061;
    let mut worst: f64 = 0.0;
    for k in -10..=10 {
        let t = hit + k as f64 * 1e-12;
        let pos12 = m1.position_at_time(t).inv_mul(&m2.position_at_time(t));
        let s = stationary_distance(&a, &b, &pos12, &DistanceOptions::default()).unwrap();
        let c = d.contact(&pos12, &a, &b, 1.0).unwrap().unwrap();
        let err = (s.distance - c.dist).abs();
        worst = worst.max(err / size);
        assert!(err <= 1e-12 * size, "t = {t}: {} against {}", s.distance, c.dist);
        assert!((s.point1 - c.point1).length() <= 1e-12 * size, "t = {t}: point1");
        assert!((s.point2 - c.point2).length() <= 1e-12 * size, "t = {t}: point2");
        let apart = smooth_ccd2d::DistanceStatus::Separated;
        assert_eq!(
            s.status == apart,
            s.distance > 0.0,
            "t = {t}: {:?} at {}",
            s.status,
            s.distance
        );
    }
    println!("needle arc: worst |stationary − exact contact| {worst:.1e} of the size over 21 times");
}

/// Found by the hunt through composite casts (a mesh with a degenerate triangle): a flat
/// triangle — two vertices equal, or all three on a line — had no curve, so its casts went to
/// parry's conservative advancement; against a turning user curve (`EccentricEllipse` 0.114 ×
/// 0.046) over a window of 384 s one cast ran for more than 15 s. A flat triangle is now its hull,
/// the segment between its two farthest vertices: every query answers as for that `Segment`, to
/// the bit, each within the time limit (random flat triangles, both kinds, against the user
/// curve turning at up to 5 rad/s over windows of up to 400 s, and against the crate's ellipse).
#[test]
fn a_flat_triangle_answers_as_the_segment_it_is() {
    let mut rng = common::rng::Rng::new(0xF1A7);
    let d = SmoothDispatcher::default();
    let (mut casts, mut hits) = (0, 0);
    for case in 0..120 {
        let (p, q) = (
            Vector::new(rng.uniform(-3.0, 3.0), rng.uniform(-1.0, 1.0)),
            Vector::new(rng.uniform(-3.0, 3.0), rng.uniform(-1.0, 1.0)),
        );
        // Two vertices equal, or the third between the other two.
        let triangle = if case % 2 == 0 {
            Triangle::new(p, q, q)
        } else {
            Triangle::new(p, q, p + (q - p) * rng.uniform(0.1, 0.9))
        };
        let segment = parry2d_f64::shape::Segment::new(p, q);
        let s = rng.log_uniform(0.1, 1.0);
        let body: Box<dyn Shape> = if case % 3 == 0 {
            Box::new(Ellipse::new(0.5 * s, 0.2 * s))
        } else {
            Box::new(CustomCurve::new(common::curves::EccentricEllipse {
                a: 0.5 * s,
                b: 0.2 * s,
                center: Vector::new(0.05 * s, 0.0),
            }))
        };
        let start = Pose::new(Vector::new(rng.uniform(-4.0, 4.0), rng.uniform(1.5, 3.0)), rng.angle());
        let aim = Vector::new(rng.uniform(-3.0, 3.0), rng.uniform(-1.0, 1.0)) - start.translation;
        let window = rng.log_uniform(0.5, 400.0);
        let m1 = NonlinearRigidMotion::new(start, Vector::new(0.01, 0.0), aim / window, rng.uniform(-5.0, 5.0));
        let m2 = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
        let body: std::sync::Arc<dyn Shape> = body.into();
        for stop in [false, true] {
            let (b, t) = (body.clone(), triangle);
            let on_triangle = within("cast against a flat triangle", move || {
                SmoothDispatcher::default().cast_shapes_nonlinear(&m1, &*b, &m2, &t, 0.0, window, stop)
            });
            let on_segment = d.cast_shapes_nonlinear(&m1, &*body, &m2, &segment, 0.0, window, stop);
            assert_eq!(
                format!("{on_triangle:?}"),
                format!("{on_segment:?}"),
                "case {case}, stop {stop}"
            );
            casts += 1;
            hits += usize::from(matches!(on_triangle, Ok(Some(_))));
        }
        let pos12 = start.inv_mul(&Pose::IDENTITY);
        assert_eq!(
            format!("{:?}", d.distance(&pos12, &*body, &triangle)),
            format!("{:?}", d.distance(&pos12, &*body, &segment)),
            "case {case}"
        );
    }
    println!("{casts} casts against flat triangles, {hits} hits, each equal to the segment's");
    assert!(hits > 20, "{hits}");
}

/// Found by a first-hour read of the docs (2026-11-29): `BallCurve`'s radius is a public field,
/// and a radius of −1 gave `stationary_distance` 3.5 and `time_of_impact` `NoHit`, a radius of 0
/// a `Hit`, where `QueryError::Degenerate` is documented. Every free query now refuses a curve
/// whose bounding radius is not finite and positive; the constructors refuse such a radius.
#[test]
fn a_ball_curve_of_no_or_negative_radius_is_degenerate_in_every_free_query() {
    use smooth_ccd2d::{bounding_circles_part, halfspace_distance, BallCurve};
    let e = Ellipse::new(0.5, 0.2);
    let pos12 = Pose::translation(4.0, 0.0);
    let m1 = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::new(10.0, 0.0), 0.0);
    let m2 = NonlinearRigidMotion::new(pos12, Vector::ZERO, Vector::ZERO, 0.0);
    let hs = HalfSpace::new(Vector::Y);
    // Moving away: the circles of any positive radii stay apart (the test would answer true).
    let away = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::new(-10.0, 0.0), 0.0);
    assert!(bounding_circles_part(
        &e,
        &away,
        &BallCurve::new(0.5),
        &m2,
        0.0,
        1.0,
        0.0
    ));
    for radius in [-1.0, 0.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let b = BallCurve { radius };
        let d = stationary_distance(&e, &b, &pos12, &DistanceOptions::default());
        assert_eq!(
            d.err(),
            Some(smooth_ccd2d::QueryError::Degenerate),
            "stationary_distance, radius {radius}"
        );
        let d = stationary_distance(&b, &e, &pos12, &DistanceOptions::default());
        assert_eq!(
            d.err(),
            Some(smooth_ccd2d::QueryError::Degenerate),
            "stationary_distance swapped, radius {radius}"
        );
        let t = time_of_impact(&e, &m1, &b, &m2, 0.0, 1.0, &ToiOptions::default());
        assert_eq!(
            t.err(),
            Some(smooth_ccd2d::QueryError::Degenerate),
            "time_of_impact, radius {radius}"
        );
        let t = time_of_impact(&b, &m2, &e, &m1, 0.0, 1.0, &ToiOptions::default());
        assert_eq!(
            t.err(),
            Some(smooth_ccd2d::QueryError::Degenerate),
            "time_of_impact swapped, radius {radius}"
        );
        let h = halfspace_distance(&b, &hs, &pos12, true);
        assert_eq!(
            h.err(),
            Some(smooth_ccd2d::QueryError::Degenerate),
            "halfspace_distance, radius {radius}"
        );
        let h = time_of_impact_halfspace(&b, &m1, &hs, &m2, 0.0, 1.0, &ToiOptions::default());
        assert_eq!(
            h.err(),
            Some(smooth_ccd2d::QueryError::Degenerate),
            "time_of_impact_halfspace, radius {radius}"
        );
        assert!(
            !bounding_circles_part(&e, &away, &b, &m2, 0.0, 1.0, 0.0),
            "bounding_circles_part, radius {radius}"
        );
        assert!(BallCurve::try_new(radius).is_err(), "try_new, radius {radius}");
    }
    // A valid radius answers as before.
    let b = BallCurve::new(0.5);
    let d = stationary_distance(&e, &b, &pos12, &DistanceOptions::default()).unwrap();
    assert!((d.distance - 3.0).abs() < 1e-12);
}
