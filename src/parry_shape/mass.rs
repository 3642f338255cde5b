//! Exact mass properties (module docs of `parry_shape`): closed forms for the rounded polygon
//! and the capsule-ellipse, adaptive Gauss–Legendre quadrature of Green's theorem for any curve.

use crate::curve::pieces::piece_bounds;
use crate::curve::ConvexCurve;
use crate::numerics::angle::ccw_angle;
use crate::numerics::math::{cross, Real, Vector};
use crate::numerics::quadrature::gauss_legendre;
use core::f64::consts::PI;
use parry2d_f64::mass_properties::MassProperties;

/// The quadrature of the moments is refined until each is within this fraction of the size's
/// power (area r², first moments r³, polar moment r⁴) …
const MOMENT_TOLERANCE: f64 = 1e-14;
/// … or this many halvings deep.
const MAX_DEPTH: u32 = 30;
/// A smooth curve (no breakpoints) is integrated in this many equal pieces of φ.
const SMOOTH_PIECES: usize = 8;

pub(crate) type Moments = [f64; 4];

/// Gauss–Legendre estimate of ∫ [½ c, ⅓ x c, ⅓ y c, ¼ |P|² c] dφ over [a, b], c = P × P′.
fn gl_moments(c: &dyn ConvexCurve, a: f64, b: f64, nodes: &([f64; 12], [f64; 12])) -> Moments {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let mut acc = [0.0; 4];
    for (z, w) in nodes.0.iter().zip(nodes.1.iter()) {
        let cp = c.eval(mid + half * z);
        let p = cp.point;
        let cr = cross(p, cp.d_point);
        acc[0] += w * 0.5 * cr;
        acc[1] += w * p.x * cr / 3.0;
        acc[2] += w * p.y * cr / 3.0;
        acc[3] += w * 0.25 * p.length_squared() * cr;
    }
    acc.map(|v| v * half)
}

fn adaptive_moments(
    c: &dyn ConvexCurve,
    a: f64,
    b: f64,
    whole: Moments,
    tol: &Moments,
    depth: u32,
    nodes: &([f64; 12], [f64; 12]),
) -> Moments {
    let m = 0.5 * (a + b);
    let left = gl_moments(c, a, m, nodes);
    let right = gl_moments(c, m, b, nodes);
    let sum = [0, 1, 2, 3].map(|k| left[k] + right[k]);
    let frac = (b - a) / (2.0 * PI);
    let ok = (0..4).all(|k| {
        let err = (sum[k] - whole[k]).abs();
        err <= tol[k] * frac || err.is_nan()
    });
    if ok || depth == 0 {
        return sum;
    }
    let l = adaptive_moments(c, a, m, left, tol, depth - 1, nodes);
    let r = adaptive_moments(c, m, b, right, tol, depth - 1, nodes);
    [0, 1, 2, 3].map(|k| l[k] + r[k])
}

/// Area, first moments and polar second moment (about the origin) of the region bounded by a
/// convex curve, by adaptive Gauss–Legendre quadrature of Green's theorem over each piece.
pub(crate) fn curve_moments(c: &dyn ConvexCurve) -> Moments {
    let nodes = gauss_legendre::<12>();
    let bp = c.breakpoints();
    let r = c.bounding_radius().abs().max(f64::MIN_POSITIVE);
    let tol = [r * r, r * r * r, r * r * r, r * r * r * r].map(|s| MOMENT_TOLERANCE * s);
    let mut total = [0.0; 4];
    let mut add = |a: f64, b: f64| {
        let whole = gl_moments(c, a, b, &nodes);
        let m = adaptive_moments(c, a, b, whole, &tol, MAX_DEPTH, &nodes);
        for k in 0..4 {
            total[k] += m[k];
        }
    };
    if bp.is_empty() {
        for i in 0..SMOOTH_PIECES {
            let a = -PI + 2.0 * PI * i as f64 / SMOOTH_PIECES as f64;
            add(a, a + 2.0 * PI / SMOOTH_PIECES as f64);
        }
    } else {
        for k in 0..bp.len() {
            let (s, e) = piece_bounds(bp, k);
            if e > s {
                add(s, e);
            }
        }
    }
    total
}

/// parry mass properties from the moments (about the origin) of a uniform region.
pub(crate) fn mass_from_moments(density: Real, m: Moments) -> MassProperties {
    let area = m[0];
    if !m.iter().all(|v| v.is_finite()) || area <= 0.0 {
        return MassProperties::new(Vector::ZERO, 0.0, 0.0);
    }
    let com = Vector::new(m[1], m[2]) / area;
    let inertia = (m[3] - area * com.length_squared()).max(0.0);
    MassProperties::new(com, density * area, density * inertia)
}

pub(crate) fn curve_mass(c: &dyn ConvexCurve, density: Real) -> MassProperties {
    mass_from_moments(density, curve_moments(c))
}

/// Adds the moments (about the origin) of the convex polygon `v` (counter-clockwise) to `acc`.
fn add_polygon_moments(v: &[Vector], acc: &mut Moments) {
    let n = v.len();
    for i in 0..n {
        let (p, q) = (v[i], v[(i + 1) % n]);
        let c = cross(p, q);
        acc[0] += 0.5 * c;
        acc[1] += c * (p.x + q.x) / 6.0;
        acc[2] += c * (p.y + q.y) / 6.0;
        acc[3] += c * (p.dot(p) + p.dot(q) + q.dot(q)) / 12.0;
    }
}

