//! Helpers shared by the benchmarks: the scenario batches of `tests/common` as parry shapes,
//! split by outcome, and the two casts being compared.
#![allow(dead_code)]

use crate::common::{generate, Scenario, ScenarioClass, TestShape};
use parry2d_f64::query::{DefaultQueryDispatcher, QueryDispatcher, ShapeCastHit};
use parry2d_f64::shape::{Ball, Shape};
use smooth_ccd2d::SmoothDispatcher;

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

/// A test shape as a parry shape.
pub fn parry_shape(t: &TestShape) -> Box<dyn Shape> {
    match t {
        TestShape::Ellipse(e) => Box::new(*e),
        TestShape::Ball(b) => Box::new(Ball::new(b.radius)),
        TestShape::RoundedPolygon(p) => Box::new(p.clone()),
        TestShape::CapsuleEllipse(c) => Box::new(c.clone()),
    }
}

impl Case {
    /// The scenario of `class` for `seed`.
    pub fn new(class: ScenarioClass, seed: u64) -> Self {
        let s = generate(class, seed);
        let (g1, g2) = (parry_shape(&s.shape1), parry_shape(&s.shape2));
        Self { s, g1, g2 }
    }

    /// This crate's nonlinear cast (`stop_at_penetration = true`, target distance 0 as parry's).
    #[inline]
    pub fn ours(&self, d: &SmoothDispatcher) -> Option<ShapeCastHit> {
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

    /// parry's nonlinear cast on the same shapes.
    #[inline]
    pub fn parry(&self) -> Option<ShapeCastHit> {
        DefaultQueryDispatcher
            .cast_shapes_nonlinear(
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
pub fn judge(answer: Option<f64>, rf: &crate::common::RefToi, size: f64, window: f64) -> Option<bool> {
    use crate::common::RefOutcome;
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
