//! [`MovingPairsOptions`]: which pairs the moving-pairs pass checks and which bodies are fast.

/// Which bodies make a pair the moving-pairs pass checks: a pair is checked when one of its
/// bodies is a fast body of this scope and the other moves within the step too (a dynamic or
/// kinematic body whose pose changed).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum PairScope {
    /// Fast dynamic bodies with CCD enabled (`RigidBodyBuilder::ccd_enabled(true)`, rapier's
    /// "bullets"): the bodies rapier sweeps against other bodies, each taken at its end pose,
    /// and never against another bullet. The default: the pass adds the pairs of two moving
    /// bodies to the bodies their user opted into CCD.
    #[default]
    Bullets,
    /// Every fast dynamic body, CCD enabled or not (rapier sweeps those without it against
    /// fixed geometry only).
    FastBodies,
}

/// The options of the moving-pairs pass (`MovingPairs`, feature `rapier`).
///
/// ```
/// use smooth_ccd2d::{MovingPairsOptions, PairScope};
/// let o = MovingPairsOptions::default();
/// assert_eq!(o.scope, PairScope::Bullets);
/// assert_eq!(o.fast_fraction, 0.5);
/// assert!(o.fixed_targets);
/// assert_eq!(o.fast_turn, core::f64::consts::FRAC_PI_4);
/// let every_fast_body = MovingPairsOptions { scope: PairScope::FastBodies, ..o };
/// # let _ = every_fast_body;
/// ```
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct MovingPairsOptions {
    /// Which pairs are checked (default [`PairScope::Bullets`]).
    pub scope: PairScope,
    /// The fast-body rule: a body is fast when a point of it may have moved more than this
    /// fraction of its thinnest collider's CCD thickness (`Shape::ccd_thickness`) within the
    /// step. The distance is bounded by the travel of its centre of mass plus the chord of
    /// its turn, R·min(|Δθ|, 2) with R its largest distance from the centre of mass
    /// (`RigidBodyMassProps::max_extent`). Default 0.5: rapier's own rule
    /// (`RigidBodyCcd::FAST_BODY_SAFETY_FACTOR`, there on |sin Δθ|·R). 0 makes every moving
    /// body of the scope fast.
    pub fast_fraction: f64,
    /// Whether a fast body that turns by more than [`MovingPairsOptions::fast_turn`] within
    /// the step (its angular velocity times the step, or its path's turn: rapier may have
    /// clamped a body spinning at 2,200 rad/s to a twentieth of its step and half a radian) is
    /// also checked against the geometry rapier's CCD holds still: colliders of no
    /// body or of a fixed body, and colliders of bodies asleep. Default `true`.
    ///
    /// rapier sweeps a fast body against those itself, on the path it clamps a body on: the
    /// rotation *nlerped* the short way between the step's two end rotations, which is the
    /// body's path only for small turns (rapier caps a body's turn at π/4 a step unless
    /// `allow_fast_rotation` lifts the cap, and its solver notes that a turn of π/2 a step breaks
    /// its CCD). A body spun past that (a parry cuboid at 2,470 rad/s turns 41 rad a step) is
    /// clamped at a pose of a path it never follows, a pose that can be inside the wall with its
    /// contact points leaving it, so the solver pushes nothing and the body crosses the wall at a
    /// later step. With this option the pass checks such a body against those targets with the
    /// crate's exact time of impact on its own path (the constant spin it integrated) and stops
    /// it at its first contact there, as it stops a pair of moving bodies. It acts only on
    /// bodies past the turn, which rapier's cap never lets exist: a scene without
    /// `allow_fast_rotation` costs nothing more.
    pub fixed_targets: bool,
    /// The turn (radians: the larger of |ω|·dt and its path's |Δθ|) past which a fast body is
    /// checked against still targets ([`MovingPairsOptions::fixed_targets`]). Default π/4,
    /// rapier's own per-step rotation cap (`MAX_ROTATION` of rapier's solver): the turn rapier's
    /// CCD is built for; past it the nlerped path drifts from the body's (by any amount past
    /// π/2, the other way round past π). 0 checks every fast body that turns at all; a NaN
    /// or +∞ checks none (as `fixed_targets: false`).
    pub fast_turn: f64,
}

impl Default for MovingPairsOptions {
    fn default() -> Self {
        MovingPairsOptions {
            scope: PairScope::Bullets,
            fast_fraction: 0.5,
            fixed_targets: true,
            fast_turn: core::f64::consts::FRAC_PI_4,
        }
    }
}
