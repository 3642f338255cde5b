//! The crate's shapes as parry2d (f32) shapes: each wraps the f64 shape of `smooth-ccd2d` built
//! from the widened f32 parameters, and implements parry2d's `Shape`, `SupportMap`,
//! `PolygonalFeatureMap`, `RayCast` and `PointQuery` by widening the query, asking the f64
//! shape, and rounding the answer once (see [`crate::convert`](crate) for the rounding rules:
//! boxes (local and posed) and local spheres outward, thicknesses down, everything else to
//! nearest). parry2d's default methods built on these (posed spheres, distances to a point,
//! projections with a maximal distance) run in f32 on the rounded answers, as for its own shapes.
//!
//! The f64 shape is always at hand ([`Ellipse::as_f64`] and the same on every wrapper) for the
//! f64 API of `smooth-ccd2d` (curves, [`smooth_ccd2d::time_of_impact`], …).

use crate::convert::{down, feature32, packed32, pose64, up, v32, v64};
use parry2d::bounding_volume::{Aabb, BoundingSphere};
use parry2d::mass_properties::MassProperties;
use parry2d::math::{Pose, Real, Vector};
use parry2d::query::{PointProjection, PointQuery, Ray, RayCast, RayIntersection};
use parry2d::shape::{FeatureId, PolygonalFeature, PolygonalFeatureMap, Shape, ShapeType, SupportMap, TypedShape};
use parry2d_f64::query as q64;
use parry2d_f64::shape as s64;
use smooth_ccd2d::{ConvexCurve, ShapeError};
use std::sync::Arc;

/// An f64 box rounded outward to f32 (it still contains what the f64 box contains).
fn outward(b: &parry2d_f64::bounding_volume::Aabb) -> Aabb {
    Aabb::new(
        Vector::new(down(b.mins.x), down(b.mins.y)),
        Vector::new(up(b.maxs.x), up(b.maxs.y)),
    )
}

/// An f64 inverse mass or inertia rounded to f32, or 0 where it overflows: the mass or inertia
/// is then below f32's normal range (an inertia ∝ size⁴ of a shape of 1e-10, a mass of one of
/// 1e-19), and an inverse of 0 is what parry2d reports for its own shapes whose mass or inertia
/// rounds to 0 in f32 (a ball of 1e-12). Rounded as it was, ∞ made rapier2d's angular velocity
/// NaN at the first step (issue 32).
fn inverse32(inv: f64) -> f32 {
    let r = inv as f32;
    if r.is_finite() {
        r
    } else {
        0.0
    }
}

