//! Bad input: the documented error of every query (constructors, non-finite numbers, overflowing
//! motions, empty and reversed windows).

use super::*;

#[test]
fn constructors_refuse_every_bad_number_with_a_shape_error() {
    use smooth_ccd2d::{MAX_LENGTH, MIN_LENGTH};
    let bad = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        -1.0,
        5e-324,
        1e-60,
        1e60,
        f64::MAX,
    ];
    for x in bad {
        assert!(Ellipse::try_new(x, 1.0).is_err(), "Ellipse half_x = {x}");
        assert!(Ellipse::try_new(1.0, x).is_err(), "Ellipse half_y = {x}");
        assert!(RoundedPolygon::try_regular(5, x, 0.1).is_err(), "circumradius {x}");
        for k in 0..3 {
            let mut p = [0.5, 1.0, 0.8];
            p[k] = x;
            assert!(
                CapsuleEllipse::try_new(p[0], p[1], p[2]).is_err(),
                "CapsuleEllipse {p:?}"
            );
        }
        if x != 0.0 {
            assert!(RoundedPolygon::try_regular(5, 1.0, x).is_err(), "corner radius {x}");
        }
    }
    // Which error, for a few.
    assert!(matches!(
        Ellipse::try_new(f64::NAN, 1.0),
        Err(ShapeError::NotFinite { name: "half_x", .. })
    ));
    assert!(matches!(
        Ellipse::try_new(1.0, -2.0),
        Err(ShapeError::NotPositive { name: "half_y", .. })
    ));
    assert!(matches!(
        Ellipse::try_new(1e60, 1.0),
        Err(ShapeError::OutOfRange { name: "half_x", .. })
    ));
    assert!(matches!(
        Ellipse::try_new(1.0, 1e-60),
        Err(ShapeError::OutOfRange { name: "half_y", .. })
    ));
    assert!(matches!(
        RoundedPolygon::try_regular(4, 1.0, -0.1),
        Err(ShapeError::Negative {
            name: "corner_radius",
            ..
        })
    ));
    assert!(matches!(
        RoundedPolygon::try_regular(2, 1.0, 0.1),
        Err(ShapeError::TooFewVertices { count: 2 })
    ));
    let v = |x: f64, y: f64| Vector::new(x, y);
    let square = [v(-1.0, -1.0), v(1.0, -1.0), v(1.0, 1.0), v(-1.0, 1.0)];
    assert!(RoundedPolygon::try_new(&square, 0.0).is_ok());
    let mut nan = square;
    nan[2].x = f64::NAN;
    assert!(matches!(
        RoundedPolygon::try_new(&nan, 0.0),
        Err(ShapeError::VertexNotFinite { index: 2 })
    ));
    let huge = square.map(|p| p * 1e51);
    assert!(matches!(
        RoundedPolygon::try_new(&huge, 0.0),
        Err(ShapeError::OutOfRange { name: "vertices", .. })
    ));
    let tiny = square.map(|p| p * 1e-51);
    assert!(matches!(
        RoundedPolygon::try_new(&tiny, 0.0),
        Err(ShapeError::OutOfRange { name: "vertices", .. })
    ));
    let mut cw = square;
    cw.reverse();
    assert!(matches!(
        RoundedPolygon::try_new(&cw, 0.0),
        Err(ShapeError::NotConvex { .. })
    ));
    let repeated = [square[0], square[1], square[1], square[2]];
    assert!(matches!(
        RoundedPolygon::try_new(&repeated, 0.0),
        Err(ShapeError::RepeatedVertex { .. })
    ));
    // The range's ends are accepted.
    assert!(Ellipse::try_new(MIN_LENGTH, MAX_LENGTH).is_ok());
    assert!(RoundedPolygon::try_regular(3, MAX_LENGTH, MAX_LENGTH).is_ok());
    assert!(CapsuleEllipse::try_new(MIN_LENGTH, MIN_LENGTH, MAX_LENGTH).is_ok());
    // Every error names its parameter.
    for e in [
        Ellipse::try_new(f64::NAN, 1.0).unwrap_err(),
        Ellipse::try_new(1e60, 1.0).unwrap_err(),
        CapsuleEllipse::try_new(1e-9, 1.0, 1.0).unwrap_err(),
    ] {
        let msg = e.to_string();
        assert!(msg.contains("half_x") || msg.contains("r1"), "{msg}");
    }
}

