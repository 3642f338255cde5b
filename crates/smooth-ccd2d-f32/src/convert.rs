//! The boundary between f32 and f64: inputs widen exactly, answers round once.
//!
//! Widening an `f32` to `f64` is exact, so every f32 input names one f64 input and the core
//! answers for exactly that input. The one exception is a rotation: an f32 unit complex number
//! (cos θ, sin θ) has a modulus within a few f32 ulps of 1, and the core reads it as the rotation
//! by its angle θ = atan2(sin, cos), i.e. normalised in f64 (a non-unit complex number would
//! scale the shape by up to 10⁻⁷).
//!
//! Answers round to nearest, except where the direction of rounding carries a guarantee:
//! bounding boxes and spheres round outward (they still contain the shape), thicknesses round
//! down (rapier's CCD thresholds stay conservative), and a time of impact rounds down (the
//! reported hit is never later than the f64 one; see [`time_down`]).

use crate::guard::AllFinite;
use parry2d::math::{Pose, Real, Vector};
use parry2d::query::{ClosestPoints, Contact, NonlinearRigidMotion, ShapeCastHit, ShapeCastOptions, ShapeCastStatus};
use parry2d::shape::{FeatureId, PackedFeatureId};
use parry2d_f64::math as m64;
use parry2d_f64::query as q64;
use parry2d_f64::shape as s64;

/// An f32 vector widened to f64 (exact).
#[inline]
pub(crate) fn v64(v: Vector) -> m64::Vector {
    m64::Vector::new(v.x as f64, v.y as f64)
}

/// An f64 vector rounded to f32 (to nearest).
#[inline]
pub(crate) fn v32(v: m64::Vector) -> Vector {
    Vector::new(v.x as f32, v.y as f32)
}

/// An f32 pose widened to f64, its rotation normalised in f64 (the rotation by the f32
/// rotation's angle). A zero or non-finite rotation stays as it is (the core refuses it).
#[inline]
pub(crate) fn pose64(p: &Pose) -> m64::Pose {
    let (re, im) = (p.rotation.re as f64, p.rotation.im as f64);
    let norm = re.hypot(im);
    let (re, im) = if norm > 0.0 && norm.is_finite() {
        (re / norm, im / norm)
    } else {
        (re, im)
    };
    m64::Pose::from_parts(v64(p.translation), m64::Rot2 { re, im })
}

/// An f32 rigid motion widened to f64.
#[inline]
pub(crate) fn motion64(m: &NonlinearRigidMotion) -> q64::NonlinearRigidMotion {
    q64::NonlinearRigidMotion::new(pose64(&m.start), v64(m.local_center), v64(m.linvel), m.angvel as f64)
}

/// The largest f32 not above `x` (rounding toward −∞); `x` itself when it is not finite.
#[inline]
pub(crate) fn down(x: f64) -> f32 {
    let y = x as f32;
    if (y as f64) > x {
        y.next_down()
    } else {
        y
    }
}

/// The smallest f32 not below `x` (rounding toward +∞); `x` itself when it is not finite.
#[inline]
pub(crate) fn up(x: f64) -> f32 {
    let y = x as f32;
    if (y as f64) < x {
        y.next_up()
    } else {
        y
    }
}

/// A time of impact `t` (f64) reported in the f32 window starting at `start`: rounded down, so
/// that the f32 hit is never later than the f64 one — except that it is never rounded down onto
/// `start` itself when `t` is after it (rapier discards hits at exactly the start of the window,
/// and the dispatcher's start-contact rule answers strictly after it): a `t` less than one f32
/// ulp after `start` is reported as the next f32 after `start`, at most one ulp late. Never
/// below `start`; NaN stays NaN (and is refused by the caller's finiteness check).
#[inline]
pub(crate) fn time_down(t: f64, start: Real) -> Real {
    if t.is_nan() {
        return f32::NAN;
    }
    let r = down(t).max(start);
    if r == start && t > start as f64 {
        start.next_up()
    } else {
        r
    }
}

/// A parry feature id carried across the boundary (the same number).
#[inline]
pub(crate) fn packed32(f: s64::PackedFeatureId) -> PackedFeatureId {
    PackedFeatureId(f.0)
}

/// A parry feature id carried across the boundary.
#[inline]
pub(crate) fn feature32(f: s64::FeatureId) -> FeatureId {
    match f {
        s64::FeatureId::Vertex(i) => FeatureId::Vertex(i),
        s64::FeatureId::Face(i) => FeatureId::Face(i),
        s64::FeatureId::Unknown => FeatureId::Unknown,
    }
}

