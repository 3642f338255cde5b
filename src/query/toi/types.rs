//! The public types of the time of impact: options, status, cost, result and trace events.

#[cfg(doc)]
use crate::error::QueryError;
use crate::error::{tolerance_ok, AllFinite};
use crate::numerics::math::Vector;
use crate::query::path::MotionPath;
use crate::query::stationary::DistanceOptions;

/// Tolerances, caps and switches of [`crate::time_of_impact`]. Distances are relative to the size s
/// of the pair: the larger bounding radius of the two shapes about their local origins.
///
/// Build them from the default with the `with_*` methods (the struct is `#[non_exhaustive]`:
/// later versions may add options):
///
/// ```
/// use smooth_ccd2d::ToiOptions;
/// let opts = ToiOptions::default().with_target_distance(1e-6).with_stop_at_penetration(false);
/// assert_eq!(opts.target_distance, 1e-6);
/// assert_eq!(opts.distance_tolerance, 1e-10);
/// ```
#[derive(Copy, Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct ToiOptions {
    /// Target distance δ ≥ 0 (absolute): contact is D(t) = δ. Default 0.
    pub target_distance: f64,
    /// Contact is accepted when δ ≤ D ≤ δ + `distance_tolerance`·s (default 1e-10).
    pub distance_tolerance: f64,
    /// |distanceSide| accepted by the corrector, relative to s (default 1e-10).
    pub side_tolerance: f64,
    /// Cap on accepted predictor steps (default 20 000).
    pub max_steps: usize,
    /// Cap on pair evaluations of one query, all steps together (default 1 000 000: tens of
    /// milliseconds; ordinary queries take tens to thousands). Reaching it ends the query with
    /// [`ToiStatus::OutOfIterations`]; it bounds the time of a query whatever the input.
    pub max_evaluations: usize,
    /// Cap on Halley iterations of one correction (default 30).
    pub max_corrector_iterations: usize,
    /// Report an initial contact immediately (true) or look past a separating one (false).
    pub stop_at_penetration: bool,
    /// Options of the stationary distance used at the start and to recover.
    pub distance: DistanceOptions,
    /// The path the bodies take between the window's end poses (default
    /// [`MotionPath::ConstantSpin`], parry's motion itself).
    pub path: MotionPath,
}

impl Default for ToiOptions {
    fn default() -> Self {
        Self {
            target_distance: 0.0,
            distance_tolerance: 1e-10,
            side_tolerance: 1e-10,
            max_steps: 20_000,
            max_evaluations: 1_000_000,
            max_corrector_iterations: 30,
            stop_at_penetration: true,
            distance: DistanceOptions::default(),
            path: MotionPath::ConstantSpin,
        }
    }
}

/// How a time-of-impact query ([`crate::time_of_impact`], [`crate::time_of_impact_halfspace`])
/// ended. Whatever the status, `time` lies in `[start_time, end_time]` and every number of the
/// [`TimeOfImpact`] is finite; bad input is a [`QueryError`] instead. Below, δ is the target
/// distance, tol = `distance_tolerance`·s and s the larger bounding radius of the two shapes.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum ToiStatus {
    /// The shapes reach the target distance at `time` and not before:
    /// δ − 1e-12·s ≤ D(`time`) ≤ δ + tol, and D > δ − 1e-12·s on [start, `time`).
    ///
    /// One exception, with `stop_at_penetration = false` only: shapes in contact at the start
    /// and separating are followed until they part; if they approach again while still in
    /// contact, `time` is that moment and `distance` ≤ δ + tol (rapier's CCD for solid bodies).
    Hit,
    /// The shapes are within δ + tol at the start, and `stop_at_penetration` is set or they are
    /// approaching (D' ≤ 0 along the contact): `time` is the start time. Also the answer of an
    /// empty window (`start_time == end_time`) with the shapes in contact.
    PenetratingAtStart,
    /// No contact in the window: D > δ − 1e-12·s until `end_time` (a graze that comes within
    /// tol of δ without reaching it may end either way), or the bounding circles about the
    /// rotation centres part for good (`time` is where tracking stopped). Also: an empty window
    /// with the shapes apart, and, with `stop_at_penetration = false`, a contact at the start
    /// that keeps separating until the window ends.
    NoHit,
    /// A cap was reached before the window was covered: [`ToiOptions::max_steps`] predictor
    /// steps, [`ToiOptions::max_evaluations`] pair evaluations, or a step the guard allows is
    /// too short to advance `time` in floating point (a spin too fast for the window). No
    /// contact in [start, `time`); nothing is known after. Seen with thin ellipses (1:1e6)
    /// spinning for many turns, and beyond the supported scales and axis ratios (docs/performance.md, "Limits").
    OutOfIterations,
}

impl ToiStatus {
    /// parry's status for a reported hit (`None` for [`crate::ToiStatus::NoHit`]).
    pub fn to_parry(self) -> Option<parry2d_f64::query::ShapeCastStatus> {
        use parry2d_f64::query::ShapeCastStatus as S;
        match self {
            ToiStatus::Hit => Some(S::Converged),
            ToiStatus::PenetratingAtStart => Some(S::PenetratingOrWithinTargetDist),
            ToiStatus::OutOfIterations => Some(S::OutOfIterations),
            ToiStatus::NoHit => None,
        }
    }
}

