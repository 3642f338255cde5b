//! The contact query against the crate's two other exact distances (the stationary distance
//! where a side is strictly convex, the gap tracker's where none is), shallow and deep.

use super::*;
use crate::curve::ConvexCurve;
use crate::query::gap::{gap_distance, CurveSide, PolySide, Side};
use crate::query::stationary::{stationary_distance, DistanceOptions};
use crate::{BallCurve, CapsuleEllipse, Ellipse, RoundedPolygon};
use core::f64::consts::TAU;

use crate::numerics::test_rng::Lcg as Rng;

enum Shape {
    Ellipse(Ellipse),
    Poly(RoundedPolygon),
    Ball(BallCurve),
    Capsule(CapsuleEllipse),
}

impl Shape {
    fn random(rng: &mut Rng, kind: usize) -> Self {
        match kind {
            0 => {
                let a = rng.range(0.2, 1.0);
                let b = a * if rng.next() < 0.3 {
                    rng.range(0.01, 0.05)
                } else {
                    rng.range(0.2, 1.0)
                };
                Shape::Ellipse(Ellipse::new(a, b))
            }
            1 => {
                let n = 3 + (rng.next() * 6.0) as usize;
                let mut v = Vec::new();
                for i in 0..n {
                    let ang = TAU * (i as f64 + rng.range(0.0, 0.6)) / n as f64;
                    let rad = rng.range(0.4, 1.0);
                    v.push(Vector::new(rad * ang.cos(), rad * ang.sin()));
                }
                let r = if rng.next() < 0.3 { 0.0 } else { rng.range(0.01, 0.2) };
                Shape::Poly(RoundedPolygon::try_new(&v, r).unwrap_or_else(|_| RoundedPolygon::regular(n, 0.7, r)))
            }
            2 => Shape::Ball(BallCurve {
                radius: rng.range(0.1, 0.8),
            }),
            _ => Shape::Capsule(CapsuleEllipse::new(
                rng.range(0.1, 0.5),
                rng.range(0.1, 0.5),
                rng.range(0.1, 0.8),
            )),
        }
    }
    fn support(&self) -> SupportShape<'_> {
        match self {
            Shape::Ellipse(e) => SupportShape::Ellipse(e.half_x(), e.half_y()),
            Shape::Poly(p) => SupportShape::Polygon {
                vertices: p.vertices(),
                normals: p.edge_normals(),
                radius: p.corner_radius(),
            },
            Shape::Ball(b) => SupportShape::Disc(b.radius),
            Shape::Capsule(c) => {
                let (r1, r2, r3) = c.params();
                SupportShape::CapsuleEllipse(r1, r2, r3)
            }
        }
    }
    fn curve(&self) -> &dyn ConvexCurve {
        match self {
            Shape::Ellipse(e) => e,
            Shape::Poly(p) => p,
            Shape::Ball(b) => b,
            Shape::Capsule(c) => c,
        }
    }
    fn side(&self) -> Option<Side<'_>> {
        match self {
            Shape::Poly(p) => PolySide::new(p.vertices(), p.edge_normals(), p.corner_radius()).map(Side::Poly),
            Shape::Capsule(c) => Some(Side::Curve(CurveSide {
                curve: c,
                faces: c.flats(),
            })),
            _ => None,
        }
    }
}

/// The signed distance by the crate's other exact queries.
fn reference(s1: &Shape, s2: &Shape, pos12: &Pose) -> Option<f64> {
    let opts = DistanceOptions::default();
    if s2.curve().is_strictly_convex() {
        stationary_distance(s1.curve(), s2.curve(), pos12, &opts)
            .ok()
            .map(|d| d.distance)
    } else if s1.curve().is_strictly_convex() {
        stationary_distance(s2.curve(), s1.curve(), &pos12.inverse(), &opts)
            .ok()
            .map(|d| d.distance)
    } else {
        gap_distance(s1.side()?, s2.side()?, pos12).map(|g| g.0)
    }
}

