//! The crate's shapes as parry shapes: bounding volumes, mass properties, ray casts, point
//! projection, support maps, polygonal features, and parry's default dispatcher on them.
//! References are independent: dense boundary sampling (chord polygons), closed forms, and
//! parry's own shapes.

mod common;

use common::curves::EccentricEllipse;
use common::rng::Rng;
use core::f64::consts::PI;
use parry2d_f64::bounding_volume::Aabb;
use parry2d_f64::mass_properties::MassProperties;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{self, ContactManifold, DefaultQueryDispatcher, PersistentQueryDispatcher, PointQuery, Ray};
use parry2d_f64::shape::{
    Ball, ConvexPolygon, Cuboid, FeatureId, HalfSpace, PolygonalFeature, RoundShape, Shape, ShapeType, TypedShape,
};
use smooth_ccd2d::{CapsuleEllipse, ConvexCurve, CustomCurve, Ellipse, RoundedPolygon};

fn custom_ellipse() -> CustomCurve {
    CustomCurve::new(EccentricEllipse {
        a: 1.3,
        b: 0.4,
        center: Vector::new(0.2, -0.1),
    })
}

/// Dense counter-clockwise boundary samples of a curve, `per_piece` per piece between
/// breakpoints (one piece when smooth).
fn dense_boundary(c: &dyn ConvexCurve, per_piece: usize) -> Vec<Vector> {
    let bp = c.breakpoints().to_vec();
    let pieces: Vec<(f64, f64)> = if bp.is_empty() {
        vec![(-PI, PI)]
    } else {
        (0..bp.len())
            .map(|k| (bp[k], if k + 1 < bp.len() { bp[k + 1] } else { bp[0] + 2.0 * PI }))
            .collect()
    };
    let mut out = Vec::new();
    for (s, e) in pieces {
        for j in 0..per_piece {
            out.push(c.eval(s + (e - s) * j as f64 / per_piece as f64).point);
        }
    }
    // Drop repeated points (sharp corners).
    let mut dedup: Vec<Vector> = Vec::with_capacity(out.len());
    for p in out {
        if dedup.last().is_none_or(|q| (p - *q).length() > 1e-13) {
            dedup.push(p);
        }
    }
    while dedup.len() > 1 && (dedup[0] - dedup[dedup.len() - 1]).length() <= 1e-13 {
        dedup.pop();
    }
    dedup
}

/// Dense samples of an ellipse by eccentric anomaly (even in arc length on flanks and tips).
fn dense_ellipse(e: &Ellipse, n: usize) -> Vec<Vector> {
    (0..n)
        .map(|i| e.point_at_eccentric(2.0 * PI * i as f64 / n as f64))
        .collect()
}

/// Ray against a counter-clockwise convex polygon (Cyrus–Beck): (t_enter, t_exit) of the line.
fn ray_polygon(poly: &[Vector], o: Vector, d: Vector) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    let n = poly.len();
    for i in 0..n {
        let (p, q) = (poly[i], poly[(i + 1) % n]);
        let e = q - p;
        let nrm = Vector::new(e.y, -e.x);
        let num = (p - o).dot(nrm);
        let den = d.dot(nrm);
        if den == 0.0 {
            if num < 0.0 {
                return None;
            }
        } else if den < 0.0 {
            t0 = t0.max(num / den);
        } else {
            t1 = t1.min(num / den);
        }
    }
    (t0 <= t1).then_some((t0, t1))
}

/// Signed distance from x to a counter-clockwise convex polygon.
fn polygon_signed_distance(poly: &[Vector], x: Vector) -> f64 {
    let n = poly.len();
    let mut dmin = f64::INFINITY;
    let mut inside = true;
    for i in 0..n {
        let (p, q) = (poly[i], poly[(i + 1) % n]);
        let e = q - p;
        if (x - p).dot(Vector::new(e.y, -e.x)) > 0.0 {
            inside = false;
        }
        let t = ((x - p).dot(e) / e.length_squared()).clamp(0.0, 1.0);
        dmin = dmin.min((x - (p + e * t)).length());
    }
    if inside {
        -dmin
    } else {
        dmin
    }
}

struct Case {
    name: &'static str,
    shape: Box<dyn Shape>,
    boundary: Vec<Vector>,
    size: f64,
}

