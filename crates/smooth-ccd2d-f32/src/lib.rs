//! # smooth-ccd2d-f32
//!
//! [`smooth-ccd2d`](smooth_ccd2d) for **parry2d and rapier2d in f32** — the builds Bevy games use
//! through bevy_rapier2d. The same shapes ([`Ellipse`], [`RoundedPolygon`], [`CapsuleEllipse`],
//! [`CustomCurve`]) and the same drop-in [`SmoothDispatcher`], with f32 at the boundary:
//!
//! ```
//! use rapier2d::prelude::*;
//! use smooth_ccd2d_f32::{Ellipse, RoundedPolygon, SmoothDispatcher};
//!
//! let mut colliders = ColliderSet::new();
//! colliders.insert(ColliderBuilder::new(SharedShape::new(Ellipse::new(0.5, 0.2))).build());
//! colliders.insert(ColliderBuilder::new(SharedShape::new(RoundedPolygon::regular(7, 1.0, 0.15))).build());
//! // The one line that adopts the crate: the narrow phase's query dispatcher.
//! let narrow_phase = NarrowPhase::with_query_dispatcher(SmoothDispatcher::default());
//! # let _ = narrow_phase;
//! ```
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

#![warn(missing_docs)]

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
pub use core_hooks::CoreContactHooks;
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
