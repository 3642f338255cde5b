//! The crate's errors: [`ShapeError`] (a shape could not be built) and [`QueryError`] (a query
//! could not run), and the range of lengths a shape accepts.

use crate::numerics::math::Vector;
use core::fmt;

/// The smallest positive length a shape accepts (semi-axis, radius, circumradius, corner radius,
/// size of a polygon). With every length in [`MIN_LENGTH`, `MAX_LENGTH`], products of up to six
/// lengths (the algorithms form squares, curvatures a²/b, a²b²/h³, …) stay within the normal
/// range of `f64` (1e-300 … 1e300), so no computation underflows to 0 or overflows to ∞.
/// Outside it the constructors return [`ShapeError::OutOfRange`].
pub const MIN_LENGTH: f64 = 1e-50;

/// The largest length (or vertex coordinate) a shape accepts; see [`MIN_LENGTH`].
pub const MAX_LENGTH: f64 = 1e50;

/// The most vertices a [`crate::RoundedPolygon`] accepts (2²⁰ = 1,048,576: about 60 MB of
/// vertices, normals and pieces). Every query on a polygon costs O(n log n) or less in its
/// vertex count n (a stationary query O(n) at most — 12 ms for the exact distance of a
/// 30,000-gon against a box —, a cast O(n) per turn of the pair), so the limit is one of
/// memory: the constructors check the count before they allocate
/// ([`ShapeError::TooManyVertices`]), where `RoundedPolygon::try_regular(1 << 40, …)` asked for
/// 17 TB and aborted the process.
pub const MAX_VERTICES: usize = 1 << 20;

