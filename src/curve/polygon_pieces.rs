//! The piece layout of a convex polygon dilated by a radius r ≥ 0 (module docs of
//! [`crate::RoundedPolygon`]): corner 0, edge 0, corner 1, … from φ = −π, the maths of the
//! boundary on each piece, and the inverse normal map.
//!
//! One implementation over borrowed slices, shared by [`crate::RoundedPolygon`] (which stores the
//! slices in `Vec`s) and the dispatcher's stack-allocated polygon for parry's shapes (fixed
//! arrays), so that both answer with the same floating-point operations.

use crate::curve::CurvePoint;
use crate::numerics::angle::{ccw_angle, wrap_phi};
use crate::numerics::math::{perp, Vector};
use core::f64::consts::PI;

/// A unit normal within √(this) = 1e-15 of an edge normal is that edge's normal (the edge's
/// whole φ-interval is its range).
const SAME_NORMAL_SQ: f64 = 1e-30;

/// The scalars of a layout ([`layout`]).
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct LayoutScalars {
    /// φ-to-length factor: φ-length = k · pseudo-length.
    pub k: f64,
    /// Pseudo-radius r + c of a corner (c = core perimeter / 2π).
    pub corner_scale: f64,
    /// Largest distance of the boundary from the local origin.
    pub bounding_radius: f64,
}

/// Computes the layout of the core polygon `vertices` (n ≥ 2, counter-clockwise, no validation)
/// dilated by `radius` into the first n entries of `edge_normals` and `edge_lengths` and the first
/// 2n + 1 of `piece_starts` (the last one is π).
pub(crate) fn layout(
    vertices: &[Vector],
    radius: f64,
    edge_normals: &mut [Vector],
    edge_lengths: &mut [f64],
    piece_starts: &mut [f64],
) -> LayoutScalars {
    let n = vertices.len();
    for i in 0..n {
        let d = vertices[(i + 1) % n] - vertices[i];
        let len = d.length();
        edge_lengths[i] = len;
        let dir = d / len;
        edge_normals[i] = Vector::new(dir.y, -dir.x);
    }
    let perimeter: f64 = edge_lengths[..n].iter().sum();
    let c = perimeter / (2.0 * PI);
    let corner_scale = radius + c;
    let total = perimeter + 2.0 * PI * corner_scale;
    let k = 2.0 * PI / total;
    let mut phi = -PI;
    for i in 0..n {
        let alpha = ccw_angle(edge_normals[(i + n - 1) % n], edge_normals[i]);
        piece_starts[2 * i] = phi;
        phi += k * alpha * corner_scale;
        piece_starts[2 * i + 1] = phi;
        phi += k * edge_lengths[i];
    }
    piece_starts[2 * n] = PI;
    LayoutScalars {
        k,
        corner_scale,
        bounding_radius: vertices.iter().fold(0.0f64, |m, v| m.max(v.length())) + radius,
    }
}

/// A laid-out polygon, borrowed: n vertices, n edge normals and lengths, 2n + 1 piece starts.
#[derive(Copy, Clone, Debug)]
pub(crate) struct PolygonPieces<'a> {
    pub vertices: &'a [Vector],
    pub edge_normals: &'a [Vector],
    pub edge_lengths: &'a [f64],
    pub piece_starts: &'a [f64],
    pub radius: f64,
    pub scalars: LayoutScalars,
}

impl<'a> PolygonPieces<'a> {
    /// The φ where pieces start (derivatives jump there), without the closing π.
    #[inline]
    pub fn breakpoints(&self) -> &'a [f64] {
        &self.piece_starts[..2 * self.vertices.len()]
    }

    /// Index of the piece containing φ (even: corner i = idx/2, odd: edge i = idx/2).
    #[inline]
    pub fn piece_of(&self, phi: f64) -> usize {
        // partition_point: first start > phi; the piece is the one before.
        self.breakpoints().partition_point(|&x| x <= phi).saturating_sub(1)
    }

    /// The boundary point and normal with their φ-derivatives. On a corner N' = ω·N⊥ with
    /// ω = 1/(k(r + c)) and P = vᵢ + r·N; on an edge N is constant and P moves at speed 1/k.
    pub fn eval(&self, phi: f64) -> CurvePoint {
        let phi = wrap_phi(phi);
        let n = self.vertices.len();
        let LayoutScalars { k, corner_scale, .. } = self.scalars;
        let piece = self.piece_of(phi);
        let i = piece / 2;
        let u = phi - self.piece_starts[piece];
        if piece.is_multiple_of(2) {
            let w = 1.0 / (k * corner_scale);
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
            let s = (u / k).clamp(0.0, len);
            CurvePoint {
                point: self.vertices[i] + e * self.radius + dir * s,
                d_point: dir / k,
                dd_point: Vector::ZERO,
                normal: e,
                d_normal: Vector::ZERO,
                dd_normal: Vector::ZERO,
            }
        }
    }

    /// The φ-range whose normal is the unit vector `m`: a point on a corner, a whole edge.
    pub fn phi_range_of_normal(&self, m: Vector) -> (f64, f64) {
        let n = self.vertices.len();
        // Corner i covers normals from e_{i-1} (exclusive) to e_i (inclusive as edge i).
        let edge_range = |i: usize| (self.piece_starts[2 * i + 1], self.piece_starts[2 * i + 2]);
        for i in 0..n {
            let e_prev = self.edge_normals[(i + n - 1) % n];
            let e = self.edge_normals[i];
            let span = ccw_angle(e_prev, e);
            let a = ccw_angle(e_prev, m);
            if a == 0.0 || (m - e_prev).length_squared() < SAME_NORMAL_SQ {
                return edge_range((i + n - 1) % n);
            }
            if a < span {
                let phi = self.piece_starts[2 * i] + a * self.scalars.k * self.scalars.corner_scale;
                return (phi, phi);
            }
            if a == span || (m - e).length_squared() < SAME_NORMAL_SQ {
                return edge_range(i);
            }
        }
        // Only reachable through rounding: the normal sits on edge n−1's boundary.
        edge_range(n - 1)
    }

    /// The support point in direction `m` (any length; zero is read as +x).
    pub fn support_point(&self, m: Vector) -> Vector {
        let m = m.normalize_or(Vector::X);
        let best = self
            .vertices
            .iter()
            .copied()
            .max_by(|a, b| a.dot(m).total_cmp(&b.dot(m)))
            .unwrap_or(Vector::ZERO);
        best + m * self.radius
    }
}
