//! The exact contact of two polygons dilated by radii — this crate's `RoundedPolygon`, parry's
//! boxes, convex polygons, triangles, segments, capsules (a segment and a radius) and discs (a
//! point and a radius), one of the two at least a polygon — by the walk of the folder's module
//! docs cut down to what such a pair needs: the same answer, bit for bit, at a fraction of the
//! cost.
//!
//! # The walk of two polygons
//!
//! With vertex pieces only, F(n) = h₁(n) + h₂(−n) is, on the arc between two consecutive merged
//! breakpoints, q·n + r with q = v₁ − v₂ (the active vertices, body 2's negated) and
//! r = r₁ + r₂ the same on every arc. So F at the merged breakpoints (the separating-axis tests
//! of both polygons' edges, each the edge's vertex against the other polygon's support vertex,
//! which the merge keeps in step) plus, on an arc whose range holds −q/|q|, the corner–corner
//! candidate r − |q| there, hold the minimum; nothing else is evaluated:
//!
//! * the cores overlapping along every breakpoint (F ≥ r there, a side with three edges or more)
//!   is a penetration: the least breakpoint value is the minimum (an interior candidate would
//!   separate the cores);
//! * apart (F < r at a breakpoint), the separation is concave where positive: only the arcs
//!   next to the breakpoints tied with the best (to [`TIE`] of the largest |F|) are looked at.
//!
//! The general walk ([`super::walk`]) does exactly this for such a pair, but through sides and
//! a walk sized and written for every shape: sixteen pieces with a radius each, an optional
//! ellipse, its screens and searches on every evaluation. Here a side is a polygon (or a disc:
//! no breakpoint, one vertex) with one radius, and each step is the general walk's own float
//! operation in the same order: the same merge (the same start, halves and order of equal
//! directions), the same values, the same first-lowest minimum, the same witnesses and
//! clipped faces (the general code's [`clip_faces`]). The unit tests pin that equality bit for
//! bit on random pairs, ties included (faces parallel, corners facing, touching).

use super::arc::in_arc;
use super::side::{polygon_is_walkable, SupportShape, MAX_BREAKPOINTS};
use super::walk::{first_breakpoints, for_each_merged, wrap, At, Entry, Minimum, TIE};
use super::{clip_faces, Contact, ContactPoint, FacingFaces, Feature};
use crate::numerics::math::{cross, Pose, Vector};

/// A polygon placed in body 1's frame with its side's sign σ (see [`super::side`]): breakpoint
/// k (the placed edge normal k, σ-signed) is face k, piece k is vertex k + 1 (σ-signed), every
/// piece of radius `r`. A disc has no breakpoint and its one piece, its centre.
struct Poly {
    /// Number of breakpoints (0: a disc).
    len: usize,
    normals: [Vector; MAX_BREAKPOINTS],
    q: [Vector; MAX_BREAKPOINTS],
    r: f64,
    sign: f64,
}

impl Poly {
    /// A side of sign σ with no piece yet (see [`Poly::place`]).
    #[inline(always)]
    fn blank(sign: f64) -> Self {
        Poly {
            len: 0,
            normals: [Vector::X; MAX_BREAKPOINTS],
            q: [Vector::ZERO; MAX_BREAKPOINTS],
            r: 0.0,
            sign,
        }
    }

    /// Places `shape` (a polygon or a disc) at `pose`, in place (a side is half a kilobyte: a
    /// move is a copy); false for a polygon the general walk refuses (too many vertices, normals
    /// that do not turn strictly), which the query then answers `None` as the walk does.
    #[inline(always)]
    fn place(&mut self, shape: SupportShape, pose: &Pose) -> bool {
        let sign = self.sign;
        match shape {
            SupportShape::Polygon {
                vertices,
                normals,
                radius,
            } => {
                if !polygon_is_walkable(vertices, normals) {
                    return false;
                }
                let n = vertices.len();
                self.len = n;
                self.r = radius;
                for (k, normal) in normals.iter().enumerate() {
                    let next = if k + 1 == n { 0 } else { k + 1 };
                    self.normals[k] = pose.transform_vector(*normal) * sign;
                    self.q[k] = pose.transform_point(vertices[next]) * sign;
                }
                true
            }
            SupportShape::Disc(r) => {
                self.q[0] = pose.transform_point(Vector::ZERO) * sign;
                self.r = r;
                true
            }
            _ => false,
        }
    }

    /// The index of the piece before breakpoint k.
    #[inline]
    fn before(&self, k: usize) -> usize {
        if k == 0 {
            self.len.max(1) - 1
        } else {
            k - 1
        }
    }

    /// The face id of breakpoint k (every breakpoint of a polygon is a face; a disc has none).
    #[inline]
    fn face(&self, k: usize) -> Option<u32> {
        (self.len > 0).then_some(k as u32)
    }