/// parry2d's traits for an f32 wrapper `$ty` of the f64 shape `$inner`, by delegation.
macro_rules! delegate_to_f64 {
    ($ty:ident, $inner:ty) => {
        impl $ty {
            /// The f64 shape this one stands for (the f32 parameters widened exactly).
            pub fn as_f64(&self) -> &$inner {
                &self.0
            }

            /// The f64 shape this one stands for, by value.
            pub fn into_f64(self) -> $inner {
                self.0
            }
        }

        impl From<$inner> for $ty {
            /// The f32 wrapper of an f64 shape (queries widen f32 input to it exactly).
            fn from(inner: $inner) -> Self {
                Self(inner)
            }
        }

        impl SupportMap for $ty {
            fn local_support_point(&self, dir: Vector) -> Vector {
                v32(s64::SupportMap::local_support_point(&self.0, v64(dir)))
            }
        }

        impl PolygonalFeatureMap for $ty {
            fn local_support_feature(&self, dir: Vector, out: &mut PolygonalFeature) {
                let mut f = s64::PolygonalFeature::default();
                s64::PolygonalFeatureMap::local_support_feature(&self.0, v64(dir), &mut f);
                out.vertices = [v32(f.vertices[0]), v32(f.vertices[1])];
                out.vids = [packed32(f.vids[0]), packed32(f.vids[1])];
                out.fid = packed32(f.fid);
                out.num_vertices = f.num_vertices;
            }
        }

        impl RayCast for $ty {
            fn cast_local_ray_and_get_normal(
                &self,
                ray: &Ray,
                max_time_of_impact: Real,
                solid: bool,
            ) -> Option<RayIntersection> {
                let ray = q64::Ray::new(v64(ray.origin), v64(ray.dir));
                let hit = q64::RayCast::cast_local_ray_and_get_normal(&self.0, &ray, max_time_of_impact as f64, solid)?;
                let r = RayIntersection::new(hit.time_of_impact as f32, v32(hit.normal), feature32(hit.feature));
                (r.time_of_impact.is_finite() && r.normal.is_finite()).then_some(r)
            }
        }

        impl PointQuery for $ty {
            fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
                let p = q64::PointQuery::project_local_point(&self.0, v64(pt), solid);
                PointProjection::new(p.is_inside, v32(p.point))
            }

            fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
                let (p, f) = q64::PointQuery::project_local_point_and_get_feature(&self.0, v64(pt));
                (PointProjection::new(p.is_inside, v32(p.point)), feature32(f))
            }

            fn contains_local_point(&self, pt: Vector) -> bool {
                q64::PointQuery::contains_local_point(&self.0, v64(pt))
            }
        }

        impl Shape for $ty {
            // A `Custom` shape, convex, its own support map and polygonal feature map, cloned as
            // itself: the f64 crate's text, with parry2d's names.
            smooth_ccd2d::custom_shape_common!();

            fn compute_local_aabb(&self) -> Aabb {
                outward(&s64::Shape::compute_local_aabb(&self.0))
            }

            fn compute_aabb(&self, position: &Pose) -> Aabb {
                outward(&s64::Shape::compute_aabb(&self.0, &pose64(position)))
            }

            fn compute_local_bounding_sphere(&self) -> BoundingSphere {
                let s = s64::Shape::compute_local_bounding_sphere(&self.0);
                let c = v32(s.center);
                // The rounded centre moved: grow the radius by the move.
                let moved = (v64(c) - s.center).length();
                BoundingSphere::new(c, up(s.radius + moved))
            }

            fn scale_dyn(&self, scale: Vector, num_subdivisions: u32) -> Option<Box<dyn Shape>> {
                let scaled = s64::Shape::scale_dyn(&self.0, v64(scale), num_subdivisions)?;
                let inner = scaled.as_shape::<$inner>()?.clone();
                Some(Box::new($ty(inner)))
            }

            fn mass_properties(&self, density: Real) -> MassProperties {
                let m = s64::Shape::mass_properties(&self.0, density as f64);
                MassProperties {
                    local_com: v32(m.local_com),
                    inv_mass: inverse32(m.inv_mass),
                    inv_principal_inertia: inverse32(m.inv_principal_inertia),
                }
            }

            fn ccd_thickness(&self) -> Real {
                down(s64::Shape::ccd_thickness(&self.0))
            }

            fn ccd_angular_thickness(&self) -> Real {
                down(s64::Shape::ccd_angular_thickness(&self.0))
            }
        }
    };
}

/// An ellipse centred at the origin with semi-axes along x and y (f32 parameters): the f32 face
/// of [`smooth_ccd2d::Ellipse`].
///
/// ```
/// use smooth_ccd2d_f32::Ellipse;
/// use parry2d::shape::Shape;
/// let e = Ellipse::new(0.5, 0.2);
/// assert_eq!(e.half_x(), 0.5);
/// assert_eq!(e.compute_local_aabb().maxs.y, 0.2);
/// ```
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Ellipse(smooth_ccd2d::Ellipse);
delegate_to_f64!(Ellipse, smooth_ccd2d::Ellipse);

impl Ellipse {
    /// The ellipse with semi-axes `half_x`, `half_y`.
    ///
    /// # Panics
    /// When a semi-axis is not finite and positive, as [`smooth_ccd2d::Ellipse::new`].
    pub fn new(half_x: f32, half_y: f32) -> Self {
        Self(smooth_ccd2d::Ellipse::new(half_x as f64, half_y as f64))
    }

    /// The ellipse with semi-axes `half_x`, `half_y`, or why not
    /// ([`smooth_ccd2d::Ellipse::try_new`]).
    pub fn try_new(half_x: f32, half_y: f32) -> Result<Self, ShapeError> {
        smooth_ccd2d::Ellipse::try_new(half_x as f64, half_y as f64).map(Self)
    }

