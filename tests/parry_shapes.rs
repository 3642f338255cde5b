//! The crate's shapes as parry shapes: bounding volumes, mass properties, ray casts, point
//! projection, support maps, polygonal features, and parry's default dispatcher on them.
//! References are independent: dense boundary sampling (chord polygons), closed forms, and
//! parry's own shapes.

mod common;
#[path = "parry_shapes/features_and_dispatch.rs"]
mod features_and_dispatch;
#[path = "parry_shapes/mass.rs"]
mod mass;
#[path = "parry_shapes/rays_and_points.rs"]
mod rays_and_points;

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