/// The capsule-ellipse's arcs of radius r1 around (0, ±r2): thinner than 1e-6·r2 the ends of the
/// arcs are lost to rounding (eq. 9 evaluates to NaN), so the constructor refuses them.
#[test]
fn capsule_ellipse_with_arcs_thinner_than_1e_minus_6_of_the_segment_is_refused() {
    assert!(CapsuleEllipse::try_new(1e-6, 1.0, 0.5).is_ok());
    assert!(matches!(
        CapsuleEllipse::try_new(0.9e-6, 1.0, 0.5),
        Err(ShapeError::Invalid(_))
    ));
    // At the limit every point, normal and support point is finite.
    let c = CapsuleEllipse::new(1e-6, 1.0, 0.5);
    for k in 0..200_000 {
        let phi = -std::f64::consts::PI + std::f64::consts::TAU * k as f64 / 200_000.0;
        assert!(c.eval(phi).is_finite(), "eval({phi})");
        let n = Vector::new(phi.cos(), phi.sin());
        assert!(c.support_point(n).is_finite());
    }
    for &b in c.breakpoints() {
        for d in [-4e-16, -2e-16, 0.0, 2e-16, 4e-16] {
            assert!(c.eval(b + d).is_finite());
        }
    }
}

/// Found by the fuzz (thin-ellipse class): a thin capsule-ellipse's arc evaluated just below its
/// rounded breakpoint gave a point behind the segment with a tilted normal, and the stationary
/// distance reported `Separated` by 5.8e-7 of the size where the shapes touch. Against the exact
/// distance from the segment (golden section on the convex distance to an ellipse, Eberly's
/// projection) it now agrees to 1e-12 of the size.
#[test]
fn thin_capsule_ellipse_distance_at_its_segment_end_is_exact() {
    let (r1, r2, r3) = (0.029299426686459993, 3975.9223765012002, 1935.2662774536552);
    let c = CapsuleEllipse::new(r1, r2, r3);
    let e = Ellipse::new(0.19253318853899007, 7198.782227083416);
    // The fuzz case's motions (seed 0x75eed, case 1349) and its time of impact.
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(-2455.694824911822, 15562.967545303543),
        37.313115843579894,
    );
    let start2 = Pose::from_parts(
        Vector::new(5757.789694814855, -4593.028361436327),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(0.8378415861972015, -0.5459134330995689),
    );
    let m2 = NonlinearRigidMotion::new(
        start2,
        Vector::new(153.76355719829766, 215.36071071033837),
        Vector::new(9079.606712042252, -2901.828223149025),
        39.70441737419846,
    );
    let t_hit = -0.6170781455997527;
    let size = r2.max(e.half_y());
    for dt in [0.0, -1e-8, -3.3e-8, -1e-7, -1e-6] {
        let t = t_hit + dt;
        let pos12 = m1.position_at_time(t).inv_mul(&m2.position_at_time(t));
        let d = stationary_distance(&c, &e, &pos12, &DistanceOptions::default()).unwrap();
        // Exact: the segment x = r1, |y| ≤ r2 against the ellipse (the distance from a line to
        // a convex set is convex along it: golden section with Eberly's projection).
        let f = |y: f64| {
            let p = pos12.inverse_transform_point(Vector::new(r1, y));
            let pr = e.project_local_point(p, false);
            let dd = (pr.point - p).length();
            if pr.is_inside {
                -dd
            } else {
                dd
            }
        };
        let (mut lo, mut hi) = (-r2, r2);
        for _ in 0..300 {
            let (a, b) = (lo + 0.382 * (hi - lo), hi - 0.382 * (hi - lo));
            if f(a) < f(b) {
                hi = b
            } else {
                lo = a
            }
        }
        let exact = f(0.5 * (lo + hi));
        assert!(
            (d.distance - exact).abs() <= 1e-12 * size,
            "t {t}: {} vs exact {exact} ({:?})",
            d.distance,
            d.status
        );
    }
}

