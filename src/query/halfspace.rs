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
use crate::numerics::math::{perp, unit_or_x, Pose, Vector};
use crate::numerics::motion::{motion_is_finite, RelativeMotion};
use crate::query::stationary::{DistanceStatus, StationaryDistance};
use crate::query::stepping::CONTACT_FLOOR;
use crate::query::time_scale::rescaled;
use crate::query::toi::{TimeOfImpact, ToiCost, ToiOptions, ToiStatus};
use parry2d_f64::query::NonlinearRigidMotion;
use parry2d_f64::shape::HalfSpace;

/// The half-space cast's guard takes its bound over a span whose rates times it stay below this
/// (metres or radians): their squares stay within f64's range.
const SPAN_REACH: f64 = 1e100;

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
    crate::error::curves_sized(&[curve.bounding_radius()])?;
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

/// The curve against the half-space at one time, in the half-space's frame (where the plane is
/// fixed: normal n = `hs.normal` through the origin).
struct Sample {
    t: f64,
    dist: f64,
    /// Support point in the curve's frame.
    p: Vector,
    /// The support point in the half-space's frame.
    x: Vector,
    /// dG/dt for the body-fixed point p.
    dg: f64,
    /// The smallest dG/dt over the whole shape.
    v_min: f64,
    /// Half-space normal in the curve's frame.
    n_c: Vector,
}

