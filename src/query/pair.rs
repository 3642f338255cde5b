//! The three distances of the specification — distanceEuclidean, distanceFwd, distanceSide —
//! with their gradient and Hessian in (φ, t) (eq. 6).
//!
//! Everything is computed in object2's local frame, where object1's boundary point and normal
//! at (φ, t) are placed by a [`PairFrame`] (module docs of `numerics::motion`). With m = −N and
//! S₂ object2's support point (eq. 4):
//!
//! ```text
//! d = S₂(m) − P,   F = d·N,   S = d × N,   E = |d|.
//! ```
//!
//! Derivatives: ψ = angle(m) moves with ∂ψ/∂φ = ω₁(φ) = N₁ × N₁', ∂ψ/∂t = ω; S₂ moves along its
//! tangent τ = m⊥ with dS₂/dψ = ρ₂τ and d²S₂/dψ² = ρ₂'τ − ρ₂m. All products are carried out in
//! [`Jet2`] arithmetic.
//!
//! Identities the tests pin (docs/theory.md, "The gap function"): ∂F/∂φ = −ω₁·S, and at S = 0
//! ∂S/∂φ = ω₁(ρ₁ + ρ₂ + F).

use crate::curve::{ConvexCurve, CurvePoint, SupportJet};
use crate::numerics::jet::{Jet2, JetVec};
use crate::numerics::math::{cross, perp, Vector};
use crate::numerics::motion::PairFrame;

/// distanceFwd, distanceSide and distanceEuclidean with gradient and Hessian in (φ, t), and the
/// geometry behind them, at one (φ, t).
#[derive(Copy, Clone, Debug, PartialEq, Default)]
pub struct PairJet {
    /// distanceFwd F = d·N.
    pub fwd: Jet2,
    /// distanceSide S = d × N.
    pub side: Jet2,
    /// Object1's boundary point and derivatives in φ, in its own frame.
    pub curve1: CurvePoint,
    /// Object2's support data at m = −N (point in object2's frame).
    pub support2: SupportJet,
    /// Object1's boundary point P in object2's frame.
    pub point1_in_2: Vector,
    /// N in object2's frame.
    pub normal_in_2: Vector,
}

impl PairJet {
    /// distanceEuclidean E = |d| with its derivatives (undefined derivatives at d = 0 come out
    /// infinite; the value is then 0).
    pub fn euclidean(&self) -> Jet2 {
        let d = self.support2.point - self.point1_in_2;
        // E² = F² + S² since N is unit; E = √(F² + S²).
        let e2 = self.fwd * self.fwd + self.side * self.side;
        if d.length_squared() == 0.0 {
            return Jet2::cst(0.0);
        }
        e2.sqrt()
    }
}

#[inline]
fn rot_jet(fr: &PairFrame, v: Vector, v_p: Vector, v_pp: Vector) -> JetVec {
    let a = fr.rotate(v);
    let a_p = fr.rotate(v_p);
    let a_pp = fr.rotate(v_pp);
    let w = fr.omega;
    let a_t = perp(a) * w;
    let a_pt = perp(a_p) * w;
    let a_tt = -a * (w * w);
    JetVec {
        x: Jet2 {
            v: a.x,
            p: a_p.x,
            t: a_t.x,
            pp: a_pp.x,
            pt: a_pt.x,
            tt: a_tt.x,
        },
        y: Jet2 {
            v: a.y,
            p: a_p.y,
            t: a_t.y,
            pp: a_pp.y,
            pt: a_pt.y,
            tt: a_tt.y,
        },
    }
}

/// Evaluates the pair at φ in the frame `fr`: F, S (and E through [`PairJet::euclidean`]) with
/// gradient and Hessian in (φ, t). `obj2` must be strictly convex; returns `None` otherwise or
/// when the result is not finite.
#[inline]
pub fn eval_pair(obj1: &dyn ConvexCurve, obj2: &dyn ConvexCurve, fr: &PairFrame, phi: f64) -> Option<PairJet> {
    let cp = obj1.eval(phi);
    eval_pair_at(cp, obj2, fr)
}

