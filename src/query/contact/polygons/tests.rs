//! The polygons' contact against the general walk, bit for bit.

use super::super::walk_contact;
use super::*;
use crate::numerics::math::perp;
use crate::numerics::test_rng::Lcg;
use core::f64::consts::{FRAC_PI_4, TAU};
use parry2d_f64::math::Rotation;

/// A shape's data, owned: a polygon's vertices and normals and its radius, or a disc's radius.
struct Owned {
    vertices: Vec<Vector>,
    normals: Vec<Vector>,
    radius: f64,
    disc: bool,
}

impl Owned {
    /// The polygon through these vertices (counter-clockwise), its normals as the dispatcher
    /// computes parry's (edge i's outward unit normal, −perp(e)/|e|).
    fn polygon(vertices: Vec<Vector>, radius: f64) -> Self {
        let n = vertices.len();
        let normals = (0..n)
            .map(|i| {
                let e = vertices[(i + 1) % n] - vertices[i];
                -perp(e) / e.length()
            })
            .collect();
        Owned {
            vertices,
            normals,
            radius,
            disc: false,
        }
    }

    /// As the contact query reads it.
    fn shape(&self) -> SupportShape<'_> {
        if self.disc {
            SupportShape::Disc(self.radius)
        } else {
            SupportShape::Polygon {
                vertices: &self.vertices,
                normals: &self.normals,
                radius: self.radius,
            }
        }
    }
}

/// A length from a few round values (faces that line up exactly, ties) or a random one.
fn length(rng: &mut Lcg, lo: f64, hi: f64) -> f64 {
    if rng.next() < 0.5 {
        [0.25, 0.5, 0.75, 1.0][(rng.next() * 4.0) as usize]
    } else {
        rng.range(lo, hi)
    }
}

/// A random shape of kind 0 (convex polygon, 3 to 8 vertices, slivers among them), 1 (box, as the dispatcher reads
/// parry's), 2 (segment or capsule) or 3 (disc); dilated or not.
fn random_shape(rng: &mut Lcg, kind: usize) -> Owned {
    let radius = if rng.next() < 0.4 { 0.0 } else { length(rng, 0.01, 0.3) };
    match kind {
        0 => {
            // Points in order on an ellipse: a convex polygon, thin ones among them.
            let n = 3 + (rng.next() * 6.0) as usize;
            let (ea, eb) = (rng.range(0.4, 1.0), rng.range(0.05, 1.0));
            let v = (0..n)
                .map(|i| {
                    let ang = TAU * (i as f64 + rng.range(0.0, 0.6)) / n as f64;
                    Vector::new(ea * ang.cos(), eb * ang.sin())
                })
                .collect();
            Owned::polygon(v, radius)
        }
        1 => {
            let (x, y) = (length(rng, 0.1, 1.0), length(rng, 0.1, 1.0));
            Owned {
                vertices: vec![
                    Vector::new(-x, -y),
                    Vector::new(x, -y),
                    Vector::new(x, y),
                    Vector::new(-x, y),
                ],
                normals: vec![-Vector::Y, Vector::X, Vector::Y, -Vector::X],
                radius,
                disc: false,
            }
        }
        2 => {
            let h = length(rng, 0.1, 1.0);
            let a = if rng.next() < 0.5 { 0.0 } else { rng.range(-3.2, 3.2) };
            let d = Vector::new(a.cos(), a.sin()) * h;
            Owned::polygon(vec![-d, d], radius)
        }
        _ => Owned {
            vertices: Vec::new(),
            normals: Vec::new(),
            radius: length(rng, 0.05, 0.8),
            disc: true,
        },
    }
}

/// A random pose of body 2 in body 1's frame: a quarter turn exactly or any angle, at a
/// distance from overlapping to apart, on a grid of quarters or anywhere.
fn random_pose(rng: &mut Lcg) -> Pose {
    let rotation = if rng.next() < 0.5 {
        let (c, s) = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][(rng.next() * 4.0) as usize];
        Rotation::from_cos_sin_unchecked(c, s)
    } else {
        Rotation::new(rng.range(-3.2, 3.2))
    };
    let dir = rng.range(-3.2, 3.2);
    let mut t = Vector::new(dir.cos(), dir.sin()) * rng.range(0.0, 3.0);
    if rng.next() < 0.5 {
        t = (t * 4.0).round() / 4.0;
    }
    Pose::from_parts(t, rotation)
}

