//! Errors for invalid shape parameters, and the range of lengths a shape accepts.

use core::fmt;

/// The smallest positive length a shape accepts (semi-axis, radius, circumradius, corner radius,
/// size of a polygon). With every length in [`MIN_LENGTH`, `MAX_LENGTH`], products of up to six
/// lengths (the algorithms form squares, curvatures a²/b, a²b²/h³, …) stay within the normal
/// range of `f64` (1e-300 … 1e300), so no computation underflows to 0 or overflows to ∞.
/// Outside it the constructors return [`ShapeError::OutOfRange`].
pub const MIN_LENGTH: f64 = 1e-50;

/// The largest length (or vertex coordinate) a shape accepts; see [`MIN_LENGTH`].
pub const MAX_LENGTH: f64 = 1e50;

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
            ShapeError::Invalid(msg) => f.write_str(msg),
        }
    }
}

impl std::error::Error for ShapeError {}

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
pub(crate) fn vertices_in_range(vertices: &[crate::math::Vector]) -> Result<(), ShapeError> {
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

/// A tolerance the queries accept: finite and ≥ 0.
fn tolerance_ok(x: f64) -> bool {
    x.is_finite() && x >= 0.0
}

impl crate::stationary::DistanceOptions {
    /// Whether the tolerances are finite and ≥ 0 (otherwise the queries answer
    /// [`crate::QueryError::NonFinite`]). Caps of 0 are allowed: the query then ends at once with
    /// `OutOfIterations`.
    pub(crate) fn is_valid(&self) -> bool {
        tolerance_ok(self.side_tolerance) && tolerance_ok(self.distance_tolerance)
    }
}

impl crate::toi::ToiOptions {
    /// Whether the target distance and the tolerances are finite and ≥ 0 (otherwise the queries
    /// answer [`crate::QueryError::NonFinite`]).
    pub(crate) fn is_valid(&self) -> bool {
        tolerance_ok(self.target_distance)
            && tolerance_ok(self.distance_tolerance)
            && tolerance_ok(self.side_tolerance)
            && self.distance.is_valid()
    }
}

impl crate::stationary::StationaryDistance {
    /// Whether every number of the answer is finite (the public queries answer
    /// [`crate::QueryError::Degenerate`] otherwise).
    pub(crate) fn is_finite(&self) -> bool {
        self.distance.is_finite()
            && self.phi.is_finite()
            && self.point1.is_finite()
            && self.point2.is_finite()
            && self.normal1.is_finite()
            && self.normal2.is_finite()
    }
}

impl crate::toi::TimeOfImpact {
    /// Whether every number of the answer is finite (the public queries answer
    /// [`crate::QueryError::Degenerate`] otherwise).
    pub(crate) fn is_finite(&self) -> bool {
        self.time.is_finite()
            && self.distance.is_finite()
            && self.distance_rate.is_finite()
            && self.point1.is_finite()
            && self.point2.is_finite()
            && self.normal1.is_finite()
            && self.normal2.is_finite()
    }
}

/// `r`, or [`crate::QueryError::Degenerate`] when the answer holds a non-finite number: the last
/// guard of the public queries (finite but absurd input, e.g. a rotation of 1e300, can overflow
/// where no earlier check looks).
pub(crate) fn finite_toi(
    r: Result<crate::toi::TimeOfImpact, crate::QueryError>,
) -> Result<crate::toi::TimeOfImpact, crate::QueryError> {
    match r {
        Ok(t) if !t.is_finite() => Err(crate::QueryError::Degenerate),
        r => r,
    }
}

/// As [`finite_toi`] for a stationary distance.
pub(crate) fn finite_distance(
    r: Result<crate::stationary::StationaryDistance, crate::QueryError>,
) -> Result<crate::stationary::StationaryDistance, crate::QueryError> {
    match r {
        Ok(d) if !d.is_finite() => Err(crate::QueryError::Degenerate),
        r => r,
    }
}
