//! Pieces of a piecewise curve: the φ-interval of each piece (between
//! [`ConvexCurve::breakpoints`]), the piece holding a φ, and the flat pieces (on which the normal
//! does not turn and the point moves: a polygon's edge, the segment of a `CapsuleEllipse`).

use crate::curve::ConvexCurve;
use crate::numerics::angle::wrap_phi;
use crate::numerics::math::{unit_or_x, Vector};
use core::f64::consts::PI;

/// How far (relative, in the normal and in its derivative) the normal may move along a piece
/// for the piece to count as flat.
const FLATNESS: f64 = 1e-12;
/// A flat piece shorter than this fraction of the curve's bounding radius is not reported (its
/// ends coincide to rounding).
const MIN_FLAT_LENGTH: f64 = 1e-12;

/// The φ-interval of piece `k` of a curve (unwrapped: `end > start`, the last piece wraps).
#[inline]
pub(crate) fn piece_bounds(bp: &[f64], k: usize) -> (f64, f64) {
    if bp.is_empty() {
        return (-PI, PI);
    }
    let s = bp[k];
    let e = if k + 1 < bp.len() { bp[k + 1] } else { bp[0] + 2.0 * PI };
    (s, e)
}

/// Index of the piece containing φ (pieces start at the breakpoints; the last one wraps).
#[inline]
pub(crate) fn piece_index(bp: &[f64], phi: f64) -> usize {
    if bp.is_empty() {
        return 0;
    }
    let phi = wrap_phi(phi);
    let k = bp.partition_point(|&b| b <= phi);
    if k == 0 {
        bp.len() - 1
    } else {
        k - 1
    }
}

/// Whether the piece `[s, e]` of `c` is flat: at a quarter, the middle and three quarters of
/// it the normal does not turn (|N'| ≤ 1e-12), stays the same (to 1e-12) and the point moves.
/// The one flatness test of the crate (flat pieces of the feature map, feature ids of the
/// manifolds).
pub(crate) fn piece_span_is_flat(c: &dyn ConvexCurve, s: f64, e: f64) -> bool {
    if e <= s || e.is_nan() || s.is_nan() {
        return false;
    }
    let samples = [0.25, 0.5, 0.75].map(|t| c.eval(s + t * (e - s)));
    let n0 = samples[1].normal;
    samples.iter().all(|cp| {
        cp.is_finite() && cp.d_normal.length() <= FLATNESS && (cp.normal - n0).length() <= FLATNESS && cp.speed() > 0.0
    })
}

/// Whether piece `k` of `c` is flat ([`piece_span_is_flat`]).
pub(crate) fn piece_is_flat(c: &dyn ConvexCurve, k: usize) -> bool {
    let (s, e) = piece_bounds(c.breakpoints(), k);
    piece_span_is_flat(c, s, e)
}

/// A flat piece of a curve: the boundary segment from `start` to `end` (counter-clockwise)
/// with outward unit normal `normal`; `index` is the piece's index (between breakpoints).
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct FlatPiece {
    /// Outward unit normal.
    pub normal: Vector,
    /// First end (counter-clockwise).
    pub start: Vector,
    /// Second end.
    pub end: Vector,
    /// Index of the piece.
    pub index: u32,
}

/// Detects the flat pieces of a curve: pieces between two breakpoints along which the normal
/// does not turn and the point moves.
pub(crate) fn flat_pieces(c: &dyn ConvexCurve) -> Vec<FlatPiece> {
    let bp = c.breakpoints();
    let mut out = Vec::new();
    if bp.is_empty() {
        return out;
    }
    let size = c.bounding_radius().abs().max(f64::MIN_POSITIVE);
    for k in 0..bp.len() {
        let (s, e) = piece_bounds(bp, k);
        if !piece_span_is_flat(c, s, e) {
            continue;
        }
        let n0 = c.eval(s + 0.5 * (e - s)).normal;
        let (p0, p1) = (c.eval(s).point, c.eval(e).point);
        if !(p0.is_finite() && p1.is_finite()) || (p1 - p0).length() <= MIN_FLAT_LENGTH * size {
            continue;
        }
        out.push(FlatPiece {
            normal: unit_or_x(n0),
            start: p0,
            end: p1,
            index: k as u32,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn piece_index_handles_the_wrap() {
        let bp = [-1.0, 0.0, 1.0];
        assert_eq!(piece_index(&bp, -0.5), 0);
        assert_eq!(piece_index(&bp, 0.0), 1);
        assert_eq!(piece_index(&bp, 2.0), 2);
        assert_eq!(piece_index(&bp, -2.0), 2);
        assert_eq!(piece_index(&[], 1.0), 0);
    }
}