fn cases() -> Vec<Case> {
    let mut v = Vec::new();
    for (a, b) in [(1.0, 1.0), (2.0, 0.5), (0.3, 1.7), (1.0, 0.01), (1.0, 1e-3)] {
        let e = Ellipse::new(a, b);
        v.push(Case {
            name: "ellipse",
            shape: Box::new(e),
            boundary: dense_ellipse(&e, 200_000),
            size: a.max(b),
        });
    }
    let irregular = [
        Vector::new(0.3, -0.2),
        Vector::new(2.1, 0.1),
        Vector::new(2.4, 1.3),
        Vector::new(1.0, 2.2),
        Vector::new(0.1, 1.0),
    ];
    for p in [
        RoundedPolygon::regular(5, 1.0, 0.0),
        RoundedPolygon::regular(4, 1.0, 0.2),
        RoundedPolygon::regular(7, 0.5, 0.5),
        RoundedPolygon::new(&irregular, 0.0),
        RoundedPolygon::new(&irregular, 0.15),
    ] {
        let boundary = dense_boundary(&p, 20_000);
        let size = p.bounding_radius();
        v.push(Case {
            name: "rounded polygon",
            shape: Box::new(p),
            boundary,
            size,
        });
    }
    for c in [CapsuleEllipse::new(0.5, 1.0, 0.8), CapsuleEllipse::new(0.2, 0.3, 2.5)] {
        let boundary = dense_boundary(&c, 50_000);
        let size = c.bounding_radius();
        v.push(Case {
            name: "capsule ellipse",
            shape: Box::new(c),
            boundary,
            size,
        });
    }
    let c = custom_ellipse();
    let boundary = dense_boundary(&c, 200_000);
    let size = c.bounding_radius();
    v.push(Case {
        name: "custom curve",
        shape: Box::new(c),
        boundary,
        size,
    });
    let c = CustomCurve::new(CapsuleEllipse::new(0.4, 0.6, 1.1));
    let boundary = dense_boundary(&c, 50_000);
    let size = c.bounding_radius();
    v.push(Case {
        name: "custom capsule ellipse",
        shape: Box::new(c),
        boundary,
        size,
    });
    v
}

/// Asserts that every point is in `aabb` (to `tol`); returns the points' own box (lo, hi).
fn box_of_points_in(points: impl Iterator<Item = Vector>, aabb: &Aabb, tol: f64, what: &str) -> (Vector, Vector) {
    let (mut lo, mut hi) = (Vector::splat(f64::INFINITY), Vector::splat(f64::NEG_INFINITY));
    for p in points {
        assert!(
            p.x >= aabb.mins.x - tol && p.y >= aabb.mins.y - tol,
            "{what}: {p} below {aabb:?}"
        );
        assert!(
            p.x <= aabb.maxs.x + tol && p.y <= aabb.maxs.y + tol,
            "{what}: {p} above {aabb:?}"
        );
        lo = lo.min(p);
        hi = hi.max(p);
    }
    (lo, hi)
}

/// Asserts that the points' box (lo, hi) reaches `aabb` to `tol`: the box is tight.
fn assert_tight(lo: Vector, hi: Vector, aabb: &Aabb, tol: f64, what: &str) {
    let gap = (lo - aabb.mins).abs().max((hi - aabb.maxs).abs()).max_element();
    assert!(gap < tol, "{what}: samples {lo} {hi} vs {aabb:?}");
}

#[test]
fn aabb_and_bounding_sphere_contain_dense_boundary_samples() {
    for c in cases() {
        let aabb = c.shape.compute_local_aabb();
        let bs = c.shape.compute_local_bounding_sphere();
        let tol = 1e-12 * c.size;
        for p in &c.boundary {
            assert!(
                (*p - bs.center).length() <= bs.radius + tol,
                "{}: {p} outside sphere",
                c.name
            );
        }
        let (lo, hi) = box_of_points_in(c.boundary.iter().copied(), &aabb, tol, c.name);
        // Exact: the samples reach the box (up to the sampling resolution).
        assert_tight(lo, hi, &aabb, 1e-6 * c.size, c.name);
    }
}

