//! parry `Shape` implementations for the crate's shapes: [`crate::Ellipse`], [`crate::RoundedPolygon`],
//! [`crate::CapsuleEllipse`] and [`crate::CustomCurve`].
//!
//! Each implements parry's `Shape`, `RayCast`, `PointQuery`, `SupportMap` and
//! `PolygonalFeatureMap`, reports `ShapeType::Custom` / `TypedShape::Custom(self)`, and so can be
//! wrapped in a `SharedShape` and used by parry's `DefaultQueryDispatcher` (through the support
//! map and the polygonal feature map) as well as by [`crate::SmoothDispatcher`].
//!
//! # Design choices
//!
//! * **Polygonal feature map** (`features`). parry builds contact manifolds between two convex shapes from
//!   one "polygonal feature" of each (at most two vertices) and panics (`unimplemented!`) when
//!   both are single vertices, so every feature returned here has two vertices, and
//!   `as_polygonal_feature_map` returns `(self, 0.0)` for all four shapes:
//!   * at a smooth support point: a tangent segment centred on the support point, of half-length
//!     min(10⁻⁴·R, ρ/4) (R the bounding radius, ρ the radius of curvature there; at least
//!     10⁻⁹·R). Both vertices project onto the direction exactly as the support point, so the
//!     distances parry derives from them are the exact gap, and the segment is too short to make
//!     a smooth body balance on a "flat patch";
//!   * within [`FLAT_FEATURE_MAX_ANGLE`] of the normal of a flat piece (the segment of a
//!     [`crate::CapsuleEllipse`], a flat piece of a [`crate::CustomCurve`]): that flat piece, or, when the
//!     support point has already left it, the chord from the piece's far end to the support
//!     point. Both vertices are boundary points, so every contact distance is exact, and a body
//!     resting on a flat side gets a two-point manifold;
//!   * for a [`crate::RoundedPolygon`]: the core edge whose normal is best aligned with the direction
//!     (parry's choice for `ConvexPolygon`), translated by r·n̂. Clipping along n̂ is unchanged
//!     by a translation along n̂, so the contacts are exactly those parry computes for its
//!     `RoundConvexPolygon` (core feature, then shifted by the border radius); the vertex on
//!     the support side is the true support point. Feature ids follow parry's `ConvexPolygon`
//!     (vertex i → 2i, edge i → 2i + 1).
//! * **CCD thickness** follows parry: the smallest half-extent of the local AABB — min(a, b) for
//!   the ellipse; for the rounded polygon parry's `RoundConvexPolygon` value (smallest half-extent
//!   of the core polygon's AABB plus the corner radius). **CCD angular thickness**: π/2 for the
//!   ellipse (π for a circle), as parry's cuboid/capsule; π/4 for the rounded polygon (parry's
//!   convex-polygon value, which a border radius does not change); π/2 for the capsule-ellipse;
//!   π/4 (conservative) for custom curves.
//! * **Mass properties** are exact: the ellipse in closed form; the rounded polygon as core
//!   polygon + one rectangle r × Lᵢ on each edge + one circular sector (radius r, angle αᵢ) at
//!   each corner, every piece's area, first moment and polar second moment summed in closed form
//!   (note that parry's own `RoundConvexPolygon` ignores the border radius in its mass); the
//!   capsule-ellipse in closed form (half ellipse + rectangle + two quarter discs); custom curves
//!   by adaptive Gauss–Legendre quadrature of Green's theorem over each piece between
//!   breakpoints (area ½∮P×P′, first moment ⅓∮P (P×P′), polar moment ¼∮|P|²(P×P′)), once, when
//!   the curve is wrapped, within an evaluation budget ([`crate::MassQuadrature`] says whether it
//!   converged).
//! * **Ray casts**: closed form for the ellipse (scaled to the unit circle, stable quadratic).
//!   The other shapes use an exact generic method: with u the unit ray direction and
//!   m = (u_y, −u_x), f(φ) = (P(φ) − o) × u is monotone on each of the two arcs between the
//!   support points in ±m (increasing on the arc facing the ray, decreasing on the other), so
//!   the entry and exit points are the roots of f on those arcs, found by bracketed Newton.
//!   parry's `solid` semantics: a ray starting inside hits at time 0 (normal −u) when solid,
//!   otherwise at its exit point with the inward normal.
//! * **Point projection**: Eberly's robust bisection for the ellipse (exact also for 1:1000
//!   axes); exact for the rounded polygon (the signed distance of a dilated convex polygon is
//!   the core's minus r); for the capsule-ellipse and custom curves the closest point is a root
//!   of g(φ) = (x − P)·T where g changes sign from + to − (T the tangent); roots are bracketed
//!   on a grid over each piece (at least 4 cells per piece, 64 in all) and polished by
//!   bracketed Newton, and the closest of all candidates wins.
//! * **Scaling** (`scale_dyn`): an ellipse scales to an ellipse by any non-zero factors; a
//!   rounded polygon by a uniform factor (or any factors when its radius is 0); the
//!   capsule-ellipse by a uniform positive factor (a mirror in y is allowed: the shape is
//!   symmetric); a custom curve not at all (`None`).

