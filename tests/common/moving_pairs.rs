//! The moving-pairs scenes' world and judge (issue 30): every shape family of the crate and of
//! parry ([`Family`]), bodies launched in a rapier world without gravity, rapier's caps lifted
//! ([`Run`], with or without the pass `MovingPairs`), and the judge of pairs that passed
//! through each other ([`Judge`]). The scenes themselves are in `moving_scenes.rs`.
#![allow(dead_code)]

use super::curves::EccentricEllipse;
use super::world::World;
use parry2d_f64::query::QueryDispatcher;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{
    CapsuleEllipse, CoreContactHooks, CustomCurve, Ellipse, MovingPairs, MovingPairsOptions, MovingPairsReport,
    OneBounceHooks, RoundedPolygon, SmoothDispatcher,
};
use std::time::{Duration, Instant};

/// A shape family: this crate's four and five of parry's own shapes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    Ellipse,
    Heptagon,
    CapsuleEllipse,
    UserCurve,
    Ball,
    Cuboid,
    Capsule,
    Triangle,
    Hexagon,
    /// A parry cuboid 3 m × 0.05 m (not in [`Family::ALL`]: the plank shots' plank).
    Plank,
}

impl Family {
    /// Every family.
    pub const ALL: [Family; 9] = [
        Family::Ellipse,
        Family::Heptagon,
        Family::CapsuleEllipse,
        Family::UserCurve,
        Family::Ball,
        Family::Cuboid,
        Family::Capsule,
        Family::Triangle,
        Family::Hexagon,
    ];

    /// The name in tables.
    pub fn name(self) -> &'static str {
        match self {
            Family::Ellipse => "ellipse",
            Family::Heptagon => "rounded heptagon",
            Family::CapsuleEllipse => "capsule-ellipse",
            Family::UserCurve => "user curve",
            Family::Ball => "parry ball",
            Family::Cuboid => "parry cuboid",
            Family::Capsule => "parry capsule",
            Family::Triangle => "parry triangle",
            Family::Hexagon => "parry hexagon",
            Family::Plank => "plank",
        }
    }

    /// The collider shape at `scale` (1: bounding radii 0.3 to 0.5).
    pub fn shape(self, s: f64) -> SharedShape {
        let regular = |n: usize, r: f64| -> Vec<Vector> {
            (0..n)
                .map(|i| {
                    let a = std::f64::consts::TAU * i as f64 / n as f64 + 0.2;
                    Vector::new(r * a.cos(), r * a.sin())
                })
                .collect()
        };
        match self {
            Family::Ellipse => SharedShape::new(Ellipse::new(0.5 * s, 0.2 * s)),
            Family::Heptagon => SharedShape::new(RoundedPolygon::regular(7, 0.4 * s, 0.06 * s)),
            Family::CapsuleEllipse => SharedShape::new(CapsuleEllipse::new(0.12 * s, 0.15 * s, 0.3 * s)),
            Family::UserCurve => SharedShape::new(CustomCurve::new(EccentricEllipse {
                a: 0.45 * s,
                b: 0.25 * s,
                center: Vector::new(0.05 * s, -0.03 * s),
            })),
            Family::Ball => SharedShape::ball(0.3 * s),
            Family::Cuboid => SharedShape::cuboid(0.4 * s, 0.15 * s),
            Family::Capsule => SharedShape::capsule_x(0.25 * s, 0.12 * s),
            Family::Triangle => {
                let p = regular(3, 0.45 * s);
                SharedShape::triangle(p[0], p[1], p[2])
            }
            Family::Hexagon => SharedShape::convex_polyline(regular(6, 0.4 * s)).expect("a convex hexagon"),
            Family::Plank => SharedShape::cuboid(1.5 * s, 0.025 * s),
        }
    }
}

/// A body to launch.
#[derive(Clone, Copy, Debug)]
pub struct Launch {
    pub family: Family,
    pub scale: f64,
    pub position: Vector,
    pub angle: f64,
    pub velocity: Vector,
    pub spin: f64,
    /// CCD enabled (a bullet).
    pub ccd: bool,
}

/// A launched body: its handles and the radii of two discs about its centre of mass, one
/// inside the shape (whatever the rotation) and one containing it.
#[derive(Clone, Copy, Debug)]
pub struct Tracked {
    pub body: RigidBodyHandle,
    pub collider: ColliderHandle,
    pub inradius: f64,
    pub bounding: f64,
}