/// The posed boxes (`compute_aabb`) contain the posed boundary samples and, for the ellipse and
/// the rounded polygon (tight boxes), are reached by them to the sampling resolution; the
/// others' posed boxes are parry's transformed local box, which contains them.
#[test]
fn posed_boxes_contain_the_posed_boundary_and_are_tight_where_promised() {
    for c in cases() {
        for k in 0..12 {
            let pose = Pose::new(Vector::new(0.3 * k as f64 - 1.0, 2.0 - 0.1 * k as f64), 0.55 * k as f64);
            let aabb = c.shape.compute_aabb(&pose);
            let tol = 1e-12 * (c.size + pose.translation.length());
            let posed = c.boundary.iter().map(|p| pose.transform_point(*p));
            let (lo, hi) = box_of_points_in(posed, &aabb, tol, c.name);
            if c.name == "ellipse" || c.name == "rounded polygon" {
                assert_tight(lo, hi, &aabb, 1e-6 * c.size, &format!("{} pose {k}", c.name));
            }
        }
    }
}

fn assert_mass_close(name: &str, m: &MassProperties, r: &MassProperties, tol: f64, size: f64) {
    assert!(
        (m.mass() - r.mass()).abs() <= tol * r.mass(),
        "{name}: mass {} vs {}",
        m.mass(),
        r.mass()
    );
    assert!(
        (m.local_com - r.local_com).length() <= tol * size,
        "{name}: com {} vs {}",
        m.local_com,
        r.local_com
    );
    let (i, ir) = (m.principal_inertia(), r.principal_inertia());
    assert!((i - ir).abs() <= tol * ir, "{name}: inertia {i} vs {ir}");
}

#[test]
fn ellipse_mass_properties_match_closed_form() {
    for (a, b) in [(1.0, 1.0), (2.0, 0.5), (1.0, 1e-3)] {
        let m = Ellipse::new(a, b).mass_properties(2.5);
        let mass = 2.5 * PI * a * b;
        assert!((m.mass() - mass).abs() < 1e-14 * mass);
        assert!((m.principal_inertia() - mass * (a * a + b * b) / 4.0).abs() < 1e-14 * mass * a * a);
        assert_eq!(m.local_com, Vector::ZERO);
    }
}

#[test]
fn sharp_rounded_polygon_mass_matches_parry_convex_and_round_convex_polygon() {
    let irregular = [
        Vector::new(0.3, -0.2),
        Vector::new(2.1, 0.1),
        Vector::new(2.4, 1.3),
        Vector::new(1.0, 2.2),
    ];
    let mut polys = vec![RoundedPolygon::new(&irregular, 0.0)];
    for n in 3..10 {
        polys.push(RoundedPolygon::regular(n, 1.7, 0.0));
    }
    for p in polys {
        let ours = p.mass_properties(3.0);
        let parry = MassProperties::from_convex_polygon(3.0, p.vertices());
        assert_mass_close(
            "sharp polygon vs ConvexPolygon",
            &ours,
            &parry,
            1e-12,
            p.bounding_radius(),
        );
        let round = p.to_parry().unwrap();
        assert_mass_close(
            "sharp polygon vs RoundConvexPolygon",
            &ours,
            &round.mass_properties(3.0),
            1e-12,
            p.bounding_radius(),
        );
    }
    // parry's RoundConvexPolygon ignores the border in its mass: ours does not.
    let p = RoundedPolygon::regular(4, 1.0, 0.5);
    assert!(p.mass_properties(1.0).mass() > p.to_parry().unwrap().mass_properties(1.0).mass() + 1.0);
}

#[test]
fn mass_properties_match_dense_polygonal_approximation() {
    for c in cases() {
        // The chord polygon of n samples underestimates area by O(1/n²).
        let reference = MassProperties::from_convex_polygon(1.5, &c.boundary);
        let ours = c.shape.mass_properties(1.5);
        assert_mass_close(c.name, &ours, &reference, 2e-7, c.size);
    }
}

