//! Runs the cases of the CCD scene suite (`ccd_scenes.rs`) and judges each step:
//!
//! * **through**: a body's centre, on its straight path over one step, crosses a `Segment` or a
//!   `Polyline` edge or meets the inside of a solid: fixed geometry, and the bodies a bullet
//!   sweeps (dynamic bodies that are not bullets, at their end pose, as rapier casts them, among
//!   rapier's candidates: a body whose box at the step's start meets the bullet's swept box);
//! * **passed** (not a failure of the case; what rapier's CCD does not look at, two moving
//!   bodies): a body's centre entering a moving body on the path taken in that body's frame,
//!   followed in [`MOVING_SAMPLES`] pieces against its pose interpolated as rapier interpolates
//!   a clamped body;
//! * **frozen**: a body whose fastest point moves at 1 m/s or more (|v| + |ω|·R, R its radius)
//!   moves less than 0.1 % of that speed × dt (|Δc| + |Δθ|·R) for 10 steps in a row;
//! * **NaN** in a body's pose or velocity, and **panics** (caught);
//! * **deepest**: after every step in which rapier's CCD swept a body (`is_ccd_active`), that
//!   body's deepest penetration into anything it sweeps, by the method's own contact query, as a
//!   fraction of its `ccd_thickness` too;
//! * **apart**: after such a step of a launched body (CCD on; this crate's shape with
//!   `SmoothDispatcher`), its deepest penetration into a fixed target it was
//!   apart from at the step's start (by more than [`APART_GAP`] of the pair's size): rapier's
//!   CCD stops the body where it touches, so this is the cast's exactness on the pose rapier
//!   applies — but for a target rapier's candidate search never hands the cast;
//! * **centre**: after such a step of a launched body, the least signed distance from its centre of mass to
//!   a fixed target's solid, as a fraction of its `ccd_thickness` (what the start-contact rule's
//!   core keeps: at least an eighth with `SmoothDispatcher`);
//! * the time of each `PhysicsPipeline::step` (with the pass `MovingPairs` around it when the
//!   case asks for it, [`Case::moving_pairs`]).
#![allow(dead_code)]

use super::ccd_scenes::{
    build, drive, recorded_casts, shape_address, start_recording, Case, Family, Method, Scene, DT,
};
use parry2d_f64::bounding_volume::BoundingVolume;
use parry2d_f64::query::sweep_toi::Sweep;
use parry2d_f64::query::{DefaultQueryDispatcher, QueryDispatcher, Ray};
use parry2d_f64::shape::{Shape, TypedShape};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{MovingPairs, SmoothDispatcher};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::Instant;

/// Steps in a row a fast body must stay (almost) still to be frozen.
pub const FROZEN_STEPS: usize = 10;
/// The speed (m/s, of a body's fastest point) from which a still body is frozen.
pub const FROZEN_SPEED: f64 = 1.0;
/// A body moving less than this fraction of its speed × dt in a step is still.
pub const FROZEN_FRACTION: f64 = 1e-3;
/// Pieces of a step in which a centre's path is followed against a moving target.
pub const MOVING_SAMPLES: usize = 16;

/// What one case did under one method.
#[derive(Clone, Debug, Default)]
pub struct Outcome {
    /// The first step at which a body went through something, and what (a description).
    pub through: Option<(usize, String)>,
    /// The first step at which a bullet passed a moving body (what rapier's CCD does not look
    /// at: counted apart, not a failure of the case).
    pub passed: Option<(usize, String)>,
    /// The first step at which a body had been frozen for [`FROZEN_STEPS`] steps.
    pub frozen: Option<usize>,
    /// The first step with a non-finite pose or velocity.
    pub nan: Option<usize>,
    /// The panic's message, if the case panicked.
    pub panicked: Option<String>,
    /// The deepest penetration after a CCD-swept step (m), and as a fraction of the body's
    /// `ccd_thickness`.
    pub deepest: f64,
    pub deepest_rel: f64,
    /// Of the pairs (a CCD-swept body, a fixed target) apart at the step's start, the deepest
    /// penetration at the step's end (m): rapier's CCD stops such a body at the touching pose.
    pub apart_deepest: f64,
    /// The same, of the pairs rapier asked the dispatcher to cast in that step
    /// (`SmoothDispatcher`'s casts recorded, `ccd_scenes::CastRecorder`; for rapier's default,
    /// whose casts of its own shapes do not go through a dispatcher, every pair): the
    /// dispatcher's answers alone, without the targets rapier's candidate search never offers.
    pub asked_apart_deepest: f64,
    /// The closest a CCD-swept body's centre of mass came to a fixed target at the end of a
    /// step (signed distance to the target's solid, as a fraction of the body's
    /// `ccd_thickness`; `INFINITY` when no swept body ended a step near one).
    pub centre_clearance: f64,
    /// Seconds spent in `PhysicsPipeline::step`, and the steps run.
    pub seconds: f64,
    pub steps: usize,
}