/// The sample at time `t` of the curve moving by `rel` relative to the half-space (object1 the
/// curve, object2 the half-space): everything in the half-space's frame, from the pair's
/// relative placement, so that poses far from the world origin lose nothing (issue 32: in world
/// coordinates a plane 1e15 from the origin put the hit 0.17·s inside it).
///
/// A body point p is at X = q + R(β)(p − c₁) (`PairFrame`), at the height G = n·X, moving at
/// ∂G/∂t = n·q' + ω n·(R(p − c₁))⊥ = n·q' − ω (R(−β)n⊥)·(p − c₁), ω = ω_c − ω_h: affine in p,
/// smallest at the support point along k = ω R(−β)n⊥.
fn sample(curve: &dyn ConvexCurve, rel: &RelativeMotion, n: Vector, t: f64) -> Sample {
    let fr = rel.frame(t);
    let n_c = fr.unrotate(n);
    let p = curve.support_point(-n_c);
    let r = fr.rotate(p - fr.center1);
    let x = fr.q + r;
    let dist = n.dot(x);
    let base = n.dot(fr.q_t);
    let g_t = |r: Vector| base + fr.omega * n.dot(perp(r));
    let dg = g_t(r);
    let v_min = if fr.omega != 0.0 {
        let k = fr.unrotate(perp(n)) * fr.omega;
        g_t(fr.rotate(curve.support_point(unit_or_x(k)) - fr.center1))
    } else {
        dg
    };
    Sample {
        t,
        dist,
        p,
        x,
        dg,
        v_min: v_min.min(dg),
        n_c,
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
    // Rates beyond 2^±64 per second: the same query on a time scale where they are about 1
    // (`query::time_scale`), as `time_of_impact` asks it (hostile seed 5106, case 1659: speeds of
    // 8e306 m/s over a window of 3e-301 s overflowed the steps' bounds, `Degenerate`, where the
    // same motion on the unscaled time answers `NoHit`).
    if let Some(r) = rescaled(mc, mh, t0, t1, curve.bounding_radius()) {
        return finite(toi_halfspace(curve, &r.m1, hs, &r.m2, r.t0, r.t1, opts).map(|a| r.answer(a)));
    }
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
    crate::error::curves_sized(&[curve.bounding_radius()])?;
    let size = curve.bounding_radius();
    let tol = opts.distance_tolerance * size;
    let delta = opts.target_distance;
    let rc = size + mc.local_center.length();
    let rel = RelativeMotion::new(mc, mh);
    let n = hs.normal;
    let w_rel = mc.angvel - mh.angvel;
    let dcv = rel.center_velocity();
    // |G''| ≤ |q''| + ω²r_c, |q''| ≤ ω_h²|ΔC| + 2|ω_h||ΔV| (ΔC affine in t: largest at an end),
    // times span² (the bound on the span's own time scale: rates times the span, so that a
    // spin of 1e-250 rad/s over 1e250 s is a turn, not a square that underflows to 0).
    let bound_over = |t: f64, span: f64| {
        let dc = rel.center_offset(t).length().max(rel.center_offset(t + span).length());
        let (wh, wr, dv) = (mh.angvel * span, w_rel * span, (dcv * span).length());
        2.0 * wh.abs() * dv + wh * wh * dc + wr * wr * rc
    };
    let mut cost = ToiCost::default();
    let finish = |s: &Sample, status: ToiStatus, cost: ToiCost| TimeOfImpact {
        status,
        time: s.t,
        distance: s.dist,
        distance_rate: s.dg,
        point1: s.p,
        point2: s.x - n * s.dist,
        normal1: -s.n_c,
        normal2: n,
        cost,
    };
    let mut s = sample(curve, &rel, n, t0);
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
            s = sample(curve, &rel, n, (s.t + h).min(t1));
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
    // The latest sample found apart by more than the tolerance (the window's start before any):
    // a Newton step back from a sample that went too deep never goes before it.
    let mut t_safe = s.t;
    loop {
        let gap = s.dist - delta;
        if gap <= tol {
            // One Newton step on D from the safe side, kept if it stays within the tolerances.
            if s.dg < 0.0 {
                let tn = (s.t - gap / s.dg).max(t_safe).min(t1);
                let sn = sample(curve, &rel, n, tn);
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
        t_safe = s.t;
        if cost.predictor_steps >= opts.max_steps {
            return Ok(finish(&s, ToiStatus::OutOfIterations, cost));
        }
        let h_max = t1 - s.t;
        // On the time scale of a span T (τ = (t − tₖ)/T ∈ [0, 1]): D ≥ gap + ṽτ − m̃τ²/2 with
        // ṽ = V_min·T and m̃ = M·T². T is the window left, or less where a rate times it would
        // pass SPAN_REACH (so that the squares stay finite).
        let rate = s
            .v_min
            .abs()
            .max(mh.angvel.abs())
            .max(w_rel.abs())
            .max(dcv.x.abs())
            .max(dcv.y.abs());
        let span = if rate * h_max > SPAN_REACH {
            SPAN_REACH / rate
        } else {
            h_max
        };
        let m = bound_over(s.t, span);
        let v = s.v_min * span;
        let tau = if m > 0.0 {
            2.0 * gap / (-v + (v * v + 2.0 * m * gap).sqrt())
        } else if v < 0.0 {
            gap / -v
        } else {
            1.0
        };
        let h = tau.min(1.0) * span;
        if h < h_max && m > 0.0 {
            cost.guard_limited_steps += 1;
        }
        let tn = if h >= h_max { t1 } else { (s.t + h).min(t1) };
        if tn <= s.t {
            return Ok(finish(&s, ToiStatus::OutOfIterations, cost));
        }
        s = sample(curve, &rel, n, tn);
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
    #[test]
    fn a_step_that_lands_too_deep_never_answers_before_the_window() {
        // A 1:1e13 ellipse whose rotation centre lies 1e20 from it (its poses lose every digit
        // below 1e4 to cancellation) against a plane spinning at 33 rad/s (adversarial fuzz seed
        // 5002, case 171443): a step lands deep in the plane, and the Newton step back from it
        // went before the window's start.
        let e = Ellipse::new(2.220446049250313e-16, 0.001623169972206168);
        let a = 2.190985422073564f64;
        let hs = HalfSpace::new(Vector::new(a.cos(), a.sin()));
        let mh = NonlinearRigidMotion::new(
            Pose::IDENTITY,
            Vector::new(-0.0003864408913939695, 0.00020455837593540894),
            Vector::new(0.0019987359199316254, 0.003653119830906449),
            33.399090152925226,
        );
        let mc = NonlinearRigidMotion::new(
            Pose::from_parts(
                Vector::new(5e-324, -0.003004930841086855),
                parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.23451733655715337, 0.9721119374095448),
            ),
            Vector::new(0.00012592908985896542, 1e20),
            Vector::new(0.004368948647027078, -0.0013309441237117745),
            0.0,
        );
        let (t0, t1) = (0.20376433010429817, 1.2625681845974506);
        let opts = ToiOptions {
            stop_at_penetration: true,
            ..ToiOptions::default()
        };
        let r = time_of_impact_halfspace(&e, &mc, &hs, &mh, t0, t1, &opts).unwrap();
        assert!(
            (t0..=t1).contains(&r.time),
            "{:?} at {} outside [{t0}, {t1}]",
            r.status,
            r.time
        );
    }
}