    /// The id of piece k: its vertex's index (0 for a disc).
    #[inline]
    fn id(&self, k: usize) -> u32 {
        if self.len == 0 {
            k as u32
        } else {
            (if k + 1 == self.len { 0 } else { k + 1 }) as u32
        }
    }

    /// The contribution of piece k to F at n: q·n + r.
    #[inline]
    fn value(&self, k: usize, n: Vector) -> f64 {
        self.q[k].dot(n) + self.r
    }

    /// The support point of this side for the query's direction n on piece k, in body 1's
    /// frame: σ(q + σ r n).
    #[inline]
    fn support(&self, k: usize, n: Vector) -> Vector {
        let s = self.sign;
        self.q[k] * s + n * (s * self.r)
    }

    /// The vertex of piece k in body 1's frame.
    #[inline]
    fn vertex(&self, k: usize) -> Vector {
        self.q[k] * self.sign
    }
}

/// The merged breakpoints of two placed polygons (at least one with breakpoints).
struct Merged<'a> {
    sides: [&'a Poly; 2],
    entries: [Entry; 2 * MAX_BREAKPOINTS],
    len: usize,
}

impl<'a> Merged<'a> {
    /// The two sides with no breakpoint merged yet (see [`Merged::merge`]).
    #[inline(always)]
    fn blank(s0: &'a Poly, s1: &'a Poly) -> Self {
        let blank = Entry {
            value: 0.0,
            side: 0,
            index: 0,
            active: [0, 0],
        };
        Merged {
            sides: [s0, s1],
            entries: [blank; 2 * MAX_BREAKPOINTS],
            len: 0,
        }
    }

    /// Merges the breakpoints of both sides counter-clockwise from side 0's first (side 1's if
    /// side 0 is a disc), F evaluated at each, in place; of two equal directions side 0's comes
    /// first.
    #[inline(always)]
    fn merge(&mut self) {
        let w = self;
        let sides = w.sides;
        let [s0, s1] = sides;
        let start = if s0.len > 0 { s0.normals[0] } else { s1.normals[0] };
        let (normals, lens) = ([&s0.normals, &s1.normals], [s0.len, s1.len]);
        let (first, halves) = first_breakpoints(start, normals, lens);
        let mut active = [s0.before(first[0]) as u8, s1.before(first[1]) as u8];
        for_each_merged(first, &halves, normals, lens, |side, k| {
            active[side] = k as u8;
            let value = w.value([active[0] as usize, active[1] as usize], sides[side].normals[k]);
            w.entries[w.len] = Entry {
                value,
                side: side as u8,
                index: k as u8,
                active,
            };
            w.len += 1;
        });
    }

    /// F at n on the pieces `p`.
    #[inline]
    fn value(&self, p: [usize; 2], n: Vector) -> f64 {
        self.sides[0].value(p[0], n) + self.sides[1].value(p[1], n)
    }

    /// The direction of merged breakpoint i.
    #[inline]
    fn normal(&self, i: usize) -> Vector {
        let e = &self.entries[i];
        self.sides[e.side()].normals[e.index()]
    }

    /// The pieces active after merged breakpoint i.
    #[inline]
    fn active(&self, i: usize) -> [usize; 2] {
        let a = self.entries[i].active;
        [a[0] as usize, a[1] as usize]
    }

    /// The minimum of F (module docs): the first lowest breakpoint, then the corner–corner
    /// candidates of the arcs that may hold a lower value. `None` when a breakpoint's value is
    /// not finite.
    fn minimum(&self) -> Option<Minimum> {
        // The first lowest breakpoint (as the walk keeps a strictly lower value only).
        let (mut first, mut lowest, mut scale) = (0, f64::INFINITY, 0.0f64);
        for (i, e) in self.entries[..self.len].iter().enumerate() {
            if !e.value.is_finite() {
                return None;
            }
            scale = scale.max(e.value.abs());
            if i == 0 || e.value < lowest {
                (first, lowest) = (i, e.value);
            }
        }
        let mut best = Minimum {
            value: lowest,
            normal: self.normal(first),
            at: At::Breakpoint(first),
            active: self.active(first),
        };
        // The cores overlap along every breakpoint (F ≥ r₁ + r₂), every arc narrower than π.
        let [s0, s1] = self.sides;
        let polygons = s0.len.max(s1.len) >= 3;
        let r_core = if polygons { s0.r + s1.r } else { 0.0 };
        if polygons && lowest >= r_core {
            return Some(best);
        }
        let cut = lowest + TIE * scale;
        let separated = lowest < r_core;
        for i in 0..self.len {
            let next = wrap(i + 1, self.len);
            if separated && !(self.entries[i].value <= cut || self.entries[next].value <= cut) {
                continue;
            }
            let (a, b) = (self.normal(i), self.normal(next));
            if self.len > 1 && cross(a, b) == 0.0 && a.dot(b) > 0.0 {
                // Two breakpoints in the same direction: an empty arc.
                continue;
            }
            // F = q·n + r on the arc: its minimum r − |q| is at n = −q/|q| when that is in it.
            let p = self.active(i);
            let q = s0.q[p[0]] + s1.q[p[1]];
            let ql = q.length();
            if ql > 0.0 && in_arc(a, b, -q) {
                let n = -q / ql;
                let value = self.value(p, n);
                // Kept when lower (a value that is not finite is not).
                if value.is_finite() && value < best.value {
                    best = Minimum {
                        value,
                        normal: n,
                        at: At::Inside(i),
                        active: p,
                    };
                }
            }
        }
        Some(best)
    }