/// Every pair of polygons, boxes, segments, capsules and discs (one a polygon at least) gets
/// the general walk's contact bit for bit: signed distance, normal, witnesses, features and the
/// clipped second point, penetrating, touching and apart, faces parallel and corners facing,
/// with and without the manifold's second point.
#[test]
fn the_polygons_contact_is_the_general_walks_to_the_bit() {
    let mut rng = Lcg(29);
    let (mut cases, mut two_points, mut apart, mut penetrating, mut inside) = (0, 0, 0, 0, 0);
    for _ in 0..60_000 {
        let (k1, k2) = ((rng.next() * 4.0) as usize, (rng.next() * 4.0) as usize);
        if k1 == 3 && k2 == 3 {
            continue;
        }
        let (a, b) = (random_shape(&mut rng, k1), random_shape(&mut rng, k2));
        let pose = random_pose(&mut rng);
        let flat_cos = if rng.next() < 0.7 { FRAC_PI_4.cos() } else { 2.0 };
        let fast = contact(a.shape(), b.shape(), &pose, flat_cos).expect("a pair of polygons");
        let general = walk_contact(a.shape(), b.shape(), &pose, flat_cos, None);
        // Debug prints every float's shortest round trip: equal strings are equal bits.
        assert_eq!(
            format!("{fast:?}"),
            format!("{general:?}"),
            "kinds {k1} {k2} pose {pose:?}"
        );
        if let Some(c) = fast {
            cases += 1;
            two_points += usize::from(c.len == 2);
            apart += usize::from(c.dist > 0.0);
            penetrating += usize::from(c.dist < 0.0);
            inside += usize::from(matches!(c.points[0].feature1, Feature::Vertex(_)) && c.len == 1);
        }
    }
    println!(
        "{cases} contacts: {two_points} with two points, {apart} apart, {penetrating} penetrating, {inside} corner"
    );
    assert!(cases > 50_000 && two_points > 5_000 && apart > 10_000 && penetrating > 10_000 && inside > 5_000);
}

/// A polygon whose normals do not turn strictly (a vertex on a straight edge) is refused as
/// the general walk refuses it: no contact, on either side.
#[test]
fn a_polygon_with_a_straight_vertex_has_no_contact_as_in_the_walk() {
    let straight = Owned::polygon(
        vec![
            Vector::new(-1.0, -1.0),
            Vector::new(0.0, -1.0),
            Vector::new(1.0, -1.0),
            Vector::new(0.0, 1.0),
        ],
        0.0,
    );
    let square = random_shape(&mut Lcg(3), 1);
    let pose = Pose::new(Vector::new(3.0, 0.0), 0.2);
    assert_eq!(contact(straight.shape(), square.shape(), &pose, 2.0), Some(None));
    assert_eq!(contact(square.shape(), straight.shape(), &pose, 2.0), Some(None));
    assert_eq!(walk_contact(straight.shape(), square.shape(), &pose, 2.0, None), None);
}

/// Pairs with an ellipse piece, and two discs, are left to the general walk.
#[test]
fn pairs_with_an_ellipse_piece_or_two_discs_are_left_to_the_walk() {
    let square = random_shape(&mut Lcg(3), 1);
    let pose = Pose::new(Vector::new(3.0, 0.0), 0.2);
    let others = [
        SupportShape::Ellipse(1.0, 0.5),
        SupportShape::CapsuleEllipse(0.2, 0.5, 0.3),
    ];
    for other in others {
        assert!(contact(square.shape(), other, &pose, 2.0).is_none());
        assert!(contact(other, square.shape(), &pose, 2.0).is_none());
    }
    assert!(contact(SupportShape::Disc(1.0), SupportShape::Disc(0.5), &pose, 2.0).is_none());
    assert!(contact(SupportShape::Disc(1.0), square.shape(), &pose, 2.0).is_some());
}
