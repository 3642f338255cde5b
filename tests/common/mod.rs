//! The helper module of the tests (`mod common;`), shared by the benches (through
//! `benches/support`) and the examples (through `examples/common`, file by file):
//!
//! * [`rng`]: the one splitmix64 generator (and the pile's LCG) of every random batch;
//! * [`reference`]: an independent exact reference for the signed distance and the time of impact;
//! * [`scenarios`]: deterministic random time-of-impact scenarios, and `par_map`;
//! * [`world`]: a rapier world to step, and a hash of its state;
//! * [`scenes`]: the rapier scenes (the mixed pile, the box pile, the wall shots);
//! * [`resting`]: resting quality — two stacks and a slope, exact and parry variants, the pile at rest;
//! * [`appendix_d`]: the specification's Appendix D scene;
//! * [`ccd_scenes`], [`ccd_judge`]: the CCD scene suite (game-like scenes, both methods) and its
//!   judge (bodies through, frozen, NaN, panics, depth after a sweep, step time);
//! * [`moving_pairs`], [`moving_scenes`]: the moving-pairs scenes (issue 30: bullets head-on,
//!   crossing, a fast plank, the closed box), their world with and without the pass, and the
//!   judge of pairs through each other;
//! * [`rocking`]: a smooth body (an ellipse, a weeble) rocking on a floor, and its stand-ins;
//! * [`watched`]: a dispatcher that passes every query on and reports it (the threads that call
//!   it, the time of each manifold query).
//!
//! `tests/reliability` (the fuzz generator of `crates/dev/tests/adversarial.rs`, `tests/golden.rs` and
//! `tests/threads.rs`) draws from [`rng`] too.
#![allow(dead_code)]

pub mod appendix_d;
pub mod ccd_judge;
pub mod ccd_scenes;
pub mod curves;
pub mod moving_pairs;
pub mod moving_scenes;
pub mod reference;
pub mod resting;
pub mod rng;
pub mod rocking;
pub mod scenarios;
pub mod scenes;
pub mod watched;
pub mod world;

#[allow(unused_imports)]
pub use reference::*;
#[allow(unused_imports)]
pub use scenarios::*;
