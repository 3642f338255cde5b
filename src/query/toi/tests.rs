//! Unit tests of the time of impact: the guard's parabola, closed forms, dense sampling.

use super::*;
use crate::numerics::math::{Pose, Vector};
use crate::query::pair::eval_pair;
use crate::{BallCurve, Ellipse, RoundedPolygon};

use crate::numerics::test_rng::Lcg;

/// A random motion: start within `reach` of the origin at any angle, rotation centre within
/// 0.2 of the local origin, speed up to 4·√2, spin up to `spin` rad/s.
fn random_motion(rng: &mut Lcg, reach: f64, spin: f64) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(
        Pose::new(
            Vector::new(rng.range(-reach, reach), rng.range(-reach, reach)),
            rng.range(-3.0, 3.0),
        ),
        Vector::new(rng.range(-0.2, 0.2), rng.range(-0.2, 0.2)),
        Vector::new(rng.range(-4.0, 4.0), rng.range(-4.0, 4.0)),
        rng.range(-spin, spin),
    )
}

/// World support value max over shape of x·u at pose.
fn world_support(c: &dyn ConvexCurve, pose: &Pose, u: Vector) -> f64 {
    let local = pose.rotation.inverse_transform_vector(u);
    (*pose * c.support_point(local)).dot(u)
}

