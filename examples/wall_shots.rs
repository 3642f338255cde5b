//! Shots of fast-spinning bodies (an ellipse, a rounded heptagon, the Appendix A capsule-ellipse
//! and a sharp square) at a thin fixed wall in rapier, CCD on
//! (the wall-shot scene of `tests/common/scenes.rs`), over a grid of speeds (100–1000 m/s) and
//! spins (0 to ±600 rad/s), three ways:
//!
//! * **smooth**: this crate's shapes with
//!   `NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())`;
//! * **rapier polygons**: the same shapes approximated by parry's polygons (a 32-gon inscribed in
//!   the ellipse, `RoundConvexPolygon` for the heptagon), which rapier sweeps with its own routine,
//!   and rapier's default narrow phase;
//! * **parry default**: this crate's shapes under parry's `DefaultQueryDispatcher`
//!   (`NarrowPhase::new()`).
//!
//! Shots above rapier's caps (400 m/s, π/4 a step) lift them (`Shot::above_caps`). A shot
//! *tunnels* when the body's centre crosses the wall's mid-plane within its height. Its *first contact
//! step* is the first step that ends with the shape within 0.01 of the wall's face (or past it);
//! the *depth* there is how far the shape's deepest point (its support point along +x) is past
//! the face (negative: stopped short). The depth is measured on the collider's own shape (the
//! polygon for the polygon method).
//!
//! Run: `cargo run --example wall_shots [output folder]` (default `target/examples-out`); writes
//! `wall_shots.svg`. That is the README's first command, a dev build (quick to compile, about 5 s
//! to run); `--release` gives the time column of docs/rapier.md's table.

/// The helpers this example uses, and only those: the drawing helpers and the wall-shot scene
/// with what it needs (`common/mod.rs` holds every example's; this is the README's first command,
/// so it compiles no more than it runs).
#[allow(dead_code)]
mod common {
    #[path = "../../tests/common/rng.rs"]
    pub mod rng;
    #[path = "../../tests/common/scenes.rs"]
    pub mod scenes;
    #[path = "svg.rs"]
    pub mod svg;
    #[path = "../../tests/common/world.rs"]
    pub mod world;

    pub use svg::*;
}

use common::scenes::{
    shot_shape, wall_shot, Shot, ShotBody, ShotMethod, WALL_FACE as FACE, WALL_HALF, WALL_HALF_HEIGHT, WALL_X,
};
use common::{max_x, out_dir, outline, Panel, Svg};
use rapier2d_f64::prelude::*;
use std::time::Instant;

/// Steps per shot (1/60 s each).
const STEPS: usize = 20;
/// A step ending with the shape this close to the face counts as the first contact.
const CONTACT_TOL: f64 = 0.01;
const SPEEDS: usize = 10;
const SPINS: usize = 10;

fn short_name(kind: ShotBody) -> &'static str {
    match kind {
        ShotBody::Ellipse => "ellipse",
        ShotBody::Heptagon => "heptagon",
        ShotBody::CapsuleEllipse => "capsule-ellipse",
        ShotBody::Square => "square",
    }
}

fn kind_name(kind: ShotBody) -> &'static str {
    match kind {
        ShotBody::Ellipse => "ellipse 0.5 x 0.2",
        ShotBody::Heptagon => "rounded heptagon r 0.4",
        ShotBody::CapsuleEllipse => "capsule-ellipse .12/.3",
        ShotBody::Square => "sharp square r 0.35",
    }
}

fn method_name(method: ShotMethod) -> &'static str {
    match method {
        ShotMethod::Smooth => "SmoothDispatcher",
        ShotMethod::Polygon => "rapier polygons",
        ShotMethod::ParryDefault => "parry default",
    }
}

/// 10 speeds × 10 spins: speeds 100, 200, …, 1000 m/s (1.7 to 17 m per step); spins 0, +67, −133,
/// …, −600 rad/s (up to 10 rad per step); initial angles spread.
fn shots() -> Vec<Shot> {
    let mut v = Vec::new();
    for i in 0..SPEEDS {
        for j in 0..SPINS {
            let sign = if j % 2 == 0 { 1.0 } else { -1.0 };
            v.push(Shot {
                speed: 100.0 * (i + 1) as f64,
                spin: sign * 600.0 * j as f64 / (SPINS - 1) as f64,
                angle0: 0.37 * (i * SPINS + j) as f64,
            });
        }
    }
    v
}

struct Outcome {
    /// Body pose at the start and after each step.
    poses: Vec<Pose>,
    tunnelled: bool,
    /// Index into `poses` of the first contact, and the depth there.
    first_contact: Option<(usize, f64)>,
    /// Largest depth over the whole run at the poses whose deepest point is over the wall's face
    /// (within its height: a body slid along the face and past its end is not in the wall).
    max_depth: f64,
}

