//! The step guard of the gap tracker: a lower bound on the distance over a step that needs no
//! strict convexity on either side.
//!
//! Take the axis u(s) that starts at the maximum's axis uₖ and turns at a constant rate λ (in
//! the time direction of the step, s ≥ 0). The gap along it, g(s) = G(θₖ + λs, tₖ + s), is a
//! lower bound on D(tₖ + s). Its three terms (module docs of `frame`):
//!
//! * −ΔC·u: a known function of s (ΔC is affine in time): its first two derivatives at 0 are
//!   exact and |λ|³·max|ΔC| + 3λ²|ΔV| bounds its third (max over the step's ends); on the nlerp
//!   path's clock (ΔC = ΔC₀ + ΔV·τ) the second derivative gains −ΔV·τ″·u and the third's bound
//!   reads |λ|³·max|ΔC| + 3λ²|ΔV|·max τ′ + 3|λ||ΔV|·max|τ″| + |ΔV|·max|τ‴|;
//! * −h̃ₓ(ψₓ(s)) for each body, with ψₓ turning at wₓ = λ − ωₓ. h̃ₓ(m) = max over the body's
//!   support points p of (p − cₓ)·m, and over the step only the points whose normals the
//!   direction sweeps can be support points: the arc A from the support at m₀ to the support at
//!   m_end = R(wₓ·span)m₀. For each such p, −(p − cₓ)·m(s) has value ≥ −h̃ₓ(m₀) at 0, slope
//!   −wₓ(p − cₓ)·m₀⊥, and second derivative at most wₓ²|p − cₓ| ≤ wₓ²R̃ₓ (R̃ₓ the body's radius
//!   about cₓ). Along the arc (p − cₓ)·m₀⊥·sign(wₓ) grows while the normal stays within π/2 of
//!   m₀, so the smallest slope is the one of the arc's end: −wₓ(p_end − cₓ)·m₀⊥. Hence
//!   −h̃ₓ(ψₓ(s)) ≥ −h̃ₓ(m₀) − wₓ(p_end − cₓ)·m₀⊥·s − wₓ²R̃ₓs²/2 on [0, span]. (Beyond a quarter
//!   turn, |wₓ|R̃ₓ bounds the slope.) A face inside the swept arc shows in p_end: the bound pays
//!   for the support jumping across it, which is why λ is ω₁ or ω₂ — the rate that keeps the
//!   body whose face holds the contact still (wₓ = 0: exact) — whichever allows the longer
//!   step.
//!
//! A polygon side whose support vertex v keeps the swept directions inside its cone is known
//! better: it contributes exactly −(v − cₓ)·m(s) − r (exact first two derivatives, third at most
//! |wₓ|³|v − cₓ|).
//!
//! Summed: g(s) ≥ q(s) = G(uₖ) + a₁s + a₂s²/2 − a₃s³/6 on [0, span] ([`Bound`]), and the step
//! is the first root of q − δ ([`Bound::step`]): no contact in [tₖ, tₖ + step]. Near a contact
//! the coefficients are the exact D′ and D″ of the contact's own configuration (the face's body
//! still, the vertex keeping its cone), so the steps converge like Newton's.

// The negated comparisons (`!(x > 0.0)`) are deliberate: they are true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::frame::GapFrame;
use super::maxgap::{GapMax, Pair};
use crate::numerics::math::{perp, rotate_cs, sin_cos};
use crate::query::stepping::parabola_step;
use core::f64::consts::FRAC_PI_2;

/// The guard's lower bound over a span: the gap along the turning axis is at least
/// q(s) = gap + a1·s + a2·s²/2 − a3·s³/6 on [0, span] (a3 ≥ 0).
#[derive(Copy, Clone, Debug)]
pub(crate) struct Bound {
    pub a1: f64,
    pub a2: f64,
    pub a3: f64,
}

/// Iterations of [`Bound::step`]'s root search at most (safeguarded Newton; bisection alone
/// needs at most ~64 to exhaust a double bracket).
const ROOT_ITERATIONS: usize = 80;

/// Relative accuracy of [`Bound::step`]'s root: the step returned is below the root by at most
/// about this fraction of it (shorter is always safe; well above the rounding noise of q, so
/// Newton's last steps are not spent on it).
const ROOT_TOL: f64 = 1e-14;

impl Bound {
    /// q at s for the gap `gap`.
    #[inline]
    pub(crate) fn q(&self, gap: f64, s: f64) -> f64 {
        gap + s * (self.a1 + s * (0.5 * self.a2 - s * self.a3 / 6.0))
    }

