//! A test-only member of the smooth-ccd2d workspace, never published: its one test,
//! `tests/rapier_parallel.rs`, steps a rapier scene with rapier's `parallel` pipeline and
//! `SmoothDispatcher` as its narrow phase, on thread pools of 1, 2 and 4 workers.
//!
//! rapier's `parallel` feature is enabled for this package's dev-dependency only, so that the
//! root package's benchmarks and examples build rapier as its users do by default. The library
//! itself is empty.
#![forbid(unsafe_code)]