fn run(kind: ShotBody, method: ShotMethod, shot: Shot) -> Outcome {
    let shape = shot_shape(kind, method);
    let (mut world, h) = wall_shot(method, shape.clone(), shot);
    let mut poses = vec![*world.bodies[h].position()];
    for _ in 0..STEPS {
        world.step(Vector::ZERO, &());
        poses.push(*world.bodies[h].position());
    }
    // The centre crossed the wall's mid-plane within the wall's height (a body sliding along
    // the wall and past its end has not tunnelled).
    let tunnelled = poses.windows(2).any(|w| {
        let (c0, c1) = (w[0].translation, w[1].translation);
        c0.x <= WALL_X && c1.x > WALL_X && {
            let y = c0.y + (c1.y - c0.y) * (WALL_X - c0.x) / (c1.x - c0.x);
            y.abs() <= WALL_HALF_HEIGHT
        }
    });
    let depths: Vec<f64> = poses.iter().map(|p| max_x(shape.as_ref(), p) - FACE).collect();
    let first_contact = if tunnelled {
        None
    } else {
        depths.iter().position(|&d| d >= -CONTACT_TOL).map(|k| (k, depths[k]))
    };
    let over_wall = |p: &Pose| {
        let deepest = shape
            .as_support_map()
            .expect("a support map")
            .support_point(p, Vector::X);
        deepest.y.abs() <= WALL_HALF_HEIGHT
    };
    let max_depth = poses
        .iter()
        .zip(&depths)
        .filter(|(p, _)| over_wall(p))
        .fold(f64::NEG_INFINITY, |m, (_, &d)| m.max(d));
    Outcome {
        poses,
        tunnelled,
        first_contact,
        max_depth,
    }
}

struct Row {
    kind: ShotBody,
    method: ShotMethod,
    outcomes: Vec<Outcome>,
    seconds: f64,
}

fn main() {
    let dir = out_dir();
    let shots = shots();
    let kinds = [
        ShotBody::Ellipse,
        ShotBody::Heptagon,
        ShotBody::CapsuleEllipse,
        ShotBody::Square,
    ];
    let methods = [ShotMethod::Smooth, ShotMethod::Polygon, ShotMethod::ParryDefault];
    let mut rows = Vec::new();
    for kind in kinds {
        for method in methods {
            let t = Instant::now();
            let outcomes = shots.iter().map(|&s| run(kind, method, s)).collect();
            rows.push(Row {
                kind,
                method,
                outcomes,
                seconds: t.elapsed().as_secs_f64(),
            });
        }
    }

    println!(
        "wall shots: wall 0.05 thick (face at x = {FACE}), {} speeds 100-1000 m/s x {} spins 0-600 rad/s, \
         dt = 1/60 s, CCD on, {STEPS} steps per shot",
        SPEEDS, SPINS
    );
    println!(
        "depth (m) = how far the shape's deepest point is past the wall face at the first contact step (< 0: short); \
         worst and least over the shots that did not tunnel"
    );
    println!(
        "deepest run (m) = the largest depth over the whole shot, after the impact too (spinning against the wall), \
         while the deepest point is over the wall's face (not past its end)"
    );
    println!(
        "{:<24} {:<18} {:>5} {:>10} {:>12} {:>12} {:>14} {:>8}",
        "shape", "method", "shots", "tunnelled", "worst depth", "least depth", "deepest run", "time s"
    );
    for r in &rows {
        let tunnelled = r.outcomes.iter().filter(|o| o.tunnelled).count();
        let firsts: Vec<f64> = r.outcomes.iter().filter_map(|o| o.first_contact.map(|f| f.1)).collect();
        let worst = firsts.iter().fold(f64::NEG_INFINITY, |m, &d| m.max(d));
        let short = firsts.iter().fold(f64::INFINITY, |m, &d| m.min(d));
        let max_run = r
            .outcomes
            .iter()
            .filter(|o| !o.tunnelled)
            .fold(f64::NEG_INFINITY, |m, o| m.max(o.max_depth));
        println!(
            "{:<24} {:<18} {:>5} {:>10} {:>12.3e} {:>12.3e} {:>14.3e} {:>8.2}",
            kind_name(r.kind),
            method_name(r.method),
            r.outcomes.len(),
            tunnelled,
            worst,
            short,
            max_run,
            r.seconds
        );
    }
    for r in &rows {
        let through: Vec<String> = r
            .outcomes
            .iter()
            .zip(&shots)
            .filter(|(o, _)| o.tunnelled)
            .map(|(_, s)| format!("{}/{:+.0}", s.speed, s.spin))
            .collect();
        if !through.is_empty() && through.len() <= 8 {
            println!(
                "tunnelled ({}, {}; speed m/s / spin rad/s): {}",
                kind_name(r.kind),
                method_name(r.method),
                through.join(", ")
            );
        }
    }

    // Where this crate's deepest run is: the shot, for the docs.
    for r in rows.iter().filter(|r| r.method == ShotMethod::Smooth) {
        let deepest = r
            .outcomes
            .iter()
            .zip(&shots)
            .filter(|(o, _)| !o.tunnelled)
            .max_by(|a, b| a.0.max_depth.total_cmp(&b.0.max_depth));
        if let Some((o, s)) = deepest {
            println!(
                "deepest run ({}, {}): {:.3e} m at {}/{:+.0} (speed m/s / spin rad/s)",
                kind_name(r.kind),
                method_name(r.method),
                o.max_depth,
                s.speed,
                s.spin
            );
        }
    }

    let path = dir.join("wall_shots.svg");
    draw(&rows, &path);
    println!("wrote {}", path.display());
}

