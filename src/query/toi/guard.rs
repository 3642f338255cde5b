//! The step guard (module docs of `query::toi`, "Why no impact is stepped over"): the bound M on
//! |g''| of the gap along an axis turning at λ, the step that keeps the parabola
//! g + g'h − Mh²/2 above the target, and the Taylor data of the curve S = 0 the predictor and
//! the aim use.

use super::Tracker;
use crate::curve::ConvexCurve;
use crate::query::pair::PairJet;

impl<'a, A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized> Tracker<'a, A, B> {
    /// The guard's bound on [t, t + h] (module docs): the axis turns at λ in the world, and
    /// M(λ) = λ²·max|ΔC| + 2|λ||ΔV| + (λ − ω₁)²H₁ + (λ − ω₂)²H₂ bounds |g''| of the gap along
    /// it. λ = ω₁ (the axis fixed in object1, H₁ not needed) unless object1 is strictly convex,
    /// in which case the λ minimising M is taken; when neither shape spins, the gap along the fixed
    /// axis (λ = 0) is affine in t and M = 0 exactly. Returns (M, λ).
    pub(super) fn guard_bound(&self, t: f64, h: f64, local: Option<&PairJet>) -> (f64, f64) {
        let (w1, w2) = (self.omega1, self.rel.omega2());
        // On a clock (the nlerp path) ΔC' = ΔV·τ' and ΔC'' = ΔV·τ'': |ΔV| becomes its largest
        // |ΔC'| over the step, and g'' gains −ΔC''·n, at most |ΔV|·max|τ''| (module docs of
        // `numerics::clock`).
        let clock = self.rel.clock_bounds(t, t + h);
        if w1 == 0.0 && w2 == 0.0 && clock.d2 == 0.0 {
            // Neither turns: along the fixed axis λ = 0 the gap is affine in t, g'' = 0.
            return (0.0, 0.0);
        }
        let w = w1 - w2;
        let dc = self
            .rel
            .center_offset(t)
            .length_squared()
            .max(self.rel.center_offset(t + h).length_squared())
            .sqrt();
        let dv = self.dv_len * clock.d1;
        let dc_dd = self.dv_len * clock.d2;
        // The axis turns at λ − ωᵢ against shape i; the optimal λ lies between 0, ω₁ and ω₂,
        // so over [t, t + h] the directions stay within these angles of the current ones.
        let sweep2 = if self.obj1_convex {
            w2.abs().max(w.abs())
        } else {
            w.abs()
        } * h;
        let h2 = match local {
            Some(j) => self.obj2.support_dd_bound_near(-j.normal_in_2, sweep2),
            None => self.h2_global,
        } + self.c2_len;
        let mut m_body = w * w * h2 + 2.0 * w1.abs() * dv + w1 * w1 * dc;
        if self.clock {
            m_body += dc_dd;
        }
        let mut best = (m_body, w1);
        if self.obj1_convex {
            let sweep1 = w1.abs().max(w.abs()) * h;
            let h1 = match local {
                Some(j) => self.obj1.support_dd_bound_near(j.curve1.normal, sweep1),
                None => self.h1_global,
            } + self.c1_len;
            let m_at = |l: f64| {
                let m = l * l * dc + 2.0 * l.abs() * dv + (l - w1) * (l - w1) * h1 + (l - w2) * (l - w2) * h2;
                if self.clock {
                    m + dc_dd
                } else {
                    m
                }
            };
            let den = dc + h1 + h2;
            if den > 0.0 {
                // M is a convex quadratic on each side of λ = 0: its minimiser on each side.
                for sign in [1.0, -1.0] {
                    let l = (w1 * h1 + w2 * h2 - sign * dv) / den;
                    let l = if l * sign >= 0.0 { l } else { 0.0 };
                    let m = m_at(l);
                    if m < best.0 {
                        best = (m, l);
                    }
                }
            }
        }
        best
    }
}

/// Taylor data of the curve S = 0 through a corrected point (eqs. 7–8): the Newton correction
/// −S/S_φ of a residual S, the slope φ' = −S_t/S_φ and the bending
/// φ'' = −(S_tt + 2S_φt φ' + S_φφ φ'²)/S_φ (all zero when S_φ ≤ 0).
#[inline]
pub(super) fn curve_taylor(j: &PairJet) -> (f64, f64, f64) {
    let s = j.side;
    if s.p > 0.0 {
        let d1 = -s.t / s.p;
        let d2 = -(s.tt + 2.0 * s.pt * d1 + s.pp * d1 * d1) / s.p;
        (-s.v / s.p, d1, d2)
    } else {
        (0.0, 0.0, 0.0)
    }
}

/// φ on the curve S = 0 at time offset h from the corrected point (φ, j) (order-2 Taylor).
#[inline]
pub(super) fn predict_phi(phi: f64, j: &PairJet, h: f64) -> f64 {
    let (resid, d1, d2) = curve_taylor(j);
    phi + resid + d1 * h + 0.5 * d2 * h * h
}
