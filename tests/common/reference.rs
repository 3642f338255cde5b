//! An independent, exact reference for the signed distance and the time of impact of two convex
//! shapes, built only on the shapes' support functions (`ConvexCurve::support_point`) and parry's
//! `NonlinearRigidMotion::position_at_time`. It shares no code with the crate's distance,
//! stationary-distance or time-of-impact algorithms.
//!
//! # Distance
//!
//! For a unit direction n = (cos θ, sin θ) the gap along n is
//! g(θ) = −h₁(n) − h₂(−n), with h the world-frame support function
//! h(n) = s(Rᵀn)·(Rᵀn) + p·n (s the shape's `support_point`, (R, p) its pose). Every g(θ) is a
//! lower bound on the signed distance D and D = max_θ g(θ). Where g > 0 it is concave in θ on a
//! single arc (a minimum of cosines each within ±π/2 of its peak), so a local maximum with g > 0 is
//! the global one.
//!
//! [`reference_distance`] samples g at [`FULL_SAMPLES`] directions, then refines every discrete
//! local maximum (the best [`MAX_PEAKS`]) by golden-section search down to a bracket of
//! ~2e-15 rad: the value is then exact to round-off for smooth maxima and to ~1e-15·size at the
//! kinks a sharp polygon face produces.
//!
//! # Time of impact
//!
//! [`reference_toi`] is conservative advancement on D: D is Lipschitz in time with constant
//! V = |v₁ − v₂| + |ω₁|·r₁ + |ω₂|·r₂ (r_i = `bounding_radius()` + |local_center|, the largest distance
//! from the rotation centre to the boundary), so from a time t with gap Δ = D(t) − δ > 0 the
//! interval [t, t + Δ/V) holds no contact. By default the step uses the tighter directional rate
//! V_n = max(0, −(v₂ − v₁)·n) + |ω₁|·r₁ + |ω₂|·r₂ ≤ V, n the direction of the current gap sample:
//! the gap along a *fixed* world direction n decreases at most that fast (translation moves it by
//! exactly (v₂ − v₁)·n, rotation moves each support point by at most |ω_i|·r_i), and it is a lower
//! bound on D. [`RefToiOptions::directional`] = false gives the plain V.
//! The advancement stops when Δ < tol (`tol_rel` × size) and the crossing is then bracketed by
//! forward probes and bisected down to ~1e-16 of the time scale (inside such a short bracket D is
//! monotone: a second crossing would need |D''| ~ 1e13 × the motions' bound).
//!
//! Speed-ups (none weakens the guarantee):
//! * away from contact the step uses a *lower bound* on D (any g(θ) is one): a warm-started local
//!   golden-section search from the previous best direction, stopped once the concave upper bound
//!   on the bracket is within 5 % of the gap ([`RefToiOptions::lower_bound_slack`]);
//! * when that lower bound falls under tol the distance is computed precisely (warm-started
//!   local search converged to 2e-15 rad, accepted only when its value is > 0, where the
//!   concavity theorem makes it global; otherwise the full resample);
//! * a full resample ([`FULL_SAMPLES`] directions) every [`RefToiOptions::resample_every`]
//!   steps anyway, and at the start.

use core::f64::consts::{PI, TAU};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::sweep_toi::Sweep;
use parry2d_f64::query::NonlinearRigidMotion;
use smooth_ccd2d::ConvexCurve;

/// Number of directions sampled by the full (cold) distance search.
pub const FULL_SAMPLES: usize = 720;
/// How many discrete local maxima of the samples the full search refines.
pub const MAX_PEAKS: usize = 8;
/// The bracket width (radians) at which golden-section refinement stops in precise mode.
pub const ANGLE_TOL: f64 = 2e-15;

const GOLDEN: f64 = 0.381_966_011_250_105_1; // (3 − √5)/2

/// The world-frame support function h(n) = max over the shape at `pose` of x·n, for a unit `n`.
pub fn world_support(shape: &dyn ConvexCurve, pose: &Pose, n: Vector) -> f64 {
    let local = pose.rotation.inverse_transform_vector(n);
    shape.support_point(local).dot(local) + pose.translation.dot(n)
}

