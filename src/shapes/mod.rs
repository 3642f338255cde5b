//! The shapes: each a [`crate::ConvexCurve`] (its boundary parametrised by φ), and through
//! `parry_shape` a parry `Shape`.

mod ball_curve;
mod capsule_ellipse;
mod curve_checks;
mod custom_curve;
mod ellipse;
mod rounded_polygon;

pub use ball_curve::BallCurve;
pub use capsule_ellipse::CapsuleEllipse;
pub use custom_curve::CustomCurve;
pub use ellipse::Ellipse;
pub use rounded_polygon::RoundedPolygon;
