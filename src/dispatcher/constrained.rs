//! A contact whose normal a composite part's pseudo-normals moved, re-derived along the new
//! normal.
//!
//! An oriented polyline, and a compound whose internal edges are fixed, hand each of their parts
//! (a segment, a box) to the dispatcher with *normal constraints*: the cone of normals the part
//! may push along at each of its features (parry's pseudo-normals; in 2D, parry computes none for
//! heightfields and meshes). Where the pair's exact normal leaves the cone —
//! a body near an inner vertex of a flat chain, whose nearest point to the segment beyond that
//! vertex is the vertex itself — the constraint turns the normal back into the cone, and the
//! contact must follow: with n the corrected normal (from the part towards the body),
//!
//! * the body's witness is its support point facing the part along n (its point furthest
//!   towards the part), and
//! * the part's witness is where the line through it along n meets the part; where the line
//!   misses the part, the part does not hold the body along n and the contact is discarded.
//!
//! This is what parry does for a ball (`contact_manifold_convex_ball`: a ray from the ball's
//! centre along the corrected normal). Keeping the old witnesses instead — the vertex, and the
//! body's point nearest to it — leaves a second support point under a body that rests on the
//! neighbouring segment: a speculative point a fraction of a millimetre below the body, off its
//! centre, which rapier's solver loads once the body settles into its first contact (rapier's
//! allowed penetration), so the body starts to roll or rock on a flat floor.

use crate::curve::ConvexCurve;
use crate::numerics::math::{Pose, Real, Vector};
use parry2d_f64::query::Ray;
use parry2d_f64::shape::Shape;

/// What [`along_corrected_normal`] makes of a contact.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(super) enum Corrected {
    /// The witnesses (each in its shape's frame) and the separation along the corrected normal.
    Contact { point1: Vector, point2: Vector, dist: Real },
    /// The line along the corrected normal misses the part: no contact.
    Discarded,
}

/// The contact of a strictly convex `body` with a `part` along the corrected normal (module
/// docs): `n_part` the normal in the part's frame pointing from the part towards the body,
/// `n_body` the same normal in the body's frame pointing from the body towards the part, and
/// `part_to_body` the body's pose in the part's frame. `None` when a value is not finite.
fn on_part(
    part: &dyn Shape,
    body: &dyn ConvexCurve,
    part_to_body: &Pose,
    n_part: Vector,
    n_body: Vector,
) -> Option<(Vector, Vector, Real, bool)> {
    let on_body = body.support_point(n_body);
    let o = part_to_body.transform_point(on_body);
    // A ray along −n from beyond everything of the part along n: its first hit is where the
    // line through `o` along n enters the part.
    let sphere = part.compute_local_bounding_sphere();
    let lift = ((sphere.center - o).dot(n_part) + sphere.radius).max(0.0) + sphere.radius;
    let ray = Ray::new(o + n_part * lift, -n_part);
    if !(lift.is_finite() && o.is_finite() && n_part.is_finite()) {
        return None;
    }
    match part.cast_local_ray(&ray, Real::MAX, true) {
        Some(t) => Some((ray.point_at(t), on_body, t - lift, true)),
        None => Some((Vector::ZERO, on_body, 0.0, false)),
    }
}

