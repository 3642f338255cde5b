//! Where the advancement starts: the exact contact at the window's start, or the face normal of
//! the body at rest along which the pair is furthest apart ([`face_separation`]).

use super::{lowest_piece, turning_of, PairOnPath};
use crate::numerics::math::{Real, Vector};
use crate::query::contact::{Contact, SupportShape, MAX_BREAKPOINTS};

/// Where an advancement starts at t₀: from the exact contact there (the caller's, or computed),
/// or from a separating axis fixed in A's frame ([`face_separation`]) — any separating axis
/// bounds the distance from below, so the steps along it are safe whichever it is; the exact
/// normal only makes the first crossing the closest one.
#[derive(Copy, Clone)]
pub(crate) enum Start {
    /// The exact contact at t₀ (shape 1 first), or `None` to compute it.
    Contact(Option<Contact>),
    /// A unit axis n in A's frame (from A towards B) with A's support h_A(n) along it, the
    /// pair apart along it by more than the tolerance at t₀.
    Axis { n: Vector, support: Real },
}

/// The largest separation of the pair at path time `t` along A's face normals (A the body of
/// `pair` that does not turn, `s1`, `s2` in the caller's order): the advancement's start along
/// it ([`Start::Axis`]) and the separation S_n(t) = min over B of n·q − h_A(n) (module docs), a
/// lower bound of the signed distance. The separating-axis theorem makes it the signed distance
/// itself when a vertex or an arc of B is nearest a face of A, the usual start of a body flying
/// at a wall; the advancement from it then takes the exact contact's own first axis without the
/// contact query. (B's faces, turning with it, were tried as well: more instructions a cast on
/// every body kind, their scan costing more than the contacts it saved.) `None` where A is not
/// a polygon with at least two faces, a polygon has more vertices than the contact query reads
/// ([`MAX_BREAKPOINTS`]), or a value is not finite.
pub(crate) fn face_separation(s1: SupportShape, s2: SupportShape, pair: &PairOnPath, t: Real) -> Option<(Start, Real)> {
    let (sa, sb) = pair.ordered(s1, s2);
    let SupportShape::Polygon {
        vertices,
        normals,
        radius,
    } = sa
    else {
        return None;
    };
    let turning = turning_of(sb, pair.k.centre)?;
    // Polygons of the contact query's size only (the scan is |A's faces| × |B's vertices|; a
    // polygon of 100,000 sides goes to the trackers as before).
    let small = |s: SupportShape| match s {
        SupportShape::Polygon { vertices, .. } => vertices.len() <= MAX_BREAKPOINTS,
        _ => true,
    };
    if normals.len() < 2 || !(small(sa) && small(sb)) {
        return None;
    }
    let mut best: Option<(Start, Real)> = None;
    for n in normals {
        let support = vertices.iter().map(|v| v.dot(*n)).fold(Real::NEG_INFINITY, Real::max) + radius;
        let sep = lowest_piece(turning, &pair.k, *n, support, t).0;
        if !(sep.is_finite() && support.is_finite()) {
            return None;
        }
        if best.is_none_or(|b| sep > b.1) {
            best = Some((Start::Axis { n: *n, support }, sep));
        }
    }
    best
}
