//! The CCD scene suite: continuous-collision scenes of the kind game engines ship, built for
//! rapier2d-f64 with this crate's shapes and `SmoothDispatcher`, and with rapier's default narrow
//! phase on parry's closest shapes, so that the two can be run side by side
//! (`ccd_judge.rs` runs and judges them; `tests/ccd_scenes.rs` and `examples/ccd_scenes.rs`).
//!
//! A [`Case`] is a scene [`Family`], the moving body's shape ([`Body`]), a launch speed and a
//! spin. Where the speed is above rapier's linear cap (400 m/s) or the spin above its rotation
//! cap (π/4 per step), the case lifts them: `normalized_max_linear_velocity = f64::MAX` and
//! `allow_fast_rotation` on the moving bodies ([`Case::lifted`]), so that the speed claimed is the
//! speed simulated ([`Case::rotation_cap_kept`] keeps the rotation cap of a case whose own spin
//! is below it).
#![allow(dead_code)]

use super::watched::{Watched, Watcher};
use super::world::{World, GRAVITY};
use core::f64::consts::{FRAC_PI_4, PI, TAU};
use parry2d_f64::shape::{PolylineFlags, Shape};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{CapsuleEllipse, ConvexCurve, Ellipse, RoundedPolygon, SmoothDispatcher};
use std::cell::RefCell;

/// The time step of every scene.
pub const DT: f64 = 1.0 / 60.0;

/// How a case is simulated.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Method {
    /// This crate's shapes, `SmoothDispatcher` as the narrow phase.
    Smooth,
    /// parry's closest shapes (a ball for a disc, `RoundConvexPolygon` for a rounded polygon,
    /// `ConvexPolygon` for a sharp one, a 32-gon for an ellipse or a `CapsuleEllipse`) and
    /// rapier's default narrow phase, which sweeps them with its own `sweep_time_of_impact`.
    Rapier,
}

impl Method {
    /// Both methods, this crate's first.
    pub const BOTH: [Method; 2] = [Method::Smooth, Method::Rapier];

    /// The method's name in tables.
    pub fn name(self) -> &'static str {
        match self {
            Method::Smooth => "SmoothDispatcher",
            Method::Rapier => "rapier default",
        }
    }

    /// The method's narrow phase.
    pub fn narrow_phase(self) -> NarrowPhase {
        match self {
            Method::Smooth => NarrowPhase::with_query_dispatcher(Watched {
                inner: SmoothDispatcher::default(),
                watcher: CastRecorder,
            }),
            Method::Rapier => NarrowPhase::new(),
        }
    }
}

thread_local! {
    /// The shape pairs rapier asked `SmoothDispatcher` to cast on this thread since
    /// [`start_recording`], `None` when not recording.
    static CASTS: RefCell<Option<Vec<(usize, usize)>>> = const { RefCell::new(None) };
}

/// A [`Watcher`] of the suite's `SmoothDispatcher` that records which pairs of shapes rapier's
/// CCD asked it to cast (by the shapes' addresses), while recording is on, without timing the
/// calls: the judge tells a swept body deep in a target the dispatcher was asked about (the
/// dispatcher's answer) from one deep in a target rapier never asked about (rapier's candidate
/// search).
pub struct CastRecorder;

impl Watcher for CastRecorder {
    fn cast(&self, g1: &dyn Shape, g2: &dyn Shape, _seconds: f64) {
        CASTS.with(|c| {
            if let Some(v) = c.borrow_mut().as_mut() {
                v.push((shape_address(g1), shape_address(g2)));
            }
        });
    }
    fn timed(&self) -> bool {
        false
    }
}

/// A shape's address, the key of [`CastRecorder`]'s records.
pub fn shape_address(g: &dyn Shape) -> usize {
    g as *const dyn Shape as *const () as usize
}

/// Starts (or restarts) recording the casts asked on this thread.
pub fn start_recording() {
    CASTS.with(|c| *c.borrow_mut() = Some(Vec::new()));
}

