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
