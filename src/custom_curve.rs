//! A concrete parry shape wrapping a user-defined [`crate::ConvexCurve`] (in progress).
