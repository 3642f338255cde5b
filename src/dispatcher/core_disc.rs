//! A shape's *core*: the largest disc about its centroid that lies inside it (centre and
//! radius, the inradius about the centroid), as the dispatcher's rapier rules use it.
//!
//! The core moves with the body's centre of mass and does not change when the body turns about
//! it, so what happens to it is what the body's translation does, whatever its spin:
//!
//! * rapier's CCD ([`super::rapier_rule`]) keeps a smaller disc about the body's rotation centre
//!   off every target — the centre of a body never reaches a wall, so it cannot pass it;
//! * the contact manifold ([`super::manifold`]) adds a *core contact*: a speculative point of
//!   the core facing the other shape along the contact normal, which rapier's solver takes only
//!   when the body's centre would close it within the step. A body whose one contact point a
//!   spin carries away from a wall while its centre moves into the wall is then stopped by the
//!   solver, where a one-point manifold would leave the approach to the CCD alone.
//!
//! Each radius is exact for the shapes the contact query reads (polygons, discs, ellipses and
//! `CapsuleEllipse`s): the inradius about the centroid in closed form.

use crate::query::contact::{Contact, SupportShape};
use parry2d_f64::math::{Pose, Vector};

/// The core contact's disc, as a fraction of the core's radius (the inradius about the
/// centroid). Larger than rapier's CCD core ([`super::rapier_rule::CastPolicy::CORE`]): the
/// solver stops a centre heading for a wall before the CCD would have to.
pub(crate) const CORE_CONTACT_FRACTION: f64 = 0.5;

/// The core contact of a pair whose exact contact is `c` (body 1 at the origin, body 2 at
/// `pos12`): the point of the incident body's core disc ([`CORE_CONTACT_FRACTION`] of its core)
/// facing the reference face along the contact normal, and the point of the face's line under
/// it, with the gap between them, in body 1's frame. Only for a contact at a face (the face's
/// body is the wall the core must not cross; a corner or a curve on both sides has no such
/// line), and only when the core's point lies over the face (its tangential position within
/// the face's extent, a segment or an edge), where the face's line is the face; `None`
/// otherwise.
pub(crate) fn core_contact(s1: SupportShape, s2: SupportShape, pos12: &Pose, c: &Contact) -> Option<CoreContact> {
    let reference = c.reference?;
    let n = c.normal;
    let w = &c.points[0];
    let (core, centre) = if reference == 0 {
        let k = core_of(s2)?;
        (k, pos12 * k.centre)
    } else {
        let k = core_of(s1)?;
        (k, k.centre)
    };
    if !(core.radius > 0.0) {
        return None;
    }
    let r = CORE_CONTACT_FRACTION * core.radius;
    let (point1, point2, gap) = if reference == 0 {
        // Body 2's core towards body 1's face (n points from body 1 to body 2).
        let q = centre - n * r;
        let gap = (q - w.point1).dot(n);
        (q - n * gap, q, gap)
    } else {
        let q = centre + n * r;
        let gap = (w.point2 - q).dot(n);
        (q, q + n * gap, gap)
    };
    let on_face = if reference == 0 { point1 } else { point2 };
    let ok = over_face(if reference == 0 { s1 } else { s2 }, reference, pos12, c, on_face);
    (ok && point1.is_finite() && point2.is_finite() && gap.is_finite()).then_some(CoreContact {
        point1,
        point2,
        dist: gap,
        centre,
    })
}

/// Whether `p` (body 1's frame), on the line of the reference face of `c`, lies within that
/// face: between the ends of the face's edge of the polygon `s` (body `body`, at the origin or
/// at `pos12`), dilated by its radius along the normal. The face is the edge whose outward
/// normal is the contact normal (n for body 1, −n for body 2).
fn over_face(s: SupportShape, body: usize, pos12: &Pose, c: &Contact, p: Vector) -> bool {
    let SupportShape::Polygon { vertices, normals, .. } = s else {
        // A CapsuleEllipse's segment is its one face: x = r1, |y| ≤ r2.
        if let SupportShape::CapsuleEllipse(_, r2, _) = s {
            let local = if body == 0 { p } else { pos12.inverse_transform_point(p) };
            return local.y.abs() <= r2;
        }
        return false;
    };
    let n_out = if body == 0 {
        c.normal
    } else {
        pos12.inverse_transform_vector(-c.normal)
    };
    let local = if body == 0 { p } else { pos12.inverse_transform_point(p) };
    let k = (0..normals.len())
        .max_by(|&i, &j| normals[i].dot(n_out).total_cmp(&normals[j].dot(n_out)))
        .unwrap_or(0);
    let (a, b) = (vertices[k], vertices[(k + 1) % vertices.len()]);
    let t = b - a;
    let u = (local - a).dot(t) / t.length_squared();
    (0.0..=1.0).contains(&u)
}

