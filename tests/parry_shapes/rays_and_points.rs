//! Ray casts, point projections and support maps against dense boundary sampling.

use super::*;

#[test]
fn ray_casts_match_dense_sampling() {
    let mut rng = Rng::new(7);
    for c in cases() {
        let mut hits = 0;
        for _ in 0..400 {
            let o = rng.direction() * c.size * rng.uniform(1.05, 3.0);
            // Aim near the shape so that most rays hit.
            let target = rng.direction() * c.size * rng.uniform(0.0, 1.2);
            let d = (target - o) * rng.uniform(0.2, 5.0);
            let ray = Ray::new(o, d);
            let reference = ray_polygon(&c.boundary, o, d).filter(|(t0, t1)| *t1 >= 0.0 && *t0 >= 0.0);
            let ours = c.shape.cast_local_ray_and_get_normal(&ray, f64::MAX, true);
            match (ours, reference) {
                (Some(hit), Some((t0, _))) => {
                    hits += 1;
                    let scale = c.size / d.length();
                    assert!(
                        (hit.time_of_impact - t0).abs() <= 1e-8 * scale,
                        "{}: toi {} vs {t0}",
                        c.name,
                        hit.time_of_impact
                    );
                    // The hit point is on the boundary and the normal is outward unit there.
                    let p = ray.point_at(hit.time_of_impact);
                    let proj = c.shape.project_local_point(p, false);
                    assert!(
                        (proj.point - p).length() <= 1e-9 * c.size,
                        "{}: hit point off the boundary",
                        c.name
                    );
                    assert!((hit.normal.length() - 1.0).abs() < 1e-12);
                    assert!(hit.normal.dot(d) <= 1e-12, "{}: normal faces the ray", c.name);
                }
                (None, None) => {}
                (ours, reference) => {
                    // Disagreement is only allowed for grazing rays: the line passes within
                    // the sampling error of the boundary.
                    let u = d.normalize();
                    let m = Vector::new(u.y, -u.x);
                    let c0 = o.x * u.y - o.y * u.x;
                    let fmax = c.shape.as_support_map().unwrap().local_support_point(m).dot(m) - c0;
                    let fmin = c.shape.as_support_map().unwrap().local_support_point(-m).dot(m) - c0;
                    assert!(
                        fmax.abs() < 1e-7 * c.size || fmin.abs() < 1e-7 * c.size,
                        "{}: ours {ours:?} vs reference {reference:?}",
                        c.name
                    );
                }
            }
        }
        assert!(hits > 100, "{}: only {hits} hits", c.name);
    }
}

#[test]
fn ray_starting_inside_follows_parry_solid_semantics() {
    let mut rng = Rng::new(11);
    for c in cases() {
        for _ in 0..100 {
            // A point strictly inside: a convex combination of boundary samples.
            let i = (rng.next_u64() as usize) % c.boundary.len();
            let j = (rng.next_u64() as usize) % c.boundary.len();
            let o = c.boundary[i].lerp(c.boundary[j], rng.uniform(0.2, 0.8));
            if polygon_signed_distance(&c.boundary, o) > -1e-6 * c.size {
                continue;
            }
            let d = rng.direction() * rng.uniform(0.1, 10.0);
            let ray = Ray::new(o, d);
            let solid = c.shape.cast_local_ray_and_get_normal(&ray, f64::MAX, true).unwrap();
            assert_eq!(solid.time_of_impact, 0.0, "{}", c.name);
            let hollow = c.shape.cast_local_ray_and_get_normal(&ray, f64::MAX, false).unwrap();
            let (_, t1) = ray_polygon(&c.boundary, o, d).unwrap();
            let scale = c.size / d.length();
            assert!(
                (hollow.time_of_impact - t1).abs() <= 1e-7 * scale,
                "{}: exit {} vs {t1}",
                c.name,
                hollow.time_of_impact
            );
            // Inward normal at the exit point (parry's convention, as for its ball).
            assert!(hollow.normal.dot(d) < 0.0, "{}", c.name);
            let exit = ray.point_at(hollow.time_of_impact);
            let outward = c
                .shape
                .cast_local_ray_and_get_normal(&Ray::new(exit + d * 10.0, -d), f64::MAX, true)
                .unwrap();
            assert!((outward.normal + hollow.normal).length() < 1e-6, "{}", c.name);
            assert!((hollow.normal.length() - 1.0).abs() < 1e-12);
            // max_time_of_impact is honoured.
            assert!(c
                .shape
                .cast_local_ray_and_get_normal(&ray, 0.5 * hollow.time_of_impact, false)
                .is_none());
            assert!(c.shape.cast_local_ray(&ray, 0.0, true).is_some());
        }
    }
}