    /// The largest s ≤ `span` with q > 0 on [0, s): the first root of q, found on the monotone
    /// piece of q (between its critical points, the roots of q' = a1 + a2·s − a3·s²/2) where q
    /// changes sign, by bisection that keeps the side where q > 0. `span` when q stays positive.
    pub(crate) fn step(&self, gap: f64, span: f64) -> f64 {
        if !(gap > 0.0 && span > 0.0) {
            return 0.0;
        }
        // Critical points in (0, span), sorted.
        let mut ends = [span; 3];
        let mut n = 0;
        let mut push = |x: f64| {
            if x > 0.0 && x < span {
                ends[n] = x;
                n += 1;
            }
        };
        let (a, b, c) = (-0.5 * self.a3, self.a2, self.a1);
        if a == 0.0 {
            if b != 0.0 {
                push(-c / b);
            }
        } else {
            let disc = b * b - 4.0 * a * c;
            if disc >= 0.0 {
                // The stable pair of roots of a·x² + b·x + c.
                let qq = -0.5 * (b + disc.sqrt().copysign(b));
                let (r1, r2) = (qq / a, if qq != 0.0 { c / qq } else { f64::NAN });
                push(r1.min(r2));
                push(r1.max(r2));
            }
        }
        if n == 2 && ends[0] > ends[1] {
            ends.swap(0, 1);
        }
        ends[n] = span;
        let mut lo = 0.0;
        for &hi in &ends[..=n] {
            if !(self.q(gap, hi) > 0.0) {
                // q falls from positive to ≤ 0 on the monotone piece [lo, hi].
                return self.last_positive(gap, lo, hi);
            }
            lo = hi;
        }
        span
    }

    /// q′ at s.
    #[inline]
    fn dq(&self, s: f64) -> f64 {
        self.a1 + s * (self.a2 - 0.5 * s * self.a3)
    }

    /// The root of q on [lo, hi], where q is monotone with q(lo) > 0 ≥ q(hi), approached from
    /// the positive side: the returned s has q(s) > 0 and lies within [`ROOT_TOL`]·s of the
    /// root (or is the last point of a bracket that no longer shrinks).
    ///
    /// Safeguarded Newton: each iterate that leaves the bracket [a, b] (q(a) > 0 ≥ q(b)) is
    /// replaced by its midpoint, and every evaluation shrinks the bracket. Newton converges to
    /// the root from one side only, so once its step is within the tolerance the point
    /// 2·[`ROOT_TOL`] beyond it on the other side is probed to close the bracket.
    fn last_positive(&self, gap: f64, lo: f64, hi: f64) -> f64 {
        let (mut a, mut b) = (lo, hi);
        let mut x = lo;
        let mut qx = self.q(gap, x);
        // Start at the root of the parabola without the cubic term, when it is in the bracket:
        // it bounds q from above, so its first root is at or beyond q's.
        let start = parabola_step(gap, self.a1, -self.a2);
        if start > a && start < b {
            x = start;
            qx = self.q(gap, x);
            if qx > 0.0 {
                a = x;
            } else {
                b = x;
            }
        }
        for _ in 0..ROOT_ITERATIONS {
            if b - a <= ROOT_TOL * b {
                break;
            }
            let newton = x - qx / self.dq(x);
            let mut converged = (newton - x).abs() <= ROOT_TOL * x.abs();
            let mut next = if converged {
                // Probe across the root, twice the tolerance away.
                x + if qx > 0.0 { 2.0 } else { -2.0 } * ROOT_TOL * x
            } else {
                newton
            };
            if !(next > a && next < b) {
                converged = false;
                next = 0.5 * (a + b);
                if !(next > a && next < b) {
                    break;
                }
            }
            let before = qx > 0.0;
            x = next;
            qx = self.q(gap, x);
            if qx > 0.0 {
                a = x;
            } else {
                b = x;
            }
            if converged && before != (qx > 0.0) {
                // The probe crossed the root: the bracket is within 3·ROOT_TOL of it.
                break;
            }
        }
        a
    }

    /// A curvature bound M of a parabola that bounds q from below over `span` (for sizing
    /// extensions, not for safety).
    pub(crate) fn curvature(&self, span: f64) -> f64 {
        (-self.a2).max(0.0) + self.a3 * span / 3.0
    }
}

