//! Errors for invalid shape parameters.

use core::fmt;

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

/// Checks that `value` is finite and > 0.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, ShapeError> {
    if !value.is_finite() {
        Err(ShapeError::NotFinite { name, value })
    } else if value <= 0.0 {
        Err(ShapeError::NotPositive { name, value })
    } else {
        Ok(value)
    }
}

/// Checks that `value` is finite and ≥ 0.
pub(crate) fn non_negative(name: &'static str, value: f64) -> Result<f64, ShapeError> {
    if !value.is_finite() {
        Err(ShapeError::NotFinite { name, value })
    } else if value < 0.0 {
        Err(ShapeError::Negative { name, value })
    } else {
        Ok(value)
    }
}