    /// The semi-axis along x (exactly the f32 it was built with; after `scale_dyn`, the scaled f64
    /// semi-axis rounded).
    pub fn half_x(&self) -> f32 {
        self.0.half_x() as f32
    }

    /// The semi-axis along y (as [`Ellipse::half_x`]).
    pub fn half_y(&self) -> f32 {
        self.0.half_y() as f32
    }

    /// Both semi-axes.
    pub fn half_extents(&self) -> Vector {
        v32(self.0.half_extents())
    }
}

/// A convex polygon dilated by a disc (f32 parameters): the f32 face of
/// [`smooth_ccd2d::RoundedPolygon`], geometrically parry's `RoundConvexPolygon`.
///
/// ```
/// use smooth_ccd2d_f32::RoundedPolygon;
/// let heptagon = RoundedPolygon::regular(7, 1.0, 0.15);
/// assert_eq!(heptagon.vertices().len(), 7);
/// assert_eq!(heptagon.corner_radius(), 0.15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RoundedPolygon(smooth_ccd2d::RoundedPolygon);
delegate_to_f64!(RoundedPolygon, smooth_ccd2d::RoundedPolygon);

impl RoundedPolygon {
    /// The convex counter-clockwise polygon `vertices` dilated by `corner_radius`.
    ///
    /// # Panics
    /// On invalid input, as [`smooth_ccd2d::RoundedPolygon::new`].
    pub fn new(vertices: &[Vector], corner_radius: f32) -> Self {
        match Self::try_new(vertices, corner_radius) {
            Ok(p) => p,
            Err(e) => panic!("RoundedPolygon::new: {e}"),
        }
    }

    /// The rounded polygon, or why not ([`smooth_ccd2d::RoundedPolygon::try_new`]).
    pub fn try_new(vertices: &[Vector], corner_radius: f32) -> Result<Self, ShapeError> {
        // The count before the widened copy is allocated.
        if vertices.len() > smooth_ccd2d::MAX_VERTICES {
            return Err(ShapeError::TooManyVertices { count: vertices.len() });
        }
        let v: Vec<_> = vertices.iter().map(|&v| v64(v)).collect();
        smooth_ccd2d::RoundedPolygon::try_new(&v, corner_radius as f64).map(Self)
    }

    /// The regular polygon with `sides` sides, core vertices at distance `circumradius` from the
    /// centre (the first on +x), rounded by `corner_radius`; its vertices are computed in f64.
    ///
    /// # Panics
    /// On invalid input, as [`smooth_ccd2d::RoundedPolygon::regular`].
    pub fn regular(sides: usize, circumradius: f32, corner_radius: f32) -> Self {
        Self(smooth_ccd2d::RoundedPolygon::regular(
            sides,
            circumradius as f64,
            corner_radius as f64,
        ))
    }

    /// The regular rounded polygon, or why not ([`smooth_ccd2d::RoundedPolygon::try_regular`]).
    pub fn try_regular(sides: usize, circumradius: f32, corner_radius: f32) -> Result<Self, ShapeError> {
        smooth_ccd2d::RoundedPolygon::try_regular(sides, circumradius as f64, corner_radius as f64).map(Self)
    }

    /// The core polygon's vertices, rounded to f32 (the f64 ones: [`RoundedPolygon::as_f64`]).
    pub fn vertices(&self) -> Vec<Vector> {
        self.0.vertices().iter().map(|&v| v32(v)).collect()
    }

    /// The corner radius.
    pub fn corner_radius(&self) -> f32 {
        self.0.corner_radius() as f32
    }
}

/// The specification's Appendix A shape (half an ellipse glued to a "D" of two circular arcs and
/// a segment), f32 parameters: the f32 face of [`smooth_ccd2d::CapsuleEllipse`].
#[derive(Clone, Debug, PartialEq)]
pub struct CapsuleEllipse(smooth_ccd2d::CapsuleEllipse);
delegate_to_f64!(CapsuleEllipse, smooth_ccd2d::CapsuleEllipse);

