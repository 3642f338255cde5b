//! [`MovingPairsReport`]: what one run of the moving-pairs pass did, with its status.

/// How a run of the moving-pairs pass ended.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum PassStatus {
    /// Every pair was checked; every body that had to stop was stopped (the default).
    #[default]
    Done,
    /// Nothing to do: the step had no length (`dt` ≤ 0, or not finite) or no start was
    /// recorded (`before_step` was not called).
    Skipped,
    /// The event loop reached its bound (never expected: each event retires a pair or stops
    /// a body, and the bound is their count); the bodies stopped so far stay stopped.
    OutOfEvents,
}

/// What one run of the pass did (`MovingPairs::after_step` returns it; every iterative query
/// of the pass reports a status, counted here).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct MovingPairsReport {
    /// How the run ended.
    pub status: PassStatus,
    /// Bodies whose pose changed over the step.
    pub moving_bodies: usize,
    /// Moving bodies that are fast bodies of the scope.
    pub fast_bodies: usize,
    /// Fast bodies that turned past `MovingPairsOptions::fast_turn` (checked against the still
    /// targets too, with `MovingPairsOptions::fixed_targets`).
    pub turning_bodies: usize,
    /// Bodies left out: a non-finite pose or velocity, or a path whose velocities overflow.
    pub refused_bodies: usize,
    /// Collider pairs whose swept boxes overlap, after the groups and hooks (solid and sensor).
    pub pairs: usize,
    /// Times of impact computed.
    pub casts: usize,
    /// Casts that found a contact (status `Converged` or `PenetratingOrWithinTargetDist`).
    pub hits: usize,
    /// Casts that stopped at a cap (`OutOfIterations`): no contact before the time they
    /// reached, which the pass treats as a contact there (as rapier does).
    pub out_of_iterations: usize,
    /// Casts the dispatcher could not answer (`Unsupported`: a shape it does not know).
    pub unsupported: usize,
    /// Bodies the pass stopped (their pose set to their pose at their first impact).
    pub stopped_bodies: usize,
    /// Sensor crossings reported as a pair of intersection events (`Started`, `Stopped`).
    pub sensor_events: usize,
}
