//! One side of a pair for the gap tracker: a convex polygon dilated by a radius r ≥ 0 (a rounded
//! or sharp polygon, a segment, a capsule, parry's boxes, triangles and polygons), seen through
//! its support function.
//!
//! With core vertices vᵢ (counter-clockwise) and edge normals eᵢ (edge i from vᵢ to vᵢ₊₁), the
//! support function about a point c is h̃(m) = maxᵢ (vᵢ − c)·m + r: vertex i is the support for
//! the unit directions m of its normal cone [eᵢ₋₁, eᵢ], where the boundary is the disc of radius
//! r about vᵢ (radius of curvature r). At an edge normal the support jumps from one end of the
//! edge to the other: h̃ has a kink there (h̃' jumps by the edge length).

use crate::curve::pieces::FlatPiece;
use crate::curve::ConvexCurve;
use crate::numerics::angle::ccw_angle;
use crate::numerics::math::{cross, Vector};
use core::f64::consts::TAU;

/// A convex polygon dilated by `radius`: core vertices counter-clockwise (at least two: a
/// segment's cones are half-planes) and the outward unit normal of each edge, in the body frame.
#[derive(Copy, Clone, Debug)]
pub(crate) struct PolySide<'a> {
    /// Core vertices, counter-clockwise.
    pub verts: &'a [Vector],
    /// Outward unit normal of edge i (from vertex i to vertex i + 1).
    pub normals: &'a [Vector],
    /// The radius the core is dilated by (0 for a sharp polygon).
    pub radius: f64,
    /// The largest distance from the local origin to the boundary
    /// ([`PolySide::radius_about`] the origin), taken once for a polygon of more than
    /// [`REACH_ONCE_ABOVE`] vertices: the walk of every exact distance reads it, and a scan of
    /// the vertices there made each step of a time of impact cost O(n) (issue 32). Smaller
    /// polygons scan (cheaper than taking it for a query that never asks).
    reach: Option<f64>,
}

/// [`PolySide::support_index_far`] climbs from its hint on polygons of at most twice this many
/// vertices (a climb of at most this many moves).
const CLIMB_BEFORE_SEARCH: usize = 8;

/// See [`PolySide::reach`].
const REACH_ONCE_ABOVE: usize = 32;

impl<'a> PolySide<'a> {
    /// The side, or `None` for fewer than two vertices or mismatched normals.
    pub(crate) fn new(verts: &'a [Vector], normals: &'a [Vector], radius: f64) -> Option<Self> {
        (verts.len() >= 2 && normals.len() == verts.len()).then(|| Self {
            verts,
            normals,
            radius,
            reach: (verts.len() > REACH_ONCE_ABOVE).then(|| farthest_vertex(verts, Vector::ZERO) + radius),
        })
    }

    /// Number of vertices.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.verts.len()
    }

    /// The next vertex index (counter-clockwise).
    #[inline]
    pub(crate) fn next(&self, i: usize) -> usize {
        if i + 1 == self.verts.len() {
            0
        } else {
            i + 1
        }
    }

    /// The previous vertex index.
    #[inline]
    pub(crate) fn prev(&self, i: usize) -> usize {
        if i == 0 {
            self.verts.len() - 1
        } else {
            i - 1
        }
    }

    /// The index of the core vertex furthest along the body direction `m`, by hill climbing from
    /// `hint` (the support of a nearby direction: one or two moves). At an edge normal, where two
    /// vertices tie, the one reached first is kept.
    #[inline]
    pub(crate) fn support_index(&self, m: Vector, hint: usize) -> usize {
        let n = self.verts.len();
        let mut i = if hint < n { hint } else { 0 };
        let mut best = self.verts[i].dot(m);
        // Counter-clockwise, then clockwise; at most n moves in all (a convex polygon's v·m is
        // unimodal around the boundary).
        for _ in 0..n {
            let j = self.next(i);
            let d = self.verts[j].dot(m);
            if d > best {
                (i, best) = (j, d);
            } else {
                break;
            }
        }
        for _ in 0..n {
            let j = self.prev(i);
            let d = self.verts[j].dot(m);
            if d > best {
                (i, best) = (j, d);
            } else {
                break;
            }
        }
        i
    }

    /// [`PolySide::support_index`] for a direction `m` that may be far from the one of `hint`:
    /// the hill climb on a polygon of at most 2·[`CLIMB_BEFORE_SEARCH`] vertices or where `hint`
    /// is already the support, else a binary search of the edge normals (counter-clockwise, so
    /// their angles from e₀ increase: vertex i is the support of the directions in [eᵢ₋₁, eᵢ])
    /// finished by a climb from its answer (rounding of the angles). O(log n) for any m.
    pub(crate) fn support_index_far(&self, m: Vector, hint: usize) -> usize {
        let n = self.verts.len();
        let i = if hint < n { hint } else { 0 };
        let near =
            |k: usize| self.verts[k].dot(m) >= self.verts[self.next(k)].dot(m).max(self.verts[self.prev(k)].dot(m));
        if n <= 2 * CLIMB_BEFORE_SEARCH || near(i) {
            return self.support_index(m, i);
        }
        let e0 = self.normals[0];
        let target = ccw_angle(e0, m);
        // The first k ≥ 1 with angle(e₀, e_k) ≥ target; n when none (vertex 0's cone).
        let (mut lo, mut hi) = (1, n);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if ccw_angle(e0, self.normals[mid]) >= target {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        self.support_index(m, if lo == n { 0 } else { lo })
    }

    /// The largest distance from `c` to the boundary (the core's furthest vertex plus the radius).
    pub(crate) fn radius_about(&self, c: Vector) -> f64 {
        match self.reach {
            Some(r) if c == Vector::ZERO => r,
            _ => farthest_vertex(self.verts, c) + self.radius,
        }
    }

    /// The support point of the dilated polygon for the unit body direction `m` whose core
    /// support is vertex `i`.
    #[inline]
    pub(crate) fn point(&self, i: usize, m: Vector) -> Vector {
        self.verts[i] + m * self.radius
    }
}

