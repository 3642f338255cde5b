//! The helper module of the benchmarks (`mod support;` in `benches/toi.rs` and
//! `benches/ratios.rs`): the scenario batches of `tests/common` as parry shapes, split by
//! outcome, the casts being compared, the poses of the stationary benchmarks, the rounded
//! polygon – disc scenarios of the sweep benchmarks, timing, parry's polygonal stand-ins, the
//! comparison on parry's own shapes ([`native`]), parry's own pairs through the dispatcher
//! ([`parry_pairs`]), the pile ([`pile`], its tables [`pile_tables`]) and its replays
//! ([`replay`]), the degenerate starts ([`corner`]).
//! The files of
//! `tests/common` it needs are included as they are (`#[path]`):
//! the reference, the RNG, the scenario generator, the rapier world and its scenes, the resting
//! scenes (whose polygonal stand-ins the benches share), the watched dispatcher.
#![allow(dead_code)]

#[path = "../../tests/common/reference.rs"]
pub mod reference;
#[path = "../../tests/common/resting.rs"]
pub mod resting;
#[path = "../../tests/common/rng.rs"]
pub mod rng;
#[path = "../../tests/common/scenarios.rs"]
pub mod scenarios;
#[path = "../../tests/common/scenes.rs"]
pub mod scenes;
#[path = "../../tests/common/watched.rs"]
#[macro_use]
pub mod watched;
#[path = "../../tests/common/world.rs"]
pub mod world;

pub mod corner;
pub mod manifolds;
pub mod native;
pub mod parry_pairs;
pub mod pile;
pub mod pile_tables;
pub mod rapier_casts;
pub mod replay;

use parry2d_f64::math::Pose;
use parry2d_f64::query::{DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit, Sweep};
use parry2d_f64::shape::{Ball, RoundConvexPolygon, Shape};
use reference::{RefOutcome, RefToi};
use scenarios::{generate, Scenario, ScenarioClass, TestShape};
use smooth_ccd2d::{BallCurve, RoundedPolygon, SmoothDispatcher};

/// Scenarios per class in a batch.
pub const BATCH: usize = 200;

/// A scenario with both shapes as parry shapes (a `BallCurve` becomes parry's `Ball`).
pub struct Case {
    /// The scenario.
    pub s: Scenario,
    /// Shape 1 as a parry shape.
    pub g1: Box<dyn Shape>,
    /// Shape 2 as a parry shape.
    pub g2: Box<dyn Shape>,
}

impl Case {
    /// The scenario of `class` for `seed`.
    pub fn new(class: ScenarioClass, seed: u64) -> Self {
        let s = generate(class, seed);
        let (g1, g2) = (s.shape1.parry_shape(), s.shape2.parry_shape());
        Self { s, g1, g2 }
    }

    /// The nonlinear cast of dispatcher `d` over the scenario's window
    /// (`stop_at_penetration = true`, target distance 0 as parry's).
    #[inline]
    pub fn cast(&self, d: &impl QueryDispatcher) -> Option<ShapeCastHit> {
        d.cast_shapes_nonlinear(
            &self.s.motion1,
            &*self.g1,
            &self.s.motion2,
            &*self.g2,
            self.s.t0,
            self.s.t1,
            true,
        )
        .ok()
        .flatten()
    }

    /// This crate's nonlinear cast.
    #[inline]
    pub fn ours(&self, d: &SmoothDispatcher) -> Option<ShapeCastHit> {
        self.cast(d)
    }

    /// parry's nonlinear cast on the same shapes.
    #[inline]
    pub fn parry(&self) -> Option<ShapeCastHit> {
        self.cast(&DefaultQueryDispatcher)
    }

    /// Shape 2's pose in shape 1's frame at the window start.
    pub fn start_pose(&self) -> Pose {
        self.s.motion1.position_at_time(self.s.t0).inverse() * self.s.motion2.position_at_time(self.s.t0)
    }

    /// The pose at the window start with the centres brought closer until this crate's signed
    /// distance is `depth` (negative: penetrating), by bisection on the translation's scale.
    pub fn pose_at_depth(&self, depth: f64, d: &SmoothDispatcher) -> Option<Pose> {
        pose_at_depth(&self.start_pose(), &*self.g1, &*self.g2, depth, d)
    }
}

