//! The moving-pairs scenes of issue 30, each run with the pass and with rapier alone (the same
//! world, `SmoothDispatcher` as the narrow phase, the pass's two calls left out): two bullets
//! head-on ([`head_on_shots`]), a bullet crossing another's path at an angle
//! ([`crossing_shots`]), a bullet at a fast dynamic plank ([`plank_shots`]), and the closed box
//! of 50 fast bouncing bodies ([`run_box`]). `tests/moving_pairs.rs`, `examples/moving_pairs.rs`
//! and `crates/parallel-tests` run them.
#![allow(dead_code)]

use super::moving_pairs::{Family, Hooks, Judge, Launch, Run, Totals, Verdicts};
use super::rng::Rng;
use super::world::state_hash;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{MovingPairsOptions, PairScope};
use std::time::Duration;

/// What one shot gave.
#[derive(Clone, Copy, Debug)]
pub struct ShotResult {
    pub verdicts: Verdicts,
    /// Kinetic energy and linear momentum at launch and at the end.
    pub e0: f64,
    pub e1: f64,
    pub p0: Vector,
    pub p1: Vector,
    /// Every pose and velocity finite at every step.
    pub finite: bool,
    pub totals: Totals,
}

impl ShotResult {
    /// Whether a pair passed through.
    pub fn through(&self) -> bool {
        self.verdicts.through > 0
    }
}

/// Runs `launches` for `steps` steps (friction `friction`), with the pass of `options` or
/// rapier alone.
pub fn run_shot(launches: &[Launch], steps: usize, friction: f64, options: Option<MovingPairsOptions>) -> ShotResult {
    run_shot_with(launches, steps, friction, options, false)
}

/// [`run_shot`], stepped with `hooks` (`true`: `CoreContactHooks`).
pub fn run_shot_with(
    launches: &[Launch],
    steps: usize,
    friction: f64,
    options: Option<MovingPairsOptions>,
    hooks: impl Into<Hooks>,
) -> ShotResult {
    let mut run = Run::new(launches, friction, options).with_hooks(hooks.into());
    let (e0, p0) = (run.energy(), run.momentum());
    let mut judge = Judge::new(&run);
    let mut finite = true;
    for _ in 0..steps {
        run.step();
        judge.observe(&run);
        finite &= run.finite();
    }
    ShotResult {
        verdicts: judge.verdicts,
        e0,
        e1: run.energy(),
        p0,
        p1: run.momentum(),
        finite,
        totals: run.totals,
    }
}

// ---------------------------------------------------------------------------------------------
// Head-on
// ---------------------------------------------------------------------------------------------

/// The head-on speeds of each body (m/s).
pub const HEAD_ON_SPEEDS: [f64; 4] = [100.0, 300.0, 1000.0, 3000.0];
/// The head-on spins of the two bodies (rad/s).
pub const HEAD_ON_SPINS: [(f64, f64); 3] = [(0.0, 0.0), (150.0, -90.0), (-600.0, 600.0)];
/// The second body's scale: equal sizes, and a body 0.4 times the size.
pub const HEAD_ON_SCALES: [f64; 2] = [1.0, 0.4];
/// Steps of a head-on shot (the bodies start 6 m apart: they meet within the first two).
pub const HEAD_ON_STEPS: usize = 20;

/// The speed of the slowed head-on shots (m/s): the same shot, every velocity and spin scaled
/// by `SLOW_SPEED / speed` (the same paths in space, the same poses at contact), which rapier
/// alone resolves without any CCD — the reference for the energy of a collision as rapier's
/// solver resolves it.
pub const SLOW_SPEED: f64 = 1.0;
/// Steps of a slowed shot (6 m apart at 2 m/s: they meet after about 180).
pub const SLOW_STEPS: usize = 300;

/// Two bullets shot at each other along the x axis.
#[derive(Clone, Copy, Debug)]
pub struct HeadOn {
    pub a: Family,
    pub b: Family,
    pub scale_b: f64,
    pub speed: f64,
    pub spins: (f64, f64),
    pub angles: (f64, f64),
}

