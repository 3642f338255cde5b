//! The parametric convex boundary ([`ConvexCurve`]) and what the crate derives from a curve's
//! pieces.

mod convex_curve;
pub(crate) mod pieces;
pub(crate) mod polygon_pieces;

pub use convex_curve::{ConvexCurve, CurvePoint, SupportJet};
