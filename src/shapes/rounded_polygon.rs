//! A convex polygon dilated by a corner radius r ≥ 0 (r = 0: a sharp polygon).
//!
//! The boundary alternates corner arcs and flat edges. Corner i sits at core vertex vᵢ and turns
//! the normal from the normal of edge i−1 to that of edge i through the angle αᵢ; edge i runs
//! from vᵢ + r·eᵢ to vᵢ₊₁ + r·eᵢ with outward normal eᵢ.
//!
//! φ runs over the pieces in the order corner 0, edge 0, corner 1, edge 1, … starting at φ = −π.
//! A corner gets the φ-length k·αᵢ·(r + c) and an edge k·Lᵢ, with c = (core perimeter)/2π so
//! that even a sharp corner (r = 0) owns a φ-interval on which its normal turns, and k scaling
//! the total to 2π. On a corner N' = ω·N⊥ with ω = 1/(k(r + c)) constant and P = vᵢ + r·N; on an
//! edge N is constant (N' = 0) and P moves at constant speed 1/k.
//!
//! This is a type of its own rather than parry's `RoundConvexPolygon` so that rapier hands its
//! continuous collision to [`crate::SmoothDispatcher`] (`ShapeType::Custom`) instead of sweeping
//! it with its own Box2D-style routine; [`RoundedPolygon::to_parry`] converts when parry's shape is
//! wanted.

use crate::curve::polygon_pieces::{layout, LayoutScalars, PolygonPieces};
use crate::curve::{ConvexCurve, CurvePoint};
use crate::error::{non_negative, positive, ShapeError, MAX_VERTICES};
use crate::numerics::math::{cross, unit, Vector};
use crate::parry_shape::{polygon_core, Core};
use core::f64::consts::PI;

/// Consecutive vertices closer than this fraction of the polygon's size are the same vertex
/// ([`ShapeError::RepeatedVertex`]).
const REPEATED_VERTEX: f64 = 1e-12;
/// A vertex where the boundary turns by less than this (the sine of the turn between the unit
/// edge directions) is not a convex corner ([`ShapeError::NotConvex`]).
const MIN_TURN: f64 = 1e-12;

/// A convex polygon with rounded corners: its core polygon dilated by `corner_radius`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "RoundedPolygonDef", into = "RoundedPolygonDef"))]
pub struct RoundedPolygon {
    vertices: Vec<Vector>,
    radius: f64,
    /// Outward unit normal of edge i (from vertex i to i+1).
    edge_normals: Vec<Vector>,
    /// Length of edge i.
    edge_lengths: Vec<f64>,
    /// φ where each piece starts (2n entries: corner 0, edge 0, corner 1, …), then π.
    piece_starts: Vec<f64>,
    /// k, r + c and the bounding radius of the layout.
    scalars: LayoutScalars,
    /// The core (centroid and inradius about it, `parry_shape::polygon_core` of the fields
    /// above), computed once here: the dispatcher reads it at every contact manifold and every
    /// rapier cast (`ccd_thickness`), where computing it — a sum over the edges, an `atan2` per
    /// rounded corner — cost more than the rest of a manifold's bookkeeping.
    core: Option<Core>,
}

#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct RoundedPolygonDef {
    vertices: Vec<[f64; 2]>,
    corner_radius: f64,
}

#[cfg(feature = "serde")]
impl TryFrom<RoundedPolygonDef> for RoundedPolygon {
    type Error = ShapeError;
    fn try_from(d: RoundedPolygonDef) -> Result<Self, ShapeError> {
        let v: Vec<Vector> = d.vertices.iter().map(|p| Vector::new(p[0], p[1])).collect();
        RoundedPolygon::try_new(&v, d.corner_radius)
    }
}

#[cfg(feature = "serde")]
impl From<RoundedPolygon> for RoundedPolygonDef {
    fn from(p: RoundedPolygon) -> Self {
        RoundedPolygonDef {
            vertices: p.vertices.iter().map(|v| [v.x, v.y]).collect(),
            corner_radius: p.radius,
        }
    }
}

impl RoundedPolygon {
    /// The convex counter-clockwise polygon `vertices` dilated by `corner_radius`.
    ///
    /// # Panics
    /// On invalid input, with a message naming the bad parameter; see [`RoundedPolygon::try_new`].
    pub fn new(vertices: &[Vector], corner_radius: f64) -> Self {
        match Self::try_new(vertices, corner_radius) {
            Ok(p) => p,
            Err(e) => panic!("RoundedPolygon::new: {e}"),
        }
    }

