//! A convex curve against a half-space: closed-form distance and an exact nonlinear time of
//! impact (parry answers `Unsupported` for a nonlinear cast against a half-space, so without this
//! a custom shape would get no continuous collision against half-space ground).
//!
//! With the half-space's outward normal n (world) and a point o of its boundary, the signed
//! distance is D = n·(X(p) − o) where p = S(−n) is the curve's support point in direction −n
//! (in the curve's frame, exact through [`ConvexCurve::phi_range_of_normal`]).
//!
//! The time of impact steps with a guard in the spirit of the tracker's ([`crate::time_of_impact`]). Here the only axis
//! is the half-space normal, and D(t) = min over body points x of G(x, t), the height of x above
//! the boundary. For each body point G(x, t) = n(t)·ΔC(t) + n·R(α_c − α_h)(x − c_c) + n·c_h, so
//! |G''| ≤ M = 2|ω_h||ΔV| + ω_h²·max|ΔC| + (ω_c − ω_h)²·r_c (r_c bounds |x − c_c|), and
//!
//! ```text
//! D(tₖ + h) ≥ Dₖ + V_min·h − M h²/2,
//! ```
//!
//! where V_min = min over the shape of ∂G/∂t(x, tₖ). ∂G/∂t is affine in x, with gradient
//! (ω_h − ω_c)·n⊥, so V_min is attained at the support point in direction −(ω_h − ω_c)·n⊥ and is
//! exact. The step h = 2Δ/(−V_min + √(V_min² + 2MΔ)) (Δ = D − δ) keeps the bound above the target,
//! so no contact is stepped over — also for sharp corners, where D has concave kinks. Close to
//! the contact V_min is the contact point's own approach speed and the steps converge like
//! Newton's.

use crate::curve::ConvexCurve;
use crate::error::{finite, QueryError};
use crate::numerics::math::{perp, Pose, Vector};
use crate::numerics::motion::motion_is_finite;
use crate::query::stationary::{DistanceStatus, StationaryDistance};
use crate::query::stepping::CONTACT_FLOOR;
use crate::query::toi::{TimeOfImpact, ToiCost, ToiOptions, ToiStatus};
use parry2d_f64::query::NonlinearRigidMotion;
use parry2d_f64::shape::HalfSpace;

/// Signed distance between `curve` and the half-space `hs`; `pos12` is shape 2's pose in shape 1's
/// frame and `curve_first` tells whether shape 1 is the curve. Results in the caller's order.
pub fn halfspace_distance(
    curve: &dyn ConvexCurve,
    hs: &HalfSpace,
    pos12: &Pose,
    curve_first: bool,
) -> Result<StationaryDistance, QueryError> {
    if !(pos12.is_finite() && hs.normal.is_finite()) {
        return Err(QueryError::NonFinite);
    }
    // Work in the curve's frame: pos_hc = pose of the half-space in the curve's frame.
    let pos_hc = if curve_first { *pos12 } else { pos12.inverse() };
    let n = pos_hc.rotation.transform_vector(hs.normal);
    let o = pos_hc.translation;
    let (lo, hi) = curve.phi_range_of_normal(-n);
    let phi = 0.5 * (lo + hi);
    let p = curve.support_point(-n);
    let dist = n.dot(p - o);
    if !dist.is_finite() {
        return Err(QueryError::Degenerate);
    }
    let on_plane = pos_hc.inverse_transform_point(p - n * dist);
    let status = if dist > 0.0 {
        DistanceStatus::Separated
    } else {
        DistanceStatus::Penetrating
    };
    let base = StationaryDistance {
        distance: dist,
        phi,
        point1: p,
        point2: on_plane,
        normal1: -n,
        normal2: hs.normal,
        status,
        newton_iterations: 0,
        evaluations: 1,
    };
    finite(Ok(if curve_first {
        base
    } else {
        StationaryDistance {
            point1: on_plane,
            point2: p,
            normal1: hs.normal,
            normal2: -n,
            ..base
        }
    }))
}

struct Sample {
    t: f64,
    dist: f64,
    /// Support point in the curve's frame.
    p: Vector,
    /// dG/dt for the body-fixed point p.
    dg: f64,
    /// The smallest dG/dt over the whole shape.
    v_min: f64,
    /// Half-space normal in the curve's frame.
    n_c: Vector,
    /// Plane point (the half-space origin) in the curve's frame.
    o_c: Vector,
}

