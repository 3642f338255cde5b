//! parry's traits for [`Ellipse`]: closed-form ray cast, Eberly's projection, exact mass.

use super::features::tangent_feature;
use super::projection::ellipse_closest_point;
use crate::curve::ConvexCurve;
use crate::custom_shape_common;
use crate::numerics::math::unit_or_x;
use crate::numerics::math::{Pose, Real, Vector};
use crate::Ellipse;
use core::f64::consts::{FRAC_PI_2, PI};
use parry2d_f64::bounding_volume::{Aabb, BoundingSphere};
use parry2d_f64::mass_properties::MassProperties;
use parry2d_f64::query::{PointProjection, PointQuery, Ray, RayCast, RayIntersection};
use parry2d_f64::shape::{FeatureId, PolygonalFeature, PolygonalFeatureMap, Shape, ShapeType, SupportMap, TypedShape};

impl Ellipse {
    /// Outward unit normal at a boundary point `p` (the normalised gradient of x²/a² + y²/b²).
    pub(crate) fn normal_at_point(&self, p: Vector) -> Vector {
        let (a, b) = (self.half_x(), self.half_y());
        unit_or_x(Vector::new(p.x / (a * a), p.y / (b * b)))
    }

    fn contains(&self, p: Vector) -> bool {
        let (u, v) = (p.x / self.half_x(), p.y / self.half_y());
        u * u + v * v <= 1.0
    }
}

impl SupportMap for Ellipse {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        self.point_with_normal(unit_or_x(dir))
    }
}

impl PolygonalFeatureMap for Ellipse {
    fn local_support_feature(&self, dir: Vector, out_feature: &mut PolygonalFeature) {
        let n = unit_or_x(dir);
        let (a2, b2) = (self.half_x() * self.half_x(), self.half_y() * self.half_y());
        let h = (a2 * n.x * n.x + b2 * n.y * n.y).sqrt();
        let p = Vector::new(a2 * n.x, b2 * n.y) / h;
        let rho = a2 * b2 / (h * h * h);
        tangent_feature(p, n, rho, self.half_x().max(self.half_y()), out_feature);
    }
}

impl RayCast for Ellipse {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        let (a, b) = (self.half_x(), self.half_y());
        let (o, d) = (ray.origin, ray.dir);
        if !(o.is_finite() && d.is_finite()) || max_time_of_impact.is_nan() {
            return None;
        }
        let o2 = Vector::new(o.x / a, o.y / b);
        let d2 = Vector::new(d.x / a, d.y / b);
        let cc = (o2.length() - 1.0) * (o2.length() + 1.0);
        let inside = cc <= 0.0;
        if d.x == 0.0 && d.y == 0.0 {
            if !inside || max_time_of_impact < 0.0 {
                return None;
            }
            let p = ellipse_closest_point(a, b, o);
            return Some(RayIntersection::new(0.0, -self.normal_at_point(p), FeatureId::Face(0)));
        }
        // Scale the quadratic to avoid under/overflow for tiny or huge directions.
        let scale = d2.x.abs().max(d2.y.abs());
        let d2s = d2 / scale;
        let aa = d2s.length_squared();
        let bb = o2.dot(d2s);
        if !inside && bb >= 0.0 {
            return None;
        }
        let disc = bb * bb - aa * cc;
        if disc < 0.0 {
            return None;
        }
        let sq = disc.sqrt();
        let q = -(bb + sq.copysign(bb));
        let (r1, r2) = if q == 0.0 { (0.0, 0.0) } else { (q / aa, cc / q) };
        let (t_in, t_out) = (r1.min(r2) / scale, r1.max(r2) / scale);
        let hit = if !inside {
            let p = o + d * t_in;
            (t_in, self.normal_at_point(p))
        } else if solid {
            (0.0, -unit_or_x(d))
        } else {
            let p = o + d * t_out;
            (t_out, -self.normal_at_point(p))
        };
        (hit.0 <= max_time_of_impact && hit.0.is_finite())
            .then(|| RayIntersection::new(hit.0.max(0.0), hit.1, FeatureId::Face(0)))
    }
}

