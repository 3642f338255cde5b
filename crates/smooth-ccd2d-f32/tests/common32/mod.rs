//! Scenarios of the workspace's f64 tests (`tests/common`) rounded to f32: the f32 shapes and
//! motions, and the f64 scenario the f32 package reads them as. Shared by path by the f32
//! package's tests and benchmarks; the including file must also include `tests/common` as
//! `common` (at its root).
#![allow(dead_code)]

use crate::common::{Scenario, TestShape};
use parry2d::math::{Pose as Pose32, Rot2, Vector as V32};
use parry2d::query::NonlinearRigidMotion as Motion32;
use parry2d::shape::Shape as Shape32;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use smooth_ccd2d::BallCurve;
use smooth_ccd2d_f32::{CapsuleEllipse, Ellipse, RoundedPolygon};

/// The unit roundoff of f32 (half an ulp of 1).
pub const U32: f64 = f32::EPSILON as f64 / 2.0;

pub fn v32(v: Vector) -> V32 {
    V32::new(v.x as f32, v.y as f32)
}

pub fn v64(v: V32) -> Vector {
    Vector::new(v.x as f64, v.y as f64)
}

/// An f64 pose rounded to f32 (translation and rotation components to nearest).
pub fn pose32(p: &Pose) -> Pose32 {
    Pose32::from_parts(
        v32(p.translation),
        Rot2 {
            re: p.rotation.re as f32,
            im: p.rotation.im as f32,
        },
    )
}

/// An f32 pose as the f32 package reads it: widened, its rotation normalised in f64.
pub fn pose64(p: &Pose32) -> Pose {
    let (re, im) = (p.rotation.re as f64, p.rotation.im as f64);
    let n = re.hypot(im);
    Pose::from_parts(v64(p.translation), parry2d_f64::math::Rot2 { re: re / n, im: im / n })
}

pub fn motion32(m: &NonlinearRigidMotion) -> Motion32 {
    Motion32::new(pose32(&m.start), v32(m.local_center), v32(m.linvel), m.angvel as f32)
}

pub fn motion64(m: &Motion32) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(pose64(&m.start), v64(m.local_center), v64(m.linvel), m.angvel as f64)
}

/// A scenario's shape in f32, and the test shape the f32 package reads it as (its parameters
/// widened); `None` when the rounded shape is refused (a polygon whose rounded corners are no
/// longer strictly convex).
pub fn shape32(s: &TestShape) -> Option<(Box<dyn Shape32>, TestShape)> {
    Some(match s {
        TestShape::Ellipse(e) => {
            let e32 = Ellipse::try_new(e.half_x() as f32, e.half_y() as f32).ok()?;
            let wide = *e32.as_f64();
            (Box::new(e32), TestShape::Ellipse(wide))
        }
        TestShape::Ball(b) => {
            let r = b.radius as f32;
            (
                Box::new(parry2d::shape::Ball::new(r)),
                TestShape::Ball(BallCurve { radius: r as f64 }),
            )
        }
        TestShape::RoundedPolygon(p) => {
            let v: Vec<V32> = p.vertices().iter().map(|&v| v32(v)).collect();
            let p32 = RoundedPolygon::try_new(&v, p.corner_radius() as f32).ok()?;
            let wide = p32.as_f64().clone();
            (Box::new(p32), TestShape::RoundedPolygon(wide))
        }
        TestShape::CapsuleEllipse(c) => {
            let (a, b, d) = c.params();
            let c32 = CapsuleEllipse::try_new(a as f32, b as f32, d as f32).ok()?;
            let wide = c32.as_f64().clone();
            (Box::new(c32), TestShape::CapsuleEllipse(wide))
        }
        TestShape::Cuboid(h, _) => {
            let h32 = v32(*h);
            let wide = v64(h32);
            let corners = [
                Vector::new(-wide.x, -wide.y),
                Vector::new(wide.x, -wide.y),
                Vector::new(wide.x, wide.y),
                Vector::new(-wide.x, wide.y),
            ];
            let curve = smooth_ccd2d::RoundedPolygon::try_new(&corners, 0.0).ok()?;
            (
                Box::new(parry2d::shape::Cuboid::new(h32)),
                TestShape::Cuboid(wide, curve),
            )
        }
    })
}

/// A scenario rounded to f32: its f32 shapes and motions, and the f64 scenario they stand for.
pub struct Rounded {
    /// Object 1 in f32.
    pub g1: Box<dyn Shape32>,
    /// Object 2 in f32.
    pub g2: Box<dyn Shape32>,
    /// Object 1's motion in f32.
    pub m1: Motion32,
    /// Object 2's motion in f32.
    pub m2: Motion32,
    /// The target distance in f32.
    pub target: f32,
    /// The f64 scenario the f32 package reads the rounded one as.
    pub wide: Scenario,
}

pub fn rounded(s: &Scenario) -> Option<Rounded> {
    let ((g1, w1), (g2, w2)) = (shape32(&s.shape1)?, shape32(&s.shape2)?);
    let (m1, m2) = (motion32(&s.motion1), motion32(&s.motion2));
    let target = s.target as f32;
    let wide = Scenario {
        shape1: w1,
        shape2: w2,
        motion1: motion64(&m1),
        motion2: motion64(&m2),
        target: target as f64,
        ..s.clone()
    };
    Some(Rounded {
        g1,
        g2,
        m1,
        m2,
        target,
        wide,
    })
}
