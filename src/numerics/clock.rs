//! The translation clock of a motion path: when the rotation is uniform in time, how far the
//! translation has got. For parry's `NonlinearRigidMotion` (constant spin, constant velocity) the
//! clock is time itself; for the *nlerp path* ([`crate::MotionPath::Nlerp`], parry's `Sweep` and
//! rapier's clamp: the rotation centre moves on a straight line at constant speed while the
//! rotation is a normalised linear interpolation between the window's end rotations) it runs
//! unevenly.
//!
//! ## The nlerp path in a uniform-rotation clock
//!
//! Let the rotation turn by Δ over the window (|Δ| < π: nlerp takes the short way round), k =
//! tan(Δ/2). At the fraction s of the window the nlerp rotation is the direction of the chord
//! point (1 − s)·q₀ + s·q₁; measured from the chord's midpoint direction its angle w satisfies
//! tan w = (2s − 1)·k, so the rotation angle is Δ/2 + w. Read the other way, with u the fraction
//! of the rotation done (angle u·Δ, w = (2u − 1)·Δ/2), the translation has done the fraction
//!
//! ```text
//! σ(u) = ½ + ½·tan(w)/k,          σ(0) = 0, σ(1) = 1, σ increasing,
//! σ'(u)   = (Δ/2k)·sec²w,
//! σ''(u)  = (Δ²/k)·sec²w·tan w,
//! σ'''(u) = (Δ³/k)·sec²w·(1 + 3 tan²w).
//! ```
//!
//! So the nlerp path *is* a rigid motion with uniform rotation (angular velocity Δ/T over a
//! window of length T) whose rotation centre runs along its straight segment on the clock
//! τ(t) = t₀ + T·σ((t − t₀)/T). The trackers take the clock's value and first two derivatives at
//! each time and bounds of its first three derivatives over a step: |σ'|, |σ''| and |σ'''| grow
//! with |w|, so over an interval of u their largest values sit at the end with the larger |w|.
//! A contact found at the clock time t is at the path's fraction σ((t − t₀)/T), the time rapier
//! clamps to.
//!
//! As |Δ| → π the nlerp rotation concentrates in the middle of the window (k → ∞): σ stays near
//! ½ for most of the rotation and its derivatives at the ends grow like sec²(Δ/2). The paths
//! closer to π than [`NLERP_HALF_TURN`] are not clocked this way ([`Clock::nlerp`] answers
//! `None`); the caller takes the path of a turn of π − [`NLERP_HALF_TURN`] for them
//! (`query::path`), which has its clock.

use core::f64::consts::PI;

/// Turns Δ closer than this to a half turn are taken as a turn of π − NLERP_HALF_TURN by the
/// caller instead of clocked:
/// there σ′ at the window's ends exceeds about 1/NLERP_HALF_TURN² (the nlerp rotation happens
/// almost at once in the middle of the window), and the guards' steps would shrink with it.
pub(crate) const NLERP_HALF_TURN: f64 = 1e-6;

/// A translation clock (module docs): identity, or the nlerp path's σ over a window.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct Clock {
    /// Window start and 1/T.
    t0: f64,
    inv_t: f64,
    /// T.
    span: f64,
    /// Δ/2 and k = tan(Δ/2).
    half: f64,
    k: f64,
    /// The constants of [`Clock::clock_of_path_bounds`], computed once a clock as it computed
    /// them every call: |k/h|, the peak x = 1/(√3·|k|) of x/(1 + x²k²)² and its value there.
    kh: f64,
    peak: f64,
    peak_g: f64,
}

/// x/(1 + x²k²)², the shape of |d²u/dτ²| in x ([`Clock::clock_of_path_bounds`]; `k` ≥ 0).
#[inline]
fn rate_slope(x: f64, k: f64) -> f64 {
    x / ((1.0 + x * x * k * k) * (1.0 + x * x * k * k))
}

/// The clock's value and first two derivatives at one time: τ, τ′ = dτ/dt, τ″.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct ClockJet {
    pub tau: f64,
    pub d1: f64,
    pub d2: f64,
}

