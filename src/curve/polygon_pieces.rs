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

    /// The corner whose normal cone [e_{i−1}, e_i] holds the unit vector `m` (up to rounding,
    /// which the callers allow for by looking at its neighbours): bisection on the angles of
    /// the edge normals from e_{n−1}, increasing in i because the polygon is convex and
    /// counter-clockwise. O(log n): a scan of every corner made each evaluation of a query on a
    /// large polygon cost O(n) (issue 32: 2 s for a cast of a 100,000-gon).
    fn corner_of(&self, m: Vector) -> usize {
        let e = self.edge_normals;
        let n = e.len();
        let base = e[n - 1];
        let a = ccw_angle(base, m);
        let (mut lo, mut hi) = (0, n - 1);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if ccw_angle(base, e[mid]) < a {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        lo
    }

    /// The corners to look at for `m`, in increasing order (up to [`WINDOW`] + 2 distinct): the
    /// one [`PolygonPieces::corner_of`] finds and its neighbours within two, and the first and
    /// last corners (where the scans of the circle wrap).
    fn window(&self, m: Vector) -> ([usize; WINDOW + 2], usize) {
        let n = self.vertices.len();
        let i = self.corner_of(m);
        let mut w = [0usize; WINDOW + 2];
        for (k, slot) in w.iter_mut().enumerate().take(WINDOW) {
            *slot = (i + n + k - WINDOW / 2) % n;
        }
        w[WINDOW] = 0;
        w[WINDOW + 1] = n - 1;
        w.sort_unstable();
        let mut len = 0;
        for k in 0..w.len() {
            if len == 0 || w[k] != w[len - 1] {
                w[len] = w[k];
                len += 1;
            }
        }
        (w, len)
    }

    /// What the scan over the corners in [`PolygonPieces::phi_range_of_normal`] answers at
    /// corner `i` for the unit vector `m`, if it stops there.
    fn range_at(&self, i: usize, m: Vector) -> Option<(f64, f64)> {
        let n = self.vertices.len();
        // Corner i covers normals from e_{i-1} (exclusive) to e_i (inclusive as edge i).
        let edge_range = |i: usize| (self.piece_starts[2 * i + 1], self.piece_starts[2 * i + 2]);
        let e_prev = self.edge_normals[(i + n - 1) % n];
        let e = self.edge_normals[i];
        let span = ccw_angle(e_prev, e);
        let a = ccw_angle(e_prev, m);
        if a == 0.0 || (m - e_prev).length_squared() < SAME_NORMAL_SQ {
            return Some(edge_range((i + n - 1) % n));
        }
        // (Before the corner's own normals: a normal a hair short of e is e, as one a hair past
        // e_prev is e_prev.)
        if a == span || (m - e).length_squared() < SAME_NORMAL_SQ {
            return Some(edge_range(i));
        }
        if a < span {
            let phi = self.piece_starts[2 * i] + a * self.scalars.k * self.scalars.corner_scale;
            return Some((phi, phi));
        }
        None
    }

    /// The φ-range whose normal is the unit vector `m`: a point on a corner, a whole edge.
    ///
    /// The answer of a scan of the corners in order (the first that holds m): for more than
    /// [`SCAN_UP_TO`] vertices taken on the corners around the one bisection finds, O(log n)
    /// (the scan itself remains for what rounding could leave outside that window).
    pub fn phi_range_of_normal(&self, m: Vector) -> (f64, f64) {
        let n = self.vertices.len();
        // Small polygons, and directions that are not unit vectors (0, NaN: outside the contract,
        // where the angles the bisection compares are those of signed zeros), are scanned.
        let found = if n <= SCAN_UP_TO || !(0.5..2.0).contains(&m.length_squared()) {
            None
        } else {
            let (w, len) = self.window(m);
            w[..len].iter().find_map(|&i| self.range_at(i, m))
        };
        found
            .or_else(|| (0..n).find_map(|i| self.range_at(i, m)))
            // Only reachable through rounding: the normal sits on edge n−1's boundary.
            .unwrap_or((self.piece_starts[2 * n - 1], self.piece_starts[2 * n]))
    }

    /// [`PolygonPieces::phi_range_of_normal`] through the window at any size (for the tests).
    #[cfg(test)]
    fn phi_range_windowed(&self, m: Vector) -> Option<(f64, f64)> {
        let (w, len) = self.window(m);
        w[..len].iter().find_map(|&i| self.range_at(i, m))
    }

    /// The support point in direction `m` (any length; zero is read as +x).
    ///
    /// The core vertex furthest along m (the last of equals in index order, as a scan keeps
    /// them): for more than [`SCAN_UP_TO`] vertices among the corners around the one whose cone
    /// holds m, O(log n).
    pub fn support_point(&self, m: Vector) -> Vector {
        let m = m.normalize_or(Vector::X);
        let best = if self.vertices.len() <= SCAN_UP_TO {
            self.vertices
                .iter()
                .copied()
                .max_by(|a, b| a.dot(m).total_cmp(&b.dot(m)))
                .unwrap_or(Vector::ZERO)
        } else {
            self.support_windowed(m)
        };
        best + m * self.radius
    }

    /// The core vertex furthest along the unit vector `m` among the window's corners.
    fn support_windowed(&self, m: Vector) -> Vector {
        let (w, len) = self.window(m);
        let mut best = self.vertices[w[0]];
        for &i in &w[1..len] {
            let v = self.vertices[i];
            if v.dot(m).total_cmp(&best.dot(m)).is_ge() {
                best = v;
            }
        }
        best
    }
}

