//! Time rescaled by a power of two for motions whose rates are far outside the normal range:
//! the time of impact of both trackers is then asked of the same motions on a time scale where
//! the rates are about 1, and its answer brought back.
//!
//! The trackers' step guards bound the distance's second derivative by squares of rates (ω²·r,
//! |ΔV|²): for a pair approaching at 1e-200 m/s and turning at 1e-210 rad/s over a window of
//! 1e210 s they underflow to 0, the bound loses the spin, and a step passes a contact (issue 32:
//! a missed hit of two capsule-ellipses turning half a turn in the window). With t = S·τ, the
//! motion with velocities S·v and spins S·ω over [t₀/S, t₁/S] is the same motion; for S a power
//! of two every input is scaled exactly, and the answer's time is S·τ exactly. Rates within
//! 2^±[`RATE_RANGE`] (about 5e-20 … 2e19 per second, speeds in sizes per second) are left
//! as they are: every ordinary query runs unchanged, to the bit.

use crate::numerics::motion::motion_is_finite;
use crate::query::toi::{TimeOfImpact, TraceEvent, Tracer};
use parry2d_f64::query::NonlinearRigidMotion;

/// Rates (spins in rad/s, speeds in the pair's sizes per second) within 2^±this are left alone.
const RATE_RANGE: i32 = 64;
/// 2^−64: rates above it (and below [`RATE_MAX`]) are left alone without taking their
/// logarithm.
const RATE_MIN: f64 = 5.421010862427522e-20;
/// 2^64.
const RATE_MAX: f64 = 1.8446744073709552e19;

/// The rescaled query: the scale S (a power of two), the motions with rates times S and the
/// window divided by S.
pub(crate) struct Rescaled {
    pub scale: f64,
    pub m1: NonlinearRigidMotion,
    pub m2: NonlinearRigidMotion,
    pub t0: f64,
    pub t1: f64,
}

/// The rescaled query when the fastest rate of the motions (spins, and speeds over `size`) lies
/// outside 2^±[`RATE_RANGE`] and every rescaled input is exact; `None` otherwise (ordinary
/// motions, motions at rest, non-finite input — which the query reports itself).
#[inline]
pub(crate) fn rescaled(
    m1: &NonlinearRigidMotion,
    m2: &NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    size: f64,
) -> Option<Rescaled> {
    // The ordinary case first, in a few comparisons (every query passes here): the largest spin
    // w and speed v with max(w, v/size) within [RATE_MIN, RATE_MAX]. (NaN fails them and goes on
    // to the checks below.)
    let w = m1.angvel.abs().max(m2.angvel.abs());
    let v = m1.linvel.abs().max(m2.linvel.abs()).max_element();
    if w <= RATE_MAX && v <= RATE_MAX * size && (w >= RATE_MIN || v >= RATE_MIN * size) {
        return None;
    }
    rescaled_beyond(m1, m2, t0, t1, size, w, v)
}

/// [`rescaled`] past its ordinary case (at rest, non-finite, or rates beyond 2^±64).
#[cold]
#[inline(never)]
fn rescaled_beyond(
    m1: &NonlinearRigidMotion,
    m2: &NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    size: f64,
    w: f64,
    v: f64,
) -> Option<Rescaled> {
    if !(motion_is_finite(m1) && motion_is_finite(m2) && t0.is_finite() && t1.is_finite() && size > 0.0) {
        return None;
    }
    let rate = w.max(v / size);
    if !(rate > 0.0 && rate.is_finite()) {
        return None;
    }
    let e = rate.log2().round() as i32;
    if e.abs() <= RATE_RANGE {
        return None;
    }
    // 2^−e, built in two halves so that it exists for every e of a finite rate.
    let half = 2f64.powi(-e / 2);
    let scale = half * 2f64.powi(-e - (-e / 2));
    let exact = |x: f64, y: f64| y.is_finite() && (y == 0.0) == (x == 0.0) && y / scale == x;
    let exact_div = |x: f64| {
        let y = x / scale;
        y.is_finite() && (y == 0.0) == (x == 0.0) && y * scale == x
    };
    let scaled = |m: &NonlinearRigidMotion| NonlinearRigidMotion {
        linvel: m.linvel * scale,
        angvel: m.angvel * scale,
        ..*m
    };
    let (s1, s2) = (scaled(m1), scaled(m2));
    let motions_exact = [(m1, &s1), (m2, &s2)]
        .iter()
        .all(|(m, s)| exact(m.linvel.x, s.linvel.x) && exact(m.linvel.y, s.linvel.y) && exact(m.angvel, s.angvel));
    (motions_exact && exact_div(t0) && exact_div(t1)).then(|| Rescaled {
        scale,
        m1: s1,
        m2: s2,
        t0: t0 / scale,
        t1: t1 / scale,
    })
}

