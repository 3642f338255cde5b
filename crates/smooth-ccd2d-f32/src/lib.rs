//! # smooth-ccd2d-f32
//!
//! [`smooth-ccd2d`](smooth_ccd2d) for **parry2d 0.31 and rapier2d 0.36 in f32** — the builds Bevy
//! games use through bevy_rapier2d 0.37. The same smooth convex shapes ([`Ellipse`],
//! [`RoundedPolygon`], [`CapsuleEllipse`], [`CustomCurve`] for your own curves) and the same
//! drop-in [`SmoothDispatcher`], which makes rapier's contacts and continuous collision detection
//! exact for them, with f32 at the boundary and f64 inside.
//!
//! ## Quick start: rapier2d (and bevy_rapier2d)
//!
//! ```
//! use rapier2d::prelude::*;
//! use smooth_ccd2d_f32::{Ellipse, SmoothDispatcher};
//!
//! let mut world = PhysicsWorld::default();
//! world.gravity = Vector::ZERO;
//! // The one line that adopts the crate: the narrow phase's query dispatcher.
//! world.narrow_phase = NarrowPhase::with_query_dispatcher(SmoothDispatcher::default());
//! world.insert(RigidBodyBuilder::fixed().translation(Vector::new(5.0, 0.0)), ColliderBuilder::cuboid(0.025, 2.0));
//! let (shot, _) = world.insert(
//!     RigidBodyBuilder::dynamic().linvel(Vector::new(300.0, 0.0)).angvel(200.0).allow_fast_rotation(true).ccd_enabled(true),
//!     ColliderBuilder::new(SharedShape::new(Ellipse::new(0.5, 0.2))),
//! );
//! for _ in 0..20 {
//!     world.step();
//! }
//! assert!(world.bodies[shot].translation().x < 5.0, "stopped in front of the wall");
//! ```
//!
//! In bevy_rapier2d 0.37 the same dispatcher goes into the rapier context in a startup system
//! (`RapierContextSimulation::set_query_dispatcher(SmoothDispatcher::default())`), a shape into
//! `Collider::from(SharedShape::new(...))`, and a fast-spinning body gets `AllowFastRotation`:
//! the repository's README ("Bevy") and `bevy-example/` give the exact lines.
//!
//! ## Quick start: a time of impact
//!
//! ```
//! use parry2d::math::{Pose, Vector};
//! use parry2d::query::NonlinearRigidMotion;
//! use parry2d::shape::Cuboid;
//! use smooth_ccd2d_f32::{shape_time_of_impact, RoundedPolygon, ToiOptions, ToiStatus};
//!
//! // A rounded heptagon at (−2, 0) moving at 10 m/s and spinning at 30 rad/s, towards a wall.
//! let hept = RoundedPolygon::regular(7, 0.5, 0.05);
//! let wall = Cuboid::new(Vector::new(0.05, 2.0));
//! let m1 = NonlinearRigidMotion::new(Pose::translation(-2.0, 0.0), Vector::ZERO, Vector::new(10.0, 0.0), 30.0);
//! let m2 = NonlinearRigidMotion::identity();
//! let r = shape_time_of_impact(&hept, &m1, &wall, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
//! assert_eq!(r.status, ToiStatus::Hit);
//! assert!(r.time > 0.13 && r.time < 0.15);
//! ```
//!
//! ## Guarantees, in brief
//!
//! The f64 crate's guarantees for the f32 inputs, each answer rounded once: a time of impact
//! rounded *down* (never later than the exact one), boxes outward, thicknesses down, everything
//! else to nearest; no NaN or infinity (an answer outside f32's range is `Err(Unsupported)`);
//! mass properties finite at every accepted size. The details follow; the package's README and the
//! repository's `docs/` (rapier.md for rapier and Bevy) give the rest.
//!
//! ## Precision: f64 inside, f32 at the boundary
//!
//! The algorithms (stationary distance, time of impact, exact contacts) are `smooth-ccd2d`'s and
//! run in f64: their exactness argument and tolerances are f64's. A query's f32 inputs are
//! widened to f64 — exactly, except that a pose's rotation is read as the rotation by its angle
//! (an f32 unit complex number is unit only to 10⁻⁷) — and the f64 answer is rounded once to
//! f32. So, in f32:
//!
//! * **the time of impact** is the f64 time of impact of the f32 inputs, rounded *down* to f32,
//!   so never later than the exact one — with one exception: an exact time less than one f32 ulp
//!   after the start of the window is reported one ulp after the start rather than at it (rapier
//!   discards hits at exactly the start). A reported hit is therefore never inside penetration
//!   by more than what the f32 rounding of the poses rapier then builds from it adds;
//! * **distances, witnesses, normals and contact points** are the f64 answers of the f32 inputs,
//!   rounded to nearest (relative error ≤ 2⁻²⁴ of each value);
//! * **bounding boxes** (local and posed) and **local bounding spheres** round outward (they
//!   contain the shape), **CCD thicknesses** round down;
//! * an answer that does not fit in f32 is `Err(Unsupported)`, never an infinity or a NaN.
//!
//! Pairs with none of this package's shapes are parry2d's own, in f32, untouched. A shape's f64
//! original is at hand (`as_f64`) for `smooth-ccd2d`'s f64 API (curves, traced times of impact,
//! stationary distances), whose options and status types are re-exported here.
//!
//! ## Layout
//!
//! The package holds only the boundary; everything else is `smooth-ccd2d`:
//! `convert` (widening and rounding), `shapes` (the f32 shapes, by delegation), `widen` (parry's
//! f32 shapes in f64), `dispatcher` and `manifold` (parry's dispatcher traits), `guard` (bad input
//! refused before parry's composite helpers), `composite`
//! (`smooth-ccd2d`'s composite routing instantiated for parry2d), `cast`
//! ([`shape_time_of_impact`]).

#![deny(missing_docs)]

mod cast;
mod composite;
mod convert;
#[cfg(feature = "rapier")]
mod core_hooks;
mod dispatcher;
mod guard;
mod manifold;
#[cfg(feature = "rapier")]
mod moving_pairs;
mod shapes;
mod widen;

pub use cast::shape_time_of_impact;
#[cfg(feature = "rapier")]
pub use core_hooks::{CoreContactHooks, OneBounceHooks};
pub use dispatcher::SmoothDispatcher;
#[cfg(feature = "rapier")]
pub use moving_pairs::MovingPairs;
pub use shapes::{CapsuleEllipse, CustomCurve, Ellipse, RoundedPolygon};
pub use smooth_ccd2d::{
    CastPolicy, ConvexCurve, CurvePoint, DistanceOptions, MotionPath, MovingPairsOptions, MovingPairsReport, PairScope,
    PassStatus, QueryError, ShapeError, TimeOfImpact, ToiCost, ToiOptions, ToiStatus,
};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