/// Exact moments (about the origin) of a convex polygon dilated by `r`: core polygon, a
/// rectangle on each edge and a circular sector at each corner.
pub(crate) fn rounded_polygon_moments(vertices: &[Vector], normals: &[Vector], r: f64) -> Moments {
    let n = vertices.len();
    if n == 0 {
        return [0.0; 4];
    }
    // Work about the vertex centroid to limit cancellation, shift at the end.
    let c0 = vertices.iter().copied().sum::<Vector>() / n as f64;
    let mut acc = [0.0; 4];
    let local: Vec<Vector> = vertices.iter().map(|v| *v - c0).collect();
    add_polygon_moments(&local, &mut acc);
    if r > 0.0 {
        for i in 0..n {
            let (p, q, e) = (local[i], local[(i + 1) % n], normals[i]);
            add_polygon_moments(&[p, p + e * r, q + e * r, q], &mut acc);
            // Sector at vertex i from the previous edge's normal to this edge's normal.
            let u0 = normals[(i + n - 1) % n];
            let alpha = ccw_angle(u0, e);
            let area = 0.5 * alpha * r * r;
            let mc = Vector::new(e.y - u0.y, u0.x - e.x) * (r * r * r / 3.0);
            let jc = 0.25 * alpha * r * r * r * r;
            acc[0] += area;
            acc[1] += mc.x + area * p.x;
            acc[2] += mc.y + area * p.y;
            acc[3] += jc + 2.0 * p.dot(mc) + area * p.length_squared();
        }
    }
    // Shift from c0 to the origin: J_O = J_c0 + 2 c0·M_c0 + A |c0|².
    let (area, m) = (acc[0], Vector::new(acc[1], acc[2]));
    [
        area,
        m.x + area * c0.x,
        m.y + area * c0.y,
        acc[3] + 2.0 * c0.dot(m) + area * c0.length_squared(),
    ]
}

/// Exact moments (about the origin) of the capsule-ellipse: half ellipse (x ≤ 0, semi-axes r3
/// and r1 + r2), rectangle [0, r1] × [−r2, r2] and two quarter discs of radius r1 centred at
/// (0, ±r2).
pub(crate) fn capsule_ellipse_moments(r1: f64, r2: f64, r3: f64) -> Moments {
    let bb = r1 + r2;
    let area = 0.5 * PI * r3 * bb + 2.0 * r1 * r2 + 0.5 * PI * r1 * r1;
    let mx = -2.0 / 3.0 * bb * r3 * r3 + r1 * r1 * r2 + 2.0 / 3.0 * r1 * r1 * r1;
    let j = PI * r3 * bb * (r3 * r3 + bb * bb) / 8.0
        + 2.0 / 3.0 * (r1 * r1 * r1 * r2 + r1 * r2 * r2 * r2)
        + PI * r1.powi(4) / 4.0
        + 4.0 / 3.0 * r2 * r1 * r1 * r1
        + PI * r1 * r1 * r2 * r2 / 2.0;
    [area, mx, 0.0, j]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};

    fn rel_close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * a.abs().max(b.abs()).max(1e-300)
    }

    #[test]
    fn green_quadrature_of_ellipses_matches_closed_form_up_to_1_to_100() {
        for (a, b) in [(1.0, 1.0), (2.0, 0.5), (0.3, 1.7), (1.0, 0.01), (0.02, 2.0)] {
            let m = curve_moments(&Ellipse::new(a, b));
            assert!(rel_close(m[0], PI * a * b, 1e-13), "area {a} {b}: {}", m[0]);
            assert!(m[1].abs() < 1e-13 * a * a * b && m[2].abs() < 1e-13 * a * b * b.max(a));
            let j = PI * a * b * (a * a + b * b) / 4.0;
            assert!(rel_close(m[3], j, 1e-13), "J {a} {b}: {} vs {j}", m[3]);
        }
    }

    #[test]
    fn rounded_polygon_moments_match_green_quadrature() {
        let irregular = [
            Vector::new(0.3, -0.2),
            Vector::new(2.1, 0.1),
            Vector::new(2.4, 1.3),
            Vector::new(1.0, 2.2),
            Vector::new(0.1, 1.0),
        ];
        let mut polys = vec![
            RoundedPolygon::new(&irregular, 0.0),
            RoundedPolygon::new(&irregular, 0.37),
        ];
        for sides in 3..9 {
            for r in [0.0, 0.05, 1.5] {
                polys.push(RoundedPolygon::regular(sides, 1.3, r));
            }
        }
        for p in polys {
            let exact = rounded_polygon_moments(p.vertices(), p.edge_normals(), p.corner_radius());
            let quad = curve_moments(&p);
            let s = p.bounding_radius();
            let scale = [s * s, s * s * s, s * s * s, s.powi(4)];
            for k in 0..4 {
                assert!(
                    (exact[k] - quad[k]).abs() <= 1e-13 * scale[k],
                    "{p:?} moment {k}: {} vs {}",
                    exact[k],
                    quad[k]
                );
            }
        }
    }

    #[test]
    fn capsule_ellipse_moments_match_green_quadrature() {
        for (r1, r2, r3) in [(0.5, 1.0, 0.8), (1.0, 0.1, 3.0), (0.2, 2.0, 0.05), (1.0, 1.0, 1.0)] {
            let c = CapsuleEllipse::new(r1, r2, r3);
            let exact = capsule_ellipse_moments(r1, r2, r3);
            let quad = curve_moments(&c);
            let s = c.bounding_radius();
            let scale = [s * s, s * s * s, s * s * s, s.powi(4)];
            for k in 0..4 {
                assert!(
                    (exact[k] - quad[k]).abs() <= 1e-13 * scale[k],
                    "({r1}, {r2}, {r3}) moment {k}: {} vs {}",
                    exact[k],
                    quad[k]
                );
            }
        }
    }
}
