//! Resting quality in rapier: three scenes that start at rest and should stay there, each built
//! with the exact shapes and `SmoothDispatcher` or with parry's stand-ins and parry's default
//! dispatcher, and how long the box pile of [`super::scenes`] takes to come to rest.
//!
//! * [`RestScene::BoxStack`]: 10 rounded boxes 1.0 × 0.5 (corner radius 0.05) stacked on a fixed
//!   box, edges exactly touching;
//! * [`RestScene::EllipseStack`]: 10 ellipses 0.5 × 0.2 lying flat (major axis horizontal),
//!   stacked tip on tip on the same box. Balanced, but not stable: a rigid body resting on a
//!   curved one is stable only when 1/h > 1/ρ₁ + 1/ρ₂ (h the height of its centre of mass above
//!   the contact, ρ the radii of curvature there, 1.25 at an ellipse's tip), so the top four
//!   ellipses taken together (h = 0.8) already topple on the fifth; only the stack's symmetry
//!   holds it up, and whatever breaks it (rounding in contacts recomputed every step) grows;
//! * [`RestScene::Slope`]: a rounded hexagon (`RoundedPolygon::regular(6, 0.5, 0.05)`) resting on
//!   a flat side on a fixed box tilted by [`SLOPE_DEG`]° (below the friction angle
//!   atan 0.5 ≈ 26.6°, so it should stick).
//!
//! The variants ([`RestVariant`]): the exact shapes with `SmoothDispatcher`; parry's stand-ins
//! (`RoundConvexPolygon` from `RoundedPolygon::to_parry` for the rounded polygons, the inscribed
//! [`POLYGON_VERTICES`]-gon of [`polygon_approximation`] for the ellipses) with parry's
//! `DefaultQueryDispatcher` (`NarrowPhase::new()`), given the exact shapes' mass properties so
//! that only the contacts differ; and the same stand-ins with parry's own mass properties.
//! Everything else is the same: friction 0.5 on every collider, 60 Hz, gravity −9.81,
//! [`REST_STEPS`] steps (10 s), sleeping disabled (a sleeping body would hide the contacts'
//! drift), rapier's default integration parameters, contact recycling as [`run_scene`] is told.
//!
//! Penetration is measured twice: from the narrow phase's manifolds (the most negative contact
//! `dist`; while rapier recycles a pair that is the `dist` of the pair's last full update, so in a
//! scene at rest it can stay at its first value) and exactly, as the signed distance of each
//! touching pair's collider shapes at the end-of-step poses (`SmoothDispatcher::contact`, exact
//! for every convex pair here, parry's polygons included): the true overlap of the geometry that
//! variant simulates.
#![allow(dead_code)]

use super::scenes::{insert_pile, pile_bodies, PileBody, PileShape};
use super::world::{World, GRAVITY};
use parry2d_f64::query::QueryDispatcher;
use parry2d_f64::shape::ConvexPolygon;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{ConvexCurve, Ellipse, RoundedPolygon, SmoothDispatcher};
use std::fmt::Write as _;
use std::time::Instant;

/// Steps of a resting scene: 10 s at 60 Hz.
pub const REST_STEPS: usize = 600;
/// Steps in "the last second" of a run.
pub const LAST_SECOND: usize = 60;
/// Friction coefficient of every collider.
pub const FRICTION: f64 = 0.5;
/// Bodies in each stack.
pub const STACK_BODIES: usize = 10;
/// The slope's angle, degrees.
pub const SLOPE_DEG: f64 = 20.0;
/// Vertices of the polygon stand-ins of smooth shapes (as `benches/support`).
pub const POLYGON_VERTICES: usize = 64;