/// As [`eval_pair`] from an already evaluated boundary point of object1.
#[inline]
pub fn eval_pair_at(cp: CurvePoint, obj2: &dyn ConvexCurve, fr: &PairFrame) -> Option<PairJet> {
    let sj = obj2.support_jet(-fr.rotate(cp.normal))?;
    jet_from(&cp, &sj, fr)
}

/// The full jet from object1's boundary point `cp` and object2's support data `sj` at m = −N.
#[inline]
fn jet_from(cp: &CurvePoint, sj: &SupportJet, fr: &PairFrame) -> Option<PairJet> {
    let mut p = rot_jet(fr, cp.point - fr.center1, cp.d_point, cp.dd_point);
    p.x.v += fr.q.x;
    p.y.v += fr.q.y;
    p.x.t += fr.q_t.x;
    p.y.t += fr.q_t.y;
    p.x.tt += fr.q_tt.x;
    p.y.tt += fr.q_tt.y;
    let n = rot_jet(fr, cp.normal, cp.d_normal, cp.dd_normal);
    let m = Vector::new(-n.x.v, -n.y.v);
    let w = cp.normal_turn_rate();
    let w_p = cp.d_normal_turn_rate();
    let om = fr.omega;
    let tau = perp(m);
    let rho = sj.radius_of_curvature;
    let k = tau * sj.d_radius_of_curvature - m * rho;
    let s_p = tau * (rho * w);
    let s_t = tau * (rho * om);
    let s_pp = k * (w * w) + tau * (rho * w_p);
    let s_pt = k * (w * om);
    let s_tt = k * (om * om);
    let s2 = JetVec {
        x: Jet2 {
            v: sj.point.x,
            p: s_p.x,
            t: s_t.x,
            pp: s_pp.x,
            pt: s_pt.x,
            tt: s_tt.x,
        },
        y: Jet2 {
            v: sj.point.y,
            p: s_p.y,
            t: s_t.y,
            pp: s_pp.y,
            pt: s_pt.y,
            tt: s_tt.y,
        },
    };
    let d = s2 - p;
    let fwd = d.dot(n);
    let side = d.cross(n);
    if !(fwd.is_finite() && side.is_finite()) {
        return None;
    }
    Some(PairJet {
        fwd,
        side,
        curve1: *cp,
        support2: *sj,
        point1_in_2: Vector::new(p.x.v, p.y.v),
        normal_in_2: Vector::new(n.x.v, n.y.v),
    })
}

/// What a solve of S(φ) = 0 at a fixed time needs at one φ: F, S, ∂S/∂φ and ∂²S/∂φ², with the
/// geometry that completes them into the full [`PairJet`] ([`PairPoint::jet`]) without
/// evaluating the shapes again. The root solvers of the stationary distance and of the time of
/// impact's corrector work on these; the tracker completes only the points it accepts, whose
/// time derivatives it needs.
///
/// Dot and cross products do not depend on the frame, so the φ-derivatives are taken in
/// object1's own frame, where P, N and their derivatives are as the curve gives them and only
/// object2's support point needs mapping: with d = S₂ − P, m = −N, τ = m⊥, ω₁ = N × N',
///
/// ```text
/// d_φ  = ω₁ρ₂τ − P',                     d_φφ = ω₁²(ρ₂'τ − ρ₂m) + ω₁'ρ₂τ − P'',
/// S_φ  = d_φ × N + d × N',               S_φφ = d_φφ × N + 2 d_φ × N' + d × N''.
/// ```
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct PairPoint {
    /// distanceFwd F = d·N.
    pub fwd: f64,
    /// distanceSide S = d × N.
    pub side: f64,
    /// ∂S/∂φ.
    pub side_p: f64,
    /// ∂²S/∂φ².
    pub side_pp: f64,
    /// Object1's boundary point and derivatives in φ, in its own frame.
    pub curve1: CurvePoint,
    /// Object2's support data at m = −N (point in object2's frame).
    pub support2: SupportJet,
    /// N in object2's frame.
    pub normal_in_2: Vector,
}

