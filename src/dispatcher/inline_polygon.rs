//! [`InlinePolygon`]: the curve of a parry polygonal shape (box, triangle, segment, capsule,
//! small convex polygon, and their round versions) built on the stack, so that the dispatcher
//! converts parry shapes without allocating.
//!
//! It is [`RoundedPolygon`](crate::RoundedPolygon) with fixed-capacity arrays instead of `Vec`s; both
//! evaluate through [`crate::curve::polygon_pieces`], so they give bit-identical answers
//! (`inline_polygon_matches_rounded_polygon_bit_for_bit` in the dispatcher's tests). Polygons with
//! more than [`INLINE_VERTICES`] vertices are converted to a `RoundedPolygon` instead.

use crate::curve::polygon_pieces::{layout, LayoutScalars, PolygonPieces};
use crate::curve::{ConvexCurve, CurvePoint};
use crate::numerics::math::Vector;

/// The most core vertices an [`InlinePolygon`] holds.
pub(crate) const INLINE_VERTICES: usize = 16;

/// A convex polygon dilated by `radius`, at most [`INLINE_VERTICES`] vertices (two: a segment,
/// a capsule when the radius is positive).
#[derive(Clone, Debug)]
pub(crate) struct InlinePolygon {
    n: usize,
    vertices: [Vector; INLINE_VERTICES],
    radius: f64,
    /// Outward unit normal of edge i (from vertex i to i+1).
    edge_normals: [Vector; INLINE_VERTICES],
    /// Length of edge i.
    edge_lengths: [f64; INLINE_VERTICES],
    /// φ where each piece starts (2n entries: corner 0, edge 0, corner 1, …), then π.
    piece_starts: [f64; 2 * INLINE_VERTICES + 1],
    /// k, r + c and the bounding radius of the layout.
    scalars: LayoutScalars,
}

impl InlinePolygon {
    /// `RoundedPolygon::from_core_unchecked` on the stack; `None` when `vertices` has more than
    /// [`INLINE_VERTICES`] entries.
    pub(crate) fn from_core_unchecked(vertices: &[Vector], radius: f64) -> Option<Self> {
        let n = vertices.len();
        if n > INLINE_VERTICES {
            return None;
        }
        let mut v = [Vector::ZERO; INLINE_VERTICES];
        v[..n].copy_from_slice(vertices);
        let mut edge_normals = [Vector::ZERO; INLINE_VERTICES];
        let mut edge_lengths = [0.0; INLINE_VERTICES];
        let mut piece_starts = [0.0; 2 * INLINE_VERTICES + 1];
        let scalars = layout(
            vertices,
            radius,
            &mut edge_normals,
            &mut edge_lengths,
            &mut piece_starts,
        );
        Some(InlinePolygon {
            n,
            vertices: v,
            radius,
            edge_normals,
            edge_lengths,
            piece_starts,
            scalars,
        })
    }

    /// The core vertices (counter-clockwise).
    pub(crate) fn vertices(&self) -> &[Vector] {
        &self.vertices[..self.n]
    }

    /// The outward unit normals of the edges (edge i from vertex i to i + 1).
    pub(crate) fn edge_normals(&self) -> &[Vector] {
        &self.edge_normals[..self.n]
    }

    /// The radius the core is dilated by.
    pub(crate) fn radius(&self) -> f64 {
        self.radius
    }

    /// The shared piece layout over this polygon's data.
    #[inline]
    fn pieces(&self) -> PolygonPieces<'_> {
        let n = self.n;
        PolygonPieces {
            vertices: &self.vertices[..n],
            edge_normals: &self.edge_normals[..n],
            edge_lengths: &self.edge_lengths[..n],
            piece_starts: &self.piece_starts[..2 * n + 1],
            radius: self.radius,
            scalars: self.scalars,
        }
    }
}

impl ConvexCurve for InlinePolygon {
    fn eval(&self, phi: f64) -> CurvePoint {
        self.pieces().eval(phi)
    }

    fn breakpoints(&self) -> &[f64] {
        &self.piece_starts[..2 * self.n]
    }

    fn bounding_radius(&self) -> f64 {
        self.scalars.bounding_radius
    }

    fn min_radius_of_curvature(&self) -> f64 {
        // As `RoundedPolygon`: corners are arcs of the radius, edges are flat.
        self.radius
    }

    fn phi_range_of_normal(&self, m: Vector) -> (f64, f64) {
        self.pieces().phi_range_of_normal(m)
    }

    fn support_point(&self, m: Vector) -> Vector {
        self.pieces().support_point(m)
    }
}
