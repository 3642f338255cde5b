//! [`SmoothDispatcher`]: parry's `QueryDispatcher` that answers every query for pairs involving
//! this crate's shapes with the algorithms of the stationary distance and the time of impact ([`crate::stationary_distance`], [`crate::time_of_impact`]), and hands
//! every other pair to parry's `DefaultQueryDispatcher`.
//!
//! Which pairs it answers itself ("ours"): one shape is an [`crate::Ellipse`], [`crate::RoundedPolygon`],
//! [`crate::CapsuleEllipse`] or [`crate::CustomCurve`], and the other is one of those or a parry `Ball`,
//! `Cuboid`, `RoundCuboid`, `Capsule`, `Segment`, `Triangle`, `RoundTriangle`, `ConvexPolygon`
//! or `RoundConvexPolygon` (converted to a [`crate::RoundedPolygon`] or [`crate::BallCurve`] on the
//! stack). A pair with a strictly convex side gets the φ–t tracker of [`crate::time_of_impact`];
//! a pair of two polygonal sides (a rounded polygon against a box) the gap tracker; a
//! `HalfSpace` the closed-form distance and [`crate::time_of_impact_halfspace`]. A composite
//! shape (compound, polyline, trimesh, heightfield) on either side is decomposed by parry's
//! composite helpers with *this* dispatcher answering the sub-queries, so smooth shapes inside
//! composites keep exact answers.
//!
//! Semantics are parry's: `pos12` is shape 2's pose in shape 1's frame, witnesses and normals are
//! in each shape's local frame, `distance` is 0 for touching or penetrating shapes, a cast hit's
//! status is `Converged`, `PenetratingOrWithinTargetDist` or `OutOfIterations`
//! ([`crate::ToiStatus::to_parry`]).
//!
//! One deliberate difference, for rapier, chosen by [`CastPolicy`] (the default is
//! [`CastPolicy::Rapier`]; its module docs give the argument): `cast_shapes_nonlinear` follows
//! the path rapier's CCD clamp applies ([`crate::MotionPath::Nlerp`]), and with
//! `stop_at_penetration = false` (rapier's CCD of solid bodies) a contact at the start of the
//! window is answered by what the step's translation does to it — the first time the fast
//! body's core reaches the target or its translation takes the contact
//! [`CastPolicy::ALLOWANCE`] of its inradius deeper — never at the start time itself, which
//! rapier discards. [`CastPolicy::Plain`] gives [`crate::time_of_impact`]'s answers unchanged.
//!
//! For the polygonal pairs parry's support-map contact and manifold can come back empty for
//! shapes that nearly touch (GJK/EPA give up on parallel faces 10⁻¹⁰ apart, exactly where
//! rapier's CCD leaves a body); where the dispatcher hands such a pair to parry it computes them
//! on the shapes pushed 10⁻⁸ of their size into each other and measures the distances at the
//! true pose (`parry_fallback::parry_contact`, and `touching_manifold` in the `manifold` module).
//!
//! # Layout
//!
//! * `route`: how a pair is answered (this crate's algorithm, a half-space, a composite, parry),
//!   with parry's shapes converted to curves on the stack (`inline_polygon`);
//! * `queries`: parry's `QueryDispatcher` (intersection, distance, contact, closest points, casts);
//! * `manifold`: parry's `PersistentQueryDispatcher` (rapier's contact manifolds);
//! * `composite`: composite shapes decomposed by parry's helpers with this dispatcher inside;
//! * `cast`: the nonlinear cast, routed, with the [`CastPolicy`] applied;
//! * `rapier_rule`: [`CastPolicy`] and rapier's rules (the clamp path, a contact at the start);
//! * `core_disc`: the shapes' cores, and the manifold's core contact;
//! * `core_hooks`: [`CoreContactHooks`], rapier hooks that keep the bounce off the core contacts
//!   (feature `rapier`);
//! * `parry_fallback`: parry's answers made robust (nearly touching contacts, windows not at 0);
//! * `input_guard`: what is refused before parry sees it.

mod apart;
mod cast;
mod composite;
mod constrained;
mod core_disc;
#[cfg(feature = "rapier")]
mod core_hooks;
mod disc_cast;
mod distance_manifold;
mod impact_row;
pub(crate) mod inline_polygon;
pub(crate) mod input_guard;
mod manifold;
pub(crate) mod parry_fallback;
mod parry_pairs;
mod part_cores;
mod queries;
pub(crate) mod rapier_rule;
pub(crate) mod route;
mod segment_side;
pub(crate) mod support_shape;
mod translation_level;

pub use cast::shape_time_of_impact;
#[doc(hidden)]
pub use core_disc::is_core_feature;
#[cfg(feature = "rapier")]
pub use core_hooks::{CoreContactHooks, OneBounceHooks};
#[doc(hidden)]
pub use impact_row::{impact_weights, ImpactSide};
#[doc(hidden)]
pub use rapier_rule::rule3_line_contact;
pub use rapier_rule::CastPolicy;

