//! User curves shared by the tests, benches and examples.
#![allow(dead_code)]

use parry2d_f64::math::Vector;
use smooth_ccd2d::method::Dual2;
use smooth_ccd2d::{ConvexCurve, CurvePoint};

/// A user's curve: an ellipse parametrised by its eccentric anomaly (the specification's eq. 1),
/// centred off its local origin, with only `eval` and `bounding_radius` implemented — so the
/// defaults (`phi_range_of_normal`, `support_point`) are exercised, and the gap tracker takes it
/// (it does not claim strict convexity).
#[derive(Debug)]
pub struct EccentricEllipse {
    pub a: f64,
    pub b: f64,
    pub center: Vector,
}

impl ConvexCurve for EccentricEllipse {
    fn eval(&self, phi: f64) -> CurvePoint {
        let x = Dual2::var(phi);
        let (c, s) = (x.cos(), x.sin());
        let (nx, ny) = (c.scale(self.b), s.scale(self.a));
        let inv = (nx * nx + ny * ny).sqrt().recip();
        let (px, py) = (c.scale(self.a), s.scale(self.b));
        let (nx, ny) = (nx * inv, ny * inv);
        CurvePoint {
            point: Vector::new(px.v + self.center.x, py.v + self.center.y),
            d_point: Vector::new(px.d, py.d),
            dd_point: Vector::new(px.dd, py.dd),
            normal: Vector::new(nx.v, ny.v),
            d_normal: Vector::new(nx.d, ny.d),
            dd_normal: Vector::new(nx.dd, ny.dd),
        }
    }
    fn bounding_radius(&self) -> f64 {
        self.center.length() + self.a.max(self.b)
    }
}