mod capsule_ellipse;
mod core;
mod custom_curve;
mod ellipse;
mod features;
mod mass;
mod projection;
mod ray;
mod rounded_polygon;

pub(crate) use core::{capsule_ellipse_core, polygon_core, Core};
pub(crate) use custom_curve::curve_core;
pub use features::FLAT_FEATURE_MAX_ANGLE;
pub(crate) use features::{face_id, vertex_id};
pub(crate) use mass::{curve_quadrature, Moments};
pub use mass::{MassQuadrature, QuadratureStatus};

use crate::curve::ConvexCurve;
use crate::numerics::math::{Real, Vector};
use parry2d_f64::bounding_volume::Aabb;

/// The methods of parry's `Shape` that are the same for every shape of this crate: a `Custom`
/// shape, convex, its own support map and polygonal feature map (with no border radius), cloned
/// as itself. The names (`Shape`, `ShapeType`, `TypedShape`, `SupportMap`, `PolygonalFeatureMap`,
/// `Real`) are those in scope where it is called: parry2d-f64's here, parry2d's in the f32
/// package (its only use outside this crate; not a public API).
#[doc(hidden)]
#[macro_export]
macro_rules! custom_shape_common {
    () => {
        fn clone_dyn(&self) -> Box<dyn Shape> {
            Box::new(self.clone())
        }

        fn shape_type(&self) -> ShapeType {
            ShapeType::Custom
        }

        fn as_typed_shape(&self) -> TypedShape<'_> {
            TypedShape::Custom(self)
        }

        fn is_convex(&self) -> bool {
            true
        }

        fn as_support_map(&self) -> Option<&dyn SupportMap> {
            Some(self as &dyn SupportMap)
        }

        fn as_polygonal_feature_map(&self) -> Option<(&dyn PolygonalFeatureMap, Real)> {
            Some((self as &dyn PolygonalFeatureMap, 0.0))
        }
    };
}

/// The local AABB of a curve from its support points along ±x and ±y.
pub(crate) fn curve_aabb(c: &dyn ConvexCurve) -> Aabb {
    let xp = c.support_point(Vector::X).x;
    let xm = c.support_point(-Vector::X).x;
    let yp = c.support_point(Vector::Y).y;
    let ym = c.support_point(-Vector::Y).y;
    Aabb::new(Vector::new(xm, ym), Vector::new(xp, yp))
}

/// parry's CCD thickness of a box: its smallest half-extent.
pub(crate) fn aabb_ccd_thickness(aabb: &Aabb) -> Real {
    let h = aabb.half_extents();
    h.x.min(h.y)
}