impl CapsuleEllipse {
    /// The shape with arc radius `r1`, segment half-length `r2` and half-ellipse semi-axis `r3`.
    ///
    /// # Panics
    /// On invalid input, as [`smooth_ccd2d::CapsuleEllipse::new`].
    pub fn new(r1: f32, r2: f32, r3: f32) -> Self {
        Self(smooth_ccd2d::CapsuleEllipse::new(r1 as f64, r2 as f64, r3 as f64))
    }

    /// The shape, or why not ([`smooth_ccd2d::CapsuleEllipse::try_new`]).
    pub fn try_new(r1: f32, r2: f32, r3: f32) -> Result<Self, ShapeError> {
        smooth_ccd2d::CapsuleEllipse::try_new(r1 as f64, r2 as f64, r3 as f64).map(Self)
    }

    /// The parameters (r1, r2, r3).
    pub fn params(&self) -> (f32, f32, f32) {
        let (a, b, c) = self.0.params();
        (a as f32, b as f32, c as f32)
    }
}

/// A user-defined convex curve as a parry2d (f32) shape: the f32 face of
/// [`smooth_ccd2d::CustomCurve`]. The curve itself implements the f64 trait
/// [`smooth_ccd2d::ConvexCurve`]: its algorithms run in f64 whatever the engine's precision.
#[derive(Clone, Debug)]
pub struct CustomCurve(smooth_ccd2d::CustomCurve);
delegate_to_f64!(CustomCurve, smooth_ccd2d::CustomCurve);

impl CustomCurve {
    /// Wraps `curve`.
    ///
    /// # Panics
    /// When the curve breaks its contract, as [`smooth_ccd2d::CustomCurve::new`].
    pub fn new(curve: impl ConvexCurve) -> Self {
        Self(smooth_ccd2d::CustomCurve::new(curve))
    }

    /// Wraps an already shared curve.
    ///
    /// # Panics
    /// As [`CustomCurve::new`].
    pub fn from_arc(curve: Arc<dyn ConvexCurve>) -> Self {
        Self(smooth_ccd2d::CustomCurve::from_arc(curve))
    }

    /// Wraps `curve`, or says which of its methods breaks the contract
    /// ([`smooth_ccd2d::CustomCurve::try_new`]).
    pub fn try_new(curve: impl ConvexCurve) -> Result<Self, ShapeError> {
        smooth_ccd2d::CustomCurve::try_new(curve).map(Self)
    }

    /// [`CustomCurve::try_new`] for an already shared curve.
    pub fn try_from_arc(curve: Arc<dyn ConvexCurve>) -> Result<Self, ShapeError> {
        smooth_ccd2d::CustomCurve::try_from_arc(curve).map(Self)
    }

    /// The wrapped curve.
    pub fn curve(&self) -> &dyn ConvexCurve {
        self.0.curve()
    }
}

