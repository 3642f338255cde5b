//! What the two step loops share — the φ–t tracker of `query::toi` and the gap tracker of
//! `query::gap` (the half-space cast takes the contract's floor too): the `Hit` contract's
//! floor, the sizing of two-sided steps, the refinement's stopping gap, the step under a
//! parabola, and the walk out of a separating contact at the window start.

// The negated comparison (`!(t_new > t)`) is deliberate: it is true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::error::QueryError;
use crate::numerics::motion::motion_is_finite;
use crate::query::toi::ToiOptions;
use parry2d_f64::query::NonlinearRigidMotion;

/// The input checks both trackers start with: `NonFinite` for a motion, a window end or an
/// option that is NaN, infinite or (for a target or tolerance) negative; `EmptyWindow` when the
/// window ends before it starts.
pub(crate) fn check_window(
    m1: &NonlinearRigidMotion,
    m2: &NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    opts: &ToiOptions,
) -> Result<(), QueryError> {
    if !(motion_is_finite(m1) && motion_is_finite(m2) && t0.is_finite() && t1.is_finite()) {
        return Err(QueryError::NonFinite);
    }
    if !opts.is_valid() {
        return Err(QueryError::NonFinite);
    }
    if t1 < t0 {
        return Err(QueryError::EmptyWindow);
    }
    Ok(())
}

/// How far below the target a reported contact may be, relative to the size (the `Hit`
/// contract: D ≥ δ − 1e-12·s).
pub(crate) const CONTACT_FLOOR: f64 = 1e-12;
/// A two-sided (or aimed) step is at most this many guard steps s_A long: the backward bound
/// from its end must cover what the forward one does not.
pub(crate) const EXTENSION: f64 = 2.0;
/// Rounds of the fixed point that sizes a two-sided step from the Taylor model of D
/// (h = (s_A + s_B(h)) / margin).
pub(crate) const EXTENSION_ROUNDS: usize = 3;
/// A two-sided step is s_A + s_B shortened by this factor: room for the model's error, so that
/// the certification after the step usually passes.
pub(crate) const EXTENSION_MARGIN: f64 = 1.1;
/// A two-sided step is tried only when it is at least this many guard steps long (shorter, the
/// plain guard step is as good and needs no certification).
pub(crate) const MIN_EXTENSION: f64 = 1.05;
/// Points closer to the target than this fraction of the size are the contact itself (the
/// refinement stops there).
pub(crate) const FINE: f64 = 1e-15;
/// The first step out of a separating contact at the start is at most this fraction of the
/// window (then doubled each step) …
const LEAVE_FIRST_STEP: f64 = 1.0 / 64.0;
/// … and at least this fraction of it.
const LEAVE_MIN_STEP: f64 = 1e-9;
/// The first step out of a separating contact aims to clear the target by this many distance
/// tolerances.
const LEAVE_CLEARANCE: f64 = 2.0;
/// Each further step out of a separating contact is this many times the last.
const LEAVE_GROWTH: f64 = 2.0;

/// The largest s with gap + slope·s − m·s²/2 ≥ 0: the step that keeps a parabolic lower bound
/// of the distance above the target (infinite when m = 0 ≤ slope).
#[inline]
pub(crate) fn parabola_step(gap: f64, slope: f64, m: f64) -> f64 {
    2.0 * gap / (-slope + (slope * slope + 2.0 * m * gap).sqrt())
}

/// The walk out of a contact at the window start that the motion separates (the target is met
/// at `t0` and D′ > 0 there; only without `stop_at_penetration`).
#[derive(Copy, Clone, Debug)]
pub(crate) struct LeaveWalk {
    /// The window's start and end.
    pub t0: f64,
    pub t1: f64,
    /// The target distance δ and the distance tolerance (absolute).
    pub delta: f64,
    pub tol_d: f64,
    /// Steps at most.
    pub max_steps: usize,
}

impl LeaveWalk {
    /// The walk of a query over `[t0, t1]` with `opts` (target, steps) and the absolute
    /// distance tolerance `tol_d`.
    pub(crate) fn new(t0: f64, t1: f64, opts: &ToiOptions, tol_d: f64) -> Self {
        Self {
            t0,
            t1,
            delta: opts.target_distance,
            tol_d,
            max_steps: opts.max_steps,
        }
    }

    /// From the point `p` at `t` with distance `d` and rate `d1`, steps of growing length until
    /// D is above the target by the tolerance or stops growing (D′ ≤ 0): that point, or `None`
    /// when the window ends first (no hit). The first step aims to clear the target by
    /// [`LEAVE_CLEARANCE`] tolerances along D′, within [`LEAVE_MIN_STEP`] and
    /// [`LEAVE_FIRST_STEP`] of the window; each next one is [`LEAVE_GROWTH`] times the last.
    /// `step(p, t_new)` gives the point at `t_new` with its D and D′.
    pub(crate) fn run<P>(
        &self,
        mut p: P,
        mut t: f64,
        (d, d1): (f64, f64),
        mut step: impl FnMut(&P, f64) -> Result<(P, f64, f64), QueryError>,
    ) -> Result<Option<P>, QueryError> {
        let window = self.t1 - self.t0;
        let mut h = window * LEAVE_FIRST_STEP;
        if d1 > 0.0 {
            h = h.min(((self.delta + LEAVE_CLEARANCE * self.tol_d - d) / d1).max(window * LEAVE_MIN_STEP));
        }
        for _ in 0..self.max_steps {
            if t >= self.t1 {
                return Ok(None);
            }
            let t_new = (t + h).min(self.t1);
            if !(t_new > t) {
                // A window below the resolution of time (h = 0): as an empty window, no hit.
                return Ok(None);
            }
            let (q, d, d1) = step(&p, t_new)?;
            p = q;
            t = t_new;
            if d > self.delta + self.tol_d || d1 <= 0.0 {
                return Ok(Some(p));
            }
            h *= LEAVE_GROWTH;
        }
        Ok(Some(p))
    }
}