/// Half-extents of the rounded boxes (outer: core plus corner radius).
const BOX_HALF: (f64, f64) = (0.5, 0.25);
/// Corner radius of the rounded boxes.
const BOX_RADIUS: f64 = 0.05;
/// Semi-axes of the ellipses.
const ELLIPSE_HALF: (f64, f64) = (0.5, 0.2);
/// Circumradius and corner radius of the hexagon on the slope.
const HEXAGON: (f64, f64) = (0.5, 0.05);
/// Half-extents of the fixed ground box (its top face through the origin, before tilting).
const GROUND_HALF: (f64, f64) = (20.0, 0.5);

/// The polygon whose vertices are the support points of `n` evenly spread directions (the first
/// along +x): inscribed in the curve, parry's polygonal stand-in for a smooth shape. For an
/// ellipse lying flat and `n` a multiple of 4, a vertex is at the bottom and one at the top.
pub fn polygon_approximation(c: &dyn ConvexCurve, n: usize) -> ConvexPolygon {
    let pts: Vec<Vector> = (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            c.support_point(Vector::new(a.cos(), a.sin()))
        })
        .collect();
    ConvexPolygon::from_convex_hull(&pts).expect("a non-degenerate polygon")
}

/// A box-pile body's shape as parry's stand-in: ellipses and `CapsuleEllipse`s as their
/// inscribed [`POLYGON_VERTICES`]-gons, rounded polygons as parry's `RoundConvexPolygon` (as
/// `benches/support/pile.rs`).
pub fn pile_polygonal(shape: &PileShape) -> SharedShape {
    match shape {
        PileShape::Ellipse(e) => SharedShape::new(polygon_approximation(e, POLYGON_VERTICES)),
        PileShape::Polygon(p) => SharedShape::new(p.to_parry().expect("a regular polygon")),
        PileShape::Capsule(c) => SharedShape::new(polygon_approximation(c, POLYGON_VERTICES)),
    }
}

/// The three resting scenes.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum RestScene {
    /// 10 rounded boxes 1.0 × 0.5 stacked on a box.
    BoxStack,
    /// 10 ellipses 0.5 × 0.2 lying flat, stacked on a box.
    EllipseStack,
    /// A rounded hexagon on a flat side on a box tilted by [`SLOPE_DEG`]°.
    Slope,
}

impl RestScene {
    /// Every scene, in table order.
    pub const ALL: [RestScene; 3] = [RestScene::BoxStack, RestScene::EllipseStack, RestScene::Slope];

    /// The scene's row label.
    pub fn label(self) -> &'static str {
        match self {
            RestScene::BoxStack => "10 rounded boxes 1.0 × 0.5 (r 0.05), stacked",
            RestScene::EllipseStack => "10 ellipses 0.5 × 0.2 lying flat, stacked",
            RestScene::Slope => "rounded hexagon (R 0.5, r 0.05) on a 20° slope",
        }
    }
}

/// How a scene is simulated: the shapes, their mass properties and the narrow phase.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum RestVariant {
    /// This crate's shapes, `SmoothDispatcher`.
    Exact,
    /// parry's stand-ins (`RoundConvexPolygon`, inscribed 64-gons) with the exact shapes' mass
    /// properties, parry's default dispatcher: the same bodies, only the contacts differ.
    Parry,
    /// parry's stand-ins with parry's own mass properties (a `RoundConvexPolygon`'s are its core
    /// polygon's: parry 0.31's `RoundShape::mass_properties` ignores the border radius), parry's
    /// default dispatcher.
    ParryOwnMass,
}

impl RestVariant {
    /// Every variant, in table order.
    pub const ALL: [RestVariant; 3] = [RestVariant::Exact, RestVariant::Parry, RestVariant::ParryOwnMass];