/// The casts asked on this thread since [`start_recording`] (empty when not recording).
pub fn recorded_casts() -> Vec<(usize, usize)> {
    CASTS.with(|c| c.borrow().clone().unwrap_or_default())
}

/// The moving body's shape: every shape family of the crate.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Body {
    /// Ellipse 0.5 × 0.2.
    Ellipse,
    /// A disc of radius 0.2 (an `Ellipse` with equal semi-axes; parry's `Ball` for rapier).
    Disc,
    /// A thin ellipse 0.4 × 0.05.
    ThinEllipse,
    /// A sharp square (corner radius 0), circumradius 0.35.
    Square,
    /// A rounded heptagon, circumradius 0.4, corner radius 0.06.
    Heptagon,
    /// A sharp sliver triangle (−0.5, 0), (−0.25, 0), (0.5, 0.125): 1 m long, its centroid
    /// 0.03 from its long side.
    Sliver,
    /// The specification's Appendix A shape, `CapsuleEllipse::new(0.12, 0.15, 0.3)`.
    CapsuleEllipse,
}

impl Body {
    /// Every shape family.
    pub const ALL: [Body; 7] = [
        Body::Ellipse,
        Body::Disc,
        Body::ThinEllipse,
        Body::Square,
        Body::Heptagon,
        Body::Sliver,
        Body::CapsuleEllipse,
    ];

    /// The shape's name in tables.
    pub fn name(self) -> &'static str {
        match self {
            Body::Ellipse => "ellipse",
            Body::Disc => "disc",
            Body::ThinEllipse => "thin ellipse",
            Body::Square => "sharp square",
            Body::Heptagon => "rounded heptagon",
            Body::Sliver => "sliver",
            Body::CapsuleEllipse => "capsule-ellipse",
        }
    }

    /// The sliver's vertices.
    const SLIVER: [(f64, f64); 3] = [(-0.5, 0.0), (-0.25, 0.0), (0.5, 0.125)];

    /// This crate's shape, as a curve.
    pub fn curve(self) -> Box<dyn ConvexCurve> {
        match self {
            Body::Ellipse => Box::new(Ellipse::new(0.5, 0.2)),
            Body::Disc => Box::new(Ellipse::new(0.2, 0.2)),
            Body::ThinEllipse => Box::new(Ellipse::new(0.4, 0.05)),
            Body::Square => Box::new(RoundedPolygon::regular(4, 0.35, 0.0)),
            Body::Heptagon => Box::new(RoundedPolygon::regular(7, 0.4, 0.06)),
            Body::Sliver => Box::new(sliver()),
            Body::CapsuleEllipse => Box::new(CapsuleEllipse::new(0.12, 0.15, 0.3)),
        }
    }

    /// The collider shape under `method`.
    pub fn shape(self, method: Method) -> SharedShape {
        match (self, method) {
            (Body::Ellipse, Method::Smooth) => SharedShape::new(Ellipse::new(0.5, 0.2)),
            (Body::Disc, Method::Smooth) => SharedShape::new(Ellipse::new(0.2, 0.2)),
            (Body::ThinEllipse, Method::Smooth) => SharedShape::new(Ellipse::new(0.4, 0.05)),
            (Body::Square, Method::Smooth) => SharedShape::new(RoundedPolygon::regular(4, 0.35, 0.0)),
            (Body::Heptagon, Method::Smooth) => SharedShape::new(RoundedPolygon::regular(7, 0.4, 0.06)),
            (Body::Sliver, Method::Smooth) => SharedShape::new(sliver()),
            (Body::CapsuleEllipse, Method::Smooth) => SharedShape::new(CapsuleEllipse::new(0.12, 0.15, 0.3)),
            (Body::Disc, Method::Rapier) => SharedShape::ball(0.2),
            (Body::Heptagon, Method::Rapier) => SharedShape::new(
                RoundedPolygon::regular(7, 0.4, 0.06)
                    .to_parry()
                    .expect("a rounded heptagon"),
            ),
            (Body::Square | Body::Sliver, Method::Rapier) => {
                let p = match self {
                    Body::Square => RoundedPolygon::regular(4, 0.35, 0.0),
                    _ => sliver(),
                };
                SharedShape::convex_polyline(p.vertices().to_vec()).expect("a convex polygon")
            }
            (Body::Ellipse | Body::ThinEllipse | Body::CapsuleEllipse, Method::Rapier) => {
                let curve = self.curve();
                // 32 boundary points spread by the normal angle: the polygon parry would be given.
                let pts = (0..32)
                    .map(|i| {
                        let a = TAU * i as f64 / 32.0;
                        curve.support_point(Vector::new(a.cos(), a.sin()))
                    })
                    .collect();
                SharedShape::convex_polyline(pts).expect("a convex 32-gon")
            }
        }
    }

    /// The largest distance from the shape's centroid to its boundary.
    pub fn radius(self) -> f64 {
        match self {
            Body::Ellipse => 0.5,
            Body::Disc => 0.2,
            Body::ThinEllipse => 0.4,
            Body::Square => 0.35,
            Body::Heptagon => 0.46,
            // The centroid is at (−1/12, 1/24); the farthest vertex (0.5, 0.125).
            Body::Sliver => 0.59,
            Body::CapsuleEllipse => 0.42,
        }
    }

    /// How far below its centroid the shape reaches at angle 0 (to rest it on a floor).
    pub fn below(self) -> f64 {
        let curve = self.curve();
        let low = curve.support_point(Vector::new(0.0, -1.0)).y;
        let centroid = match self {
            Body::Sliver => 0.125 / 3.0,
            _ => 0.0,
        };
        centroid - low
    }
}

