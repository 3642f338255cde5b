//! The world of the f32 package's shot tests: rapier2d (f32) at 60 Hz without gravity, the
//! `SmoothDispatcher` as the narrow phase's query dispatcher, and rapier's linear velocity cap
//! lifted (`normalized_max_linear_velocity`), so that the shots run at the speeds they claim.
//! Shared by path (`mod uncapped;`); bodies that turn past rapier's rotation cap also need
//! `allow_fast_rotation`, which the tests set on their bodies.

use rapier2d::prelude::*;
use smooth_ccd2d_f32::SmoothDispatcher;

/// A 60 Hz world with no gravity, the crate's dispatcher and no linear velocity cap.
pub fn uncapped_world() -> PhysicsWorld {
    let mut w = PhysicsWorld {
        gravity: Vector::ZERO,
        narrow_phase: NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
        ..PhysicsWorld::default()
    };
    w.integration_parameters.dt = 1.0 / 60.0;
    w.integration_parameters.normalized_max_linear_velocity = f32::MAX;
    w
}