/// The gap along the unit direction `n` (pointing from shape 1 towards shape 2):
/// g(n) = −h₁(n) − h₂(−n). A lower bound on the signed distance; its maximum over n is the
/// signed distance.
pub fn gap_along(shape1: &dyn ConvexCurve, pose1: &Pose, shape2: &dyn ConvexCurve, pose2: &Pose, n: Vector) -> f64 {
    -world_support(shape1, pose1, n) - world_support(shape2, pose2, -n)
}

/// A signed distance with the direction that realises it.
#[derive(Copy, Clone, Debug)]
pub struct RefDistance {
    /// Signed distance: Euclidean distance when apart, minus the penetration depth when
    /// overlapping.
    pub distance: f64,
    /// Angle θ of the maximising direction n = (cos θ, sin θ), from shape 1 towards shape 2.
    pub angle: f64,
    /// The maximising direction n.
    pub normal: Vector,
    /// Number of support-function pairs evaluated.
    pub evals: u64,
}

/// Evaluates g(θ) for two fixed poses, counting evaluations.
struct Gap<'a> {
    s1: &'a dyn ConvexCurve,
    s2: &'a dyn ConvexCurve,
    p1: Pose,
    p2: Pose,
    evals: u64,
}

impl<'a> Gap<'a> {
    fn new(s1: &'a dyn ConvexCurve, p1: Pose, s2: &'a dyn ConvexCurve, p2: Pose) -> Self {
        Self {
            s1,
            s2,
            p1,
            p2,
            evals: 0,
        }
    }

    #[inline]
    fn at(&mut self, theta: f64) -> f64 {
        self.evals += 1;
        let (s, c) = theta.sin_cos();
        let n = Vector::new(c, s);
        gap_along(self.s1, &self.p1, self.s2, &self.p2, n)
    }

    /// Golden-section search on a bracketing triple a < b < c with f(b) ≥ f(a), f(c).
    /// Stops when c − a < `ANGLE_TOL`, or — when `stop` is `Some((delta, slack))` and
    /// f(b) > delta — once the concave upper bound U on the bracket satisfies
    /// U − f(b) ≤ slack·(f(b) − delta). Returns (θ, g(θ)) of the best point.
    fn golden(&mut self, mut t: [f64; 3], mut f: [f64; 3], stop: Option<(f64, f64)>) -> (f64, f64) {
        for _ in 0..200 {
            let [a, b, c] = t;
            let [fa, fb, fc] = f;
            if c - a < ANGLE_TOL {
                break;
            }
            if let Some((delta, slack)) = stop {
                if fb > delta && b > a && c > b {
                    // Concave f lies below the extensions of its chords outside them.
                    let u1 = fb + (fb - fc) * (b - a) / (c - b);
                    let u2 = fb + (fb - fa) * (c - b) / (b - a);
                    if u1.max(u2) - fb <= slack * (fb - delta) {
                        break;
                    }
                }
            }
            let x = if c - b > b - a {
                b + GOLDEN * (c - b)
            } else {
                b - GOLDEN * (b - a)
            };
            if x <= a || x >= c || x == b {
                break; // No representable progress left.
            }
            let fx = self.at(x);
            if x > b {
                if fx > fb {
                    t = [b, x, c];
                    f = [fb, fx, fc];
                } else {
                    t = [a, b, x];
                    f = [fa, fb, fx];
                }
            } else if fx > fb {
                t = [a, x, b];
                f = [fa, fx, fb];
            } else {
                t = [x, b, c];
                f = [fx, fb, fc];
            }
        }
        (t[1], f[1])
    }

    /// The full search: dense samples, then golden refinement of the best discrete maxima.
    fn full(&mut self) -> (f64, f64) {
        let n = FULL_SAMPLES;
        let h = TAU / n as f64;
        let vals: Vec<f64> = (0..n).map(|i| self.at(i as f64 * h)).collect();
        let mut peaks: Vec<usize> = (0..n)
            .filter(|&i| {
                let (l, r) = (vals[(i + n - 1) % n], vals[(i + 1) % n]);
                vals[i] >= l && vals[i] >= r
            })
            .collect();
        peaks.sort_by(|&i, &j| vals[j].total_cmp(&vals[i]));
        peaks.truncate(MAX_PEAKS);
        let mut best = (0.0, f64::NEG_INFINITY);
        for &i in &peaks {
            let b = i as f64 * h;
            let tri = [b - h, b, b + h];
            let f = [vals[(i + n - 1) % n], vals[i], vals[(i + 1) % n]];
            let (th, g) = self.golden(tri, f, None);
            if g > best.1 {
                best = (th, g);
            }
        }
        if peaks.is_empty() {
            // Constant g (cannot happen for bounded shapes, but stay total).
            best = (0.0, vals[0]);
        }
        best
    }

