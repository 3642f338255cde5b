//! The moving-pairs CCD pass: exact continuous collision detection between two bodies that
//! both move within a rapier step (issue 30).
//!
//! rapier's CCD sweeps a fast body against targets held still: fixed geometry for every fast
//! body, and for a body with CCD enabled (a "bullet") kinematic and dynamic bodies too, each at
//! its end-of-step pose — never against another bullet (`tier_allows` in rapier's
//! `dynamics/ccd/sweeps.rs`). Two fast bodies therefore pass through each other, whatever the
//! dispatcher. The pass runs around `PhysicsPipeline::step` (rapier's step takes its own
//! `CCDSolver`: the pass cannot replace it) and checks the pairs of two moving bodies with the
//! crate's exact time of impact of two bodies that both translate and spin.
//!
//! # Layout
//!
//! * `path`: [`StepPath`], a body's path over the step (the start pose to the solved end pose,
//!   constant velocity and spin; the turn rule);
//! * `records`: the pass's f64 records of the bodies, colliders and pairs;
//! * `broad`: the pairs from the fast bodies' swept boxes (sort and sweep);
//! * `schedule`: the event loop, earliest impact first, and its argument;
//! * `options`, `report`: [`MovingPairsOptions`], [`MovingPairsReport`];
//! * `adapter`: `MovingPairs` for a rapier build (a hidden macro), instantiated for
//!   rapier2d-f64 in `rapier_f64` (feature `rapier`) and for rapier2d in the f32 package.

mod adapter;
mod broad;
mod options;
mod path;
#[cfg(feature = "rapier")]
mod rapier_f64;
mod records;
mod report;
mod schedule;

pub use options::{MovingPairsOptions, PairScope};
#[cfg(feature = "rapier")]
pub use rapier_f64::MovingPairs;
pub use report::{MovingPairsReport, PassStatus};

/// The pass's plain-f64 core, for `moving_pairs_rapier!` (the rapier adapters of both
/// packages). Not a public API.
#[doc(hidden)]
pub mod core {
    pub use super::broad::Broad;
    pub use super::path::{may_be_fast, StepPath};
    pub use super::records::{PassBody, PassCollider, PassPair};
    pub use super::schedule::{sensor_crossing, CastOutcome, PairCast, Schedule};
    pub use parry2d_f64::math::{Pose, Vector};
    pub use parry2d_f64::query::NonlinearRigidMotion;
}

#[allow(unused_imports)]
use path::StepPath;
