//! A lower bound of the signed distance of two shapes from a few separating-axis tests, cheap
//! enough to run before the exact contact query where a pair is usually far apart (a manifold
//! asked for a pair beyond the prediction distance: rapier's broad phase pairs a fast body with
//! whatever its swept box meets).
//!
//! For convex bodies A₁ (at the origin) and A₂ (at the pose (R, t)), with support functions h₁
//! and h₂ in their own frames, the separation along a unit direction n of body 1's frame,
//!
//!   S(n) = min over y ∈ A₂ of n·(R·y + t) − max over x ∈ A₁ of n·x = n·t − h₂(−Rᵀn) − h₁(n),
//!
//! is at most the signed distance for every n (the separating-axis theorem: the signed distance
//! is the largest of them) and equal to it along the contact normal. So S along the pair's
//! previous contact normal, or along the line of its centres, bounds the distance from below;
//! with an upper bound of h in place of h (a `CapsuleEllipse`) it still does.

use super::side::polygon_is_walkable;
use super::SupportShape;
use crate::numerics::math::{Pose, Real, Vector};

/// h(n), the support function of `s` along the unit `n` of its own frame, or an upper bound of
/// it for a `CapsuleEllipse`: the larger of its capsule's (the segment from (0, −r₂) to (0, r₂)
/// dilated by r₁) and of the whole ellipse with semi-axes r₃ and r₁ + r₂ (the shape lies in
/// their hull).
pub(crate) fn support_bound(s: SupportShape, n: Vector) -> Real {
    match s {
        SupportShape::Polygon { vertices, radius, .. } => {
            vertices.iter().map(|v| v.dot(n)).fold(Real::NEG_INFINITY, Real::max) + radius
        }
        SupportShape::Disc(r) => r,
        SupportShape::Ellipse(a, b) => ((a * n.x).powi(2) + (b * n.y).powi(2)).sqrt(),
        SupportShape::CapsuleEllipse(r1, r2, r3) => {
            let capsule = r1 + r2 * n.y.abs();
            let ellipse = ((r3 * n.x).powi(2) + ((r1 + r2) * n.y).powi(2)).sqrt();
            capsule.max(ellipse)
        }
    }
}

/// S(n) of the module docs: the separation of `s1` (at the origin) and `s2` (at `pos12`) along
/// the unit `n` of body 1's frame, at most their signed distance (NaN for a pose or a direction
/// that is not finite).
pub(crate) fn separation_along(s1: SupportShape, s2: SupportShape, pos12: &Pose, n: Vector) -> Real {
    let n2 = pos12.inverse_transform_vector(-n);
    n.dot(pos12.translation) - support_bound(s2, n2) - support_bound(s1, n)
}

/// Relative rounding allowed to [`apart_beyond`]'s separations and to the exact contact's
/// distance, of the pair's scale.
const SEPARATION_ROUNDING: Real = 1e-9;