    /// The variant's column label.
    pub fn label(self) -> &'static str {
        match self {
            RestVariant::Exact => "exact shapes, SmoothDispatcher",
            RestVariant::Parry => "parry stand-ins (exact mass), default dispatcher",
            RestVariant::ParryOwnMass => "parry stand-ins (parry's mass), default dispatcher",
        }
    }

    /// The variant's narrow phase.
    pub fn narrow_phase(self) -> NarrowPhase {
        match self {
            RestVariant::Exact => NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
            RestVariant::Parry | RestVariant::ParryOwnMass => NarrowPhase::new(),
        }
    }

    /// The collider of a body whose exact shape is `exact` and parry stand-in `stand_in()`
    /// (density 1, friction [`FRICTION`]).
    pub fn collider(self, exact: SharedShape, stand_in: impl FnOnce() -> SharedShape) -> ColliderBuilder {
        let c = match self {
            RestVariant::Exact => ColliderBuilder::new(exact),
            RestVariant::Parry => ColliderBuilder::new(stand_in()).mass_properties(exact.mass_properties(1.0)),
            RestVariant::ParryOwnMass => ColliderBuilder::new(stand_in()),
        };
        c.friction(FRICTION)
    }

    /// The collider of a rounded polygon (stand-in: parry's `RoundConvexPolygon`).
    fn rounded(self, p: RoundedPolygon) -> ColliderBuilder {
        let stand_in = p.to_parry().expect("a convex polygon");
        self.collider(SharedShape::new(p), || SharedShape::new(stand_in))
    }

    /// The collider of an ellipse (stand-in: its inscribed [`POLYGON_VERTICES`]-gon).
    fn ellipse(self, e: Ellipse) -> ColliderBuilder {
        self.collider(SharedShape::new(e), || {
            SharedShape::new(polygon_approximation(&e, POLYGON_VERTICES))
        })
    }
}

/// A dynamic body of a resting scene and where it started (its rest position).
#[derive(Clone, Copy, Debug)]
pub struct RestBody {
    /// The body.
    pub handle: RigidBodyHandle,
    /// Its starting (rest) position.
    pub start: Vector,
    /// Its starting angle.
    pub angle: f64,
    /// Its width along the surface it rests on (toppled: displaced by more than half of it).
    pub width: f64,
}

/// A resting scene built in a [`World`].
pub struct Resting {
    /// The world.
    pub world: World,
    /// The dynamic bodies, bottom first.
    pub bodies: Vec<RestBody>,
    /// The unit vector down the slope (the slope scene only).
    pub downhill: Option<Vector>,
}

/// Inserts the fixed ground box, its top face through the origin with outward normal at angle
/// `tilt` from +y (turned counter-clockwise), friction [`FRICTION`].
fn insert_ground(world: &mut World, tilt: f64) {
    let normal = Vector::new(-tilt.sin(), tilt.cos());
    world.insert(
        RigidBodyBuilder::fixed()
            .translation(-GROUND_HALF.1 * normal)
            .rotation(tilt),
        ColliderBuilder::cuboid(GROUND_HALF.0, GROUND_HALF.1).friction(FRICTION),
    );
}

/// Inserts a dynamic body of `collider` at `start`, turned by `angle`, at rest, never asleep.
fn insert_body(world: &mut World, collider: ColliderBuilder, start: Vector, angle: f64, width: f64) -> RestBody {
    let (handle, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(start)
            .rotation(angle)
            .can_sleep(false),
        collider,
    );
    RestBody {
        handle,
        start,
        angle,
        width,
    }
}

/// The rounded box of the box stack: core half-extents [`BOX_HALF`] minus [`BOX_RADIUS`].
pub fn rounded_box() -> RoundedPolygon {
    let (hx, hy) = (BOX_HALF.0 - BOX_RADIUS, BOX_HALF.1 - BOX_RADIUS);
    let core = [
        Vector::new(-hx, -hy),
        Vector::new(hx, -hy),
        Vector::new(hx, hy),
        Vector::new(-hx, hy),
    ];
    RoundedPolygon::new(&core, BOX_RADIUS)
}