/// `start` (shape 2 in shape 1's frame) with the translation scaled down until the dispatcher's
/// signed distance is `depth` (negative: penetrating), by bisection on the scale (its `contact`
/// with prediction 0: the signed distance when overlapping, apart taken as +∞); `None` when the
/// scale 1 is not apart by more or the scale 0 not deeper.
pub fn pose_at_depth(start: &Pose, g1: &dyn Shape, g2: &dyn Shape, depth: f64, d: &SmoothDispatcher) -> Option<Pose> {
    let at = |k: f64| Pose::new(start.translation * k, start.rotation.angle());
    let dist = |k: f64| -> Option<f64> {
        match d.contact(&at(k), g1, g2, 0.0) {
            Ok(Some(c)) => Some(c.dist),
            Ok(None) => Some(f64::INFINITY),
            Err(_) => None,
        }
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    if !(dist(hi)? > depth && dist(lo)? < depth) {
        return None;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if dist(mid)? > depth {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(at(hi))
}

/// Microseconds with two decimals ("–" for NaN).
pub fn us(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else {
        format!("{:.2}", x * 1e6)
    }
}

/// One significant decimal in scientific notation ("–" for NaN).
pub fn sci(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else {
        format!("{x:.1e}")
    }
}

/// The batch of `class` (seeds `0..BATCH`) split by this crate's outcome: (hits, misses).
pub fn split_batch(class: ScenarioClass) -> (Vec<Case>, Vec<Case>) {
    let d = SmoothDispatcher::default();
    (0..BATCH as u64)
        .map(|seed| Case::new(class, seed))
        .partition(|c| c.ours(&d).is_some())
}

/// Whether a cast's answer (`Some(time)` for a hit) agrees with the reference: `None` when the
/// reference was capped, `Some(true)` for a right answer. At a reference graze (a hit without a
/// sign change, or a miss whose smallest gap is within `1e-9` of the size) either answer is
/// right. At a crossing the answer must be a hit within `1e-6` of the window plus the time
/// `1e-9·size / |dD/dt|` (ill-conditioned near-grazing crossings).
pub fn judge(answer: Option<f64>, rf: &RefToi, size: f64, window: f64) -> Option<bool> {
    match rf.outcome {
        RefOutcome::Capped { .. } => None,
        RefOutcome::Hit { crossed: false, .. } => Some(true),
        RefOutcome::Miss => Some(answer.is_none() || rf.min_gap < 1e-9 * size),
        RefOutcome::Hit { time, crossed: true } => Some(match answer {
            Some(a) => (a - time).abs() <= 1e-6 * window + 1e-9 * size / rf.slope.abs().max(1e-300),
            None => false,
        }),
    }
}

/// A `rounded_polygon-ellipse` scenario with the ellipse replaced by the disc of the same area,
/// for parry's `sweep_time_of_impact` (which takes rounded polygons and balls, not ellipses).
pub struct PolygonDisc {
    /// The scenario, shape 2 the disc, target 0.
    pub s: Scenario,
    /// Shape 1.
    pub poly: RoundedPolygon,
    /// Shape 1 as parry's rounded polygon.
    pub parry_poly: RoundConvexPolygon,
    /// The disc's radius.
    pub radius: f64,
}

impl PolygonDisc {
    /// The scenario of `seed`; `keep_spin`: keep the spins, but only where they turn the bodies by
    /// at most 45° over the window (rapier's regime; `None` otherwise), else set them to 0 (where
    /// parry's sweep follows the same path).
    pub fn new(seed: u64, keep_spin: bool) -> Option<Self> {
        let mut s = generate(ScenarioClass::RoundedPolygonEllipse, seed);
        let (TestShape::RoundedPolygon(poly), TestShape::Ellipse(e)) = (&s.shape1, &s.shape2) else {
            return None;
        };
        let poly: RoundedPolygon = poly.clone();
        let radius = (e.half_x() * e.half_y()).sqrt();
        if keep_spin {
            let turn = (s.motion1.angvel.abs() + s.motion2.angvel.abs()) * (s.t1 - s.t0);
            if turn > core::f64::consts::FRAC_PI_4 {
                return None;
            }
        } else {
            s.motion1.angvel = 0.0;
            s.motion2.angvel = 0.0;
        }
        s.shape2 = TestShape::Ball(BallCurve { radius });
        s.target = 0.0;
        let parry_poly = poly.to_parry()?;
        Some(Self {
            s,
            poly,
            parry_poly,
            radius,
        })
    }
}

/// parry's `Sweep` of `m` over [t0, t1]: its poses at both ends (parry interpolates between them).
pub fn sweep_of(m: &NonlinearRigidMotion, t0: f64, t1: f64) -> Sweep {
    Sweep::from_poses(&m.position_at_time(t0), &m.position_at_time(t1), m.local_center)
}

/// Timing helpers shared by the table-printing benchmark: every measurement repeats the query
/// until it lasts at least `MIN_TIMING`, and a time is the minimum over `ROUNDS` rounds that
/// alternate between the two contenders (robust against interference from other processes).
pub mod timing {
    use std::time::{Duration, Instant};

    /// The shortest timed batch.
    pub const MIN_TIMING: Duration = Duration::from_micros(200);
    /// Rounds per measurement.
    pub const ROUNDS: usize = 5;

    /// Repetitions of `f` that take at least `MIN_TIMING`.
    pub fn calibrate(f: &mut dyn FnMut()) -> u32 {
        let mut reps = 1u32;
        loop {
            let start = Instant::now();
            for _ in 0..reps {
                f();
            }
            let el = start.elapsed();
            if el >= MIN_TIMING {
                return reps;
            }
            let want = (MIN_TIMING.as_secs_f64() / el.as_secs_f64().max(1e-9) * 1.2).ceil();
            reps = (want as u32).clamp(reps.saturating_mul(2), reps.saturating_mul(100).max(2));
        }
    }

    /// Seconds per call of `f`, repeated `reps` times.
    pub fn time_once(f: &mut dyn FnMut(), reps: u32) -> f64 {
        let start = Instant::now();
        for _ in 0..reps {
            f();
        }
        start.elapsed().as_secs_f64() / reps as f64
    }

    /// Seconds per call of `f` alone (minimum over `ROUNDS`).
    pub fn time_one(f: &mut dyn FnMut()) -> f64 {
        let reps = calibrate(f);
        (0..ROUNDS).map(|_| time_once(f, reps)).fold(f64::INFINITY, f64::min)
    }

    /// Per-call seconds of `a` and `b` (minimum over `ROUNDS` alternating rounds).
    pub fn time_pair(a: &mut dyn FnMut(), b: &mut dyn FnMut()) -> (f64, f64) {
        let (ra, rb) = (calibrate(a), calibrate(b));
        let (mut ta, mut tb) = (f64::INFINITY, f64::INFINITY);
        for round in 0..ROUNDS {
            if round % 2 == 0 {
                ta = ta.min(time_once(a, ra));
                tb = tb.min(time_once(b, rb));
            } else {
                tb = tb.min(time_once(b, rb));
                ta = ta.min(time_once(a, ra));
            }
        }
        (ta, tb)
    }

    /// Per-call seconds of `ours` and `parry` by [`time_pair`], their answers kept from the
    /// optimiser.
    pub fn time_contenders<A, B>(mut ours: impl FnMut() -> A, mut parry: impl FnMut() -> B) -> (f64, f64) {
        time_pair(
            &mut || {
                std::hint::black_box(ours());
            },
            &mut || {
                std::hint::black_box(parry());
            },
        )
    }

    /// The q-quantile (nearest rank) of `v`; NaN for an empty slice.
    pub fn quantile(v: &[f64], q: f64) -> f64 {
        if v.is_empty() {
            return f64::NAN;
        }
        let mut s = v.to_vec();
        s.sort_by(f64::total_cmp);
        let i = ((q * s.len() as f64).ceil() as usize).clamp(1, s.len()) - 1;
        s[i]
    }
}

pub use resting::{polygon_approximation, POLYGON_VERTICES};

/// A test shape as a shape parry's own dispatcher builds manifolds for: a smooth shape becomes its
/// `POLYGON_VERTICES`-gon approximation, a rounded polygon parry's `RoundConvexPolygon` (exact), a
/// disc parry's `Ball`.
pub fn parry_polygonal(t: &TestShape) -> Box<dyn Shape> {
    match t {
        TestShape::Ellipse(e) => Box::new(polygon_approximation(e, POLYGON_VERTICES)),
        TestShape::Ball(b) => Box::new(Ball::new(b.radius)),
        TestShape::RoundedPolygon(p) => match p.to_parry() {
            Some(r) if p.corner_radius() > 0.0 => Box::new(r),
            Some(r) => Box::new(r.inner_shape),
            None => Box::new(polygon_approximation(p, POLYGON_VERTICES)),
        },
        TestShape::CapsuleEllipse(c) => Box::new(polygon_approximation(c, POLYGON_VERTICES)),
        TestShape::Cuboid(h, _) => Box::new(parry2d_f64::shape::Cuboid::new(*h)),
    }
}