/// The radii of [`Tracked`] for `shape`: a lower bound of the distance from its centre of mass
/// to its boundary, and its farthest point's distance.
///
/// The distance from an inner point c to the boundary of a convex shape is the least of its
/// support function about c, h_c(θ) = max over the shape's points p of (p − c)·(cos θ, sin θ).
/// h_c changes by at most R·|Δθ| between two directions (R the farthest point's distance), so
/// its least value over `INRADIUS_SAMPLES` equally spaced directions, less R·π/`INRADIUS_SAMPLES`,
/// is a lower bound — what the judge needs: two centres closer than the sum of two lower bounds
/// are two overlapping shapes. (parry's point projection is not used: for an inner point of a
/// `ConvexPolygon` it answers a point farther than the nearest edge.)
pub fn radii(shape: &dyn Shape) -> (f64, f64) {
    const INRADIUS_SAMPLES: usize = 4096;
    let com = shape.mass_properties(1.0).local_com;
    let sphere = shape.compute_local_bounding_sphere();
    let bounding = (sphere.center - com).length() + sphere.radius;
    let inradius = match (shape.as_ball(), shape.as_support_map()) {
        (Some(b), _) => b.radius,
        (None, Some(s)) => {
            let least = (0..INRADIUS_SAMPLES)
                .map(|k| {
                    let a = std::f64::consts::TAU * k as f64 / INRADIUS_SAMPLES as f64;
                    let n = Vector::new(a.cos(), a.sin());
                    (s.local_support_point(n) - com).dot(n)
                })
                .fold(f64::INFINITY, f64::min);
            (least - bounding * std::f64::consts::PI / INRADIUS_SAMPLES as f64).max(0.0)
        }
        (None, None) => 0.0,
    };
    (inradius, bounding)
}

/// The rapier hooks a run steps with.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Hooks {
    /// None (`()`).
    #[default]
    None,
    /// `CoreContactHooks`: no bounce on the core contacts.
    Core,
    /// `OneBounceHooks`: `CoreContactHooks` and one bouncing row per impact.
    OneBounce,
}

impl From<bool> for Hooks {
    /// `true`: `CoreContactHooks`; `false`: none.
    fn from(core: bool) -> Self {
        if core {
            Hooks::Core
        } else {
            Hooks::None
        }
    }
}

/// The sums of the pass's reports over a run.
#[derive(Clone, Copy, Debug, Default)]
pub struct Totals {
    pub casts: usize,
    pub hits: usize,
    pub out_of_iterations: usize,
    pub unsupported: usize,
    pub stopped_bodies: usize,
    pub pairs: usize,
    pub not_done: usize,
}

impl Totals {
    pub fn add(&mut self, r: &MovingPairsReport) {
        self.casts += r.casts;
        self.hits += r.hits;
        self.out_of_iterations += r.out_of_iterations;
        self.unsupported += r.unsupported;
        self.stopped_bodies += r.stopped_bodies;
        self.pairs += r.pairs;
        self.not_done += usize::from(!matches!(
            r.status,
            smooth_ccd2d::PassStatus::Done | smooth_ccd2d::PassStatus::Skipped
        ));
    }
}

/// A world of launched bodies (no gravity, rapier's speed cap lifted, every body's rotation
/// cap lifted, never asleep, restitution 1), stepped with or without the pass.
pub struct Run {
    pub world: World,
    pub pass: Option<MovingPairs>,
    pub bodies: Vec<Tracked>,
    /// Time in `PhysicsPipeline::step` and in the pass's two calls.
    pub step_time: Duration,
    pub pass_time: Duration,
    pub totals: Totals,
    /// The bodies the pass stopped in the last step, with the fraction of the step where.
    pub stops: Vec<(RigidBodyHandle, f64)>,
    /// The hooks it steps with ([`Run::with_hooks`]).
    pub hooks: Hooks,
}