impl HeadOn {
    /// The same shot at [`SLOW_SPEED`], its spins scaled alike.
    pub fn slowed(&self) -> HeadOn {
        let k = SLOW_SPEED / self.speed;
        HeadOn {
            speed: SLOW_SPEED,
            spins: (self.spins.0 * k, self.spins.1 * k),
            ..*self
        }
    }

    pub fn launches(&self) -> [Launch; 2] {
        let body = |family, scale, x: f64, dir: f64, spin, angle| Launch {
            family,
            scale,
            position: Vector::new(x, 0.0),
            angle,
            velocity: Vector::new(dir * self.speed, 0.0),
            spin,
            ccd: true,
        };
        [
            body(self.a, 1.0, -3.0, 1.0, self.spins.0, self.angles.0),
            body(self.b, self.scale_b, 3.0, -1.0, self.spins.1, self.angles.1),
        ]
    }
}

/// The family pairs of the head-on table: each family against itself, its neighbour in
/// [`Family::ALL`] and the family four further on (27 pairs: every family on each side).
pub fn head_on_pairs() -> Vec<(Family, Family)> {
    let n = Family::ALL.len();
    (0..n)
        .flat_map(|i| [0, 1, 4].map(|k| (Family::ALL[i], Family::ALL[(i + k) % n])))
        .collect()
}

/// Every head-on shot: the pairs × speeds × spins × sizes (648), angles varied by index.
pub fn head_on_shots() -> Vec<HeadOn> {
    let mut shots = Vec::new();
    for (a, b) in head_on_pairs() {
        for &speed in &HEAD_ON_SPEEDS {
            for &spins in &HEAD_ON_SPINS {
                for &scale_b in &HEAD_ON_SCALES {
                    let k = shots.len() as f64;
                    shots.push(HeadOn {
                        a,
                        b,
                        scale_b,
                        speed,
                        spins,
                        angles: ((0.37 * k) % 3.1, (1.13 * k) % 3.1),
                    });
                }
            }
        }
    }
    shots
}

// ---------------------------------------------------------------------------------------------
// Crossing paths
// ---------------------------------------------------------------------------------------------

/// The angles between the two paths (degrees).
pub const CROSSING_ANGLES: [f64; 5] = [30.0, 60.0, 90.0, 120.0, 150.0];
/// The speeds (m/s, both bodies).
pub const CROSSING_SPEEDS: [f64; 3] = [300.0, 1000.0, 3000.0];
/// The family pairs.
pub const CROSSING_PAIRS: [(Family, Family); 5] = [
    (Family::Ellipse, Family::Heptagon),
    (Family::Cuboid, Family::Ball),
    (Family::CapsuleEllipse, Family::UserCurve),
    (Family::Triangle, Family::Hexagon),
    (Family::Capsule, Family::Ellipse),
];

/// A bullet along +x and another whose path crosses it at `angle` degrees, both reaching the
/// crossing point (the origin) at the same time.
#[derive(Clone, Copy, Debug)]
pub struct Crossing {
    pub a: Family,
    pub b: Family,
    pub angle: f64,
    pub speed: f64,
}

impl Crossing {
    pub fn launches(&self) -> [Launch; 2] {
        let dir = Vector::new(self.angle.to_radians().cos(), self.angle.to_radians().sin());
        [
            Launch {
                family: self.a,
                scale: 1.0,
                position: Vector::new(-3.0, 0.0),
                angle: 0.4,
                velocity: Vector::new(self.speed, 0.0),
                spin: 100.0,
                ccd: true,
            },
            Launch {
                family: self.b,
                scale: 0.7,
                position: dir * -3.0,
                angle: 1.3,
                velocity: dir * self.speed,
                spin: -300.0,
                ccd: true,
            },
        ]
    }
}

/// Every crossing shot (75).
pub fn crossing_shots() -> Vec<Crossing> {
    let mut shots = Vec::new();
    for &(a, b) in &CROSSING_PAIRS {
        for &angle in &CROSSING_ANGLES {
            for &speed in &CROSSING_SPEEDS {
                shots.push(Crossing { a, b, angle, speed });
            }
        }
    }
    shots
}

// ---------------------------------------------------------------------------------------------
// A fast dynamic plank
// ---------------------------------------------------------------------------------------------