/// Builds `scene` as `variant`: every body exactly at its rest position (touching, distance 0).
pub fn build(scene: RestScene, variant: RestVariant) -> Resting {
    let mut world = World::new(variant.narrow_phase());
    let mut bodies = Vec::new();
    let mut downhill = None;
    match scene {
        RestScene::BoxStack => {
            insert_ground(&mut world, 0.0);
            for k in 0..STACK_BODIES {
                let y = BOX_HALF.1 * (2 * k + 1) as f64;
                let collider = variant.rounded(rounded_box());
                bodies.push(insert_body(
                    &mut world,
                    collider,
                    Vector::new(0.0, y),
                    0.0,
                    2.0 * BOX_HALF.0,
                ));
            }
        }
        RestScene::EllipseStack => {
            insert_ground(&mut world, 0.0);
            for k in 0..STACK_BODIES {
                let y = ELLIPSE_HALF.1 * (2 * k + 1) as f64;
                let collider = variant.ellipse(Ellipse::new(ELLIPSE_HALF.0, ELLIPSE_HALF.1));
                let width = 2.0 * ELLIPSE_HALF.0;
                bodies.push(insert_body(&mut world, collider, Vector::new(0.0, y), 0.0, width));
            }
        }
        RestScene::Slope => {
            let tilt = SLOPE_DEG.to_radians();
            insert_ground(&mut world, tilt);
            // regular(6, ..) has a vertex at angle 0, so a flat side at the bottom; turned by the
            // tilt, that side lies on the slope. Centre: the apothem plus the corner radius out
            // along the slope's normal.
            let (r, c) = HEXAGON;
            let apothem = r * (std::f64::consts::PI / 6.0).cos() + c;
            let normal = Vector::new(-tilt.sin(), tilt.cos());
            let collider = variant.rounded(RoundedPolygon::regular(6, r, c));
            bodies.push(insert_body(&mut world, collider, apothem * normal, tilt, 2.0 * (r + c)));
            downhill = Some(Vector::new(-tilt.cos(), -tilt.sin()));
        }
    }
    Resting {
        world,
        bodies,
        downhill,
    }
}

/// The most negative contact `dist` over every contact point of the narrow phase's manifolds, 0
/// when none is negative (none penetrating).
pub fn manifold_penetration(world: &World) -> f64 {
    let mut worst: f64 = 0.0;
    for pair in world.narrow_phase.contact_pairs() {
        for m in pair.manifolds() {
            for p in &m.points {
                worst = worst.min(p.dist);
            }
        }
    }
    worst
}

/// The most negative exact signed distance of the collider shapes of the narrow phase's pairs
/// with contact points, at the colliders' current poses (`SmoothDispatcher::contact`); 0 when
/// none overlaps.
pub fn exact_penetration(world: &World) -> f64 {
    let d = SmoothDispatcher::default();
    let mut worst: f64 = 0.0;
    for pair in world.narrow_phase.contact_pairs() {
        if pair.manifolds().iter().all(|m| m.points.is_empty()) {
            continue;
        }
        let (c1, c2) = (&world.colliders[pair.collider1], &world.colliders[pair.collider2]);
        let pos12 = c1.position().inv_mul(c2.position());
        if let Ok(Some(c)) = d.contact(&pos12, c1.shape(), c2.shape(), 0.0) {
            worst = worst.min(c.dist);
        }
    }
    worst
}

/// What one run of a resting scene measured.
#[derive(Clone, Copy, Debug)]
pub struct RestReport {
    /// The scene.
    pub scene: RestScene,
    /// The variant.
    pub variant: RestVariant,
    /// Max over bodies of |final − start position| (m).
    pub drift: f64,
    /// Max over bodies of the horizontal part of it (m).
    pub horizontal_drift: f64,
    /// Max over bodies of |final − start angle| (rad).
    pub turn: f64,
    /// The slope scene: distance slid down the slope (m; negative: up); 0 for the stacks.
    pub slope_slide: f64,
    /// Most negative manifold contact `dist` over the run (m).
    pub worst_manifold: f64,
    /// Mean over the last second of each step's most negative manifold `dist` (m).
    pub mean_manifold_last: f64,
    /// Most negative exact signed distance of a touching pair over the run (m).
    pub worst_exact: f64,
    /// Mean over the last second of each step's most negative exact signed distance (m).
    pub mean_exact_last: f64,
    /// Max linear speed of a body after the last step (m/s).
    pub end_speed: f64,
    /// Whether a body ended displaced by more than half its width.
    pub toppled: bool,
}

