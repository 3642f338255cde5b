//! The rapier scenes shared by the tests, examples and benches, built in a [`World`]:
//!
//! * the mixed pile ([`mixed_pile`]): 150 bodies of every shape on a box with three fast CCD
//!   shots into it, stepped on 1 to 4 workers by `crates/parallel-tests` and hashed by
//!   `tests/golden.rs`;
//! * the box pile ([`pile_bodies`], [`insert_pile`]): 200 ellipses, rounded polygons and
//!   `CapsuleEllipse`s dropped into a box, drawn by [`Lcg`]; `examples/pile.rs` (through
//!   `examples/common`) and the pile benchmarks (through `benches/support`);
//! * the wall shots ([`wall_shot`]): a fast-spinning ellipse or rounded heptagon fired with CCD at
//!   a thin fixed wall, `tests/rapier_integration.rs` and `examples/wall_shots.rs`.
#![allow(dead_code)]

use super::rng::Lcg;
use super::world::World;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{CapsuleEllipse, ConvexCurve, Ellipse, RoundedPolygon, SmoothDispatcher};

// ---------------------------------------------------------------------------------------------
// The mixed pile
// ---------------------------------------------------------------------------------------------

/// Bodies of [`mixed_pile`] besides its three shots (enough for rapier to split its narrow
/// phase, solver and CCD sweeps between workers: more than 64 pairs, 64 swept bodies).
pub const MIXED_PILE_BODIES: usize = 150;

/// A pile of ellipses, rounded polygons and capsule-ellipses on a box, with three fast CCD
/// ellipse shots into it (`crates/parallel-tests`, `tests/golden.rs`). Returns the dynamic bodies.
pub fn mixed_pile(world: &mut World) -> Vec<RigidBodyHandle> {
    let mut handles = Vec::new();
    world.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(0.0, -0.5)),
        ColliderBuilder::cuboid(20.0, 0.5),
    );
    for i in 0..MIXED_PILE_BODIES {
        let x = -9.0 + 0.9 * (i % 20) as f64;
        let y = 1.0 + 0.9 * (i / 20) as f64;
        let shape = match i % 4 {
            0 => SharedShape::new(Ellipse::new(0.4, 0.18)),
            1 => SharedShape::new(RoundedPolygon::regular(3 + i % 5, 0.3, 0.03)),
            2 => SharedShape::new(CapsuleEllipse::new(0.1, 0.15, 0.2)),
            _ => SharedShape::new(Ellipse::new(0.25, 0.25)),
        };
        let (h, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, y))
                .rotation(0.37 * i as f64)
                .angvel(2.0 - 0.1 * i as f64)
                .ccd_enabled(i % 2 == 0),
            ColliderBuilder::new(shape),
        );
        handles.push(h);
    }
    for k in 0..3 {
        let (shot, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(-15.0 - 3.0 * k as f64, 1.5 + 1.2 * k as f64))
                .linvel(Vector::new(250.0, 0.0))
                .angvel(120.0)
                // 2 rad a step: above rapier's rotation cap of π/4, lifted.
                .allow_fast_rotation(true)
                .ccd_enabled(true),
            ColliderBuilder::new(SharedShape::new(Ellipse::new(0.3, 0.08))),
        );
        handles.push(shot);
    }
    handles
}

// ---------------------------------------------------------------------------------------------
// The box pile
// ---------------------------------------------------------------------------------------------

/// Bodies in the box pile.
pub const PILE_BODIES: usize = 200;
/// Bodies per row of the pile's starting grid.
pub const PILE_COLUMNS: usize = 12;
/// Inner half-width of the pile's box; the floor's top face is at y = 0.
pub const PILE_HALF_WIDTH: f64 = 6.0;
/// Height of the box's walls.
pub const PILE_WALL_HEIGHT: f64 = 24.0;
/// The seed of the pile's [`Lcg`].
pub const PILE_SEED: u64 = 0x005e_ed2d;

/// The shape of a body of the pile: body `i` is an ellipse, a rounded polygon or a
/// `CapsuleEllipse` as `i mod 3` is 0, 1 or 2.
#[derive(Clone, Debug)]
pub enum PileShape {
    Ellipse(Ellipse),
    Polygon(RoundedPolygon),
    Capsule(CapsuleEllipse),
}