/// The sliver as this crate's polygon.
fn sliver() -> RoundedPolygon {
    let v: Vec<Vector> = Body::SLIVER.iter().map(|&(x, y)| Vector::new(x, y)).collect();
    RoundedPolygon::new(&v, 0.0)
}

/// A scene family.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Family {
    /// A body resting on a long `Segment` floor slides along it at the launch speed (a little
    /// into the floor, 2 % of it), spinning; gravity.
    SegmentSlide,
    /// A body dropped onto a `Segment` floor at the launch speed (10 % sideways); gravity,
    /// restitution 0.5.
    SegmentDrop,
    /// A closed `Polyline` box 10 × 10, a body bouncing inside (restitution 1, no gravity).
    ChainBox,
    /// An open `Polyline` terrain of hills; a body launched along and into it; gravity.
    ChainTerrain,
    /// A grid of thin posts (vertical `Segment`s and 0.01-thick cuboids) crossed diagonally
    /// (restitution 1, no gravity).
    Posts,
    /// A V-shaped funnel of two `Segment`s (60° opening); a body dropped into it at speed;
    /// gravity.
    Funnel,
    /// An acute wedge of two `Segment`s (20° opening); a body shot into its apex; no gravity.
    Wedge,
    /// An L of two `Segment`s: a body sliding along the floor into the corner; gravity.
    SlideCorner,
    /// A bullet (CCD on) shot into a stack of 12 boxes resting against a 0.05 wall; gravity.
    BulletsStack,
    /// A motorised flipper (a box on a revolute joint) batting the body, dropped at speed, into a
    /// `Segment` ceiling; gravity.
    Flipper,
    /// A closed box of four 0.05-thick cuboid walls, a body bouncing inside (restitution 1, no
    /// gravity).
    BouncingBox,
    /// Shots at a thin cuboid wall 0.05, 0.02 or 0.01 thick (by the spin's index); no gravity.
    ThinWalls,
    /// A body dropped at speed onto a 0.05-thick cuboid plank; gravity.
    PlankDrop,
}