/// Corners around the bisection's [`PolygonPieces::window`] looks at.
const WINDOW: usize = 5;
/// Polygons of up to this many vertices are scanned rather than bisected (the bisection takes
/// an arctangent per halving: slower than a scan of a few dot products; the answers are the
/// same to the bit).
const SCAN_UP_TO: usize = 16;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::math::unit;
    use crate::{ConvexCurve, RoundedPolygon};

    /// The scans [`PolygonPieces::phi_range_of_normal`] and [`PolygonPieces::support_point`]
    /// replaced (issue 32).
    fn scanned(p: &PolygonPieces, m: Vector) -> ((f64, f64), Vector) {
        let n = p.vertices.len();
        let range = (0..n)
            .find_map(|i| p.range_at(i, m))
            .unwrap_or((p.piece_starts[2 * n - 1], p.piece_starts[2 * n]));
        let u = m.normalize_or(Vector::X);
        let best = p
            .vertices
            .iter()
            .copied()
            .max_by(|a, b| a.dot(u).total_cmp(&b.dot(u)))
            .unwrap_or(Vector::ZERO);
        (range, best + u * p.radius)
    }

    /// The windows around the bisection answer as the scans do, to the bit: segments,
    /// triangles, squares, irregular polygons and a 1,000-gon, at random directions, at every
    /// edge normal and vertex direction exactly, and a rounding off them.
    #[test]
    fn bisection_answers_as_the_scan_of_every_corner() {
        let mut seed = 7u64;
        let mut next = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut polygons = vec![
            RoundedPolygon::from_core_unchecked(vec![Vector::new(-1.0, 0.2), Vector::new(0.7, -0.1)], 0.1),
            RoundedPolygon::regular(3, 1.0, 0.0),
            RoundedPolygon::regular(4, 1.0, 0.2),
            RoundedPolygon::regular(1000, 2.0, 0.01),
        ];
        for _ in 0..40 {
            let n = 3 + (next() * 30.0) as usize;
            let mut a: Vec<f64> = (0..n).map(|_| next() * core::f64::consts::TAU).collect();
            a.sort_by(f64::total_cmp);
            let v: Vec<Vector> = a.iter().map(|&t| Vector::new(t.cos(), 0.3 * t.sin())).collect();
            if let Ok(p) = RoundedPolygon::try_new(&v, 0.1 * next()) {
                polygons.push(p);
            }
        }
        let mut checked = 0;
        for p in &polygons {
            let pieces = p.pieces_for_tests();
            let mut dirs: Vec<Vector> = (0..200).map(|_| unit(next() * 7.0 - 3.5)).collect();
            for &e in p.edge_normals() {
                dirs.extend([e, -e, unit(e.y.atan2(e.x) + 1e-16), unit(e.y.atan2(e.x) - 1e-15)]);
            }
            for &v in p.vertices() {
                dirs.push(v.normalize_or(Vector::X));
            }
            for m in dirs {
                let (range, support) = scanned(&pieces, m);
                // The windows themselves, at every size (the small polygons' queries scan).
                let windowed = pieces.phi_range_windowed(m).expect("the window holds m");
                let u = m.normalize_or(Vector::X);
                let got = (windowed, pieces.support_windowed(u) + u * pieces.radius);
                assert_eq!(got.0 .0.to_bits(), range.0.to_bits(), "{p:?} {m}");
                assert_eq!(got.0 .1.to_bits(), range.1.to_bits(), "{p:?} {m}");
                assert_eq!(got.1, support, "{p:?} {m}");
                // The queries themselves, also at directions outside their contract (zero,
                // scaled, NaN, infinite): the scan's answers.
                for d in [
                    m,
                    m * 1e300,
                    m * 1e-300,
                    m * 3.0,
                    Vector::ZERO,
                    -Vector::ZERO,
                    Vector::new(f64::NAN, 1.0),
                ] {
                    let (range, support) = scanned(&pieces, d);
                    let got = pieces.phi_range_of_normal(d);
                    assert_eq!(
                        (got.0.to_bits(), got.1.to_bits()),
                        (range.0.to_bits(), range.1.to_bits()),
                        "{d}"
                    );
                    assert_eq!(pieces.support_point(d), support, "{d}");
                }
                checked += 1;
            }
        }
        assert!(checked > 10_000, "{checked}");
        let _ = ConvexCurve::bounding_radius(&polygons[0]);
    }

    /// A unit normal within 1e-15 of an edge normal is that edge's normal from either side: its
    /// range is the edge's whole φ-interval. (Short of the normal, the corner before the edge
    /// used to answer with its last point: the stationary distance's node then carried F's slope
    /// from the wrong side of the kink.)
    #[test]
    fn a_normal_a_rounding_off_an_edge_normal_is_the_edge() {
        for p in [
            RoundedPolygon::regular(4, 1.0, 0.0),
            RoundedPolygon::regular(7, 1.0, 0.1),
        ] {
            let pieces = p.pieces_for_tests();
            for (i, &e) in p.edge_normals().iter().enumerate() {
                let edge = (pieces.piece_starts[2 * i + 1], pieces.piece_starts[2 * i + 2]);
                let a = e.y.atan2(e.x);
                for m in [e, unit(a - 4e-16), unit(a + 4e-16)] {
                    if (m - e).length_squared() < SAME_NORMAL_SQ {
                        assert_eq!(pieces.phi_range_of_normal(m), edge, "edge {i}, {m} against {e}");
                    }
                }
            }
        }
        // The box of the degenerate start: its bottom edge's normal as the search computes it.
        let b = RoundedPolygon::new(
            &[
                Vector::new(0.0, 0.0),
                Vector::new(1.0, 0.0),
                Vector::new(1.0, 1.0),
                Vector::new(0.0, 1.0),
            ],
            0.0,
        );
        let (lo, hi) = b.phi_range_of_normal(unit(1.5 * core::f64::consts::PI));
        assert!(hi > lo, "({lo}, {hi})");
    }
}
