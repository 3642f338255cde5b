//! # smooth-ccd2d
//!
//! Smooth convex shapes for [parry2d-f64] and [rapier2d-f64] — ellipses, rounded polygons,
//! piecewise-smooth convex curves — with an exact stationary distance and an exact time of
//! impact between two of them while both translate and spin.
//!
//! ## Conventions (stated once, used everywhere)
//!
//! * **Boundary parameter φ** ∈ [−π, π), counter-clockwise, see [`ConvexCurve`]. Built-in
//!   shapes: [`Ellipse`] and [`BallCurve`] use the outward normal angle; [`RoundedPolygon`]
//!   alternates corner and edge pieces starting at φ = −π; [`CapsuleEllipse`] uses the
//!   specification's own parameter (Appendix A).
//! * **Orientation**: counter-clockwise; `a × b = a_x b_y − a_y b_x`; T = N⊥ = (−N_y, N_x).
//! * **Roles**: *object1* is any convex curve; *object2* must be strictly convex (its contact
//!   point comes from the normal, eq. 4). Computations happen in object2's local frame. Pairs
//!   with no strictly convex side (polygons, boxes, capsule-ellipses) have no roles: they take
//!   the gap tracker, through [`shape_time_of_impact`] and [`SmoothDispatcher`].
//! * **The three distances**, with d = S₂(−N) − P₁(φ) in object2's frame:
//!   distanceEuclidean = |d|, distanceFwd F = d·N, distanceSide S = d × N ([`eval_pair`]).
//!   max over φ of F is the signed distance (negative: penetration depth).
//! * **`pos12`** is parry's: the pose of shape 2 in shape 1's local frame. Witness points and
//!   normals are returned in each shape's own local frame; `normal1` points from shape 1
//!   towards shape 2, `normal2 = −normal1` expressed in shape 2's frame.
//! * **Motion** is parry's `NonlinearRigidMotion`: the point `start * local_center` moves at
//!   constant `linvel`, the body spins at constant `angvel` about it; times are absolute, the
//!   window is `[start_time, end_time]`.
//!
//! [parry2d-f64]: https://docs.rs/parry2d-f64
//! [rapier2d-f64]: https://docs.rs/rapier2d-f64
#![warn(missing_docs)]

mod curve;
mod dispatcher;
mod error;
mod moving_pairs;
mod numerics;
mod parry_shape;
mod query;
mod shapes;

pub use curve::{ConvexCurve, CurvePoint, SupportJet};
#[doc(hidden)]
pub use dispatcher::is_core_feature as __is_core_feature;
#[cfg(feature = "rapier")]
pub use dispatcher::CoreContactHooks;
pub use dispatcher::{shape_time_of_impact, CastPolicy, SmoothDispatcher};
pub use error::{QueryError, ShapeError, MAX_LENGTH, MAX_VERTICES, MIN_LENGTH};
#[doc(hidden)]
pub use moving_pairs::core as __moving_pairs;
#[cfg(feature = "rapier")]
pub use moving_pairs::MovingPairs;
pub use moving_pairs::{MovingPairsOptions, MovingPairsReport, PairScope, PassStatus};
pub use numerics::angle::wrap_phi;
pub use numerics::jet::{Dual2, Jet2, JetVec};
pub use numerics::motion::PairFrame;
pub use parry_shape::{MassQuadrature, QuadratureStatus, FLAT_FEATURE_MAX_ANGLE};
pub use query::halfspace::{halfspace_distance, time_of_impact_halfspace};
pub use query::pair::{eval_pair, eval_pair_at, PairJet};
pub use query::path::MotionPath;
pub use query::stationary::{stationary_distance, DistanceOptions, DistanceStatus, StationaryDistance};
pub use query::toi::{
    bounding_circles_part, time_of_impact, time_of_impact_traced, TimeOfImpact, ToiCost, ToiOptions, ToiStatus,
    TraceEvent,
};
pub use shapes::{BallCurve, CapsuleEllipse, CustomCurve, Ellipse, RoundedPolygon};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