/// Runs `scene` as `variant` for `steps` steps, rapier's contact recycling as `recycling`.
pub fn run_scene(scene: RestScene, variant: RestVariant, steps: usize, recycling: bool) -> RestReport {
    let mut r = build(scene, variant);
    r.world.params.contact_recycling = recycling;
    let (mut worst_manifold, mut worst_exact) = (0.0f64, 0.0f64);
    let (mut sum_manifold, mut sum_exact, mut last) = (0.0, 0.0, 0usize);
    for step in 1..=steps {
        r.world.step(GRAVITY, &());
        let (m, e) = (manifold_penetration(&r.world), exact_penetration(&r.world));
        worst_manifold = worst_manifold.min(m);
        worst_exact = worst_exact.min(e);
        if step + LAST_SECOND > steps {
            sum_manifold += m;
            sum_exact += e;
            last += 1;
        }
    }
    let (mut drift, mut horizontal_drift, mut turn, mut end_speed) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let (mut slope_slide, mut toppled) = (0.0, false);
    for b in &r.bodies {
        let rb = &r.world.bodies[b.handle];
        let d = rb.translation() - b.start;
        drift = drift.max(d.length());
        turn = turn.max((rb.rotation().angle() - b.angle).abs());
        end_speed = end_speed.max(rb.linvel().length());
        match r.downhill {
            Some(down) => {
                slope_slide = d.dot(down);
                horizontal_drift = horizontal_drift.max(d.x.abs());
            }
            None => horizontal_drift = horizontal_drift.max(d.x.abs()),
        }
        toppled |= d.length() > 0.5 * b.width;
    }
    let last = last.max(1) as f64;
    RestReport {
        scene,
        variant,
        drift,
        horizontal_drift,
        turn,
        slope_slide,
        worst_manifold,
        mean_manifold_last: sum_manifold / last,
        worst_exact,
        mean_exact_last: sum_exact / last,
        end_speed,
        toppled,
    }
}

/// The markdown table of resting reports: one row per scene and variant.
pub fn rest_table(reports: &[RestReport]) -> String {
    let mut s = String::new();
    s.push_str(
        "| scene | narrow phase | max drift (m) | max horizontal drift (m) | max turn (rad) | slope slide (m) \
         | worst penetration, manifolds (m) | mean penetration last second, manifolds (m) \
         | worst penetration, exact (m) | mean penetration last second, exact (m) | max speed at end (m/s) \
         | toppled |\n",
    );
    s.push_str("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for r in reports {
        let slide = if r.scene == RestScene::Slope {
            format!("{:.3e}", r.slope_slide)
        } else {
            "–".to_string()
        };
        let _ = writeln!(
            s,
            "| {} | {} | {:.3e} | {:.3e} | {:.3e} | {slide} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {} |",
            r.scene.label(),
            r.variant.label(),
            r.drift,
            r.horizontal_drift,
            r.turn,
            r.worst_manifold,
            r.mean_manifold_last,
            r.worst_exact,
            r.mean_exact_last,
            r.end_speed,
            if r.toppled { "yes" } else { "no" },
        );
    }
    s
}

// ---------------------------------------------------------------------------------------------
// The box pile at rest
// ---------------------------------------------------------------------------------------------