impl Family {
    /// Every family.
    pub const ALL: [Family; 13] = [
        Family::SegmentSlide,
        Family::SegmentDrop,
        Family::ChainBox,
        Family::ChainTerrain,
        Family::Posts,
        Family::Funnel,
        Family::Wedge,
        Family::SlideCorner,
        Family::BulletsStack,
        Family::Flipper,
        Family::BouncingBox,
        Family::ThinWalls,
        Family::PlankDrop,
    ];

    /// The family's name in tables.
    pub fn name(self) -> &'static str {
        match self {
            Family::SegmentSlide => "segment slide",
            Family::SegmentDrop => "segment drop",
            Family::ChainBox => "chain box",
            Family::ChainTerrain => "chain terrain",
            Family::Posts => "thin posts",
            Family::Funnel => "funnel",
            Family::Wedge => "acute wedge",
            Family::SlideCorner => "slide into corner",
            Family::BulletsStack => "bullet into stack",
            Family::Flipper => "flipper",
            Family::BouncingBox => "bouncing box",
            Family::ThinWalls => "thin walls",
            Family::PlankDrop => "plank drop",
        }
    }

    /// Steps each case of the family runs.
    pub fn steps(self) -> usize {
        match self {
            Family::ChainBox | Family::BouncingBox | Family::Posts | Family::Flipper => 120,
            _ => 60,
        }
    }
}

/// The launch speeds of the suite (m/s): from the samples' tens of m/s to 3000.
pub const SPEEDS: [f64; 6] = [10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0];
/// The spins of the suite (rad/s): none, within rapier's cap (47 rad/s at 60 Hz), beyond it.
pub const SPINS: [f64; 4] = [0.0, 20.0, -100.0, 600.0];

/// One case of the suite.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    pub family: Family,
    pub body: Body,
    /// Launch speed, m/s.
    pub speed: f64,
    /// Spin, rad/s.
    pub spin: f64,
    /// The spin's index in [`SPINS`] (picks a family's variant, such as a wall's thickness).
    pub variant: usize,
    /// rapier's contact recycling (`IntegrationParameters::contact_recycling`, on by default).
    pub recycling: bool,
    /// rapier's `normalized_contact_recycle_distance` when not its default (0.05).
    pub recycle_distance: Option<f64>,
    /// The launched CCD bodies' colliders with `ActiveHooks::MODIFY_SOLVER_CONTACTS` (the
    /// scenes step with the no-op hooks `()`): rapier never recycles a pair with active hooks,
    /// so these bodies' pairs are recomputed every step while every other pair is recycled as
    /// usual (docs/rapier.md, "What is left").
    pub ccd_hooks: bool,
    /// `allow_fast_rotation` only where the case's spin is above rapier's rotation cap (π/4 a
    /// step), rather than on every case above either cap ([`Case::lifted`]): a fast body
    /// launched with a slow spin keeps rapier's rotation cap, whatever spin its collisions
    /// give it (`--rotation-cap-kept` of the example). By default (false) it is lifted too.
    pub rotation_cap_kept: bool,
    /// This crate's pass for two moving bodies, `MovingPairs` (default options: bullets, and
    /// fixed targets of the bodies turning past rapier's regime), around every step of
    /// `SmoothDispatcher`'s run (`--moving-pairs` of the example; docs/rapier.md, "Two moving
    /// bodies"). rapier's default runs as it is.
    pub moving_pairs: bool,
    /// The chain box and the chain terrain built as oriented polylines (`PolylineFlags::
    /// ORIENTED`, facing the body: one-sided chains, as a game builds its level; `--oriented-chains`
    /// of the example), for both methods. By default (false) the plain two-sided polylines.
    pub oriented_chains: bool,
}

impl Case {
    /// The case as lists name it: family, body, speed and spin.
    pub fn describe(&self) -> String {
        format!(
            "{} {} {} m/s {} rad/s",
            self.family.name(),
            self.body.name(),
            self.speed,
            self.spin
        )
    }

