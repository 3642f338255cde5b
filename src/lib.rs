//! # smooth-ccd2d
//!
//! Smooth convex shapes for [parry2d-f64] 0.31 and [rapier2d-f64] 0.36 — [`Ellipse`],
//! [`RoundedPolygon`], the specification's [`CapsuleEllipse`] and your own curves
//! ([`CustomCurve`]) — with an exact distance and an exact time of impact between two of them
//! while both translate and spin. [`SmoothDispatcher`] is a drop-in parry query dispatcher: put
//! in rapier's narrow phase, it makes contacts and continuous collision detection (CCD) exact for
//! these shapes and hands every other pair to parry. For parry2d and rapier2d in f32
//! (bevy_rapier2d), the package `smooth-ccd2d-f32` is the same crate.
//!
//! ## Quick start: rapier
//!
//! An ellipse shot at 300 m/s and spinning at 200 rad/s at a wall 5 cm thick: with the
//! dispatcher, rapier's CCD stops it at the wall.
//!
//! ```
//! use rapier2d_f64::prelude::*;
//! use smooth_ccd2d::{Ellipse, SmoothDispatcher};
//!
//! let mut world = PhysicsWorld::default();
//! world.gravity = Vector::ZERO;
//! // The one line that adopts the crate (with rapier's `PhysicsPipeline::step`, pass this
//! // narrow phase as its `narrow_phase` argument).
//! world.narrow_phase = NarrowPhase::with_query_dispatcher(SmoothDispatcher::default());
//!
//! world.insert(RigidBodyBuilder::fixed().translation(Vector::new(5.0, 0.0)), ColliderBuilder::cuboid(0.025, 2.0));
//! let (shot, _) = world.insert(
//!     RigidBodyBuilder::dynamic()
//!         .linvel(Vector::new(300.0, 0.0))
//!         .angvel(200.0)
//!         .allow_fast_rotation(true) // rapier caps a CCD body's spin at π/4 a step otherwise
//!         .ccd_enabled(true),
//!     ColliderBuilder::new(SharedShape::new(Ellipse::new(0.5, 0.2))),
//! );
//! for _ in 0..20 {
//!     world.step();
//! }
//! assert!(world.bodies[shot].translation().x < 5.0, "stopped in front of the wall");
//! ```
//!
//! ## Quick start: a time of impact
//!
//! ```
//! use parry2d_f64::math::{Pose, Vector};
//! use parry2d_f64::query::NonlinearRigidMotion;
//! use smooth_ccd2d::{time_of_impact, Ellipse, RoundedPolygon, ToiOptions, ToiStatus};
//!
//! // A heptagon (core circumradius 1, rounded by 0.15) at (−2, 0) moving at 4 m/s along x and
//! // spinning at 30 rad/s; an ellipse with semi-axes 0.5 and 1.5 at rest at the origin.
//! let a = RoundedPolygon::regular(7, 1.0, 0.15);
//! let b = Ellipse::new(0.5, 1.5);
//! let m1 = NonlinearRigidMotion::new(Pose::translation(-2.0, 0.0), Vector::ZERO, Vector::new(4.0, 0.0), 30.0);
//! let m2 = NonlinearRigidMotion::identity();
//! // The first time in [0, 1] at which the distance reaches 0.
//! let toi = time_of_impact(&a, &m1, &b, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
//! assert_eq!(toi.status, ToiStatus::Hit);
//! assert!(toi.distance.abs() < 1e-9 && toi.time > 0.0 && toi.time < 0.5);
//! ```
//!
//! ## What is here
//!
//! * **Shapes** (parry shapes: `SharedShape::new(shape)`): [`Ellipse`], [`RoundedPolygon`],
//!   [`CapsuleEllipse`], [`CustomCurve`] (your [`ConvexCurve`]). [`BallCurve`] is parry's `Ball`
//!   as a curve for the free queries below, not a parry shape. Constructors `new` panic naming a
//!   bad parameter, `try_new` return a [`ShapeError`].
//! * **Queries**: [`stationary_distance`]; [`time_of_impact`] (traced:
//!   [`time_of_impact_traced`]); [`shape_time_of_impact`] for any two convex parry shapes;
//!   [`halfspace_distance`] and [`time_of_impact_halfspace`]; [`bounding_circles_part`]. Errors:
//!   [`QueryError`].
//! * **rapier**: [`SmoothDispatcher`] (parry's `QueryDispatcher` and
//!   `PersistentQueryDispatcher`), with [`CastPolicy`] (rapier's CCD rules) and [`MotionPath`].
//!   With the feature `rapier`: `MovingPairs`, the opt-in pass around rapier's step that stops
//!   two fast bodies at their exact first contact (rapier never sweeps a bullet against a
//!   bullet; options [`MovingPairsOptions`], report [`MovingPairsReport`]), and
//!   `CoreContactHooks`, rapier hooks for bouncing bodies (no bounce on the core contacts), and
//!   `OneBounceHooks` (opt-in: also one bouncing row per impact, so that rapier's restitution
//!   adds no energy where flat sides meet).
//! * **The method** ([`method`]): the jets and the specification's distance functions, for
//!   writing a curve or studying the algorithm.
//!
//! ## Guarantees, in brief
//!
//! With s the larger bounding radius of a pair:
//!
//! * a [`ToiStatus::Hit`] is at a distance within −1e-12·s … +1e-10·s of the target, with no
//!   earlier contact in the window; the stationary distance is certified global when apart;
//! * no query panics, hangs or returns NaN or infinity; bad input gives an `Err` (parry's
//!   `Unsupported` through the dispatcher); every loop is bounded by a count, and a cap reached is
//!   a status ([`ToiStatus::OutOfIterations`]), not a wrong answer;
//! * supported lengths 1e-6 … 1e6 and axis ratios to 1:1e6 (accepted: 1e-50 … 1e50); poses far
//!   from the origin answer as at it;
//! * every type is `Send + Sync` and every answer deterministic to the bit, across threads too.
//!
//! The repository's documents (shipped in the package's `docs/` folder) give the rest:
//! `docs/rapier.md` (the dispatcher in rapier and bevy_rapier2d, [`CastPolicy`], rapier's
//! pitfalls with custom shapes), `docs/theory.md` (the method, the conventions),
//! `docs/performance.md` (every measurement and the limits), `docs/avian.md` (avian2d).
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
//!   distanceEuclidean = |d|, distanceFwd F = d·N, distanceSide S = d × N
//!   ([`method::eval_pair`]). max over φ of F is the signed distance (negative: penetration
//!   depth).
//! * **`pos12`** is parry's: the pose of shape 2 in shape 1's local frame. Witness points and
//!   normals are returned in each shape's own local frame; `normal1` points from shape 1
//!   towards shape 2, `normal2 = −normal1` expressed in shape 2's frame.
//! * **Motion** is parry's `NonlinearRigidMotion`: the point `start * local_center` moves at
//!   constant `linvel`, the body spins at constant `angvel` about it; times are absolute, the
//!   window is `[start_time, end_time]`.
//!
//! The specification is "Collision Detection Between Two Moving Convex Objects In 2D"; its
//! equations and appendices are cited by number.
//!
//! [parry2d-f64]: https://docs.rs/parry2d-f64
//! [rapier2d-f64]: https://docs.rs/rapier2d-f64
#![deny(missing_docs)]

