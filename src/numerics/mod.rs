//! Numerics under everything else: vector helpers, angles, jets (automatic differentiation),
//! the relative motion of two bodies, a safeguarded root finder and quadrature nodes.

pub(crate) mod angle;
pub(crate) mod jet;
pub(crate) mod math;
pub(crate) mod motion;
pub(crate) mod quadrature;
pub(crate) mod roots;
#[cfg(test)]
pub(crate) mod test_rng;