#[test]
fn custom_curve_mass_matches_the_wrapped_shapes_closed_form() {
    let e = Ellipse::new(1.3, 0.2);
    let custom = CustomCurve::new(e);
    assert_mass_close(
        "custom ellipse",
        &custom.mass_properties(2.0),
        &e.mass_properties(2.0),
        1e-13,
        1.3,
    );
    let p = RoundedPolygon::regular(6, 1.0, 0.3);
    let custom = CustomCurve::new(p.clone());
    assert_mass_close(
        "custom rounded",
        &custom.mass_properties(2.0),
        &p.mass_properties(2.0),
        1e-13,
        1.3,
    );
    let c = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let custom = CustomCurve::new(c.clone());
    assert_mass_close(
        "custom capsule ellipse",
        &custom.mass_properties(2.0),
        &c.mass_properties(2.0),
        1e-13,
        1.5,
    );
    // Off-centre eccentric-anomaly ellipse: πab, centre of mass at its centre.
    let m = custom_ellipse().mass_properties(1.0);
    let (a, b) = (1.3, 0.4);
    assert!((m.mass() - PI * a * b).abs() < 1e-13);
    assert!((m.local_com - Vector::new(0.2, -0.1)).length() < 1e-13);
    assert!((m.principal_inertia() - PI * a * b * (a * a + b * b) / 4.0).abs() < 1e-13);
}

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

fn feature_of(shape: &dyn Shape, dir: Vector) -> PolygonalFeature {
    let (pfm, radius) = shape.as_polygonal_feature_map().unwrap();
    assert_eq!(radius, 0.0);
    let mut f = PolygonalFeature::default();
    pfm.local_support_feature(dir, &mut f);
    f
}

#[test]
fn polygonal_features_are_segments_touching_the_support_level() {
    let mut rng = Rng::new(13);
    for c in cases() {
        let sm = c.shape.as_support_map().unwrap();
        let mut dirs: Vec<Vector> = (0..300).map(|_| rng.direction()).collect();
        dirs.extend([
            Vector::X,
            -Vector::X,
            Vector::Y,
            -Vector::Y,
            Vector::new(1.0, 1e-3).normalize(),
        ]);
        for n in dirs {
            let f = feature_of(&*c.shape, n * 2.5);
            assert_eq!(f.num_vertices, 2, "{}", c.name);
            let [v0, v1] = f.vertices;
            assert!(v0.is_finite() && v1.is_finite());
            assert!((v1 - v0).length() > 0.0, "{}: degenerate feature", c.name);
            assert_ne!(f.vids[0], f.vids[1]);
            // Counter-clockwise seen from outside: v1 − v0 turns with the tangent perp(n).
            assert!(
                (v1 - v0).dot(Vector::new(-n.y, n.x)) > 0.0,
                "{}: feature orientation",
                c.name
            );
            // Its highest vertex is at the support level: parry reads contact distances off it.
            let h = sm.local_support_point(n).dot(n);
            let top = v0.dot(n).max(v1.dot(n));
            assert!(
                (top - h).abs() <= 1e-12 * c.size,
                "{}: feature at {top}, support at {h}",
                c.name
            );
            // Both vertices lie in the shape (up to rounding) or on its tangent line.
            for v in [v0, v1] {
                assert!(v.dot(n) <= h + 1e-12 * c.size);
            }
        }
    }
    // Smooth points give a short tangent segment; flat sides give the whole side.
    let e = Ellipse::new(1.0, 0.001);
    let f = feature_of(&e, Vector::X);
    assert!((f.vertices[1] - f.vertices[0]).length() <= 1e-6);
    let cap = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let f = feature_of(&cap, Vector::new(1.0, 0.01));
    assert!((f.vertices[0] - Vector::new(0.5, -1.0)).length() < 1e-12);
    assert!((f.vertices[1] - ConvexCurve::support_point(&cap, Vector::new(1.0, 0.01).normalize())).length() < 1e-12);
    let sq = RoundedPolygon::regular(4, 1.0, 0.1);
    let f = feature_of(&sq, Vector::new(1.0, 1.0));
    assert!(((f.vertices[1] - f.vertices[0]).length() - 2f64.sqrt()).abs() < 1e-12);
}

fn manifolds(pos12: &Pose, s1: &dyn Shape, s2: &dyn Shape, prediction: f64) -> Vec<ContactManifold<(), ()>> {
    let mut out: Vec<ContactManifold<(), ()>> = Vec::new();
    let mut ws = None;
    DefaultQueryDispatcher
        .contact_manifolds(pos12, s1, s2, prediction, &mut out, &mut ws)
        .expect("supported");
    out
}

