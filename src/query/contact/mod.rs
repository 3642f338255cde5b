//! The exact contact of two shapes made of polygon corners, flat edges and at most one ellipse
//! per pair: polygons (sharp or rounded, parry's boxes, segments, capsules, triangles), discs,
//! ellipses and `CapsuleEllipse`s against any of the polygonal ones — the signed distance, its
//! normal and witness points, and the manifold's one or two points, at the cost of a walk over
//! the two shapes' breakpoints.
//!
//! # The function minimised
//!
//! For convex bodies A₁, A₂ with support functions h₁, h₂ (in body 1's frame), the separation
//! along a unit direction n (from body 1 towards body 2) is
//!
//!   sep(n) = min over A₂ of n·x − max over A₁ of n·x = −(h₁(n) + h₂(−n)) = −F(n),
//!
//! and the signed distance is the largest separation, d = −min over n of F(n), positive when
//! apart (the distance), negative when overlapping (minus the penetration depth): F is the
//! support function of the Minkowski difference A₁ − A₂, and −min F is the signed distance of
//! the origin to it. The minimising n is the contact normal, and the support points of the two
//! bodies there are the witnesses.
//!
//! # Why the walk is exact
//!
//! Each body's support function is a sequence of pieces between breakpoints of the direction
//! ([`side`]): a vertex with a radius (v·n + r) or an ellipse (c·n + k(n)). Merging the two
//! sides' breakpoints counter-clockwise ([`walk`]) splits the circle into arcs on which F is a
//! sum of one piece of each side. Its minimum is either at a breakpoint (F is evaluated at every
//! one: for a polygon these are the separating-axis tests of its edges) or at a stationary point
//! inside an arc:
//!
//! * two vertices: F = q·n + r with q = v₁ − v₂, stationary only at n = −q/|q|, value r − |q|
//!   (two corners facing each other);
//! * a vertex and an ellipse: F − r is the support function of the ellipse moved to q, whose
//!   stationary directions are the normals at the *feet* of the normals from −q to the ellipse
//!   ([`feet`]). The nearest foot is the minimum over every direction, so when its normal lies in
//!   the arc it is the arc's minimum; otherwise the arc's minimum is at an end (a breakpoint,
//!   already evaluated) or at the *middle* foot that is a minimum (a point inside the evolute
//!   has two more feet, a minimum and a maximum: the stationary points alternate around the
//!   circle), found exactly (closed form of where the multiplier's function dips, monotone
//!   Newton). The farthest foot is never a minimum;
//! * two ellipses (`two_ellipses`): a descent, certificates, and a branch and bound with a
//!   second-order bound; `None` (the caller's other query) if its budget runs out.
//!
//! Every candidate is a value of F at an actual direction, so the smallest is the global
//! minimum — no tolerance, no iteration cap that could cut the search short, and no difference
//! between a shallow and a deep contact (deeper than the ellipse's radius of curvature, F has
//! several local minima on an arc: the middle feet are exactly those). An arc is skipped when an
//! exact lower bound of F on it (the minimum of the linear part plus the minimum of k, each over
//! the arc, both in closed form) exceeds the best value so far; skipping never changes the
//! answer. The merge needs each polygon's edge normals to turn strictly (a vertex on a straight
//! edge, which parry's unmodified polylines keep, makes [`contact`] answer `None`).
//!
//! # Two polygons
//!
//! A pair of polygons (dilated or not: this crate's rounded polygons, parry's boxes, triangles,
//! convex polygons, segments and capsules), or a polygon and a disc, has vertex pieces only: its
//! walk is the separating-axis tests of both polygons' edges and, on an arc, at most one
//! corner–corner candidate. [`contact`] answers it by a lean copy of this walk
//! (`polygons`, the same float operations in the same order: the same answer to the bit, at
//! a fraction of the cost); every other pair takes the general walk.
//!
//! # The manifold's points
//!
//! When the minimum is at a breakpoint that is a face of one body (an edge, dilated) and the
//! other body has a face within the flat-feature angle of it, the manifold has two points: the
//! incident face clipped to the slab of the reference face, each point with its own distance
//! along the normal; the witness vertex is one of them, so the deepest distance is the signed
//! distance. Otherwise it has one point, the witnesses (a witness on a face is the point of the
//! face facing the other witness). Features: a face is `Face(edge index)` (a `CapsuleEllipse`'s
//! segment is face 0), a vertex piece `Vertex(vertex index)` (a `CapsuleEllipse`'s arcs 0 and 1,
//! its half-ellipse 2), an ellipse `Vertex(0)`.