    /// Whether the case lifts rapier's caps (its speed or spin is above them; with
    /// [`Case::rotation_cap_kept`], the rotation cap only where its spin is above it).
    pub fn lifted(&self) -> bool {
        self.speed > 400.0 || self.spin.abs() * DT > FRAC_PI_4
    }
}

/// Every case: each family × each body × each speed × each spin.
pub fn all_cases() -> Vec<Case> {
    let mut cases = Vec::new();
    for family in Family::ALL {
        for body in Body::ALL {
            for speed in SPEEDS {
                for (variant, spin) in SPINS.into_iter().enumerate() {
                    cases.push(Case {
                        family,
                        body,
                        speed,
                        spin,
                        variant,
                        recycling: true,
                        recycle_distance: None,
                        ccd_hooks: false,
                        rotation_cap_kept: false,
                        moving_pairs: false,
                        oriented_chains: false,
                    });
                }
            }
        }
    }
    cases
}

/// What a case's judge must know of a built scene.
pub struct Scene {
    pub world: World,
    pub gravity: Vector,
    /// Every dynamic body, the launched ones first.
    pub dynamic: Vec<RigidBodyHandle>,
    /// The colliders of fixed geometry.
    pub fixed: Vec<ColliderHandle>,
    /// A motor to switch on at a step: the joint, the step, the motor's target velocity.
    pub motor: Option<(ImpulseJointHandle, usize, f64)>,
    pub steps: usize,
}

/// A fixed collider with restitution `e` (friction 0.3).
fn fixed(world: &mut World, co: ColliderBuilder, e: f64) -> ColliderHandle {
    world.colliders.insert(
        co.restitution(e)
            .friction(0.3)
            .restitution_combine_rule(CoefficientCombineRule::Max),
    )
}

/// Builds the case's scene for `method`.
pub fn build(case: &Case, method: Method) -> Scene {
    let mut world = World::new(method.narrow_phase());
    let lifted = case.lifted();
    if lifted {
        world.params.normalized_max_linear_velocity = f64::MAX;
    }
    world.params.contact_recycling = case.recycling;
    if let Some(d) = case.recycle_distance {
        world.params.normalized_contact_recycle_distance = d;
    }
    let launcher = Launcher {
        case,
        shape: case.body.shape(method),
    };
    let mut f = Furnished {
        fixed: Vec::new(),
        dynamic: Vec::new(),
        motor: None,
        gravity: GRAVITY,
    };
    if !furnish_walls(case, &mut world, &launcher, &mut f) {
        furnish_bodies(case, &mut world, &launcher, &mut f);
    }
    Scene {
        world,
        gravity: f.gravity,
        dynamic: f.dynamic,
        fixed: f.fixed,
        motor: f.motor,
        steps: case.family.steps(),
    }
}

/// The case's launched body, one shape for every launch.
struct Launcher<'a> {
    case: &'a Case,
    shape: SharedShape,
}

impl Launcher<'_> {
    /// Launches the body at `at`, velocity `v`, angle `angle`, restitution `e`, with CCD when
    /// `bullet`.
    fn launch(&self, world: &mut World, at: Vector, v: Vector, angle: f64, e: f64, bullet: bool) -> RigidBodyHandle {
        let case = self.case;
        world
            .insert(
                RigidBodyBuilder::dynamic()
                    .translation(at)
                    .rotation(angle)
                    .linvel(v)
                    .angvel(case.spin)
                    .ccd_enabled(bullet)
                    .allow_fast_rotation(if case.rotation_cap_kept {
                        case.spin.abs() * DT > FRAC_PI_4
                    } else {
                        case.lifted()
                    })
                    .can_sleep(false),
                ColliderBuilder::new(self.shape.clone())
                    .active_hooks(if bullet && case.ccd_hooks {
                        ActiveHooks::MODIFY_SOLVER_CONTACTS
                    } else {
                        ActiveHooks::empty()
                    })
                    .restitution(e)
                    .friction(0.3)
                    .restitution_combine_rule(CoefficientCombineRule::Max),
            )
            .0
    }
}