/// How the plank (3 m long, 0.05 m thick, dynamic, not a bullet) meets the bullet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlankWay {
    /// The plank flies along its length, edge first, at the bullet coming the other way: the
    /// bullet meets its 0.05 m end.
    EdgeOn,
    /// The plank flies broadside (along its thin direction) at the bullet: a thin wall that
    /// itself moves fast.
    Broadside,
}

/// A bullet shot at a plank flying at it.
#[derive(Clone, Copy, Debug)]
pub struct PlankShot {
    pub bullet: Family,
    pub way: PlankWay,
    pub bullet_speed: f64,
    pub plank_speed: f64,
    pub bullet_spin: f64,
}

/// The bullet speeds, plank speeds and bullet spins of the plank shots.
pub const PLANK_BULLET_SPEEDS: [f64; 3] = [300.0, 1000.0, 3000.0];
pub const PLANK_SPEEDS: [f64; 2] = [100.0, 400.0];
pub const PLANK_SPINS: [f64; 2] = [0.0, 400.0];

impl PlankShot {
    pub fn launches(&self) -> [Launch; 2] {
        let bullet = Launch {
            family: self.bullet,
            scale: 1.0,
            position: Vector::new(-3.0, 0.0),
            angle: 0.3,
            velocity: Vector::new(self.bullet_speed, 0.0),
            spin: self.bullet_spin,
            ccd: true,
        };
        let plank = Launch {
            family: Family::Plank,
            scale: 1.0,
            position: Vector::new(if self.way == PlankWay::EdgeOn { 4.5 } else { 3.0 }, 0.0),
            angle: if self.way == PlankWay::EdgeOn {
                0.0
            } else {
                std::f64::consts::FRAC_PI_2
            },
            velocity: Vector::new(-self.plank_speed, 0.0),
            spin: 0.0,
            ccd: false,
        };
        [bullet, plank]
    }
}

/// Every plank shot (144).
pub fn plank_shots() -> Vec<PlankShot> {
    let mut shots = Vec::new();
    for way in [PlankWay::EdgeOn, PlankWay::Broadside] {
        for bullet in Family::ALL {
            for &bullet_speed in &PLANK_BULLET_SPEEDS {
                for &plank_speed in &PLANK_SPEEDS {
                    for &bullet_spin in &PLANK_SPINS[..1 + usize::from(bullet_speed < 3000.0)] {
                        shots.push(PlankShot {
                            bullet,
                            way,
                            bullet_speed,
                            plank_speed,
                            bullet_spin,
                        });
                    }
                }
            }
        }
    }
    shots
}

// ---------------------------------------------------------------------------------------------
// The closed box
// ---------------------------------------------------------------------------------------------

/// Bodies in the box.
pub const BOX_BODIES: usize = 50;
/// The box's inner half-width (m).
pub const BOX_HALF: f64 = 8.0;
/// Half the thickness of the box's walls (m).
pub const BOX_WALL_HALF: f64 = 0.5;
/// Steps: 10 s at rapier's 60 Hz.
pub const BOX_STEPS: usize = 600;
/// The seed of the bodies' launches.
pub const BOX_SEED: u64 = 0xB0C5_2030;

/// The box's bodies: a 10 × 5 grid, every family in turn, scales 0.6–1.2, speeds 50–250 m/s
/// in every direction, spins to ±300 rad/s, all bullets.
pub fn box_launches() -> Vec<Launch> {
    box_launches_seeded(BOX_SEED)
}

/// [`box_launches`] drawn from the random sequence of `seed` (the example's `--seed=N`: the
/// same box with other launches).
pub fn box_launches_seeded(seed: u64) -> Vec<Launch> {
    let mut rng = Rng::new(seed);
    (0..BOX_BODIES)
        .map(|i| {
            let (col, row) = ((i % 10) as f64, (i / 10) as f64);
            let dir = rng.uniform(0.0, std::f64::consts::TAU);
            let speed = rng.uniform(50.0, 250.0);
            Launch {
                family: Family::ALL[i % Family::ALL.len()],
                scale: rng.uniform(0.6, 1.2),
                position: Vector::new(-6.75 + 1.5 * col, -6.0 + 3.0 * row),
                angle: rng.uniform(-3.0, 3.0),
                velocity: Vector::new(dir.cos(), dir.sin()) * speed,
                spin: rng.uniform(-300.0, 300.0),
                ccd: true,
            }
        })
        .collect()
}

