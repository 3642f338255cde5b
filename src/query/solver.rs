//! The root solver of distanceSide at a fixed time, shared by the stationary distance and the
//! time of impact's corrector: a bracket grown from a start, then safeguarded Halley inside it
//! with bisection whenever an iterate leaves the bracket or fails to halve |S| (derivatives jump
//! at piece ends).

use crate::curve::ConvexCurve;
use crate::numerics::motion::PairFrame;
use crate::query::pair::{eval_point, PairPoint};
use core::f64::consts::PI;

/// The first step of a growing bracket is the Newton step |S/S_φ| clamped to
/// [`MIN_BRACKET_STEP`, `MAX_BRACKET_STEP`] (radians) …
const MIN_BRACKET_STEP: f64 = 1e-6;
/// … and no step is longer than this.
const MAX_BRACKET_STEP: f64 = 0.5;
/// The first step when S_φ ≤ 0 (no Newton step to size it).
const BLIND_BRACKET_STEP: f64 = 0.1;
/// Each probe of a growing bracket goes this many steps ahead (overshooting the Newton step).
const BRACKET_REACH: f64 = 1.5;
/// Each step of a growing bracket is this many times the last.
const BRACKET_GROWTH: f64 = 2.0;
/// A growing bracket gives up after this many evaluations of the solver (or a whole turn).
const MAX_BRACKET_EVALUATIONS: usize = 10_000;
/// A bracket narrower than this many ulps of φ has converged.
const BRACKET_ULPS: f64 = 4.0;
/// A Halley iteration that does not bring |S| below this fraction of the last is followed by
/// a bisection.
const HALLEY_PROGRESS: f64 = 0.5;

/// A root solver's state, shared with the time of impact's corrector.
pub(crate) struct Solver<'a, A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized> {
    pub obj1: &'a A,
    pub obj2: &'a B,
    pub frame: PairFrame,
    pub side_tol: f64,
    pub max_iter: usize,
    pub evaluations: usize,
    pub newton: usize,
}

impl<'a, A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized> Solver<'a, A, B> {
    #[inline]
    pub fn eval(&mut self, phi: f64) -> Option<PairPoint> {
        self.evaluations += 1;
        eval_point(self.obj1, self.obj2, &self.frame, phi)
    }

    /// Solves S(φ) = 0 with S increasing, starting at `phi0` whose evaluation is `j0`: grows a
    /// bracket in the direction the sign of S points to, then safeguarded Halley.
    pub fn local_root(&mut self, phi0: f64, j0: PairPoint) -> Option<(f64, PairPoint)> {
        if j0.side.abs() <= self.side_tol {
            return Some((phi0, j0));
        }
        // Grow a bracket: S < 0 ⇒ root ahead; S > 0 ⇒ root behind.
        let dir = if j0.side < 0.0 { 1.0 } else { -1.0 };
        let mut step = if j0.side_p > 0.0 {
            (j0.side.abs() / j0.side_p).clamp(MIN_BRACKET_STEP, MAX_BRACKET_STEP)
        } else {
            BLIND_BRACKET_STEP
        };
        let (mut a, mut ja) = (phi0, j0);
        let mut travelled = 0.0;
        loop {
            let b = a + dir * step * BRACKET_REACH;
            let jb = self.eval(b)?;
            if (jb.side > 0.0) == (dir > 0.0) || jb.side == 0.0 {
                let (lo, jlo, hi, jhi) = if dir > 0.0 { (a, ja, b, jb) } else { (b, jb, a, ja) };
                return self.bracketed_root(lo, jlo, hi, jhi);
            }
            travelled += step * BRACKET_REACH;
            if travelled > 2.0 * PI || self.evaluations > MAX_BRACKET_EVALUATIONS {
                return None;
            }
            a = b;
            ja = jb;
            step = (step * BRACKET_GROWTH).min(MAX_BRACKET_STEP);
        }
    }

    /// Safeguarded Halley on S inside [lo, hi] with S(lo) ≤ 0 ≤ S(hi): each iterate replaces the
    /// end of the bracket with the same sign of S; an iterate outside the bracket, or one after an
    /// iteration that did not halve |S|, is replaced by the midpoint (derivatives jump at piece
    /// ends, where Halley stalls or oscillates).
    pub fn bracketed_root(
        &mut self,
        mut lo: f64,
        mut jlo: PairPoint,
        mut hi: f64,
        mut jhi: PairPoint,
    ) -> Option<(f64, PairPoint)> {
        if jlo.side.abs() <= self.side_tol {
            return Some((lo, jlo));
        }
        if jhi.side.abs() <= self.side_tol {
            return Some((hi, jhi));
        }
        // Start from the end with the smaller |S|.
        let (mut x, mut jx) = if jlo.side.abs() < jhi.side.abs() {
            (lo, jlo)
        } else {
            (hi, jhi)
        };
        // |S| before the last iteration: an iteration that did not halve it is followed by a
        // bisection (the Halley iterate is stalling or oscillating).
        let mut last_s = f64::INFINITY;
        for _ in 0..self.max_iter {
            let (s, s1, s2) = (jx.side, jx.side_p, jx.side_pp);
            let mut cand = f64::NAN;
            if s1 > 0.0 {
                let denom = 2.0 * s1 * s1 - s * s2;
                cand = if denom > 0.0 {
                    x - 2.0 * s * s1 / denom
                } else {
                    x - s / s1
                };
            }
            let use_bisect = !(cand > lo && cand < hi) || s.abs() > HALLEY_PROGRESS * last_s;
            last_s = s.abs();
            if use_bisect {
                cand = 0.5 * (lo + hi);
            } else {
                self.newton += 1;
            }
            let jc = self.eval(cand)?;
            if jc.side.abs() <= self.side_tol || hi - lo <= BRACKET_ULPS * f64::EPSILON * (1.0 + cand.abs()) {
                return Some((cand, jc));
            }
            if jc.side < 0.0 {
                lo = cand;
                jlo = jc;
            } else {
                hi = cand;
                jhi = jc;
            }
            x = cand;
            jx = jc;
        }
        let _ = (jlo, jhi);
        Some((x, jx))
    }
}
