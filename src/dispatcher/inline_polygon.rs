//! [`InlinePolygon`]: the curve of a parry polygonal shape (box, triangle, segment, capsule,
//! small convex polygon, and their round versions) built on the stack, so that the dispatcher
//! converts parry shapes without allocating.
//!
//! It is [`RoundedPolygon`](crate::RoundedPolygon) with fixed-capacity arrays instead of `Vec`s:
//! the same φ parametrisation (corner 0, edge 0, corner 1, … from φ = −π) and the same floating
//! point operations in the same order, so both give bit-identical answers
//! (`inline_polygon_matches_rounded_polygon_bit_for_bit` in the dispatcher's tests). Polygons with
//! more than [`INLINE_VERTICES`] vertices are converted to a `RoundedPolygon` instead.

use crate::curve::{ccw_angle, wrap_phi, ConvexCurve, CurvePoint};
use crate::math::{perp, Vector};
use core::f64::consts::PI;

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
    /// φ-to-length factor: φ-length = k · pseudo-length.
    k: f64,
    /// Pseudo-radius r + c of a corner.
    corner_scale: f64,
    bounding_radius: f64,
}

impl InlinePolygon {
    /// `RoundedPolygon::from_core_unchecked` on the stack; `None` when `vertices` has more than
    /// [`INLINE_VERTICES`] entries.
    pub(crate) fn from_core_unchecked(vertices: &[Vector], radius: f64) -> Option<Self> {
        let n = vertices.len();
        if n > INLINE_VERTICES {
            return None;
        }
        let mut p = InlinePolygon {
            n,
            vertices: [Vector::ZERO; INLINE_VERTICES],
            radius,
            edge_normals: [Vector::ZERO; INLINE_VERTICES],
            edge_lengths: [0.0; INLINE_VERTICES],
            piece_starts: [0.0; 2 * INLINE_VERTICES + 1],
            k: 0.0,
            corner_scale: 0.0,
            bounding_radius: 0.0,
        };
        p.vertices[..n].copy_from_slice(vertices);
        for i in 0..n {
            let d = vertices[(i + 1) % n] - vertices[i];
            let len = d.length();
            p.edge_lengths[i] = len;
            let dir = d / len;
            p.edge_normals[i] = Vector::new(dir.y, -dir.x);
        }
        let perimeter: f64 = p.edge_lengths[..n].iter().sum();
        let c = perimeter / (2.0 * PI);
        let corner_scale = radius + c;
        let total = perimeter + 2.0 * PI * corner_scale;
        let k = 2.0 * PI / total;
        let mut phi = -PI;
        for i in 0..n {
            let alpha = ccw_angle(p.edge_normals[(i + n - 1) % n], p.edge_normals[i]);
            p.piece_starts[2 * i] = phi;
            phi += k * alpha * corner_scale;
            p.piece_starts[2 * i + 1] = phi;
            phi += k * p.edge_lengths[i];
        }
        p.piece_starts[2 * n] = PI;
        p.bounding_radius = vertices.iter().fold(0.0f64, |m, v| m.max(v.length())) + radius;
        p.k = k;
        p.corner_scale = corner_scale;
        Some(p)
    }

    /// Index of the piece containing φ (even: corner i = idx/2, odd: edge i = idx/2).
    #[inline]
    fn piece_of(&self, phi: f64) -> usize {
        let s = &self.piece_starts[..2 * self.n];
        let idx = s.partition_point(|&x| x <= phi);
        idx.saturating_sub(1)
    }
}

impl ConvexCurve for InlinePolygon {
    fn eval(&self, phi: f64) -> CurvePoint {
        let phi = wrap_phi(phi);
        let n = self.n;
        let piece = self.piece_of(phi);
        let i = piece / 2;
        let u = phi - self.piece_starts[piece];
        if piece.is_multiple_of(2) {
            let w = 1.0 / (self.k * self.corner_scale);
            let e_prev = self.edge_normals[(i + n - 1) % n];
            let theta = u * w;
            let (s, c) = theta.sin_cos();
            let normal = e_prev * c + perp(e_prev) * s;
            let t = perp(normal);
            CurvePoint {
                point: self.vertices[i] + normal * self.radius,
                d_point: t * (self.radius * w),
                dd_point: normal * (-self.radius * w * w),
                normal,
                d_normal: t * w,
                dd_normal: normal * (-w * w),
            }
        } else {
            let e = self.edge_normals[i];
            let dir = perp(e);
            let len = self.edge_lengths[i];
            let s = (u / self.k).clamp(0.0, len);
            CurvePoint {
                point: self.vertices[i] + e * self.radius + dir * s,
                d_point: dir / self.k,
                dd_point: Vector::ZERO,
                normal: e,
                d_normal: Vector::ZERO,
                dd_normal: Vector::ZERO,
            }
        }
    }

    fn breakpoints(&self) -> &[f64] {
        &self.piece_starts[..2 * self.n]
    }

    fn bounding_radius(&self) -> f64 {
        self.bounding_radius
    }

    fn phi_range_of_normal(&self, m: Vector) -> (f64, f64) {
        let n = self.n;
        let edge_range = |i: usize| (self.piece_starts[2 * i + 1], self.piece_starts[2 * i + 2]);
        for i in 0..n {
            let e_prev = self.edge_normals[(i + n - 1) % n];
            let e = self.edge_normals[i];
            let span = ccw_angle(e_prev, e);
            let a = ccw_angle(e_prev, m);
            if a == 0.0 || (m - e_prev).length_squared() < 1e-30 {
                return edge_range((i + n - 1) % n);
            }
            if a < span {
                let phi = self.piece_starts[2 * i] + a * self.k * self.corner_scale;
                return (phi, phi);
            }
            if a == span || (m - e).length_squared() < 1e-30 {
                return edge_range(i);
            }
        }
        edge_range(n - 1)
    }

    fn support_point(&self, m: Vector) -> Vector {
        let m = m.normalize_or(Vector::X);
        let best = self.vertices[..self.n]
            .iter()
            .copied()
            .max_by(|a, b| a.dot(m).total_cmp(&b.dot(m)))
            .unwrap_or(Vector::ZERO);
        best + m * self.radius
    }
}
