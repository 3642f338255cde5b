//! The point of a polygon dilated by a radius, or of a disc, nearest to a given point: the
//! certificate's projection (`certificate` in the module above), exact at every scale.
//!
//! For a convex polygon with vertices vₖ (counter-clockwise) and outward edge normals nₖ, a
//! point p with nₖ·(p − vₖ) ≤ 0 for every edge is inside the polygon (three edges or more); a
//! point outside is nearest to the segment [vₖ, vₖ₊₁] of some edge it is outside of
//! (nₖ·(p − vₖ) > 0), so the least distance to those edges' segments is the distance to the
//! polygon. Dilating by r moves the nearest point r along the direction to p, and takes in
//! every point within r. parry's projection onto a support map (GJK) works to absolute
//! tolerances, which at shapes of 10⁻⁴⁵ m take every point for inside: this one compares only
//! distances of the shapes' own scale.

use crate::numerics::math::{Real, Vector};
use crate::query::contact::SupportShape;

/// The point of `s` (in its frame) nearest to `p` and whether `p` is inside `s` (then the
/// point is `p` itself); `None` for a shape other than a polygon or a disc, or a value that is
/// not finite.
pub(super) fn project_on(s: SupportShape, p: Vector) -> Option<(Vector, bool)> {
    let (core, r) = match s {
        SupportShape::Polygon {
            vertices,
            normals,
            radius,
        } => (nearest_on_polygon(vertices, normals, p)?, radius),
        SupportShape::Disc(r) => (Some(Vector::ZERO), r),
        _ => return None,
    };
    let Some(q) = core else {
        // Inside the core.
        return Some((p, true));
    };
    let d = (p - q).length();
    if !(d.is_finite() && r.is_finite()) {
        return None;
    }
    if d <= r {
        return Some((p, true));
    }
    Some((q + (p - q) * (r / d), false))
}

/// The point of the polygon's boundary nearest to `p`, `Some(None)` when `p` is inside it (three
/// vertices or more; a segment has no inside); `None` when the normals do not match the
/// vertices or a value is not finite.
fn nearest_on_polygon(vertices: &[Vector], normals: &[Vector], p: Vector) -> Option<Option<Vector>> {
    let n = vertices.len();
    if n == 0 || normals.len() != n || !p.is_finite() {
        return None;
    }
    if n == 1 {
        return Some(Some(vertices[0]));
    }
    let mut best: Option<(Real, Vector)> = None;
    let mut outside = false;
    for k in 0..n {
        let (a, b) = (vertices[k], vertices[if k + 1 == n { 0 } else { k + 1 }]);
        let side = normals[k].dot(p - a);
        if side.is_nan() {
            return None;
        }
        if side <= 0.0 && n >= 3 {
            continue;
        }
        outside = true;
        let e = b - a;
        let ee = e.dot(e);
        let t = if ee > 0.0 {
            ((p - a).dot(e) / ee).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let q = a + e * t;
        let d = (p - q).length();
        if best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, q));
        }
    }
    if !outside {
        return Some(None);
    }
    let (d, q) = best?;
    (d.is_finite() && q.is_finite()).then_some(Some(q))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn polygon<'a>(vertices: &'a [Vector], normals: &'a [Vector], radius: Real) -> SupportShape<'a> {
        SupportShape::Polygon {
            vertices,
            normals,
            radius,
        }
    }

    fn unit_square() -> (Vec<Vector>, Vec<Vector>) {
        (
            vec![
                Vector::new(-1.0, -1.0),
                Vector::new(1.0, -1.0),
                Vector::new(1.0, 1.0),
                Vector::new(-1.0, 1.0),
            ],
            vec![-Vector::Y, Vector::X, Vector::Y, -Vector::X],
        )
    }

    #[test]
    fn a_point_beside_a_face_or_a_corner_projects_onto_the_nearest_boundary_point() {
        let (v, n) = unit_square();
        let s = polygon(&v, &n, 0.5);
        assert_eq!(
            project_on(s, Vector::new(3.0, 0.25)),
            Some((Vector::new(1.5, 0.25), false))
        );
        let (q, inside) = project_on(s, Vector::new(4.0, 5.0)).unwrap();
        assert!(!inside);
        assert!((q - Vector::new(1.3, 1.4)).length() < 1e-15, "{q}");
        assert_eq!(
            project_on(s, Vector::new(0.2, 0.3)),
            Some((Vector::new(0.2, 0.3), true))
        );
        // Within the radius of the core: inside the dilated square.
        assert_eq!(
            project_on(s, Vector::new(1.2, 1.2)),
            Some((Vector::new(1.2, 1.2), true))
        );
    }

    #[test]
    fn the_projection_keeps_its_answer_at_every_scale() {
        let (v, n) = unit_square();
        for scale in [1e-45, 1e-20, 1.0, 1e20, 1e45] {
            let vs: Vec<Vector> = v.iter().map(|x| *x * scale).collect();
            let s = polygon(&vs, &n, 0.0);
            let (q, inside) = project_on(s, Vector::new(3.0, 0.25) * scale).unwrap();
            assert!(!inside, "scale {scale}");
            assert!(
                (q / scale - Vector::new(1.0, 0.25)).length() < 1e-15,
                "scale {scale}: {q}"
            );
            let (_, inside) = project_on(s, Vector::new(0.9, -0.9) * scale).unwrap();
            assert!(inside, "scale {scale}");
        }
    }

    #[test]
    fn a_segment_has_no_inside_and_a_disc_its_radius() {
        let v = [Vector::new(-1.0, 0.0), Vector::new(1.0, 0.0)];
        let n = [-Vector::Y, Vector::Y];
        let seg = polygon(&v, &n, 0.0);
        assert_eq!(
            project_on(seg, Vector::new(3.0, 0.0)),
            Some((Vector::new(1.0, 0.0), false))
        );
        assert_eq!(
            project_on(seg, Vector::new(0.5, 0.0)),
            Some((Vector::new(0.5, 0.0), true))
        );
        let disc = SupportShape::Disc(2.0);
        assert_eq!(
            project_on(disc, Vector::new(0.0, 4.0)),
            Some((Vector::new(0.0, 2.0), false))
        );
        assert_eq!(
            project_on(disc, Vector::new(0.0, 1.0)),
            Some((Vector::new(0.0, 1.0), true))
        );
        assert_eq!(project_on(SupportShape::Ellipse(1.0, 2.0), Vector::X), None);
        assert_eq!(project_on(disc, Vector::new(Real::NAN, 0.0)), None);
    }
}