impl PileShape {
    /// The shape as a curve (for outlines and bounding radii).
    pub fn curve(&self) -> &dyn ConvexCurve {
        match self {
            PileShape::Ellipse(e) => e,
            PileShape::Polygon(p) => p,
            PileShape::Capsule(c) => c,
        }
    }

    /// The exact shape as rapier's shape.
    pub fn shared(&self) -> SharedShape {
        match self {
            PileShape::Ellipse(e) => SharedShape::new(*e),
            PileShape::Polygon(p) => SharedShape::new(p.clone()),
            PileShape::Capsule(c) => SharedShape::new(c.clone()),
        }
    }
}

/// A body of the pile as it starts: its shape, position, angle and angular velocity (at rest
/// otherwise).
#[derive(Clone, Debug)]
pub struct PileBody {
    pub shape: PileShape,
    pub translation: Vector,
    pub rotation: f64,
    pub angvel: f64,
}

/// The shape of body `i`; sizes span a factor of about 3 (bounding radii 0.15 to 0.45).
fn pile_shape(i: usize, rng: &mut Lcg) -> PileShape {
    let size = rng.range(0.15, 0.45);
    match i % 3 {
        0 => PileShape::Ellipse(Ellipse::new(size, size * rng.range(0.3, 1.0))),
        1 => {
            let sides = 3 + (rng.unit() * 6.0) as usize;
            PileShape::Polygon(RoundedPolygon::regular(
                sides,
                0.85 * size,
                0.15 * size * rng.range(0.3, 1.0),
            ))
        }
        _ => {
            let r1 = size * rng.range(0.35, 0.5);
            PileShape::Capsule(CapsuleEllipse::new(
                r1,
                size * rng.range(0.1, 0.4),
                size * rng.range(0.4, 0.7),
            ))
        }
    }
}

/// The [`PILE_BODIES`] bodies of the pile (deterministic: [`Lcg`] seeded with [`PILE_SEED`]),
/// on a grid of [`PILE_COLUMNS`] columns a metre apart in height, jittered sideways.
pub fn pile_bodies() -> Vec<PileBody> {
    let mut rng = Lcg::new(PILE_SEED);
    let spacing = 2.0 * PILE_HALF_WIDTH / PILE_COLUMNS as f64;
    (0..PILE_BODIES)
        .map(|i| {
            let shape = pile_shape(i, &mut rng);
            let (row, col) = (i / PILE_COLUMNS, i % PILE_COLUMNS);
            let x = -PILE_HALF_WIDTH + spacing * (col as f64 + 0.5) + rng.range(-0.03, 0.03);
            let y = 1.0 + row as f64;
            let rotation = rng.range(-3.0, 3.0);
            let angvel = rng.range(-2.0, 2.0);
            PileBody {
                shape,
                translation: Vector::new(x, y),
                rotation,
                angvel,
            }
        })
        .collect()
}

/// The pile's box: the floor (top face at y = 0) and two walls (inner faces at
/// x = ±[`PILE_HALF_WIDTH`]), as (centre, half-extents).
pub fn pile_walls() -> [(Vector, Vector); 3] {
    [
        (Vector::new(0.0, -0.5), Vector::new(PILE_HALF_WIDTH + 1.0, 0.5)),
        (
            Vector::new(-PILE_HALF_WIDTH - 0.5, 0.5 * PILE_WALL_HEIGHT),
            Vector::new(0.5, 0.5 * PILE_WALL_HEIGHT),
        ),
        (
            Vector::new(PILE_HALF_WIDTH + 0.5, 0.5 * PILE_WALL_HEIGHT),
            Vector::new(0.5, 0.5 * PILE_WALL_HEIGHT),
        ),
    ]
}