/// The pile is at rest once every point of every body moves slower than this (m/s: the
/// body's linear speed plus its angular speed times its bounding radius) …
pub const PILE_REST_SPEED: f64 = 0.01;
/// … for this many consecutive steps.
pub const PILE_REST_WINDOW: usize = 30;
/// The steps over which the pile's step time is compared across runs: falling, then piling up,
/// before any run has come to rest (rapier's sleeping bodies cost almost nothing, so a pile that
/// falls asleep earlier would have cheaper steps after that).
pub const PILE_TIMED_STEPS: usize = 200;
/// How much trial `k` turns every pile body's starting angle by: `k` times this (rad). The pile
/// is chaotic, so each trial is another sample of the same scene.
pub const PILE_TRIAL_TURN: f64 = 1e-6;

/// What a run of the box pile measured until rest.
#[derive(Clone, Copy, Debug)]
pub struct PileRest {
    /// The shapes, masses and narrow phase.
    pub variant: RestVariant,
    /// rapier's contact recycling.
    pub recycling: bool,
    /// The trial (0: the pile of `examples/pile.rs` as it is).
    pub trial: usize,
    /// Steps run.
    pub steps: usize,
    /// The first step of the first [`PILE_REST_WINDOW`] consecutive steps with every body
    /// slower than [`PILE_REST_SPEED`]; `None` if not at rest within the run.
    pub rest_step: Option<usize>,
    /// The first step after which every body was asleep (rapier's sleeping).
    pub asleep_step: Option<usize>,
    /// Bodies asleep at the end.
    pub asleep_end: usize,
    /// Wall time of `PhysicsPipeline::step` summed over the first [`PILE_TIMED_STEPS`] steps (s).
    pub timed: f64,
    /// Wall time of `PhysicsPipeline::step` summed over the run (s).
    pub total: f64,
    /// The longest step (s).
    pub max_step: f64,
    /// Most negative manifold contact `dist` over the run (m).
    pub worst_manifold: f64,
}

/// Inserts the box pile's box and `bodies` as `variant` (the exact shapes and parry's own
/// stand-ins through `scenes::insert_pile`, as `examples/pile.rs` and `benches/support/pile.rs`).
fn insert_pile_as(world: &mut World, bodies: &[PileBody], variant: RestVariant) -> Vec<RigidBodyHandle> {
    match variant {
        RestVariant::Exact => insert_pile(world, bodies, PileShape::shared),
        RestVariant::ParryOwnMass => insert_pile(world, bodies, pile_polygonal),
        RestVariant::Parry => {
            insert_pile(world, &[], pile_polygonal);
            bodies
                .iter()
                .map(|b| {
                    let body = RigidBodyBuilder::dynamic()
                        .translation(b.translation)
                        .rotation(b.rotation)
                        .angvel(b.angvel);
                    let collider = variant.collider(b.shape.shared(), || pile_polygonal(&b.shape));
                    world.insert(body, collider).0
                })
                .collect()
        }
    }
}