    /// A local search from `theta0` with initial half-width `w`: brackets a local maximum by
    /// walking uphill with doubling steps, then refines it with [`Gap::golden`]. `None` when
    /// the walk covers more than π without bracketing.
    fn local(&mut self, theta0: f64, w: f64, stop: Option<(f64, f64)>) -> Option<(f64, f64)> {
        let mut w = w.clamp(1e-12, 0.5);
        let mut t = [theta0 - w, theta0, theta0 + w];
        let mut f = [self.at(t[0]), self.at(t[1]), self.at(t[2])];
        let mut walked = 0.0;
        while !(f[1] >= f[0] && f[1] >= f[2]) {
            walked += w;
            if walked > PI {
                return None;
            }
            w *= 2.0;
            if f[0] > f[2] {
                t = [t[0] - w, t[0], t[1]];
                f = [self.at(t[0]), f[0], f[1]];
            } else {
                t = [t[1], t[2], t[2] + w];
                f = [f[1], f[2], self.at(t[2])];
            }
        }
        Some(self.golden(t, f, stop))
    }
}

fn wrap_angle(a: f64) -> f64 {
    a.rem_euclid(TAU)
}

fn wrap_pm(a: f64) -> f64 {
    (a + PI).rem_euclid(TAU) - PI
}

fn make_distance(theta: f64, g: f64, evals: u64) -> RefDistance {
    let theta = wrap_angle(theta);
    let (s, c) = theta.sin_cos();
    RefDistance {
        distance: g,
        angle: theta,
        normal: Vector::new(c, s),
        evals,
    }
}

/// The reference signed distance between `shape1` at `pose1` and `shape2` at `pose2` (cold:
/// dense sampling + golden-section refinement; exact to ~1e-15 of the size).
pub fn reference_distance(
    shape1: &dyn ConvexCurve,
    pose1: &Pose,
    shape2: &dyn ConvexCurve,
    pose2: &Pose,
) -> RefDistance {
    let mut gap = Gap::new(shape1, *pose1, shape2, *pose2);
    let (th, g) = gap.full();
    make_distance(th, g, gap.evals)
}

/// The reference signed distance of two moving shapes at time `t`.
pub fn reference_distance_at(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
    motion2: &NonlinearRigidMotion,
    t: f64,
) -> RefDistance {
    reference_distance(
        shape1,
        &motion1.position_at_time(t),
        shape2,
        &motion2.position_at_time(t),
    )
}

/// The Lipschitz constant of the distance in time used by the conservative advancement:
/// V = |v₁ − v₂| + |ω₁|·r₁ + |ω₂|·r₂, with r_i = `bounding_radius()` + |local_center| bounding the
/// distance from body i's rotation centre to its boundary.
pub fn speed_bound(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
    motion2: &NonlinearRigidMotion,
) -> f64 {
    let r1 = shape1.bounding_radius() + motion1.local_center.length();
    let r2 = shape2.bounding_radius() + motion2.local_center.length();
    (motion1.linvel - motion2.linvel).length() + motion1.angvel.abs() * r1 + motion2.angvel.abs() * r2
}

/// The size s of a pair of the crate's tolerances: the larger bounding radius about the local origins.
pub fn pair_size(shape1: &dyn ConvexCurve, shape2: &dyn ConvexCurve) -> f64 {
    shape1.bounding_radius().max(shape2.bounding_radius())
}