/// Inserts the box (fixed cuboids) and then `bodies` (dynamic, friction 0.5), each body's collider
/// shape given by `shape_of` (the exact shape: [`PileShape::shared`]). Returns the bodies' handles,
/// in order.
pub fn insert_pile(
    world: &mut World,
    bodies: &[PileBody],
    shape_of: impl Fn(&PileShape) -> SharedShape,
) -> Vec<RigidBodyHandle> {
    for (c, h) in pile_walls() {
        world.insert(
            RigidBodyBuilder::fixed().translation(c),
            ColliderBuilder::cuboid(h.x, h.y),
        );
    }
    bodies
        .iter()
        .map(|b| {
            world
                .insert(
                    RigidBodyBuilder::dynamic()
                        .translation(b.translation)
                        .rotation(b.rotation)
                        .angvel(b.angvel),
                    ColliderBuilder::new(shape_of(&b.shape)).friction(0.5),
                )
                .0
        })
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Wall shots
// ---------------------------------------------------------------------------------------------

/// The shots' wall: centre x, half-thickness (0.05 thick), half-height.
pub const WALL_X: f64 = 5.0;
pub const WALL_HALF: f64 = 0.025;
pub const WALL_HALF_HEIGHT: f64 = 3.0;
/// The wall's face towards the shots (x = 4.975).
pub const WALL_FACE: f64 = WALL_X - WALL_HALF;

/// What is shot at the wall.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum ShotBody {
    /// Ellipse 0.5 × 0.2.
    Ellipse,
    /// Rounded regular heptagon, circumradius 0.4, corner radius 0.06.
    Heptagon,
    /// The Appendix A shape, `CapsuleEllipse::new(0.12, 0.15, 0.3)`.
    CapsuleEllipse,
    /// A sharp square (corner radius 0), circumradius 0.35.
    Square,
}

/// What the shots hit: a thin fixed plank 0.05 × 6 at x = [`WALL_X`].
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Wall {
    /// parry's `Cuboid`.
    Cuboid,
    /// This crate's `RoundedPolygon`: the plank's core dilated by a corner radius of 0.005
    /// (parry's `RoundConvexPolygon` for the polygon method).
    Rounded,
}

/// The plank's corner radius when it is a rounded polygon.
const PLANK_RADIUS: f64 = 0.005;

/// How a shot is simulated: the shape and the narrow phase.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum ShotMethod {
    /// This crate's shape, `SmoothDispatcher`.
    Smooth,
    /// The shape approximated by parry's convex polygon (a 32-gon inscribed in the ellipse,
    /// `RoundConvexPolygon` for the heptagon), rapier's default narrow phase and its own sweeps.
    Polygon,
    /// This crate's shape, parry's `DefaultQueryDispatcher` (`NarrowPhase::new()`).
    ParryDefault,
}

impl ShotMethod {
    /// The narrow phase of the method.
    pub fn narrow_phase(self) -> NarrowPhase {
        match self {
            ShotMethod::Smooth => NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
            _ => NarrowPhase::new(),
        }
    }
}

/// The heptagon's circumradius.
const HEPTAGON_R: f64 = 0.4;

/// The collider shape of `body` under `method`.
pub fn shot_shape(body: ShotBody, method: ShotMethod) -> SharedShape {
    match (body, method) {
        (ShotBody::Ellipse, ShotMethod::Polygon) => {
            let pts = (0..32)
                .map(|i| {
                    let a = std::f64::consts::TAU * i as f64 / 32.0;
                    Vector::new(0.5 * a.cos(), 0.2 * a.sin())
                })
                .collect();
            SharedShape::convex_polyline(pts).expect("a convex 32-gon")
        }
        (ShotBody::Ellipse, _) => SharedShape::new(Ellipse::new(0.5, 0.2)),
        (ShotBody::Heptagon, m) => {
            let p = RoundedPolygon::regular(7, HEPTAGON_R, 0.15 * HEPTAGON_R);
            if m == ShotMethod::Polygon {
                SharedShape::new(p.to_parry().expect("a heptagon"))
            } else {
                SharedShape::new(p)
            }
        }
        (ShotBody::CapsuleEllipse, m) => {
            let c = CapsuleEllipse::new(0.12, 0.15, 0.3);
            if m == ShotMethod::Polygon {
                // 32 boundary points, spread by the normal angle.
                let pts = (0..32)
                    .map(|i| {
                        let a = std::f64::consts::TAU * i as f64 / 32.0;
                        ConvexCurve::support_point(&c, Vector::new(a.cos(), a.sin()))
                    })
                    .collect();
                SharedShape::convex_polyline(pts).expect("a convex 32-gon")
            } else {
                SharedShape::new(c)
            }
        }
        (ShotBody::Square, m) => {
            let p = RoundedPolygon::regular(4, 0.35, 0.0);
            if m == ShotMethod::Polygon {
                SharedShape::new(p.to_parry().expect("a square").inner_shape)
            } else {
                SharedShape::new(p)
            }
        }
    }
}