    /// The convex counter-clockwise polygon `vertices` dilated by `corner_radius`, or why not:
    /// fewer than three vertices or more than [`crate::MAX_VERTICES`], a non-finite vertex, a repeated vertex, a reflex, flat or
    /// clockwise corner, a negative or non-finite radius, or a length outside
    /// [[`crate::MIN_LENGTH`], [`crate::MAX_LENGTH`]] ([`ShapeError::OutOfRange`]).
    pub fn try_new(vertices: &[Vector], corner_radius: f64) -> Result<Self, ShapeError> {
        let r = non_negative("corner_radius", corner_radius)?;
        if vertices.len() < 3 {
            return Err(ShapeError::TooFewVertices { count: vertices.len() });
        }
        if vertices.len() > MAX_VERTICES {
            return Err(ShapeError::TooManyVertices { count: vertices.len() });
        }
        if let Some(index) = vertices.iter().position(|v| !v.is_finite()) {
            return Err(ShapeError::VertexNotFinite { index });
        }
        crate::error::vertices_in_range(vertices)?;
        let n = vertices.len();
        let size = vertices
            .iter()
            .fold(0.0f64, |m, v| m.max(v.length()))
            .max(f64::MIN_POSITIVE);
        for i in 0..n {
            let j = (i + 1) % n;
            if (vertices[j] - vertices[i]).length() <= REPEATED_VERTEX * size {
                return Err(ShapeError::RepeatedVertex { index: j });
            }
        }
        let mut total_turn = 0.0;
        for i in 0..n {
            let a = vertices[(i + n - 1) % n];
            let b = vertices[i];
            let c = vertices[(i + 1) % n];
            let (e0, e1) = ((b - a).normalize(), (c - b).normalize());
            if cross(e0, e1) <= MIN_TURN {
                return Err(ShapeError::NotConvex { index: i });
            }
            total_turn += cross(e0, e1).atan2(e0.dot(e1));
        }
        if (total_turn - 2.0 * PI).abs() > 1e-6 {
            return Err(ShapeError::NotConvex { index: 0 });
        }
        Ok(Self::from_core_unchecked(vertices.to_vec(), r))
    }

    /// The regular polygon with `sides` sides, core vertices at distance `circumradius` from the
    /// centre (the first on +x, counter-clockwise), rounded outside by `corner_radius`.
    ///
    /// # Panics
    /// On invalid input, naming the bad parameter; see [`RoundedPolygon::try_regular`].
    ///
    /// ```
    /// use smooth_ccd2d::{ConvexCurve, RoundedPolygon};
    /// let heptagon = RoundedPolygon::regular(7, 1.0, 0.15);
    /// assert_eq!(heptagon.vertices().len(), 7);
    /// assert!((heptagon.vertices()[0].x - 1.0).abs() < 1e-15); // the first on +x
    /// assert!((heptagon.bounding_radius() - 1.15).abs() < 1e-12); // core radius + corner radius
    /// ```
    pub fn regular(sides: usize, circumradius: f64, corner_radius: f64) -> Self {
        match Self::try_regular(sides, circumradius, corner_radius) {
            Ok(p) => p,
            Err(e) => panic!("RoundedPolygon::regular: {e}"),
        }
    }

    /// The regular polygon of [`RoundedPolygon::regular`], or why not (as
    /// [`RoundedPolygon::try_new`]; the count of sides is checked against
    /// [`crate::MAX_VERTICES`] before anything is allocated).
    pub fn try_regular(sides: usize, circumradius: f64, corner_radius: f64) -> Result<Self, ShapeError> {
        let r = positive("circumradius", circumradius)?;
        non_negative("corner_radius", corner_radius)?;
        if sides < 3 {
            return Err(ShapeError::TooFewVertices { count: sides });
        }
        // Before allocating: `usize::MAX` sides overflowed the capacity (a panic), 2⁴⁰ asked for
        // 17 TB (an abort).
        if sides > MAX_VERTICES {
            return Err(ShapeError::TooManyVertices { count: sides });
        }
        let v: Vec<Vector> = (0..sides)
            .map(|i| unit(2.0 * PI * i as f64 / sides as f64) * r)
            .collect();
        Self::try_new(&v, corner_radius)
    }