/// What a family puts in the world besides the world itself ([`Scene`]'s other fields).
struct Furnished {
    fixed: Vec<ColliderHandle>,
    dynamic: Vec<RigidBodyHandle>,
    motor: Option<(ImpulseJointHandle, usize, f64)>,
    gravity: Vector,
}

/// The families of walls, chains, posts and wedges: their fixed geometry and launched body;
/// false for the other families ([`furnish_bodies`]).
fn furnish_walls(case: &Case, world: &mut World, launcher: &Launcher, f: &mut Furnished) -> bool {
    let v = case.speed;
    match case.family {
        Family::SegmentSlide => {
            let len = 1.2 * v * DT * Family::SegmentSlide.steps() as f64 + 20.0;
            f.fixed.push(fixed(
                world,
                ColliderBuilder::segment(Vector::new(-10.0, 0.0), Vector::new(len, 0.0)),
                0.0,
            ));
            let at = Vector::new(0.0, case.body.below());
            f.dynamic
                .push(launcher.launch(world, at, Vector::new(v, -0.02 * v), 0.0, 0.0, true));
        }
        Family::SegmentDrop => {
            let len = 0.2 * v * DT * Family::SegmentDrop.steps() as f64 + 20.0;
            f.fixed.push(fixed(
                world,
                ColliderBuilder::segment(Vector::new(-len, 0.0), Vector::new(len, 0.0)),
                0.5,
            ));
            f.dynamic
                .push(launcher.launch(world, Vector::new(0.0, 2.0), Vector::new(0.1 * v, -v), 0.3, 0.5, true));
        }
        Family::ChainBox => {
            f.gravity = Vector::ZERO;
            let h = 5.0;
            let pts = vec![
                Vector::new(-h, -h),
                Vector::new(h, -h),
                Vector::new(h, h),
                Vector::new(-h, h),
            ];
            // Counter-clockwise; oriented, each segment reversed so that the box faces in (parry's
            // outward normal of a segment a → b is (b − a) turned clockwise).
            let chain = if case.oriented_chains {
                let idx = vec![[1, 0], [2, 1], [3, 2], [0, 3]];
                ColliderBuilder::polyline_with_flags(pts, Some(idx), PolylineFlags::ORIENTED)
            } else {
                let idx = vec![[0, 1], [1, 2], [2, 3], [3, 0]];
                ColliderBuilder::polyline(pts, Some(idx))
            };
            f.fixed.push(fixed(world, chain, 1.0));
            let dir = Vector::new(0.3f64.cos(), 0.3f64.sin());
            f.dynamic
                .push(launcher.launch(world, Vector::ZERO, dir * v, 0.0, 1.0, true));
        }
        Family::ChainTerrain => {
            let pts: Vec<Vector> = (0..=120)
                .map(|i| {
                    let x = -20.0 + i as f64;
                    Vector::new(x, 0.6 * (0.7 * x).sin() + 0.3 * (1.9 * x).sin())
                })
                .collect();
            // Left to right; oriented, right to left so that the terrain faces up.
            let chain = if case.oriented_chains {
                let pts = pts.into_iter().rev().collect();
                ColliderBuilder::polyline_with_flags(pts, None, PolylineFlags::ORIENTED)
            } else {
                ColliderBuilder::polyline(pts, None)
            };
            f.fixed.push(fixed(world, chain, 0.3));
            let dir = Vector::new(1.0, -0.35).normalize();
            f.dynamic
                .push(launcher.launch(world, Vector::new(-18.0, 2.5), dir * v, 0.2, 0.3, true));
        }
        Family::Posts => {
            f.gravity = Vector::ZERO;
            for i in 0..5 {
                for j in 0..5 {
                    let c = Vector::new(2.0 + 1.6 * i as f64, -3.2 + 1.6 * j as f64 + 0.4 * (i % 2) as f64);
                    let co = if (i + j) % 2 == 0 {
                        ColliderBuilder::segment(c - Vector::new(0.0, 0.35), c + Vector::new(0.0, 0.35))
                    } else {
                        ColliderBuilder::cuboid(0.005, 0.35).translation(c)
                    };
                    f.fixed.push(fixed(world, co, 1.0));
                }
            }
            let dir = Vector::new(1.0, 0.27).normalize();
            f.dynamic
                .push(launcher.launch(world, Vector::new(0.0, -2.0), dir * v, 0.5, 1.0, true));
        }
        Family::Funnel => {
            let half = PI / 6.0; // 60° opening
            let l = 6.0;
            let a = Vector::new(-l * half.sin(), l * half.cos());
            let b = Vector::new(l * half.sin(), l * half.cos());
            f.fixed
                .push(fixed(world, ColliderBuilder::segment(a, Vector::ZERO), 0.2));
            f.fixed
                .push(fixed(world, ColliderBuilder::segment(Vector::ZERO, b), 0.2));
            f.dynamic
                .push(launcher.launch(world, Vector::new(0.4, 5.0), Vector::new(0.05 * v, -v), 0.7, 0.2, true));
        }
        Family::Wedge => {
            f.gravity = Vector::ZERO;
            let half = PI / 18.0; // 20° opening, apex at (6, 0), open towards −x
            let l = 8.0;
            let apex = Vector::new(6.0, 0.0);
            let up = apex + Vector::new(-l * half.cos(), l * half.sin());
            let down = apex + Vector::new(-l * half.cos(), -l * half.sin());
            f.fixed.push(fixed(world, ColliderBuilder::segment(up, apex), 0.3));
            f.fixed.push(fixed(world, ColliderBuilder::segment(down, apex), 0.3));
            f.dynamic
                .push(launcher.launch(world, Vector::new(0.0, 0.1), Vector::new(v, 0.0), 0.0, 0.3, true));
        }
        Family::SlideCorner => {
            f.fixed.push(fixed(
                world,
                ColliderBuilder::segment(Vector::new(-20.0, 0.0), Vector::new(8.0, 0.0)),
                0.2,
            ));
            f.fixed.push(fixed(
                world,
                ColliderBuilder::segment(Vector::new(8.0, 0.0), Vector::new(8.0, 6.0)),
                0.2,
            ));
            let at = Vector::new(0.0, case.body.below());
            f.dynamic
                .push(launcher.launch(world, at, Vector::new(v, 0.0), 0.0, 0.2, true));
        }
        _ => return false,
    }
    true
}