impl PairPoint {
    /// The full jet at this point in the frame it was evaluated in. Its F, S, S_φ and S_φφ are
    /// this point's, so that a decision taken on the point holds for the jet.
    ///
    /// The rest is derived in object1's frame, where N and its φ-derivatives are the curve's
    /// (the same values as [`eval_pair`]'s jet arithmetic, by fewer operations). With
    /// u = S₂ − q in object2's frame, m = −N there, τ = m⊥, k = ρ₂'τ − ρ₂m, and d₁ = R(−β)u + c₁ − P₁:
    ///
    /// ```text
    /// u_t  = ρ₂ωτ − q',   u_tt = ω²k − q'',
    /// d₁_t = R(−β)(u_t − ω u⊥),   d₁_tt = R(−β)(u_tt − 2ω u_t⊥ − ω² u),   d₁_φt = ωω₁ρ₂' τ₁,
    /// ```
    ///
    /// with τ₁ = R(−β)τ = −N⊥ (object1's frame); then F_t = d₁_t·N, F_φt = d₁_t·N',
    /// F_tt = d₁_tt·N, S_t = d₁_t × N, S_φt = ωω₁ρ₂' + d₁_t × N', S_tt = d₁_tt × N, and from
    /// the identity F_φ = −ω₁S (docs/theory.md § 5) and its derivative, F_φ = −ω₁S and
    /// F_φφ = −(ω₁'S + ω₁S_φ) with the point's S and S_φ (the same values as d₁·N' and
    /// d₁_φφ·N + 2d₁_φ·N' + d₁·N'' up to rounding, without recomputing d₁ and its φ-derivatives).
    #[inline]
    pub fn jet(&self, fr: &PairFrame) -> Option<PairJet> {
        let cp = &self.curve1;
        let sj = &self.support2;
        let (n, n_p) = (cp.normal, cp.d_normal);
        let w1 = cp.normal_turn_rate();
        let om = fr.omega;
        let (rho, rho_p) = (sj.radius_of_curvature, sj.d_radius_of_curvature);
        // Object2's frame.
        let m = -self.normal_in_2;
        let tau = perp(m);
        let k = tau * rho_p - m * rho;
        let u = sj.point - fr.q;
        let u_t = tau * (rho * om) - fr.q_t;
        let u_tt = k * (om * om) - fr.q_tt;
        // Object1's frame.
        let d_t = fr.unrotate(u_t - perp(u) * om);
        let d_tt = fr.unrotate(u_tt - perp(u_t) * (2.0 * om) - u * (om * om));
        let fwd = Jet2 {
            v: self.fwd,
            p: -w1 * self.side,
            t: d_t.dot(n),
            pp: -(cp.d_normal_turn_rate() * self.side + w1 * self.side_p),
            pt: d_t.dot(n_p),
            tt: d_tt.dot(n),
        };
        let side = Jet2 {
            v: self.side,
            p: self.side_p,
            t: cross(d_t, n),
            pp: self.side_pp,
            pt: om * w1 * rho_p + cross(d_t, n_p),
            tt: cross(d_tt, n),
        };
        if !(fwd.is_finite() && side.is_finite()) {
            return None;
        }
        Some(PairJet {
            fwd,
            side,
            curve1: *cp,
            support2: *sj,
            point1_in_2: fr.to_frame2(cp.point),
            normal_in_2: self.normal_in_2,
        })
    }
}

impl PairJet {
    /// The values of this jet a root solve needs ([`PairPoint`]).
    #[inline]
    pub(crate) fn point(&self) -> PairPoint {
        PairPoint {
            fwd: self.fwd.v,
            side: self.side.v,
            side_p: self.side.p,
            side_pp: self.side.pp,
            curve1: self.curve1,
            support2: self.support2,
            normal_in_2: self.normal_in_2,
        }
    }
}