use crate::error::QueryError;
use crate::numerics::math::{Pose, Real};
use crate::query::halfspace::halfspace_distance;
use crate::query::stationary::{DistanceOptions, StationaryDistance};
use crate::query::toi::ToiOptions;
use parry2d_f64::shape::Shape;
use route::{pair_distance, route, Route, RouteScratch};

/// The query dispatcher of this crate: exact smooth-shape queries, parry for everything else.
///
/// Drop it into rapier with `NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())`:
/// the default options and [`CastPolicy::Rapier`] are what rapier's CCD needs. Other callers
/// of `cast_shapes_nonlinear` who want the crate's time of impact as it is (parry's
/// constant-spin motions and `stop_at_penetration` semantics) choose [`CastPolicy::Plain`]:
///
/// ```
/// use smooth_ccd2d::{CastPolicy, SmoothDispatcher};
/// let for_rapier = SmoothDispatcher::default();
/// assert_eq!(for_rapier.cast_policy, CastPolicy::Rapier);
/// let plain = SmoothDispatcher::default().with_cast_policy(CastPolicy::Plain);
/// assert_eq!(plain.cast_policy, CastPolicy::Plain);
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SmoothDispatcher {
    /// Options of the stationary distance (distance, contact, closest points, intersection).
    pub distance_options: DistanceOptions,
    /// Options of the casts (the target distance and `stop_at_penetration` come from the caller).
    pub toi_options: ToiOptions,
    /// What `cast_shapes_nonlinear` answers: rapier's CCD rules (the default) or the crate's
    /// time of impact as it is ([`CastPolicy`]).
    pub cast_policy: CastPolicy,
    /// Whether a contact manifold's computation starts from the normal of the manifold rapier
    /// hands back (default true). The answer is the same either way (the same certificate of
    /// global optimality; `tests/warm_start.rs`); only pairs with two curved sides go faster.
    pub warm_start: bool,
}

impl Default for SmoothDispatcher {
    fn default() -> Self {
        Self {
            distance_options: DistanceOptions::default(),
            toi_options: ToiOptions::default(),
            cast_policy: CastPolicy::default(),
            warm_start: true,
        }
    }
}

impl SmoothDispatcher {
    /// The most steps parry's nonlinear cast (the dispatcher's fallback for the pairs its own
    /// casts do not take) may take,
    /// and the most relative turns, and travels of the pair's size (sum of bounding radii), in
    /// its window: a window holding more is refused with `Unsupported` (parry would run for
    /// hours).
    pub const PARRY_MAX_STEPS: Real = 1e4;

    /// The dispatcher with default options and rapier's start-contact rule (as `default()`).
    pub fn new() -> Self {
        Self::default()
    }

    /// The same dispatcher with these stationary-distance options.
    pub fn with_distance_options(mut self, options: DistanceOptions) -> Self {
        self.distance_options = options;
        self
    }

    /// The same dispatcher with these time-of-impact options (the target distance and
    /// `stop_at_penetration` of a cast still come from its caller).
    pub fn with_toi_options(mut self, options: ToiOptions) -> Self {
        self.toi_options = options;
        self
    }

    /// The same dispatcher with contact manifolds warm-started (`true`, the default) or not.
    pub fn with_warm_start(mut self, warm_start: bool) -> Self {
        self.warm_start = warm_start;
        self
    }

    /// The same dispatcher with this cast policy.
    pub fn with_cast_policy(mut self, policy: CastPolicy) -> Self {
        self.cast_policy = policy;
        self
    }

    /// The signed distance, witnesses and normals of a pair with a strictly convex side or a
    /// half-space, in the caller's order, as [`crate::stationary_distance`] gives them; `None`
    /// for other pairs (those with no strictly convex side get their exact distance through
    /// the dispatcher's `distance`, `contact` and `closest_points`; the rest go to parry).
    pub fn signed_distance(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Option<Result<StationaryDistance, QueryError>> {
        self.routed_distance(&route(g1, g2, &mut RouteScratch::default()), pos12)
    }

    /// [`SmoothDispatcher::signed_distance`] of an already routed pair.
    pub(crate) fn routed_distance(
        &self,
        route: &Route,
        pos12: &Pose,
    ) -> Option<Result<StationaryDistance, QueryError>> {
        match route {
            Route::Curves { c1, c2, swapped } => Some(pair_distance(c1, c2, *swapped, pos12, &self.distance_options)),
            Route::HalfSpace { curve, hs, curve_first } => {
                Some(halfspace_distance(curve.get(), hs, pos12, *curve_first))
            }
            _ => None,
        }
    }

    /// Quick rejection on bounding circles: true when the shapes are surely further apart than
    /// `margin`.
    pub(crate) fn far_apart(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, margin: Real) -> bool {
        // Never for a non-finite pose, whose distance ∞ would read as apart (issue 32).
        apart::circles_apart(pos12, &apart::circles(pos12, g1, g2), margin)
    }
}