/// One panel per shape kind × method; one lane per speed showing that speed's worst shot
/// (tunnelled, else deepest at first contact): the outline at every step near the wall (grey),
/// at the first contact step (blue, red when past the face), the centre's path (green).
fn draw(rows: &[Row], path: &std::path::Path) {
    let (pw, margin, top) = (330.0, 30.0, 40.0);
    let (x0, x1) = (3.2, 6.8);
    let lane = 1.1;
    let (y0, y1) = (-0.5 * lane, (SPEEDS as f64 - 0.5) * lane);
    let ph = pw * (y1 - y0) / (x1 - x0);
    let mut svg = Svg::new(3.0 * (pw + margin) + margin, 2.0 * (ph + top) + top);
    svg.text(
        margin,
        18.0,
        13.0,
        "Shots at a 0.05-thick wall, one lane per speed (100 m/s at the bottom, 1000 at the top), worst spin of each; blue/red: \
         first contact (red: past the face), red: tunnelled",
    );
    for (idx, r) in rows.iter().enumerate() {
        let (row, col) = (idx / 3, idx % 3);
        let p = Panel::fit(
            margin + col as f64 * (pw + margin),
            top + 20.0 + row as f64 * (ph + top),
            pw,
            x0,
            x1,
            y0,
            y1,
        );
        let tunnelled = r.outcomes.iter().filter(|o| o.tunnelled).count();
        svg.begin_panel(
            &p,
            &format!(
                "{}: {} ({tunnelled} tunnelled)",
                short_name(r.kind),
                method_name(r.method)
            ),
        );
        let shape = shot_shape(r.kind, r.method);
        for s in 0..SPEEDS {
            let lane_y = s as f64 * lane;
            let shift = Vector::new(0.0, lane_y);
            let score = |o: &Outcome| {
                if o.tunnelled {
                    f64::INFINITY
                } else {
                    o.first_contact.map_or(f64::NEG_INFINITY, |f| f.1)
                }
            };
            let o = r.outcomes[s * SPINS..(s + 1) * SPINS]
                .iter()
                .max_by(|a, b| score(a).total_cmp(&score(b)))
                .expect("a lane of shots");
            let wall = [
                Vector::new(FACE, lane_y - 0.6),
                Vector::new(WALL_X + WALL_HALF, lane_y - 0.6),
                Vector::new(WALL_X + WALL_HALF, lane_y + 0.6),
                Vector::new(FACE, lane_y + 0.6),
            ];
            svg.polyline(&p, &wall, true, "#333", 0.5, "#999");
            let first = o.first_contact.map(|f| f.0);
            for (k, pose) in o.poses.iter().enumerate() {
                if Some(k) != first {
                    let pts: Vec<Vector> = outline(shape.as_ref(), pose, 48).iter().map(|&q| q + shift).collect();
                    let stroke = if o.tunnelled { "#d62728" } else { "#aaa" };
                    svg.polyline(&p, &pts, true, stroke, 0.5, "none");
                }
            }
            if let Some((k, depth)) = o.first_contact {
                let pts: Vec<Vector> = outline(shape.as_ref(), &o.poses[k], 48)
                    .iter()
                    .map(|&q| q + shift)
                    .collect();
                let stroke = if depth > 0.0 { "#d62728" } else { "#1f77b4" };
                svg.polyline(&p, &pts, true, stroke, 1.2, "none");
            }
            let centres: Vec<Vector> = o.poses.iter().map(|q| q.translation + shift).collect();
            svg.polyline(&p, &centres, false, "#2ca02c", 0.6, "none");
            for c in &centres {
                svg.circle(&p, *c, 1.2, "#2ca02c");
            }
        }
        svg.end_panel();
    }
    svg.save(path);
}