/// Evaluates the pair at φ in the frame `fr` for a solve at fixed time ([`PairPoint`]). `obj2`
/// must be strictly convex; returns `None` otherwise or when the result is not finite.
#[inline]
pub(crate) fn eval_point<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    obj1: &A,
    obj2: &B,
    fr: &PairFrame,
    phi: f64,
) -> Option<PairPoint> {
    let cp = obj1.eval(phi);
    let normal_in_2 = fr.rotate(cp.normal);
    let sj = obj2.support_jet(-normal_in_2)?;
    let n = cp.normal;
    let d = fr.to_frame1(sj.point) - cp.point;
    let w = cp.normal_turn_rate();
    let w_p = cp.d_normal_turn_rate();
    // m = −N, τ = m⊥ = −N⊥.
    let tau = -perp(n);
    let rho = sj.radius_of_curvature;
    let k = tau * sj.d_radius_of_curvature + n * rho;
    let d_p = tau * (rho * w) - cp.d_point;
    let d_pp = k * (w * w) + tau * (rho * w_p) - cp.dd_point;
    let fwd = d.dot(n);
    let side = cross(d, n);
    let side_p = cross(d_p, n) + cross(d, cp.d_normal);
    let side_pp = cross(d_pp, n) + 2.0 * cross(d_p, cp.d_normal) + cross(d, cp.dd_normal);
    if !(fwd.is_finite() && side.is_finite() && side_p.is_finite() && side_pp.is_finite()) {
        return None;
    }
    Some(PairPoint {
        fwd,
        side,
        side_p,
        side_pp,
        curve1: cp,
        support2: sj,
        normal_in_2,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::math::Pose;
    use crate::numerics::motion::RelativeMotion;
    use crate::{BallCurve, CapsuleEllipse, Ellipse, RoundedPolygon};
    use parry2d_f64::query::NonlinearRigidMotion;

    fn motion(x: f64, y: f64, a: f64, vx: f64, vy: f64, w: f64, c: Vector) -> NonlinearRigidMotion {
        NonlinearRigidMotion::new(Pose::new(Vector::new(x, y), a), c, Vector::new(vx, vy), w)
    }

    /// Brute-force F and S at (φ, t) from parry's `position_at_time` (a second route).
    fn brute(
        o1: &dyn ConvexCurve,
        o2: &dyn ConvexCurve,
        m1: &NonlinearRigidMotion,
        m2: &NonlinearRigidMotion,
        phi: f64,
        t: f64,
    ) -> (f64, f64) {
        let (p1, p2) = (m1.position_at_time(t), m2.position_at_time(t));
        let cp = o1.eval(phi);
        let pw = p1 * cp.point;
        let nw = p1.rotation * cp.normal;
        let pl = p2.inverse_transform_point(pw);
        let nl = p2.rotation.inverse_transform_vector(nw);
        let s2 = o2.support_jet(-nl).unwrap().point;
        let d = s2 - pl;
        (d.dot(nl), crate::numerics::math::cross(d, nl))
    }

    fn check_pair(o1: &dyn ConvexCurve, o2: &dyn ConvexCurve) {
        let m1 = motion(-1.3, 0.4, 0.3, 0.7, -0.2, 2.5, Vector::new(0.1, -0.05));
        let m2 = motion(1.0, 0.5, 1.0, -0.3, 0.1, -1.2, Vector::new(-0.02, 0.03));
        let rel = RelativeMotion::new(&m1, &m2);
        let bps = o1.breakpoints().to_vec();
        for k in 0..40 {
            let phi = -3.1 + 0.155 * k as f64;
            if bps.iter().any(|b| (b - phi).abs() < 2e-3) {
                continue;
            }
            for t in [0.0, 0.37, 1.1] {
                let j = eval_pair(o1, o2, &rel.frame(t), phi).unwrap();
                let (f, s) = brute(o1, o2, &m1, &m2, phi, t);
                assert!(
                    (j.fwd.v - f).abs() < 1e-12 && (j.side.v - s).abs() < 1e-12,
                    "value at φ={phi}, t={t}"
                );
                let h = 1e-5;
                let fd = |dp: f64, dt: f64| brute(o1, o2, &m1, &m2, phi + dp, t + dt);
                let (fp, sp) = fd(h, 0.0);
                let (fm, sm) = fd(-h, 0.0);
                let (ftp, stp) = fd(0.0, h);
                let (ftm, stm) = fd(0.0, -h);
                let tol1 = 1e-7;
                let rel = |x: f64| 1.0 + x.abs();
                assert!(
                    (j.fwd.p - (fp - fm) / (2.0 * h)).abs() < tol1 * rel(j.fwd.p),
                    "F_φ φ={phi} t={t}"
                );
                assert!((j.side.p - (sp - sm) / (2.0 * h)).abs() < tol1 * rel(j.side.p), "S_φ");
                assert!((j.fwd.t - (ftp - ftm) / (2.0 * h)).abs() < tol1 * rel(j.fwd.t), "F_t");
                assert!(
                    (j.side.t - (stp - stm) / (2.0 * h)).abs() < tol1 * rel(j.side.t),
                    "S_t {} vs {} phi={phi} t={t}",
                    j.side.t,
                    (stp - stm) / (2.0 * h)
                );
                let tol2 = 1e-4;
                assert!(
                    (j.fwd.pp - (fp - 2.0 * f + fm) / (h * h)).abs() < tol2 * rel(j.fwd.pp),
                    "F_φφ"
                );
                assert!(
                    (j.side.pp - (sp - 2.0 * s + sm) / (h * h)).abs() < tol2 * rel(j.side.pp),
                    "S_φφ"
                );
                assert!(
                    (j.fwd.tt - (ftp - 2.0 * f + ftm) / (h * h)).abs() < tol2 * rel(j.fwd.tt),
                    "F_tt"
                );
                assert!(
                    (j.side.tt - (stp - 2.0 * s + stm) / (h * h)).abs() < tol2 * rel(j.side.tt),
                    "S_tt"
                );
                let (fpp, spp) = fd(h, h);
                let (fpm, spm) = fd(h, -h);
                let (fmp, smp) = fd(-h, h);
                let (fmm, smm) = fd(-h, -h);
                assert!(
                    (j.fwd.pt - (fpp - fpm - fmp + fmm) / (4.0 * h * h)).abs() < tol2 * rel(j.fwd.pt),
                    "F_φt"
                );
                assert!(
                    (j.side.pt - (spp - spm - smp + smm) / (4.0 * h * h)).abs() < tol2 * rel(j.side.pt),
                    "S_φt"
                );
                // Identity ∂F/∂φ = −ω₁ S (docs/theory.md § 5).
                let w = j.curve1.normal_turn_rate();
                assert!((j.fwd.p + w * j.side.v).abs() < 1e-12 * (1.0 + j.fwd.p.abs()));
                // E² = F² + S² and E = |d|.
                let e = j.euclidean();
                assert!((e.v - (f * f + s * s).sqrt()).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn jets_match_finite_differences_and_parry_poses_ellipse_ellipse() {
        check_pair(&Ellipse::new(0.5, 0.8), &Ellipse::new(0.5, 2.0));
    }

    #[test]
    fn jets_match_finite_differences_and_parry_poses_polygon_and_capsule_ellipse() {
        check_pair(&RoundedPolygon::regular(7, 1.0, 0.15), &Ellipse::new(0.5, 1.5));
        check_pair(&RoundedPolygon::regular(5, 1.0, 0.0), &BallCurve { radius: 0.4 });
        check_pair(&CapsuleEllipse::new(0.5, 1.0, 0.8), &Ellipse::new(0.3, 0.9));
    }

    #[test]
    fn pair_point_matches_the_full_jet_and_completes_to_it() {
        let m1 = motion(-1.3, 0.4, 0.3, 0.7, -0.2, 2.5, Vector::new(0.1, -0.05));
        let m2 = motion(1.0, 0.5, 1.0, -0.3, 0.1, -1.2, Vector::new(-0.02, 0.03));
        // A fast spin against an object2 that does not turn.
        let m3 = motion(0.2, -0.9, -2.0, 3.0, 1.5, -31.0, Vector::new(0.3, 0.2));
        let m4 = motion(-0.4, 1.1, 0.6, -1.0, 0.0, 0.0, Vector::new(0.1, 0.0));
        let rels = [RelativeMotion::new(&m1, &m2), RelativeMotion::new(&m3, &m4)];
        let pairs: [(&dyn ConvexCurve, &dyn ConvexCurve); 4] = [
            (&Ellipse::new(0.5, 0.8), &Ellipse::new(0.05, 2.0)),
            (&RoundedPolygon::regular(7, 1.0, 0.15), &Ellipse::new(0.5, 1.5)),
            (&RoundedPolygon::regular(5, 1.0, 0.0), &BallCurve { radius: 0.4 }),
            (&CapsuleEllipse::new(0.5, 1.0, 0.8), &Ellipse::new(0.3, 0.9)),
        ];
        for ((o1, o2), rel) in pairs.into_iter().flat_map(|p| rels.iter().map(move |r| (p, r))) {
            for k in 0..64 {
                let phi = -3.13 + 0.0981 * k as f64;
                for t in [0.0, 0.37, 1.1] {
                    let fr = rel.frame(t);
                    let j = eval_pair(o1, o2, &fr, phi).unwrap();
                    let p = eval_point(o1, o2, &fr, phi).unwrap();
                    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()));
                    assert!(close(p.fwd, j.fwd.v), "F at φ={phi}, t={t}");
                    assert!(close(p.side, j.side.v), "S at φ={phi}, t={t}");
                    assert!(
                        close(p.side_p, j.side.p),
                        "S_φ at φ={phi}, t={t}: {} vs {}",
                        p.side_p,
                        j.side.p
                    );
                    assert!(
                        close(p.side_pp, j.side.pp),
                        "S_φφ at φ={phi}, t={t}: {} vs {}",
                        p.side_pp,
                        j.side.pp
                    );
                    assert_eq!(p.normal_in_2, j.normal_in_2);
                    let c = p.jet(&fr).unwrap();
                    assert_eq!(
                        (c.fwd.v, c.side.v, c.side.p, c.side.pp),
                        (p.fwd, p.side, p.side_p, p.side_pp)
                    );
                    // The rest by its own formulas: the same values to rounding.
                    let pairs = [
                        ("F_φ", c.fwd.p, j.fwd.p),
                        ("F_t", c.fwd.t, j.fwd.t),
                        ("F_φφ", c.fwd.pp, j.fwd.pp),
                        ("F_φt", c.fwd.pt, j.fwd.pt),
                        ("F_tt", c.fwd.tt, j.fwd.tt),
                        ("S_t", c.side.t, j.side.t),
                        ("S_φt", c.side.pt, j.side.pt),
                        ("S_tt", c.side.tt, j.side.tt),
                        ("P.x", c.point1_in_2.x, j.point1_in_2.x),
                        ("P.y", c.point1_in_2.y, j.point1_in_2.y),
                    ];
                    for (name, a, b) in pairs {
                        assert!(close(a, b), "{name} at φ={phi}, t={t}: {a} vs {b}");
                    }
                    assert_eq!(
                        (c.curve1, c.support2, c.normal_in_2),
                        (j.curve1, j.support2, j.normal_in_2)
                    );
                    assert_eq!(c.point(), p);
                }
            }
        }
    }

    #[test]
    fn pair_frame_pos12_round_trips() {
        let pos12 = Pose::new(Vector::new(0.3, -1.2), 0.7);
        let fr = PairFrame::from_pos12(&pos12);
        let back = fr.pos12();
        assert!((back.translation - pos12.translation).length() < 1e-14);
        assert!((back.rotation.angle() - 0.7).abs() < 1e-14);
        let x = Vector::new(0.2, 0.9);
        assert!((fr.to_frame1(fr.to_frame2(x)) - x).length() < 1e-14);
        assert!((fr.to_frame2(x) - pos12.inverse_transform_point(x)).length() < 1e-14);
    }
}
