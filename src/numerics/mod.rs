//! Numerics under everything else: vector helpers, angles, jets (automatic differentiation),
//! the relative motion of two bodies and the clock of its path, a safeguarded root finder and quadrature nodes.

pub(crate) mod angle;
pub(crate) mod clock;
pub(crate) mod jet;
pub(crate) mod math;
pub(crate) mod motion;
pub(crate) mod quadrature;
pub(crate) mod roots;
#[cfg(test)]
pub(crate) mod test_rng;