/// Bounds over an interval of the clock's first three derivatives (in time): max τ′, max |τ″|,
/// max |τ‴|.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct ClockBounds {
    pub d1: f64,
    pub d2: f64,
    pub d3: f64,
}

impl ClockBounds {
    /// The identity clock's: τ′ = 1, τ″ = τ‴ = 0.
    pub(crate) const IDENTITY: ClockBounds = ClockBounds {
        d1: 1.0,
        d2: 0.0,
        d3: 0.0,
    };
}

impl Clock {
    /// The clock of the nlerp path that turns by `delta` (radians, |Δ| < π) over the window
    /// [`t0`, `t1`]; `None` when the path needs no clock (Δ = 0, an empty window) or cannot have
    /// one (|Δ| closer to π than [`NLERP_HALF_TURN`], or not finite). A turn of exactly
    /// π − [`NLERP_HALF_TURN`] has its clock: `query::path` takes that turn for the paths closer
    /// to a half turn.
    pub(crate) fn nlerp(delta: f64, t0: f64, t1: f64) -> Option<Clock> {
        let span = t1 - t0;
        if delta == 0.0 || !(span > 0.0 && span.is_finite() && delta.abs() <= PI - NLERP_HALF_TURN) {
            return None;
        }
        let half = 0.5 * delta;
        let k = libm::tan(half);
        let peak = 1.0 / (3.0f64.sqrt() * k.abs());
        Some(Clock {
            t0,
            inv_t: 1.0 / span,
            span,
            half,
            k,
            kh: (k / half).abs(),
            peak,
            peak_g: rate_slope(peak, k.abs()),
        })
    }

    /// w = (2u − 1)·Δ/2 at time `t` (u clamped to [0, 1]).
    #[inline]
    fn w(&self, t: f64) -> f64 {
        let u = ((t - self.t0) * self.inv_t).clamp(0.0, 1.0);
        (2.0 * u - 1.0) * self.half
    }

    /// σ at time `t`: the fraction of the translation done.
    #[inline]
    pub(crate) fn fraction(&self, t: f64) -> f64 {
        let w = self.w(t);
        if w == -self.half {
            return 0.0;
        }
        if w == self.half {
            return 1.0;
        }
        0.5 + 0.5 * libm::tan(w) / self.k
    }

    /// The clock's value and derivatives at time `t`.
    #[inline]
    pub(crate) fn jet(&self, t: f64) -> ClockJet {
        let w = self.w(t);
        let tw = libm::tan(w);
        let sec2 = 1.0 + tw * tw;
        let sigma = if w == -self.half {
            0.0
        } else if w == self.half {
            1.0
        } else {
            0.5 + 0.5 * tw / self.k
        };
        // d/dt = (1/T)·d/du.
        let d1 = self.half / self.k * sec2;
        let d2 = 4.0 * self.half * self.half / self.k * sec2 * tw * self.inv_t;
        ClockJet {
            tau: self.t0 + self.span * sigma,
            d1,
            d2,
        }
    }

    /// Bounds of τ′, |τ″| and |τ‴| over the times between `ta` and `tb` (either order).
    pub(crate) fn bounds(&self, ta: f64, tb: f64) -> ClockBounds {
        let w = self.w(ta).abs().max(self.w(tb).abs());
        // At the same |w| on both sides of the middle when the interval straddles it: the
        // derivatives grow with |w|, so the end with the larger |w| bounds them.
        let tw = libm::tan(w);
        let sec2 = 1.0 + tw * tw;
        let hk = (self.half / self.k).abs();
        let h2 = 4.0 * self.half * self.half;
        ClockBounds {
            d1: hk * sec2,
            d2: h2 / self.k.abs() * sec2 * tw * self.inv_t,
            d3: 2.0 * h2 * self.half.abs() / self.k.abs() * sec2 * (1.0 + 3.0 * tw * tw) * self.inv_t * self.inv_t,
        }
    }

