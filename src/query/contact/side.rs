//! A side of the contact query: a shape's support function as pieces between breakpoints of the
//! direction, placed in body 1's frame.
//!
//! The shapes the query takes ([`SupportShape`]) have support functions made of two kinds of
//! pieces over arcs of the direction n:
//!
//! * a **vertex** v with a radius r: h(n) = v·n + r (a polygon's corner, dilated or not, a disc,
//!   the two arcs of a `CapsuleEllipse`);
//! * an **ellipse** centred at c with semi-axes a, b along unit axes u, w:
//!   h(n) = c·n + k(n), k(n) = √(a²(n·u)² + b²(n·w)²).
//!
//! The breakpoints are the directions where the piece changes: a polygon's edge normals, the
//! three junctions of a `CapsuleEllipse`. A breakpoint between two vertices of the same radius
//! is a *face* (the edge between them, dilated). A side enters the query's function
//! F(n) = h₁(n) + h₂(−n) with the sign σ = +1 (body 1, h₁(n)) or σ = −1 (body 2, h₂(−n)); both
//! kinds of piece keep their form: a vertex contributes (σv)·n + r, an ellipse (σc)·n + k(n)
//! (k is even). A side is stored by piece (coefficients and radii in arrays), read by index. Body 2's breakpoints are negated, which keeps them counter-clockwise.

use crate::numerics::math::{Pose, Vector};

/// The most breakpoints a side may have (a polygon of this many vertices); larger polygons are
/// left to the general stationary distance.
pub(crate) const MAX_BREAKPOINTS: usize = 16;

/// A shape as the contact query sees it, in its own frame.
#[derive(Copy, Clone, Debug)]
pub(crate) enum SupportShape<'a> {
    /// A convex polygon (counter-clockwise, at least two vertices; edge i from vertex i to
    /// i + 1 with outward unit normal `normals[i]`) dilated by `radius` ≥ 0.
    Polygon {
        vertices: &'a [Vector],
        normals: &'a [Vector],
        radius: f64,
    },
    /// A disc of this radius centred at the origin.
    Disc(f64),
    /// An ellipse centred at the origin with these semi-axes along x and y.
    Ellipse(f64, f64),
    /// A `CapsuleEllipse` with parameters r1, r2, r3.
    CapsuleEllipse(f64, f64, f64),
}

/// The ellipse of a side, in body 1's frame: semi-axes `a`, `b` along unit axes `u`, `w`.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Axes {
    pub a: f64,
    pub b: f64,
    pub u: Vector,
    pub w: Vector,
}

impl Axes {
    /// k(n) = √(a²(n·u)² + b²(n·w)²), the support function of the centred ellipse.
    #[inline]
    pub(crate) fn k(&self, n: Vector) -> f64 {
        let (x, y) = (self.a * n.dot(self.u), self.b * n.dot(self.w));
        // Not `hypot` (four times slower): the shapes' sizes are within the crate's accepted
        // length range, far from overflow.
        (x * x + y * y).sqrt()
    }
    /// The support point of the centred ellipse in direction n: (a²(n·u)u + b²(n·w)w)/k(n).
    #[inline]
    pub(crate) fn support(&self, n: Vector) -> Vector {
        let (x, y) = (self.a * self.a * n.dot(self.u), self.b * self.b * n.dot(self.w));
        (self.u * x + self.w * y) / self.k(n)
    }
    /// k(n) and the support point in direction n together (one square root).
    #[inline]
    pub(crate) fn k_and_support(&self, n: Vector) -> (f64, Vector) {
        let (x, y) = (n.dot(self.u), n.dot(self.w));
        let (a2, b2) = (self.a * self.a, self.b * self.b);
        let k = (a2 * x * x + b2 * y * y).sqrt();
        (k, (self.u * (a2 * x) + self.w * (b2 * y)) / k)
    }

    /// `v` in the ellipse's axes.
    #[inline]
    pub(crate) fn local(&self, v: Vector) -> Vector {
        Vector::new(v.dot(self.u), v.dot(self.w))
    }
    /// `v` from the ellipse's axes to body 1's frame.
    #[inline]
    pub(crate) fn world(&self, v: Vector) -> Vector {
        self.u * v.x + self.w * v.y
    }
}

/// Whether consecutive edge normals turn strictly counter-clockwise by less than π (at least
/// three edges), or are opposite (a segment's two). The merge of the walk relies on it: a vertex
/// on a straight edge (two equal normals, which parry's unmodified polylines keep) would put a
/// breakpoint out of order.
pub(super) fn turning(normals: &[Vector]) -> bool {
    let n = normals.len();
    if n == 2 {
        return normals[0].dot(normals[1]) < 0.0 && crate::numerics::math::cross(normals[0], normals[1]).abs() <= 1e-12;
    }
    (0..n).all(|k| crate::numerics::math::cross(normals[k], normals[if k + 1 == n { 0 } else { k + 1 }]) > 0.0)
}

/// Whether the walk takes a polygon of these vertices and edge normals: 2 to
/// [`MAX_BREAKPOINTS`] vertices, one normal each, normals [`turning`].
#[inline]
pub(crate) fn polygon_is_walkable(vertices: &[Vector], normals: &[Vector]) -> bool {
    (2..=MAX_BREAKPOINTS).contains(&vertices.len()) && normals.len() == vertices.len() && turning(normals)
}

/// How a side's breakpoints are faces and its pieces are named.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Layout {
    /// One piece, no breakpoint (a disc, an ellipse).
    Single,
    /// A polygon: breakpoint k is face k, piece k is vertex k + 1.
    Polygon,
    /// A `CapsuleEllipse`: breakpoint 1 is the segment (face 0); pieces are the arcs 0 and 1 and
    /// the half-ellipse 2.
    Capsule,
}