impl Pair<'_> {
    /// The longest span over which the guard's bound from `at` (axis turning at `lambda`, time
    /// direction `dir`) is the exact one: each turning polygon side keeps its support vertex
    /// (and turns by at most a quarter turn). 0 when a turning side is a curve.
    pub(crate) fn exact_span(&self, fr: &GapFrame, at: &GapMax, lambda: f64, dir: f64) -> f64 {
        let mut span = f64::INFINITY;
        for k in 0..2 {
            let w = dir * (lambda - self.motion.omega[k]);
            if w == 0.0 {
                continue;
            }
            let side = &self.sides[k];
            let f = if k == 0 { at.i } else { at.j };
            if side.disc(f).is_none() {
                return 0.0;
            }
            let m0 = fr.to_body(k, if k == 0 { at.u } else { -at.u });
            span = span.min(side.room(f, m0, w).min(FRAC_PI_2) / w.abs());
        }
        span
    }

    /// The guard's lower bound from the maximum `at` of the frame `fr` (module docs), the axis
    /// turning at `lambda` over `span` in the time direction `dir` (+1 forward, −1 backward),
    /// with the body radii about the rotation centres `radius`.
    ///
    /// The offset term −ΔC·u is a known function of s: its first two derivatives at 0 are exact
    /// and |ΔC|·|λ|³ + 3λ²|ΔV| bounds its third. A polygon side whose support vertex v keeps the
    /// swept directions inside its cone contributes the exact sinusoid −(v − c)·m(s) − r (third
    /// derivative at most |w|³|v − c|); any other turning side the swept-arc bound of the module
    /// docs (its arc end's slope, and curvature at most w²R̃).
    pub(crate) fn guard(
        &self,
        fr: &GapFrame,
        at: &GapMax,
        lambda: f64,
        span: f64,
        dir: f64,
        radius: [f64; 2],
    ) -> Bound {
        let u = at.u;
        let up = perp(u);
        let mo = &self.motion;
        let lam = dir * lambda;
        let dv = fr.dc_t * dir;
        let dc_end = mo.dc(fr.time + dir * span);
        let dc_max = fr.dc.length().max(dc_end.length());
        let mut b = Bound {
            a1: -dv.dot(u) - lam * fr.dc.dot(up),
            a2: lam * lam * fr.dc.dot(u) - 2.0 * lam * dv.dot(up),
            a3: lam.abs().powi(3) * dc_max + 3.0 * lam * lam * dv.length(),
        };
        if mo.clock.is_some() {
            // On a clock: ΔC″ = ΔV·τ″ enters the second derivative exactly, and the third is
            // bounded with the clock's bounds over the span, |ΔC‴| + 3|λ||ΔC″| + 3λ²|ΔC′| +
            // |λ|³|ΔC| (the λ² term taking the largest |ΔC′| instead of its value at s = 0).
            let cb = mo.clock_bounds(fr.time, fr.time + dir * span);
            let v = mo.dv.length();
            b.a2 -= fr.dc_tt.dot(u);
            b.a3 = lam.abs().powi(3) * dc_max + 3.0 * lam * lam * v * cb.d1 + 3.0 * lam.abs() * v * cb.d2 + v * cb.d3;
        }
        for (k, r_k) in radius.into_iter().enumerate() {
            let w = lam - dir * mo.omega[k];
            if w == 0.0 {
                continue;
            }
            let side = &self.sides[k];
            let m0 = fr.to_body(k, if k == 0 { u } else { -u });
            let c = mo.centre[k];
            let f = if k == 0 { at.i } else { at.j };
            let sweep = w * span;
            // A polygon vertex that stays the support over the sweep: the exact sinusoid.
            if let Some((v, _)) = side
                .disc(f)
                .filter(|_| sweep.abs() <= FRAC_PI_2 && side.keeps(f, m0, sweep))
            {
                let q = v - c;
                b.a1 -= w * q.dot(perp(m0));
                b.a2 += w * w * q.dot(m0);
                b.a3 += w.abs().powi(3) * q.length();
                continue;
            }
            let s_k = if sweep.abs() <= FRAC_PI_2 {
                let (sn, cs) = sin_cos(sweep);
                let m_end = rotate_cs(cs, sn, m0);
                let e = side.feature_of(m_end, f);
                // At a face normal take the face's far end in the direction of the turn.
                -w * (side.support_beyond(e, m_end, w > 0.0) - c).dot(perp(m0))
            } else {
                -w.abs() * r_k
            };
            b.a1 += s_k;
            b.a2 -= w * w * r_k;
        }
        b
    }
}