/// A core contact ([`core_contact`]): its points on bodies 1 and 2 in body 1's frame, its gap
/// along the contact normal and the core's centre (body 1's frame).
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct CoreContact {
    pub point1: Vector,
    pub point2: Vector,
    pub dist: f64,
    pub centre: Vector,
}

impl CoreContact {
    /// Whether the two points `p` (of the core's body, body 1's frame) lie on either side of the
    /// core's centre along the tangent of the normal `n`: the centre's motion then shows in
    /// their own, and a two-point manifold keeps them both.
    pub(crate) fn straddled_by(&self, n: Vector, p: [Vector; 2]) -> bool {
        let t = Vector::new(-n.y, n.x);
        (p[0] - self.centre).dot(t) * (p[1] - self.centre).dot(t) <= 0.0
    }
}

/// A disc inside a shape: its centre (the shape's centroid) and radius (the distance from the
/// centroid to the boundary).
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct Core {
    pub centre: Vector,
    pub radius: f64,
}

impl Core {
    /// The radius of a disc about `c` that lies inside the shape: the core's radius less the
    /// distance from its centre (0 when `c` is not inside the core).
    pub(crate) fn radius_about(&self, c: Vector) -> f64 {
        (self.radius - (c - self.centre).length()).max(0.0)
    }
}

/// The core of a shape the contact query reads; `None` for a degenerate polygon (no area).
pub(crate) fn core_of(s: SupportShape) -> Option<Core> {
    let core = match s {
        SupportShape::Disc(r) => Core {
            centre: Vector::ZERO,
            radius: r,
        },
        SupportShape::Ellipse(a, b) => Core {
            centre: Vector::ZERO,
            radius: a.min(b),
        },
        SupportShape::Polygon {
            vertices,
            normals,
            radius,
        } => polygon_core(vertices, normals, radius)?,
        SupportShape::CapsuleEllipse(r1, r2, r3) => capsule_ellipse_core(r1, r2, r3),
    };
    (core.centre.is_finite() && core.radius.is_finite() && core.radius >= 0.0).then_some(core)
}

/// The core of a convex polygon (counter-clockwise, its edge normals) dilated by `r`: the
/// centroid of the dilated region — the core polygon, a rectangle r wide on each edge, a
/// circular sector at each corner — and its distance to the nearest edge line plus r. A segment
/// (two vertices) has no area of its own: its core is its midpoint with radius r.
fn polygon_core(v: &[Vector], normals: &[Vector], r: f64) -> Option<Core> {
    let n = v.len();
    if n < 2 || normals.len() != n {
        return None;
    }
    // Moments about the vertex mean (less cancellation), without allocating.
    let c0 = v.iter().copied().sum::<Vector>() / n as f64;
    let (mut area, mut m) = (0.0, Vector::ZERO);
    // The signed area and first moment of the triangle (c0, p, q), c0 at the origin.
    let fan = |p: Vector, q: Vector| {
        let c = p.perp_dot(q);
        (0.5 * c, (p + q) * (c / 6.0))
    };
    for i in 0..n {
        let (a, mm) = fan(v[i] - c0, v[(i + 1) % n] - c0);
        area += a;
        m += mm;
    }
    if r > 0.0 {
        for i in 0..n {
            let (p, q, e) = (v[i] - c0, v[(i + 1) % n] - c0, normals[i]);
            // The rectangle on edge i (as a fan about c0: its signed pieces sum to it).
            let (pe, qe) = (p + e * r, q + e * r);
            for (a, b) in [(p, pe), (pe, qe), (qe, q), (q, p)] {
                let (da, dm) = fan(a, b);
                area += da;
                m += dm;
            }
            // The sector at vertex i, from the previous edge's normal to this one's.
            let u0 = normals[(i + n - 1) % n];
            let alpha = u0.perp_dot(e).atan2(u0.dot(e)).rem_euclid(core::f64::consts::TAU);
            let sector = 0.5 * alpha * r * r;
            area += sector;
            m += Vector::new(e.y - u0.y, u0.x - e.x) * (r * r * r / 3.0) + p * sector;
        }
    }
    let centre = if area > 0.0 {
        c0 + m / area
    } else if n == 2 || r > 0.0 {
        c0
    } else {
        return None;
    };
    let radius = (0..n)
        .map(|i| normals[i].dot(v[i] - centre))
        .fold(f64::INFINITY, f64::min)
        + r;
    Some(Core {
        centre,
        radius: radius.max(0.0),
    })
}

