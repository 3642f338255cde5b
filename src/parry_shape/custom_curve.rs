//! parry's traits for [`CustomCurve`], generically from the wrapped curve.

use super::core::Core;
use super::features::curve_feature;
use super::mass::mass_from_moments;
use super::projection::{project_on_curve, project_on_curve_with_feature};
use super::ray::piecewise_ray;
use super::{aabb_ccd_thickness, curve_aabb};
use crate::custom_shape_common;
use crate::numerics::math::unit_or_x;
use crate::numerics::math::{Real, Vector};
use crate::CustomCurve;
use core::f64::consts::FRAC_PI_4;
use parry2d_f64::bounding_volume::{Aabb, BoundingSphere};
use parry2d_f64::mass_properties::MassProperties;
use parry2d_f64::query::{PointProjection, PointQuery, Ray, RayCast, RayIntersection};
use parry2d_f64::shape::{FeatureId, PolygonalFeature, PolygonalFeatureMap, Shape, ShapeType, SupportMap, TypedShape};

impl SupportMap for CustomCurve {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        self.curve().support_point(unit_or_x(dir))
    }
}

impl PolygonalFeatureMap for CustomCurve {
    fn local_support_feature(&self, dir: Vector, out_feature: &mut PolygonalFeature) {
        curve_feature(self.curve(), self.flats(), dir, out_feature);
    }
}

impl RayCast for CustomCurve {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        piecewise_ray(self.curve(), ray, max_time_of_impact, solid)
    }
}

impl PointQuery for CustomCurve {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        project_on_curve(self.curve(), pt, solid)
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        project_on_curve_with_feature(self.curve(), pt)
    }
}

impl Shape for CustomCurve {
    custom_shape_common!();

    fn compute_local_aabb(&self) -> Aabb {
        curve_aabb(self.curve())
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::new(Vector::ZERO, self.curve().bounding_radius())
    }

    fn scale_dyn(&self, _scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        None
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        mass_from_moments(density, self.moments())
    }

    fn ccd_thickness(&self) -> Real {
        // The inradius about the centroid (module docs of `core`): the distance from the
        // centroid to the curve, by projection, computed when the curve was wrapped
        // ([`curve_core`]; the box's half-width where that fails).
        match self.core() {
            Some(core) => core.radius,
            None => aabb_ccd_thickness(&self.compute_local_aabb()),
        }
    }

    fn ccd_angular_thickness(&self) -> Real {
        FRAC_PI_4
    }
}

/// The core of a wrapped curve: its centroid, and the distance from it to the curve by point
/// projection; `None` where the centroid does not project inside at a finite positive distance.
pub(crate) fn curve_core(c: &CustomCurve) -> Option<Core> {
    let centre = c.mass_properties(1.0).local_com;
    let p = c.project_local_point(centre, false);
    let d = (p.point - centre).length();
    (p.is_inside && d.is_finite() && d > 0.0 && centre.is_finite()).then_some(Core { centre, radius: d })
}
