//! The time of impact of two parry2d (f32) shapes on rigid motions, answered in f64.

use crate::convert::motion64;
use crate::widen::widen;
use parry2d::math::Real;
use parry2d::query::NonlinearRigidMotion;
use parry2d::shape::Shape;
use smooth_ccd2d::{QueryError, TimeOfImpact, ToiOptions};

/// [`smooth_ccd2d::shape_time_of_impact`] for f32 shapes and motions: the inputs widened to f64
/// (exactly; rotations read as their angle), the answer left in f64 — the exact time of impact
/// of the f32 inputs, with its status and cost. The dispatcher's `cast_shapes_nonlinear` reports
/// `time` rounded down to f32.
///
/// ```
/// use parry2d::math::{Pose, Vector};
/// use parry2d::query::NonlinearRigidMotion;
/// use parry2d::shape::Cuboid;
/// use smooth_ccd2d_f32::{shape_time_of_impact, RoundedPolygon, ToiOptions, ToiStatus};
///
/// let hept = RoundedPolygon::regular(7, 0.5, 0.05);
/// let wall = Cuboid::new(Vector::new(0.05, 2.0));
/// let m1 = NonlinearRigidMotion::new(Pose::translation(-2.0, 0.0), Vector::ZERO, Vector::new(10.0, 0.0), 30.0);
/// let m2 = NonlinearRigidMotion::identity();
/// let r = shape_time_of_impact(&hept, &m1, &wall, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
/// assert_eq!(r.status, ToiStatus::Hit);
/// assert!(r.time > 0.13 && r.time < 0.15);
/// ```
///
/// # Errors
/// [`QueryError::UnsupportedShape`] for a shape the core does not take (composites, voxels, a
/// user's own parry shape); otherwise the errors of [`smooth_ccd2d::shape_time_of_impact`].
pub fn shape_time_of_impact(
    shape1: &dyn Shape,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn Shape,
    motion2: &NonlinearRigidMotion,
    start_time: Real,
    end_time: Real,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    let (a, b) = match (widen(shape1), widen(shape2)) {
        (Some(a), Some(b)) => (a, b),
        _ => return Err(QueryError::UnsupportedShape),
    };
    smooth_ccd2d::shape_time_of_impact(
        a.get(),
        &motion64(motion1),
        b.get(),
        &motion64(motion2),
        start_time as f64,
        end_time as f64,
        options,
    )
}