/// The contact of a pair with normals `n1`, `n2` (each in its shape's frame, n1 from shape 1
/// towards shape 2, n2 the reverse) that normal constraints moved, when exactly one side is
/// strictly convex (`c1`, `c2`: the shapes' curves, the body's being this crate's): re-derived
/// along the corrected normal (module docs). `None` where the rule does not apply (neither or
/// both sides strictly convex, a value not finite): the caller keeps its contact.
pub(super) fn along_corrected_normal(
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    c1: Option<&dyn ConvexCurve>,
    c2: Option<&dyn ConvexCurve>,
    n1: Vector,
    n2: Vector,
) -> Option<Corrected> {
    fn strict(c: Option<&dyn ConvexCurve>) -> Option<&dyn ConvexCurve> {
        c.filter(|c| c.is_strictly_convex())
    }
    let found = match (strict(c1), strict(c2)) {
        (None, Some(body)) => on_part(g1, body, pos12, n1, n2),
        (Some(body), None) => on_part(g2, body, &pos12.inverse(), n2, n1).map(|(p2, p1, d, hit)| (p1, p2, d, hit)),
        _ => None,
    }?;
    let (point1, point2, dist, hit) = found;
    Some(if !hit {
        Corrected::Discarded
    } else if point1.is_finite() && point2.is_finite() && dist.is_finite() {
        Corrected::Contact { point1, point2, dist }
    } else {
        return None;
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ellipse;
    use parry2d_f64::shape::Segment;

    /// An ellipse resting on the segment left of a flat chain's inner vertex (at the origin),
    /// 2 cm from it: for the segment right of the vertex the corrected (vertical) normal's line
    /// through the ellipse's lowest point misses it — no contact; for the segment under the
    /// lowest point it meets it there, at the gap.
    #[test]
    fn a_corrected_normal_whose_line_misses_the_part_discards_the_contact() {
        let ellipse = Ellipse::new(0.5, 0.2);
        let gap = 1e-4;
        let body = Pose::translation(-0.02, 0.2 + gap);
        let up = Vector::new(0.0, 1.0);
        let right = Segment::new(Vector::new(0.0, 0.0), Vector::new(1.0, 0.0));
        let left = Segment::new(Vector::new(-1.0, 0.0), Vector::new(0.0, 0.0));
        let curve = Some(&ellipse as &dyn ConvexCurve);
        assert_eq!(
            along_corrected_normal(&body, &right, &ellipse, None, curve, up, -up),
            Some(Corrected::Discarded)
        );
        let Some(Corrected::Contact { point1, point2, dist }) =
            along_corrected_normal(&body, &left, &ellipse, None, curve, up, -up)
        else {
            panic!("the segment under the body holds it");
        };
        assert!((point1 - Vector::new(-0.02, 0.0)).length() < 1e-12, "{point1:?}");
        assert!((point2 - Vector::new(0.0, -0.2)).length() < 1e-12, "{point2:?}");
        assert!((dist - gap).abs() < 1e-12, "{dist}");
        // The same pair with the body as shape 1: the mirrored answer.
        let Some(Corrected::Contact {
            point1,
            point2,
            dist: d,
        }) = along_corrected_normal(&body.inverse(), &ellipse, &left, curve, None, -up, up)
        else {
            panic!("mirrored");
        };
        assert!((point2 - Vector::new(-0.02, 0.0)).length() < 1e-12, "{point2:?}");
        assert!((point1 - Vector::new(0.0, -0.2)).length() < 1e-12, "{point1:?}");
        assert!((d - gap).abs() < 1e-12, "{d}");
    }

    /// A body sunk into the part: the separation along the corrected normal is negative.
    #[test]
    fn a_body_below_the_part_gets_its_depth_along_the_corrected_normal() {
        let disc = Ellipse::new(0.25, 0.25);
        let body = Pose::translation(0.3, 0.25 - 0.01);
        let up = Vector::new(0.0, 1.0);
        let seg = Segment::new(Vector::new(0.0, 0.0), Vector::new(1.0, 0.0));
        let Some(Corrected::Contact { dist, .. }) =
            along_corrected_normal(&body, &seg, &disc, None, Some(&disc as &dyn ConvexCurve), up, -up)
        else {
            panic!("a contact");
        };
        assert!((dist + 0.01).abs() < 1e-12, "{dist}");
    }

    /// Neither side strictly convex (a polygon's corner on a segment): not this rule's.
    #[test]
    fn pairs_without_one_strictly_convex_side_are_left_to_the_caller() {
        let seg = Segment::new(Vector::new(0.0, 0.0), Vector::new(1.0, 0.0));
        let up = Vector::new(0.0, 1.0);
        assert_eq!(
            along_corrected_normal(&Pose::IDENTITY, &seg, &seg, None, None, up, -up),
            None
        );
    }
}