/// Options of [`reference_toi_with`].
#[derive(Copy, Clone, Debug)]
pub struct RefToiOptions {
    /// Stop advancing when D − target < `tol_rel` × size (default 1e-13).
    pub tol_rel: f64,
    /// Give up after this many advancement steps (default 10 million).
    pub max_steps: u64,
    /// Full direction resample every this many steps (default 256).
    pub resample_every: u64,
    /// Relative slack of the warm lower bound used away from contact (default 0.05): the step
    /// uses a lower bound L with D − L ≤ slack·(L − target) (when the concave bound applies).
    pub lower_bound_slack: f64,
    /// Use the directional rate bound V_n = max(0, −(v₂ − v₁)·n) + |ω₁|·r₁ + |ω₂|·r₂ along the
    /// direction n of the current gap sample instead of V (default true; both are rigorous, V_n
    /// ≤ V, and V_n makes translational grazes converge like Newton steps).
    pub directional: bool,
    /// Follow the nlerp path between the motions' poses at the window's ends (parry's
    /// `Sweep::transform_at`, rapier's clamp) instead of the motions themselves (default false).
    /// The rate bounds then take each body's largest nlerp angular speed, 2|tan(Δ/2)|/T for a
    /// turn Δ (wrapped into [−π, π)) over a window of length T.
    pub nlerp: bool,
}

impl Default for RefToiOptions {
    fn default() -> Self {
        Self {
            tol_rel: 1e-13,
            max_steps: 10_000_000,
            resample_every: 256,
            lower_bound_slack: 0.05,
            directional: true,
            nlerp: false,
        }
    }
}

/// What the reference found.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum RefOutcome {
    /// The distance reaches the target at `time` (the first such time in the window).
    Hit {
        /// The impact time: the last time found with D > target of the final bisection bracket
        /// (the bracket is ~1e-16 of the time scale wide); `t0` when the pair starts within the
        /// target distance.
        time: f64,
        /// True when D − target was seen to change sign (a bracketed crossing). False for a graze:
        /// D came within tol of the target and rose again without a sample ≤ target (then `time`
        /// is the time of the smallest gap seen), or the pair starts within the target.
        crossed: bool,
    },
    /// The distance stays above the target over the whole window.
    Miss,
    /// The step cap was hit at time `reached` before deciding (no contact in [t0, reached)).
    Capped {
        /// How far the advancement got.
        reached: f64,
    },
}

/// The reference time of impact and what it cost.
#[derive(Copy, Clone, Debug)]
pub struct RefToi {
    /// Hit, miss or capped.
    pub outcome: RefOutcome,
    /// D(t0) − target.
    pub start_gap: f64,
    /// The pair is within the target distance at t0 (then the outcome is a hit at t0).
    pub initially_within_target: bool,
    /// Smallest D − target seen at the advancement's sample times (each sample is the precise
    /// gap or a lower bound within 5 % of it). On a miss, an estimate of the minimum clearance.
    pub min_gap: f64,
    /// dD/dt near the hit (central difference at ±1e-7 of the window), 0 otherwise. Small |slope|
    /// means a grazing contact whose time is ill-conditioned.
    pub slope: f64,
    /// Conservative-advancement steps taken.
    pub steps: u64,
    /// Support-function pair evaluations in total.
    pub evals: u64,
    /// The Lipschitz bound V used.
    pub speed_bound: f64,
    /// The stopping tolerance tol = `tol_rel` × size.
    pub tol: f64,
}

impl RefToi {
    /// The impact time, if any (`Capped` counts as none).
    pub fn hit_time(&self) -> Option<f64> {
        match self.outcome {
            RefOutcome::Hit { time, .. } => Some(time),
            _ => None,
        }
    }
    /// True for a hit.
    pub fn is_hit(&self) -> bool {
        matches!(self.outcome, RefOutcome::Hit { .. })
    }
    /// True when the step cap stopped the search.
    pub fn is_capped(&self) -> bool {
        matches!(self.outcome, RefOutcome::Capped { .. })
    }
}

/// The moving pair, with warm-started distance evaluation.
struct Pair<'a> {
    s1: &'a dyn ConvexCurve,
    m1: NonlinearRigidMotion,
    s2: &'a dyn ConvexCurve,
    m2: NonlinearRigidMotion,
    evals: u64,
    /// The nlerp sweeps of the two bodies over the window (t0, 1/T), when the path is nlerp.
    sweeps: Option<([Sweep; 2], f64, f64)>,
}

