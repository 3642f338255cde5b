//! The end of a query: the refinement of a contact to the time resolution
//! ([`Tracker::refine_hit`]), the back-up of an aimed step that landed beyond the contact, and
//! leaving a separating contact at the start.

use super::corrector::Tol;
use super::guard::{curve_taylor, predict_phi};
use super::{NoTrace, TimeOfImpact, ToiStatus, TraceEvent, Tracer, Tracker};
use crate::curve::ConvexCurve;
use crate::error::QueryError;
use crate::query::pair::PairJet;
use crate::query::stepping::{LeaveWalk, CONTACT_FLOOR, FINE};

/// The refinement of a contact ([`Tracker::refine_hit`]) stops when its next Newton step on D
/// would move the time by less than this fraction of the window: the time is then within about
/// that of the contact (the accuracy tests allow 1e-9; the worst measured is in docs/performance.md).
const REFINE_TIME: f64 = 1e-13;
/// Newton steps on D backwards from an aimed point a hair below the target.
const BACKWARD_NEWTON_STEPS: usize = 4;
/// Newton steps on D from the safe side.
const FORWARD_NEWTON_STEPS: usize = 8;
/// Illinois regula falsi iterations between a safe point and one beyond the contact.
const ILLINOIS_STEPS: usize = 40;

/// Where the walk out of a separating contact at the start ended ([`Tracker::leave_contact`]).
pub(super) enum Leave {
    /// At (t, φ, jet): the distance is above the target, or the shapes approach again while
    /// still in contact.
    At(f64, f64, PairJet),
    /// The window ended with the shapes still in contact and separating: the pair at its end.
    End(PairJet),
}

impl<'a, A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized> Tracker<'a, A, B> {
    /// From a point (t_b, φ_b) of an aimed step that landed beyond the contact (D < δ), back to
    /// where the order-2 Taylor model of D about it reaches the target (Newton when the model has
    /// no root there), corrected to the side tolerance: (t, φ, jet). None when the distance is
    /// not decreasing there or the point would not lie in (t, t_b).
    // Cold, out of the step loop (as `finish`).
    #[inline(never)]
    pub(super) fn back_to_contact<T: Tracer>(
        &mut self,
        t: f64,
        t_b: f64,
        phi_b: f64,
        jb: &PairJet,
        trace: &mut T,
    ) -> Option<(f64, f64, PairJet)> {
        let over = self.opts.target_distance - jb.fwd.v;
        let d1 = jb.fwd.t;
        if !(over > 0.0 && d1 < 0.0) {
            return None;
        }
        let (_, dphi, _) = curve_taylor(jb);
        let d2 = jb.fwd.tt + jb.fwd.pt * dphi;
        // gap + D'u + D''u²/2 = 0 for the u < 0 nearest 0; with v = −u:
        // (D''/2)v² − D'v − over = 0, v = 2·over/(−D' + √(D'² + 2D''·over)).
        let disc = d1 * d1 + 2.0 * d2 * over;
        let v = if disc >= 0.0 {
            2.0 * over / (-d1 + disc.sqrt())
        } else {
            over / -d1
        };
        let tc = t_b - v;
        if !(tc > t && tc < t_b) {
            return None;
        }
        let (p, j) = self.correct(tc, predict_phi(phi_b, jb, -v), Tol::Fixed(self.side_tol), trace)?;
        Some((tc, p, j))
    }

    /// The point at time `t_n` corrected to the side tolerance, predicted from the corrected
    /// point (t, φ, jet) ([`predict_phi`]); untraced (the refinement of a contact).
    pub(super) fn correct_tight_from(&mut self, t: f64, phi: f64, j: &PairJet, t_n: f64) -> Option<(f64, PairJet)> {
        self.correct(
            t_n,
            predict_phi(phi, j, t_n - t),
            Tol::Fixed(self.side_tol),
            &mut NoTrace,
        )
    }

