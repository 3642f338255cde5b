//! [`SmoothDispatcher`] for parry2d and rapier2d in f32: parry2d's `QueryDispatcher`.
//!
//! Every query is routed once:
//!
//! 1. a composite-like shape (compound, polyline, trimesh, heightfield, voxels) on either side:
//!    parry2d's composite helpers with this dispatcher answering the sub-pairs
//!    ([`crate::composite`](crate)), so smooth shapes inside composites keep exact answers;
//! 2. one of this package's shapes against one of them or a parry shape the core takes (ball,
//!    cuboid, capsule, segment, triangle, convex polygon, their round versions, half-space): the
//!    query is widened to f64, answered by `smooth-ccd2d`'s [`smooth_ccd2d::SmoothDispatcher`]
//!    (the same routing, algorithms, options and start-contact rule as in f64), and the answer
//!    rounded once to f32 (`convert`);
//! 3. anything else: parry2d's `DefaultQueryDispatcher`, in f32, exactly as without this crate
//!    (this package's shapes then answer through their support maps and polygonal feature maps,
//!    under the same guards as route 1: e.g. one of them against a user's own parry shape).
//!
//! An answer that rounds to a non-finite f32 (an f64 answer beyond f32's range) is
//! `Err(Unsupported)`, never a NaN or an infinity; so is bad input on route 1 (`guard`, the checks
//! the f64 dispatcher makes before parry's composite helpers; route 2 is checked by the f64
//! dispatcher itself).

use crate::composite::{
    composite_cast, composite_cast_nonlinear, composite_closest_points, composite_contact, composite_distance,
    composite_intersection, is_composite_like,
};
use crate::convert::{cast_options64, closest32, contact32, hit32, motion64, pose64, v64};
use crate::guard::{cast_ok, guarded, inputs_ok, linear_cast_ok};
use crate::shapes::own_f64;
use crate::widen::{widen_pair, Wide};
use parry2d::math::{Pose, Real, Vector};
use parry2d::query::{
    ClosestPoints, Contact, DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit,
    ShapeCastOptions, ShapeDistance, ShapeIntersection, Unsupported,
};
use parry2d::shape::Shape;
use parry2d_f64::query::QueryDispatcher as _;
use smooth_ccd2d::{CastPolicy, DistanceOptions, ToiOptions};

/// The query dispatcher for parry2d / rapier2d in f32: exact smooth-shape queries computed in
/// f64, parry2d for everything else.
///
/// Drop it into rapier2d with `NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())`
/// (in bevy_rapier2d: the narrow phase's dispatcher of the rapier context). The options are
/// those of [`smooth_ccd2d::SmoothDispatcher`], kept in [`SmoothDispatcher::core`]:
///
/// ```
/// use smooth_ccd2d_f32::{CastPolicy, SmoothDispatcher};
/// let for_rapier = SmoothDispatcher::default();
/// assert_eq!(for_rapier.core.cast_policy, CastPolicy::Rapier);
/// let plain = SmoothDispatcher::default().with_cast_policy(CastPolicy::Plain);
/// assert_eq!(plain.core.cast_policy, CastPolicy::Plain);
/// ```
#[derive(Clone, Debug, Default)]
pub struct SmoothDispatcher {
    /// The f64 dispatcher that answers the widened queries (its options are this one's).
    pub core: smooth_ccd2d::SmoothDispatcher,
}

impl SmoothDispatcher {
    /// The dispatcher with default options and rapier's CCD rules (as `default()`).
    pub fn new() -> Self {
        Self::default()
    }

    /// The same dispatcher with these stationary-distance options.
    pub fn with_distance_options(mut self, options: DistanceOptions) -> Self {
        self.core = self.core.with_distance_options(options);
        self
    }

    /// The same dispatcher with these time-of-impact options.
    pub fn with_toi_options(mut self, options: ToiOptions) -> Self {
        self.core = self.core.with_toi_options(options);
        self
    }

    /// The same dispatcher with this cast policy ([`CastPolicy`]: rapier's CCD rules, the
    /// default, or the crate's time of impact as it is).
    pub fn with_cast_policy(mut self, policy: CastPolicy) -> Self {
        self.core = self.core.with_cast_policy(policy);
        self
    }

    /// The same dispatcher with contact manifolds warm-started (`true`, the default) or not.
    pub fn with_warm_start(mut self, warm_start: bool) -> Self {
        self.core = self.core.with_warm_start(warm_start);
        self
    }
}

/// parry2d-f64's `Unsupported` as parry2d's.
pub(crate) fn unsupported(_: parry2d_f64::query::Unsupported) -> Unsupported {
    Unsupported
}

/// Whether either side is composite-like (route 1 of the module docs).
pub(crate) fn composite_pair(g1: &dyn Shape, g2: &dyn Shape) -> bool {
    is_composite_like(g1, g1.shape_type()) || is_composite_like(g2, g2.shape_type())
}

/// How a pair is answered (the routes of the module docs).
enum Way<'a> {
    /// Route 1: parry2d's composite helpers with this dispatcher, under the guards.
    Composite,
    /// Route 2: the f64 crate on the widened pair.
    Wide(Wide<'a>, Wide<'a>),
    /// Route 3 with one of this package's shapes (against a shape the core does not take):
    /// parry2d through the shape's support map, under the guards.
    GuardedParry,
    /// Route 3 without: parry2d, untouched.
    Parry,
}

impl<'a> Way<'a> {
    fn of(g1: &'a dyn Shape, g2: &'a dyn Shape) -> Self {
        if composite_pair(g1, g2) {
            Way::Composite
        } else if let Some((a, b)) = widen_pair(g1, g2) {
            Way::Wide(a, b)
        } else if own_f64(g1).is_some() || own_f64(g2).is_some() {
            Way::GuardedParry
        } else {
            Way::Parry
        }
    }
}

