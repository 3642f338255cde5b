//! Angles: φ wrapped into [−π, π), unwrapped after a base, and the counter-clockwise angle
//! between two unit vectors.

use crate::numerics::math::{cross, Vector};
use core::f64::consts::PI;

/// Wraps φ into [−π, π).
#[inline]
pub fn wrap_phi(phi: f64) -> f64 {
    if (-PI..PI).contains(&phi) {
        phi
    } else {
        (phi + PI).rem_euclid(2.0 * PI) - PI
    }
}

/// Angle in [0, 2π) from unit vector `a` to unit vector `b`, counter-clockwise.
#[inline]
pub(crate) fn ccw_angle(a: Vector, b: Vector) -> f64 {
    let ang = cross(a, b).atan2(a.dot(b));
    if ang < 0.0 {
        ang + 2.0 * PI
    } else {
        ang
    }
}

/// `x + 2πk`, the representative of x in `[base, base + 2π)`; `base` for non-finite input.
///
/// From |base| ≈ 5.7e16 on, 2π is below half an ulp of `base` and `base + 2π == base`: no
/// representative may exist, and adding or taking 2π does not move a number. So the integer k
/// is computed once (its rounding may leave the sum up to a few ulps of `base` outside the
/// interval; the product is taken for x beyond the interval on either side), corrected by at
/// most [`UNWRAP_CORRECTIONS`] steps of 2π each way, and the result
/// is clamped to `base` from below: never a loop whose progress depends on the magnitude of the
/// input.
#[inline]
pub(crate) fn unwrap_after(base: f64, x: f64) -> f64 {
    let mut y = x;
    if !(y.is_finite() && base.is_finite()) {
        return base;
    }
    let k = ((base - y) / (2.0 * PI)).ceil();
    if k != 0.0 {
        y += k * 2.0 * PI;
    }
    for _ in 0..UNWRAP_CORRECTIONS {
        if y >= base {
            break;
        }
        y += 2.0 * PI;
    }
    for _ in 0..UNWRAP_CORRECTIONS {
        if y < base + 2.0 * PI {
            break;
        }
        y -= 2.0 * PI;
    }
    y.max(base)
}

/// Steps of 2π [`unwrap_after`] takes each way after its one multiplication: rounding leaves
/// the product at most one step off while 2π is above an ulp of the numbers (and no step moves
/// them beyond).
const UNWRAP_CORRECTIONS: usize = 4;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_phi_maps_into_half_open_circle() {
        assert_eq!(wrap_phi(0.5), 0.5);
        assert!((wrap_phi(PI) + PI).abs() < 1e-15);
        assert!((wrap_phi(3.0 * PI + 0.25) - (-PI + 0.25)).abs() < 1e-12);
        assert!((wrap_phi(-PI - 0.25) - (PI - 0.25)).abs() < 1e-12);
    }

    #[test]
    fn ccw_angle_is_in_zero_two_pi() {
        let a = Vector::new(1.0, 0.0);
        assert!((ccw_angle(a, Vector::new(0.0, 1.0)) - PI / 2.0).abs() < 1e-15);
        assert!((ccw_angle(a, Vector::new(0.0, -1.0)) - 1.5 * PI).abs() < 1e-15);
    }

    #[test]
    fn unwrap_after_handles_the_wrap() {
        assert!((unwrap_after(3.0, -3.0) - (2.0 * PI - 3.0)).abs() < 1e-15);
        assert_eq!(unwrap_after(-1.0, 0.5), 0.5);
        assert!((unwrap_after(0.0, 100.0) - (100.0 - 15.0 * 2.0 * PI)).abs() < 1e-12);
        assert_eq!(unwrap_after(0.0, f64::NAN), 0.0);
    }

    /// From |base| ≈ 5.7e16 on `base + 2π == base`: the loops that added or took 2π until the
    /// number was in range never ended there (issue 32, item 2). Now a bounded number of steps,
    /// and the answer is never below `base`.
    #[test]
    fn unwrap_after_ends_for_bases_beyond_the_resolution_of_two_pi() {
        for base in [5.7e16, 1e17 + 0.3, -1e17, 1e300, -1e300, f64::MAX, -f64::MAX] {
            for x in [0.1, -3.0, 3.1, 1e17, -1e18] {
                let y = unwrap_after(base, x);
                assert!(y.is_finite() && y >= base, "unwrap_after({base}, {x}) = {y}");
            }
        }
        // Ordinary numbers keep their exact answers.
        assert_eq!(unwrap_after(-1.0, 0.5), 0.5);
        assert_eq!(unwrap_after(3.0, -3.0), -3.0 + 2.0 * PI);
    }
}
