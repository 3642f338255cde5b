//! The box pile of `tests/common/scenes.rs` (the pile of `examples/pile.rs`: 200 ellipses,
//! rounded polygons and `CapsuleEllipse`s dropped into a box), built either with the exact shapes
//! and `SmoothDispatcher` as rapier's narrow phase, or with parry's polygon approximations
//! (`POLYGON_VERTICES`-gons for the smooth shapes, parry's `RoundConvexPolygon` for the rounded
//! polygons) and parry's default dispatcher.

use super::resting::pile_polygonal;
use super::scenes::{insert_pile, pile_bodies, PileShape};
use super::world::{World, GRAVITY};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::SmoothDispatcher;

pub use super::scenes::PILE_BODIES as BODIES;

/// A rapier world stepping the pile.
pub struct Pile {
    world: World,
}

impl Pile {
    /// The pile at rest before the first step; `exact`: this crate's shapes and dispatcher.
    pub fn new(exact: bool) -> Self {
        Self::with(exact, true, true)
    }

    /// As [`Pile::new`], with rapier's contact recycling on or off and the dispatcher's warm
    /// start on or off (exact shapes only).
    pub fn with(exact: bool, recycling: bool, warm_start: bool) -> Self {
        let narrow_phase = if exact {
            NarrowPhase::with_query_dispatcher(SmoothDispatcher::default().with_warm_start(warm_start))
        } else {
            NarrowPhase::new()
        };
        let mut world = World::new(narrow_phase);
        world.params.contact_recycling = recycling;
        let bodies = pile_bodies();
        if exact {
            insert_pile(&mut world, &bodies, PileShape::shared);
        } else {
            insert_pile(&mut world, &bodies, pile_polygonal);
        }
        Pile { world }
    }

    /// One rapier step (1/60 s).
    pub fn step(&mut self) {
        self.world.step(GRAVITY, &());
    }

    /// Contact pairs with at least one contact point.
    pub fn touching_pairs(&self) -> usize {
        self.world
            .narrow_phase
            .contact_pairs()
            .filter(|p| p.manifolds().iter().any(|m| !m.points.is_empty()))
            .count()
    }
}