#[test]
fn default_dispatcher_contact_manifolds_on_ellipse_pairs_do_not_panic() {
    let e1 = Ellipse::new(1.0, 0.5);
    let e2 = Ellipse::new(0.7, 0.2);
    let cuboid = Cuboid::new(Vector::new(2.0, 0.3));
    let mut rng = Rng::new(17);
    let others: Vec<(&str, Box<dyn Shape>)> = vec![
        ("ellipse", Box::new(e2)),
        ("cuboid", Box::new(cuboid)),
        ("ball", Box::new(Ball::new(0.4))),
        ("rounded polygon", Box::new(RoundedPolygon::regular(5, 0.6, 0.1))),
        ("sharp polygon", Box::new(RoundedPolygon::regular(3, 0.6, 0.0))),
        ("capsule ellipse", Box::new(CapsuleEllipse::new(0.3, 0.4, 0.5))),
        ("custom", Box::new(custom_ellipse())),
        (
            "parry round polygon",
            Box::new(RoundedPolygon::regular(6, 0.5, 0.1).to_parry().unwrap()),
        ),
    ];
    for (name, other) in &others {
        let mut found = 0;
        for _ in 0..200 {
            let dir = rng.direction();
            let gap = rng.uniform(-0.2, 0.3);
            let angle = rng.uniform(-PI, PI);
            // Place shape 2 along dir at roughly the gap.
            let mut pos12 = Pose::new(dir * 6.0, angle);
            let d = query::distance(&Pose::IDENTITY, &e1, &pos12, &**other)
                .unwrap()
                .distance;
            pos12 = Pose::new(dir * (6.0 - d + gap), angle);
            let ms = manifolds(&pos12, &e1, &**other, 0.1);
            let contact = query::contact(&Pose::IDENTITY, &e1, &pos12, &**other, 0.1).unwrap();
            let points: Vec<f64> = ms.iter().flat_map(|m| m.points.iter().map(|p| p.dist)).collect();
            if let Some(contact) = contact {
                assert!(!points.is_empty(), "{name}: contact {contact:?} but no manifold point");
                found += 1;
                let dmin = points.iter().copied().fold(f64::INFINITY, f64::min);
                assert!(
                    (dmin - contact.dist).abs() < 1e-3,
                    "{name}: manifold {dmin} vs contact {}",
                    contact.dist
                );
                for m in &ms {
                    assert!(m.local_n1.is_finite() && (m.local_n1.length() - 1.0).abs() < 1e-9);
                    for p in &m.points {
                        assert!(p.local_p1.is_finite() && p.local_p2.is_finite() && p.dist.is_finite());
                    }
                }
            }
            // Swapped roles too.
            let _ = manifolds(&pos12.inverse(), &**other, &e1, 0.1);
        }
        assert!(found > 20, "{name}: only {found} contacts");
    }
    // Ellipse on a half-space (parry's half-space × feature-map path).
    let ground = HalfSpace::new(Vector::Y);
    let ms = manifolds(&Pose::new(Vector::new(0.0, 0.49), 0.0), &ground, &e1, 0.1);
    assert_eq!(ms.len(), 1);
    assert!(ms[0].points.iter().all(|p| (p.dist + 0.01).abs() < 1e-12));
}

#[test]
fn resting_flat_sides_give_two_point_manifolds() {
    let ground = Cuboid::new(Vector::new(5.0, 0.5));
    // A rounded square lying on its side, and the capsule-ellipse on its segment.
    let sq = RoundedPolygon::regular(4, 1.0, 0.1);
    let h = (PI / 4.0).cos() + 0.1;
    let pos = Pose::new(Vector::new(0.3, 0.5 + h - 1e-3), PI / 4.0);
    let ms = manifolds(&pos, &ground, &sq, 0.05);
    assert_eq!(ms[0].points.len(), 2, "{ms:?}");
    for p in &ms[0].points {
        assert!((p.dist + 1e-3).abs() < 1e-9, "{}", p.dist);
    }
    let cap = CapsuleEllipse::new(0.5, 1.0, 0.8);
    // Segment x = r1 facing down: rotate by −π/2.
    let pos = Pose::new(Vector::new(0.0, 0.5 + 0.5 - 2e-3), -PI / 2.0);
    let ms = manifolds(&pos, &ground, &cap, 0.05);
    assert_eq!(ms[0].points.len(), 2, "{ms:?}");
    for p in &ms[0].points {
        assert!((p.dist + 2e-3).abs() < 1e-9, "{}", p.dist);
    }
}