impl Outcome {
    /// Whether the case went wrong in any way the suite counts.
    pub fn failed(&self) -> bool {
        self.through.is_some() || self.frozen.is_some() || self.nan.is_some() || self.panicked.is_some()
    }
}

/// A body's state before a step.
#[derive(Clone, Copy)]
struct Before {
    com: Vector,
    rot: Rotation,
}

/// A target of the through test: a collider and whether its body moves.
struct Target {
    collider: ColliderHandle,
    body: Option<RigidBodyHandle>,
}

/// Runs `case` under `method` and judges it; a panic is caught and reported.
pub fn run_case(case: &Case, method: Method) -> Outcome {
    match catch_unwind(AssertUnwindSafe(|| run_inner(case, method))) {
        Ok(o) => o,
        Err(e) => Outcome {
            panicked: Some(
                e.downcast_ref::<String>()
                    .cloned()
                    .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_else(|| "panic".into()),
            ),
            centre_clearance: f64::INFINITY,
            ..Outcome::default()
        },
    }
}

fn run_inner(case: &Case, method: Method) -> Outcome {
    let mut scene = build(case, method);
    let mut out = Outcome {
        centre_clearance: f64::INFINITY,
        ..Outcome::default()
    };
    let mut still = vec![0usize; scene.dynamic.len()];
    // This crate's pass for two moving bodies around each step, when the case asks for it.
    let mut pass = (case.moving_pairs && method == Method::Smooth).then(MovingPairs::default);
    let radii: Vec<f64> = scene.dynamic.iter().map(|h| body_radius(&scene, *h, case)).collect();
    for step in 0..scene.steps {
        drive(&mut scene, step);
        let before: Vec<Before> = scene
            .dynamic
            .iter()
            .map(|h| {
                let rb = &scene.world.bodies[*h];
                Before {
                    com: rb.center_of_mass(),
                    rot: *rb.rotation(),
                }
            })
            .collect();
        let poses_before: Vec<(ColliderHandle, Pose)> = scene
            .world
            .colliders
            .iter()
            .map(|(h, co)| (h, *co.position()))
            .collect();
        let apart = apart_pairs(&scene, method);
        start_recording();
        let t = Instant::now();
        if let Some(p) = pass.as_mut() {
            p.before_step(&scene.world.bodies);
        }
        scene.world.step(scene.gravity, &());
        if let Some(p) = pass.as_mut() {
            let w = &mut scene.world;
            p.after_step(&w.params, &mut w.bodies, &mut w.colliders, &(), &());
        }
        out.seconds += t.elapsed().as_secs_f64();
        out.steps += 1;
        if let Some(k) = first_non_finite(&scene) {
            let _ = k;
            out.nan = Some(step);
            break;
        }
        if out.through.is_none() || out.passed.is_none() {
            let (th, pa) = through(&scene, &before, &poses_before);
            if out.through.is_none() {
                out.through = th.map(|what| (step, what));
            }
            if out.passed.is_none() {
                out.passed = pa.map(|what| (step, what));
            }
        }
        for (i, h) in scene.dynamic.iter().enumerate() {
            let rb = &scene.world.bodies[*h];
            let r = radii[i];
            let (speed, moved) = if std::env::var("STRICT").is_ok() {
                let turn = (*rb.rotation() * before[i].rot.inverse()).angle().abs();
                (
                    rb.linvel().length() + rb.angvel().abs() * r,
                    (rb.center_of_mass() - before[i].com).length() + turn * r,
                )
            } else {
                (rb.linvel().length(), (rb.center_of_mass() - before[i].com).length())
            };
            if speed >= FROZEN_SPEED && moved < FROZEN_FRACTION * speed * DT {
                still[i] += 1;
                if still[i] >= FROZEN_STEPS && out.frozen.is_none() {
                    out.frozen = Some(step);
                }
            } else {
                still[i] = 0;
            }
        }
        let (d, rel) = deepest_after_sweep(&scene, method);
        if d > out.deepest {
            out.deepest = d;
        }
        out.deepest_rel = out.deepest_rel.max(rel);
        let asked = recorded_casts();
        let (apart_deepest, asked_apart_deepest, clearance) = after_sweep_checks(&scene, method, &apart, &asked);
        out.apart_deepest = out.apart_deepest.max(apart_deepest);
        out.asked_apart_deepest = out.asked_apart_deepest.max(asked_apart_deepest);
        out.centre_clearance = out.centre_clearance.min(clearance);
    }
    out
}

