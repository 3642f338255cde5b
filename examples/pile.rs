//! 200 bodies — ellipses, rounded polygons and `CapsuleEllipse`s of mixed sizes — dropped into a
//! box of fixed cuboid walls, with `SmoothDispatcher` as rapier's narrow phase, until at rest.
//!
//! Prints the time per step (mean and max), the worst penetration (the most negative contact
//! distance in the narrow phase's contact manifolds, over the whole run and at the end) and the
//! kinetic energy every 100 steps; writes `pile.svg` (the final configuration, each body's outline
//! from its boundary curve, and the kinetic energy over time). Deterministic: the sizes, shapes
//! and starting poses come from a fixed-seed generator (the box pile of `tests/common/scenes.rs`).
//!
//! Run: `cargo run --release --example pile [output folder]` (default `target/examples-out`).

#[path = "common/mod.rs"]
mod common;

use common::resting::manifold_penetration as worst_penetration;
use common::scenes::{
    insert_pile, pile_bodies, pile_walls as walls, PileShape, PILE_BODIES as BODIES, PILE_HALF_WIDTH as HALF_WIDTH,
};
use common::world::{World, GRAVITY};
use common::{out_dir, Panel, Svg};
use parry2d_f64::query::QueryDispatcher;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{ConvexCurve, SmoothDispatcher};
use std::time::Instant;

const MAX_STEPS: usize = 3000;
const PRINT_EVERY: usize = 100;
/// At rest: kinetic energy below this (J) for `REST_STEPS` consecutive steps.
const REST_KE: f64 = 1e-3;
const REST_STEPS: usize = 60;

/// The fill colour of a body's outline.
fn colour(shape: &PileShape) -> &'static str {
    match shape {
        PileShape::Ellipse(_) => "#9ecae1",
        PileShape::Polygon(_) => "#fdae6b",
        PileShape::Capsule(_) => "#a1d99b",
    }
}

/// The outline of a curve at a pose, sampled at `n` parameter values per piece-free turn (plus the
/// piece ends, so that corners of rounded polygons are kept).
fn curve_outline(c: &dyn ConvexCurve, pose: &Pose, n: usize) -> Vec<Vector> {
    let mut phis: Vec<f64> = (0..n)
        .map(|k| -std::f64::consts::PI + std::f64::consts::TAU * k as f64 / n as f64)
        .collect();
    phis.extend_from_slice(c.breakpoints());
    phis.sort_by(f64::total_cmp);
    phis.iter().map(|&phi| *pose * c.eval(phi).point).collect()
}

/// What one run of the pile measured.
struct Run {
    steps: usize,
    at_rest: bool,
    asleep: usize,
    mean_step: f64,
    max_step: f64,
    /// Most negative contact `dist` in the narrow phase's manifolds, and its step.
    worst_manifold: (f64, usize),
    /// Most negative exact signed distance of a contact pair at the end-of-step poses.
    worst_exact: (f64, usize),
    end_manifold: f64,
    end_exact: f64,
    energy: Vec<(usize, f64)>,
    scene: World,
    bodies: Vec<(RigidBodyHandle, PileShape)>,
}

/// The most negative exact signed distance over the narrow phase's contact pairs, at the
/// colliders' current poses (`SmoothDispatcher::contact`: exact for the crate's pairs, parry's
/// for the pairs it hands over).
fn exact_penetration(scene: &World) -> f64 {
    let d = SmoothDispatcher::default();
    let mut worst: f64 = 0.0;
    for pair in scene.narrow_phase.contact_pairs() {
        if pair.manifolds().iter().all(|m| m.points.is_empty()) {
            continue;
        }
        let (c1, c2) = (&scene.colliders[pair.collider1], &scene.colliders[pair.collider2]);
        let pos12 = c1.position().inv_mul(c2.position());
        if let Ok(Some(c)) = d.contact(&pos12, c1.shape(), c2.shape(), 0.0) {
            worst = worst.min(c.dist);
        }
    }
    worst
}

