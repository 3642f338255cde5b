//! The random numbers of the tests, benches and examples: one splitmix64 generator ([`Rng`]) and
//! the 64-bit LCG of the pile scene ([`Lcg`]). Both are small, seedable and identical on every
//! platform, so every random scene and batch is the same on every run.
//!
//! [`Rng`] draws the scenarios of `scenarios.rs`, the fuzz cases of `tests/reliability`, and the
//! random configurations of `tests/parry_shapes.rs`, `tests/distance_vs_parry.rs`,
//! `crates/dev/tests/adversarial.rs` and `tests/threads.rs`. [`Lcg`] draws the pile of `scenes.rs` (used by
//! `examples/pile.rs` and the pile benchmarks through `examples/common` and `benches/support`).
#![allow(dead_code)]

use core::f64::consts::{PI, TAU};
use parry2d_f64::math::Vector;

/// splitmix64's increment (the golden gamma).
const GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;

/// splitmix64: a tiny, good-enough deterministic PRNG.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// The generator whose state is `state` (the first number drawn is the mix of
    /// `state + GAMMA`).
    pub fn new(state: u64) -> Self {
        Self(state)
    }
    /// The generator of the fuzz cases (`tests/reliability`): state `seed ^ GAMMA`, so that seed 0
    /// does not start from state 0.
    pub fn mixed(seed: u64) -> Self {
        Self(seed ^ GAMMA)
    }
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(GAMMA);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1): the top 53 bits over 2^53.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Log-uniform in [lo, hi) (both > 0).
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (self.uniform(lo.ln(), hi.ln())).exp()
    }
    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
    /// Uniform integer in [lo, hi] (inclusive).
    pub fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as usize
    }
    /// ±1 with equal probability.
    pub fn sign(&mut self) -> f64 {
        if self.chance(0.5) {
            1.0
        } else {
            -1.0
        }
    }
    /// An angle uniform in [−π, π).
    pub fn angle(&mut self) -> f64 {
        self.uniform(-PI, PI)
    }
    /// A unit vector at an angle uniform in [−π, π) ([`Rng::angle`]).
    pub fn direction(&mut self) -> Vector {
        let a = self.angle();
        Vector::new(a.cos(), a.sin())
    }
    /// A unit vector at an angle uniform in [0, 2π): the scenario generator's directions (the
    /// same distribution as [`Rng::direction`], another sequence).
    pub fn direction_tau(&mut self) -> Vector {
        let a = self.uniform(0.0, TAU);
        Vector::new(a.cos(), a.sin())
    }
    /// A uniformly random point in the disc of radius `r` ([`Rng::direction_tau`] first).
    pub fn in_disc(&mut self, r: f64) -> Vector {
        self.direction_tau() * (r * self.unit().sqrt())
    }
    /// One of `xs`, uniformly.
    pub fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[self.int(0, xs.len() - 1)]
    }
}

/// A 64-bit linear congruential generator (Knuth's MMIX constants), its top 53 bits as the
/// number: the generator of the pile scene.
#[derive(Clone, Debug)]
pub struct Lcg(u64);

impl Lcg {
    /// The generator whose state is `seed`.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}