impl Pair<'_> {
    fn pose(&self, k: usize, t: f64) -> Pose {
        match &self.sweeps {
            Some((sw, t0, inv_t)) => sw[k].transform_at((t - t0) * inv_t),
            None if k == 0 => self.m1.position_at_time(t),
            None => self.m2.position_at_time(t),
        }
    }

    fn gap_at(&self, t: f64) -> Gap<'_> {
        Gap::new(self.s1, self.pose(0, t), self.s2, self.pose(1, t))
    }

    /// Precise distance at `t`: cold full search.
    fn full(&mut self, t: f64) -> (f64, f64) {
        let mut g = self.gap_at(t);
        let r = g.full();
        self.evals += g.evals;
        r
    }

    /// Precise distance at `t`, warm-started at `theta` with half-width `w`; falls back to the
    /// full search unless the local maximum is positive (then it is global).
    fn precise(&mut self, t: f64, theta: f64, w: f64) -> (f64, f64) {
        let mut g = self.gap_at(t);
        let r = g.local(theta, w, None);
        self.evals += g.evals;
        match r {
            Some((th, d)) if d > 0.0 => (th, d),
            _ => self.full(t),
        }
    }

    /// A lower bound on the distance at `t` (within `slack` of the gap above `delta` when the
    /// concave bound applies); falls back to the precise search when not positive.
    fn lower(&mut self, t: f64, theta: f64, w: f64, delta: f64, slack: f64) -> (f64, f64) {
        let mut g = self.gap_at(t);
        let r = g.local(theta, w, Some((delta, slack)));
        self.evals += g.evals;
        match r {
            Some((th, d)) if d > 0.0 => (th, d),
            _ => self.full(t),
        }
    }

    fn precise_distance(&mut self, t: f64, theta: f64) -> f64 {
        self.precise(t, theta, 1e-6).1
    }
}

/// The reference time of impact with default options; see [`reference_toi_with`].
pub fn reference_toi(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
    motion2: &NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    target: f64,
) -> RefToi {
    reference_toi_with(
        shape1,
        motion1,
        shape2,
        motion2,
        t0,
        t1,
        target,
        &RefToiOptions::default(),
    )
}

/// The reference time of impact: the first time in `[t0, t1]` at which the signed distance of the
/// two moving shapes comes down to `target` (≥ 0), by conservative advancement on the reference
/// distance followed by bisection of the crossing (see the module documentation).
#[allow(clippy::too_many_arguments)]
pub fn reference_toi_with(
    shape1: &dyn ConvexCurve,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn ConvexCurve,
    motion2: &NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    target: f64,
    opts: &RefToiOptions,
) -> RefToi {
    let window = (t1 - t0).max(f64::MIN_POSITIVE);
    // On the nlerp path each body turns at most at 2|tan(Δ/2)|/T (at the middle of the window).
    let rate = |m: &NonlinearRigidMotion| {
        if opts.nlerp {
            let d = (m.angvel * window + PI).rem_euclid(TAU) - PI;
            2.0 * (0.5 * d).tan().abs() / window
        } else {
            m.angvel.abs()
        }
    };
    let (w1, w2) = (rate(motion1), rate(motion2));
    let r1 = shape1.bounding_radius() + motion1.local_center.length();
    let r2 = shape2.bounding_radius() + motion2.local_center.length();
    let v = (motion1.linvel - motion2.linvel).length() + w1 * r1 + w2 * r2;
    let sweeps = opts.nlerp.then(|| {
        let sweep = |m: &NonlinearRigidMotion| {
            Sweep::from_poses(&m.position_at_time(t0), &m.position_at_time(t1), m.local_center)
        };
        ([sweep(motion1), sweep(motion2)], t0, 1.0 / window)
    });
    let tol = opts.tol_rel * pair_size(shape1, shape2);
    let mut search = Search {
        pair: Pair {
            s1: shape1,
            m1: *motion1,
            s2: shape2,
            m2: *motion2,
            evals: 0,
            sweeps,
        },
        opts: *opts,
        t0,
        t1,
        target,
        tol,
        window: (t1 - t0).max(f64::MIN_POSITIVE),
        v,
        v_rel: motion2.linvel - motion1.linvel,
        w_rot: w1 * r1 + w2 * r2,
        res: RefToi {
            outcome: RefOutcome::Miss,
            start_gap: 0.0,
            initially_within_target: false,
            min_gap: f64::INFINITY,
            slope: 0.0,
            steps: 0,
            evals: 0,
            speed_bound: v,
            tol,
        },
    };
    search.run();
    search.res.evals = search.pair.evals;
    search.res
}