/// Drops the pile; `smooth`: `SmoothDispatcher`, else parry's default dispatcher; `recycling` is
/// rapier's `contact_recycling` (on by default: a pair whose relative pose moved less than 0.05
/// since its last full update keeps its previous manifold, `dist` included).
fn simulate(smooth: bool, recycling: bool, verbose: bool) -> Run {
    let narrow_phase = if smooth {
        NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
    } else {
        NarrowPhase::new()
    };
    let mut scene = World::new(narrow_phase);
    scene.params.contact_recycling = recycling;
    let pile = pile_bodies();
    let handles = insert_pile(&mut scene, &pile, PileShape::shared);
    let bodies: Vec<(RigidBodyHandle, PileShape)> =
        handles.into_iter().zip(pile.into_iter().map(|b| b.shape)).collect();
    let kinetic = |scene: &World| {
        bodies
            .iter()
            .map(|(h, _)| scene.bodies[*h].kinetic_energy())
            .sum::<f64>()
    };
    let asleep = |scene: &World| bodies.iter().filter(|(h, _)| scene.bodies[*h].is_sleeping()).count();

    if verbose {
        println!(
            "{:>6} {:>12} {:>20} {:>18} {:>7}",
            "step", "KE (J)", "manifold min dist", "exact min dist", "asleep"
        );
    }
    let mut energy = vec![(0usize, kinetic(&scene))];
    let (mut total, mut max_step) = (0.0f64, 0.0f64);
    let mut worst_manifold = (0.0f64, 0usize);
    let mut worst_exact = (0.0f64, 0usize);
    let mut quiet = 0;
    let mut steps = 0;
    while steps < MAX_STEPS && quiet < REST_STEPS {
        let t = Instant::now();
        scene.step(GRAVITY, &());
        let dt = t.elapsed().as_secs_f64();
        steps += 1;
        total += dt;
        max_step = max_step.max(dt);
        let pen = worst_penetration(&scene);
        if pen < worst_manifold.0 {
            worst_manifold = (pen, steps);
        }
        let exact = exact_penetration(&scene);
        if exact < worst_exact.0 {
            worst_exact = (exact, steps);
        }
        let ke = kinetic(&scene);
        energy.push((steps, ke));
        quiet = if ke < REST_KE { quiet + 1 } else { 0 };
        if verbose && steps % PRINT_EVERY == 0 {
            println!(
                "{steps:>6} {ke:>12.4e} {pen:>20.3e} {exact:>18.3e} {:>7}",
                asleep(&scene)
            );
        }
    }
    Run {
        steps,
        at_rest: quiet >= REST_STEPS,
        asleep: asleep(&scene),
        mean_step: total / steps as f64,
        max_step,
        worst_manifold,
        worst_exact,
        end_manifold: worst_penetration(&scene),
        end_exact: exact_penetration(&scene),
        energy,
        scene,
        bodies,
    }
}

fn summary(r: &Run) {
    let ke = r.energy.last().map_or(0.0, |e| e.1);
    if r.at_rest {
        println!(
            "  at rest after {} steps (KE < {REST_KE} J for {REST_STEPS} steps): KE = {ke:.3e} J, {} asleep",
            r.steps, r.asleep
        );
    } else {
        println!(
            "  stopped after {} steps: KE = {ke:.3e} J, {} asleep",
            r.steps, r.asleep
        );
    }
    println!(
        "  time per step: mean {:.3} ms, max {:.3} ms",
        1e3 * r.mean_step,
        1e3 * r.max_step
    );
    println!(
        "  worst penetration, manifolds' contact dist: {:.3e} m (step {}), at the end {:.3e} m",
        r.worst_manifold.0, r.worst_manifold.1, r.end_manifold
    );
    println!(
        "  worst penetration, exact at end-of-step poses: {:.3e} m (step {}), at the end {:.3e} m",
        r.worst_exact.0, r.worst_exact.1, r.end_exact
    );
    let (i, ke) = r
        .bodies
        .iter()
        .enumerate()
        .map(|(i, (h, _))| (i, r.scene.bodies[*h].kinetic_energy()))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .expect("bodies");
    let kind = match r.bodies[i].1 {
        PileShape::Ellipse(_) => "ellipse",
        PileShape::Polygon(_) => "rounded polygon",
        PileShape::Capsule(_) => "CapsuleEllipse",
    };
    println!(
        "  most energetic body at the end: #{i} ({kind}), KE {ke:.3e} J, angular velocity {:.3e} rad/s",
        r.scene.bodies[r.bodies[i].0].angvel()
    );
}