#[test]
fn distance_and_contact_work_through_support_maps() {
    let e = Ellipse::new(2.0, 0.3);
    let ball = Ball::new(0.25);
    let mut rng = Rng::new(21);
    for _ in 0..100 {
        let c = rng.direction() * rng.uniform(2.5, 4.0);
        let pos2 = Pose::new(c, 0.0);
        let d = query::distance(&Pose::IDENTITY, &e, &pos2, &ball).unwrap().distance;
        let exact = (e.project_local_point(c, true).point - c).length() - 0.25;
        assert!((d - exact).abs() < 1e-6, "{d} vs {exact}");
    }
    // Penetrating ellipses: contact reports a negative distance, close to our projection-based
    // bound along the axis.
    let e2 = Ellipse::new(0.5, 0.5);
    let pos2 = Pose::new(Vector::new(2.3, 0.0), 0.3);
    let c = query::contact(&Pose::IDENTITY, &e, &pos2, &e2, 0.0).unwrap().unwrap();
    assert!((c.dist - (-0.2)).abs() < 1e-6, "{}", c.dist);
    // Custom, capsule-ellipse and rounded polygons against parry's own shapes.
    let shapes: Vec<Box<dyn Shape>> = vec![
        Box::new(custom_ellipse()),
        Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8)),
        Box::new(RoundedPolygon::regular(6, 1.0, 0.2)),
    ];
    for s in &shapes {
        let d = query::distance(&Pose::IDENTITY, &**s, &Pose::new(Vector::new(5.0, 0.0), 0.0), &ball)
            .unwrap()
            .distance;
        let exact = (s.project_local_point(Vector::new(5.0, 0.0), true).point - Vector::new(5.0, 0.0)).length() - 0.25;
        assert!((d - exact).abs() < 1e-6, "{d} vs {exact}");
    }
    // The rounded polygon agrees with parry's RoundConvexPolygon.
    let p = RoundedPolygon::regular(5, 1.0, 0.3);
    let parry_p = p.to_parry().unwrap();
    let cub = Cuboid::new(Vector::new(0.4, 0.2));
    for _ in 0..50 {
        let pos2 = Pose::new(rng.direction() * rng.uniform(1.0, 3.0), rng.uniform(-PI, PI));
        let ours = query::contact(&Pose::IDENTITY, &p, &pos2, &cub, 1.0).unwrap();
        let theirs = query::contact(&Pose::IDENTITY, &parry_p, &pos2, &cub, 1.0).unwrap();
        assert_eq!(ours.is_some(), theirs.is_some());
        if let (Some(a), Some(b)) = (ours, theirs) {
            assert!((a.dist - b.dist).abs() < 1e-6, "{} vs {}", a.dist, b.dist);
        }
    }
}

#[test]
fn queries_on_bad_input_do_not_panic_or_return_nan() {
    for c in cases() {
        let s = &*c.shape;
        let bad = [
            Vector::new(f64::NAN, 0.0),
            Vector::new(f64::INFINITY, 1.0),
            Vector::ZERO,
        ];
        for v in bad {
            let pr = s.project_local_point(v, false);
            assert!(pr.point.is_finite(), "{}", c.name);
            let (fp, _) = s.project_local_point_and_get_feature(v);
            assert!(fp.point.is_finite());
            assert!(s.as_support_map().unwrap().local_support_point(v).is_finite());
            let f = feature_of(s, v);
            assert!(f.vertices[0].is_finite() && f.vertices[1].is_finite());
            for o in [
                Vector::ZERO,
                Vector::new(10.0 * c.size, 0.0),
                Vector::new(f64::NAN, 0.0),
            ] {
                for solid in [true, false] {
                    if let Some(hit) = s.cast_local_ray_and_get_normal(&Ray::new(o, v), f64::MAX, solid) {
                        assert!(hit.time_of_impact.is_finite() && hit.normal.is_finite(), "{}", c.name);
                    }
                    let _ = s.cast_local_ray_and_get_normal(&Ray::new(v, Vector::X), f64::NAN, solid);
                }
            }
        }
        // A zero-length ray from inside hits at 0; from outside it misses.
        let inside = c.boundary[0].lerp(c.boundary[c.boundary.len() / 2], 0.5);
        let hit = s
            .cast_local_ray_and_get_normal(&Ray::new(inside, Vector::ZERO), 1.0, false)
            .unwrap();
        assert_eq!(hit.time_of_impact, 0.0);
        assert!(hit.normal.is_finite());
        assert!(s
            .cast_local_ray_and_get_normal(&Ray::new(Vector::splat(10.0 * c.size), Vector::ZERO), 1.0, true)
            .is_none());
    }
}