/// The numbers that are not finite.
const NON_FINITE: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

/// The shapes, pose and options the non-finite numbers are given with: an ellipse and a disc
/// (both strictly convex), a rounded pentagon (not), a finite pose, default distance options.
struct Fixture {
    e: Ellipse,
    b: BallCurve,
    p: RoundedPolygon,
    ok_pose: Pose,
    opts: DistanceOptions,
}

impl Fixture {
    fn new() -> Self {
        Fixture {
            e: Ellipse::new(1.0, 0.4),
            b: BallCurve { radius: 0.3 },
            p: RoundedPolygon::regular(5, 0.8, 0.1),
            ok_pose: Pose::new(Vector::new(2.5, 0.2), 0.3),
            opts: DistanceOptions::default(),
        }
    }
}

#[test]
fn queries_with_non_finite_inputs_return_the_documented_errors() {
    distances_with_non_finite_inputs_return_the_documented_errors();
    times_of_impact_with_non_finite_inputs_return_the_documented_errors();
}

/// The stationary and half-space distances: a non-finite pose or option, a bad ball.
fn distances_with_non_finite_inputs_return_the_documented_errors() {
    let Fixture { e, b, p, ok_pose, opts } = Fixture::new();
    for x in NON_FINITE {
        for pose in [
            Pose::new(Vector::new(x, 0.0), 0.0),
            Pose::new(Vector::new(0.0, x), 0.0),
            Pose::new(Vector::ZERO, x),
        ] {
            assert_eq!(stationary_distance(&e, &b, &pose, &opts), Err(QueryError::NonFinite));
            assert_eq!(
                halfspace_distance(&e, &HalfSpace::new(Vector::Y), &pose, true).map(|d| d.distance),
                Err(QueryError::NonFinite)
            );
        }
        for o in [opts.with_side_tolerance(x), opts.with_distance_tolerance(x)] {
            assert_eq!(stationary_distance(&e, &b, &ok_pose, &o), Err(QueryError::NonFinite));
        }
    }
    assert_eq!(
        stationary_distance(&e, &b, &ok_pose, &opts.with_side_tolerance(-1e-10)),
        Err(QueryError::NonFinite)
    );
    assert_eq!(
        stationary_distance(&e, &p, &ok_pose, &opts),
        Err(QueryError::NotStrictlyConvex)
    );
    // NaN pose and a non-strictly-convex object2: NonFinite first.
    assert_eq!(
        stationary_distance(&e, &p, &Pose::new(Vector::new(f64::NAN, 0.0), 0.0), &opts),
        Err(QueryError::NonFinite)
    );
    // A ball built with a bad radius (a public field): Degenerate, not NaN.
    for r in [f64::NAN, f64::INFINITY, 0.0, -1.0] {
        let bad_ball = BallCurve { radius: r };
        let d = stationary_distance(&e, &bad_ball, &ok_pose, &opts);
        assert!(
            matches!(d, Err(QueryError::Degenerate)) || d.is_ok_and(|d| d.distance.is_finite()),
            "radius {r}: {d:?}"
        );
    }
}

