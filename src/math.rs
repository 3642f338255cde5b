//! Small vector helpers over parry's glam types.

pub use parry2d_f64::math::{Pose, Real, Rotation, Vector};

/// 2D cross product `a × b = a_x b_y − a_y b_x`.
#[inline]
pub fn cross(a: Vector, b: Vector) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Counter-clockwise perpendicular `(−v_y, v_x)`.
#[inline]
pub fn perp(v: Vector) -> Vector {
    Vector::new(-v.y, v.x)
}

/// The unit vector at angle `a`.
#[inline]
pub fn unit(a: f64) -> Vector {
    let (s, c) = a.sin_cos();
    Vector::new(c, s)
}

/// Rotates `v` by the rotation whose cosine and sine are `c`, `s`.
#[inline]
pub fn rotate_cs(c: f64, s: f64, v: Vector) -> Vector {
    Vector::new(c * v.x - s * v.y, s * v.x + c * v.y)
}