impl PointQuery for Ellipse {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        if !pt.is_finite() {
            return PointProjection::new(false, Vector::new(self.half_x(), 0.0));
        }
        // A point beyond 1e50 sizes (where Eberly's scaled coordinates overflow): its closest
        // point is the one whose normal points at it, to within 1e-50 of the size.
        if pt.x.abs().max(pt.y.abs()) > 1e50 * self.half_x().max(self.half_y()) {
            return PointProjection::new(false, self.point_with_normal(unit_or_x(pt)));
        }
        let inside = self.contains(pt);
        if inside && solid {
            return PointProjection::new(true, pt);
        }
        PointProjection::new(inside, ellipse_closest_point(self.half_x(), self.half_y(), pt))
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        (self.project_local_point(pt, false), FeatureId::Face(0))
    }

    fn contains_local_point(&self, pt: Vector) -> bool {
        self.contains(pt)
    }
}

impl Shape for Ellipse {
    custom_shape_common!();

    fn compute_local_aabb(&self) -> Aabb {
        let h = Vector::new(self.half_x(), self.half_y());
        Aabb::new(-h, h)
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::new(Vector::ZERO, self.bounding_radius())
    }

    /// The tight box of the posed ellipse: half-widths √(a²c² + b²s²) and √(a²s² + b²c²) for the
    /// rotation (c, s) (parry's default transforms the local box, up to √2 wider per axis, which
    /// gives rapier's broad phase pairs that cannot touch). The square roots are taken as they
    /// stand, not by `hypot` (glibc's is several times slower, and rapier asks for this box
    /// of every ellipse at every step): the semi-axes lie within the accepted length range and
    /// a pose's (c, s) is a unit complex number, so the sum of the squares cannot overflow, and
    /// its larger term cannot underflow (at most one ulp from `hypot`); a pose that makes it
    /// overflow (not a rotation) takes `hypot`.
    fn compute_aabb(&self, position: &Pose) -> Aabb {
        let (a, b) = (self.half_x(), self.half_y());
        let (c, s) = (position.rotation.re, position.rotation.im);
        let root = |x: Real, y: Real| {
            let r = (x * x + y * y).sqrt();
            if r.is_finite() {
                r
            } else {
                x.hypot(y)
            }
        };
        let h = Vector::new(root(a * c, b * s), root(a * s, b * c));
        let t = position.translation;
        Aabb::new(t - h, t + h)
    }

    fn scale_dyn(&self, scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        let e = Ellipse::try_new(self.half_x() * scale.x.abs(), self.half_y() * scale.y.abs()).ok()?;
        Some(Box::new(e))
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        let (a, b) = (self.half_x(), self.half_y());
        let mass = density * PI * a * b;
        MassProperties::new(Vector::ZERO, mass, mass * (a * a + b * b) / 4.0)
    }

    fn ccd_thickness(&self) -> Real {
        self.half_x().min(self.half_y())
    }

    fn ccd_angular_thickness(&self) -> Real {
        if self.half_x() == self.half_y() {
            PI
        } else {
            FRAC_PI_2
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use parry2d_f64::math::Rotation;

    /// The half-widths `hypot` would give, for comparison.
    fn hypot_half_widths(a: f64, b: f64, c: f64, s: f64) -> Vector {
        Vector::new((a * c).hypot(b * s), (a * s).hypot(b * c))
    }

    #[test]
    fn posed_box_is_within_one_ulp_of_hypot_for_rotations() {
        let e = Ellipse::new(0.5, 0.2);
        for k in 0..64 {
            let angle = 0.1 * k as f64;
            let pose = Pose::new(Vector::new(1.0, -2.0), angle);
            let h = e.compute_aabb(&pose).half_extents();
            let (c, s) = (pose.rotation.re, pose.rotation.im);
            let want = hypot_half_widths(0.5, 0.2, c, s);
            for (got, want) in [(h.x, want.x), (h.y, want.y)] {
                // Half extents come back through (max − min)/2 about the translation: a few ulps
                // of the translation on top of the half-width's own.
                assert!(
                    (got - want).abs() <= 8.0 * f64::EPSILON * 3.0,
                    "angle {angle}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn posed_box_of_a_pose_that_is_not_a_rotation_takes_hypot_where_squares_overflow() {
        // Components of 1e200 (not a unit complex number): a·c squared overflows; `hypot` does not.
        let e = Ellipse::new(1e50, 1.0);
        let pose = Pose::from_parts(Vector::ZERO, Rotation::from_cos_sin_unchecked(1e200, 1e200));
        let aabb = e.compute_aabb(&pose);
        let want = hypot_half_widths(1e50, 1.0, 1e200, 1e200);
        assert!(want.is_finite(), "the reference is finite");
        assert_eq!(aabb.maxs, want);
        assert_eq!(aabb.mins, -want);
    }
}
