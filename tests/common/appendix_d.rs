//! The specification's Appendix D scene: a rounded regular heptagon (circumradius 1, corner radius
//! 0.15) starting at (−1.85, 0), spinning at 30 rad/s and drifting at (2, 0) m/s, against a fixed
//! ellipse (a = 0.5, b = 1.5) at the origin, over the window [0, 1] s.
//!
//! Used by `tests/toi_vs_reference.rs` (through `mod common`) and by `examples/appendix_d.rs`,
//! `examples/stationary.rs` and `crates/dev/examples/figures.rs` (through `examples/common`).
#![allow(dead_code)]

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use smooth_ccd2d::{time_of_impact, Ellipse, RoundedPolygon, TimeOfImpact, ToiOptions};

/// The heptagon's starting position.
pub const START: Vector = Vector::new(-1.85, 0.0);
/// The heptagon's velocity (m/s).
pub const LINVEL: Vector = Vector::new(2.0, 0.0);
/// The heptagon's spin (rad/s).
pub const ANGVEL: f64 = 30.0;
/// The window of the time of impact (s).
pub const WINDOW: (f64, f64) = (0.0, 1.0);

/// The moving heptagon (object 1).
pub fn heptagon() -> RoundedPolygon {
    RoundedPolygon::regular(7, 1.0, 0.15)
}

/// The fixed ellipse (object 2).
pub fn ellipse() -> Ellipse {
    Ellipse::new(0.5, 1.5)
}

/// The heptagon's motion: from [`START`] at angle 0, at [`LINVEL`] and [`ANGVEL`] about its centre.
pub fn heptagon_motion() -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(Pose::new(START, 0.0), Vector::ZERO, LINVEL, ANGVEL)
}

/// The ellipse's motion: at rest at the origin.
pub fn ellipse_motion() -> NonlinearRigidMotion {
    NonlinearRigidMotion::constant_position(Pose::IDENTITY)
}

/// The crate's time of impact of the scene (default options, over [`WINDOW`]): a hit at
/// t ≈ 0.1128168 s, about half a turn.
pub fn impact() -> TimeOfImpact {
    time_of_impact(
        &heptagon(),
        &heptagon_motion(),
        &ellipse(),
        &ellipse_motion(),
        WINDOW.0,
        WINDOW.1,
        &ToiOptions::default(),
    )
    .expect("finite motions")
}