impl Rescaled {
    /// The answer of the rescaled query on the original time scale: its time times S, its
    /// rate of distance divided by S.
    pub(crate) fn answer(&self, r: TimeOfImpact) -> TimeOfImpact {
        TimeOfImpact {
            time: r.time * self.scale,
            distance_rate: r.distance_rate / self.scale,
            ..r
        }
    }
}

/// A trace of a rescaled query, recorded on the original time scale.
pub(crate) struct ScaledTrace<'a, T: Tracer> {
    pub inner: &'a mut T,
    pub scale: f64,
}

impl<T: Tracer> Tracer for ScaledTrace<'_, T> {
    fn push(&mut self, e: TraceEvent) {
        let s = self.scale;
        self.inner.push(match e {
            TraceEvent::Start { phi, t, distance } => TraceEvent::Start {
                phi,
                t: t * s,
                distance,
            },
            TraceEvent::Predict { phi, t } => TraceEvent::Predict { phi, t: t * s },
            TraceEvent::Correct { phi, t, side } => TraceEvent::Correct { phi, t: t * s, side },
            TraceEvent::Backtrack { phi, t } => TraceEvent::Backtrack { phi, t: t * s },
            TraceEvent::Accept { phi, t, distance } => TraceEvent::Accept {
                phi,
                t: t * s,
                distance,
            },
            TraceEvent::Impact { phi, t } => TraceEvent::Impact { phi, t: t * s },
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::math::{Pose, Vector};

    #[test]
    fn ordinary_rates_are_left_alone_and_extreme_ones_scaled_exactly() {
        assert_eq!(RATE_MIN, 2f64.powi(-RATE_RANGE));
        assert_eq!(RATE_MAX, 2f64.powi(RATE_RANGE));
        let m = |v: f64, w: f64| {
            NonlinearRigidMotion::new(Pose::translation(1.0, 2.0), Vector::ZERO, Vector::new(v, -v), w)
        };
        assert!(rescaled(&m(3.0, 40.0), &m(0.0, 0.0), 0.0, 1.0, 0.5).is_none());
        assert!(rescaled(&m(0.0, 0.0), &m(0.0, 0.0), 0.0, 1.0, 0.5).is_none());
        assert!(rescaled(&m(1e-30, 0.0), &m(0.0, 1e-18), 0.0, 1.0, 0.5).is_none());
        for (v, t1) in [(1e-200, 1e201), (1e-300, 1e300), (1e200, 1e-199), (1e300, 1e-299)] {
            let r = rescaled(&m(v, 0.0), &m(0.0, 0.0), 0.0, t1, 1.0).expect("rescaled");
            let rate = r.m1.linvel.x.abs();
            assert!((0.5..=2.0).contains(&rate), "{v}: {rate}");
            assert_eq!(r.t1 * r.scale, t1);
            assert_eq!(r.m1.linvel.x / r.scale, v);
        }
        // A window end that would not survive the division: not rescaled.
        assert!(rescaled(&m(1e-300, 0.0), &m(0.0, 0.0), 1e-100, 1.0, 1.0).is_none());
    }
}
