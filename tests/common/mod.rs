//! Shared helpers of the integration tests: an independent exact reference for the signed
//! distance and the time of impact ([`reference`]), and deterministic random scenario generators
//! ([`scenarios`]).
#![allow(dead_code)]

pub mod reference;
pub mod scenarios;

#[allow(unused_imports)]
pub use reference::*;
#[allow(unused_imports)]
pub use scenarios::*;