/// The largest distance from `c` to a vertex of `verts`.
fn farthest_vertex(verts: &[Vector], c: Vector) -> f64 {
    verts.iter().fold(0.0f64, |r, v| r.max((*v - c).length()))
}

/// A convex curve with its flat pieces (faces): the capsule-ellipse, a user's curve, any curve
/// with no strictly convex representation. Between consecutive faces its support point moves
/// continuously with the direction (an arc of the boundary, corners included: there the point
/// stays while the normal turns); across a face's normal it jumps from one end of the face to
/// the other.
#[derive(Copy, Clone, Debug)]
pub(crate) struct CurveSide<'a> {
    /// The curve.
    pub curve: &'a dyn ConvexCurve,
    /// Its flat pieces, in counter-clockwise order of their normals.
    pub faces: &'a [FlatPiece],
}

/// One side of a pair: a dilated polygon, or a curve with faces.
///
/// The side's *features* split the circle of directions at its kinks (the faces' normals): a
/// polygon's vertices (feature i owns the cone [eᵢ₋₁, eᵢ]), a curve's arcs between consecutive
/// faces (arc f from face f's normal to face f + 1's; one arc over the whole circle when there
/// is no face).
#[derive(Copy, Clone, Debug)]
pub(crate) enum Side<'a> {
    Poly(PolySide<'a>),
    Curve(CurveSide<'a>),
}

/// Two unit directions less than this apart (radians) are the same direction (a face normal).
const SAME_DIRECTION: f64 = 1e-15;

/// Whether the unit directions `a` and `b` are the same to [`SAME_DIRECTION`].
#[inline]
fn same_direction(a: Vector, b: Vector) -> bool {
    a.dot(b) > 0.0 && cross(a, b).abs() <= SAME_DIRECTION
}

impl<'a> Side<'a> {
    /// The number of features.
    #[inline]
    pub(crate) fn features(&self) -> usize {
        match self {
            Side::Poly(p) => p.len(),
            Side::Curve(c) => c.faces.len().max(1),
        }
    }

    /// The next feature counter-clockwise.
    #[inline]
    pub(crate) fn next(&self, f: usize) -> usize {
        if f + 1 >= self.features() {
            0
        } else {
            f + 1
        }
    }

    /// The previous feature.
    #[inline]
    pub(crate) fn prev(&self, f: usize) -> usize {
        if f == 0 {
            self.features() - 1
        } else {
            f - 1
        }
    }

    /// The normal cone of feature `f` in the body frame: its boundaries (counter-clockwise) and
    /// its width; `None` for a curve with no face (the whole circle).
    #[inline]
    pub(crate) fn cone(&self, f: usize) -> Option<(Vector, Vector, f64)> {
        match self {
            Side::Poly(p) => {
                let (lo, hi) = (p.normals[p.prev(f)], p.normals[f]);
                Some((lo, hi, ccw_angle(lo, hi)))
            }
            Side::Curve(c) => match c.faces.len() {
                0 => None,
                1 => Some((c.faces[0].normal, c.faces[0].normal, TAU)),
                _ => {
                    let (lo, hi) = (c.faces[f].normal, c.faces[self.next(f)].normal);
                    Some((lo, hi, ccw_angle(lo, hi)))
                }
            },
        }
    }

    /// The feature whose cone holds the body direction `m` (from `hint`).
    pub(crate) fn feature_of(&self, m: Vector, hint: usize) -> usize {
        match self {
            Side::Poly(p) => p.support_index(m, hint),
            Side::Curve(c) => {
                let n = c.faces.len();
                if n <= 1 {
                    return 0;
                }
                let start = if hint < n { hint } else { 0 };
                for k in 0..n {
                    let f = (start + k) % n;
                    let (lo, _, width) = self.cone(f).expect("faces");
                    if ccw_angle(lo, m) <= width {
                        return f;
                    }
                }
                start
            }
        }
    }

    /// [`Side::feature_of`] for a direction that may be far from the one of `hint`: O(log n) on
    /// a polygon ([`PolySide::support_index_far`]).
    pub(crate) fn feature_far(&self, m: Vector, hint: usize) -> usize {
        match self {
            Side::Poly(p) => p.support_index_far(m, hint),
            Side::Curve(_) => self.feature_of(m, hint),
        }
    }

    /// The support point (body frame) of feature `f` for the unit body direction `m` inside its
    /// cone, with the radius of curvature there. (At a cone boundary, a face normal, a curve gives
    /// a point of the face: the one-sided supports are the face's ends, `face_after`.)
    pub(crate) fn support(&self, f: usize, m: Vector) -> (Vector, f64) {
        match self {
            Side::Poly(p) => (p.point(f, m), p.radius),
            Side::Curve(c) => {
                let (lo, hi) = c.curve.phi_range_of_normal(m);
                let cp = c.curve.eval(0.5 * (lo + hi));
                let w = cp.normal_turn_rate();
                let rho = if w > 0.0 { (cp.speed() / w).max(0.0) } else { 0.0 };
                (cp.point, rho)
            }
        }
    }

    /// The support point of feature `f` for the body direction `m` as the limit from beyond `m`
    /// in the direction of a turn (`upward`: counter-clockwise): at a kink, the far end of the
    /// face. (The guard's bound needs the support point furthest along the turn.)
    pub(crate) fn support_beyond(&self, f: usize, m: Vector, upward: bool) -> Vector {
        match self {
            Side::Poly(p) => {
                let g = if upward { p.next(f) } else { p.prev(f) };
                if p.verts[g].dot(m) >= p.verts[f].dot(m) {
                    p.point(g, m)
                } else {
                    p.point(f, m)
                }
            }
            Side::Curve(c) => {
                if let Some((lo, hi, _)) = self.cone(f) {
                    if upward && same_direction(hi, m) {
                        return self.face_after(f).1;
                    }
                    if !upward && same_direction(lo, m) {
                        return self.face_after(self.prev(f)).0;
                    }
                }
                let _ = c;
                self.support(f, m).0
            }
        }
    }

    /// Whether the body direction `m` turned by any angle between 0 and `sweep` stays in the cone
    /// of feature `f` (closed: a boundary still has `f`'s support).
    pub(crate) fn keeps(&self, f: usize, m: Vector, sweep: f64) -> bool {
        match self.cone(f) {
            None => true,
            Some((lo, _, width)) => {
                let mut off = ccw_angle(lo, m);
                if off > width {
                    // A rounding error outside the cone: at its nearer boundary.
                    off = if off > 0.5 * (width + TAU) { 0.0 } else { width };
                }
                let end = off + sweep;
                (0.0..=width).contains(&end)
            }
        }
    }

    /// How far (radians) the body direction `m` can turn in the direction of `sign` and stay in
    /// the cone of feature `f`: ∞ for a whole-circle cone.
    pub(crate) fn room(&self, f: usize, m: Vector, sign: f64) -> f64 {
        match self.cone(f) {
            None => f64::INFINITY,
            Some((lo, _, width)) => {
                let mut off = ccw_angle(lo, m);
                if off > width {
                    off = if off > 0.5 * (width + TAU) { 0.0 } else { width };
                }
                if sign > 0.0 {
                    width - off
                } else {
                    off
                }
            }
        }
    }

    /// The disc feature `f`'s support lies on (centre, radius), when it is one (a polygon's
    /// vertex): its gap to another disc is closed-form.
    #[inline]
    pub(crate) fn disc(&self, f: usize) -> Option<(Vector, f64)> {
        match self {
            Side::Poly(p) => Some((p.verts[f], p.radius)),
            Side::Curve(_) => None,
        }
    }

    /// The face at the upper boundary of feature `f`'s cone: (start, end, outward normal), body
    /// frame.
    pub(crate) fn face_after(&self, f: usize) -> (Vector, Vector, Vector) {
        match self {
            Side::Poly(p) => {
                let e = p.normals[f];
                (p.verts[f] + e * p.radius, p.verts[p.next(f)] + e * p.radius, e)
            }
            Side::Curve(c) => {
                let face = &c.faces[self.next(f) % c.faces.len().max(1)];
                (face.start, face.end, face.normal)
            }
        }
    }

    /// An upper bound on the distance from `c` to the boundary.
    pub(crate) fn radius_about(&self, c: Vector) -> f64 {
        match self {
            Side::Poly(p) => p.radius_about(c),
            Side::Curve(s) => s.curve.bounding_radius() + c.length(),
        }
    }

    /// A lower bound on the radius of curvature over the boundary (the radius of a polygon).
    pub(crate) fn min_radius(&self) -> f64 {
        match self {
            Side::Poly(p) => p.radius,
            Side::Curve(c) => c.curve.min_radius_of_curvature().max(0.0),
        }
    }
}
