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
}

impl Default for MovingPairsOptions {
    fn default() -> Self {
        MovingPairsOptions {
            scope: PairScope::Bullets,
            fast_fraction: 0.5,
        }
    }
}