/// A body's distance from a fixed target at the step's start below which the pair counts as in
/// contact there, as a fraction of the pair's size (the sum of the two shapes' bounding radii):
/// `CastPolicy::Rapier` takes pairs within 10⁻⁶ of that size (of a part's, for a composite
/// target) as in contact; this is ten times wider, so that no pair the rule treats as in
/// contact is judged as apart.
pub const APART_GAP: f64 = 1e-5;

/// The method's dispatcher for the judge's own contact queries.
fn judge_dispatcher(method: Method) -> Box<dyn QueryDispatcher> {
    match method {
        Method::Smooth => Box::new(SmoothDispatcher::default()),
        Method::Rapier => Box::new(DefaultQueryDispatcher),
    }
}

/// The colliders of the scene's dynamic bodies that `keep` accepts, with their body's handle and
/// the body: the loop of the judge's per-step checks.
fn body_colliders<'a>(
    scene: &'a Scene,
    keep: impl Fn(&RigidBody) -> bool + 'a,
) -> impl Iterator<Item = (RigidBodyHandle, &'a RigidBody, ColliderHandle, &'a Collider)> + 'a {
    scene.dynamic.iter().flat_map(move |h| {
        let rb = &scene.world.bodies[*h];
        let colliders: &[ColliderHandle] = if keep(rb) { rb.colliders() } else { &[] };
        colliders.iter().map(move |c| (*h, rb, *c, &scene.world.colliders[*c]))
    })
}

/// The pairs (a collider of a CCD-enabled dynamic body, a fixed collider) apart at the step's
/// start by more than [`APART_GAP`] of the pair's size, by the method's contact query.
fn apart_pairs(scene: &Scene, method: Method) -> Vec<(ColliderHandle, ColliderHandle)> {
    let dispatcher = judge_dispatcher(method);
    let mut out = Vec::new();
    for (_, _, c, co1) in body_colliders(scene, |rb| rb.is_ccd_enabled()) {
        let radius = co1.shape().compute_local_bounding_sphere().radius;
        for t in &scene.fixed {
            let co2 = &scene.world.colliders[*t];
            let gap = APART_GAP * (radius + co2.shape().compute_local_bounding_sphere().radius);
            let pos12 = co1.position().inv_mul(co2.position());
            if let Ok(None) = dispatcher.contact(&pos12, co1.shape(), co2.shape(), gap) {
                out.push((c, *t));
            }
        }
    }
    out
}

/// After a step, for the CCD-enabled bodies (the launched ones) rapier's CCD swept in it: the
/// deepest penetration (m) into a fixed target of a pair that `apart` holds (apart at the step's
/// start), the same of the pairs among them whose shapes rapier asked the dispatcher to cast
/// (`asked`, [`recorded_casts`]; every pair for rapier's default), and the smallest signed
/// distance from the body's centre of mass to a fixed target's solid, over the body's
/// `ccd_thickness` (`INFINITY` if none).
fn after_sweep_checks(
    scene: &Scene,
    method: Method,
    apart: &[(ColliderHandle, ColliderHandle)],
    asked: &[(usize, usize)],
) -> (f64, f64, f64) {
    let dispatcher = judge_dispatcher(method);
    let (mut deepest, mut asked_deepest, mut clearance) = (0.0f64, 0.0f64, f64::INFINITY);
    // The case's launched bodies (CCD on: this crate's shapes with `SmoothDispatcher`), in the
    // steps rapier's CCD swept them.
    for (_, rb, c, co1) in body_colliders(scene, |rb| rb.is_ccd_enabled() && rb.is_ccd_active()) {
        for (_, t) in apart.iter().filter(|(b, _)| *b == c) {
            let co2 = &scene.world.colliders[*t];
            let pos12 = co1.position().inv_mul(co2.position());
            if let Ok(Some(k)) = dispatcher.contact(&pos12, co1.shape(), co2.shape(), 0.0) {
                deepest = deepest.max(-k.dist);
                let (a1, a2) = (shape_address(co1.shape()), shape_address(co2.shape()));
                if method == Method::Rapier || asked.iter().any(|&(x, y)| (x, y) == (a1, a2) || (x, y) == (a2, a1)) {
                    asked_deepest = asked_deepest.max(-k.dist);
                }
            }
        }
        let (com, thickness) = (rb.center_of_mass(), co1.shape().ccd_thickness());
        for t in &scene.fixed {
            let co2 = &scene.world.colliders[*t];
            let p = co2.position().inverse_transform_point(com);
            let proj = co2.shape().project_local_point(p, true);
            let d = (p - proj.point).length();
            let signed = if proj.is_inside { -d } else { d };
            if thickness > 0.0 {
                clearance = clearance.min(signed / thickness);
            }
        }
    }
    (deepest, asked_deepest, clearance)
}

