//! The method's building blocks: for writing a [`ConvexCurve`](crate::ConvexCurve) and for
//! studying the algorithm. A user of the shapes, the queries and the dispatcher needs none of it.
//!
//! * **Writing a curve**: [`wrap_phi`] brings φ into [−π, π) (a curve's `eval` must accept any
//!   φ); [`Dual2`] differentiates a formula in φ twice, for `CurvePoint`'s derivatives.
//! * **The specification's distance functions**: [`eval_pair`] (and [`eval_pair_at`]) evaluate
//!   distanceFwd F and distanceSide S of a pair at one (φ, t), with gradient and Hessian in
//!   (φ, t), as a [`PairJet`]; [`PairFrame`] places object1 in object2's frame at a time t;
//!   [`Jet2`] and [`JetVec`] carry the derivatives. The crate's trackers are built on these
//!   (docs/theory.md in the repository gives the method).
//!
//! These items were at the crate's root up to 0.1.0 (CHANGELOG, "Changed").
//!
//! ```
//! use parry2d_f64::math::Pose;
//! use smooth_ccd2d::method::{eval_pair, wrap_phi, Dual2, PairFrame};
//! use smooth_ccd2d::{BallCurve, Ellipse};
//!
//! // φ is wrapped into [−π, π).
//! assert_eq!(wrap_phi(3.0 * std::f64::consts::PI), -std::f64::consts::PI);
//!
//! // d/dφ and d²/dφ² of a·cos φ at φ = 0.3, as a curve's `eval` would compute them.
//! let x = Dual2::var(0.3).cos().scale(2.0);
//! assert!((x.d + 2.0 * 0.3f64.sin()).abs() < 1e-15 && (x.dd + 2.0 * 0.3f64.cos()).abs() < 1e-15);
//!
//! // An ellipse (object1) and a disc of radius 0.5 (object2, strictly convex) 3 apart along x:
//! // at φ = 0, the ellipse's point facing the disc, distanceFwd is the gap and distanceSide 0.
//! let (ellipse, disc) = (Ellipse::new(1.0, 0.5), BallCurve { radius: 0.5 });
//! let frame = PairFrame::from_pos12(&Pose::translation(3.0, 0.0));
//! let j = eval_pair(&ellipse, &disc, &frame, 0.0).expect("the disc is strictly convex");
//! assert!((j.fwd.v - 1.5).abs() < 1e-12 && j.side.v.abs() < 1e-12);
//! ```

pub use crate::numerics::angle::wrap_phi;
pub use crate::numerics::jet::{Dual2, Jet2, JetVec};
pub use crate::numerics::motion::PairFrame;
pub use crate::query::pair::{eval_pair, eval_pair_at, PairJet};