/// Why a shape could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeError {
    /// A size parameter is NaN or infinite.
    NotFinite {
        /// The parameter's name.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A size parameter that must be positive is zero or negative.
    NotPositive {
        /// The parameter's name.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A size parameter that must be non-negative is negative.
    Negative {
        /// The parameter's name.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A finite, positive length outside [`MIN_LENGTH`, `MAX_LENGTH`] (a vertex coordinate
    /// beyond `MAX_LENGTH`, a polygon smaller than `MIN_LENGTH`).
    OutOfRange {
        /// The parameter's name.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// Fewer vertices than a polygon needs.
    TooFewVertices {
        /// How many were given.
        count: usize,
    },
    /// More vertices than a polygon accepts ([`MAX_VERTICES`]).
    TooManyVertices {
        /// How many were asked for.
        count: usize,
    },
    /// A vertex is NaN or infinite.
    VertexNotFinite {
        /// Its index.
        index: usize,
    },
    /// Two consecutive vertices coincide (relative to the polygon's size).
    RepeatedVertex {
        /// Index of the second of the two.
        index: usize,
    },
    /// The vertices do not form a strictly convex counter-clockwise polygon (a reflex, flat
    /// or clockwise corner at `index`, or the boundary winds more than once).
    NotConvex {
        /// The vertex where convexity fails.
        index: usize,
    },
    /// A parameter combination the shape does not support.
    Invalid(&'static str),
    /// A user's curve breaks the [`crate::ConvexCurve`] contract where
    /// [`crate::CustomCurve::try_new`] checks it (on a fixed sample of the curve).
    BrokenContract {
        /// The method that answered wrongly (`"eval"`, `"bounding_radius"`, `"support_jet"`, …).
        method: &'static str,
        /// What was wrong.
        reason: &'static str,
        /// Where: the φ, or the angle of the direction, at which it was found, or the value
        /// returned (NaN when none applies).
        at: f64,
    },
}

impl fmt::Display for ShapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShapeError::NotFinite { name, value } => {
                write!(f, "parameter `{name}` must be finite, got {value}")
            }
            ShapeError::NotPositive { name, value } => {
                write!(f, "parameter `{name}` must be positive, got {value}")
            }
            ShapeError::Negative { name, value } => {
                write!(f, "parameter `{name}` must be non-negative, got {value}")
            }
            ShapeError::OutOfRange { name, value } => write!(
                f,
                "parameter `{name}` must lie within [{MIN_LENGTH:e}, {MAX_LENGTH:e}], got {value:e}"
            ),
            ShapeError::TooFewVertices { count } => {
                write!(f, "parameter `vertices` needs at least 3 vertices, got {count}")
            }
            ShapeError::VertexNotFinite { index } => {
                write!(f, "parameter `vertices`: vertex {index} is not finite")
            }
            ShapeError::RepeatedVertex { index } => {
                write!(f, "parameter `vertices`: vertex {index} repeats the previous one")
            }
            ShapeError::NotConvex { index } => write!(
                f,
                "parameter `vertices`: not a strictly convex counter-clockwise polygon at vertex {index}"
            ),
            ShapeError::TooManyVertices { count } => write!(
                f,
                "parameter `vertices`: {count} vertices, more than the {MAX_VERTICES} accepted"
            ),
            ShapeError::Invalid(msg) => f.write_str(msg),
            ShapeError::BrokenContract { method, reason, at } => {
                write!(f, "ConvexCurve::{method} breaks its contract: {reason} (at {at})")
            }
        }
    }
}

impl std::error::Error for ShapeError {}

/// Checks the bounding radii of a query's curves at its entry: each finite and > 0, else
/// [`QueryError::Degenerate`] (a [`crate::BallCurve`] of radius 0, negative or NaN: its field is
/// public; a user's curve reporting no size).
pub(crate) fn curves_sized(radii: &[f64]) -> Result<(), QueryError> {
    if radii.iter().all(|r| r.is_finite() && *r > 0.0) {
        Ok(())
    } else {
        Err(QueryError::Degenerate)
    }
}

/// Checks that `value` is finite, > 0 and within [`MIN_LENGTH`, `MAX_LENGTH`].
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, ShapeError> {
    if !value.is_finite() {
        Err(ShapeError::NotFinite { name, value })
    } else if value <= 0.0 {
        Err(ShapeError::NotPositive { name, value })
    } else if !(MIN_LENGTH..=MAX_LENGTH).contains(&value) {
        Err(ShapeError::OutOfRange { name, value })
    } else {
        Ok(value)
    }
}

/// Checks that `value` is finite and ≥ 0, and within [`MIN_LENGTH`, `MAX_LENGTH`] unless 0.
pub(crate) fn non_negative(name: &'static str, value: f64) -> Result<f64, ShapeError> {
    if !value.is_finite() {
        Err(ShapeError::NotFinite { name, value })
    } else if value < 0.0 {
        Err(ShapeError::Negative { name, value })
    } else if value != 0.0 && !(MIN_LENGTH..=MAX_LENGTH).contains(&value) {
        Err(ShapeError::OutOfRange { name, value })
    } else {
        Ok(value)
    }
}

/// Checks the vertices of a polygon: every coordinate within ±[`MAX_LENGTH`] and the polygon's
/// size (its largest vertex distance from the origin) at least [`MIN_LENGTH`].
pub(crate) fn vertices_in_range(vertices: &[Vector]) -> Result<(), ShapeError> {
    let mut size = 0.0f64;
    for v in vertices {
        let m = v.x.abs().max(v.y.abs());
        if m > MAX_LENGTH {
            return Err(ShapeError::OutOfRange {
                name: "vertices",
                value: m,
            });
        }
        size = size.max(m);
    }
    if size < MIN_LENGTH {
        return Err(ShapeError::OutOfRange {
            name: "vertices",
            value: size,
        });
    }
    Ok(())
}

/// Why a query could not run. No query of the crate panics or returns a non-finite number: bad
/// input gives one of these. When several apply, [`crate::time_of_impact`] reports
/// `NotStrictlyConvex`, then `NonFinite`, then `EmptyWindow`; [`crate::stationary_distance`] reports
/// `NonFinite` before `NotStrictlyConvex`. [`crate::SmoothDispatcher`] turns them into parry's
/// `Unsupported` (except `EmptyWindow`: no hit).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum QueryError {
    /// A number of the input is NaN or infinite: a pose (`pos12`, a motion's start pose or local
    /// centre), a linear or angular velocity, a time of the window, a half-space's normal, or an
    /// option (the target distance or a tolerance; a negative one too).
    NonFinite,
    /// Object2 must be strictly convex (eq. 4 needs a unique point per normal):
    /// [`crate::stationary_distance`] needs `obj2` strictly convex, [`crate::time_of_impact`] one of the
    /// two shapes (it swaps the roles itself).
    NotStrictlyConvex,
    /// Every input is finite but a shape or a pose evaluated to a non-finite value: positions so
    /// large, or motions travelling so far in the window, that they overflow (beyond about
    /// 1e150; rates alone do not: the times of impact rescale time for rates beyond 2^±64 per
    /// second, unless the answer's own rate of distance passes f64's range, as a half-space
    /// spun at 5e301 rad/s does 5e6 m from its centre), a [`crate::BallCurve`] built with a
    /// non-finite or non-positive radius (its field
    /// is public), a user curve that returns NaN between the points its checks sampled, or whose
    /// `support_jet` fails there. The crate's own constructors refuse the lengths that would do
    /// this ([`crate::MIN_LENGTH`], [`crate::MAX_LENGTH`]).
    Degenerate,
    /// A shape the query cannot take: [`crate::shape_time_of_impact`] takes this crate's shapes
    /// and parry's convex shapes (ball, cuboid, capsule, segment, triangle, convex polygon and
    /// their round versions) and half-spaces, not composites, other custom shapes, two
    /// half-spaces or a box whose half-extents are not both positive.
    UnsupportedShape,
    /// The time window is reversed (`end_time < start_time`). An empty window
    /// (`start_time == end_time`) is not an error: the answer is at `start_time`,
    /// [`crate::ToiStatus::PenetratingAtStart`] or [`crate::ToiStatus::NoHit`].
    EmptyWindow,
    /// A motion the query's path cannot follow: [`crate::MotionPath::Nlerp`] with both bodies
    /// turning (the nlerp path of one body is a uniform turn on a translation clock; two
    /// bodies' turns have no common clock).
    UnsupportedMotion,
}