/// The times of impact (with another shape and with a half-space): every number of the motions,
/// the window and the options.
fn times_of_impact_with_non_finite_inputs_return_the_documented_errors() {
    let Fixture { e, b, p, ok_pose, opts } = Fixture::new();
    let m1 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(-3.0, 0.1), 0.2),
        Vector::ZERO,
        Vector::X * 2.0,
        3.0,
    );
    let m2 = still(0.5, 0.0, 0.0);
    let toi = |m1: &NonlinearRigidMotion, t0: f64, t1: f64, o: &ToiOptions| time_of_impact(&e, m1, &b, &m2, t0, t1, o);
    let topts = ToiOptions::default();
    assert!(toi(&m1, 0.0, 2.0, &topts).is_ok());
    for x in NON_FINITE {
        let variants = [
            NonlinearRigidMotion {
                linvel: Vector::new(x, 0.0),
                ..m1
            },
            NonlinearRigidMotion { angvel: x, ..m1 },
            NonlinearRigidMotion {
                local_center: Vector::new(0.0, x),
                ..m1
            },
            NonlinearRigidMotion {
                start: Pose::new(Vector::new(x, 0.0), 0.0),
                ..m1
            },
            NonlinearRigidMotion {
                start: Pose::new(Vector::ZERO, x),
                ..m1
            },
        ];
        for m in &variants {
            assert_eq!(
                toi(m, 0.0, 2.0, &topts).map(|r| r.time),
                Err(QueryError::NonFinite),
                "{m:?}"
            );
            let hs = time_of_impact_halfspace(&e, m, &HalfSpace::new(Vector::Y), &m2, 0.0, 2.0, &topts);
            assert_eq!(hs.map(|r| r.time), Err(QueryError::NonFinite));
        }
        assert_eq!(toi(&m1, x, 2.0, &topts).map(|r| r.time), Err(QueryError::NonFinite));
        assert_eq!(toi(&m1, 0.0, x, &topts).map(|r| r.time), Err(QueryError::NonFinite));
        for o in [
            topts.with_target_distance(x),
            topts.with_distance_tolerance(x),
            topts.with_side_tolerance(x),
            topts.with_distance_options(opts.with_side_tolerance(x)),
        ] {
            assert_eq!(toi(&m1, 0.0, 2.0, &o).map(|r| r.time), Err(QueryError::NonFinite));
            let hs = time_of_impact_halfspace(&e, &m1, &HalfSpace::new(Vector::Y), &m2, 0.0, 2.0, &o);
            assert_eq!(hs.map(|r| r.time), Err(QueryError::NonFinite));
        }
        // A half-space whose normal is not finite.
        let hs = HalfSpace::new(Vector::new(x, 1.0));
        assert_eq!(
            time_of_impact_halfspace(&e, &m1, &hs, &m2, 0.0, 2.0, &topts).map(|r| r.time),
            Err(QueryError::NonFinite)
        );
        assert_eq!(
            halfspace_distance(&e, &hs, &ok_pose, true).map(|d| d.distance),
            Err(QueryError::NonFinite)
        );
    }
    assert_eq!(
        toi(&m1, 0.0, 2.0, &topts.with_target_distance(-0.1)).map(|r| r.time),
        Err(QueryError::NonFinite)
    );
    // Neither shape strictly convex: NotStrictlyConvex, even before NonFinite.
    let nan_m = NonlinearRigidMotion { angvel: f64::NAN, ..m1 };
    assert_eq!(
        time_of_impact(&p, &nan_m, &p, &m2, 0.0, 1.0, &topts).map(|r| r.time),
        Err(QueryError::NotStrictlyConvex)
    );
    // Reversed window.
    assert_eq!(toi(&m1, 2.0, 1.0, &topts).map(|r| r.time), Err(QueryError::EmptyWindow));
}

