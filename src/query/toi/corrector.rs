//! The corrector: φ solved at fixed t so that S(φ, t) = 0 (Halley's method from the prediction,
//! the bracketed solver when an iteration does not shrink |S|), with the loose tolerance away
//! from contact (module docs of `query::toi`), and the global stationary distance the tracker
//! falls back to.

use super::{TraceEvent, Tracer, Tracker};
use crate::curve::ConvexCurve;
use crate::error::QueryError;
use crate::query::pair::{eval_point, PairJet, PairPoint};
use crate::query::solver::Solver;
use crate::query::stationary::stationary_in_frame;

/// The |S| a correction accepts.
#[derive(Copy, Clone)]
pub(super) enum Tol {
    /// This |S| (the side tolerance).
    Fixed(f64),
    /// A fraction of the gap away from contact ([`Tracker::loose_side`]).
    Loose,
}

/// Halley iterations the corrector tries from the prediction before the bracketed solver.
const HALLEY_TRIES: usize = 4;
/// |S| accepted away from contact, as a fraction of the gap F − δ ([`Tracker::loose_side`]).
const LOOSE_SIDE: f64 = 0.1;
/// Largest F deficit ω₁S²/(2S_φ) an inexact root may cost away from contact, as a fraction of the
/// gap F − δ ([`Tracker::loose_side`]). 2 % took the fewest evaluations at the ellipse medians
/// (0.5 %: 12 at the ellipse–ball median, 2 %: 10; 5 %: shorter guard steps, slower ellipse pairs).
const LOOSE_DEFICIT: f64 = 2e-2;
/// Away from contact the residual's Newton step |S/S_φ| must also stay below this (radians):
/// on a flat piece S can be large while F is exact. The next prediction starts with that step.
const LOOSE_PHI: f64 = 3e-1;
/// Largest Halley step of the corrector (radians): beyond it, or when a step does not shrink |S|,
/// the bracketed solver takes over. 1 rad instead of 0.3 let the corrector converge from the
/// poorer predictions of long steps (5 % fewer instructions over the ellipse pairs' hits).
const HALLEY_MAX_STEP: f64 = 1.0;

impl<'a, A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized> Tracker<'a, A, B> {
    /// Global stationary distance at t starting from φ: (φ, full jet). The local solve comes
    /// first, as in [`stationary_in_frame`]: a root of S with F > 0 is the global maximum, and its
    /// jet is kept; otherwise the full search runs, from that root.
    // Cold, out of the step loop (as `finish`).
    #[inline(never)]
    pub(super) fn global_at(&mut self, t: f64, phi: f64, tol: Tol) -> Result<(f64, PairJet), QueryError> {
        let frame = self.frame(t);
        let mut sv = Solver {
            side_tol: self.opts.distance.side_tolerance * self.size,
            max_iter: self.opts.distance.max_local_iterations,
            ..self.solver(frame)
        };
        let local = self.solve(&mut sv, phi, tol);
        self.cost.evaluations += sv.evaluations;
        self.cost.corrector_iterations += sv.evaluations.saturating_sub(1);
        if let Some((p, j)) = local.filter(|(_, j)| j.fwd > 0.0) {
            if let Some(j) = j.jet(&frame) {
                return Ok((p, j));
            }
        }
        // The full search starts its own local solve from the root just found (a penetration: a
        // local maximum of F ≤ 0, which it certifies or not), not from φ again: the bracket
        // grown to it would be grown twice (a third of the evaluations of a deep start).
        let phi0 = local.map_or(phi, |(p, _)| p);
        let r = stationary_in_frame(self.obj1, self.obj2, frame, phi0, &self.opts.distance)?;
        self.cost.evaluations += r.evaluations;
        self.cost.corrector_iterations += r.newton_iterations;
        self.cost.evaluations += 1;
        let j = eval_point(self.obj1, self.obj2, &frame, r.phi)
            .and_then(|p| p.jet(&frame))
            .ok_or(QueryError::Degenerate)?;
        Ok((r.phi, j))
    }

    /// Whether the point `j` is accepted as a root of S under `tol` ([`Tol`]).
    #[inline]
    pub(super) fn accepts(&self, tol: Tol, j: &PairPoint) -> bool {
        let (s, s1) = (j.side.abs(), j.side_p);
        s1 > 0.0
            && match tol {
                Tol::Fixed(x) => s <= x,
                Tol::Loose => s <= self.loose_side(j) && s <= LOOSE_PHI * s1,
            }
    }

    /// The |S| handed to the bracketed solver under `tol`, judged at the point `j`.
    #[inline]
    pub(super) fn bracket_tol(&self, tol: Tol, j: &PairPoint) -> f64 {
        match tol {
            Tol::Fixed(x) => x,
            Tol::Loose => {
                if j.side_p > 0.0 {
                    self.loose_side(j).min(LOOSE_PHI * j.side_p).max(self.side_tol)
                } else {
                    self.side_tol
                }
            }
        }
    }

