//! The unit tests' random numbers: a 64-bit linear congruential generator (Knuth's MMIX
//! constants), seedable and the same on every platform.

/// A 64-bit LCG; the state is public so that a test can seed it inline (`Lcg(7)`).
pub(crate) struct Lcg(pub u64);

impl Lcg {
    /// Uniform in [0, 1): the top 53 bits of the next state over 2^53.
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub(crate) fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}
