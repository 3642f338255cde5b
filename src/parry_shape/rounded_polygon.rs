//! parry's traits for [`RoundedPolygon`]: exact projection (the core polygon's signed distance
//! minus the radius), parry's `RoundConvexPolygon` features, exact mass.

use super::mass::{mass_from_moments, rounded_polygon_moments};
use super::ray::curve_ray;
use super::{face_id, vertex_id};
use crate::curve::pieces::piece_index;
use crate::curve::ConvexCurve;
use crate::custom_shape_common;
use crate::numerics::math::unit_or_x;
use crate::numerics::math::{Pose, Real, Vector};
use crate::RoundedPolygon;
use core::f64::consts::FRAC_PI_4;
use parry2d_f64::bounding_volume::{Aabb, BoundingSphere};
use parry2d_f64::mass_properties::MassProperties;
use parry2d_f64::query::{PointProjection, PointQuery, Ray, RayCast, RayIntersection};
use parry2d_f64::shape::{FeatureId, PolygonalFeature, PolygonalFeatureMap, Shape, ShapeType, SupportMap, TypedShape};

impl RoundedPolygon {
    /// Exact closest boundary point, its outward normal and feature (vertex i: corner arc i;
    /// face i: edge i), and whether `x` is inside.
    fn project_exact(&self, x: Vector) -> (Vector, Vector, FeatureId, bool) {
        let v = self.vertices();
        let e = self.edge_normals();
        let r = self.corner_radius();
        let n = v.len();
        // Largest signed distance to an edge line.
        let (mut imax, mut smax) = (0usize, f64::NEG_INFINITY);
        for i in 0..n {
            let s = (x - v[i]).dot(e[i]);
            if s > smax {
                smax = s;
                imax = i;
            }
        }
        if smax <= 0.0 {
            // Inside the core (or on its boundary): the nearest edge line.
            let p = x + e[imax] * (r - smax);
            return (p, e[imax], FeatureId::Face(imax as u32), true);
        }
        // Outside the core: the closest point of the core's boundary.
        let (mut best_d2, mut best_q, mut best_f) = (f64::INFINITY, v[0], FeatureId::Vertex(0));
        for i in 0..n {
            let (a, b) = (v[i], v[(i + 1) % n]);
            let ab = b - a;
            let t = ((x - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
            let (q, f) = if t <= 0.0 {
                (a, FeatureId::Vertex(i as u32))
            } else if t >= 1.0 {
                (b, FeatureId::Vertex(((i + 1) % n) as u32))
            } else {
                (a + ab * t, FeatureId::Face(i as u32))
            };
            let d2 = (x - q).length_squared();
            if d2 < best_d2 {
                best_d2 = d2;
                best_q = q;
                best_f = f;
            }
        }
        let dist = best_d2.sqrt();
        let nrm = match best_f {
            FeatureId::Face(i) => e[i as usize],
            _ => {
                if dist > 0.0 {
                    (x - best_q) / dist
                } else {
                    e[imax]
                }
            }
        };
        (best_q + nrm * r, nrm, best_f, dist <= r)
    }

    fn feature_of_phi(&self, phi: f64) -> FeatureId {
        let k = piece_index(self.breakpoints(), phi);
        if k.is_multiple_of(2) {
            FeatureId::Vertex((k / 2) as u32)
        } else {
            FeatureId::Face((k / 2) as u32)
        }
    }
}

impl SupportMap for RoundedPolygon {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        ConvexCurve::support_point(self, unit_or_x(dir))
    }
}

impl PolygonalFeatureMap for RoundedPolygon {
    fn local_support_feature(&self, dir: Vector, out_feature: &mut PolygonalFeature) {
        let n_hat = unit_or_x(dir);
        let v = self.vertices();
        let e = self.edge_normals();
        let n = v.len();
        let mut best = 0usize;
        let mut best_dot = f64::NEG_INFINITY;
        for (i, ei) in e.iter().enumerate() {
            let d = ei.dot(n_hat);
            if d > best_dot {
                best_dot = d;
                best = i;
            }
        }
        let shift = n_hat * self.corner_radius();
        let j = (best + 1) % n.max(1);
        *out_feature = PolygonalFeature {
            vertices: [v[best] + shift, v[j] + shift],
            vids: [vertex_id(2 * best as u32), vertex_id(2 * j as u32)],
            fid: face_id(2 * best as u32 + 1),
            num_vertices: 2,
        };
    }
}

impl RayCast for RoundedPolygon {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        if ray.dir.x == 0.0 && ray.dir.y == 0.0 {
            if !ray.origin.is_finite() || max_time_of_impact < 0.0 || max_time_of_impact.is_nan() {
                return None;
            }
            let (_, nrm, f, inside) = self.project_exact(ray.origin);
            return inside.then(|| RayIntersection::new(0.0, -nrm, f));
        }
        let hit = curve_ray(self, ray, max_time_of_impact, solid)?;
        Some(RayIntersection::new(hit.toi, hit.normal, self.feature_of_phi(hit.phi)))
    }
}

