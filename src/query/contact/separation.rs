//! A one-axis certificate that two shapes are further apart than a margin, at the cost of their
//! two support values.
//!
//! For any unit direction n (body 1's frame, from body 1 towards body 2) the separation along n,
//!
//!   sep(n) = min over A₂ of n·x − max over A₁ of n·x = n·t − h₂(−Rᵀn) − h₁(n)
//!
//! (body 2 at pose (R, t) in body 1's frame, h₁, h₂ the support functions in each body's own
//! frame), is a lower bound of the signed distance: d = max over n of sep(n) (see the folder's
//! module docs). So sep(n) > margin proves d > margin along any one axis, with no search; the
//! contact query would return no point within that margin. A good axis is the previous normal
//! of a pair that was apart (rapier hands back the manifold), or the line of the centres.

use super::side::SupportShape;
use crate::numerics::math::{Pose, Vector};

/// The rounding allowance of [`apart_along`], relative to the magnitudes summed (|n·t| and the
/// two support values): each is computed to a few units in the last place (about 1e-16), so
/// 1e-12 leaves four orders of magnitude, while a pair within it of the margin is left to the
/// exact query.
pub(crate) const SEPARATION_ROUNDING: f64 = 1e-12;

impl SupportShape<'_> {
    /// h(m) = max over the shape of m·x, its support function in its own frame (positively
    /// homogeneous: any length of m). A polygon: max vᵢ·m + r; a disc: r|m|; an ellipse:
    /// √((a mₓ)² + (b m_y)²); a `CapsuleEllipse` (the right half of the stadium of the segment
    /// from (0, −r2) to (0, r2) with radius r1, glued to the left half of the ellipse with
    /// semi-axes r3, r1 + r2): r1|m| + r2|m_y| for mₓ ≥ 0, the ellipse's √((r3 mₓ)² + ((r1 + r2) m_y)²)
    /// for mₓ < 0 (each half holds the support point in its own half-plane of directions).
    pub(crate) fn support_value(&self, m: Vector) -> f64 {
        let ellipse = |a: f64, b: f64| ((a * m.x) * (a * m.x) + (b * m.y) * (b * m.y)).sqrt();
        match *self {
            SupportShape::Polygon { vertices, radius, .. } => {
                let top = vertices.iter().map(|v| v.dot(m)).fold(f64::NEG_INFINITY, f64::max);
                top + radius * m.length()
            }
            SupportShape::Disc(r) => r * m.length(),
            SupportShape::Ellipse(a, b) => ellipse(a, b),
            SupportShape::CapsuleEllipse(r1, r2, r3) => {
                if m.x >= 0.0 {
                    r1 * m.length() + r2 * m.y.abs()
                } else {
                    ellipse(r3, r1 + r2)
                }
            }
        }
    }
}