#[test]
fn point_projection_on_1_to_1000_ellipses_matches_dense_sampling() {
    let mut rng = Rng::new(3);
    for (a, b) in [(1.0, 1e-3), (1e-3, 1.0), (50.0, 0.05)] {
        let e = Ellipse::new(a, b);
        let boundary = dense_ellipse(&e, 400_000);
        let size = a.max(b);
        let mut points = vec![
            Vector::ZERO,
            Vector::new(0.5 * a, 0.0),
            Vector::new(0.0, 0.5 * b),
            Vector::new(a * 1.001, 0.0),
            Vector::new(a * 0.999, b * 1e-3),
            Vector::new(0.0, b * 3.0),
            Vector::new(a * 2.0, b * 2.0),
            Vector::new(-a * 0.9999, -b * 0.001),
        ];
        for _ in 0..300 {
            // Mostly near the boundary, on all scales, including near the tips.
            let ang = rng.uniform(-PI, PI);
            let rad = match rng.next_u64() % 4 {
                0 => rng.uniform(0.0, 1.0),
                1 => 1.0 + rng.uniform(-1e-3, 1e-3),
                2 => rng.uniform(1.0, 3.0),
                _ => 1.0 + rng.uniform(-1e-6, 1e-6),
            };
            points.push(Vector::new(a * rad * ang.cos(), b * rad * ang.sin()));
        }
        for x in points {
            let pr = e.project_local_point(x, false);
            let reference = polygon_signed_distance(&boundary, x);
            let ours = (pr.point - x).length();
            assert!(
                (ours - reference.abs()).abs() <= 1e-9 * size,
                "{a}x{b}: {x}: distance {ours} vs reference {reference}"
            );
            assert_eq!(pr.is_inside, reference <= 0.0, "{a}x{b}: {x} inside flag");
            // On the ellipse.
            let g = (pr.point.x / a).powi(2) + (pr.point.y / b).powi(2) - 1.0;
            assert!(g.abs() < 1e-12);
            let solid = e.project_local_point(x, true);
            if pr.is_inside {
                assert_eq!(solid.point, x);
                assert!(solid.is_inside);
            } else {
                assert_eq!(solid.point, pr.point);
            }
            let (fp, f) = e.project_local_point_and_get_feature(x);
            assert_eq!(fp.point, pr.point);
            assert_eq!(f, FeatureId::Face(0));
        }
    }
}

#[test]
fn point_projection_matches_dense_sampling_for_every_shape() {
    let mut rng = Rng::new(5);
    for c in cases() {
        for _ in 0..300 {
            let x = rng.direction() * c.size * rng.uniform(0.0, 2.0);
            let reference = polygon_signed_distance(&c.boundary, x);
            let pr = c.shape.project_local_point(x, false);
            let ours = (pr.point - x).length();
            assert!(
                (ours - reference.abs()).abs() <= 1e-8 * c.size,
                "{}: {x}: {ours} vs {reference}",
                c.name
            );
            if reference.abs() > 1e-8 * c.size {
                assert_eq!(pr.is_inside, reference < 0.0, "{}: {x} inside flag", c.name);
                assert_eq!(c.shape.contains_local_point(x), reference < 0.0);
            }
            let d = c.shape.distance_to_local_point(x, true);
            assert!(
                (d - reference.max(0.0)).abs() <= 2e-8 * c.size,
                "{}: {d} vs {reference}",
                c.name
            );
            let (fp, _) = c.shape.project_local_point_and_get_feature(x);
            assert!((fp.point - pr.point).length() <= 1e-12 * c.size);
        }
    }
}

#[test]
fn support_map_matches_convex_curve_support_point() {
    let curves: Vec<(Box<dyn Shape>, Box<dyn ConvexCurve>)> = vec![
        (Box::new(Ellipse::new(2.0, 0.1)), Box::new(Ellipse::new(2.0, 0.1))),
        (
            Box::new(RoundedPolygon::regular(5, 1.0, 0.2)),
            Box::new(RoundedPolygon::regular(5, 1.0, 0.2)),
        ),
        (
            Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8)),
            Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8)),
        ),
        (Box::new(custom_ellipse()), Box::new(custom_ellipse())),
    ];
    let mut rng = Rng::new(9);
    for (shape, curve) in &curves {
        let sm = shape.as_support_map().unwrap();
        for _ in 0..200 {
            let n = rng.direction();
            let expected = curve.support_point(n);
            for scale in [1.0, 1e-200, 3.7, 1e200] {
                let p = sm.local_support_point(n * scale);
                assert!((p - expected).length() < 1e-12, "{p} vs {expected}");
            }
            assert!((sm.local_support_point_toward(n) - expected).length() < 1e-12);
        }
        // Zero, NaN and infinite directions give a finite boundary point.
        for bad in [
            Vector::ZERO,
            Vector::new(f64::NAN, 1.0),
            Vector::new(f64::INFINITY, 0.0),
        ] {
            assert!(sm.local_support_point(bad).is_finite());
        }
    }
}