/// What a query cost.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct ToiCost {
    /// Accepted predictor steps.
    pub predictor_steps: usize,
    /// Halley (and bisection) iterations of the corrector, all steps together.
    pub corrector_iterations: usize,
    /// Rejected steps retried with a shorter step.
    pub backtracks: usize,
    /// Evaluations of the pair (φ-only and full jets).
    pub evaluations: usize,
    /// Steps whose length was set by the guard.
    pub guard_limited_steps: usize,
}

/// The result of [`crate::time_of_impact`]. Points and normals are at `time`, each in its own shape's
/// local frame, in the caller's order of the shapes.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct TimeOfImpact {
    /// How the query ended.
    pub status: ToiStatus,
    /// Impact time (`Hit`), start time (`PenetratingAtStart`), last safe time
    /// (`OutOfIterations`), or where tracking stopped (`NoHit`).
    pub time: f64,
    /// Signed distance at `time`.
    pub distance: f64,
    /// dD/dt at `time` along the contact (negative: approaching).
    pub distance_rate: f64,
    /// Witness point on shape 1 (its local frame).
    pub point1: Vector,
    /// Witness point on shape 2 (its local frame).
    pub point2: Vector,
    /// Shape 1's outward normal at its witness (its local frame).
    pub normal1: Vector,
    /// Shape 2's outward normal at its witness (its local frame).
    pub normal2: Vector,
    /// What it cost.
    pub cost: ToiCost,
}

impl TimeOfImpact {
    /// The same impact with the roles of the two shapes exchanged (witness points and normals
    /// swapped; time, distance and cost unchanged).
    pub fn swapped(self) -> Self {
        Self {
            point1: self.point2,
            point2: self.point1,
            normal1: self.normal2,
            normal2: self.normal1,
            ..self
        }
    }
}

/// One event of the tracked path, for figures and debugging ([`crate::time_of_impact_traced`]).
///
/// φ is recorded unwrapped — continuous along the path, so it may leave [−π, π) after turns;
/// wrap it with [`crate::method::wrap_phi`] to evaluate or draw.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum TraceEvent {
    /// The starting point from the stationary distance.
    Start {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
        /// D.
        distance: f64,
    },
    /// A predictor step landed at (φ, t).
    Predict {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
    },
    /// A corrector iteration at fixed t moved to φ with distanceSide `side`.
    Correct {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
        /// distanceSide after the iteration.
        side: f64,
    },
    /// A step was rejected at t and retried shorter.
    Backtrack {
        /// φ of the rejected point.
        phi: f64,
        /// t of the rejected point.
        t: f64,
    },
    /// A step was accepted at (φ, t) with distance D.
    Accept {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
        /// D.
        distance: f64,
    },
    /// Contact.
    Impact {
        /// φ.
        phi: f64,
        /// t.
        t: f64,
    },
}

pub(crate) trait Tracer {
    fn push(&mut self, e: TraceEvent);
}
pub(crate) struct NoTrace;
impl Tracer for NoTrace {
    #[inline(always)]
    fn push(&mut self, _: TraceEvent) {}
}
impl Tracer for Vec<TraceEvent> {
    fn push(&mut self, e: TraceEvent) {
        Vec::push(self, e)
    }
}

impl ToiOptions {
    /// With target distance δ ≥ 0 (absolute).
    pub fn with_target_distance(mut self, target_distance: f64) -> Self {
        self.target_distance = target_distance;
        self
    }

    /// With this distance tolerance (relative to the size).
    pub fn with_distance_tolerance(mut self, distance_tolerance: f64) -> Self {
        self.distance_tolerance = distance_tolerance;
        self
    }

    /// With this side tolerance (relative to the size).
    pub fn with_side_tolerance(mut self, side_tolerance: f64) -> Self {
        self.side_tolerance = side_tolerance;
        self
    }

    /// With this cap on accepted predictor steps.
    pub fn with_max_steps(mut self, max_steps: usize) -> Self {
        self.max_steps = max_steps;
        self
    }

    /// With this cap on pair evaluations of one query.
    pub fn with_max_evaluations(mut self, max_evaluations: usize) -> Self {
        self.max_evaluations = max_evaluations;
        self
    }

    /// With this cap on Halley iterations of one correction.
    pub fn with_max_corrector_iterations(mut self, max_corrector_iterations: usize) -> Self {
        self.max_corrector_iterations = max_corrector_iterations;
        self
    }

    /// Reporting an initial contact immediately (true) or looking past a separating one (false).
    pub fn with_stop_at_penetration(mut self, stop_at_penetration: bool) -> Self {
        self.stop_at_penetration = stop_at_penetration;
        self
    }

    /// With these options of the stationary distance (at the start and to recover).
    pub fn with_distance_options(mut self, distance: DistanceOptions) -> Self {
        self.distance = distance;
        self
    }

    /// On this path ([`MotionPath`]).
    pub fn with_path(mut self, path: MotionPath) -> Self {
        self.path = path;
        self
    }

    /// Whether the target distance and the tolerances are finite and ≥ 0 (otherwise the queries
    /// answer [`QueryError::NonFinite`]).
    pub(crate) fn is_valid(&self) -> bool {
        tolerance_ok(self.target_distance)
            && tolerance_ok(self.distance_tolerance)
            && tolerance_ok(self.side_tolerance)
            && self.distance.is_valid()
    }
}

impl AllFinite for TimeOfImpact {
    fn all_finite(&self) -> bool {
        self.time.is_finite()
            && self.distance.is_finite()
            && self.distance_rate.is_finite()
            && self.point1.is_finite()
            && self.point2.is_finite()
            && self.normal1.is_finite()
            && self.normal2.is_finite()
    }
}
