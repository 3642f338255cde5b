//! The polygonal feature map of the curves (module docs of `parry_shape`): a short tangent
//! segment at a smooth support point, a flat piece (or its chord to the support point) within
//! [`FLAT_FEATURE_MAX_ANGLE`] of its normal.

use crate::curve::pieces::FlatPiece;
use crate::curve::ConvexCurve;
use crate::numerics::math::{perp, unit_or_x, Vector};
use parry2d_f64::shape::{PackedFeatureId, PolygonalFeature};

/// Largest angle (radians) between a direction and the normal of a flat piece for which the
/// polygonal feature map returns that flat piece (or the chord from its far end to the support
/// point) instead of a short tangent segment.
pub const FLAT_FEATURE_MAX_ANGLE: f64 = 0.02;

/// The header bits of parry's vertex feature ids (`vertex_id(code)` is
/// `0b01 << 30 | code`).
const VERTEX_HEADER: u32 = 0b01 << 30;

/// The header bits of parry's face feature ids (`face_id(code)` is
/// `0b11 << 30 | code`).
const FACE_HEADER: u32 = 0b11 << 30;

/// The bits a feature code may use (below the two header bits).
const CODE_MASK: u32 = !(0b11 << 30);

/// parry's `vertex_id(code)`, written in place: parry's constructor does not inline
/// across crates (it checks the code with an assertion), and a manifold builds up to four ids.
/// The codes here are piece indices, far below 2³⁰ (checked in debug builds).
#[inline]
pub(crate) fn vertex_id(code: u32) -> PackedFeatureId {
    debug_assert_eq!(code & !CODE_MASK, 0);
    PackedFeatureId(VERTEX_HEADER | (code & CODE_MASK))
}

/// parry's `face_id(code)`, written in place (see [`vertex_id`]).
#[inline]
pub(crate) fn face_id(code: u32) -> PackedFeatureId {
    debug_assert_eq!(code & !CODE_MASK, 0);
    PackedFeatureId(FACE_HEADER | (code & CODE_MASK))
}

/// Half-length of a tangent feature, relative to the bounding radius, at most.
const TANGENT_FEATURE_REL: f64 = 1e-4;
/// Half-length of a tangent feature, relative to the bounding radius, at least.
const TANGENT_FEATURE_MIN_REL: f64 = 1e-9;

/// The support point in the unit direction `n` and the radius of curvature there (∞ on a flat
/// piece or where the normal does not turn).
fn support_and_curvature(c: &dyn ConvexCurve, n: Vector) -> (Vector, f64) {
    if let Some(j) = c.support_jet(n) {
        return (j.point, j.radius_of_curvature);
    }
    let (lo, hi) = c.phi_range_of_normal(n);
    let p = c.support_point(n);
    if hi > lo {
        return (p, f64::INFINITY);
    }
    let cp = c.eval(lo);
    let w = cp.normal_turn_rate();
    let rho = if w > 0.0 { cp.speed() / w } else { f64::INFINITY };
    (p, rho)
}

/// A tangent segment centred on `p` (outward normal `n`), of half-length set by the radius of
/// curvature `rho` and the size `size`.
pub(crate) fn tangent_feature(p: Vector, n: Vector, rho: f64, size: f64, out: &mut PolygonalFeature) {
    let size = if size.is_finite() && size > 0.0 { size } else { 1.0 };
    let mut half = TANGENT_FEATURE_REL * size;
    if rho.is_finite() && rho >= 0.0 {
        half = half.min(0.25 * rho);
    }
    half = half.max(TANGENT_FEATURE_MIN_REL * size);
    let t = perp(n) * half;
    *out = PolygonalFeature {
        vertices: [p - t, p + t],
        vids: [vertex_id(0), vertex_id(1)],
        fid: face_id(0),
        num_vertices: 2,
    };
}

/// The feature for a direction within [`FLAT_FEATURE_MAX_ANGLE`] of the flat piece `f`:
/// the piece itself, or the chord from its far end to the support point `p` once `p` has
/// left it.
fn flat_feature(f: &FlatPiece, p: Vector, size: f64, out: &mut PolygonalFeature) {
    let t = perp(f.normal);
    let (s0, s1, sp) = (f.start.dot(t), f.end.dot(t), p.dot(t));
    let tol = 1e-12 * size.max(f64::MIN_POSITIVE);
    let vertices = if sp > s1 + tol {
        [f.start, p]
    } else if sp < s0 - tol {
        [p, f.end]
    } else {
        [f.start, f.end]
    };
    let k = f.index;
    *out = PolygonalFeature {
        vertices,
        vids: [vertex_id(2 * k + 2), vertex_id(2 * k + 3)],
        fid: face_id(k + 1),
        num_vertices: 2,
    };
}

/// The polygonal feature of a curve with flat pieces `flats` in direction `dir`.
pub(crate) fn curve_feature(c: &dyn ConvexCurve, flats: &[FlatPiece], dir: Vector, out: &mut PolygonalFeature) {
    let n = unit_or_x(dir);
    let size = c.bounding_radius();
    let cos_max = FLAT_FEATURE_MAX_ANGLE.cos();
    let mut best: Option<&FlatPiece> = None;
    let mut best_dot = cos_max;
    for f in flats {
        let d = f.normal.dot(n);
        if d >= best_dot {
            best_dot = d;
            best = Some(f);
        }
    }
    if let Some(f) = best {
        let p = c.support_point(n);
        flat_feature(f, p, size, out);
        return;
    }
    let (p, rho) = support_and_curvature(c, n);
    tangent_feature(p, n, rho, size, out);
}

#[cfg(test)]
mod id_tests {
    use super::*;

    #[test]
    fn the_inlined_feature_ids_are_parrys() {
        for code in (0..4096).chain([(1 << 30) - 1]) {
            assert_eq!(vertex_id(code), PackedFeatureId::vertex(code));
            assert_eq!(face_id(code), PackedFeatureId::face(code));
        }
    }
}
