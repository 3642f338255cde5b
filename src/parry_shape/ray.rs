//! Exact ray casts on convex curves (module docs of `parry_shape`): the entry and exit points are
//! the roots of the monotone f(φ) = (P(φ) − o) × u on the two arcs between the support points
//! in ±m.

use crate::curve::pieces::piece_index;
use crate::curve::{ConvexCurve, CurvePoint};
use crate::numerics::angle::{unwrap_after, wrap_phi};
use crate::numerics::math::{cross, unit_or_x, Real, Vector};
use crate::numerics::roots::solve_increasing;
use crate::parry_shape::projection::curve_project;
use core::f64::consts::{PI, TAU};
use parry2d_f64::query::{Ray, RayIntersection};
use parry2d_f64::shape::FeatureId;

/// A ray hit on a curve: time of impact, normal (parry's convention) and boundary parameter.
#[derive(Copy, Clone, Debug)]
pub(crate) struct CurveHit {
    pub toi: f64,
    pub normal: Vector,
    pub phi: f64,
}

/// The root of f(φ) = P(φ)·m − c0 on the arc `[a, b]` on which it is monotone (increasing when
/// `sign = 1`, decreasing when `sign = −1`).
fn ray_arc_root(c: &dyn ConvexCurve, m: Vector, c0: f64, a: f64, b: f64, sign: f64) -> (f64, CurvePoint) {
    let f = |phi: f64| {
        let cp = c.eval(phi);
        (sign * (cp.point.dot(m) - c0), sign * cp.d_point.dot(m))
    };
    let (fa, fb) = (f(a).0, f(b).0);
    let phi = solve_increasing(a, b, fa, fb, f);
    (phi, c.eval(phi))
}

/// [`ConvexCurve::phi_range_of_normal`] kept to what its contract allows: an interval of φ
/// within one turn starting in [−π, π]. A user's curve that answers otherwise (non-finite, or
/// `(p, p + 1e17)`: issue 32) gets the one φ of its start, wrapped, so the arcs below stay
/// within a turn (and `wrap_phi` of a non-finite start is 0).
fn phi_range(c: &dyn ConvexCurve, n: Vector) -> (f64, f64) {
    let (lo, hi) = c.phi_range_of_normal(n);
    if lo.is_finite() && hi.is_finite() && lo <= hi && hi - lo <= TAU && (-PI..=PI).contains(&lo) {
        (lo, hi)
    } else {
        let lo = if lo.is_finite() { wrap_phi(lo) } else { 0.0 };
        (lo, lo)
    }
}

/// Exact ray cast on a convex curve (see the module documentation).
pub(crate) fn curve_ray(c: &dyn ConvexCurve, ray: &Ray, max_toi: Real, solid: bool) -> Option<CurveHit> {
    let (o, d) = (ray.origin, ray.dir);
    if !(o.is_finite() && d.is_finite()) || max_toi.is_nan() {
        return None;
    }
    if d.x == 0.0 && d.y == 0.0 {
        let pr = curve_project(c, o);
        return (pr.signed_dist <= 0.0 && max_toi >= 0.0).then_some(CurveHit {
            toi: 0.0,
            normal: -pr.normal,
            phi: pr.phi,
        });
    }
    let u = unit_or_x(d);
    let len = d.dot(u);
    if !(len > 0.0 && len.is_finite()) {
        return None;
    }
    let m = Vector::new(u.y, -u.x);
    let c0 = cross(o, u);
    let (lo_m, hi_m) = phi_range(c, m);
    let (lo_n, hi_n) = phi_range(c, -m);
    // f is at its maximum at S(m) and its minimum at S(−m); the line misses the curve unless
    // f_max ≥ 0 ≥ f_min.
    let f_max = c.eval(lo_m).point.dot(m) - c0;
    let f_min = c.eval(hi_n).point.dot(m) - c0;
    if !(f_max >= 0.0 && f_min <= 0.0) {
        return None;
    }
    // Entry: the arc from S(−m) to S(m) counter-clockwise (normals through −u), f increasing.
    let b_in = unwrap_after(hi_n, lo_m);
    let (phi_in, cp_in) = ray_arc_root(c, m, c0, hi_n, b_in, 1.0);
    // Exit: the arc from S(m) to S(−m) (normals through +u), f decreasing.
    let b_out = unwrap_after(hi_m, lo_n);
    let (phi_out, cp_out) = ray_arc_root(c, m, c0, hi_m, b_out, -1.0);
    let s_in = (cp_in.point - o).dot(u);
    let s_out = (cp_out.point - o).dot(u);
    if s_out < 0.0 || s_out.is_nan() {
        return None;
    }
    let hit = if s_in >= 0.0 {
        CurveHit {
            toi: s_in / len,
            normal: cp_in.normal,
            phi: wrap_phi(phi_in),
        }
    } else if solid {
        CurveHit {
            toi: 0.0,
            normal: -u,
            phi: wrap_phi(phi_in),
        }
    } else {
        CurveHit {
            toi: s_out / len,
            normal: -cp_out.normal,
            phi: wrap_phi(phi_out),
        }
    };
    (hit.toi <= max_toi && hit.toi.is_finite()).then_some(hit)
}

/// parry's ray cast on a curve whose feature is the piece hit (`Face(k)`, k the piece index):
/// the capsule-ellipse and user curves.
pub(crate) fn piecewise_ray(
    c: &dyn ConvexCurve,
    ray: &Ray,
    max_time_of_impact: Real,
    solid: bool,
) -> Option<RayIntersection> {
    let hit = curve_ray(c, ray, max_time_of_impact, solid)?;
    let f = FeatureId::Face(piece_index(c.breakpoints(), hit.phi) as u32);
    Some(RayIntersection::new(hit.toi, hit.normal, f))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CurvePoint, Ellipse};

    /// An ellipse whose `phi_range_of_normal` answers (p, p + w).
    #[derive(Debug)]
    struct HugeRange(Ellipse, f64);
    impl ConvexCurve for HugeRange {
        fn eval(&self, phi: f64) -> CurvePoint {
            self.0.eval(phi)
        }
        fn bounding_radius(&self) -> f64 {
            self.0.bounding_radius()
        }
        fn phi_range_of_normal(&self, n: Vector) -> (f64, f64) {
            let (lo, _) = self.0.phi_range_of_normal(n);
            (lo, lo + self.1)
        }
    }

    /// Issue 32, item 2: with such ranges the arcs between the support points were unwrapped
    /// by a loop that never ended from 5.7e16 on. The ray cast keeps a user's range within one
    /// turn: every ray ends, with the sound curve's answer where the lie does not matter (the
    /// support points are the ranges' starts, which are right).
    #[test]
    fn ray_cast_ends_when_phi_range_of_normal_answers_a_huge_interval() {
        let e = Ellipse::new(0.6, 0.3);
        for w in [1e17, 5.7e16, 1e300, f64::INFINITY, f64::NAN, -1.0] {
            let c = HugeRange(e, w);
            for k in 0..32 {
                let a = core::f64::consts::TAU * k as f64 / 32.0;
                let d = crate::numerics::math::unit(a);
                let ray = Ray::new(-d * 3.0 + crate::numerics::math::perp(d) * 0.1, d);
                let (got, sound) = (curve_ray(&c, &ray, 10.0, true), curve_ray(&e, &ray, 10.0, true));
                assert_eq!(got.map(|h| h.toi), sound.map(|h| h.toi), "width {w}, direction {a}");
            }
        }
    }
}