impl Run {
    /// The world of `launches` with `friction`, with the pass of `options` when given.
    pub fn new(launches: &[Launch], friction: f64, options: Option<MovingPairsOptions>) -> Self {
        let mut world = World::new(NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()));
        world.params.normalized_max_linear_velocity = f64::MAX;
        let bodies = launches.iter().map(|l| launch(&mut world, l, friction)).collect();
        Run {
            world,
            pass: options.map(MovingPairs::new),
            bodies,
            step_time: Duration::ZERO,
            pass_time: Duration::ZERO,
            totals: Totals::default(),
            stops: Vec::new(),
            hooks: Hooks::None,
        }
    }

    /// The same world stepped with `CoreContactHooks`, every collider's
    /// `ActiveHooks::MODIFY_SOLVER_CONTACTS` on.
    pub fn with_core_hooks(self) -> Self {
        self.with_hooks(Hooks::Core)
    }

    /// The same world stepped with `hooks`, every collider's `ActiveHooks::MODIFY_SOLVER_CONTACTS`
    /// on unless `Hooks::None`.
    pub fn with_hooks(mut self, hooks: Hooks) -> Self {
        if hooks != Hooks::None {
            for (_, co) in self.world.colliders.iter_mut() {
                co.set_active_hooks(co.active_hooks() | ActiveHooks::MODIFY_SOLVER_CONTACTS);
            }
        }
        self.hooks = hooks;
        self
    }

    /// Inserts a fixed box of half-extents `half` at `at` (restitution 1, `friction`).
    pub fn wall(&mut self, at: Vector, half: Vector, friction: f64) {
        self.world.insert(
            RigidBodyBuilder::fixed().translation(at),
            ColliderBuilder::cuboid(half.x, half.y)
                .restitution(1.0)
                .friction(friction),
        );
    }

    /// One step: the pass's `before_step`, rapier's step, the pass's `after_step`.
    pub fn step(&mut self) {
        let t0 = Instant::now();
        if let Some(p) = &mut self.pass {
            p.before_step(&self.world.bodies);
        }
        let t1 = Instant::now();
        let hooks: &dyn PhysicsHooks = match self.hooks {
            Hooks::None => &(),
            Hooks::Core => &CoreContactHooks,
            Hooks::OneBounce => &OneBounceHooks,
        };
        self.world.step_with(Vector::ZERO, hooks, &());
        let t2 = Instant::now();
        if let Some(p) = &mut self.pass {
            let w = &mut self.world;
            let r = p.after_step(&w.params, &mut w.bodies, &mut w.colliders, hooks, &());
            self.totals.add(&r);
        }
        let end = Instant::now();
        self.stops.clear();
        if let Some(p) = &self.pass {
            self.stops.extend(p.stops());
        }
        self.step_time += t2 - t1;
        self.pass_time += (t1 - t0) + (end - t2);
    }

    /// The kinetic energy ½m|v|² + ½Iω² of the launched bodies.
    pub fn energy(&self) -> f64 {
        self.bodies
            .iter()
            .map(|t| {
                let rb = &self.world.bodies[t.body];
                let inv_i = rb.mass_properties().local_mprops.inv_principal_inertia;
                let spin = if inv_i > 0.0 {
                    rb.angvel() * rb.angvel() / inv_i
                } else {
                    0.0
                };
                0.5 * (rb.mass() * rb.linvel().length_squared() + spin)
            })
            .sum()
    }

    /// The linear momentum Σ m v of the launched bodies.
    pub fn momentum(&self) -> Vector {
        self.bodies
            .iter()
            .map(|t| {
                let rb = &self.world.bodies[t.body];
                rb.linvel() * rb.mass()
            })
            .fold(Vector::ZERO, |a, b| a + b)
    }

    /// Whether every launched body's pose and velocities are finite.
    pub fn finite(&self) -> bool {
        self.bodies.iter().all(|t| {
            let rb = &self.world.bodies[t.body];
            rb.position().is_finite() && rb.linvel().is_finite() && rb.angvel().is_finite()
        })
    }

    /// The world centre of mass, pose and linear velocity of every launched body.
    pub fn centres(&self) -> Vec<Centre> {
        self.bodies
            .iter()
            .map(|t| {
                let rb = &self.world.bodies[t.body];
                Centre {
                    com: rb.center_of_mass(),
                    pose: *rb.position(),
                    covered: self.stops.iter().find(|s| s.0 == t.body).map_or(1.0, |s| s.1),
                }
            })
            .collect()
    }
}

/// A body's centre of mass and pose after a step, and the fraction of the step over which it
/// moved (the pass stopped it there; 1 otherwise).
#[derive(Clone, Copy, Debug)]
pub struct Centre {
    pub com: Vector,
    pub pose: Pose,
    pub covered: f64,
}

