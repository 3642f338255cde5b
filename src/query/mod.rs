//! The queries on two curves: the three distances with their derivatives (`pair`), the root
//! solver of distanceSide (`solver`), the stationary distance, the time of impact (`toi` with a
//! strictly convex side, `gap` without one, what their step loops share in `stepping`, the time
//! scale of extreme motions in `time_scale`), and both against a half-space, on the path the
//! bodies take over the window (`path`).

pub(crate) mod advance;
pub(crate) mod contact;
pub(crate) mod gap;
pub(crate) mod halfspace;
pub(crate) mod pair;
pub(crate) mod path;
pub(crate) mod polish;
pub(crate) mod solver;
pub(crate) mod stationary;
pub(crate) mod stepping;
pub(crate) mod time_scale;
pub(crate) mod toi;
