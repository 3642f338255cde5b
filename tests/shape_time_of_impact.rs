//! `shape_time_of_impact`, the time of impact of any two convex parry shapes, on bad input: the
//! documented errors for every non-finite number, a reversed window, bad options and shapes it
//! cannot take, and finite answers (or `Degenerate`) for finite but absurd motions, for the
//! three routes (a strictly convex side, none, a half-space).

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use parry2d_f64::shape::{Ball, Compound, ConvexPolygon, Cuboid, HalfSpace, Shape, SharedShape};
use smooth_ccd2d::{
    shape_time_of_impact, CapsuleEllipse, Ellipse, QueryError, RoundedPolygon, TimeOfImpact, ToiOptions, ToiStatus,
};

const NON_FINITE: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

/// Every number of the answer is finite.
fn finite(r: &TimeOfImpact) -> bool {
    [r.time, r.distance, r.distance_rate].iter().all(|x| x.is_finite())
        && [r.point1, r.point2, r.normal1, r.normal2].iter().all(|v| v.is_finite())
}

/// A named pair of shapes.
type Pair = (&'static str, Box<dyn Shape>, Box<dyn Shape>);

/// Pairs over the three routes, shape 1 flying at shape 2 (both spinning, a hit in [0, 1]).
fn pairs() -> Vec<Pair> {
    vec![
        (
            "rounded polygon – ellipse",
            Box::new(RoundedPolygon::regular(5, 0.5, 0.1)),
            Box::new(Ellipse::new(0.6, 0.3)),
        ),
        (
            "rounded polygon – cuboid",
            Box::new(RoundedPolygon::regular(7, 0.5, 0.05)),
            Box::new(Cuboid::new(Vector::new(0.3, 0.8))),
        ),
        (
            "capsule-ellipse – polygon",
            Box::new(CapsuleEllipse::new(0.2, 0.3, 0.4)),
            Box::new(RoundedPolygon::regular(4, 0.5, 0.0)),
        ),
        (
            "cuboid – cuboid",
            Box::new(Cuboid::new(Vector::new(0.4, 0.2))),
            Box::new(Cuboid::new(Vector::new(0.3, 0.6))),
        ),
        (
            "rounded polygon – half-space",
            Box::new(RoundedPolygon::regular(6, 0.5, 0.1)),
            Box::new(HalfSpace::new(-Vector::X)),
        ),
    ]
}

fn motions() -> (NonlinearRigidMotion, NonlinearRigidMotion) {
    (
        NonlinearRigidMotion::new(
            Pose::new(Vector::new(-3.0, 0.1), 0.3),
            Vector::ZERO,
            Vector::new(6.0, 0.0),
            7.0,
        ),
        NonlinearRigidMotion::new(Pose::new(Vector::new(1.0, 0.0), 0.0), Vector::ZERO, Vector::ZERO, -4.0),
    )
}

#[test]
fn valid_pairs_of_every_route_hit() {
    let (m1, m2) = motions();
    for (name, g1, g2) in pairs() {
        let r = shape_time_of_impact(&*g1, &m1, &*g2, &m2, 0.0, 1.0, &ToiOptions::default()).expect(name);
        assert_eq!(r.status, ToiStatus::Hit, "{name}");
        assert!(finite(&r), "{name}: {r:?}");
    }
}

#[test]
fn non_finite_motions_times_and_options_are_non_finite_errors() {
    let (m1, m2) = motions();
    let opts = ToiOptions::default();
    for (name, g1, g2) in pairs() {
        let toi = |a: &NonlinearRigidMotion, b: &NonlinearRigidMotion, t0: f64, t1: f64, o: &ToiOptions| {
            shape_time_of_impact(&*g1, a, &*g2, b, t0, t1, o)
        };
        for x in NON_FINITE {
            let bad_motions = [
                NonlinearRigidMotion {
                    linvel: Vector::new(x, 0.0),
                    ..m1
                },
                NonlinearRigidMotion { angvel: x, ..m1 },
                NonlinearRigidMotion {
                    start: Pose::new(Vector::new(x, 0.0), 0.3),
                    ..m1
                },
                NonlinearRigidMotion {
                    local_center: Vector::new(0.0, x),
                    ..m1
                },
            ];
            for m in &bad_motions {
                assert_eq!(
                    toi(m, &m2, 0.0, 1.0, &opts),
                    Err(QueryError::NonFinite),
                    "{name}: motion 1 {m:?}"
                );
                assert_eq!(
                    toi(&m2, m, 0.0, 1.0, &opts),
                    Err(QueryError::NonFinite),
                    "{name}: motion 2 {m:?}"
                );
            }
            assert_eq!(
                toi(&m1, &m2, x, 1.0, &opts),
                Err(QueryError::NonFinite),
                "{name}: start {x}"
            );
            assert_eq!(
                toi(&m1, &m2, 0.0, x, &opts),
                Err(QueryError::NonFinite),
                "{name}: end {x}"
            );
            for o in [
                opts.with_target_distance(x),
                opts.with_distance_tolerance(x),
                opts.with_side_tolerance(x),
            ] {
                assert_eq!(
                    toi(&m1, &m2, 0.0, 1.0, &o),
                    Err(QueryError::NonFinite),
                    "{name}: options {x}"
                );
            }
        }
        assert_eq!(
            toi(&m1, &m2, 0.0, 1.0, &opts.with_target_distance(-1e-3)),
            Err(QueryError::NonFinite),
            "{name}: negative target"
        );
        assert_eq!(
            toi(&m1, &m2, 1.0, 0.0, &opts),
            Err(QueryError::EmptyWindow),
            "{name}: reversed window"
        );
        let empty = toi(&m1, &m2, 0.5, 0.5, &opts).expect(name);
        assert!(finite(&empty) && empty.time == 0.5, "{name}: empty window {empty:?}");
    }
}

#[test]
fn shapes_it_cannot_take_are_unsupported_shape_errors() {
    let (m1, m2) = motions();
    let opts = ToiOptions::default();
    let polygon = RoundedPolygon::regular(5, 0.5, 0.1);
    let compound = Compound::new(vec![(Pose::identity(), SharedShape::ball(0.3))]);
    let flat_box = Cuboid::new(Vector::new(0.0, 0.5));
    let nan_box = Cuboid::new(Vector::new(f64::NAN, 0.5));
    let refused: [(&str, &dyn Shape); 3] = [("compound", &compound), ("flat box", &flat_box), ("NaN box", &nan_box)];
    for (name, g) in refused {
        for (a, b) in [(g, &polygon as &dyn Shape), (&polygon as &dyn Shape, g)] {
            assert_eq!(
                shape_time_of_impact(a, &m1, b, &m2, 0.0, 1.0, &opts),
                Err(QueryError::UnsupportedShape),
                "{name}"
            );
        }
    }
    // Two half-spaces have no convex side to track.
    let hs = HalfSpace::new(Vector::X);
    assert_eq!(
        shape_time_of_impact(&hs, &m1, &hs, &m2, 0.0, 1.0, &opts),
        Err(QueryError::UnsupportedShape)
    );
    // A ball is fine on either side.
    let ball = Ball::new(0.4);
    assert!(shape_time_of_impact(&ball, &m1, &polygon, &m2, 0.0, 1.0, &opts).is_ok());
}

#[test]
fn absurd_finite_motions_give_finite_answers_or_degenerate() {
    let opts = ToiOptions::default();
    let polygon = ConvexPolygon::from_convex_polyline(vec![
        Vector::new(-0.5, -0.5),
        Vector::new(0.5, -0.5),
        Vector::new(0.5, 0.5),
        Vector::new(-0.5, 0.5),
    ])
    .expect("a square");
    let mut checked = 0;
    for (name, g1, _) in pairs() {
        for big in [1e150, 1e300, f64::MAX] {
            let motions = [
                NonlinearRigidMotion::new(
                    Pose::new(Vector::new(-3.0, 0.0), 0.0),
                    Vector::ZERO,
                    Vector::new(big, 0.0),
                    1.0,
                ),
                NonlinearRigidMotion::new(Pose::new(Vector::new(-3.0, 0.0), 0.0), Vector::ZERO, Vector::ZERO, big),
                NonlinearRigidMotion::new(Pose::new(Vector::new(big, 0.0), big), Vector::ZERO, Vector::X, 1.0),
            ];
            for m in &motions {
                let r = shape_time_of_impact(&*g1, m, &polygon, &NonlinearRigidMotion::identity(), 0.0, 1.0, &opts);
                match r {
                    Ok(r) => assert!(finite(&r), "{name}, {big}: {r:?}"),
                    Err(e) => assert!(
                        matches!(e, QueryError::Degenerate | QueryError::NonFinite),
                        "{name}, {big}: {e:?}"
                    ),
                }
                checked += 1;
            }
        }
    }
    println!("absurd motions: {checked} cases, none NaN, none panicked");
}
