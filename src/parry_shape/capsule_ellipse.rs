//! parry's traits for [`CapsuleEllipse`]: generic ray cast and projection, its segment as a
//! flat feature, exact mass.

use super::core::capsule_ellipse_core;
use super::features::curve_feature;
use super::mass::{capsule_ellipse_moments, mass_from_moments};
use super::projection::{project_on_curve, project_on_curve_with_feature};
use super::ray::piecewise_ray;
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

    /// In closed form: the segment at x = r1, the half-ellipse's tip at x = −r3, the arcs' tops
    /// at y = ±(r1 + r2). The same bits as the support points along ±x, ±y (`curve_aabb`; its
    /// evaluations took 2 % of a rapier pile step, where the broad phase asks for it every step).
    fn compute_local_aabb(&self) -> Aabb {
        let (r1, r2, r3) = self.params();
        let h = r1 + r2;
        Aabb::new(Vector::new(-r3, -h), Vector::new(r1, h))
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
        // The inradius about the centroid (module docs of `core`).
        let (r1, r2, r3) = self.params();
        capsule_ellipse_core(r1, r2, r3).radius
    }

    fn ccd_angular_thickness(&self) -> Real {
        FRAC_PI_2
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::test_rng::Lcg;
    use crate::parry_shape::curve_aabb;

    #[test]
    fn closed_form_box_is_the_support_points_box_bit_for_bit() {
        let mut rng = Lcg(7);
        for _ in 0..10_000 {
            let r1 = 10f64.powf(rng.range(-3.0, 3.0));
            let r2 = r1 * 10f64.powf(rng.range(-3.0, 5.9));
            let r3 = 10f64.powf(rng.range(-3.0, 3.0));
            let c = CapsuleEllipse::new(r1, r2, r3);
            let (a, b) = (c.compute_local_aabb(), curve_aabb(&c));
            assert_eq!((a.mins, a.maxs), (b.mins, b.maxs), "{:?}", c.params());
        }
    }
}
