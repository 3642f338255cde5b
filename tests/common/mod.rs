//! Shared helpers of the integration tests: an independent exact reference for the signed
//! distance and the time of impact ([`reference`]), deterministic random scenario generators
//! ([`scenarios`]), and a rapier world to step ([`world`]).
#![allow(dead_code)]

pub mod reference;
pub mod scenarios;
pub mod world;

#[allow(unused_imports)]
pub use reference::*;
#[allow(unused_imports)]
pub use scenarios::*;
