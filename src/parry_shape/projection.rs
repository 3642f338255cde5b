//! Closest boundary points (module docs of `parry_shape`): a grid-bracketed, Newton-polished
//! search for any curve, and Eberly's robust bisection for the ellipse.

use crate::curve::pieces::{piece_bounds, piece_index};
use crate::curve::{ConvexCurve, CurvePoint};
use crate::numerics::angle::wrap_phi;
use crate::numerics::math::{perp, unit_or_x, Vector};
use crate::numerics::roots::solve_increasing;
use parry2d_f64::query::PointProjection;
use parry2d_f64::shape::FeatureId;

/// Bisections of Eberly's ellipse root at most (enough to exhaust f64 from any start; it stops
/// when the midpoint no longer moves).
const ELLIPSE_BISECTIONS: usize = 1100;
/// The projection's grid brackets the closest points with this many cells over the curve …
const GRID_CELLS: usize = 64;
/// … and at least this many per piece.
const MIN_CELLS_PER_PIECE: usize = 4;

/// The closest boundary point of a curve to a point.
#[derive(Copy, Clone, Debug)]
pub(crate) struct CurveProjection {
    pub point: Vector,
    /// Outward unit normal at `point`.
    pub normal: Vector,
    pub phi: f64,
    /// Signed distance (negative inside).
    pub signed_dist: f64,
}

/// Closest boundary point by bracketing the sign changes of g(φ) = (x − P)·T on a grid and
/// polishing with bracketed Newton (see the module documentation).
pub(crate) fn curve_project(c: &dyn ConvexCurve, x: Vector) -> CurveProjection {
    let x = if x.is_finite() { x } else { Vector::ZERO };
    let bp = c.breakpoints();
    let np = bp.len().max(1);
    let sub = GRID_CELLS.div_ceil(np).max(MIN_CELLS_PER_PIECE);
    let g_of = |cp: &CurvePoint| (x - cp.point).dot(perp(cp.normal));
    let mut best: Option<(f64, f64, CurvePoint)> = None;
    let mut consider = |phi: f64, cp: CurvePoint| {
        let d2 = (x - cp.point).length_squared();
        if d2.is_finite() && best.as_ref().is_none_or(|b| d2 < b.0) {
            best = Some((d2, phi, cp));
        }
    };
    for k in 0..np {
        let (s, e) = piece_bounds(bp, k);
        if e <= s || e.is_nan() || s.is_nan() {
            continue;
        }
        let h = (e - s) / sub as f64;
        let mut phi_a = s;
        let mut cp_a = c.eval(s);
        let mut g_a = g_of(&cp_a);
        consider(phi_a, cp_a);
        for j in 1..=sub {
            let phi_b = if j == sub { e } else { s + j as f64 * h };
            let cp_b = c.eval(phi_b);
            let g_b = g_of(&cp_b);
            consider(phi_b, cp_b);
            if g_a > 0.0 && g_b < 0.0 {
                // −g is increasing through the root.
                let root = solve_increasing(phi_a, phi_b, -g_a, -g_b, |phi| {
                    let cp = c.eval(phi);
                    let g = (x - cp.point).dot(perp(cp.normal));
                    let dg = -cp.d_point.dot(perp(cp.normal)) + (x - cp.point).dot(perp(cp.d_normal));
                    (-g, -dg)
                });
                consider(root, c.eval(root));
            }
            phi_a = phi_b;
            cp_a = cp_b;
            g_a = g_b;
        }
    }
    match best {
        Some((d2, phi, cp)) => {
            let n = unit_or_x(cp.normal);
            let side = (x - cp.point).dot(n);
            let dist = d2.sqrt();
            CurveProjection {
                point: cp.point,
                normal: n,
                phi: wrap_phi(phi),
                signed_dist: if side <= 0.0 { -dist } else { dist },
            }
        }
        None => {
            let p = c.support_point(Vector::X);
            CurveProjection {
                point: p,
                normal: Vector::X,
                phi: 0.0,
                signed_dist: 0.0,
            }
        }
    }
}

/// parry's point projection on a curve by [`curve_project`] (the capsule-ellipse and user
/// curves).
pub(crate) fn project_on_curve(c: &dyn ConvexCurve, pt: Vector, solid: bool) -> PointProjection {
    let pr = curve_project(c, pt);
    let inside = pr.signed_dist <= 0.0 && pt.is_finite();
    if inside && solid {
        PointProjection::new(true, pt)
    } else {
        PointProjection::new(inside, pr.point)
    }
}

/// As [`project_on_curve`] with the feature holding the projection (`Face(k)`, k the piece
/// index).
pub(crate) fn project_on_curve_with_feature(c: &dyn ConvexCurve, pt: Vector) -> (PointProjection, FeatureId) {
    let pr = curve_project(c, pt);
    let inside = pr.signed_dist <= 0.0 && pt.is_finite();
    let f = FeatureId::Face(piece_index(c.breakpoints(), pr.phi) as u32);
    (PointProjection::new(inside, pr.point), f)
}