#[test]
fn guard_parabola_bounds_the_gap_along_the_turning_axis() {
    // For random pairs, motions, points φ (roots or not) and steps: along the axis that
    // starts at object1's normal N(φ) and turns at the guard's λ, the gap G(t) stays above
    // F + g'·s − M s²/2 with g' = F_t − (λ − ω₁)S, M from `guard_bound` (global and local
    // curvature bounds) — the inequality the guard and its two-sided check rest on.
    let shapes: Vec<Box<dyn ConvexCurve>> = vec![
        Box::new(Ellipse::new(1.0, 0.05)),
        Box::new(Ellipse::new(0.3, 0.7)),
        Box::new(BallCurve { radius: 0.4 }),
        Box::new(RoundedPolygon::regular(5, 0.8, 0.1)),
        Box::new(RoundedPolygon::regular(3, 0.6, 0.0)),
    ];
    let mut rng = Lcg(7);
    let (mut checked, mut spin_free, mut spun_disc) = (0, 0, 0);
    for case in 0..400 {
        let o1 = &*shapes[case % shapes.len()];
        let o2 = &*shapes[(case / shapes.len()) % 3];
        let (mut m1, mut m2) = (random_motion(&mut rng, 3.0, 40.0), random_motion(&mut rng, 3.0, 40.0));
        if case % 4 == 3 {
            // Neither spins as tracked: `guard_bound` answers M = 0 along the fixed axis at
            // once. A disc turning about its centre keeps its spin (it is tracked without it).
            m1.angvel = 0.0;
            if o2.support_dd_bound() == 0.0 {
                m2.local_center = Vector::ZERO;
            } else {
                m2.angvel = 0.0;
            }
        } else if case % 4 == 2 {
            // Only object2 turns: a bound is needed (M = 0 here would be wrong).
            m1.angvel = 0.0;
        }
        let tr = Tracker::new(o1, &m1, o2, &m2, 0.0, 1.0, &ToiOptions::default(), None).unwrap();
        spin_free += usize::from(tr.omega1 == 0.0 && tr.rel.omega2() == 0.0);
        spun_disc += usize::from(tr.spin2 != 0.0);
        let t = rng.range(0.0, 0.5);
        let phi = rng.range(-3.1, 3.1);
        let Some(j) = eval_pair(o1, o2, &tr.rel.frame(t), phi) else {
            continue;
        };
        let h = rng.range(1e-3, 0.3);
        for local in [None, Some(&j)] {
            let (m, lam) = tr.guard_bound(t, h, local);
            let slope = j.fwd.t - (lam - m1.angvel) * j.side.v;
            let n0 = m1.position_at_time(t).rotation * j.curve1.normal;
            for k in 1..=20 {
                let s = h * k as f64 / 20.0;
                let (p1, p2) = (m1.position_at_time(t + s), m2.position_at_time(t + s));
                let n = crate::numerics::math::rotate_cs((lam * s).cos(), (lam * s).sin(), n0);
                let gap = -world_support(o1, &p1, n) - world_support(o2, &p2, -n);
                let bound = j.fwd.v + slope * s - 0.5 * m * s * s;
                assert!(
                    gap >= bound - 1e-9 * (1.0 + bound.abs()),
                    "case {case}: gap {gap} below the bound {bound} at s = {s} (h = {h}, λ = {lam}, local {})",
                    local.is_some()
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 10_000);
    assert!(
        spin_free >= 100 && spun_disc >= 20,
        "{spin_free} spin-free pairs, {spun_disc} spun discs"
    );
}

#[test]
fn local_curvature_bound_of_the_ellipse_covers_its_arc() {
    let mut rng = Lcg(11);
    for _ in 0..300 {
        let e = Ellipse::new(rng.range(0.01, 2.0), rng.range(0.01, 2.0));
        let psi0 = rng.range(-4.0, 4.0);
        let w = rng.range(0.0, 1.2) * rng.next();
        let bound = e.support_dd_bound_near(crate::numerics::math::unit(psi0), w);
        assert!(bound <= e.support_dd_bound() * (1.0 + 1e-12));
        for k in 0..=200 {
            let psi = psi0 - w + 2.0 * w * k as f64 / 200.0;
            let u = crate::numerics::math::unit(psi);
            let sj = e.support_jet(u).unwrap();
            let hdd = sj.radius_of_curvature - sj.point.dot(u);
            assert!(
                hdd.abs() <= bound * (1.0 + 1e-9),
                "{hdd} > {bound} at ψ = {psi}, arc {psi0} ± {w}"
            );
        }
    }
}

fn still(x: f64, y: f64, a: f64) -> NonlinearRigidMotion {
    NonlinearRigidMotion::constant_position(Pose::new(Vector::new(x, y), a))
}

#[test]
fn head_on_discs_hit_at_the_closed_form_time() {
    let (a, b) = (BallCurve { radius: 0.5 }, BallCurve { radius: 0.25 });
    let m1 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(-2.0, 0.0), 0.0),
        Vector::ZERO,
        Vector::new(1.5, 0.0),
        3.0,
    );
    let m2 = still(1.0, 0.0, 0.0);
    let r = time_of_impact(&a, &m1, &b, &m2, 0.0, 4.0, &ToiOptions::default()).unwrap();
    assert_eq!(r.status, ToiStatus::Hit);
    let exact = (3.0 - 0.75) / 1.5;
    assert!((r.time - exact).abs() < 1e-9 * 4.0, "{} vs {exact}", r.time);
    assert!(r.distance >= -1e-12 && r.distance <= 1e-10);
}

/// Distance from the disc (centre (0, 0.8), radius 0.1) to the ellipse a=1, b=0.2 turned by
/// θ, by dense sampling of the ellipse (error ~1e-12).
fn disc_gap(theta: f64) -> f64 {
    let c = Vector::new(0.0, 0.8);
    let mut best = f64::INFINITY;
    let n = 400_000;
    for k in 0..n {
        let e = 2.0 * core::f64::consts::PI * k as f64 / n as f64;
        let p = crate::numerics::math::rotate_cs(theta.cos(), theta.sin(), Vector::new(e.cos(), 0.2 * e.sin()));
        best = best.min((p - c).length());
    }
    best - 0.1
}

#[test]
fn spinning_ellipse_reaches_a_disc_when_dense_sampling_says_so() {
    let (e, d) = (Ellipse::new(1.0, 0.2), BallCurve { radius: 0.1 });
    let w = 5.0;
    let m1 = NonlinearRigidMotion::new(Pose::new(Vector::ZERO, 0.0), Vector::ZERO, Vector::ZERO, w);
    let m2 = still(0.0, 0.8, 0.0);
    let r = time_of_impact(&e, &m1, &d, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
    assert_eq!(r.status, ToiStatus::Hit);
    assert!(disc_gap(w * r.time).abs() < 1e-8, "gap {}", disc_gap(w * r.time));
    for k in 0..20 {
        let t = r.time * k as f64 / 20.0;
        assert!(disc_gap(w * t) > 0.0);
    }
    // 1e-6 earlier the gap is still positive: the hit is not late.
    assert!(disc_gap(w * (r.time - 1e-6)) > 0.0);
}

#[test]
fn passing_shapes_report_no_hit() {
    let (a, b) = (Ellipse::new(0.5, 0.2), Ellipse::new(0.3, 0.6));
    let m1 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(-3.0, 2.0), 0.0),
        Vector::ZERO,
        Vector::new(6.0, 0.0),
        10.0,
    );
    let m2 = still(0.0, 0.0, 0.3);
    let r = time_of_impact(&a, &m1, &b, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
    assert_eq!(r.status, ToiStatus::NoHit);
}

#[test]
fn bounding_circles_part_only_when_no_impact_is_possible() {
    // Closed form: unit discs 10 apart closing at speed 1 come within 2 (touch) at t = 8.
    let disc = BallCurve { radius: 1.0 };
    let at = |x: f64, v: f64| {
        NonlinearRigidMotion::new(
            Pose::new(Vector::new(x, 0.0), 0.0),
            Vector::ZERO,
            Vector::new(v, 0.0),
            0.0,
        )
    };
    let (m1, m2) = (at(0.0, 0.0), at(10.0, -1.0));
    assert!(bounding_circles_part(&disc, &m1, &disc, &m2, 0.0, 7.9, 0.0));
    assert!(!bounding_circles_part(&disc, &m1, &disc, &m2, 0.0, 8.1, 0.0));
    assert!(
        !bounding_circles_part(&disc, &m1, &disc, &m2, 0.0, 7.9, 0.2),
        "target counts"
    );
    assert!(
        !bounding_circles_part(&disc, &m1, &disc, &m2, 1.0, 0.0, 0.0),
        "reversed window"
    );
    assert!(
        !bounding_circles_part(&disc, &m1, &disc, &m2, 0.0, f64::NAN, 0.0),
        "NaN window"
    );
    // Random pairs: whenever the circles part, the full query finds no impact either.
    let shapes: Vec<Box<dyn ConvexCurve>> = vec![
        Box::new(Ellipse::new(1.0, 0.05)),
        Box::new(Ellipse::new(0.3, 0.7)),
        Box::new(BallCurve { radius: 0.4 }),
        Box::new(RoundedPolygon::regular(5, 0.8, 0.1)),
    ];
    let mut rng = Lcg(11);
    let (mut parted, mut cases) = (0, 0);
    for case in 0..2000 {
        let o1 = &*shapes[case % shapes.len()];
        let o2 = &*shapes[(case / shapes.len()) % 3];
        let (m1, m2) = (random_motion(&mut rng, 4.0, 20.0), random_motion(&mut rng, 4.0, 20.0));
        let target = rng.range(0.0, 0.1);
        let o = ToiOptions {
            target_distance: target,
            ..ToiOptions::default()
        };
        let Ok(r) = time_of_impact(o1, &m1, o2, &m2, 0.0, 1.0, &o) else {
            continue;
        };
        cases += 1;
        if bounding_circles_part(o1, &m1, o2, &m2, 0.0, 1.0, target) {
            parted += 1;
            assert_eq!(r.status, ToiStatus::NoHit, "case {case}");
            assert!(r.distance > target);
        }
    }
    assert!(parted > 200 && parted < cases - 200, "{parted} of {cases} parted");
}

#[test]
fn appendix_d_heptagon_hits_the_ellipse_after_about_half_a_turn() {
    let hept = RoundedPolygon::regular(7, 1.0, 0.15);
    let ell = Ellipse::new(0.5, 1.5);
    let m1 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(-1.85, 0.0), 0.0),
        Vector::ZERO,
        Vector::new(2.0, 0.0),
        30.0,
    );
    let m2 = still(0.0, 0.0, 0.0);
    let r = time_of_impact(&hept, &m1, &ell, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
    assert_eq!(r.status, ToiStatus::Hit);
    let turns = 30.0 * r.time / (2.0 * core::f64::consts::PI);
    assert!(turns > 0.2 && turns < 1.0, "time {} turns {turns}", r.time);
}