    /// The one contact point of the minimum: the support points of the active pieces, the one
    /// on a face at the minimum's breakpoint replaced by the face's point facing the other.
    fn witness_point(&self, m: &Minimum) -> ContactPoint {
        let n = m.normal;
        let dist = -m.value;
        let [s0, s1] = self.sides;
        let mut p1 = s0.support(m.active[0], n);
        let mut p2 = s1.support(m.active[1], n);
        let mut f = [Feature::Vertex(s0.id(m.active[0])), Feature::Vertex(s1.id(m.active[1]))];
        if let At::Breakpoint(i) = m.at {
            let e = &self.entries[i];
            if let Some(face) = self.sides[e.side()].face(e.index()) {
                f[e.side()] = Feature::Face(face);
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

    /// The two points of a face facing a face, when the minimum is at face breakpoint i and
    /// the other side has a face within the angle whose cosine is `flat_cos` (the nearest in
    /// angle, looking both ways along the merged order).
    fn facing_faces(&self, i: usize, m: &Minimum, flat_cos: f64) -> Option<[ContactPoint; 2]> {
        let e = &self.entries[i];
        let (rs, os) = (e.side(), 1 - e.side());
        let (reference, other) = (self.sides[rs], self.sides[os]);
        let ref_face = reference.face(e.index())?;
        let mut best: Option<(f64, usize)> = None;
        for step in [1, self.len - 1] {
            let mut j = i;
            for _ in 1..self.len {
                j = wrap(j + step, self.len);
                let c = self.normal(j).dot(m.normal);
                if c < flat_cos {
                    break;
                }
                let ej = &self.entries[j];
                if ej.side() == os && other.face(ej.index()).is_some() {
                    if best.is_none_or(|b| c > b.0) {
                        best = Some((c, ej.index()));
                    }
                    break;
                }
            }
        }
        let (_, k) = best?;
        let ref_before = reference.before(e.index());
        let faces = FacingFaces {
            rs,
            a: [reference.vertex(ref_before), reference.vertex(e.index())],
            r_ref: reference.r,
            ref_face,
            ref_ids: [reference.id(ref_before), reference.id(e.index())],
            b: [other.vertex(other.before(k)), other.vertex(k)],
            r_inc: other.r,
            other_face: other.face(k)?,
            inc_ids: [other.id(other.before(k)), other.id(k)],
        };
        clip_faces(&faces, m)
    }
}

/// The exact contact ([`super::contact`]) of two polygons, or a polygon and a disc; `None` for
/// any other pair (the general walk's), `Some(None)` where the walk answers `None`.
#[inline]
pub(super) fn contact(
    shape1: SupportShape,
    shape2: SupportShape,
    pos12: &Pose,
    flat_cos: f64,
) -> Option<Option<Contact>> {
    let polygon = |s: &SupportShape| matches!(s, SupportShape::Polygon { .. });
    let disc = |s: &SupportShape| matches!(s, SupportShape::Disc(_));
    let ours = |s: &SupportShape| polygon(s) || disc(s);
    if !(ours(&shape1) && ours(&shape2) && (polygon(&shape1) || polygon(&shape2))) {
        return None;
    }
    let (mut s0, mut s1) = (Poly::blank(1.0), Poly::blank(-1.0));
    if !(s0.place(shape1, &Pose::IDENTITY) && s1.place(shape2, pos12)) {
        return Some(None);
    }
    let mut walk = Merged::blank(&s0, &s1);
    walk.merge();
    let Some(m) = walk.minimum() else {
        return Some(None);
    };
    let one = walk.witness_point(&m);
    let mut c = Contact {
        dist: -m.value,
        normal: m.normal,
        points: [one; 2],
        len: 1,
    };
    if let At::Breakpoint(i) = m.at {
        if let Some(two) = walk.facing_faces(i, &m, flat_cos) {
            c.points = two;
            c.len = 2;
        }
    }
    let ok = c.points[..c.len]
        .iter()
        .all(|p| p.point1.is_finite() && p.point2.is_finite() && p.dist.is_finite());
    Some((ok && c.normal.is_finite()).then_some(c))
}

#[cfg(test)]
mod tests;