fn sample(
    curve: &dyn ConvexCurve,
    mc: &NonlinearRigidMotion,
    hs: &HalfSpace,
    mh: &NonlinearRigidMotion,
    t: f64,
) -> Sample {
    let pc = mc.position_at_time(t);
    let ph = mh.position_at_time(t);
    let nw = ph.rotation.transform_vector(hs.normal);
    let ow = ph.translation;
    let n_c = pc.rotation.inverse_transform_vector(nw);
    let p = curve.support_point(-n_c);
    let x = pc.transform_point(p);
    let dist = nw.dot(x - ow);
    // Velocities of the material points.
    let cc = pc.transform_point(mc.local_center);
    let ch = ph.transform_point(mh.local_center);
    let xv = mc.linvel + perp(x - cc) * mc.angvel;
    let ov = mh.linvel + perp(ow - ch) * mh.angvel;
    let nv = perp(nw) * mh.angvel;
    let g_t = |x: Vector| {
        let xv = mc.linvel + perp(x - cc) * mc.angvel;
        nv.dot(x - ow) + nw.dot(xv - ov)
    };
    let dg = g_t(x);
    let _ = xv;
    // ∂G/∂t = k·x + const with k = (ω_h − ω_c)·n⊥: smallest at the support point along −k.
    let k = perp(nw) * (mh.angvel - mc.angvel);
    let v_min = if k.length_squared() > 0.0 {
        let kc = pc.rotation.inverse_transform_vector(-k);
        g_t(pc.transform_point(curve.support_point(kc)))
    } else {
        dg
    };
    Sample {
        t,
        dist,
        p,
        dg,
        v_min: v_min.min(dg),
        n_c,
        o_c: pc.inverse_transform_point(ow),
    }
}

/// The time of impact of `curve` moving by `mc` against the half-space `hs` moving by `mh`,
/// with the semantics of [`crate::time_of_impact`]; the result has the curve as shape 1.
///
/// An ellipse with semi-axes 0.5 × 0.2 falling at 10 m/s from 1.2 above the ground y = 0, lying
/// flat: it touches when its lowest point (0.2 below its centre) reaches the plane, at t = 0.1:
///
/// ```
/// use parry2d_f64::math::{Pose, Vector};
/// use parry2d_f64::query::NonlinearRigidMotion;
/// use parry2d_f64::shape::HalfSpace;
/// use smooth_ccd2d::{time_of_impact_halfspace, Ellipse, ToiOptions, ToiStatus};
///
/// let fall = NonlinearRigidMotion::new(Pose::translation(0.0, 1.2), Vector::ZERO, Vector::new(0.0, -10.0), 0.0);
/// let ground = HalfSpace::new(Vector::Y);
/// let r = time_of_impact_halfspace(&Ellipse::new(0.5, 0.2), &fall, &ground, &NonlinearRigidMotion::identity(), 0.0, 1.0, &ToiOptions::default())
///     .unwrap();
/// assert_eq!(r.status, ToiStatus::Hit);
/// assert!((r.time - 0.1).abs() < 1e-12);
/// ```
pub fn time_of_impact_halfspace(
    curve: &dyn ConvexCurve,
    mc: &NonlinearRigidMotion,
    hs: &HalfSpace,
    mh: &NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    opts: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    finite(toi_halfspace(curve, mc, hs, mh, t0, t1, opts))
}