#[test]
fn scale_dyn_follows_the_shapes_rules() {
    let e = Ellipse::new(2.0, 0.5);
    let s = e.scale_dyn(Vector::new(-0.5, 3.0), 8).unwrap();
    let s = s.as_shape::<Ellipse>().unwrap();
    assert_eq!((s.half_x(), s.half_y()), (1.0, 1.5));
    assert!(e.scale_dyn(Vector::new(0.0, 1.0), 8).is_none());

    let p = RoundedPolygon::regular(5, 1.0, 0.2);
    let s = p.scale_dyn(Vector::new(2.0, -2.0), 8).unwrap();
    let s = s.as_shape::<RoundedPolygon>().unwrap();
    assert!((s.corner_radius() - 0.4).abs() < 1e-15);
    assert!((s.compute_local_aabb().maxs.x - 2.4).abs() < 1e-12);
    assert!(p.scale_dyn(Vector::new(2.0, 1.0), 8).is_none());
    let sharp = RoundedPolygon::regular(5, 1.0, 0.0);
    let s = sharp.scale_dyn(Vector::new(2.0, 1.0), 8).unwrap();
    assert!((s.compute_local_aabb().maxs.x - 2.0).abs() < 1e-12);

    let c = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let s = c.scale_dyn(Vector::new(2.0, -2.0), 8).unwrap();
    assert_eq!(s.as_shape::<CapsuleEllipse>().unwrap().params(), (1.0, 2.0, 1.6));
    assert!(c.scale_dyn(Vector::new(-2.0, 2.0), 8).is_none());
    assert!(c.scale_dyn(Vector::new(2.0, 1.0), 8).is_none());
    assert!(custom_ellipse().scale_dyn(Vector::splat(2.0), 8).is_none());
}

#[test]
fn shapes_are_custom_convex_with_support_and_feature_maps() {
    for c in cases() {
        let s = &*c.shape;
        assert_eq!(s.shape_type(), ShapeType::Custom);
        assert!(matches!(s.as_typed_shape(), TypedShape::Custom(_)));
        assert!(s.is_convex());
        assert!(s.as_support_map().is_some());
        assert!(s.as_polygonal_feature_map().is_some());
        let b = s.clone_dyn();
        assert_eq!(b.compute_local_aabb(), s.compute_local_aabb());
        assert!(s.ccd_thickness() > 0.0 && s.ccd_angular_thickness() > 0.0);
    }
}