/// A cast's options widened to f64.
#[inline]
pub(crate) fn cast_options64(o: &ShapeCastOptions) -> q64::ShapeCastOptions {
    q64::ShapeCastOptions {
        max_time_of_impact: o.max_time_of_impact as f64,
        target_distance: o.target_distance as f64,
        stop_at_penetration: o.stop_at_penetration,
        compute_impact_geometry_on_penetration: o.compute_impact_geometry_on_penetration,
    }
}

/// A cast status carried across the boundary.
#[inline]
pub(crate) fn status32(s: q64::ShapeCastStatus) -> ShapeCastStatus {
    match s {
        q64::ShapeCastStatus::OutOfIterations => ShapeCastStatus::OutOfIterations,
        q64::ShapeCastStatus::Converged => ShapeCastStatus::Converged,
        q64::ShapeCastStatus::Failed => ShapeCastStatus::Failed,
        q64::ShapeCastStatus::PenetratingOrWithinTargetDist => ShapeCastStatus::PenetratingOrWithinTargetDist,
    }
}

/// A cast's hit rounded to f32, its time by [`time_down`] in the window starting at `start`;
/// `None` when a rounded value is not finite (an f64 answer beyond f32's range).
pub(crate) fn hit32(h: &q64::ShapeCastHit, start: Real) -> Option<ShapeCastHit> {
    let hit = ShapeCastHit {
        time_of_impact: time_down(h.time_of_impact, start),
        witness1: v32(h.witness1),
        witness2: v32(h.witness2),
        normal1: v32(h.normal1),
        normal2: v32(h.normal2),
        status: status32(h.status),
        subshape1: h.subshape1,
        subshape2: h.subshape2,
    };
    hit.all_finite().then_some(hit)
}

/// A contact rounded to f32; `None` when a rounded value is not finite.
pub(crate) fn contact32(c: &q64::Contact) -> Option<Contact> {
    let c = Contact::new(
        v32(c.point1),
        v32(c.point2),
        v32(c.normal1),
        v32(c.normal2),
        c.dist as f32,
    );
    c.all_finite().then_some(c)
}

/// Closest points rounded to f32; `None` when a rounded point is not finite.
pub(crate) fn closest32(c: &q64::ClosestPoints) -> Option<ClosestPoints> {
    let c = match c {
        q64::ClosestPoints::Intersecting => ClosestPoints::Intersecting,
        q64::ClosestPoints::Disjoint => ClosestPoints::Disjoint,
        q64::ClosestPoints::WithinMargin(a, b) => ClosestPoints::WithinMargin(v32(*a), v32(*b)),
    };
    c.all_finite().then_some(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directed_rounding_brackets_the_f64_value() {
        for x in [0.1f64, -0.1, 1.0 / 3.0, 1e-30, -7.3e12, 2.0, 0.0] {
            let (d, u) = (down(x), up(x));
            assert!((d as f64) <= x && x <= (u as f64), "{x}");
            assert!(u == d || u == d.next_up(), "{x}");
        }
        assert_eq!(down(0.5), 0.5);
        assert_eq!(up(0.5), 0.5);
        assert!(down(f64::NAN).is_nan());
    }

    #[test]
    fn time_of_impact_never_rounds_onto_or_before_the_start() {
        let start = 0.25f32;
        assert_eq!(time_down(0.25, start), start);
        assert_eq!(time_down(0.25 + 1e-12, start), start.next_up());
        assert_eq!(time_down(0.2, start), start);
        let t = 0.3f64;
        assert!((time_down(t, start) as f64) <= t && time_down(t, start) == down(t));
        assert!(time_down(f64::NAN, start).is_nan());
    }

    #[test]
    fn pose_widens_to_a_unit_rotation_of_the_same_angle() {
        let p = Pose::new(Vector::new(1.5, -2.25), 0.7);
        let q = pose64(&p);
        assert!((q.rotation.re.hypot(q.rotation.im) - 1.0).abs() < 1e-15);
        let angle32 = (p.rotation.im as f64).atan2(p.rotation.re as f64);
        assert!((q.rotation.im.atan2(q.rotation.re) - angle32).abs() < 1e-15);
        assert_eq!(q.translation, m64::Vector::new(1.5, -2.25));
    }
}
