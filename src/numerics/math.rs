//! Small vector helpers over parry's glam types.

pub use parry2d_f64::math::{Pose, Real, Vector};

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

/// (sin a, cos a) by the `libm` crate's port of FreeBSD's `sincos` (error below 1 ulp, as
/// the standard library's). Every evaluation of a curve and every new time of a query takes one
/// or two of these; this one took 4–5 % less time per time of impact than `f64::sin_cos` (glibc)
/// at the ellipse medians (`cargo bench --bench ratios`). `libm` is already a dependency of
/// parry's (through glam and num-traits).
#[inline]
pub fn sin_cos(a: f64) -> (f64, f64) {
    libm::sincos(a)
}

/// The unit vector at angle `a`.
#[inline]
pub fn unit(a: f64) -> Vector {
    let (s, c) = sin_cos(a);
    Vector::new(c, s)
}

/// Rotates `v` by the rotation whose cosine and sine are `c`, `s`.
#[inline]
pub fn rotate_cs(c: f64, s: f64, v: Vector) -> Vector {
    Vector::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// `d` normalised; +x for a zero, non-finite or NaN vector. Robust to under/overflow.
#[inline]
pub(crate) fn unit_or_x(d: Vector) -> Vector {
    if !d.is_finite() {
        return Vector::X;
    }
    let m = d.x.abs().max(d.y.abs());
    if m == 0.0 {
        return Vector::X;
    }
    let s = d / m;
    s / s.length()
}

/// `d / |d|` as glam's `normalize` computes it when |d| is a normal number, otherwise
/// [`unit_or_x`]: a direction between points up to about 1e154 apart keeps its bits, and one
/// between points farther apart (|d|² overflows, `normalize` gives 0) or nearer (it underflows)
/// is still a unit vector (issue 32: an axis of 0 made shapes 1e155 apart touch).
#[inline]
pub(crate) fn direction(d: Vector) -> Vector {
    if d.length().is_normal() {
        d.normalize()
    } else {
        unit_or_x(d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_or_x_survives_tiny_huge_and_bad_vectors() {
        assert_eq!(unit_or_x(Vector::ZERO), Vector::X);
        assert_eq!(unit_or_x(Vector::new(f64::NAN, 1.0)), Vector::X);
        assert_eq!(unit_or_x(Vector::new(f64::INFINITY, 1.0)), Vector::X);
        let t = unit_or_x(Vector::new(3e-320, 4e-320));
        assert!((t - Vector::new(0.6, 0.8)).length() < 1e-3);
        let h = unit_or_x(Vector::new(3e307, 4e307));
        assert!((h - Vector::new(0.6, 0.8)).length() < 1e-15);
        assert!((unit_or_x(unit(0.3) * 7.0) - unit(0.3)).length() < 1e-15);
    }

    #[test]
    fn direction_is_normalize_in_range_and_unit_beyond() {
        let v = Vector::new(0.3, -2.7);
        assert_eq!(direction(v), v.normalize());
        for s in [1e-200, 1e155, 1e300] {
            let u = direction(Vector::new(3.0, 4.0) * s);
            assert!((u - Vector::new(0.6, 0.8)).length() < 1e-15, "{s}: {u}");
        }
        assert_eq!(direction(Vector::ZERO), Vector::X);
    }
}
