//! A dispatcher that passes every query on to the one it wraps and tells a [`Watcher`] about
//! it: which threads call rapier's narrow phase (`crates/parallel-tests`), how long each
//! `contact_manifolds` call and each CCD cast takes by pair kind (the pile benchmark,
//! `benches/support/pile.rs`).
#![allow(dead_code)]

use parry2d_f64::math::{Pose, Real, Vector};
use parry2d_f64::query::details::NormalConstraints;
use parry2d_f64::query::{
    ClosestPoints, Contact, ContactManifold, ContactManifoldsWorkspace, NonlinearRigidMotion,
    PersistentQueryDispatcher, QueryDispatcher, ShapeCastHit, ShapeCastOptions, ShapeDistance, ShapeIntersection,
    Unsupported,
};
use parry2d_f64::shape::Shape;

/// What a [`Watched`] dispatcher reports.
pub trait Watcher: Send + Sync {
    /// Called before every query.
    fn query(&self) {}
    /// Called after every `contact_manifolds` call: its shapes, the seconds it took (one clock
    /// reading before, one after) and the contact points it returned.
    fn manifolds(&self, _g1: &dyn Shape, _g2: &dyn Shape, _seconds: f64, _points: usize) {}
    /// Called after every `cast_shapes_nonlinear` call (rapier's CCD): its shapes and the
    /// seconds it took.
    fn cast(&self, _g1: &dyn Shape, _g2: &dyn Shape, _seconds: f64) {}
    /// Whether the calls are timed (two clock readings each); a watcher that only records which
    /// calls were made answers false, and the seconds it is given are 0.
    fn timed(&self) -> bool {
        true
    }
}

/// A clock reading when `on`: the seconds since it, or 0 (`Watcher::timed`).
struct Clock(Option<std::time::Instant>);

impl Clock {
    fn start(on: bool) -> Self {
        Clock(on.then(std::time::Instant::now))
    }
    fn seconds(&self) -> f64 {
        self.0.map_or(0.0, |t| t.elapsed().as_secs_f64())
    }
}

/// The dispatcher `inner`, watched by `watcher`; its answers are `inner`'s.
pub struct Watched<D, W> {
    pub inner: D,
    pub watcher: W,
}

/// The five queries of `QueryDispatcher` a pass-through dispatcher hands on unchanged to its
/// field `$inner`, each after `self.$hook.query()` when a hook field is named:
/// `forward_plain_queries!(inner, watcher)` in [`Watched`], `forward_plain_queries!(inner)` in
/// the benches' replay (`benches/support/replay.rs`). Each writes `cast_shapes_nonlinear`.
macro_rules! forward_plain_queries {
    ($inner:ident $(, $hook:ident)?) => {
        fn intersection_test(
            &self,
            pos12: &Pose,
            g1: &dyn Shape,
            g2: &dyn Shape,
        ) -> Result<ShapeIntersection, Unsupported> {
            $(self.$hook.query();)?
            self.$inner.intersection_test(pos12, g1, g2)
        }
        fn distance(&self, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> Result<ShapeDistance, Unsupported> {
            $(self.$hook.query();)?
            self.$inner.distance(pos12, g1, g2)
        }
        fn contact(
            &self,
            pos12: &Pose,
            g1: &dyn Shape,
            g2: &dyn Shape,
            prediction: Real,
        ) -> Result<Option<Contact>, Unsupported> {
            $(self.$hook.query();)?
            self.$inner.contact(pos12, g1, g2, prediction)
        }
        fn closest_points(
            &self,
            pos12: &Pose,
            g1: &dyn Shape,
            g2: &dyn Shape,
            max_dist: Real,
        ) -> Result<ClosestPoints, Unsupported> {
            $(self.$hook.query();)?
            self.$inner.closest_points(pos12, g1, g2, max_dist)
        }
        fn cast_shapes(
            &self,
            pos12: &Pose,
            local_vel12: Vector,
            g1: &dyn Shape,
            g2: &dyn Shape,
            options: ShapeCastOptions,
        ) -> Result<Option<ShapeCastHit>, Unsupported> {
            $(self.$hook.query();)?
            self.$inner.cast_shapes(pos12, local_vel12, g1, g2, options)
        }
    };
}

impl<D: QueryDispatcher, W: Watcher> QueryDispatcher for Watched<D, W> {
    forward_plain_queries!(inner, watcher);

    fn cast_shapes_nonlinear(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        self.watcher.query();
        let start = Clock::start(self.watcher.timed());
        let answer =
            self.inner
                .cast_shapes_nonlinear(motion1, g1, motion2, g2, start_time, end_time, stop_at_penetration);
        self.watcher.cast(g1, g2, start.seconds());
        answer
    }
}

impl<M, C, D: PersistentQueryDispatcher<M, C>, W: Watcher> PersistentQueryDispatcher<M, C> for Watched<D, W> {
    fn contact_manifolds(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
        manifolds: &mut Vec<ContactManifold<M, C>>,
        workspace: &mut Option<ContactManifoldsWorkspace>,
    ) -> Result<(), Unsupported> {
        self.watcher.query();
        let start = Clock::start(self.watcher.timed());
        let answer = self
            .inner
            .contact_manifolds(pos12, g1, g2, prediction, manifolds, workspace);
        let seconds = start.seconds();
        let points = manifolds.iter().map(|m| m.points.len()).sum();
        self.watcher.manifolds(g1, g2, seconds, points);
        answer
    }

    fn contact_manifold_convex_convex(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        normal_constraints1: Option<&dyn NormalConstraints>,
        normal_constraints2: Option<&dyn NormalConstraints>,
        prediction: Real,
        manifold: &mut ContactManifold<M, C>,
    ) -> Result<(), Unsupported> {
        self.watcher.query();
        self.inner.contact_manifold_convex_convex(
            pos12,
            g1,
            g2,
            normal_constraints1,
            normal_constraints2,
            prediction,
            manifold,
        )
    }
}