/// What a run of the box gave.
#[derive(Clone, Copy, Debug)]
pub struct BoxResult {
    pub verdicts: Verdicts,
    /// Bodies whose centre left the box at some step: beyond a wall's outer face.
    pub out_of_box: usize,
    /// Bodies whose centre entered a wall at some step (past its inner face), out or not.
    pub in_wall: usize,
    /// A pose or velocity not finite at some step.
    pub nan: bool,
    /// The run panicked (the other figures are those before it).
    pub panicked: bool,
    pub step_time: Duration,
    pub pass_time: Duration,
    pub totals: Totals,
    /// FNV-1a of the final state's bits.
    pub hash: u64,
    /// The kinetic energy at the end over that at the start.
    pub energy_ratio: f64,
}

/// Runs the box for `steps` steps (frictionless, restitution 1, walls 1 m thick), with the
/// pass of `options` or rapier alone, with `hooks` (`true`: `CoreContactHooks`, as docs/rapier.md
/// advises for bouncing bodies) or without; a panic is caught and reported.
pub fn run_box(steps: usize, options: Option<MovingPairsOptions>, hooks: impl Into<Hooks>) -> BoxResult {
    run_box_with(steps, options, hooks, &|_| {})
}

/// [`run_box`] in a world that `setup` prepares first (`crates/parallel-tests`: rapier's
/// thread pool).
pub fn run_box_with(
    steps: usize,
    options: Option<MovingPairsOptions>,
    hooks: impl Into<Hooks>,
    setup: &dyn Fn(&mut super::world::World),
) -> BoxResult {
    run_box_seeded(BOX_SEED, steps, options, hooks, setup)
}

/// [`run_box_with`] on the launches of `seed` ([`box_launches_seeded`]).
pub fn run_box_seeded(
    seed: u64,
    steps: usize,
    options: Option<MovingPairsOptions>,
    hooks: impl Into<Hooks>,
    setup: &dyn Fn(&mut super::world::World),
) -> BoxResult {
    let mut run = box_run(seed, options, hooks.into());
    setup(&mut run.world);
    let e0 = run.energy();
    let mut judge = Judge::new(&run);
    let mut out = vec![false; run.bodies.len()];
    let mut in_wall = vec![false; run.bodies.len()];
    let mut nan = false;
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        for _ in 0..steps {
            run.step();
            judge.observe(&run);
            nan |= !run.finite();
            for (k, c) in run.centres().iter().enumerate() {
                // A NaN centre counts as in a wall and out.
                let far = c.com.x.abs().max(c.com.y.abs());
                let within = |h: f64| far.partial_cmp(&h) == Some(std::cmp::Ordering::Less);
                in_wall[k] |= !within(BOX_HALF);
                out[k] |= !within(BOX_HALF + 2.0 * BOX_WALL_HALF);
            }
        }
    }));
    let handles: Vec<RigidBodyHandle> = run.bodies.iter().map(|t| t.body).collect();
    BoxResult {
        verdicts: judge.verdicts,
        out_of_box: out.iter().filter(|o| **o).count(),
        in_wall: in_wall.iter().filter(|o| **o).count(),
        nan,
        panicked: outcome.is_err(),
        step_time: run.step_time,
        pass_time: run.pass_time,
        totals: run.totals,
        hash: state_hash(&run.world, &handles).0,
        energy_ratio: run.energy() / e0,
    }
}

/// The box's world before its first step: the launches of `seed`, the four walls, `hooks`.
pub fn box_run(seed: u64, options: Option<MovingPairsOptions>, hooks: Hooks) -> Run {
    let mut run = Run::new(&box_launches_seeded(seed), 0.0, options);
    let (w, h, t) = (BOX_WALL_HALF, BOX_HALF + BOX_WALL_HALF, BOX_HALF + 2.0 * BOX_WALL_HALF);
    for (at, half) in [
        (Vector::new(0.0, -h), Vector::new(t, w)),
        (Vector::new(0.0, h), Vector::new(t, w)),
        (Vector::new(-h, 0.0), Vector::new(w, t)),
        (Vector::new(h, 0.0), Vector::new(w, t)),
    ] {
        run.wall(at, half, 0.0);
    }
    run.with_hooks(hooks)
}