/// True when `shape1` (at the origin) and `shape2` (at `pos12`) are proved further apart than
/// `margin` along `axis` (any length, body 1's frame, towards body 2): sep(axis/|axis|) exceeds
/// the margin by more than [`SEPARATION_ROUNDING`] of the magnitudes. False when not proved
/// (the axis does not separate them by that much, or a value is not finite). Body 2's support
/// value is taken at Rᵀ(−n) with R the pose's rotation as a matrix, the geometry in which the
/// exact query places body 2 (the same for a rotation a little off unit length).
pub(crate) fn apart_along(shape1: SupportShape, shape2: SupportShape, pos12: &Pose, axis: Vector, margin: f64) -> bool {
    let len = axis.length();
    if !(len > 0.0 && len.is_finite()) {
        return false;
    }
    let n = axis / len;
    let (h1, h2) = (
        shape1.support_value(n),
        shape2.support_value(pos12.inverse_transform_vector(-n)),
    );
    let along = n.dot(pos12.translation);
    let sep = along - h2 - h1;
    let rounding = SEPARATION_ROUNDING * (along.abs() + h1.abs() + h2.abs());
    sep - rounding > margin
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::ConvexCurve;
    use crate::query::contact::contact;
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};

    /// max over `n` boundary samples of the curve of m·P(φ).
    fn sampled_support(c: &dyn ConvexCurve, m: Vector, n: usize) -> f64 {
        (0..n)
            .map(|i| {
                let phi = -core::f64::consts::PI + 2.0 * core::f64::consts::PI * i as f64 / n as f64;
                c.eval(phi).point.dot(m)
            })
            .fold(f64::NEG_INFINITY, f64::max)
    }

    #[test]
    fn support_values_match_the_sampled_boundary_of_each_shape() {
        let e = Ellipse::new(0.7, 0.2);
        let c = CapsuleEllipse::new(0.5, 1.0, 0.8);
        let p = RoundedPolygon::new(
            &[Vector::new(-0.4, -0.3), Vector::new(0.5, -0.2), Vector::new(0.1, 0.6)],
            0.05,
        );
        let shapes: [(SupportShape, &dyn ConvexCurve); 3] = [
            (SupportShape::Ellipse(0.7, 0.2), &e),
            (SupportShape::CapsuleEllipse(0.5, 1.0, 0.8), &c),
            (
                SupportShape::Polygon {
                    vertices: p.vertices(),
                    normals: p.edge_normals(),
                    radius: 0.05,
                },
                &p,
            ),
        ];
        for (s, curve) in shapes {
            for k in 0..64 {
                let a = k as f64 * 0.1;
                let m = Vector::new(a.cos(), a.sin()) * 1.5;
                let exact = s.support_value(m);
                let sampled = sampled_support(curve, m, 20_000);
                // The samples lie on the boundary: never above, and within the sampling's chord.
                assert!(sampled <= exact + 1e-12, "{s:?} at {m:?}: {sampled} > {exact}");
                assert!(exact - sampled < 1e-5, "{s:?} at {m:?}: {exact} vs {sampled}");
            }
        }
    }

    #[test]
    fn a_proved_separation_is_one_the_exact_query_confirms() {
        // Ellipse against a rounded triangle over a ring of poses and axes: whenever the axis
        // proves the pair apart by more than the margin, the exact signed distance is larger.
        let p = RoundedPolygon::new(
            &[Vector::new(-0.4, -0.3), Vector::new(0.5, -0.2), Vector::new(0.1, 0.6)],
            0.05,
        );
        let s1 = SupportShape::Ellipse(0.7, 0.2);
        let s2 = SupportShape::Polygon {
            vertices: p.vertices(),
            normals: p.edge_normals(),
            radius: 0.05,
        };
        let margin = 0.01;
        let (mut proved, mut cases) = (0, 0);
        for i in 0..40 {
            for j in 0..12 {
                let a = i as f64 * 0.157;
                let pos12 = Pose::new(Vector::new(a.cos(), a.sin()) * (0.6 + 0.05 * j as f64), 0.3 * i as f64);
                let exact = contact(s1, s2, &pos12, 0.9, None).expect("the exact contact");
                for k in 0..8 {
                    let b = a + (k as f64 - 4.0) * 0.2;
                    cases += 1;
                    if apart_along(s1, s2, &pos12, Vector::new(b.cos(), b.sin()), margin) {
                        proved += 1;
                        assert!(
                            exact.dist > margin,
                            "pose {pos12:?}, axis angle {b}: d = {}",
                            exact.dist
                        );
                    }
                }
                // The exact normal itself proves every pair apart by more than the margin.
                if exact.dist > margin + 1e-9 {
                    assert!(apart_along(s1, s2, &pos12, exact.normal, margin));
                }
            }
        }
        assert!(proved > cases / 10 && proved < cases, "{proved} of {cases} proved");
    }

    #[test]
    fn a_degenerate_axis_proves_nothing() {
        let s = SupportShape::Disc(1.0);
        let far = Pose::new(Vector::new(10.0, 0.0), 0.0);
        assert!(apart_along(s, s, &far, Vector::X, 0.0));
        for axis in [
            Vector::ZERO,
            Vector::new(f64::NAN, 1.0),
            Vector::new(f64::INFINITY, 0.0),
        ] {
            assert!(!apart_along(s, s, &far, axis, 0.0));
        }
    }
}