/// Random pairs at random overlaps and separations: the distance agrees with the reference,
/// the witnesses are support points of their bodies, and the points' distances are along the
/// normal.
#[test]
fn contact_matches_the_exact_distances_shallow_and_deep() {
    let mut rng = Rng(7);
    let mut cases = 0;
    let pairs = [
        (1, 0),
        (0, 1),
        (1, 1),
        (1, 2),
        (2, 1),
        (3, 1),
        (1, 3),
        (0, 2),
        (2, 2),
        (3, 2),
        (0, 0),
        (3, 0),
        (0, 3),
        (3, 3),
    ];
    for &(k1, k2) in &pairs {
        for _ in 0..600 {
            let s1 = Shape::random(&mut rng, k1);
            let s2 = Shape::random(&mut rng, k2);
            let size = s1.curve().bounding_radius().max(s2.curve().bounding_radius());
            let dir = rng.range(0.0, TAU);
            let reach = s1.curve().bounding_radius() + s2.curve().bounding_radius();
            let dist = reach * rng.range(0.0, 1.1);
            let pos12 = Pose::new(Vector::new(dist * dir.cos(), dist * dir.sin()), rng.range(-3.2, 3.2));
            let c = contact(s1.support(), s2.support(), &pos12, 0.02f64.cos(), None).expect("a contact");
            let r = reference(&s1, &s2, &pos12).expect("a reference");
            assert!(
                (c.dist - r).abs() <= 1e-12 * size,
                "pair {k1}-{k2} pose {pos12:?}: ours {} reference {r}",
                c.dist
            );
            let n = c.normal;
            assert!((n.length() - 1.0).abs() < 1e-14);
            let p = c.points[0];
            assert_eq!(
                p.dist,
                c.points[..c.len].iter().map(|p| p.dist).fold(f64::INFINITY, f64::min)
            );
            assert!((p.dist - c.dist).abs() <= 1e-13 * size);
            for q in &c.points[..c.len] {
                assert!(((q.point2 - q.point1).dot(n) - q.dist).abs() <= 1e-12 * size);
                assert!((q.point2 - q.point1 - n * q.dist).length() <= 1e-9 * size);
            }
            // The witnesses are on the boundaries: support points along ±n.
            let h1 = s1.curve().support_point(n).dot(n);
            assert!((p.point1.dot(n) - h1).abs() <= 1e-12 * size, "{k1}-{k2}");
            let n2 = pos12.inverse_transform_vector(-n);
            let h2 = s2.curve().support_point(n2).dot(n2);
            assert!(((pos12.inverse_transform_point(p.point2)).dot(n2) - h2).abs() <= 1e-12 * size);
            cases += 1;
        }
    }
    println!("contact_matches_the_exact_distances_shallow_and_deep: {cases} cases");
}

/// A rounded box resting flat on a box: two points at the ends of the shorter face, with the
/// exact depth and distinct ids; tilted beyond the flat angle, one point.
#[test]
fn flat_on_flat_gives_two_points_with_distinct_ids() {
    let plank = RoundedPolygon::new(
        &[
            Vector::new(-2.0, -0.5),
            Vector::new(2.0, -0.5),
            Vector::new(2.0, 0.5),
            Vector::new(-2.0, 0.5),
        ],
        0.0,
    );
    let boxy = RoundedPolygon::new(
        &[
            Vector::new(-0.4, -0.2),
            Vector::new(0.4, -0.2),
            Vector::new(0.4, 0.2),
            Vector::new(-0.4, 0.2),
        ],
        0.05,
    );
    let s1 = SupportShape::Polygon {
        vertices: plank.vertices(),
        normals: plank.edge_normals(),
        radius: 0.0,
    };
    let s2 = SupportShape::Polygon {
        vertices: boxy.vertices(),
        normals: boxy.edge_normals(),
        radius: 0.05,
    };
    let pos12 = Pose::new(Vector::new(0.3, 0.5 + 0.25 - 0.01), 0.001);
    let c = contact(s1, s2, &pos12, 0.02f64.cos(), None).unwrap();
    assert_eq!(c.len, 2);
    assert!((c.normal - Vector::Y).length() < 1e-15);
    assert_ne!(c.points[0].feature2, c.points[1].feature2);
    assert_eq!(c.points[0].feature1, Feature::Face(2));
    let deepest = -0.01 - 0.4 * 0.001f64.sin() + 0.2 * (1.0 - 0.001f64.cos());
    assert!((c.dist - deepest).abs() < 1e-12, "{} {deepest}", c.dist);
    let tilted = Pose::new(pos12.translation, 0.1);
    assert_eq!(contact(s1, s2, &tilted, 0.02f64.cos(), None).unwrap().len, 1);
}