/// Where the conservative advancement stopped: at `t`, the precise gap `gap` = D − target < tol
/// along the direction at angle `theta`; `prev` is the sample before (time, gap).
struct Advanced {
    t: f64,
    theta: f64,
    gap: f64,
    prev: Option<(f64, f64)>,
}

/// The state of [`reference_toi_with`]: the pair, the window, the rate bounds and the answer so far.
struct Search<'a> {
    pair: Pair<'a>,
    opts: RefToiOptions,
    t0: f64,
    t1: f64,
    target: f64,
    tol: f64,
    /// t1 − t0 (at least the smallest positive number).
    window: f64,
    /// The Lipschitz bound V.
    v: f64,
    /// v₂ − v₁.
    v_rel: Vector,
    /// |ω₁|·r₁ + |ω₂|·r₂.
    w_rot: f64,
    res: RefToi,
}

impl Search<'_> {
    /// The search: the start, the advancement, the bracket of the crossing, its bisection and the
    /// slope there; the outcome and statistics in `self.res` (but for `evals`).
    fn run(&mut self) {
        let (t0, target) = (self.t0, self.target);
        let (theta0, d0) = self.pair.full(t0);
        let gap = d0 - target;
        self.res.start_gap = gap;
        self.res.min_gap = gap;
        if gap <= 0.0 {
            self.res.initially_within_target = true;
            self.res.outcome = RefOutcome::Hit {
                time: t0,
                crossed: false,
            };
            return;
        }
        let adv = match self.advance(wrap_pm(theta0), gap) {
            Ok(adv) => adv,
            Err(outcome) => {
                self.res.outcome = outcome;
                return;
            }
        };
        // Refinement. `gap` (precise) < tol at time t, and [t0, t) holds no contact.
        let (lo, glo, hi) = self.bracket(&adv);
        self.res.min_gap = self.res.min_gap.min(glo);
        let time = match hi {
            Some(hi) => {
                let lo = self.bisect(lo, hi, adv.theta);
                self.res.outcome = RefOutcome::Hit {
                    time: lo,
                    crossed: true,
                };
                lo
            }
            None => {
                self.res.outcome = RefOutcome::Hit {
                    time: lo,
                    crossed: false,
                };
                lo
            }
        };
        self.slope_at(time, adv.theta);
    }

    /// Conservative advancement from t0 (gap `gap` along the direction at `theta`) until the
    /// precise gap is within tol of the target; `Err` with the outcome when it passes t1 or can
    /// never close (a miss) or reaches the step cap.
    fn advance(&mut self, mut theta: f64, mut gap: f64) -> Result<Advanced, RefOutcome> {
        let (opts, target, tol) = (self.opts, self.target, self.tol);
        let mut t = self.t0;
        // Previous sample (time, gap), for the slope estimate of the probes.
        let mut prev: Option<(f64, f64)> = None;
        let mut dtheta = 1e-3_f64;
        loop {
            if gap < tol {
                // Within tol of the target: refine.
                return Ok(Advanced { t, theta, gap, prev });
            }
            // The gap sample is g(n, t) along n = (cos θ, sin θ); d/dt g(n, ·) ≥ −rate.
            let rate = if opts.directional {
                let n = Vector::new(theta.cos(), theta.sin());
                (-self.v_rel.dot(n)).max(0.0) + self.w_rot
            } else {
                self.v
            };
            if rate <= 0.0 {
                // The gap along n can never decrease: no contact ever.
                return Err(RefOutcome::Miss);
            }
            let h = gap / rate;
            if t + h > self.t1 {
                return Err(RefOutcome::Miss);
            }
            if self.res.steps >= opts.max_steps {
                return Err(RefOutcome::Capped { reached: t });
            }
            prev = Some((t, gap));
            t += h;
            self.res.steps += 1;
            let w = (2.0 * dtheta.abs()).max(1e-9);
            let (th, d) = if self.res.steps.is_multiple_of(opts.resample_every) {
                self.pair.full(t)
            } else {
                self.pair.lower(t, theta, w, target, opts.lower_bound_slack)
            };
            let (th, d) = if d - target < tol {
                self.pair.precise(t, th, 1e-6)
            } else {
                (th, d)
            };
            // Angles stay in [−π, π) so that ANGLE_TOL stays a few ulps.
            dtheta = wrap_pm(th - theta);
            theta = wrap_pm(th);
            gap = d - target;
            self.res.min_gap = self.res.min_gap.min(gap);
        }
    }

    /// After the advancement: (lo, D(lo) − target, hi) with a crossing in (lo, hi] when `hi` is
    /// some, else lo is the time of the smallest gap seen (a graze). Probes forward from the last
    /// sample with slope-based steps until the gap crosses the target or clearly rises.
    fn bracket(&mut self, adv: &Advanced) -> (f64, f64, Option<f64>) {
        let Advanced { t, theta, gap, prev } = *adv;
        if gap <= 0.0 {
            // Round-off put the sample at or below the target: the crossing is after `prev`.
            let (tp, gp) = prev.unwrap_or((self.t0, self.res.start_gap));
            return (tp, gp, Some(t));
        }
        let (mut lo, mut glo) = (t, gap);
        // Round-off level of D: a few ulps of the coordinates involved.
        let (q1, q2) = (self.pair.m1.position_at_time(t), self.pair.m2.position_at_time(t));
        let scale = pair_size(self.pair.s1, self.pair.s2) + q1.translation.length().max(q2.translation.length());
        let noise = 8.0 * f64::EPSILON * scale;
        let floor = 1e-15 * (t.abs() + self.window);
        let window = self.window;
        // Next probe step from a descending slope: twice the linear root, and long enough for
        // the slope to show above the noise.
        let step_for = |g: f64, slope: f64| {
            if slope < 0.0 {
                (2.0 * g / -slope).max(4.0 * noise / -slope).max(floor)
            } else {
                (1e-12 * window).max(floor)
            }
        };
        let slope_est = prev.map(|(tp, gp)| (gap - gp) / (t - tp)).unwrap_or(0.0);
        let mut h = step_for(gap, slope_est);
        let (mut cur_t, mut cur_g) = (t, gap);
        let mut shrinks = 0;
        for _ in 0..400 {
            let tp = (cur_t + h).min(self.t1);
            if tp <= cur_t {
                break;
            }
            let gp = self.pair.precise_distance(tp, theta) - self.target;
            if gp <= 0.0 {
                return (cur_t, cur_g, Some(tp));
            }
            if gp > cur_g + noise {
                // Clearly rising: the gap bottomed out within tol without crossing (a graze),
                // unless a probe stepped over a dip; probe shorter steps a few times first.
                if shrinks < 6 && h > floor {
                    h *= 0.125;
                    shrinks += 1;
                    continue;
                }
                break;
            }
            if gp < cur_g - noise {
                // Clearly descending: move the probe base on, slope-based next step.
                let slope = (gp - cur_g) / (tp - cur_t);
                (cur_t, cur_g) = (tp, gp);
                h = step_for(gp, slope);
            } else {
                // Flat within round-off: look further.
                if gp < cur_g {
                    (cur_t, cur_g) = (tp, gp);
                }
                h *= 2.0;
            }
            if cur_g < glo {
                (lo, glo) = (cur_t, cur_g);
            }
            if tp >= self.t1 {
                break;
            }
        }
        (lo, glo, None)
    }

    /// Bisection of a crossing: D(lo) > target ≥ D(hi); returns the last lo (~1e-16 of the time
    /// scale below the crossing).
    fn bisect(&mut self, mut lo: f64, mut hi: f64, theta: f64) -> f64 {
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let g = self.pair.precise_distance(mid, theta) - self.target;
            if g <= 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        lo
    }

    /// The slope of D near the hit at `time` (for conditioning): a central difference at ±1e-7 of
    /// the window, clipped to it.
    fn slope_at(&mut self, time: f64, theta: f64) {
        let dh = 1e-7 * self.window;
        let (ta, tb) = ((time - dh).max(self.t0), (time + dh).min(self.t1));
        if tb > ta {
            let (da, db) = (
                self.pair.precise_distance(ta, theta),
                self.pair.precise_distance(tb, theta),
            );
            self.res.slope = (db - da) / (tb - ta);
        }
    }
}