    /// At a point within tolerance of the target, sharpens the contact time: Newton steps on D
    /// from the safe side (a few, while they stay above the target), then, if one lands beyond
    /// the target, Illinois regula falsi on D(t) − δ between the last safe point and that point.
    /// A start a hair below the target (an aimed step, D ≥ δ − 1e-12·s) first takes Newton steps
    /// backwards, never before `t_lo` (the previous accepted point), until one is above it. The
    /// answer is the sample closest to the target among those with D ≥ δ − 1e-12·s (the start
    /// itself when nothing better is found). The bracket is ~gap/|D'| wide, far inside what the
    /// guard would step over, so the root found is the first.
    // Cold, out of the step loop (as `finish`).
    #[inline(never)]
    pub(super) fn refine_hit<T: Tracer>(
        &mut self,
        t_lo: f64,
        t: f64,
        phi: f64,
        j: PairJet,
        trace: &mut T,
    ) -> TimeOfImpact {
        let delta = self.opts.target_distance;
        let floor = -CONTACT_FLOOR * self.size;
        let fine = FINE * self.size;
        let mut best = (t, phi, j);
        let better = |best: &(f64, f64, PairJet), jj: &PairJet| {
            let g = jj.fwd.v - delta;
            g >= floor && g.abs() < (best.2.fwd.v - delta).abs() && jj.side.p > 0.0
        };
        let (mut ts, mut ps, mut js) = (t, phi, j);
        let mut beyond: Option<(f64, f64, f64, PairJet)> = None;
        if j.fwd.v - delta < -fine {
            // An aimed step accepted a hair beyond the target: Newton on D backwards (not before
            // the previous accepted point) until a point above the target brackets the contact.
            let mut safe = None;
            beyond = Some((t, phi, j.fwd.v - delta, j));
            for _ in 0..BACKWARD_NEWTON_STEPS {
                let (g, d1) = (js.fwd.v - delta, js.fwd.t);
                let t_n = (ts - g / d1).max(t_lo);
                if !(d1 < 0.0 && t_n < ts) {
                    break;
                }
                let Some((phi_n, jn)) = self.correct_tight_from(ts, ps, &js, t_n) else {
                    break;
                };
                if better(&best, &jn) {
                    best = (t_n, phi_n, jn);
                }
                let gn = jn.fwd.v - delta;
                if gn >= -fine {
                    if gn > fine {
                        safe = Some((t_n, phi_n, jn));
                    } else {
                        beyond = None;
                    }
                    break;
                }
                beyond = Some((t_n, phi_n, gn, jn));
                (ts, ps, js) = (t_n, phi_n, jn);
            }
            match safe {
                Some(sp) => (ts, ps, js) = sp,
                None => beyond = None,
            }
        }
        // Newton from the safe side, while its step is above the time resolution.
        let t_fine = REFINE_TIME * (self.t1 - self.t0);
        for _ in 0..if beyond.is_some() { 0 } else { FORWARD_NEWTON_STEPS } {
            let gap = js.fwd.v - delta;
            let d1 = js.fwd.t;
            if gap <= fine || d1 >= 0.0 || gap <= t_fine * -d1 {
                break;
            }
            let t_n = (ts - gap / d1).min(self.t1);
            if t_n <= ts {
                break;
            }
            let Some((phi_n, jn)) = self.correct_tight_from(ts, ps, &js, t_n) else {
                break;
            };
            if better(&best, &jn) {
                best = (t_n, phi_n, jn);
            }
            let gn = jn.fwd.v - delta;
            if gn < 0.0 {
                beyond = Some((t_n, phi_n, gn, jn));
                break;
            }
            (ts, ps, js) = (t_n, phi_n, jn);
        }
        if let Some((tb0, pb, gb0, jb)) = beyond.filter(|b| b.2 < -fine) {
            // Illinois regula falsi between (ts, gap > 0) and (tb, gb < 0).
            let (mut ta, mut ga, mut tb, mut gb) = (ts, js.fwd.v - delta, tb0, gb0);
            let mut side = 0i8;
            // The last corrected point, to predict φ at the next sample.
            let mut last = (tb0, pb, jb);
            for _ in 0..ILLINOIS_STEPS {
                let tm = (ta * gb - tb * ga) / (gb - ga);
                if !(tm > ta && tm < tb) {
                    break;
                }
                let Some((pm, jm)) = self.correct_tight_from(last.0, last.1, &last.2, tm) else {
                    break;
                };
                last = (tm, pm, jm);
                if better(&best, &jm) {
                    best = (tm, pm, jm);
                }
                let gm = jm.fwd.v - delta;
                if gm.abs() <= fine {
                    break;
                }
                if gm > 0.0 {
                    (ta, ga) = (tm, gm);
                    if side == 1 {
                        gb *= 0.5;
                    }
                    side = 1;
                } else {
                    (tb, gb) = (tm, gm);
                    if side == -1 {
                        ga *= 0.5;
                    }
                    side = -1;
                }
            }
        }
        trace.push(TraceEvent::Impact {
            phi: self.unwrapped(best.1),
            t: best.0,
        });
        self.result(ToiStatus::Hit, best.0, &best.2)
    }

    /// From a separating contact at t, steps forward until the distance exceeds the target
    /// (returns that point), the shapes start approaching again while still in contact (returns
    /// that point, distance ≤ target), or the window ends ([`Leave::End`], with the last point
    /// the walk reached: the window's end, where the answer `NoHit` reports the distance).
    // Cold, out of the step loop (as `finish`).
    #[inline(never)]
    pub(super) fn leave_contact(&mut self, t: f64, phi: f64, j0: &PairJet) -> Result<Leave, QueryError> {
        let walk = LeaveWalk::new(self.t0, self.t1, &self.opts, self.tol_d);
        let mut last = *j0;
        let left = walk.run((t, phi, *j0), t, (j0.fwd.v, j0.fwd.t), |&(_, phi, _), t_new| {
            let (p2, j2) = self.global_at(t_new, phi, Tol::Fixed(self.side_tol))?;
            self.cost.predictor_steps += 1;
            last = j2;
            Ok(((t_new, self.rewrap(p2), j2), j2.fwd.v, j2.fwd.t))
        })?;
        Ok(match left {
            Some((t2, phi2, j2)) => Leave::At(t2, phi2, j2),
            None => Leave::End(last),
        })
    }
}