    /// Builds the pieces without validation. Also accepts two vertices (a segment: with r > 0 a
    /// capsule), which is how parry's segments and capsules take part as object1.
    pub(crate) fn from_core_unchecked(vertices: Vec<Vector>, radius: f64) -> Self {
        let n = vertices.len();
        let mut edge_normals = vec![Vector::ZERO; n];
        let mut edge_lengths = vec![0.0; n];
        let mut piece_starts = vec![0.0; 2 * n + 1];
        let scalars = layout(
            &vertices,
            radius,
            &mut edge_normals,
            &mut edge_lengths,
            &mut piece_starts,
        );
        let core = polygon_core(&vertices, &edge_normals, radius);
        Self {
            vertices,
            radius,
            edge_normals,
            edge_lengths,
            piece_starts,
            scalars,
            core,
        }
    }

    /// The polygon's core: `parry_shape::polygon_core` of its vertices, edge normals and corner
    /// radius, stored when it was built.
    #[inline]
    pub(crate) fn core(&self) -> Option<Core> {
        self.core
    }

    /// The shared piece layout over this polygon's data.
    #[inline]
    fn pieces(&self) -> PolygonPieces<'_> {
        PolygonPieces {
            vertices: &self.vertices,
            edge_normals: &self.edge_normals,
            edge_lengths: &self.edge_lengths,
            piece_starts: &self.piece_starts,
            radius: self.radius,
            scalars: self.scalars,
        }
    }

    /// The shared piece layout, for the tests of `curve::polygon_pieces`.
    #[cfg(test)]
    pub(crate) fn pieces_for_tests(&self) -> PolygonPieces<'_> {
        self.pieces()
    }

    /// The core polygon's vertices (counter-clockwise).
    pub fn vertices(&self) -> &[Vector] {
        &self.vertices
    }

    /// The corner radius r.
    pub fn corner_radius(&self) -> f64 {
        self.radius
    }

    /// Outward unit normals of the edges (edge i runs from vertex i to vertex i+1).
    pub fn edge_normals(&self) -> &[Vector] {
        &self.edge_normals
    }

    /// This shape as parry's `RoundConvexPolygon` (or `ConvexPolygon` when r = 0 is wanted,
    /// take `.inner_shape`). `None` only for a degenerate core (fewer than three vertices).
    pub fn to_parry(&self) -> Option<parry2d_f64::shape::RoundConvexPolygon> {
        let poly = parry2d_f64::shape::ConvexPolygon::from_convex_polyline(self.vertices.clone())?;
        Some(parry2d_f64::shape::RoundShape {
            inner_shape: poly,
            border_radius: self.radius,
        })
    }
}

impl ConvexCurve for RoundedPolygon {
    fn eval(&self, phi: f64) -> CurvePoint {
        self.pieces().eval(phi)
    }

    fn breakpoints(&self) -> &[f64] {
        &self.piece_starts[..2 * self.vertices.len()]
    }

    fn bounding_radius(&self) -> f64 {
        self.scalars.bounding_radius
    }

    fn min_radius_of_curvature(&self) -> f64 {
        // Corners are arcs of the corner radius, edges are flat.
        self.radius
    }

    fn phi_range_of_normal(&self, m: Vector) -> (f64, f64) {
        self.pieces().phi_range_of_normal(m)
    }