/// The largest distance from a dynamic body's centre of mass to its boundary.
fn body_radius(scene: &Scene, h: RigidBodyHandle, case: &Case) -> f64 {
    if h == scene.dynamic[0] {
        return case.body.radius();
    }
    let rb = &scene.world.bodies[h];
    rb.colliders()
        .iter()
        .map(|c| {
            let co = &scene.world.colliders[*c];
            co.shape().compute_local_bounding_sphere().radius
                + co.position_wrt_parent().map_or(0.0, |p| p.translation.length())
        })
        .fold(0.0, f64::max)
}

/// The index of a dynamic body whose pose or velocity is not finite.
fn first_non_finite(scene: &Scene) -> Option<usize> {
    scene.dynamic.iter().position(|h| {
        let rb = &scene.world.bodies[*h];
        !(rb.translation().is_finite()
            && rb.rotation().re.is_finite()
            && rb.rotation().im.is_finite()
            && rb.linvel().is_finite()
            && rb.angvel().is_finite())
    })
}

/// The targets of body `h`: fixed geometry; for a bullet, the dynamic bodies that are not bullets.
fn targets(scene: &Scene, h: RigidBodyHandle) -> Vec<Target> {
    let mut out: Vec<Target> = scene
        .fixed
        .iter()
        .map(|c| Target {
            collider: *c,
            body: None,
        })
        .collect();
    if scene.world.bodies[h].is_ccd_enabled() {
        for o in &scene.dynamic {
            let rb = &scene.world.bodies[*o];
            if *o != h && !rb.is_ccd_enabled() {
                for c in rb.colliders() {
                    out.push(Target {
                        collider: *c,
                        body: Some(*o),
                    });
                }
            }
        }
    }
    out
}

/// Whether the path p0 → p1 crosses the segment a–b (strictly from one side to the other).
fn crosses(a: Vector, b: Vector, p0: Vector, p1: Vector) -> bool {
    let e = b - a;
    let s0 = e.perp_dot(p0 - a);
    let s1 = e.perp_dot(p1 - a);
    // Not strictly on both sides (NaN positions are counted apart, not as crossings).
    if s0 * s1 >= 0.0 || (s0 * s1).is_nan() {
        return false;
    }
    let p = p0 + (p1 - p0) * (s0 / (s0 - s1));
    let u = (p - a).dot(e) / e.length_squared();
    (0.0..=1.0).contains(&u)
}

/// Whether the straight path `p0` → `p1` (in a collider's frame) crosses its `Segment` or
/// `Polyline` edges or meets the inside of its solid shape.
fn path_hits(shape: &dyn Shape, p0: Vector, p1: Vector) -> bool {
    match shape.as_typed_shape() {
        TypedShape::Segment(s) => crosses(s.a, s.b, p0, p1),
        TypedShape::Polyline(p) => p.segments().any(|s| crosses(s.a, s.b, p0, p1)),
        _ => {
            let d = p1 - p0;
            if d.length() > 0.0 {
                shape.intersects_local_ray(&Ray::new(p0, d), 1.0)
            } else {
                shape.contains_local_point(p1)
            }
        }
    }
}