    /// The |S| accepted away from contact at the point `j`, never below the side tolerance.
    ///
    /// F_φ = −ω₁S (ω₁ = N × N'), so about the root φ* (S ≈ S_φ·(φ − φ*)) an inexact root costs
    /// F(φ) ≈ D − ω₁S²/(2S_φ). Away from contact (gap F − δ above twice the distance tolerance)
    /// |S| is accepted while that deficit stays below `LOOSE_DEFICIT` of the gap; always, |S| up
    /// to `LOOSE_SIDE` of the gap (the deficit is then ≤ S²/(2·gap) ≤ 0.5 % of the gap, since
    /// S_φ/ω₁ ≈ ρ₁ + ρ₂ + F ≥ gap). Within twice the distance tolerance only the second holds, so
    /// it tightens by itself to the side tolerance as the contact nears and the contact decisions
    /// are taken on nearly exact roots. A lower F only shortens the next guard step a little; the
    /// guard itself does not depend on it: F(φ, t) at any φ is a lower bound on the distance.
    #[inline]
    pub(super) fn loose_side(&self, j: &PairPoint) -> f64 {
        let gap = j.fwd - self.opts.target_distance;
        let by_gap = LOOSE_SIDE * gap;
        let w = j.curve1.normal_turn_rate();
        let by_deficit = if gap > 2.0 * self.tol_d && w > 0.0 && j.side_p > 0.0 {
            (2.0 * LOOSE_DEFICIT * gap * j.side_p / w).sqrt()
        } else {
            0.0
        };
        by_gap.max(by_deficit).max(self.side_tol)
    }

    /// Solves S(φ) = 0 at the solver's fixed time from `phi`: Halley iterations (cubic
    /// convergence: none or one after an order-2 prediction), falling back to the bracketed
    /// solver of the stationary distance when an iteration does not shrink |S| or would move φ
    /// by more than `HALLEY_MAX_STEP`. Returns the root (S_φ > 0) and its evaluation.
    pub(super) fn solve(&self, sv: &mut Solver<A, B>, phi: f64, tol: Tol) -> Option<(f64, PairPoint)> {
        let mut j = sv.eval(phi)?;
        let x = self.solve_from(sv, phi, &mut j, tol)?;
        Some((x, j))
    }

    /// As [`Tracker::solve`] from an already evaluated point `j` at `phi`, in place: on success
    /// `j` holds the root's evaluation and the root is returned. (In place because the points
    /// are large: passing them by value cost a copy per call and per iteration.)
    #[inline(never)]
    pub(super) fn solve_from(&self, sv: &mut Solver<A, B>, phi: f64, j: &mut PairPoint, tol: Tol) -> Option<f64> {
        let mut x = phi;
        for _ in 0..HALLEY_TRIES {
            if self.accepts(tol, j) {
                return Some(x);
            }
            let (s, s1, s2) = (j.side, j.side_p, j.side_pp);
            if !(s1 > 0.0) {
                break;
            }
            let denom = 2.0 * s1 * s1 - s * s2;
            let step = if denom > 0.0 { -2.0 * s * s1 / denom } else { -s / s1 };
            if !(step.abs() <= HALLEY_MAX_STEP) {
                break;
            }
            let Some(jn) = sv.eval(x + step) else { break };
            if !(jn.side.abs() < s.abs()) {
                // Not converging (a piece end, a far root): bracket between the two if S
                // changes sign, otherwise start the bracketed solver from the better point.
                if (jn.side > 0.0) != (s > 0.0) {
                    sv.side_tol = self.bracket_tol(tol, if jn.fwd < j.fwd { &jn } else { j });
                    let r = if step > 0.0 {
                        sv.bracketed_root(x, *j, x + step, jn)
                    } else {
                        sv.bracketed_root(x + step, jn, x, *j)
                    };
                    let (xr, jr) = r?;
                    *j = jr;
                    return Some(xr);
                }
                break;
            }
            x += step;
            *j = jn;
        }
        if self.accepts(tol, j) {
            return Some(x);
        }
        sv.side_tol = self.bracket_tol(tol, j);
        let (xr, jr) = sv.local_root(x, *j)?;
        *j = jr;
        Some(xr)
    }

    /// Corrects φ at fixed t ([`Tracker::solve`]); returns the root and its full jet.
    ///
    /// Always inlined: the library's own copy of the step loop otherwise calls it and moves
    /// its large answer through memory (through `SmoothDispatcher`, 2.5 % more time per
    /// ellipse–disc query; the direct generic call, compiled in the caller's crate, is about
    /// 1.5 % faster without it).
    #[inline(always)]
    pub(super) fn correct<T: Tracer>(&mut self, t: f64, phi: f64, tol: Tol, trace: &mut T) -> Option<(f64, PairJet)> {
        let frame = self.frame(t);
        let mut sv = self.solver(frame);
        let mut p = sv.eval(phi);
        let root = p.as_mut().and_then(|p| self.solve_from(&mut sv, phi, p, tol));
        self.cost.evaluations += sv.evaluations;
        // The first evaluation is the prediction itself; the rest are Halley/bisection steps.
        self.cost.corrector_iterations += sv.evaluations.saturating_sub(1);
        let phi = root?;
        let j = p.as_ref()?.jet(&frame)?;
        trace.push(TraceEvent::Correct {
            phi: self.unwrapped(phi),
            t,
            side: j.side.v,
        });
        Some((phi, j))
    }
}
