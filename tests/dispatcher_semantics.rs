//! SmoothDispatcher keeps parry's semantics: pos12, casts, `stop_at_penetration`, composite
//! shapes, half-spaces, and bad input.

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastStatus};
use parry2d_f64::shape::{Ball, Compound, HalfSpace, SharedShape};
use smooth_ccd2d::{Ellipse, RoundedPolygon, SmoothDispatcher};

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
}

#[test]
fn stop_at_penetration_semantics_follow_the_design() {
    let d = SmoothDispatcher::default();
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
    // Approaching while overlapping: the start time when stopping at penetration.
    let coming = NonlinearRigidMotion::new(
        Pose::new(Vector::new(0.7, 0.0), 0.0),
        Vector::ZERO,
        Vector::new(-1.0, 0.0),
        0.0,
    );
    let hit = d
        .cast_shapes_nonlinear(&still, &e, &coming, &b, 0.0, 1.0, true)
        .unwrap()
        .unwrap();
    assert_eq!(hit.time_of_impact, 0.0);
    // For rapier (false): a fast approach is reported just after the start (rapier drops hits
    // at exactly the start); a slow one (resting, sliding) is left to the contact solver.
    let hit = d
        .cast_shapes_nonlinear(&still, &e, &coming, &b, 0.0, 1.0, false)
        .unwrap()
        .unwrap();
    assert_eq!(hit.time_of_impact, smooth_ccd2d::dispatcher::START_NUDGE);
    let creeping = NonlinearRigidMotion::new(
        Pose::new(Vector::new(0.7, 0.0), 0.0),
        Vector::ZERO,
        Vector::new(-1e-3, 0.0),
        0.0,
    );
    assert!(d
        .cast_shapes_nonlinear(&still, &e, &creeping, &b, 0.0, 1.0, false)
        .unwrap()
        .is_none());
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