/// A side placed in body 1's frame (see the module docs), stored by piece: piece k contributes
/// `q[k]·n + r[k]`, plus k(n) when it is the ellipse piece.
#[derive(Clone, Debug)]
pub(crate) struct Placed {
    /// Number of breakpoints (0: one piece over every direction).
    pub len: usize,
    /// Breakpoint k, counter-clockwise, in the query's variable.
    pub normals: [Vector; MAX_BREAKPOINTS],
    /// The linear coefficient of the piece after breakpoint k (piece 0 alone when `len` is 0).
    pub q: [Vector; MAX_BREAKPOINTS],
    /// The radius of piece k (0 for the ellipse piece).
    pub r: [f64; MAX_BREAKPOINTS],
    /// The ellipse piece's index (`u8::MAX`: none) and the side's ellipse.
    pub ellipse: u8,
    pub axes: Option<Axes>,
    /// σ: +1 for body 1, −1 for body 2.
    pub sign: f64,
    layout: Layout,
}

impl Placed {
    /// A side with no piece yet (see [`Placed::place`]).
    #[inline]
    pub(crate) fn blank(sign: f64) -> Self {
        Placed {
            len: 0,
            normals: [Vector::X; MAX_BREAKPOINTS],
            q: [Vector::ZERO; MAX_BREAKPOINTS],
            r: [0.0; MAX_BREAKPOINTS],
            ellipse: u8::MAX,
            axes: None,
            sign,
            layout: Layout::Single,
        }
    }

    /// Places `shape` at `pose` in body 1's frame; false for more than [`MAX_BREAKPOINTS`]
    /// breakpoints or a polygon with fewer than two vertices or mismatched normals.
    #[inline]
    pub(crate) fn place(&mut self, shape: SupportShape, pose: &Pose) -> bool {
        let s = self;
        let sign = s.sign;
        let at = |v: Vector| pose.transform_point(v) * sign;
        let dir = |n: Vector| pose.transform_vector(n) * sign;
        let axes = |a: f64, b: f64| Axes {
            a,
            b,
            u: pose.transform_vector(Vector::X),
            w: pose.transform_vector(Vector::Y),
        };
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
                s.len = n;
                s.layout = Layout::Polygon;
                for (k, normal) in normals.iter().enumerate() {
                    let next = if k + 1 == n { 0 } else { k + 1 };
                    s.normals[k] = dir(*normal);
                    s.q[k] = at(vertices[next]);
                    s.r[k] = radius;
                }
            }
            SupportShape::Disc(r) => {
                s.q[0] = at(Vector::ZERO);
                s.r[0] = r;
            }
            SupportShape::Ellipse(a, b) => {
                s.q[0] = at(Vector::ZERO);
                s.ellipse = 0;
                s.axes = Some(axes(a, b));
            }
            SupportShape::CapsuleEllipse(r1, r2, r3) => {
                s.len = 3;
                s.layout = Layout::Capsule;
                s.normals[..3].copy_from_slice(&[dir(-Vector::Y), dir(Vector::X), dir(Vector::Y)]);
                s.q[..3].copy_from_slice(&[at(Vector::new(0.0, -r2)), at(Vector::new(0.0, r2)), at(Vector::ZERO)]);
                s.r[..3].copy_from_slice(&[r1, r1, 0.0]);
                s.ellipse = 2;
                s.axes = Some(axes(r3, r1 + r2));
            }
        }
        true
    }

    /// The index of the piece before breakpoint k.
    #[inline]
    pub(crate) fn before(&self, k: usize) -> usize {
        if k == 0 {
            self.len.max(1) - 1
        } else {
            k - 1
        }
    }

    /// The face id of breakpoint k, if it is a face.
    #[inline]
    pub(crate) fn face(&self, k: usize) -> Option<u32> {
        match self.layout {
            Layout::Polygon => Some(k as u32),
            Layout::Capsule => (k == 1).then_some(0),
            Layout::Single => None,
        }
    }

    /// The id of piece k (see the folder's module docs).
    #[inline]
    pub(crate) fn id(&self, k: usize) -> u32 {
        match self.layout {
            Layout::Polygon => (if k + 1 == self.len { 0 } else { k + 1 }) as u32,
            _ => k as u32,
        }
    }

    /// Whether piece k is the ellipse.
    #[inline]
    pub(crate) fn is_ellipse(&self, k: usize) -> bool {
        self.ellipse as usize == k
    }

    /// The contribution of piece k to F at n.
    #[inline]
    pub(crate) fn value(&self, k: usize, n: Vector) -> f64 {
        let v = self.q[k].dot(n) + self.r[k];
        match self.axes {
            Some(ax) if self.is_ellipse(k) => v + ax.k(n),
            _ => v,
        }
    }

    /// The support point of this side for the query's direction n (body 1: h₁ at n; body 2:
    /// h₂ at −n), on piece k, in body 1's frame.
    pub(crate) fn support(&self, k: usize, n: Vector) -> Vector {
        let s = self.sign;
        let p = self.q[k] * s + n * (s * self.r[k]);
        match self.axes {
            Some(ax) if self.is_ellipse(k) => p + ax.support(n) * s,
            _ => p,
        }
    }

    /// The vertex of piece k in body 1's frame with its radius (`None` for the ellipse piece).
    #[inline]
    pub(crate) fn vertex(&self, k: usize) -> Option<(Vector, f64)> {
        (!self.is_ellipse(k)).then(|| (self.q[k] * self.sign, self.r[k]))
    }
}