/// Whether the separation along one of `axes` (unit directions of body 1's frame; one that is
/// not finite or not of unit length is passed over) exceeds `level` by more than
/// [`SEPARATION_ROUNDING`] of `scale` (at least the distance of body 2's origin from body 1's
/// plus both shapes' reach from their own): the shapes are then further apart than `level`,
/// whatever the rounding of this bound and of the exact contact. False when not shown, on
/// input that is not finite, and for a polygon the exact contact query does not read (more
/// than [`super::MAX_BREAKPOINTS`] vertices, normals that do not turn strictly), which its
/// callers answer another way.
pub(crate) fn apart_beyond(
    s1: SupportShape,
    s2: SupportShape,
    pos12: &Pose,
    axes: &[Vector],
    level: Real,
    scale: Real,
) -> bool {
    let read = |s: SupportShape| match s {
        SupportShape::Polygon { vertices, normals, .. } => polygon_is_walkable(vertices, normals),
        _ => true,
    };
    if !(read(s1) && read(s2)) {
        return false;
    }
    let margin = SEPARATION_ROUNDING * scale;
    axes.iter()
        .filter(|n| n.is_finite() && (n.length_squared() - 1.0).abs() < 1e-9)
        .any(|&n| separation_along(s1, s2, pos12, n) > level + margin)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::contact::contact;

    fn unit_square() -> (Vec<Vector>, Vec<Vector>) {
        let v = vec![
            Vector::new(-1.0, -1.0),
            Vector::new(1.0, -1.0),
            Vector::new(1.0, 1.0),
            Vector::new(-1.0, 1.0),
        ];
        let n = vec![-Vector::Y, Vector::X, Vector::Y, -Vector::X];
        (v, n)
    }

    /// A small deterministic generator (xorshift), uniform in [0, 1).
    fn uniform(state: &mut u64) -> Real {
        *state ^= *state << 13;
        *state ^= *state >> 7;
        *state ^= *state << 17;
        (*state >> 11) as Real / (1u64 << 53) as Real
    }

    #[test]
    fn the_separation_along_any_axis_never_exceeds_the_exact_distance_and_meets_it_at_the_normal() {
        let (sv, sn) = unit_square();
        let seg_v = [Vector::new(-3.0, 0.0), Vector::new(3.0, 0.0)];
        let seg_n = [-Vector::Y, Vector::Y];
        let shapes = [
            SupportShape::Polygon {
                vertices: &sv,
                normals: &sn,
                radius: 0.0,
            },
            SupportShape::Polygon {
                vertices: &sv,
                normals: &sn,
                radius: 0.3,
            },
            SupportShape::Polygon {
                vertices: &seg_v,
                normals: &seg_n,
                radius: 0.0,
            },
            SupportShape::Disc(0.7),
            SupportShape::Ellipse(1.5, 0.2),
            SupportShape::CapsuleEllipse(0.2, 0.5, 0.9),
        ];
        let mut state = 0x9e37_79b9_7f4a_7c15;
        let mut checked = 0;
        for _ in 0..4000 {
            let i = (uniform(&mut state) * shapes.len() as Real) as usize;
            let j = (uniform(&mut state) * shapes.len() as Real) as usize;
            let pos12 = Pose::new(
                Vector::new(8.0 * uniform(&mut state) - 4.0, 8.0 * uniform(&mut state) - 4.0),
                6.3 * uniform(&mut state),
            );
            let Some(c) = contact(shapes[i], shapes[j], &pos12, 2.0, None) else {
                continue;
            };
            let scale = 1.0 + pos12.translation.length();
            for _ in 0..4 {
                let a = 6.3 * uniform(&mut state);
                let n = Vector::new(a.cos(), a.sin());
                let s = separation_along(shapes[i], shapes[j], &pos12, n);
                assert!(s <= c.dist + 1e-12 * scale, "{s} > {} ({i}, {j}, {pos12:?})", c.dist);
            }
            // Along the contact normal the bound is the distance for the shapes whose support
            // function it computes exactly.
            if !matches!(shapes[i], SupportShape::CapsuleEllipse(..))
                && !matches!(shapes[j], SupportShape::CapsuleEllipse(..))
            {
                let s = separation_along(shapes[i], shapes[j], &pos12, c.normal);
                assert!((s - c.dist).abs() <= 1e-12 * scale, "{s} against {} ({i}, {j})", c.dist);
            }
            checked += 1;
        }
        assert!(checked > 3000, "{checked} pairs read");
    }

    #[test]
    fn apart_beyond_needs_a_unit_axis_that_clears_the_level_and_the_rounding() {
        let (sv, sn) = unit_square();
        let square = SupportShape::Polygon {
            vertices: &sv,
            normals: &sn,
            radius: 0.0,
        };
        let disc = SupportShape::Disc(0.5);
        // The disc 0.5 above the square's top face: the separation along +y is 0.5.
        let pos12 = Pose::translation(0.0, 2.0);
        assert!(apart_beyond(square, disc, &pos12, &[Vector::Y], 0.4, 3.0));
        assert!(!apart_beyond(square, disc, &pos12, &[Vector::Y], 0.5, 3.0));
        // Along x the shapes overlap in projection: nothing shown.
        assert!(!apart_beyond(square, disc, &pos12, &[Vector::X], 0.0, 3.0));
        // Axes that are not unit or not finite are passed over.
        assert!(!apart_beyond(square, disc, &pos12, &[Vector::Y * 2.0], 0.4, 3.0));
        assert!(!apart_beyond(
            square,
            disc,
            &pos12,
            &[Vector::NAN, Vector::ZERO],
            0.4,
            3.0
        ));
        // A polygon the contact query does not read shows nothing (its callers answer it).
        let collinear = [Vector::new(-1.0, 0.0), Vector::new(0.0, 0.0), Vector::new(1.0, 0.0)];
        let same = [-Vector::Y, -Vector::Y, Vector::Y];
        let unread = SupportShape::Polygon {
            vertices: &collinear,
            normals: &same,
            radius: 0.0,
        };
        assert!(!apart_beyond(unread, disc, &pos12, &[Vector::Y], 0.4, 3.0));
        // A pose that is not finite shows nothing.
        let bad = Pose::translation(Real::NAN, 2.0);
        assert!(!apart_beyond(square, disc, &bad, &[Vector::Y], 0.0, 3.0));
    }
}