/// What went through what in one step: (through, passed), each the first such event described.
///
/// * **through** (what rapier's CCD answers for): a body's centre path crossing fixed geometry,
///   or, for a bullet, entering a dynamic body that is not a bullet at that body's end-of-step
///   pose (rapier sweeps a bullet against its targets taken still at their end pose);
/// * **passed** (what rapier's CCD never looks at, two moving bodies): a bullet's centre meeting a
///   moving dynamic body along their relative motion — both poses interpolated over the step in
///   [`MOVING_SAMPLES`] pieces as rapier interpolates a clamped body — without it being a
///   `through`.
fn through(
    scene: &Scene,
    before: &[Before],
    poses_before: &[(ColliderHandle, Pose)],
) -> (Option<String>, Option<String>) {
    let pose_before = |c: ColliderHandle| poses_before.iter().find(|(h, _)| *h == c).map(|(_, p)| *p);
    let mut passed = None;
    for (i, h) in scene.dynamic.iter().enumerate() {
        let c0 = before[i].com;
        let c1 = scene.world.bodies[*h].center_of_mass();
        for t in targets(scene, *h) {
            let co = &scene.world.colliders[t.collider];
            let (Some(pose0), pose1) = (pose_before(t.collider), *co.position()) else {
                continue;
            };
            let describe = |what: &str| {
                format!(
                    "body {i} {what} ({:?}) from {:?} to {:?}",
                    co.shape().shape_type(),
                    c0,
                    c1
                )
            };
            let (e0, e1) = (pose1.inverse_transform_point(c0), pose1.inverse_transform_point(c1));
            match t.body {
                None => {
                    if path_hits(co.shape(), e0, e1) {
                        return (Some(describe("through fixed geometry")), passed);
                    }
                }
                Some(b) => {
                    // rapier's contract: the target still at its end pose, entered from outside —
                    // for the targets rapier casts against: its candidates are the bodies whose
                    // box in its tree (where they were at the step's start) meets the bullet's
                    // swept box; a body that came into the path during the step is a moving
                    // pair rapier never looked at (counted as passed below).
                    let shape = co.shape();
                    let swept = shape_box(scene, *h, before[i].com, c1);
                    let candidate = swept.is_none_or(|b| shape.compute_aabb(&pose0).intersects(&b));
                    if candidate && !shape.contains_local_point(e0) && path_hits(shape, e0, e1) {
                        return (Some(describe("through a dynamic body at its end pose")), passed);
                    }
                    if passed.is_none() {
                        let com = co
                            .position()
                            .inverse_transform_point(scene.world.bodies[b].center_of_mass());
                        let sweep = Sweep::from_poses(&pose0, &pose1, com);
                        let local = |k: usize| {
                            let s = k as f64 / MOVING_SAMPLES as f64;
                            sweep.transform_at(s).inverse_transform_point(c0.lerp(c1, s))
                        };
                        if (0..MOVING_SAMPLES).any(|k| path_hits(co.shape(), local(k), local(k + 1))) {
                            passed = Some(describe("passed a moving body"));
                        }
                    }
                }
            }
        }
    }
    (None, passed)
}

/// The box a body's bounding circle sweeps from centre `c0` to centre `c1` (`None` for a body
/// without a collider).
fn shape_box(
    scene: &Scene,
    body: RigidBodyHandle,
    c0: Vector,
    c1: Vector,
) -> Option<parry2d_f64::bounding_volume::Aabb> {
    let co = scene.world.bodies[body].colliders().first()?;
    let shape = scene.world.colliders[*co].shape();
    let sphere = shape.compute_local_bounding_sphere();
    let r = Vector::splat(sphere.radius + sphere.center.length());
    Some(parry2d_f64::bounding_volume::Aabb::new(c0.min(c1) - r, c0.max(c1) + r))
}

/// The deepest penetration, after this step, of a body rapier's CCD swept in it into its
/// targets (m, and as a fraction of its `ccd_thickness`), by the method's contact query.
fn deepest_after_sweep(scene: &Scene, method: Method) -> (f64, f64) {
    let dispatcher = judge_dispatcher(method);
    let (mut deepest, mut rel) = (0.0f64, 0.0f64);
    for (h, _, _, co1) in body_colliders(scene, |rb| rb.is_ccd_active()) {
        let thickness = co1.shape().ccd_thickness();
        for t in targets(scene, h) {
            let co2 = &scene.world.colliders[t.collider];
            let pos12 = co1.position().inv_mul(co2.position());
            if let Ok(Some(k)) = dispatcher.contact(&pos12, co1.shape(), co2.shape(), 0.0) {
                if k.dist < 0.0 {
                    deepest = deepest.max(-k.dist);
                    if thickness > 0.0 {
                        rel = rel.max(-k.dist / thickness);
                    }
                }
            }
        }
    }
    (deepest, rel)
}