impl PointQuery for RoundedPolygon {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        if !pt.is_finite() {
            return PointProjection::new(false, ConvexCurve::support_point(self, Vector::X));
        }
        let (p, _, _, inside) = self.project_exact(pt);
        if inside && solid {
            PointProjection::new(true, pt)
        } else {
            PointProjection::new(inside, p)
        }
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        if !pt.is_finite() {
            let p = ConvexCurve::support_point(self, Vector::X);
            return (PointProjection::new(false, p), FeatureId::Unknown);
        }
        let (p, _, f, inside) = self.project_exact(pt);
        (PointProjection::new(inside, p), f)
    }
}

impl Shape for RoundedPolygon {
    custom_shape_common!();

    fn compute_local_aabb(&self) -> Aabb {
        let v = self.vertices();
        let (mut lo, mut hi) = (v[0], v[0]);
        for p in v {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        let r = Vector::splat(self.corner_radius());
        Aabb::new(lo - r, hi + r)
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::new(Vector::ZERO, self.bounding_radius())
    }

    /// The tight box of the posed shape: the posed core vertices' box grown by the radius (as
    /// parry's `RoundConvexPolygon`; the default transforms the local box, up to √2 wider).
    fn compute_aabb(&self, position: &Pose) -> Aabb {
        let v = self.vertices();
        let first = position.transform_point(v[0]);
        let (mut lo, mut hi) = (first, first);
        for p in &v[1..] {
            let q = position.transform_point(*p);
            lo = lo.min(q);
            hi = hi.max(q);
        }
        let r = Vector::splat(self.corner_radius());
        Aabb::new(lo - r, hi + r)
    }

    fn scale_dyn(&self, scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        if !scale.is_finite() || scale.x == 0.0 || scale.y == 0.0 {
            return None;
        }
        let uniform = scale.x.abs() == scale.y.abs();
        let r = self.corner_radius();
        if !uniform && r != 0.0 {
            return None;
        }
        let mut v: Vec<Vector> = self.vertices().iter().map(|p| *p * scale).collect();
        if scale.x * scale.y < 0.0 {
            // A mirror reverses the orientation.
            v.reverse();
        }
        let r = if uniform { r * scale.x.abs() } else { 0.0 };
        let p = RoundedPolygon::try_new(&v, r).ok()?;
        Some(Box::new(p))
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        let m = rounded_polygon_moments(self.vertices(), self.edge_normals(), self.corner_radius());
        mass_from_moments(density, m)
    }

    fn ccd_thickness(&self) -> Real {
        // The inradius about the centroid (module docs of `core`): a thin polygon turned off its
        // axes is thinner than its box says.
        // Stored when the polygon was built (`RoundedPolygon::core`).
        self.core().map_or(0.0, |c| c.radius)
    }

    fn ccd_angular_thickness(&self) -> Real {
        FRAC_PI_4
    }
}