/// One shot: launch speed (m/s, along +x), spin (rad/s), initial angle.
#[derive(Clone, Copy, Debug)]
pub struct Shot {
    pub speed: f64,
    pub spin: f64,
    pub angle0: f64,
}

impl Shot {
    /// Whether the shot is above rapier's caps: 400 m/s (`normalized_max_linear_velocity` at a
    /// length unit of 1) or π/4 of rotation in a step of 1/60 s (47 rad/s, without
    /// `allow_fast_rotation`). The scenes lift both for such a shot, so that the speed claimed is
    /// the speed simulated.
    pub fn above_caps(&self) -> bool {
        self.speed > 400.0 || self.spin.abs() / 60.0 > core::f64::consts::FRAC_PI_4
    }
}

/// A world without gravity holding the wall and, at the origin, a body of collider `shape` launched
/// as `shot` (CCD on, never asleep; rapier's caps lifted for a shot above them,
/// [`Shot::above_caps`]), with the narrow phase of `method`. Returns the world and the body.
pub fn wall_shot(method: ShotMethod, shape: SharedShape, shot: Shot) -> (World, RigidBodyHandle) {
    wall_shot_at(method, shape, shot, Wall::Cuboid)
}

/// As [`wall_shot`] with the plank `wall`.
pub fn wall_shot_at(method: ShotMethod, shape: SharedShape, shot: Shot, wall: Wall) -> (World, RigidBodyHandle) {
    let mut world = World::new(method.narrow_phase());
    let plank = match wall {
        Wall::Cuboid => ColliderBuilder::cuboid(WALL_HALF, WALL_HALF_HEIGHT),
        Wall::Rounded => {
            let (hx, hy) = (WALL_HALF - PLANK_RADIUS, WALL_HALF_HEIGHT - PLANK_RADIUS);
            let core = [
                Vector::new(-hx, -hy),
                Vector::new(hx, -hy),
                Vector::new(hx, hy),
                Vector::new(-hx, hy),
            ];
            let p = RoundedPolygon::new(&core, PLANK_RADIUS);
            if method == ShotMethod::Polygon {
                ColliderBuilder::new(SharedShape::new(p.to_parry().expect("a plank")))
            } else {
                ColliderBuilder::new(SharedShape::new(p))
            }
        }
    };
    world.insert(RigidBodyBuilder::fixed().translation(Vector::new(WALL_X, 0.0)), plank);
    if shot.above_caps() {
        world.params.normalized_max_linear_velocity = f64::MAX;
    }
    let (h, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .rotation(shot.angle0)
            .linvel(Vector::new(shot.speed, 0.0))
            .angvel(shot.spin)
            .allow_fast_rotation(shot.above_caps())
            .ccd_enabled(true)
            .can_sleep(false),
        ColliderBuilder::new(shape),
    );
    (world, h)
}

/// Where the two bodies of [`head_on`] start: at x = ∓`HEAD_ON_X`.
pub const HEAD_ON_X: f64 = 3.0;

/// A world without gravity holding two bodies shot at each other along the x axis: collider
/// `a` at (−[`HEAD_ON_X`], 0) launched as `sa` (towards +x), collider `b` at (+[`HEAD_ON_X`], 0)
/// launched as `sb` (towards −x); never asleep. CCD is on for `a` only: rapier 0.36 sweeps a
/// CCD body ("bullet") against every other body, moving ones included, but never against
/// another bullet (`tier_allows` in its `dynamics/ccd/sweeps.rs`). Returns the world and the
/// bodies.
pub fn head_on(
    method: ShotMethod,
    a: SharedShape,
    b: SharedShape,
    sa: Shot,
    sb: Shot,
) -> (World, RigidBodyHandle, RigidBodyHandle) {
    let mut world = World::new(method.narrow_phase());
    if sa.above_caps() || sb.above_caps() {
        world.params.normalized_max_linear_velocity = f64::MAX;
    }
    let mut launch = |x: f64, dir: f64, s: Shot, shape: SharedShape, ccd: bool| {
        world
            .insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(x, 0.0))
                    .rotation(s.angle0)
                    .linvel(Vector::new(dir * s.speed, 0.0))
                    .angvel(s.spin)
                    .allow_fast_rotation(s.above_caps())
                    .ccd_enabled(ccd)
                    .can_sleep(false),
                ColliderBuilder::new(shape),
            )
            .0
    };
    let ha = launch(-HEAD_ON_X, 1.0, sa, a, true);
    let hb = launch(HEAD_ON_X, -1.0, sb, b, false);
    (world, ha, hb)
}