/// A motion that overflows: finite numbers whose positions or velocities are not.
#[test]
fn overflowing_motions_give_degenerate_not_nan() {
    let e = Ellipse::new(1.0, 0.4);
    let b = BallCurve { radius: 0.3 };
    let hs = HalfSpace::new(Vector::Y);
    let topts = ToiOptions::default();
    for m in [
        NonlinearRigidMotion::new(
            Pose::new(Vector::new(0.0, 3.0), 0.0),
            Vector::new(0.0, f64::MAX),
            Vector::ZERO,
            3.0,
        ),
        NonlinearRigidMotion::new(
            Pose::new(Vector::new(f64::MAX, 3.0), 0.0),
            Vector::ZERO,
            Vector::new(f64::MAX, 0.0),
            0.0,
        ),
        NonlinearRigidMotion::new(
            Pose::new(Vector::new(0.0, 3.0), 0.0),
            Vector::ZERO,
            Vector::ZERO,
            f64::MAX,
        ),
    ] {
        for r in [
            time_of_impact(&e, &m, &b, &still(0.0, 0.0, 0.0), 0.0, 1.0, &topts),
            time_of_impact_halfspace(&e, &m, &hs, &NonlinearRigidMotion::identity(), 0.0, 1.0, &topts),
            time_of_impact_halfspace(&e, &still(0.0, 3.0, 0.0), &hs, &m, 0.0, 1.0, &topts),
        ] {
            match r {
                Err(QueryError::Degenerate) => {}
                Ok(r) => assert!(
                    r.time.is_finite()
                        && r.distance.is_finite()
                        && r.distance_rate.is_finite()
                        && r.point1.is_finite()
                        && r.point2.is_finite(),
                    "{m:?}: {r:?}"
                ),
                Err(e) => panic!("{m:?}: {e:?}"),
            }
        }
    }
}

#[test]
fn empty_and_reversed_windows_have_documented_answers() {
    let e = Ellipse::new(1.0, 0.4);
    let b = BallCurve { radius: 0.3 };
    let d = SmoothDispatcher::default();
    let m1 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(-3.0, 0.1), 0.2),
        Vector::ZERO,
        Vector::X * 2.0,
        3.0,
    );
    let touching = NonlinearRigidMotion::new(Pose::new(Vector::new(-1.3, 0.0), 0.0), Vector::ZERO, Vector::X, 0.0);
    let m2 = still(0.0, 0.0, 0.0);
    for t in [-5.0, 0.0, 0.7, 1e6] {
        for stop in [true, false] {
            let o = ToiOptions::default().with_stop_at_penetration(stop);
            // Apart: NoHit at t0.
            let r = time_of_impact(&b, &m1, &e, &m2, t, t, &o).unwrap();
            assert_eq!(r.status, ToiStatus::NoHit, "t = {t}");
            assert_eq!(r.time, t);
            // Reversed: EmptyWindow.
            assert_eq!(
                time_of_impact(&b, &m1, &e, &m2, t, t - 1.0, &o),
                Err(QueryError::EmptyWindow)
            );
            // In contact at t0 (moving the ball to touch the ellipse at t).
            let m = NonlinearRigidMotion {
                start: Pose::new(Vector::new(-1.3 - t, 0.0), 0.0),
                ..touching
            };
            let r = time_of_impact(&b, &m, &e, &m2, t, t, &o).unwrap();
            assert_eq!(r.status, ToiStatus::PenetratingAtStart, "t = {t}, stop {stop}");
            assert_eq!(r.time, t);
            // The dispatcher: no hit for a reversed window, the start for an empty one in contact.
            let ball = Ball::new(0.3);
            assert!(d
                .cast_shapes_nonlinear(&m1, &ball, &m2, &e, t, t - 1.0, stop)
                .unwrap()
                .is_none());
            assert!(d
                .cast_shapes_nonlinear(&m1, &ball, &m2, &e, t, t, stop)
                .unwrap()
                .is_none());
            // Two rounded polygons (answered by parry): no hit for a reversed window either.
            let p = RoundedPolygon::regular(5, 0.8, 0.1);
            let q = RoundedPolygon::regular(4, 0.5, 0.0);
            let mp = NonlinearRigidMotion::new(Pose::new(Vector::new(-0.5, 0.0), 0.0), Vector::ZERO, Vector::X, 2.0);
            assert!(d
                .cast_shapes_nonlinear(&mp, &p, &m2, &q, t, t - 1.0, stop)
                .unwrap()
                .is_none());
        }
    }
}