/// The f64 shape behind one of this package's shapes; `None` for any other shape.
pub(crate) fn own_f64(g: &dyn Shape) -> Option<&dyn s64::Shape> {
    if g.shape_type() != ShapeType::Custom {
        return None;
    }
    if let Some(s) = g.as_shape::<Ellipse>() {
        Some(&s.0)
    } else if let Some(s) = g.as_shape::<RoundedPolygon>() {
        Some(&s.0)
    } else if let Some(s) = g.as_shape::<CapsuleEllipse>() {
        Some(&s.0)
    } else {
        g.as_shape::<CustomCurve>().map(|s| &s.0 as &dyn s64::Shape)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shapes() -> Vec<(&'static str, Box<dyn Shape>)> {
        vec![
            ("ellipse", Box::new(Ellipse::new(0.5, 0.2))),
            ("heptagon", Box::new(RoundedPolygon::regular(7, 1.0, 0.15))),
            ("capsule-ellipse", Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8))),
            (
                "custom",
                Box::new(CustomCurve::new(smooth_ccd2d::Ellipse::new(0.3, 0.7))),
            ),
        ]
    }

    #[test]
    fn bounding_volumes_round_outward_and_contain_the_boundary() {
        for (name, s) in shapes() {
            let (aabb, sphere) = (s.compute_local_aabb(), s.compute_local_bounding_sphere());
            for k in 0..360 {
                let dir = Vector::new((k as f32).to_radians().cos(), (k as f32).to_radians().sin());
                let p = own_f64(&*s)
                    .expect("ours")
                    .as_support_map()
                    .expect("support map")
                    .local_support_point(v64(dir));
                assert!(p.x >= aabb.mins.x as f64 && p.x <= aabb.maxs.x as f64, "{name}");
                assert!(p.y >= aabb.mins.y as f64 && p.y <= aabb.maxs.y as f64, "{name}");
                assert!((p - v64(sphere.center)).length() <= sphere.radius as f64, "{name}");
            }
        }
    }

    #[test]
    fn answers_are_the_f64_answers_rounded() {
        for (name, s) in shapes() {
            let wide = own_f64(&*s).expect("ours");
            let dir = Vector::new(0.3, -0.8);
            let p32 = s.as_support_map().expect("support map").local_support_point(dir);
            let p64 = wide
                .as_support_map()
                .expect("support map")
                .local_support_point(v64(dir));
            assert_eq!(p32, v32(p64), "{name}");
            let m32 = s.mass_properties(2.0);
            let m64 = wide.mass_properties(2.0);
            assert_eq!(m32.inv_mass, m64.inv_mass as f32, "{name}");
            assert_eq!(m32.inv_principal_inertia, m64.inv_principal_inertia as f32, "{name}");
            assert_eq!(m32.local_com, v32(m64.local_com), "{name}");
            assert!(s.ccd_thickness() as f64 <= wide.ccd_thickness(), "{name}");
            let pt = Vector::new(3.0, 1.0);
            let proj = s.project_local_point(pt, true);
            let proj64 = q64::PointQuery::project_local_point(wide, v64(pt), true);
            assert_eq!(proj.point, v32(proj64.point), "{name}");
            assert!(!proj.is_inside && s.contains_local_point(Vector::ZERO), "{name}");
            let ray = Ray::new(Vector::new(-5.0, 0.01), Vector::X);
            let hit = s
                .cast_local_ray_and_get_normal(&ray, 100.0, true)
                .expect("the ray hits");
            let hit64 = q64::RayCast::cast_local_ray_and_get_normal(
                wide,
                &q64::Ray::new(v64(ray.origin), v64(ray.dir)),
                100.0,
                true,
            )
            .expect("the ray hits");
            assert_eq!(hit.time_of_impact, hit64.time_of_impact as f32, "{name}");
            let mut f = PolygonalFeature::default();
            s.as_polygonal_feature_map()
                .expect("feature map")
                .0
                .local_support_feature(dir, &mut f);
            assert_eq!(f.num_vertices, 2, "{name}");
            let pose = Pose::new(Vector::new(1.0, 2.0), 0.3);
            let (b32, b64) = (s.compute_aabb(&pose), wide.compute_aabb(&pose64(&pose)));
            assert!(
                (b32.mins.x as f64) <= b64.mins.x && (b32.maxs.y as f64) >= b64.maxs.y,
                "{name}"
            );
        }
    }

    #[test]
    fn scaling_keeps_the_type_and_refusals_are_errors() {
        let e = Ellipse::new(0.5, 0.2);
        let scaled = e.scale_dyn(Vector::new(2.0, 3.0), 0).expect("an ellipse scales");
        let s = scaled.as_shape::<Ellipse>().expect("still an ellipse");
        assert_eq!((s.half_x(), s.half_y()), (1.0, 0.6));
        assert!(CustomCurve::new(smooth_ccd2d::Ellipse::new(1.0, 2.0))
            .scale_dyn(Vector::ONE, 0)
            .is_none());
        assert!(Ellipse::try_new(-1.0, 1.0).is_err());
        assert!(Ellipse::try_new(f32::NAN, 1.0).is_err());
        assert!(RoundedPolygon::try_new(&[Vector::ZERO, Vector::X], 0.1).is_err());
        assert!(CapsuleEllipse::try_new(0.5, 1.0, f32::INFINITY).is_err());
        assert_eq!(
            RoundedPolygon::regular(5, 1.0, 0.1).vertices()[0],
            Vector::new(1.0, 0.0)
        );
        assert_eq!(CapsuleEllipse::new(0.5, 1.0, 0.8).params(), (0.5, 1.0, 0.8));
    }
}