/// Inserts the body of `l` in `world`.
fn launch(world: &mut World, l: &Launch, friction: f64) -> Tracked {
    let shape = l.family.shape(l.scale);
    let (inradius, bounding) = radii(shape.as_ref());
    let (body, collider) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(l.position)
            .rotation(l.angle)
            .linvel(l.velocity)
            .angvel(l.spin)
            .allow_fast_rotation(true)
            .ccd_enabled(l.ccd)
            .can_sleep(false),
        ColliderBuilder::new(shape).restitution(1.0).friction(friction),
    );
    Tracked {
        body,
        collider,
        inradius,
        bounding,
    }
}

/// Shapes within this distance of each other are in contact (the judge's threshold).
pub const TOUCH: f64 = 1e-9;

/// What the judge counts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Verdicts {
    /// Pairs that passed through each other: their centre vector reversed within one step,
    /// d(k+1)·d(k) < 0, while apart at both ends, and their centres came within the sum of the
    /// inradii on the way (so the two must have overlapped: no near miss). On the way, each
    /// centre of mass moves at constant velocity in a straight line over the step, or over the
    /// part of it before the pass stopped it (and then stands still).
    pub through: usize,
    /// The same, but in contact at one end of the step (a crossing the solver let happen).
    pub crossed_in_contact: usize,
    /// Reversals apart at both ends whose centres came between the sums of the inradii and of
    /// the bounding radii: near misses or grazing crossings (undecided; context only).
    pub grazing: usize,
}

/// The judge of pairs through each other (the criterion, [`Verdicts`]), fed the
/// bodies' centres after every step.
pub struct Judge {
    prev: Vec<Centre>,
    pub verdicts: Verdicts,
    dispatcher: SmoothDispatcher,
}

impl Judge {
    /// A judge of `run`'s bodies as they are now.
    pub fn new(run: &Run) -> Self {
        Judge {
            prev: run.centres(),
            verdicts: Verdicts::default(),
            dispatcher: SmoothDispatcher::default(),
        }
    }

    /// Judges every pair of `run`'s bodies over the step just taken.
    pub fn observe(&mut self, run: &Run) {
        let now = run.centres();
        for i in 0..now.len() {
            for j in i + 1..now.len() {
                let (d0, d1) = (self.prev[j].com - self.prev[i].com, now[j].com - now[i].com);
                if d0.dot(d1) >= 0.0 {
                    continue;
                }
                let (ti, tj) = (&run.bodies[i], &run.bodies[j]);
                let closest = closest_approach(&self.prev[i], &now[i], &self.prev[j], &now[j]);
                if closest >= ti.bounding + tj.bounding {
                    continue;
                }
                let shape = |t: &Tracked| run.world.colliders[t.collider].shape();
                let apart = |pi: &Pose, pj: &Pose| {
                    self.dispatcher
                        .distance(&(pi.inverse() * *pj), shape(ti), shape(tj))
                        .is_ok_and(|d| d.distance > TOUCH)
                };
                let both_apart = apart(&self.prev[i].pose, &self.prev[j].pose) && apart(&now[i].pose, &now[j].pose);
                if closest < ti.inradius + tj.inradius {
                    if both_apart {
                        self.verdicts.through += 1;
                    } else {
                        self.verdicts.crossed_in_contact += 1;
                    }
                } else if both_apart {
                    self.verdicts.grazing += 1;
                }
            }
        }
        self.prev = now;
    }
}

/// The least distance between two centres of mass over a step ([`Verdicts::through`]: each
/// moves in a straight line over the part of the step it covered, then stays).
pub fn closest_approach(i0: &Centre, i1: &Centre, j0: &Centre, j1: &Centre) -> f64 {
    let (si, sj) = (i1.covered, j1.covered);
    let at = |tau: f64, a: &Centre, b: &Centre, s: f64| {
        let f = if s > 0.0 { (tau / s).min(1.0) } else { 1.0 };
        a.com + (b.com - a.com) * f
    };
    let d = |tau: f64| at(tau, j0, j1, sj) - at(tau, i0, i1, si);
    let mut breaks = [0.0, si.min(sj), si.max(sj), 1.0];
    breaks.sort_by(f64::total_cmp);
    breaks
        .windows(2)
        .map(|w| closest_to_origin(d(w[0]), d(w[1])))
        .fold(f64::INFINITY, f64::min)
}

/// The least |d0 + s (d1 − d0)| over s in [0, 1].
pub fn closest_to_origin(d0: Vector, d1: Vector) -> f64 {
    let e = d1 - d0;
    let s = if e.length_squared() > 0.0 {
        (-d0.dot(e) / e.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (d0 + e * s).length()
}