mod curve;
mod dispatcher;
mod error;
pub mod method;
mod moving_pairs;
mod numerics;
mod parry_shape;
mod query;
mod shapes;

pub use curve::{ConvexCurve, CurvePoint, SupportJet};
#[doc(hidden)]
pub use dispatcher::is_core_feature as __is_core_feature;
#[doc(hidden)]
pub use dispatcher::rule3_line_contact as __rule3_line_contact;
#[doc(hidden)]
pub use dispatcher::{impact_weights as __impact_weights, ImpactSide as __ImpactSide};
pub use dispatcher::{shape_time_of_impact, CastPolicy, SmoothDispatcher};
#[cfg(feature = "rapier")]
pub use dispatcher::{CoreContactHooks, OneBounceHooks};
pub use error::{QueryError, ShapeError, MAX_LENGTH, MAX_VERTICES, MIN_LENGTH};
#[doc(hidden)]
pub use moving_pairs::core as __moving_pairs;
#[cfg(feature = "rapier")]
pub use moving_pairs::MovingPairs;
pub use moving_pairs::{MovingPairsOptions, MovingPairsReport, PairScope, PassStatus};
pub use parry_shape::{MassQuadrature, QuadratureStatus, FLAT_FEATURE_MAX_ANGLE};
pub use query::halfspace::{halfspace_distance, time_of_impact_halfspace};
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