impl QueryDispatcher for SmoothDispatcher {
    fn intersection_test(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeIntersection, Unsupported> {
        let ok = || inputs_ok(pos12, g1, g2, 0.0);
        match Way::of(g1, g2) {
            Way::Composite => guarded(ok(), || composite_intersection(self, pos12, g1, g2)),
            Way::Wide(a, b) => {
                let i = self
                    .core
                    .intersection_test(&pose64(pos12), a.get(), b.get())
                    .map_err(unsupported)?;
                Ok(ShapeIntersection::new(i.intersecting))
            }
            Way::GuardedParry => guarded(ok(), || DefaultQueryDispatcher.intersection_test(pos12, g1, g2)),
            Way::Parry => DefaultQueryDispatcher.intersection_test(pos12, g1, g2),
        }
    }

    fn distance(&self, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> Result<ShapeDistance, Unsupported> {
        let ok = || inputs_ok(pos12, g1, g2, 0.0);
        match Way::of(g1, g2) {
            Way::Composite => guarded(ok(), || composite_distance(self, pos12, g1, g2)),
            Way::Wide(a, b) => {
                let d = self
                    .core
                    .distance(&pose64(pos12), a.get(), b.get())
                    .map_err(unsupported)?
                    .distance as f32;
                d.is_finite().then(|| ShapeDistance::new(d)).ok_or(Unsupported)
            }
            Way::GuardedParry => guarded(ok(), || DefaultQueryDispatcher.distance(pos12, g1, g2)),
            Way::Parry => DefaultQueryDispatcher.distance(pos12, g1, g2),
        }
    }

    fn contact(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
    ) -> Result<Option<Contact>, Unsupported> {
        let ok = || inputs_ok(pos12, g1, g2, prediction);
        match Way::of(g1, g2) {
            Way::Composite => guarded(ok(), || composite_contact(self, pos12, g1, g2, prediction)),
            Way::Wide(a, b) => match self
                .core
                .contact(&pose64(pos12), a.get(), b.get(), prediction as f64)
                .map_err(unsupported)?
            {
                Some(c) => contact32(&c).map(Some).ok_or(Unsupported),
                None => Ok(None),
            },
            Way::GuardedParry => guarded(ok(), || DefaultQueryDispatcher.contact(pos12, g1, g2, prediction)),
            Way::Parry => DefaultQueryDispatcher.contact(pos12, g1, g2, prediction),
        }
    }

    fn closest_points(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        max_dist: Real,
    ) -> Result<ClosestPoints, Unsupported> {
        let ok = || inputs_ok(pos12, g1, g2, max_dist);
        match Way::of(g1, g2) {
            Way::Composite => guarded(ok(), || composite_closest_points(self, pos12, g1, g2, max_dist)),
            Way::Wide(a, b) => {
                let c = self
                    .core
                    .closest_points(&pose64(pos12), a.get(), b.get(), max_dist as f64)
                    .map_err(unsupported)?;
                closest32(&c).ok_or(Unsupported)
            }
            Way::GuardedParry => guarded(ok(), || DefaultQueryDispatcher.closest_points(pos12, g1, g2, max_dist)),
            Way::Parry => DefaultQueryDispatcher.closest_points(pos12, g1, g2, max_dist),
        }
    }

    fn cast_shapes(
        &self,
        pos12: &Pose,
        local_vel12: Vector,
        g1: &dyn Shape,
        g2: &dyn Shape,
        options: ShapeCastOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let ok = || linear_cast_ok(pos12, local_vel12, g1, g2, &options);
        match Way::of(g1, g2) {
            Way::Composite => guarded(ok(), || composite_cast(self, pos12, local_vel12, g1, g2, options)),
            Way::Wide(a, b) => {
                let hit = self
                    .core
                    .cast_shapes(
                        &pose64(pos12),
                        v64(local_vel12),
                        a.get(),
                        b.get(),
                        cast_options64(&options),
                    )
                    .map_err(unsupported)?;
                match hit {
                    Some(h) => hit32(&h, 0.0).map(Some).ok_or(Unsupported),
                    None => Ok(None),
                }
            }
            Way::GuardedParry => guarded(ok(), || {
                DefaultQueryDispatcher.cast_shapes(pos12, local_vel12, g1, g2, options)
            }),
            Way::Parry => DefaultQueryDispatcher.cast_shapes(pos12, local_vel12, g1, g2, options),
        }
    }

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
        let (m1, m2, t0, t1, stop) = (motion1, motion2, start_time, end_time, stop_at_penetration);
        let ok = || cast_ok(m1, g1, m2, g2, t0, t1);
        match Way::of(g1, g2) {
            Way::Composite => guarded(ok(), || composite_cast_nonlinear(self, m1, g1, m2, g2, t0, t1, stop)),
            Way::Wide(a, b) => {
                let (m1, m2) = (motion64(m1), motion64(m2));
                let hit = self
                    .core
                    .cast_shapes_nonlinear(&m1, a.get(), &m2, b.get(), t0 as f64, t1 as f64, stop)
                    .map_err(unsupported)?;
                match hit {
                    Some(h) => hit32(&h, t0).map(Some).ok_or(Unsupported),
                    None => Ok(None),
                }
            }
            Way::GuardedParry => guarded(ok(), || {
                DefaultQueryDispatcher.cast_shapes_nonlinear(m1, g1, m2, g2, t0, t1, stop)
            }),
            Way::Parry => DefaultQueryDispatcher.cast_shapes_nonlinear(m1, g1, m2, g2, t0, t1, stop),
        }
    }
}