/// The pass's options in the scenes: every pair with a fast bullet (the default).
pub fn pass_options() -> MovingPairsOptions {
    MovingPairsOptions {
        scope: PairScope::Bullets,
        ..MovingPairsOptions::default()
    }
}

// ---------------------------------------------------------------------------------------------
// References: the pass's cost where no pair is fast; rapier's own CCD bounce
// ---------------------------------------------------------------------------------------------

/// The pass's cost in the mixed pile of `scenes.rs` (150 bodies dropped on the ground, half of
/// them bullets), where no two bodies move fast at each other.
#[derive(Clone, Copy, Debug)]
pub struct PileCost {
    pub steps: usize,
    /// Time in `PhysicsPipeline::step` and in the pass's two calls, over the steps where the
    /// pass found no fast body (`[0]`) and where it found one (`[1]`).
    pub step_time: [Duration; 2],
    pub pass_time: [Duration; 2],
    /// Steps where the pass found a fast body, and its casts over the run.
    pub steps_with_fast: usize,
    pub casts: usize,
}

/// Steps the mixed pile with the pass (`SmoothDispatcher` as the narrow phase), timing the
/// step and the pass apart.
pub fn pile_cost(steps: usize) -> PileCost {
    use super::scenes::mixed_pile;
    use super::world::{World, GRAVITY};
    use smooth_ccd2d::{MovingPairs, SmoothDispatcher};
    use std::time::Instant;
    let mut world = World::new(NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()));
    mixed_pile(&mut world);
    let mut pass = MovingPairs::new(pass_options());
    let mut cost = PileCost {
        steps,
        step_time: [Duration::ZERO; 2],
        pass_time: [Duration::ZERO; 2],
        steps_with_fast: 0,
        casts: 0,
    };
    for _ in 0..steps {
        let t0 = Instant::now();
        pass.before_step(&world.bodies);
        let t1 = Instant::now();
        world.step(GRAVITY, &());
        let t2 = Instant::now();
        let report = pass.after_step(&world.params, &mut world.bodies, &mut world.colliders, &(), &());
        let t3 = Instant::now();
        let fast = usize::from(report.fast_bodies > 0);
        cost.step_time[fast] += t2 - t1;
        cost.pass_time[fast] += (t1 - t0) + (t3 - t2);
        cost.steps_with_fast += fast;
        cost.casts += report.casts;
    }
    cost
}

/// rapier's own CCD on the head-on speeds and spins: one bullet of every family shot at a fixed
/// 2 m thick wall (restitution 1, friction 0.5, 20 steps), rapier clamping it at its impact and
/// its solver resolving the contact at the next step — as the pass leaves a pair. Returns how
/// many shots ended with more kinetic energy than they started with, of how many, and the
/// largest ratio after over before. `hooks`: the hooks rapier steps with (`Hooks::None`: rapier's
/// own restitution).
pub fn wall_bounce_energy(hooks: Hooks) -> (usize, usize, f64) {
    let (mut gained, mut total, mut worst) = (0, 0, 0.0f64);
    for family in Family::ALL {
        for &speed in &HEAD_ON_SPEEDS {
            for &(spin, _) in &HEAD_ON_SPINS {
                let launch = Launch {
                    family,
                    scale: 1.0,
                    position: Vector::new(-3.0, 0.0),
                    angle: 0.37 * total as f64 % 3.1,
                    velocity: Vector::new(speed, 0.0),
                    spin,
                    ccd: true,
                };
                let mut run = Run::new(&[launch], 0.5, None);
                run.wall(Vector::new(3.0, 0.0), Vector::new(1.0, 20.0), 0.5);
                let mut run = run.with_hooks(hooks);
                let e0 = run.energy();
                for _ in 0..HEAD_ON_STEPS {
                    run.step();
                }
                let ratio = run.energy() / e0;
                total += 1;
                gained += usize::from(ratio > 1.0 + 1e-9);
                worst = worst.max(ratio);
            }
        }
    }
    (gained, total, worst)
}