    /// The clock time at which the translation has done the fraction `s` ∈ [0, 1] (σ⁻¹).
    #[cfg(test)]
    pub(crate) fn time_of_fraction(&self, s: f64) -> f64 {
        let s = s.clamp(0.0, 1.0);
        let w = libm::atan((2.0 * s - 1.0) * self.k);
        let u = (0.5 + 0.5 * w / self.half).clamp(0.0, 1.0);
        self.t0 + self.span * u
    }

    /// The clock time u at the *path* time `tau` (σ⁻¹: where the rotation, uniform in the clock,
    /// has got when the translation has done the fraction s = (τ − t₀)/T), with du/dτ and
    /// d²u/dτ². With x = 2s − 1 and h = Δ/2, k = tan h:
    ///
    /// ```text
    /// u = t₀ + T/2 + (T/2h)·atan(x·k),
    /// du/dτ = (k/h) / (1 + x²k²),
    /// d²u/dτ² = −(4k³x / (h·T)) / (1 + x²k²)².
    /// ```
    ///
    /// So a rotation uniform in the clock, θ = θ₀ + ω·u, is the nlerp rotation in path time
    /// (θ′ = 2k/(T(1 + x²k²)) with ω = 2h/T, the largest at the middle of the window). The
    /// advancement takes the rotation without the arc tangent ([`Clock::turn_of_path`]); this
    /// form checks it.
    #[cfg(test)]
    pub(crate) fn clock_of_path(&self, tau: f64) -> (f64, f64, f64) {
        let x = (2.0 * (tau - self.t0) * self.inv_t - 1.0).clamp(-1.0, 1.0);
        let q = 1.0 + x * x * self.k * self.k;
        let u = self.t0 + 0.5 * self.span + 0.5 * self.span / self.half * libm::atan(x * self.k);
        let d1 = self.k / self.half / q;
        let d2 = -4.0 * self.k * self.k * self.k * x / (self.half * self.span * q * q);
        (u, d1, d2)
    }

    /// The nlerp rotation at the *path* time `tau` measured from the middle of the window, as the
    /// tangent of its angle, y = x·k (the angle is atan(x·k) = ω·(u − t₀ − T/2), with x and u
    /// as in `Clock::clock_of_path`), and du/dτ = (k/h)/(1 + y²): no trigonometric function.
    #[inline]
    pub(crate) fn turn_of_path(&self, tau: f64) -> (f64, f64) {
        let x = (2.0 * (tau - self.t0) * self.inv_t - 1.0).clamp(-1.0, 1.0);
        let y = x * self.k;
        (y, self.k / self.half / (1.0 + y * y))
    }

    /// How much the nlerp turning rate varies over the window: its largest over its least
    /// value, 1 + k² (du/dτ = (k/h)/(1 + x²k²) over x ∈ [−1, 1]).
    pub(crate) fn rate_spread(&self) -> f64 {
        1.0 + self.k * self.k
    }

    /// The clock time at the middle of the window, t₀ + T/2 (where the nlerp rotation is at
    /// half its turn).
    pub(crate) fn middle(&self) -> f64 {
        self.t0 + 0.5 * self.span
    }

    /// Bounds of |du/dτ| and |d²u/dτ²| (`Clock::clock_of_path`) for path times between `ta`
    /// and `tb` (either order): |du/dτ| is largest at the x of least |x|, |d²u/dτ²| ∝
    /// |x|/(1 + x²k²)² grows up to |x| = 1/(√3·|k|) and falls after.
    pub(crate) fn clock_of_path_bounds(&self, ta: f64, tb: f64) -> (f64, f64) {
        let x_at = |t: f64| (2.0 * (t - self.t0) * self.inv_t - 1.0).clamp(-1.0, 1.0);
        let (x_ta, x_tb) = (x_at(ta), x_at(tb));
        let (xa, xb) = (x_ta.min(x_tb), x_ta.max(x_tb));
        let k = self.k.abs();
        let kh = self.kh;
        let least = if xa <= 0.0 && xb >= 0.0 {
            0.0
        } else {
            xa.abs().min(xb.abs())
        };
        let d1 = kh / (1.0 + least * least * k * k);
        let g = |x: f64| rate_slope(x, k);
        let peak = self.peak;
        let (lo, hi) = if xb <= 0.0 {
            (-xb, -xa)
        } else if xa >= 0.0 {
            (xa, xb)
        } else {
            (0.0, (-xa).max(xb))
        };
        let top = if peak >= lo && peak <= hi {
            self.peak_g
        } else {
            g(lo).max(g(hi))
        };
        let d2 = 4.0 * k * k * kh * top * self.inv_t;
        (d1, d2)
    }

