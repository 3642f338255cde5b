//! parry's traits for [`CapsuleEllipse`]: generic ray cast and projection, its segment as a
//! flat feature, exact mass.

use super::features::curve_feature;
use super::mass::{capsule_ellipse_moments, mass_from_moments};
use super::projection::{project_on_curve, project_on_curve_with_feature};
use super::ray::piecewise_ray;
use super::{aabb_ccd_thickness, curve_aabb};
use crate::curve::ConvexCurve;
use crate::custom_shape_common;
use crate::numerics::math::unit_or_x;
use crate::numerics::math::{Real, Vector};
use crate::CapsuleEllipse;
use core::f64::consts::FRAC_PI_2;
use parry2d_f64::bounding_volume::{Aabb, BoundingSphere};
use parry2d_f64::mass_properties::MassProperties;
use parry2d_f64::query::{PointProjection, PointQuery, Ray, RayCast, RayIntersection};
use parry2d_f64::shape::{FeatureId, PolygonalFeature, PolygonalFeatureMap, Shape, ShapeType, SupportMap, TypedShape};

impl SupportMap for CapsuleEllipse {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        ConvexCurve::support_point(self, unit_or_x(dir))
    }
}

impl PolygonalFeatureMap for CapsuleEllipse {
    fn local_support_feature(&self, dir: Vector, out_feature: &mut PolygonalFeature) {
        curve_feature(self, self.flats(), dir, out_feature);
    }
}

impl RayCast for CapsuleEllipse {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        piecewise_ray(self, ray, max_time_of_impact, solid)
    }
}

impl PointQuery for CapsuleEllipse {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        project_on_curve(self, pt, solid)
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        project_on_curve_with_feature(self, pt)
    }
}

impl Shape for CapsuleEllipse {
    custom_shape_common!();

    fn compute_local_aabb(&self) -> Aabb {
        curve_aabb(self)
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::new(Vector::ZERO, self.bounding_radius())
    }

    fn scale_dyn(&self, scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        // Symmetric about the x axis only: a mirror in y is fine, one in x is not.
        if !(scale.x > 0.0 && scale.x.is_finite() && scale.y.abs() == scale.x) {
            return None;
        }
        let (r1, r2, r3) = self.params();
        let s = scale.x;
        Some(Box::new(CapsuleEllipse::try_new(r1 * s, r2 * s, r3 * s).ok()?))
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        let (r1, r2, r3) = self.params();
        mass_from_moments(density, capsule_ellipse_moments(r1, r2, r3))
    }

    fn ccd_thickness(&self) -> Real {
        aabb_ccd_thickness(&self.compute_local_aabb())
    }

    fn ccd_angular_thickness(&self) -> Real {
        FRAC_PI_2
    }
}