/// The core of the `CapsuleEllipse` (r1, r2, r3): its centroid (cx, 0) on the axis of symmetry,
/// from its closed-form moments, and the distance from there to each piece of the boundary —
/// the segment x = r1 (r1 − cx); the two arcs, whose nearest points are their ends (the squared
/// distance to a point of an arc, as a function of the arc's angle, is a cosine with its maximum
/// inside the arc); the half ellipse x ≤ 0, semi-axes r3 and B = r1 + r2, where the squared
/// distance is the quadratic (r3² − B²)c² − 2r3·cx·c + cx² + B² of c = cos φ ∈ [−1, 0].
fn capsule_ellipse_core(r1: f64, r2: f64, r3: f64) -> Core {
    let m = crate::parry_shape::capsule_ellipse_moments(r1, r2, r3);
    let cx = m[1] / m[0];
    let b = r1 + r2;
    let segment = r1 - cx;
    let arcs = ((r1 - cx).powi(2) + r2 * r2).sqrt().min((cx * cx + b * b).sqrt());
    let quad = |c: f64| (r3 * r3 - b * b) * c * c - 2.0 * r3 * cx * c + cx * cx + b * b;
    let mut best = quad(-1.0).min(quad(0.0));
    let k = r3 * r3 - b * b;
    if k > 0.0 {
        let c = (r3 * cx / k).clamp(-1.0, 0.0);
        best = best.min(quad(c));
    }
    let ellipse = best.max(0.0).sqrt();
    Core {
        centre: Vector::new(cx, 0.0),
        radius: segment.min(arcs).min(ellipse).max(0.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dispatcher::support_shape::{support_shape, SupportScratch};
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};
        use parry2d_f64::shape::{Ball, Cuboid, Segment, Shape};

    /// The centroid of parry's mass properties and, the reference's radius, the smallest
    /// support value about it over 200,000 directions (the distance from an inner point to the
    /// boundary of a convex shape is the minimum of its support function about the point).
    fn reference(s: &dyn Shape) -> Core {
        let centre = s.mass_properties(1.0).local_com;
        assert!(s.contains_local_point(centre));
        let sm = s.as_support_map().unwrap();
        let radius = (0..200_000)
            .map(|k| {
                let a = core::f64::consts::TAU * k as f64 / 200_000.0;
                let u = Vector::new(a.cos(), a.sin());
                (sm.local_support_point(u) - centre).dot(u)
            })
            .fold(f64::INFINITY, f64::min);
        Core { centre, radius }
    }

    #[test]
    fn cores_are_the_centroid_and_its_distance_to_the_boundary() {
        let shapes: Vec<Box<dyn Shape>> = vec![
            Box::new(Ellipse::new(0.5, 0.2)),
            Box::new(Ellipse::new(0.3, 0.3)),
            Box::new(RoundedPolygon::regular(7, 0.4, 0.06)),
            Box::new(RoundedPolygon::regular(4, 0.35, 0.0)),
            Box::new(RoundedPolygon::new(
                &[Vector::new(-0.5, 0.0), Vector::new(-0.25, 0.0), Vector::new(0.5, 0.125)],
                0.0,
            )),
            Box::new(RoundedPolygon::new(
                &[Vector::new(0.3, -0.2), Vector::new(2.1, 0.1), Vector::new(1.2, 1.4)],
                0.2,
            )),
            Box::new(CapsuleEllipse::new(0.12, 0.15, 0.3)),
            Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8)),
            Box::new(CapsuleEllipse::new(0.3, 0.05, 2.0)),
            Box::new(Ball::new(0.7)),
            Box::new(Cuboid::new(Vector::new(0.6, 0.25))),
        ];
        for s in &shapes {
            let mut scratch = SupportScratch::default();
            let ours = core_of(support_shape(&**s, &mut scratch).unwrap()).unwrap();
            let want = reference(&**s);
            let size = s.compute_local_bounding_sphere().radius;
            assert!(
                (ours.centre - want.centre).length() <= 1e-12 * size,
                "{:?}: centre {:?} vs {:?}",
                s.shape_type(),
                ours.centre,
                want.centre
            );
            // Sampling overestimates the minimum by at most the support function's slope
            // (≤ the size) times half the spacing of the directions.
            let sampling = core::f64::consts::PI / 200_000.0 * 2.0 * size;
            assert!(
                ours.radius <= want.radius + 1e-12 * size && want.radius - ours.radius <= sampling,
                "{:?}: radius {} vs {}",
                s.shape_type(),
                ours.radius,
                want.radius
            );
        }
        // A segment has no inside: its core is its midpoint with radius 0.
        let mut scratch = SupportScratch::default();
        let seg = Segment::new(Vector::new(-1.0, 2.0), Vector::new(3.0, 2.0));
        let core = core_of(support_shape(&seg, &mut scratch).unwrap()).unwrap();
        assert_eq!(core.centre, Vector::new(1.0, 2.0));
        assert_eq!(core.radius, 0.0);
    }
}
