//! Composite shapes (compound, polyline, trimesh, heightfield) on either side of a query:
//! parry's composite helpers, called with [`SmoothDispatcher`] as the inner dispatcher so that
//! every sub-pair comes back to it.

use super::SmoothDispatcher;
use crate::numerics::math::{Pose, Real, Vector};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{
    self, ClosestPoints, Contact, NonlinearRigidMotion, ShapeCastHit, ShapeDistance, ShapeIntersection, Unsupported,
};
use parry2d_f64::shape::Shape;

pub(crate) fn composite_intersection(
    d: &SmoothDispatcher,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
) -> Result<ShapeIntersection, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::intersection_test_composite_shape_shape(
            d, pos12, c1, g2,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::intersection_test_shape_composite_shape(
            d, pos12, g1, c2,
        ))
    } else {
        Err(Unsupported)
    }
}

pub(crate) fn composite_distance(
    d: &SmoothDispatcher,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
) -> Result<ShapeDistance, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::distance_composite_shape_shape(d, pos12, c1, g2))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::distance_shape_composite_shape(d, pos12, g1, c2))
    } else {
        Err(Unsupported)
    }
}

pub(crate) fn composite_contact(
    d: &SmoothDispatcher,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    prediction: Real,
) -> Result<Option<Contact>, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::contact_composite_shape_shape(
            d, pos12, c1, g2, prediction,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::contact_shape_composite_shape(
            d, pos12, g1, c2, prediction,
        ))
    } else {
        Err(Unsupported)
    }
}

pub(crate) fn composite_closest_points(
    d: &SmoothDispatcher,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    max_dist: Real,
) -> Result<ClosestPoints, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::closest_points_composite_shape_shape(
            d, pos12, c1, g2, max_dist,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::closest_points_shape_composite_shape(
            d, pos12, g1, c2, max_dist,
        ))
    } else {
        Err(Unsupported)
    }
}

pub(crate) fn composite_cast(
    d: &SmoothDispatcher,
    pos12: &Pose,
    vel12: Vector,
    g1: &dyn Shape,
    g2: &dyn Shape,
    options: ShapeCastOptions,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::cast_shapes_composite_shape_shape(
            d, pos12, vel12, c1, g2, options,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::cast_shapes_shape_composite_shape(
            d, pos12, vel12, g1, c2, options,
        ))
    } else {
        Err(Unsupported)
    }
}

#[allow(clippy::too_many_arguments)]
pub(crate) fn composite_cast_nonlinear(
    d: &SmoothDispatcher,
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
    stop: bool,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::cast_shapes_nonlinear_composite_shape_shape(
            d, m1, c1, m2, g2, t0, t1, stop,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::cast_shapes_nonlinear_shape_composite_shape(
            d, m1, g1, m2, c2, t0, t1, stop,
        ))
    } else {
        Err(Unsupported)
    }
}