/// The families with more than fixed geometry (a stack, a flipper) and the closed or thin
/// walls: their bodies and launched body ([`furnish_walls`] takes the others).
fn furnish_bodies(case: &Case, world: &mut World, launcher: &Launcher, f: &mut Furnished) {
    let v = case.speed;
    match case.family {
        Family::BulletsStack => {
            f.fixed.push(fixed(
                world,
                ColliderBuilder::cuboid(20.0, 0.5).translation(Vector::new(0.0, -0.5)),
                0.1,
            ));
            f.fixed.push(fixed(
                world,
                ColliderBuilder::cuboid(0.025, 4.0).translation(Vector::new(6.025, 4.0)),
                0.1,
            ));
            let bullet = launcher.launch(world, Vector::new(-6.0, 0.6), Vector::new(v, 0.0), 0.0, 0.1, true);
            f.dynamic.push(bullet);
            for i in 0..3 {
                for j in 0..4 {
                    let c = Vector::new(4.6 + 0.46 * i as f64, 0.2 + 0.401 * j as f64);
                    let (h, _) = world.insert(
                        RigidBodyBuilder::dynamic().translation(c),
                        ColliderBuilder::cuboid(0.2, 0.2).friction(0.5),
                    );
                    f.dynamic.push(h);
                }
            }
        }
        Family::Flipper => {
            let anchor = world
                .bodies
                .insert(RigidBodyBuilder::fixed().translation(Vector::new(-1.0, 0.0)));
            // The flipper's hinge end (−1, 0) in its frame sits on the anchor at angle −0.4.
            let angle: f64 = -0.4;
            let hinge = Vector::new(-angle.cos(), -angle.sin());
            let (flipper, _) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(-1.0, 0.0) - hinge)
                    .rotation(angle)
                    .can_sleep(false),
                ColliderBuilder::cuboid(1.0, 0.08).density(5.0).friction(0.3),
            );
            let joint = RevoluteJointBuilder::new()
                .local_anchor1(Vector::ZERO)
                .local_anchor2(Vector::new(-1.0, 0.0))
                .limits([-0.5, 0.5])
                .motor_velocity(-5.0, 50.0);
            let jh = world.impulse_joints.insert(anchor, flipper, joint, true);
            f.motor = Some((jh, 20, 40.0));
            f.fixed.push(fixed(
                world,
                ColliderBuilder::segment(Vector::new(-6.0, 6.0), Vector::new(6.0, 6.0)),
                0.5,
            ));
            f.fixed.push(fixed(
                world,
                ColliderBuilder::segment(Vector::new(-6.0, -3.0), Vector::new(6.0, -3.0)),
                0.5,
            ));
            let ball = launcher.launch(world, Vector::new(0.4, 2.5), Vector::new(0.0, -v), 0.0, 0.5, true);
            f.dynamic.push(ball);
            f.dynamic.push(flipper);
        }
        Family::BouncingBox => {
            f.gravity = Vector::ZERO;
            let (h, t) = (5.0, 0.025);
            for (c, he) in [
                (Vector::new(0.0, -h - t), Vector::new(h + 2.0 * t, t)),
                (Vector::new(0.0, h + t), Vector::new(h + 2.0 * t, t)),
                (Vector::new(-h - t, 0.0), Vector::new(t, h)),
                (Vector::new(h + t, 0.0), Vector::new(t, h)),
            ] {
                f.fixed
                    .push(fixed(world, ColliderBuilder::cuboid(he.x, he.y).translation(c), 1.0));
            }
            let dir = Vector::new(0.61f64.cos(), 0.61f64.sin());
            f.dynamic
                .push(launcher.launch(world, Vector::new(0.3, -0.2), dir * v, 0.0, 1.0, true));
        }
        Family::ThinWalls => {
            f.gravity = Vector::ZERO;
            let half = [0.025, 0.01, 0.005, 0.025][case.variant % 4];
            f.fixed.push(fixed(
                world,
                ColliderBuilder::cuboid(half, 3.0).translation(Vector::new(5.0, 0.0)),
                0.3,
            ));
            f.dynamic
                .push(launcher.launch(world, Vector::ZERO, Vector::new(v, 0.0), 0.4, 0.3, true));
        }
        Family::PlankDrop => {
            let len = 0.2 * v * DT * Family::PlankDrop.steps() as f64 + 20.0;
            f.fixed.push(fixed(world, ColliderBuilder::cuboid(len, 0.025), 0.3));
            f.dynamic
                .push(launcher.launch(world, Vector::new(0.0, 3.0), Vector::new(0.1 * v, -v), 0.9, 0.3, true));
        }
        _ => unreachable!("furnish_walls takes {:?}", case.family),
    }
}

/// Switches on the scene's motor when its step comes.
pub fn drive(scene: &mut Scene, step: usize) {
    if let Some((jh, at, vel)) = scene.motor {
        if step == at {
            if let Some(j) = scene.world.impulse_joints.get_mut(jh, true) {
                if let Some(r) = j.data.as_revolute_mut() {
                    r.set_motor_velocity(vel, 50.0);
                }
            }
        }
    }
}