/// A CCD sweep rapier asked of the dispatcher in the box pile: a body already in the floor box
/// at the start of the step (`stop_at_penetration = false`, the window one step of 1/60 s),
/// which the start-contact rule answers (recorded from the pile's runs).
pub struct RestingSweep {
    /// What the sweep is.
    pub name: &'static str,
    /// The body's shape and motion.
    pub body: PileShape,
    pub motion: parry2d_f64::query::NonlinearRigidMotion,
    /// The floor box (the pile's first wall) and its motion (at rest).
    pub floor: parry2d_f64::shape::Cuboid,
    pub floor_motion: parry2d_f64::query::NonlinearRigidMotion,
    /// Whether rapier's rule reports it within the step (the translation takes the contact an
    /// allowance deeper, or the core reaches the floor).
    pub deepens: bool,
}

/// The three slowest sweeps of a pile run: two `CapsuleEllipse`s and an ellipse spinning at
/// 13–27 rad/s while in the floor (the second one rises out of it within the step, the others
/// dive deeper: the first by less than a quarter of its inradius, the ellipse by more).
pub fn resting_sweeps() -> Vec<RestingSweep> {
    use parry2d_f64::math::Pose;
    use parry2d_f64::query::NonlinearRigidMotion;
    let motion = |(re, im): (f64, f64), t: [f64; 2], c: [f64; 2], v: [f64; 2], w: f64| {
        let mut start = Pose::new(Vector::new(t[0], t[1]), 0.0);
        start.rotation.re = re;
        start.rotation.im = im;
        NonlinearRigidMotion::new(start, Vector::new(c[0], c[1]), Vector::new(v[0], v[1]), w)
    };
    let (centre, half) = pile_walls()[0];
    let floor = parry2d_f64::shape::Cuboid::new(half);
    let floor_motion = NonlinearRigidMotion::new(Pose::new(centre, 0.0), Vector::ZERO, Vector::ZERO, 0.0);
    vec![
        RestingSweep {
            name: "capsule ellipse, 19 rad/s",
            body: PileShape::Capsule(CapsuleEllipse::new(
                0.178_234_504_238_823_37,
                0.109_016_788_418_517_27,
                0.167_714_088_374_334_74,
            )),
            motion: motion(
                (-0.034_168_353_875_497_52, -0.999_416_091_322_047_2),
                [-0.334_812_958_242_428, 0.178_963_876_429_483_8],
                [0.011_258_892_149_778_411, -2.059_984_127_722_458_4e-18],
                [-1.710_109_712_819_610_8, -2.215_656_670_272_618],
                19.250_505_440_691_928,
            ),
            floor,
            floor_motion,
            deepens: false,
        },
        RestingSweep {
            name: "capsule ellipse, 14 rad/s",
            body: PileShape::Capsule(CapsuleEllipse::new(
                0.127_643_510_412_145_17,
                0.034_864_026_770_626_97,
                0.174_338_512_523_946_25,
            )),
            motion: motion(
                (0.018_974_962_525_721_645, -0.999_819_959_191_227_3),
                [-0.923_284_777_736_674_4, 0.125_671_351_445_109_88],
                [-0.016_941_900_915_805_03, 1.029_992_063_861_229_2e-17],
                [-1.972_706_692_825_847_4, 0.490_722_179_003_552_64],
                13.648_057_258_332_125,
            ),
            floor,
            floor_motion,
            deepens: false,
        },
        RestingSweep {
            name: "ellipse, 27 rad/s",
            body: PileShape::Ellipse(Ellipse::new(0.228_795_364_536_342_14, 0.098_942_531_627_549_4)),
            motion: motion(
                (0.919_679_486_465_683_9, -0.392_669_889_569_108_75),
                [3.564_996_040_121_253_7, 0.127_851_480_521_780_5],
                [0.0, 0.0],
                [-0.263_043_739_540_886_9, -3.432_771_096_673_055],
                26.619_307_138_972_49,
            ),
            floor,
            floor_motion,
            deepens: true,
        },
    ]
}
