//! A contact manifold from the exact stationary distance (`query::stationary`), for the pairs
//! the exact contact query does not read (a user's curve, a polygon of more than 16 vertices, a
//! curve on a half-space, and every contact on a part with normal constraints): one point where a
//! side is strictly convex, two where a curve rests a flat piece on a half-space. The feature ids
//! are the curve's pieces ([`super::manifold`]'s module docs).

use super::constrained::{along_corrected_normal, Corrected};
use crate::curve::pieces::{flat_pieces, piece_index, piece_is_flat};
use crate::curve::ConvexCurve;
use crate::numerics::math::{Pose, Real, Vector};
use crate::parry_shape::{face_id, vertex_id, FLAT_FEATURE_MAX_ANGLE};
use crate::query::stationary::StationaryDistance;
use parry2d_f64::query::details::{NormalConstraints, NormalConstraintsPair};
use parry2d_f64::query::{ContactManifold, TrackedContact};
use parry2d_f64::shape::{HalfSpace, PackedFeatureId, Shape};

/// The feature id of the point of `c` whose outward normal is `n` (see the module docs).
fn curve_fid(c: &dyn ConvexCurve, n: Vector) -> PackedFeatureId {
    let bp = c.breakpoints();
    if bp.is_empty() || !n.is_finite() {
        return vertex_id(0);
    }
    let (lo, hi) = c.phi_range_of_normal(n);
    let k = piece_index(bp, 0.5 * (lo + hi));
    if piece_is_flat(c, k) {
        face_id(k as u32)
    } else {
        vertex_id(2 * k as u32)
    }
}

/// Two contacts of a curve resting a flat piece on a half-space, in the curve's frame:
/// `(point on the curve, id)` pairs; `None` when no flat piece faces the plane.
fn flat_on_halfspace(c: &dyn ConvexCurve, nc: Vector, support: Vector) -> Option<[(Vector, PackedFeatureId); 2]> {
    let flats = flat_pieces(c);
    let cos_max = FLAT_FEATURE_MAX_ANGLE.cos();
    let mut best = None;
    let mut best_dot = cos_max;
    for f in &flats {
        let d = f.normal.dot(nc);
        if d >= best_dot {
            best_dot = d;
            best = Some(*f);
        }
    }
    let f = best?;
    let nb = c.breakpoints().len().max(1) as u32;
    let k = f.index;
    let id_start = vertex_id(2 * k + 1);
    let id_end = vertex_id(2 * ((k + 1) % nb) + 1);
    // The support point replaces the end it has passed (it lies on a neighbouring piece).
    let t = crate::numerics::math::perp(f.normal);
    let (s0, s1, sp) = (f.start.dot(t), f.end.dot(t), support.dot(t));
    let tol = 1e-12 * c.bounding_radius().abs().max(f64::MIN_POSITIVE);
    let support_id = || curve_fid(c, nc);
    Some(if sp > s1 + tol {
        [(f.start, id_start), (support, support_id())]
    } else if sp < s0 - tol {
        [(support, support_id()), (f.end, id_end)]
    } else {
        [(f.start, id_start), (f.end, id_end)]
    })
}

/// Fills `manifold` from the stationary distance of a pair this crate answers.
#[allow(clippy::too_many_arguments)]
pub(super) fn manifold_from_distance<M, C: Default + Copy>(
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    curves: (Option<&dyn ConvexCurve>, Option<&dyn ConvexCurve>),
    sd: &StationaryDistance,
    normal_constraints1: Option<&dyn NormalConstraints>,
    normal_constraints2: Option<&dyn NormalConstraints>,
    prediction: Real,
    manifold: &mut ContactManifold<M, C>,
) {
    let old_points = manifold.points.clone();
    manifold.clear();

    let (mut n1, mut n2) = (sd.normal1, sd.normal2);
    let constrained = normal_constraints1.is_some() || normal_constraints2.is_some();
    if constrained && !(normal_constraints1, normal_constraints2).project_local_normals(pos12, &mut n1, &mut n2) {
        // The contact is discarded by the normal constraints.
        manifold.local_n1 = Vector::ZERO;
        return;
    }
    manifold.local_n1 = n1;
    manifold.local_n2 = n2;

    // A curve with a flat piece on a half-space: two points.
    let hs1 = g1.as_shape::<HalfSpace>();
    let hs2 = g2.as_shape::<HalfSpace>();
    if hs1.is_some() != hs2.is_some() && !constrained {
        let curve_first = hs2.is_some();
        if let Some(curve) = if curve_first { curves.0 } else { curves.1 } {
            let (nc, support) = if curve_first { (n1, sd.point1) } else { (n2, sd.point2) };
            if let Some(points) = flat_on_halfspace(curve, nc, support) {
                // Pose of the half-space in the curve's frame; the plane's normal is −nc.
                let pos_ch = if curve_first { *pos12 } else { pos12.inverse() };
                let m = -nc;
                let o = pos_ch.translation;
                for (p, id) in points {
                    let dist = m.dot(p - o);
                    if dist > prediction || !dist.is_finite() {
                        continue;
                    }
                    let on_plane = pos_ch.inverse_transform_point(p - m * dist);
                    manifold
                        .points
                        .push(TrackedContact::flipped(p, on_plane, id, face_id(0), dist, !curve_first));
                }
                manifold.match_contacts(&old_points);
                return;
            }
        }
    }

    let (c1, c2) = curves;
    let strict = |c: Option<&dyn ConvexCurve>| c.is_some_and(|c| c.is_strictly_convex());
    // The witness on a flat piece is not unique (any point of the piece maximises the
    // distance): the contact point is the one facing the strictly convex side's witness, which
    // is unique. p2 − p1 = dist · n1 at the solution, so this only moves a flat-piece witness.
    let (mut p1, mut p2) = (sd.point1, sd.point2);
    let mut dist = sd.distance;
    let moved = n1 != sd.normal1;
    match moved
        .then(|| along_corrected_normal(pos12, g1, g2, c1, c2, n1, n2))
        .flatten()
    {
        // The normal constraints moved the normal: the body's support point along the new one
        // and the part's point on its line, or no contact where the line misses the part.
        Some(Corrected::Contact {
            point1,
            point2,
            dist: d,
        }) => (p1, p2, dist) = (point1, point2, d),
        Some(Corrected::Discarded) => {
            manifold.local_n1 = Vector::ZERO;
            return;
        }
        None => {
            if moved {
                // The separation along the new normal.
                dist = (pos12.transform_point(p2) - p1).dot(n1);
            }
            if strict(c2) || g1.as_shape::<HalfSpace>().is_some() {
                p1 = pos12.transform_point(p2) - n1 * dist;
            } else if strict(c1) || g2.as_shape::<HalfSpace>().is_some() {
                p2 = pos12.inverse_transform_point(p1 + n1 * dist);
            }
        }
    }
    if dist <= prediction && dist.is_finite() && p1.is_finite() && p2.is_finite() {
        let fid = |g: &dyn Shape, c: Option<&dyn ConvexCurve>, n: Vector| match c {
            Some(c) => curve_fid(c, n),
            None if g.as_shape::<HalfSpace>().is_some() => face_id(0),
            None => PackedFeatureId::UNKNOWN,
        };
        // A witness moved by the normal constraints is read at the corrected normal.
        let (m1, m2) = if moved { (n1, n2) } else { (sd.normal1, sd.normal2) };
        let fid1 = fid(g1, c1, m1);
        let fid2 = fid(g2, c2, m2);
        manifold.points.push(TrackedContact::new(p1, p2, fid1, fid2, dist));
    }
    manifold.match_contacts(&old_points);
}