mod arc;
pub(crate) mod feet;
pub(crate) mod minkowski;
mod polygons;
pub(crate) mod separation;
mod side;
mod two_ellipses;
mod walk;

pub(crate) use side::{SupportShape, MAX_BREAKPOINTS};

use crate::numerics::math::{perp, Pose, Vector};
use side::Placed;
use walk::{At, Minimum, Walk};

/// How much shallower (relative to the faces' lengths plus radii) the deepest of two clipped
/// points may be than the signed distance: rounding only. Deeper than that, the witness was
/// clipped away and the manifold keeps the one exact point.
const TWO_POINT_DEPTH: f64 = 1e-12;

/// Two ends of facing faces closer than this fraction of the faces' lengths (along them) are
/// one end of their overlap for the feature ids (see `facing_faces`).
const SAME_END: f64 = 1e-6;

/// A feature of a body holding a contact point.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum Feature {
    /// A face (edge or segment).
    Face(u32),
    /// A vertex piece (corner, arc) or an ellipse.
    Vertex(u32),
}

/// One contact point: the points of both bodies in body 1's frame, their features and the
/// distance between them along the normal.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct ContactPoint {
    pub point1: Vector,
    pub point2: Vector,
    pub feature1: Feature,
    pub feature2: Feature,
    pub dist: f64,
}

/// The exact contact of two shapes.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct Contact {
    /// Signed distance (negative: penetration depth).
    pub dist: f64,
    /// Unit normal in body 1's frame, from body 1 towards body 2.
    pub normal: Vector,
    /// The manifold's points; the first `len` are set, the first is the deepest.
    pub points: [ContactPoint; 2],
    pub len: usize,
}

/// The exact contact of `shape1` (at the origin) and `shape2` (at `pos12` in body 1's frame);
/// `flat_cos` is the cosine of the largest angle between two faces that gives two points;
/// `hint`, a direction near the normal (the previous manifold's), where the search of an arc
/// between two ellipse pieces starts (the answer does not depend on it).
/// `None` when a side has too many breakpoints, both have an ellipse piece, or a value is not
/// finite.
pub(crate) fn contact(
    shape1: SupportShape,
    shape2: SupportShape,
    pos12: &Pose,
    flat_cos: f64,
    hint: Option<Vector>,
) -> Option<Contact> {
    if let Some(answer) = polygons::contact(shape1, shape2, pos12, flat_cos) {
        return answer;
    }
    walk_contact(shape1, shape2, pos12, flat_cos, hint)
}

/// [`contact`] by the general walk (every pair of shapes, the polygons' too).
fn walk_contact(
    shape1: SupportShape,
    shape2: SupportShape,
    pos12: &Pose,
    flat_cos: f64,
    hint: Option<Vector>,
) -> Option<Contact> {
    // Built in place: a side is most of a kilobyte, a move is a copy.
    let (mut s0, mut s1) = (Placed::blank(1.0), Placed::blank(-1.0));
    if !(s0.place(shape1, &Pose::IDENTITY) && s1.place(shape2, pos12)) {
        return None;
    }
    let mut walk = Walk::blank(&s0, &s1);
    walk.merge();
    walk.hint = hint.filter(|h| h.is_finite() && (h.length() - 1.0).abs() < 1e-6);
    let m = walk.minimum()?;
    let one = witness_point(&walk, &m);
    let mut c = Contact {
        dist: -m.value,
        normal: m.normal,
        points: [one; 2],
        len: 1,
    };
    if let At::Breakpoint(i) = m.at {
        if let Some(two) = facing_faces(&walk, i, &m, flat_cos) {
            c.points = two;
            c.len = 2;
        }
    }
    let ok = c.points[..c.len]
        .iter()
        .all(|p| p.point1.is_finite() && p.point2.is_finite() && p.dist.is_finite());
    (ok && c.normal.is_finite()).then_some(c)
}