impl fmt::Display for QueryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            QueryError::NonFinite => "a pose, motion, time or option is not finite",
            QueryError::NotStrictlyConvex => {
                "neither shape is strictly convex (for stationary_distance: object2 is not); \
                 shape_time_of_impact takes two flat-sided shapes"
            }
            QueryError::Degenerate => "a shape evaluated to a non-finite value",
            QueryError::EmptyWindow => "the time window is reversed",
            QueryError::UnsupportedShape => "a shape the query cannot take",
            QueryError::UnsupportedMotion => "a motion the query's path cannot follow (nlerp with both bodies turning)",
        })
    }
}

impl std::error::Error for QueryError {}

/// Answers whose every number can be checked finite: the last guard of the queries (finite but
/// absurd input, e.g. a rotation of 1e300, can overflow where no earlier check looks).
pub(crate) trait AllFinite {
    /// Whether every number in the answer is finite.
    fn all_finite(&self) -> bool;
}

/// `r`, or [`QueryError::Degenerate`] when the answer holds a non-finite number.
pub(crate) fn finite<T: AllFinite>(r: Result<T, QueryError>) -> Result<T, QueryError> {
    match r {
        Ok(v) if !v.all_finite() => Err(QueryError::Degenerate),
        r => r,
    }
}

/// A tolerance the queries accept: finite and ≥ 0.
pub(crate) fn tolerance_ok(x: f64) -> bool {
    x.is_finite() && x >= 0.0
}