/// Closest point on the ellipse with semi-axes `a`, `b` to `p` (Eberly, "Distance from a Point
/// to an Ellipse, an Ellipsoid, or a Hyperellipsoid"): robust bisection on the Lagrange
/// multiplier, exact for any axis ratio, inside and outside.
pub(crate) fn ellipse_closest_point(a: f64, b: f64, p: Vector) -> Vector {
    let swap = b > a;
    let (e0, e1) = if swap { (b, a) } else { (a, b) };
    let (q0, q1) = if swap { (p.y, p.x) } else { (p.x, p.y) };
    let (y0, y1) = (q0.abs(), q1.abs());
    // A coordinate below 1e-290 of its semi-axis is 0 to rounding; kept, the bisection below
    // divides one underflowed number by another (an infinite closest point).
    let y0 = if y0 < 1e-290 * e0 { 0.0 } else { y0 };
    let y1 = if y1 < 1e-290 * e1 { 0.0 } else { y1 };
    let (x0, x1);
    if y1 > 0.0 {
        if y0 > 0.0 {
            let z0 = y0 / e0;
            let z1 = y1 / e1;
            let g = z0.hypot(z1) - 1.0;
            if g != 0.0 {
                let r0 = (e0 / e1) * (e0 / e1);
                // r0 − 1 without cancellation (near-circles).
                let rm1 = ((e0 - e1) / e1) * ((e0 + e1) / e1);
                let u = ellipse_root(r0, rm1, z0, z1, g);
                x0 = r0 * y0 / (u + rm1);
                x1 = y1 / u;
            } else {
                x0 = y0;
                x1 = y1;
            }
        } else {
            x0 = 0.0;
            x1 = e1;
        }
    } else {
        let numer0 = e0 * y0;
        let denom0 = (e0 - e1) * (e0 + e1);
        if numer0 < denom0 {
            let xde0 = numer0 / denom0;
            x0 = e0 * xde0;
            x1 = e1 * ((1.0 - xde0) * (1.0 + xde0)).max(0.0).sqrt();
        } else {
            x0 = e0;
            x1 = 0.0;
        }
    }
    let (x0, x1) = (x0.copysign(q0), x1.copysign(q1));
    if swap {
        Vector::new(x1, x0)
    } else {
        Vector::new(x0, x1)
    }
}

/// Eberly's root of G(s) = (r0 z0/(s + r0))² + (z1/(s + 1))² − 1, bisected in u = s + 1 (so
/// that s + 1 = u and s + r0 = u + (r0 − 1) keep full relative precision when the closest
/// point is near the end of the minor axis).
fn ellipse_root(r0: f64, rm1: f64, z0: f64, z1: f64, g: f64) -> f64 {
    let n0 = r0 * z0;
    let mut u0 = z1;
    let mut u1 = if g < 0.0 { 1.0 } else { n0.hypot(z1) };
    let mut u = u1;
    for _ in 0..ELLIPSE_BISECTIONS {
        u = 0.5 * (u0 + u1);
        if u == u0 || u == u1 {
            break;
        }
        let ratio0 = n0 / (u + rm1);
        let ratio1 = z1 / u;
        let gg = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
        if gg > 0.0 {
            u0 = u;
        } else if gg < 0.0 {
            u1 = u;
        } else {
            break;
        }
    }
    u
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::math::cross;
    use crate::Ellipse;

    #[test]
    fn ellipse_closest_point_is_a_foot_of_perpendicular_for_extreme_ratios() {
        for (a, b) in [(1.0, 1e-3), (1e-3, 1.0), (2.0, 2.0), (3.0, 0.5)] {
            let e = Ellipse::new(a, b);
            for k in 0..200 {
                let ang = 0.031 * k as f64;
                for rad in [0.0, 1e-4, 0.3, 0.999, 1.0, 1.001, 2.0, 50.0] {
                    let x =
                        Vector::new(a * rad * ang.cos(), b * rad * ang.sin()) + Vector::new(0.0, 1e-3 * (k % 3) as f64);
                    let p = ellipse_closest_point(a, b, x);
                    // On the ellipse.
                    let g = (p.x / a).powi(2) + (p.y / b).powi(2) - 1.0;
                    assert!(g.abs() < 1e-12, "off the ellipse: {g} a={a} b={b} x={x} p={p}");
                    // x − p along the normal at p.
                    let n = e.normal_at_point(p);
                    let d = x - p;
                    assert!(cross(d, n).abs() <= 1e-12 * a.max(b), "not a foot: {x} -> {p}");
                }
            }
        }
    }
}