/// The tally of a set of outcomes.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    pub cases: usize,
    pub through: usize,
    pub passed: usize,
    pub frozen: usize,
    pub nan: usize,
    pub panicked: usize,
    pub deepest: f64,
    pub deepest_rel: f64,
    pub apart_deepest: f64,
    pub asked_apart_deepest: f64,
    pub centre_clearance: f64,
    pub seconds: f64,
    pub steps: usize,
}

impl Tally {
    /// Adds one outcome.
    pub fn add(&mut self, o: &Outcome) {
        self.cases += 1;
        self.through += o.through.is_some() as usize;
        self.passed += o.passed.is_some() as usize;
        self.frozen += o.frozen.is_some() as usize;
        self.nan += o.nan.is_some() as usize;
        self.panicked += o.panicked.is_some() as usize;
        self.deepest = self.deepest.max(o.deepest);
        self.deepest_rel = self.deepest_rel.max(o.deepest_rel);
        self.apart_deepest = self.apart_deepest.max(o.apart_deepest);
        self.asked_apart_deepest = self.asked_apart_deepest.max(o.asked_apart_deepest);
        // The first outcome's, then the least.
        self.centre_clearance = if self.cases == 1 {
            o.centre_clearance
        } else {
            self.centre_clearance.min(o.centre_clearance)
        };
        self.seconds += o.seconds;
        self.steps += o.steps;
    }

    /// Mean time per step, µs.
    pub fn step_us(&self) -> f64 {
        1e6 * self.seconds / self.steps.max(1) as f64
    }
}

/// The outcomes of every case of `cases` under both methods (this crate's first), each case run
/// under both methods in turn so that the machine's load is shared evenly.
pub fn run_all(cases: &[Case]) -> Vec<[Outcome; 2]> {
    cases
        .iter()
        .map(|c| [run_case(c, Method::Smooth), run_case(c, Method::Rapier)])
        .collect()
}

/// The table of `outcomes` by family, one row per family and method and a total row per method,
/// with the step-time ratio (this crate's mean step time over rapier's).
pub fn table(cases: &[Case], outcomes: &[[Outcome; 2]]) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<18} {:<17} {:>5} {:>7} {:>6} {:>6} {:>4} {:>6} {:>9} {:>9} {:>9} {:>7} {:>8} {:>6}",
        "family",
        "method",
        "cases",
        "through",
        "frozen",
        "passed",
        "NaN",
        "panics",
        "deepest m",
        "/ thick",
        "apart m",
        "centre",
        "step us",
        "ratio"
    );
    let mut totals = [Tally::default(), Tally::default()];
    let rows = |name: &str, tallies: &[Tally; 2], s: &mut String| {
        let ratio = tallies[0].step_us() / tallies[1].step_us();
        for (m, t) in Method::BOTH.iter().zip(tallies) {
            let r = if *m == Method::Smooth {
                format!("{ratio:.2}")
            } else {
                String::new()
            };
            let _ = writeln!(
                s,
                "{:<18} {:<17} {:>5} {:>7} {:>6} {:>6} {:>4} {:>6} {:>9.2e} {:>9.3} {:>9.2e} {:>7.3} {:>8.1} {:>6}",
                name,
                m.name(),
                t.cases,
                t.through,
                t.frozen,
                t.passed,
                t.nan,
                t.panicked,
                t.deepest,
                t.deepest_rel,
                t.apart_deepest,
                t.centre_clearance,
                t.step_us(),
                r
            );
        }
    };
    for f in Family::ALL {
        let mut tallies = [Tally::default(), Tally::default()];
        for (c, o) in cases.iter().zip(outcomes) {
            if c.family == f {
                for k in 0..2 {
                    tallies[k].add(&o[k]);
                    totals[k].add(&o[k]);
                }
            }
        }
        if tallies[0].cases > 0 {
            rows(f.name(), &tallies, &mut s);
        }
    }
    rows("all", &totals, &mut s);
    // The cases neither method fails: the cost of the same work, where rapier's default has
    // not let its body out of the scene (a body gone has no contacts left to pay for).
    let mut both = [Tally::default(), Tally::default()];
    for o in outcomes.iter().filter(|o| !o[0].failed() && !o[1].failed()) {
        for k in 0..2 {
            both[k].add(&o[k]);
        }
    }
    rows("all, both pass", &both, &mut s);
    s
}