#[test]
fn ccd_thickness_is_the_inradius_about_the_centroid() {
    // The distance from the centroid (rapier's rotation centre) to the boundary: rapier sweeps a
    // body that moves more than a fraction of it in a step.
    assert_eq!(Ellipse::new(2.0, 0.3).ccd_thickness(), 0.3);
    for (n, r) in [(3, 0.0), (5, 0.2), (8, 1.0)] {
        let p = RoundedPolygon::regular(n, 1.0, r);
        let inradius = (std::f64::consts::PI / n as f64).cos() + r;
        assert!((p.ccd_thickness() - inradius).abs() < 1e-14, "{n} {r}");
        let parry: RoundShape<ConvexPolygon> = p.to_parry().unwrap();
        assert_eq!(p.ccd_angular_thickness(), parry.ccd_angular_thickness());
    }
    // A thin sliver turned off its axes: its box is wide, the body is not.
    let sliver = RoundedPolygon::new(
        &[Vector::new(-0.5, -0.5), Vector::new(0.5, 0.4), Vector::new(0.4, 0.5)],
        0.0,
    );
    let c = sliver.mass_properties(1.0).local_com;
    let by_projection = (sliver.project_local_point(c, false).point - c).length();
    assert!((sliver.ccd_thickness() - by_projection).abs() < 1e-12);
    assert!(sliver.ccd_thickness() < 0.05, "{}", sliver.ccd_thickness());
    // CapsuleEllipse (r1 = 0.5, r2 = 1.0, r3 = 0.8): its centroid and the nearest boundary point,
    // against point projection.
    let cap = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let c = cap.mass_properties(1.0).local_com;
    let by_projection = (cap.project_local_point(c, false).point - c).length();
    assert!(
        (cap.ccd_thickness() - by_projection).abs() < 1e-9,
        "{} {by_projection}",
        cap.ccd_thickness()
    );
    // A custom curve (an ellipse 1.3 × 0.4 off its origin): its semi-minor axis.
    assert!(
        (custom_ellipse().ccd_thickness() - 0.4).abs() < 1e-9,
        "{}",
        custom_ellipse().ccd_thickness()
    );
}

#[test]
fn rapier_default_narrow_phase_keeps_every_shape_on_the_ground() {
    use rapier2d_f64::prelude::*;
    // (name, shape, smallest distance from the body origin to its boundary, comes to rest):
    // smooth shapes rock for a long time (rolling without slipping dissipates little).
    let shapes: Vec<(&str, SharedShape, f64, bool)> = vec![
        ("ellipse", SharedShape::new(Ellipse::new(0.6, 0.25)), 0.25, false),
        ("thin ellipse", SharedShape::new(Ellipse::new(1.0, 0.05)), 0.05, false),
        (
            "rounded square",
            SharedShape::new(RoundedPolygon::regular(4, 0.5, 0.05)),
            0.4,
            true,
        ),
        (
            "sharp pentagon",
            SharedShape::new(RoundedPolygon::regular(5, 0.5, 0.0)),
            0.4,
            true,
        ),
        (
            "capsule ellipse",
            SharedShape::new(CapsuleEllipse::new(0.3, 0.4, 0.5)),
            0.3,
            false,
        ),
        ("custom", SharedShape::new(custom_ellipse()), 0.2, false),
    ];
    for (name, shape, inner, rests) in shapes {
        let mut world = PhysicsWorld::default();
        world.insert(RigidBodyBuilder::fixed(), ColliderBuilder::cuboid(50.0, 0.5));
        let (body, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, 3.0))
                .rotation(0.7)
                .angvel(2.0),
            ColliderBuilder::new(shape),
        );
        let energy = |w: &PhysicsWorld| {
            let rb = &w.bodies[body];
            let m = rb.mass();
            let i = rb.mass_properties().local_mprops.principal_inertia();
            m * 9.81 * rb.center_of_mass().y
                + 0.5 * m * rb.linvel().length_squared()
                + 0.5 * i * rb.angvel() * rb.angvel()
        };
        let e0 = energy(&world);
        // Lowest centre over the whole run (impact included) and over the second half.
        let (mut min_all, mut min_late) = (f64::INFINITY, f64::INFINITY);
        for step in 0..1200 {
            world.step();
            let y = world.bodies[body].translation().y;
            min_all = min_all.min(y);
            if step >= 600 {
                min_late = min_late.min(y);
            }
        }
        let rb = &world.bodies[body];
        let y = rb.translation().y;
        assert!(
            min_all.is_finite() && min_all > 0.4,
            "{name}: went through the ground: {min_all}"
        );
        assert!(min_late > 0.5 + inner - 0.01, "{name}: sank to y = {min_late}");
        assert!(y < 2.0, "{name}: flew to y = {y}");
        assert!(energy(&world) < e0, "{name}: gained energy");
        if rests {
            assert!(
                rb.linvel().length() < 0.05 && rb.angvel().abs() < 0.1,
                "{name}: still moving {} {}",
                rb.linvel(),
                rb.angvel()
            );
        }
    }
}