    /// The path's time (window start + fraction × window) of the clock time `t`.
    pub(crate) fn path_time(&self, t: f64) -> f64 {
        self.t0 + self.span * self.fraction(t)
    }
}

/// The clock of a path as the trackers see it: the identity (`None`) or a [`Clock`].
pub(crate) trait ClockExt {
    /// Bounds of the derivatives between `ta` and `tb`.
    fn bounds_over(&self, ta: f64, tb: f64) -> ClockBounds;
}

impl ClockExt for Option<Clock> {
    #[inline]
    fn bounds_over(&self, ta: f64, tb: f64) -> ClockBounds {
        match self {
            None => ClockBounds::IDENTITY,
            Some(c) => c.bounds(ta, tb),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The nlerp rotation angle at the fraction s of a turn by Δ (parry's `Sweep::transform_at`).
    fn nlerp_angle(delta: f64, s: f64) -> f64 {
        let (x, y) = ((1.0 - s) + s * delta.cos(), s * delta.sin());
        y.atan2(x)
    }

    /// The clock of a path time is the nlerp rotation, uniform in the clock: its angle, its
    /// derivatives (against central differences) and their bounds over intervals (against
    /// dense sampling).
    #[test]
    fn the_clock_of_a_path_time_is_the_nlerp_rotation_with_its_derivatives_and_bounds() {
        for delta in [1e-6, 0.1, -0.7, core::f64::consts::FRAC_PI_4, 2.0, -3.0, 3.1] {
            let (t0, span) = (2.0, 0.5);
            let c = Clock::nlerp(delta, t0, t0 + span).unwrap();
            let omega = delta / span;
            for i in 0..=200 {
                let s = i as f64 / 200.0;
                let tau = t0 + span * s;
                let (u, d1, d2) = c.clock_of_path(tau);
                let angle = omega * (u - t0);
                assert!((angle - nlerp_angle(delta, s)).abs() < 1e-12, "Δ {delta} s {s}");
                if i > 0 && i < 200 {
                    let e = 1e-6;
                    let (up, _, _) = c.clock_of_path(tau + e);
                    let (um, _, _) = c.clock_of_path(tau - e);
                    let (_, d1p, _) = c.clock_of_path(tau + e);
                    let (_, d1m, _) = c.clock_of_path(tau - e);
                    assert!(
                        ((up - um) / (2.0 * e) - d1).abs() < 1e-5 * (1.0 + d1.abs()),
                        "Δ {delta} s {s}"
                    );
                    assert!(
                        ((d1p - d1m) / (2.0 * e) - d2).abs() < 1e-4 * (1.0 + d2.abs()),
                        "Δ {delta} s {s}"
                    );
                }
            }
            // The same rotation without the arc tangent: tan(ω·(u − t₀ − T/2)) and du/dτ.
            let mid = c.middle();
            assert_eq!(mid, t0 + 0.5 * span);
            for i in 0..=200 {
                let tau = t0 + span * i as f64 / 200.0;
                let (u, d1, _) = c.clock_of_path(tau);
                let (y, e1) = c.turn_of_path(tau);
                let angle = omega * (u - mid);
                assert!(
                    (y.atan() - angle).abs() <= 1e-12 * (1.0 + angle.abs()),
                    "Δ {delta} τ {tau}"
                );
                assert!((e1 - d1).abs() <= 1e-12 * d1.abs(), "Δ {delta} τ {tau}");
            }
            for (a, b) in [(0.0, 1.0), (0.0, 0.3), (0.6, 0.9), (0.45, 0.55), (0.9, 1.0)] {
                let (ta, tb) = (t0 + span * a, t0 + span * b);
                let (m1, m2) = c.clock_of_path_bounds(ta, tb);
                for i in 0..=1000 {
                    let tau = ta + (tb - ta) * i as f64 / 1000.0;
                    let (_, d1, d2) = c.clock_of_path(tau);
                    assert!(d1.abs() <= m1 * (1.0 + 1e-12), "Δ {delta} [{a}, {b}]");
                    assert!(d2.abs() <= m2 * (1.0 + 1e-12) + 1e-12, "Δ {delta} [{a}, {b}]");
                }
            }
        }
    }

    #[test]
    fn the_clock_turns_uniformly_where_nlerp_has_done_the_fraction_sigma() {
        for delta in [1e-6, 0.1, -0.7, core::f64::consts::FRAC_PI_4, 2.0, -3.0, 3.1] {
            let c = Clock::nlerp(delta, 2.0, 2.5).unwrap();
            for i in 0..=200 {
                let u = i as f64 / 200.0;
                let t = 2.0 + 0.5 * u;
                let s = c.fraction(t);
                // At the translation's fraction s, nlerp's angle is u·Δ.
                let err = (nlerp_angle(delta, s) - u * delta).abs();
                assert!(err <= 1e-12 * delta.abs().max(1.0), "Δ {delta} u {u}: {err}");
                // And back.
                assert!((c.time_of_fraction(s) - t).abs() <= 1e-9, "Δ {delta} u {u}");
            }
            assert_eq!(c.fraction(2.0), 0.0);
            assert_eq!(c.fraction(2.5), 1.0);
        }
    }

    #[test]
    fn the_clock_derivatives_match_finite_differences_and_stay_within_their_bounds() {
        for delta in [0.3, -1.2, 2.5] {
            let (t0, t1) = (0.0, 0.2);
            let c = Clock::nlerp(delta, t0, t1).unwrap();
            let b = c.bounds(t0, t1);
            for i in 1..100 {
                let t = 0.2 * i as f64 / 100.0;
                let h = 1e-6;
                let j = c.jet(t);
                let (jm, jp) = (c.jet(t - h), c.jet(t + h));
                assert!((j.d1 - (jp.tau - jm.tau) / (2.0 * h)).abs() <= 1e-6 * j.d1.abs().max(1.0));
                assert!((j.d2 - (jp.d1 - jm.d1) / (2.0 * h)).abs() <= 1e-5 * j.d2.abs().max(1.0));
                let d3 = (jp.d2 - jm.d2) / (2.0 * h);
                assert!(j.d1 > 0.0 && j.d1 <= b.d1 * (1.0 + 1e-12));
                assert!(j.d2.abs() <= b.d2 * (1.0 + 1e-12));
                assert!(d3.abs() <= b.d3 * (1.0 + 1e-6), "Δ {delta} t {t}: {d3} > {}", b.d3);
                // Over a sub-interval the bound is the larger end's.
                let bs = c.bounds(t, t + 0.01);
                assert!(bs.d1 >= j.d1 * (1.0 - 1e-12) && bs.d1 <= b.d1 * (1.0 + 1e-12));
            }
        }
    }

    #[test]
    fn no_clock_for_no_turn_or_a_half_turn() {
        assert!(Clock::nlerp(0.0, 0.0, 1.0).is_none());
        assert!(Clock::nlerp(PI, 0.0, 1.0).is_none());
        assert!(Clock::nlerp(-PI + 0.5 * NLERP_HALF_TURN, 0.0, 1.0).is_none());
        // The turn the caller takes for those closer to a half turn has its clock.
        assert!(Clock::nlerp(-(PI - NLERP_HALF_TURN), 0.0, 1.0).is_some());
        assert!(Clock::nlerp(1.0, 1.0, 1.0).is_none());
        assert!(Clock::nlerp(f64::NAN, 0.0, 1.0).is_none());
    }
}