    fn support_point(&self, m: Vector) -> Vector {
        self.pieces().support_point(m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fd_check(c: &dyn ConvexCurve, phi: f64) {
        let h = 1e-6;
        let (a, b, m) = (c.eval(phi - h), c.eval(phi + h), c.eval(phi));
        let dp = (b.point - a.point) / (2.0 * h);
        let dn = (b.normal - a.normal) / (2.0 * h);
        assert!((dp - m.d_point).length() < 1e-6, "dP at {phi}: {dp} vs {}", m.d_point);
        assert!((dn - m.d_normal).length() < 1e-6, "dN at {phi}");
    }

    #[test]
    fn regular_polygon_puts_first_vertex_on_positive_x() {
        let p = RoundedPolygon::regular(7, 1.0, 0.15);
        assert!((p.vertices()[0] - Vector::new(1.0, 0.0)).length() < 1e-15);
        assert!((p.bounding_radius() - 1.15).abs() < 1e-15);
        // The rightmost boundary point is the first vertex pushed out by the radius.
        assert!((p.support_point(Vector::X) - Vector::new(1.15, 0.0)).length() < 1e-14);
    }

    #[test]
    fn point_and_normal_are_continuous_at_piece_ends() {
        for r in [0.0, 0.2] {
            let p = RoundedPolygon::regular(5, 1.0, r);
            for &b in p.breakpoints() {
                let (l, rr) = (p.eval(b - 1e-12), p.eval(b + 1e-12));
                assert!(
                    (l.point - rr.point).length() < 1e-10,
                    "r={r} b={b}: {} vs {}",
                    l.point,
                    rr.point
                );
                assert!((l.normal - rr.normal).length() < 1e-10);
            }
            let (l, rr) = (p.eval(PI - 1e-12), p.eval(-PI));
            assert!((l.point - rr.point).length() < 1e-10);
        }
    }

    #[test]
    fn derivatives_match_finite_differences_inside_pieces() {
        let p = RoundedPolygon::regular(6, 1.3, 0.1);
        let bp = p.breakpoints().to_vec();
        for w in bp.windows(2) {
            fd_check(&p, 0.5 * (w[0] + w[1]));
        }
    }

    #[test]
    fn phi_range_of_normal_inverts_the_normal_map() {
        let p = RoundedPolygon::regular(5, 1.0, 0.0);
        for k in 0..50 {
            let phi = -PI + 2.0 * PI * (k as f64 + 0.37) / 50.0;
            let cp = p.eval(phi);
            let (lo, hi) = p.phi_range_of_normal(cp.normal);
            assert!(lo <= phi + 1e-12 && phi <= hi + 1e-12, "{phi} not in [{lo}, {hi}]");
        }
    }

    #[test]
    fn try_new_rejects_bad_vertex_lists() {
        let sq = [
            Vector::new(0.0, 0.0),
            Vector::new(1.0, 0.0),
            Vector::new(1.0, 1.0),
            Vector::new(0.0, 1.0),
        ];
        assert!(RoundedPolygon::try_new(&sq, 0.1).is_ok());
        let cw: Vec<Vector> = sq.iter().rev().copied().collect();
        assert!(matches!(
            RoundedPolygon::try_new(&cw, 0.1),
            Err(ShapeError::NotConvex { .. })
        ));
        assert!(matches!(
            RoundedPolygon::try_new(&sq[..2], 0.1),
            Err(ShapeError::TooFewVertices { count: 2 })
        ));
        assert!(matches!(
            RoundedPolygon::try_new(&sq, -0.1),
            Err(ShapeError::Negative { .. })
        ));
        let rep = [sq[0], sq[1], sq[1], sq[2]];
        assert!(matches!(
            RoundedPolygon::try_new(&rep, 0.0),
            Err(ShapeError::RepeatedVertex { .. })
        ));
        let nan = [sq[0], Vector::new(f64::NAN, 0.0), sq[2]];
        assert!(matches!(
            RoundedPolygon::try_new(&nan, 0.0),
            Err(ShapeError::VertexNotFinite { index: 1 })
        ));
        let reflex = [sq[0], sq[1], Vector::new(0.5, 0.2), sq[3]];
        assert!(matches!(
            RoundedPolygon::try_new(&reflex, 0.0),
            Err(ShapeError::NotConvex { .. })
        ));
        // A pentagram's vertices turn convexly at every corner but wind twice.
        let star: Vec<Vector> = (0..5).map(|i| unit(4.0 * PI * i as f64 / 5.0)).collect();
        assert!(RoundedPolygon::try_new(&star, 0.0).is_err());
        assert!(matches!(
            RoundedPolygon::try_regular(2, 1.0, 0.0),
            Err(ShapeError::TooFewVertices { .. })
        ));
        assert!(matches!(
            RoundedPolygon::try_regular(5, 0.0, 0.0),
            Err(ShapeError::NotPositive {
                name: "circumradius",
                ..
            })
        ));
    }

    #[test]
    #[should_panic(expected = "corner_radius")]
    fn regular_panics_naming_the_parameter() {
        let _ = RoundedPolygon::regular(5, 1.0, f64::NAN);
    }
}
