//! Arcs of directions: membership by cross products (no angles).

use crate::numerics::math::{cross, Vector};

/// Whether direction `d` (any length) lies in the arc from `a` counter-clockwise to `b`.
#[inline]
pub(crate) fn in_arc(a: Vector, b: Vector, d: Vector) -> bool {
    let c = cross(a, b);
    if c > 0.0 {
        cross(a, d) >= 0.0 && cross(d, b) >= 0.0
    } else if c == 0.0 && a.dot(b) < 0.0 {
        cross(a, d) >= 0.0
    } else if c == 0.0 {
        false
    } else {
        !(cross(b, d) > 0.0 && cross(d, a) > 0.0)
    }
}

/// An arc of directions: between two (counter-clockwise), or all of them.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) enum Arc {
    Between(Vector, Vector),
    Full,
}

impl Arc {
    /// Whether direction `d` (any length) is in the arc.
    #[inline]
    pub(crate) fn contains(self, d: Vector) -> bool {
        match self {
            Arc::Between(a, b) => in_arc(a, b, d),
            Arc::Full => true,
        }
    }
}
