//! The box pile of `tests/common/scenes.rs` (the pile of `examples/pile.rs`: 200 ellipses,
//! rounded polygons and `CapsuleEllipse`s dropped into a box), built either with the exact shapes
//! and `SmoothDispatcher` as rapier's narrow phase, or with parry's polygon approximations
//! (`POLYGON_VERTICES`-gons for the smooth shapes, parry's `RoundConvexPolygon` for the rounded
//! polygons) and parry's default dispatcher.

use super::resting::pile_polygonal;
use super::scenes::{insert_pile, pile_bodies, PileShape};
use super::watched::{Watched, Watcher};
use super::world::{World, GRAVITY};
use parry2d_f64::query::{DefaultQueryDispatcher, PersistentQueryDispatcher};
use parry2d_f64::shape::Shape;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{CapsuleEllipse, Ellipse, RoundedPolygon, SmoothDispatcher};
use std::collections::BTreeMap;
use std::sync::{Arc, Mutex};

pub use super::scenes::PILE_BODIES as BODIES;

/// A rapier world stepping the pile.
pub struct Pile {
    world: World,
    bodies: Vec<RigidBodyHandle>,
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
        Self::build(narrow_phase, exact, recycling)
    }

    /// The pile in a world with this narrow phase: the exact shapes (`exact`) or parry's
    /// stand-ins, rapier's contact recycling on or off.
    fn build(narrow_phase: NarrowPhase, exact: bool, recycling: bool) -> Self {
        let mut world = World::new(narrow_phase);
        world.params.contact_recycling = recycling;
        let bodies = pile_bodies();
        let bodies = if exact {
            insert_pile(&mut world, &bodies, PileShape::shared)
        } else {
            insert_pile(&mut world, &bodies, pile_polygonal)
        };
        Pile { world, bodies }
    }

    /// The exact pile with `dispatcher` as rapier's narrow phase, contact recycling on or off.
    pub fn on<D>(dispatcher: D, recycling: bool) -> Self
    where
        D: PersistentQueryDispatcher<ContactManifoldData, ContactData> + 'static,
    {
        Self::on_shapes(dispatcher, true, recycling)
    }

    /// The pile with the exact shapes (`exact`) or parry's stand-ins, `dispatcher` as rapier's
    /// narrow phase, contact recycling on or off.
    pub fn on_shapes<D>(dispatcher: D, exact: bool, recycling: bool) -> Self
    where
        D: PersistentQueryDispatcher<ContactManifoldData, ContactData> + 'static,
    {
        Self::build(NarrowPhase::with_query_dispatcher(dispatcher), exact, recycling)
    }

    /// The rapier world.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The pile's bodies (the walls left out), in the order they were made.
    pub fn bodies(&self) -> Vec<RigidBodyHandle> {
        self.bodies.clone()
    }

    /// One rapier step (1/60 s).
    pub fn step(&mut self) {
        self.world.step(GRAVITY, &());
    }

    /// The pile with its dispatcher's `contact_manifolds` calls and CCD casts
    /// (`cast_shapes_nonlinear`) timed and counted by pair kind (into `stats`); the rest as
    /// [`Pile::with`] (warm start on).
    pub fn timed(exact: bool, recycling: bool, stats: &Arc<Mutex<CallStats>>) -> Self {
        let watcher = CallTimes(Arc::clone(stats));
        let narrow_phase = if exact {
            NarrowPhase::with_query_dispatcher(Watched {
                inner: SmoothDispatcher::default(),
                watcher,
            })
        } else {
            NarrowPhase::with_query_dispatcher(Watched {
                inner: DefaultQueryDispatcher,
                watcher,
            })
        };
        Self::build(narrow_phase, exact, recycling)
    }

    /// Turns on rapier's counters (`PhysicsPipeline::counters`): its stage timers run only in a
    /// build with rapier's `profiler` feature, and the counters add a statistics pass to every
    /// step, so the step-time tables do not use them.
    pub fn with_counters(mut self) -> Self {
        self.world.pipeline.counters.enable();
        self
    }

    /// The last step's times in ms from rapier's counters: the whole step, the narrow phase
    /// (every pair's manifolds, this crate's dispatcher or parry's), the solver, and the update
    /// of the colliders' poses and boxes. Zeros without rapier's `profiler` feature.
    pub fn stage_ms(&self) -> [f64; 4] {
        let c = &self.world.pipeline.counters;
        [
            c.step_time_ms(),
            c.cd.narrow_phase_time.time_ms(),
            c.stages.solver_time.time_ms(),
            c.stages.update_time.time_ms(),
        ]
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

/// The dispatcher's calls in a run, per pair kind ("a – b", sorted).
#[derive(Default)]
pub struct CallStats {
    /// `contact_manifolds`: calls, seconds in them and contact points returned.
    pub manifolds: BTreeMap<String, (u64, f64, u64)>,
    /// `cast_shapes_nonlinear` (rapier's CCD): casts, seconds in them and the longest cast's.
    pub casts: BTreeMap<String, (u64, f64, f64)>,
}

/// The watcher of [`Pile::timed`]: each `contact_manifolds` call's time and points and each
/// cast's time, added up by pair kind (a pair of clock readings costs about 50 ns, part of it
/// inside the times).
struct CallTimes(Arc<Mutex<CallStats>>);

/// A shape's name in the call statistics: this crate's shapes by name, parry's by type.
fn shape_name(g: &dyn Shape) -> String {
    if g.as_shape::<Ellipse>().is_some() {
        "Ellipse".into()
    } else if g.as_shape::<RoundedPolygon>().is_some() {
        "RoundedPolygon".into()
    } else if g.as_shape::<CapsuleEllipse>().is_some() {
        "CapsuleEllipse".into()
    } else {
        format!("{:?}", g.shape_type())
    }
}

/// "a – b" with the two shapes' names sorted.
pub fn pair_kind(g1: &dyn Shape, g2: &dyn Shape) -> String {
    let mut names = [shape_name(g1), shape_name(g2)];
    names.sort();
    format!("{} – {}", names[0], names[1])
}

impl Watcher for CallTimes {
    fn manifolds(&self, g1: &dyn Shape, g2: &dyn Shape, seconds: f64, points: usize) {
        let kind = pair_kind(g1, g2);
        let mut stats = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let entry = stats.manifolds.entry(kind).or_default();
        entry.0 += 1;
        entry.1 += seconds;
        entry.2 += points as u64;
    }

    fn cast(&self, g1: &dyn Shape, g2: &dyn Shape, seconds: f64) {
        let kind = pair_kind(g1, g2);
        let mut stats = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let entry = stats.casts.entry(kind).or_default();
        entry.0 += 1;
        entry.1 += seconds;
        entry.2 = entry.2.max(seconds);
    }
}