/// The one contact point of the minimum.
fn witness_point(walk: &Walk, m: &Minimum) -> ContactPoint {
    let n = m.normal;
    let dist = -m.value;
    let [s0, s1] = walk.sides;
    let mut p1 = s0.support(m.active[0], n);
    let mut p2 = s1.support(m.active[1], n);
    let mut f = [Feature::Vertex(s0.id(m.active[0])), Feature::Vertex(s1.id(m.active[1]))];
    if let At::Breakpoint(i) = m.at {
        let e = &walk.entries[i];
        if let Some(face) = walk.sides[e.side()].face(e.index()) {
            f[e.side()] = Feature::Face(face);
            // The point of the face facing the other witness.
            if e.side() == 0 {
                p1 = p2 - n * dist;
            } else {
                p2 = p1 + n * dist;
            }
        }
    }
    ContactPoint {
        point1: p1,
        point2: p2,
        feature1: f[0],
        feature2: f[1],
        dist,
    }
}

/// The two points of a face facing a face (see the module docs), when the minimum is at face
/// breakpoint i and the other side has a face within the angle whose cosine is `flat_cos`.
fn facing_faces(walk: &Walk, i: usize, m: &Minimum, flat_cos: f64) -> Option<[ContactPoint; 2]> {
    let e = &walk.entries[i];
    let (rs, os) = (e.side(), 1 - e.side());
    let reference = walk.sides[rs];
    let other = walk.sides[os];
    let ref_face = reference.face(e.index())?;
    // The other side's face breakpoint nearest in angle (the walk is sorted: look both ways).
    let mut best: Option<(f64, usize)> = None;
    for step in [1, walk.len - 1] {
        let mut j = i;
        for _ in 1..walk.len {
            j = walk::wrap(j + step, walk.len);
            let c = walk.normal(j).dot(m.normal);
            if c < flat_cos {
                break;
            }
            let ej = &walk.entries[j];
            if ej.side() == os && other.face(ej.index()).is_some() {
                if best.is_none_or(|b| c > b.0) {
                    best = Some((c, ej.index()));
                }
                break;
            }
        }
    }
    let (_, k) = best?;
    let (a0, r_ref) = reference.vertex(reference.before(e.index()))?;
    let (a1, _) = reference.vertex(e.index())?;
    let (b0, r_inc) = other.vertex(other.before(k))?;
    let (b1, _) = other.vertex(k)?;
    let faces = FacingFaces {
        rs,
        a: [a0, a1],
        r_ref,
        ref_face,
        ref_ids: [reference.id(reference.before(e.index())), reference.id(e.index())],
        b: [b0, b1],
        r_inc,
        other_face: other.face(k)?,
        inc_ids: [other.id(other.before(k)), other.id(k)],
    };
    clip_faces(&faces, m)
}

/// Two faces facing each other within the flat-feature angle: the reference face a₀a₁ (radius
/// `r_ref`, face `ref_face`, its vertices' ids) of side `rs`, at the minimum's breakpoint, and
/// the incident face b₀b₁ (radius `r_inc`) of the other side, in body 1's frame.
pub(super) struct FacingFaces {
    pub rs: usize,
    pub a: [Vector; 2],
    pub r_ref: f64,
    pub ref_face: u32,
    pub ref_ids: [u32; 2],
    pub b: [Vector; 2],
    pub r_inc: f64,
    pub other_face: u32,
    pub inc_ids: [u32; 2],
}