/// A parry polygon with a vertex on a straight edge (two equal consecutive normals, kept by
/// `from_convex_polyline_unmodified`) is refused by the query (its merge needs strictly turning
/// normals), and the dispatcher's answer stays exact: here the shapes overlap.
#[test]
fn a_vertex_on_a_straight_edge_is_refused_and_the_contact_stays_exact() {
    use crate::SmoothDispatcher;
    use parry2d_f64::query::QueryDispatcher;
    use parry2d_f64::shape::ConvexPolygon;
    let pts = [
        Vector::new(1.0, 0.0),
        Vector::new(2.0, 0.0),
        Vector::new(2.0, 1.0),
        Vector::new(0.0, 1.0),
        Vector::new(0.0, 0.0),
    ];
    let poly = ConvexPolygon::from_convex_polyline_unmodified(pts.to_vec()).expect("a polygon");
    let diamond = RoundedPolygon::new(
        &[
            Vector::new(0.5, 0.0),
            Vector::new(0.0, 0.5),
            Vector::new(-0.5, 0.0),
            Vector::new(0.0, -0.5),
        ],
        0.0,
    );
    let shape = SupportShape::Polygon {
        vertices: poly.points(),
        normals: poly.normals(),
        radius: 0.0,
    };
    let d = SupportShape::Polygon {
        vertices: diamond.vertices(),
        normals: diamond.edge_normals(),
        radius: 0.0,
    };
    let pos12 = Pose::new(Vector::new(-0.2, -0.2), 0.0);
    assert!(contact(shape, d, &pos12, 0.9998, None).is_none());
    let c = SmoothDispatcher::default()
        .contact(&pos12, &poly, &diamond, 10.0)
        .unwrap()
        .expect("a contact");
    // The gap tracker's exact distance on the same polygon without the extra vertex.
    let square = RoundedPolygon::new(&pts[1..], 0.0);
    let reference = gap_distance(
        PolySide::new(square.vertices(), square.edge_normals(), 0.0)
            .map(Side::Poly)
            .unwrap(),
        PolySide::new(diamond.vertices(), diamond.edge_normals(), 0.0)
            .map(Side::Poly)
            .unwrap(),
        &pos12,
    )
    .unwrap()
    .0;
    assert!((c.dist - reference).abs() < 1e-12, "{} {reference}", c.dist);
    assert!(c.dist < 0.0);
}

/// A segment against a disc beyond its end, and two collinear capsules: the arcs are exactly π
/// wide, where overlapping cores along every breakpoint do not mean overlapping cores.
#[test]
fn segments_and_discs_in_line_are_apart() {
    let seg = [Vector::new(-1.0, 0.0), Vector::new(1.0, 0.0)];
    let normals = [Vector::new(0.0, -1.0), Vector::new(0.0, 1.0)];
    let segment = |radius| SupportShape::Polygon {
        vertices: &seg,
        normals: &normals,
        radius,
    };
    let pos12 = Pose::new(Vector::new(5.0, 0.0), 0.0);
    let c = contact(segment(0.0), SupportShape::Disc(0.5), &pos12, 0.9998, None).unwrap();
    assert!((c.dist - 3.5).abs() < 1e-14, "{}", c.dist);
    let c = contact(segment(0.2), segment(0.2), &pos12, 0.9998, None).unwrap();
    assert!((c.dist - 2.6).abs() < 1e-14, "{}", c.dist);
}