/// Drops the box pile (`scenes::pile_bodies`, 200 bodies, sleeping on, every starting angle turned
/// by `trial` × [`PILE_TRIAL_TURN`]) as `variant`, contact recycling as `recycling`, until it is
/// at rest and asleep (and at least [`PILE_TIMED_STEPS`] steps have run) or after `max_steps`
/// steps.
pub fn pile_rest(variant: RestVariant, recycling: bool, trial: usize, max_steps: usize) -> PileRest {
    let mut world = World::new(variant.narrow_phase());
    world.params.contact_recycling = recycling;
    let mut pile = pile_bodies();
    for b in &mut pile {
        b.rotation += trial as f64 * PILE_TRIAL_TURN;
    }
    let handles = insert_pile_as(&mut world, &pile, variant);
    let radii: Vec<f64> = pile.iter().map(|b| b.shape.curve().bounding_radius()).collect();
    let mut r = PileRest {
        variant,
        recycling,
        trial,
        steps: 0,
        rest_step: None,
        asleep_step: None,
        asleep_end: 0,
        timed: 0.0,
        total: 0.0,
        max_step: 0.0,
        worst_manifold: 0.0,
    };
    let mut quiet = 0usize;
    let settled = |r: &PileRest| r.rest_step.is_some() && r.asleep_step.is_some() && r.steps >= PILE_TIMED_STEPS;
    while r.steps < max_steps && !settled(&r) {
        let t = Instant::now();
        world.step(GRAVITY, &());
        let dt = t.elapsed().as_secs_f64();
        r.steps += 1;
        r.total += dt;
        if r.steps <= PILE_TIMED_STEPS {
            r.timed += dt;
        }
        r.max_step = r.max_step.max(dt);
        r.worst_manifold = r.worst_manifold.min(manifold_penetration(&world));
        let fastest = handles
            .iter()
            .zip(&radii)
            .map(|(h, radius)| {
                let rb = &world.bodies[*h];
                rb.linvel().length() + rb.angvel().abs() * radius
            })
            .fold(0.0f64, f64::max);
        quiet = if fastest < PILE_REST_SPEED { quiet + 1 } else { 0 };
        if r.rest_step.is_none() && quiet >= PILE_REST_WINDOW {
            r.rest_step = Some(r.steps + 1 - PILE_REST_WINDOW);
        }
        if r.asleep_step.is_none() && handles.iter().all(|h| world.bodies[*h].is_sleeping()) {
            r.asleep_step = Some(r.steps);
        }
    }
    r.asleep_end = handles.iter().filter(|h| world.bodies[**h].is_sleeping()).count();
    r
}

/// Steps as "k (t s)", or "–" when the run did not get there.
fn steps_list(steps: impl Iterator<Item = Option<usize>>) -> String {
    let v: Vec<String> = steps
        .map(|s| s.map_or("–".to_string(), |k| format!("{k} ({:.1} s)", k as f64 / 60.0)))
        .collect();
    v.join(", ")
}

/// The markdown table of pile runs, one row per variant and recycling setting (their trials
/// side by side, in the order given).
pub fn pile_table(runs: &[PileRest]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "| shapes and narrow phase | contact recycling | at rest from step, per trial | all asleep at step, per \
         trial | asleep at the end | mean step, first {PILE_TIMED_STEPS} steps (ms) | mean step, whole run (ms) \
         | max step (ms) | worst penetration, manifolds (m) |",
    );
    s.push_str("|---|---|---|---|---|---:|---:|---:|---:|\n");
    let mut keys: Vec<(RestVariant, bool)> = Vec::new();
    for r in runs {
        if !keys.contains(&(r.variant, r.recycling)) {
            keys.push((r.variant, r.recycling));
        }
    }
    for (variant, recycling) in keys {
        let rows: Vec<&PileRest> = runs
            .iter()
            .filter(|r| r.variant == variant && r.recycling == recycling)
            .collect();
        let n = rows.len() as f64;
        let asleep: Vec<String> = rows.iter().map(|r| r.asleep_end.to_string()).collect();
        let timed = rows
            .iter()
            .map(|r| r.timed / r.steps.min(PILE_TIMED_STEPS) as f64)
            .sum::<f64>()
            / n;
        let whole = rows.iter().map(|r| r.total / r.steps as f64).sum::<f64>() / n;
        let max_step = rows.iter().map(|r| r.max_step).fold(0.0f64, f64::max);
        let worst = rows.iter().map(|r| r.worst_manifold).fold(0.0f64, f64::min);
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {:.3} | {:.3} | {:.3} | {:.3e} |",
            variant.label(),
            if recycling { "on" } else { "off" },
            steps_list(rows.iter().map(|r| r.rest_step)),
            steps_list(rows.iter().map(|r| r.asleep_step)),
            asleep.join(", "),
            1e3 * timed,
            1e3 * whole,
            1e3 * max_step,
            worst,
        );
    }
    s
}