fn main() {
    let dir = out_dir();
    let started = Instant::now();
    // The pile's body i is of kind i mod 3.
    let count = |kind: usize| (0..BODIES).filter(|i| i % 3 == kind).count();
    println!(
        "pile: {BODIES} bodies ({} ellipses, {} rounded polygons, {} CapsuleEllipses, sizes 0.15-0.45) \
         dropped into a box {:.0} wide, dt = 1/60 s",
        count(0),
        count(1),
        count(2),
        2.0 * HALF_WIDTH
    );
    let run = simulate(true, true, true);
    println!("SmoothDispatcher, rapier defaults (contact recycling on):");
    summary(&run);
    println!("SmoothDispatcher, contact recycling off (every manifold recomputed every step):");
    summary(&simulate(true, false, false));
    println!("baseline: parry's default dispatcher (polygonal feature maps), contact recycling on:");
    summary(&simulate(false, true, false));
    println!("baseline: parry's default dispatcher, contact recycling off:");
    summary(&simulate(false, false, false));

    let (scene, bodies, steps) = (&run.scene, &run.bodies, run.steps);
    let top = bodies
        .iter()
        .map(|(h, b)| scene.bodies[*h].translation().y + b.curve().bounding_radius())
        .fold(0.0f64, f64::max);
    let escaped = bodies
        .iter()
        .filter(|(h, _)| {
            let p = scene.bodies[*h].translation();
            p.x.abs() > HALF_WIDTH || p.y < 0.0
        })
        .count();
    println!("pile height {top:.2} m; bodies outside the box: {escaped}");

    // Picture: the final configuration, and the kinetic energy over time (log scale).
    let (x0, x1, y0, y1) = (-HALF_WIDTH - 1.2, HALF_WIDTH + 1.2, -1.2, top.max(4.0) + 0.8);
    let p = Panel::fit(20.0, 40.0, 700.0, x0, x1, y0, y1);
    let q = Panel {
        px: 20.0,
        py: p.py + p.height + 50.0,
        width: 700.0,
        height: 220.0,
        x0: 0.0,
        x1: steps as f64,
        y0: -4.0,
        y1: run
            .energy
            .iter()
            .fold(0.0f64, |m, e| m.max(e.1))
            .max(1e-3)
            .log10()
            .ceil(),
    };
    let mut svg = Svg::new(740.0, q.py + q.height + 30.0);
    svg.text(
        20.0,
        22.0,
        13.0,
        &format!("{BODIES} bodies after {steps} steps (ellipses blue, rounded polygons orange, CapsuleEllipses green)"),
    );
    svg.begin_panel(&p, "");
    for (c, h) in walls() {
        let r = [
            c + Vector::new(-h.x, -h.y),
            c + Vector::new(h.x, -h.y),
            c + Vector::new(h.x, h.y),
            c + Vector::new(-h.x, h.y),
        ];
        svg.polyline(&p, &r, true, "#555", 0.8, "#bbb");
    }
    for (h, b) in bodies {
        let pose = *scene.bodies[*h].position();
        svg.polyline(&p, &curve_outline(b.curve(), &pose, 64), true, "#333", 0.6, colour(b));
        svg.circle(&p, pose.translation, 0.8, "#333");
    }
    svg.end_panel();
    svg.begin_panel(&q, "kinetic energy (J, log10, clipped at 1e-4) over the steps");
    let pts: Vec<Vector> = run
        .energy
        .iter()
        .map(|&(k, e)| Vector::new(k as f64, e.max(1e-4).log10()))
        .collect();
    svg.polyline(&q, &pts, false, "#d62728", 1.0, "none");
    for d in (q.y0 as i32)..=(q.y1 as i32) {
        let (_, py) = q.map(0.0, d as f64);
        svg.text(q.px + 3.0, py - 2.0, 10.0, &format!("1e{d}"));
    }
    svg.end_panel();
    let path = dir.join("pile.svg");
    svg.save(&path);
    println!(
        "wrote {} ({:.2} s in all)",
        path.display(),
        started.elapsed().as_secs_f64()
    );
}