/// The manifold's two points of facing faces (see the module docs): the incident face clipped
/// to the slab of the reference face, each point with its distance along the normal; `None`
/// when the clip leaves one point or drops the minimum's witness.
pub(super) fn clip_faces(f: &FacingFaces, m: &Minimum) -> Option<[ContactPoint; 2]> {
    let (rs, os) = (f.rs, 1 - f.rs);
    let ([a0, a1], [b0, b1]) = (f.a, f.b);
    let (r_ref, r_inc, ref_face, other_face) = (f.r_ref, f.r_inc, f.ref_face, f.other_face);
    let (ref_ids, inc_ids) = (f.ref_ids, f.inc_ids);
    // The reference face's outward normal; the slab of the face along its tangent.
    let n_ref = if rs == 0 { m.normal } else { -m.normal };
    let t = perp(n_ref);
    let (ta0, ta1) = (a0.dot(t), a1.dot(t));
    let (lo, hi) = (ta0.min(ta1), ta0.max(ta1));
    let (tb0, tb1) = (b0.dot(t), b1.dot(t));
    if tb0 == tb1 {
        return None;
    }
    // Each end of the overlap of the two faces along the tangent comes from one vertex, of
    // either face: the point's features are that vertex and the other body's face, whichever
    // body is the reference (so a reference that flips between two parallel faces keeps the
    // ids, and rapier's warm start).
    // An incident end within this distance (along the face) of a reference end is the same end
    // of the overlap, which is then attributed to body 2's vertex whichever body is the
    // reference (two faces of equal extent, a box on a box, keep their ids when the reference
    // flips from one to the other).
    let tie = SAME_END * ((a1 - a0).length() + (b1 - b0).length());
    let end = |b: Vector, tb: f64, id: u32| -> Option<(Vector, Feature, Feature)> {
        let inside = tb >= lo && tb <= hi;
        let tc = tb.clamp(lo, hi);
        let near = if (tb - ta0).abs() <= (tb - ta1).abs() { 0 } else { 1 };
        let tied = (tb - [ta0, ta1][near]).abs() <= tie;
        let point = if inside {
            b
        } else {
            let lambda = (tc - tb0) / (tb1 - tb0);
            if !(0.0..=1.0).contains(&lambda) {
                return None;
            }
            b0 + (b1 - b0) * lambda
        };
        let incident_owns = if tied { os == 1 } else { inside };
        Some(if incident_owns {
            (point, Feature::Vertex(id), Feature::Face(ref_face))
        } else {
            let ref_id = if tied {
                ref_ids[near]
            } else if tc == ta0 {
                ref_ids[0]
            } else {
                ref_ids[1]
            };
            (point, Feature::Face(other_face), Feature::Vertex(ref_id))
        })
    };
    let q0 = end(b0, tb0, inc_ids[0])?;
    let q1 = end(b1, tb1, inc_ids[1])?;
    if q0.0 == q1.0 {
        return None;
    }
    let point = |(q, f_inc, f_ref): (Vector, Feature, Feature)| {
        let h = (q - a0).dot(n_ref);
        let p_ref = q - n_ref * h + n_ref * r_ref;
        let p_inc = q - n_ref * r_inc;
        let dist = h - r_ref - r_inc;
        if rs == 0 {
            ContactPoint {
                point1: p_ref,
                point2: p_inc,
                feature1: f_ref,
                feature2: f_inc,
                dist,
            }
        } else {
            ContactPoint {
                point1: p_inc,
                point2: p_ref,
                feature1: f_inc,
                feature2: f_ref,
                dist,
            }
        }
    };
    let (p0, p1) = (point(q0), point(q1));
    // The deepest point must be the contact (its distance the signed distance, to rounding):
    // not so when the incident face's deepest end was clipped away (a corner past the end of
    // the reference face); then the one point of the minimum is the manifold.
    let deepest = p0.dist.min(p1.dist);
    let scale = (a1 - a0).length() + (b1 - b0).length() + r_ref + r_inc;
    let exact = deepest + m.value <= TWO_POINT_DEPTH * scale;
    if !exact {
        return None;
    }
    Some(if p0.dist <= p1.dist { [p0, p1] } else { [p1, p0] })
}

#[cfg(test)]
mod tests;
