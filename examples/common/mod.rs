//! The helper module of the examples (`#[path = "common/mod.rs"] mod common;`; the figures of
//! `crates/dev` reach it by path): the drawing helpers ([`svg`]: the output folder, shape
//! outlines, a hand-written SVG writer), and the files of `tests/common` the examples share with
//! the tests, included as they are (`#[path]`): the rapier world ([`world`]), its scenes
//! ([`scenes`], with the RNG [`rng`]), the resting scenes ([`resting`]) and the rocking body
//! ([`rocking`]), the Appendix D scene
//! ([`appendix_d`]), and the scenario generator ([`scenarios`], with its [`reference`]) that
//! `examples/toi_timing.rs` times. The main example, `wall_shots`, includes only the four files it
//! uses (its first build is a newcomer's first wait).
#![allow(dead_code)]

#[path = "../../tests/common/appendix_d.rs"]
pub mod appendix_d;
#[path = "../../tests/common/ccd_judge.rs"]
pub mod ccd_judge;
#[path = "../../tests/common/ccd_scenes.rs"]
pub mod ccd_scenes;
#[path = "../../tests/common/curves.rs"]
pub mod curves;
#[path = "../../tests/common/moving_pairs.rs"]
pub mod moving_pairs;
#[path = "../../tests/common/moving_scenes.rs"]
pub mod moving_scenes;
#[path = "../../tests/common/reference.rs"]
pub mod reference;
#[path = "../../tests/common/resting.rs"]
pub mod resting;
#[path = "../../tests/common/rng.rs"]
pub mod rng;
#[path = "../../tests/common/rocking.rs"]
pub mod rocking;
#[path = "../../tests/common/scenarios.rs"]
pub mod scenarios;
#[path = "../../tests/common/scenes.rs"]
pub mod scenes;
#[path = "svg.rs"]
pub mod svg;
#[path = "../../tests/common/watched.rs"]
pub mod watched;
#[path = "../../tests/common/world.rs"]
pub mod world;

// Not every example draws.
#[allow(unused_imports)]
pub use svg::*;