fn toi_halfspace(
    curve: &dyn ConvexCurve,
    mc: &NonlinearRigidMotion,
    hs: &HalfSpace,
    mh: &NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    opts: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    if !(motion_is_finite(mc)
        && motion_is_finite(mh)
        && t0.is_finite()
        && t1.is_finite()
        && hs.normal.is_finite()
        && opts.is_valid())
    {
        return Err(QueryError::NonFinite);
    }
    if t1 < t0 {
        return Err(QueryError::EmptyWindow);
    }
    let size = curve.bounding_radius();
    let tol = opts.distance_tolerance * size;
    let delta = opts.target_distance;
    let rc = size + mc.local_center.length();
    let w_rel = mc.angvel - mh.angvel;
    let dv = (mc.linvel - mh.linvel).length();
    let c0 = mc.start.transform_point(mc.local_center) - mh.start.transform_point(mh.local_center);
    let dcv = mc.linvel - mh.linvel;
    let bound = |t: f64, h: f64| {
        let dc = (c0 + dcv * t).length().max((c0 + dcv * (t + h)).length());
        2.0 * mh.angvel.abs() * dv + mh.angvel * mh.angvel * dc + w_rel * w_rel * rc
    };
    let mut cost = ToiCost::default();
    let finish = |s: &Sample, status: ToiStatus, cost: ToiCost| {
        let on_plane = s.p - s.n_c * s.dist;
        let _ = s.o_c;
        let ph = mh.position_at_time(s.t);
        let pc = mc.position_at_time(s.t);
        TimeOfImpact {
            status,
            time: s.t,
            distance: s.dist,
            distance_rate: s.dg,
            point1: s.p,
            point2: ph.inverse_transform_point(pc.transform_point(on_plane)),
            normal1: -s.n_c,
            normal2: hs.normal,
            cost,
        }
    };
    let mut s = sample(curve, mc, hs, mh, t0);
    cost.evaluations += 1;
    if !(s.dist.is_finite() && s.dg.is_finite() && s.v_min.is_finite()) {
        return Err(QueryError::Degenerate);
    }
    if s.dist <= delta + tol {
        if opts.stop_at_penetration || s.dg <= 0.0 {
            return Ok(finish(&s, ToiStatus::PenetratingAtStart, cost));
        }
        // Separating contact: step out of it.
        let mut h = ((delta + 2.0 * tol - s.dist) / s.dg).max((t1 - t0) * 1e-9);
        while s.dist <= delta + tol {
            if s.t >= t1 || cost.predictor_steps >= opts.max_steps {
                return Ok(finish(&s, ToiStatus::NoHit, cost));
            }
            s = sample(curve, mc, hs, mh, (s.t + h).min(t1));
            cost.predictor_steps += 1;
            cost.evaluations += 1;
            if !(s.dist.is_finite() && s.dg.is_finite() && s.v_min.is_finite()) {
                return Err(QueryError::Degenerate);
            }
            if s.dist <= delta + tol && s.dg <= 0.0 {
                return Ok(finish(&s, ToiStatus::Hit, cost));
            }
            h *= 2.0;
        }
    }
    loop {
        let gap = s.dist - delta;
        if gap <= tol {
            // One Newton step on D from the safe side, kept if it stays within the tolerances.
            if s.dg < 0.0 {
                let tn = (s.t - gap / s.dg).min(t1);
                let sn = sample(curve, mc, hs, mh, tn);
                cost.evaluations += 1;
                let g = sn.dist - delta;
                if g >= -CONTACT_FLOOR * size && g <= tol {
                    return Ok(finish(&sn, ToiStatus::Hit, cost));
                }
            }
            return Ok(finish(&s, ToiStatus::Hit, cost));
        }
        if s.t >= t1 {
            return Ok(finish(&s, ToiStatus::NoHit, cost));
        }
        if cost.predictor_steps >= opts.max_steps {
            return Ok(finish(&s, ToiStatus::OutOfIterations, cost));
        }
        let h_max = t1 - s.t;
        let m = bound(s.t, h_max);
        let v = s.v_min;
        let h = if m > 0.0 {
            2.0 * gap / (-v + (v * v + 2.0 * m * gap).sqrt())
        } else if v < 0.0 {
            gap / -v
        } else {
            h_max
        };
        if h < h_max && m > 0.0 {
            cost.guard_limited_steps += 1;
        }
        let tn = if h >= h_max { t1 } else { s.t + h };
        if tn <= s.t {
            return Ok(finish(&s, ToiStatus::OutOfIterations, cost));
        }
        s = sample(curve, mc, hs, mh, tn);
        cost.predictor_steps += 1;
        cost.evaluations += 1;
        if !(s.dist.is_finite() && s.dg.is_finite() && s.v_min.is_finite()) {
            return Err(QueryError::Degenerate);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Ellipse, RoundedPolygon};

    #[test]
    fn ellipse_falls_on_ground_at_closed_form_time() {
        let e = Ellipse::new(0.5, 0.2);
        // Ellipse at height 2 falling at 1 m/s, no spin: contact when its bottom (y − 0.2) reaches 0.
        let mc = NonlinearRigidMotion::new(
            Pose::new(Vector::new(0.0, 2.0), 0.0),
            Vector::ZERO,
            Vector::new(0.0, -1.0),
            0.0,
        );
        let mh = NonlinearRigidMotion::identity();
        let hs = HalfSpace::new(Vector::Y);
        let r = time_of_impact_halfspace(&e, &mc, &hs, &mh, 0.0, 5.0, &ToiOptions::default()).unwrap();
        assert_eq!(r.status, ToiStatus::Hit);
        assert!((r.time - 1.8).abs() < 1e-10, "{}", r.time);
    }

    #[test]
    fn spinning_polygon_corner_reaches_ground_when_its_support_does() {
        // Square of circumradius 1 turned by π/4, spinning at 10 rad/s at height 0.9: its corner
        // at angle 5π/4 + θ is at height 0.9 + sin(5π/4 + θ), which first reaches 0 at
        // θ = π/4 − acos(0.9).
        let p = RoundedPolygon::regular(4, 1.0, 0.0);
        let w = 10.0;
        let mc = NonlinearRigidMotion::new(
            Pose::new(Vector::new(0.0, 0.9), core::f64::consts::FRAC_PI_4),
            Vector::ZERO,
            Vector::ZERO,
            w,
        );
        let hs = HalfSpace::new(Vector::Y);
        let r = time_of_impact_halfspace(
            &p,
            &mc,
            &hs,
            &NonlinearRigidMotion::identity(),
            0.0,
            1.0,
            &ToiOptions::default(),
        )
        .unwrap();
        assert_eq!(r.status, ToiStatus::Hit);
        let exact = (core::f64::consts::FRAC_PI_4 - 0.9f64.acos()) / w;
        assert!((r.time - exact).abs() < 1e-10, "{} vs {exact}", r.time);
    }
}
