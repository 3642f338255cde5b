//! Deterministic random scenarios for time-of-impact tests: two convex shapes, two
//! `NonlinearRigidMotion`s, a window and a target distance, generated from a `u64` seed with the
//! splitmix64 generator of `rng.rs`. Used by the tests of `tests/` through `mod common`, the
//! benches through `benches/support` and `examples/toi_timing.rs` through `examples/common`.
//!
//! Every scenario is built around a configuration at a chosen time t_c: both shapes placed with
//! a chosen gap along a chosen normal (their support points aligned along it, so the distance is
//! the gap when it is ≥ 0), velocities chosen relative to that normal, and the motions then run
//! backwards to the window start. Scenarios are rejected until the pair is separated at the
//! start by more than 1e-4 of its size above the target, so every scenario starts apart.
//!
//! Shapes are built at unit size and scaled by a factor 10^U(−2, 2); positions and velocities
//! scale with them, spins do not, the window is always [0, 1].

use super::reference::{reference_distance_at, reference_toi, world_support, RefToi};
use super::rng::Rng;
use core::f64::consts::{PI, TAU};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use parry2d_f64::shape::{Ball, Cuboid, Shape};
use smooth_ccd2d::{BallCurve, CapsuleEllipse, ConvexCurve, Ellipse, RoundedPolygon};

/// A shape of a scenario, concrete so that tests can wrap it in whatever parry shape they need.
#[derive(Clone, Debug)]
pub enum TestShape {
    /// An ellipse.
    Ellipse(Ellipse),
    /// A disc.
    Ball(BallCurve),
    /// A rounded (or sharp, radius 0) convex polygon.
    RoundedPolygon(RoundedPolygon),
    /// The specification's Appendix A shape.
    CapsuleEllipse(CapsuleEllipse),
    /// parry's `Cuboid` with these half-extents (as a curve: the sharp box it is).
    Cuboid(Vector, RoundedPolygon),
}

impl TestShape {
    /// The shape as a convex curve.
    pub fn curve(&self) -> &dyn ConvexCurve {
        match self {
            TestShape::Ellipse(s) => s,
            TestShape::Ball(s) => s,
            TestShape::RoundedPolygon(s) => s,
            TestShape::CapsuleEllipse(s) => s,
            TestShape::Cuboid(_, s) => s,
        }
    }
    /// The shape as a parry shape (a disc as parry's `Ball`, a box as parry's `Cuboid`).
    pub fn parry_shape(&self) -> Box<dyn Shape> {
        match self {
            TestShape::Ellipse(e) => Box::new(*e),
            TestShape::Ball(b) => Box::new(Ball::new(b.radius)),
            TestShape::RoundedPolygon(p) => Box::new(p.clone()),
            TestShape::CapsuleEllipse(c) => Box::new(c.clone()),
            TestShape::Cuboid(h, _) => Box::new(Cuboid::new(*h)),
        }
    }
    /// A short description (type and parameters).
    pub fn describe(&self) -> String {
        match self {
            TestShape::Ellipse(e) => format!("Ellipse({:e}, {:e})", e.half_x(), e.half_y()),
            TestShape::Ball(b) => format!("Ball({:e})", b.radius),
            TestShape::RoundedPolygon(p) => {
                format!(
                    "RoundedPolygon({} vertices, r = {:e})",
                    p.vertices().len(),
                    p.corner_radius()
                )
            }
            TestShape::CapsuleEllipse(c) => format!("CapsuleEllipse{:?}", c.params()),
            TestShape::Cuboid(h, _) => format!("Cuboid({:e}, {:e})", h.x, h.y),
        }
    }
}

/// The shape pairings (object 1 – object 2) scenarios are drawn from.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum ScenarioClass {
    /// Ellipse – ellipse (axis ratios up to 1:100).
    EllipseEllipse,
    /// Ellipse – disc (`BallCurve` as object 2).
    EllipseBall,
    /// Rounded polygon (corner radius > 0) – ellipse.
    RoundedPolygonEllipse,
    /// Ellipse – rounded polygon (corner radius > 0).
    EllipseRoundedPolygon,
    /// Appendix A's `CapsuleEllipse` – ellipse.
    CapsuleEllipseEllipse,
    /// Sharp polygon (corner radius 0) – ellipse.
    SharpPolygonEllipse,
    /// Polygon – polygon, each rounded or sharp (radius 0 on either side): no strictly convex
    /// side.
    PolygonPolygon,
    /// Polygon (rounded or sharp) – parry `Cuboid`.
    PolygonCuboid,
    /// Appendix A's `CapsuleEllipse` – polygon (rounded or sharp; a `Cuboid` one time in four).
    CapsuleEllipsePolygon,
    /// parry `Cuboid` – `Cuboid` (parry's rotating-box misses, its issue #317).
    CuboidCuboid,
}

impl ScenarioClass {
    /// Every class.
    pub const ALL: [ScenarioClass; 10] = [
        ScenarioClass::EllipseEllipse,
        ScenarioClass::EllipseBall,
        ScenarioClass::RoundedPolygonEllipse,
        ScenarioClass::EllipseRoundedPolygon,
        ScenarioClass::CapsuleEllipseEllipse,
        ScenarioClass::SharpPolygonEllipse,
        ScenarioClass::PolygonPolygon,
        ScenarioClass::PolygonCuboid,
        ScenarioClass::CapsuleEllipsePolygon,
        ScenarioClass::CuboidCuboid,
    ];
    /// The classes with a strictly convex side (the φ–t tracker's; `time_of_impact` takes them).
    pub const STRICTLY_CONVEX: [ScenarioClass; 6] = [
        ScenarioClass::EllipseEllipse,
        ScenarioClass::EllipseBall,
        ScenarioClass::RoundedPolygonEllipse,
        ScenarioClass::EllipseRoundedPolygon,
        ScenarioClass::CapsuleEllipseEllipse,
        ScenarioClass::SharpPolygonEllipse,
    ];
    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            ScenarioClass::EllipseEllipse => "ellipse-ellipse",
            ScenarioClass::EllipseBall => "ellipse-ball",
            ScenarioClass::RoundedPolygonEllipse => "rounded_polygon-ellipse",
            ScenarioClass::EllipseRoundedPolygon => "ellipse-rounded_polygon",
            ScenarioClass::CapsuleEllipseEllipse => "capsule_ellipse-ellipse",
            ScenarioClass::SharpPolygonEllipse => "sharp_polygon-ellipse",
            ScenarioClass::PolygonPolygon => "polygon-polygon",
            ScenarioClass::PolygonCuboid => "polygon-cuboid",
            ScenarioClass::CapsuleEllipsePolygon => "capsule_ellipse-polygon",
            ScenarioClass::CuboidCuboid => "cuboid-cuboid",
        }
    }
    fn salt(self) -> u64 {
        let i = ScenarioClass::ALL.iter().position(|&c| c == self).unwrap() as u64;
        (i + 1).wrapping_mul(0xD1B5_4A32_D192_ED03)
    }
}

/// How the motions of a scenario were drawn.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum ScenarioKind {
    /// Spins up to 3 rad/s; hit inside the window, hit after it, or a pass-by.
    Ordinary,
    /// One body (sometimes both) spinning at 20–60 rad/s.
    FastSpin,
    /// One body at 30–60 rad/s with a slow approach: several turns before the impact.
    MultiTurn,
    /// A tangential pass whose distance has a critical point within ±1e-9..1e-3 of the size
    /// around the target (near-grazing hits and near misses), any spin.
    Grazing,
    /// A clear pass-by at 2–50 % of the size, spins up to 10 rad/s.
    PassBy,
}

impl ScenarioKind {
    /// Every kind.
    pub const ALL: [ScenarioKind; 5] = [
        ScenarioKind::Ordinary,
        ScenarioKind::FastSpin,
        ScenarioKind::MultiTurn,
        ScenarioKind::Grazing,
        ScenarioKind::PassBy,
    ];
}

/// One time-of-impact problem.
#[derive(Clone, Debug)]
pub struct Scenario {
    /// The class it was drawn from.
    pub class: ScenarioClass,
    /// How its motion was drawn.
    pub kind: ScenarioKind,
    /// The seed it was generated from (`generate(class, seed)` reproduces it).
    pub seed: u64,
    /// Object 1.
    pub shape1: TestShape,
    /// Object 2.
    pub shape2: TestShape,
    /// Motion of object 1.
    pub motion1: NonlinearRigidMotion,
    /// Motion of object 2.
    pub motion2: NonlinearRigidMotion,
    /// Window start (0).
    pub t0: f64,
    /// Window end (1).
    pub t1: f64,
    /// Target distance (≥ 0).
    pub target: f64,
    /// The size scale factor applied to unit-size shapes.
    pub scale: f64,
    /// The time t_c of the constructed configuration (may lie outside the window).
    pub tc: f64,
    /// The gap along the constructed normal at t_c, minus the target (< 0: aimed to hit).
    pub aimed_gap: f64,
}

impl Scenario {
    /// Object 1 as a curve.
    pub fn curve1(&self) -> &dyn ConvexCurve {
        self.shape1.curve()
    }
    /// Object 2 as a curve.
    pub fn curve2(&self) -> &dyn ConvexCurve {
        self.shape2.curve()
    }
    /// The size s of the crate's tolerances: the larger bounding radius of the two shapes.
    pub fn size(&self) -> f64 {
        self.curve1().bounding_radius().max(self.curve2().bounding_radius())
    }
    /// The reference signed distance at time `t`.
    pub fn distance_at(&self, t: f64) -> f64 {
        reference_distance_at(self.curve1(), &self.motion1, self.curve2(), &self.motion2, t).distance
    }
    /// The reference time of impact (default options).
    pub fn reference(&self) -> RefToi {
        self.reference_with_target(self.target)
    }
    /// The reference time of impact for another target distance (e.g. `target + margin`, to
    /// tell a clear miss from one that comes within `margin` of the target).
    pub fn reference_with_target(&self, target: f64) -> RefToi {
        reference_toi(
            self.curve1(),
            &self.motion1,
            self.curve2(),
            &self.motion2,
            self.t0,
            self.t1,
            target,
        )
    }
    /// Turns of the faster-spinning body over `[t0, t]`.
    pub fn turns_until(&self, t: f64) -> f64 {
        self.motion1.angvel.abs().max(self.motion2.angvel.abs()) * (t - self.t0) / TAU
    }
    /// Everything as finite numbers?
    pub fn is_finite(&self) -> bool {
        let m_ok = |m: &NonlinearRigidMotion| {
            m.start.translation.is_finite()
                && m.start.rotation.re.is_finite()
                && m.start.rotation.im.is_finite()
                && m.local_center.is_finite()
                && m.linvel.is_finite()
                && m.angvel.is_finite()
        };
        m_ok(&self.motion1)
            && m_ok(&self.motion2)
            && self.target.is_finite()
            && self.curve1().bounding_radius().is_finite()
            && self.curve2().bounding_radius().is_finite()
    }
    /// A one-line description for failure messages.
    pub fn describe(&self) -> String {
        format!(
            "{} {:?} seed {}: {} vs {}, m1 {:?}, m2 {:?}, window [{}, {}], target {:e}",
            self.class.name(),
            self.kind,
            self.seed,
            self.shape1.describe(),
            self.shape2.describe(),
            self.motion1,
            self.motion2,
            self.t0,
            self.t1,
            self.target
        )
    }
}

fn ellipse(rng: &mut Rng, s: f64) -> TestShape {
    // Axis ratio b/a in [1/100, 1], a quarter of them thinner than 1:30.
    let ratio = if rng.chance(0.25) {
        rng.log_uniform(0.01, 1.0 / 30.0)
    } else {
        rng.log_uniform(0.01, 1.0)
    };
    let (a, b) = (s, s * ratio);
    TestShape::Ellipse(if rng.chance(0.5) {
        Ellipse::new(a, b)
    } else {
        Ellipse::new(b, a)
    })
}

fn polygon(rng: &mut Rng, s: f64, rounded: bool) -> TestShape {
    let circ = s * rng.uniform(0.4, 1.0);
    let radius = if rounded {
        circ * rng.log_uniform(0.01, 0.5)
    } else {
        0.0
    };
    if rng.chance(0.7) {
        let sides = rng.int(3, 8);
        return TestShape::RoundedPolygon(RoundedPolygon::regular(sides, circ, radius));
    }
    // Irregular: vertices on a circle, angular gaps in [0.15, π − 0.1].
    loop {
        let n = rng.int(3, 8);
        let mut gaps: Vec<f64> = (0..n).map(|_| rng.uniform(0.3, 1.0)).collect();
        let sum: f64 = gaps.iter().sum();
        gaps.iter_mut().for_each(|g| *g *= TAU / sum);
        if gaps.iter().any(|&g| !(0.15..=PI - 0.1).contains(&g)) {
            continue;
        }
        let start = rng.uniform(0.0, TAU);
        let mut a = start;
        let verts: Vec<Vector> = gaps
            .iter()
            .map(|g| {
                let v = Vector::new(a.cos(), a.sin()) * circ;
                a += g;
                v
            })
            .collect();
        if let Ok(p) = RoundedPolygon::try_new(&verts, radius) {
            return TestShape::RoundedPolygon(p);
        }
    }
}

fn capsule_ellipse(rng: &mut Rng, s: f64) -> TestShape {
    let (r1, r2, r3) = (rng.uniform(0.2, 0.8), rng.uniform(0.1, 0.8), rng.uniform(0.1, 1.5));
    TestShape::CapsuleEllipse(CapsuleEllipse::new(s * r1, s * r2, s * r3))
}

/// A parry `Cuboid` of size about `s`, aspect ratio 1 to 1:20.
fn cuboid(rng: &mut Rng, s: f64) -> TestShape {
    let a = s * rng.uniform(0.5, 1.0);
    let b = a * rng.log_uniform(0.05, 1.0);
    let h = if rng.chance(0.5) {
        Vector::new(a, b)
    } else {
        Vector::new(b, a)
    };
    let curve = RoundedPolygon::new(
        &[
            Vector::new(-h.x, -h.y),
            Vector::new(h.x, -h.y),
            Vector::new(h.x, h.y),
            Vector::new(-h.x, h.y),
        ],
        0.0,
    );
    TestShape::Cuboid(h, curve)
}

/// The shapes of the classes with no strictly convex side.
fn faceted_shapes(class: ScenarioClass, rng: &mut Rng, s: f64, s2: f64) -> (TestShape, TestShape) {
    match class {
        ScenarioClass::PolygonPolygon => {
            let rounded1 = rng.chance(0.5);
            let first = polygon(rng, s, rounded1);
            let rounded2 = rng.chance(0.5);
            (first, polygon(rng, s2, rounded2))
        }
        ScenarioClass::PolygonCuboid => {
            let rounded = rng.chance(0.5);
            let first = polygon(rng, s, rounded);
            (first, cuboid(rng, s2))
        }
        ScenarioClass::CapsuleEllipsePolygon => {
            let first = capsule_ellipse(rng, s);
            let second = if rng.chance(0.25) {
                cuboid(rng, s2)
            } else {
                let rounded = rng.chance(0.5);
                polygon(rng, s2, rounded)
            };
            (first, second)
        }
        _ => {
            let first = cuboid(rng, s);
            (first, cuboid(rng, s2))
        }
    }
}

fn shapes(class: ScenarioClass, rng: &mut Rng, s: f64) -> (TestShape, TestShape) {
    if !ScenarioClass::STRICTLY_CONVEX.contains(&class) {
        let s2 = s * rng.uniform(0.3, 1.0);
        return faceted_shapes(class, rng, s, s2);
    }
    let first = match class {
        ScenarioClass::EllipseEllipse | ScenarioClass::EllipseBall | ScenarioClass::EllipseRoundedPolygon => {
            ellipse(rng, s)
        }
        ScenarioClass::RoundedPolygonEllipse => polygon(rng, s, true),
        ScenarioClass::CapsuleEllipseEllipse => capsule_ellipse(rng, s),
        ScenarioClass::SharpPolygonEllipse => polygon(rng, s, false),
        _ => unreachable!("classes with a strictly convex side"),
    };
    let s2 = match class {
        ScenarioClass::EllipseBall => s * rng.uniform(0.05, 1.0),
        _ => s * rng.uniform(0.3, 1.0),
    };
    let second = match class {
        ScenarioClass::EllipseBall => TestShape::Ball(BallCurve { radius: s2 }),
        ScenarioClass::EllipseRoundedPolygon => polygon(rng, s2, true),
        _ => ellipse(rng, s2),
    };
    (first, second)
}

fn pick_kind(rng: &mut Rng) -> ScenarioKind {
    let u = rng.unit();
    if u < 0.35 {
        ScenarioKind::Ordinary
    } else if u < 0.55 {
        ScenarioKind::FastSpin
    } else if u < 0.70 {
        ScenarioKind::MultiTurn
    } else if u < 0.90 {
        ScenarioKind::Grazing
    } else {
        ScenarioKind::PassBy
    }
}

fn perp(v: Vector) -> Vector {
    Vector::new(-v.y, v.x)
}

/// The target distance: 0 (45 %), a few 1e-6 of the size (40 %), or 0.1–5 % of it.
fn draw_target(rng: &mut Rng, size: f64) -> f64 {
    let u = rng.unit();
    if u < 0.45 {
        0.0
    } else if u < 0.85 {
        size * rng.uniform(1e-6, 4e-6)
    } else {
        size * rng.uniform(1e-3, 0.05)
    }
}

/// A spin of 20–60 rad/s either way.
fn fast_spin(rng: &mut Rng) -> f64 {
    rng.sign() * rng.uniform(20.0, 60.0)
}

/// `fast` on body 1 or body 2 (even odds), `other` on the other body.
fn either_body(rng: &mut Rng, fast: f64, other: f64) -> (f64, f64) {
    if rng.chance(0.5) {
        (fast, other)
    } else {
        (other, fast)
    }
}

/// The spins (ω1, ω2) of `kind`.
fn draw_spins(rng: &mut Rng, kind: ScenarioKind) -> (f64, f64) {
    match kind {
        ScenarioKind::Ordinary => (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)),
        ScenarioKind::FastSpin => {
            let fast = fast_spin(rng);
            let other = if rng.chance(0.3) {
                fast_spin(rng)
            } else {
                rng.uniform(-5.0, 5.0)
            };
            either_body(rng, fast, other)
        }
        ScenarioKind::MultiTurn => {
            let fast = rng.sign() * rng.uniform(30.0, 60.0);
            let other = rng.uniform(-3.0, 3.0);
            either_body(rng, fast, other)
        }
        ScenarioKind::Grazing => {
            let u = rng.unit();
            if u < 0.5 {
                (0.0, 0.0)
            } else if u < 0.8 {
                (rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0))
            } else if rng.chance(0.5) {
                (fast_spin(rng), rng.uniform(-2.0, 2.0))
            } else {
                (rng.uniform(-2.0, 2.0), fast_spin(rng))
            }
        }
        ScenarioKind::PassBy => (rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0)),
    }
}

/// A rotation centre in the body's frame: its origin, or (three times in ten) a point within half
/// its bounding radius `br`.
fn draw_centre(rng: &mut Rng, br: f64) -> Vector {
    if rng.chance(0.3) {
        rng.in_disc(0.5 * br)
    } else {
        Vector::ZERO
    }
}

/// The configuration of a scenario at its time t_c, relative to the normal n from object 1 to
/// object 2: the gap along n and the relative velocity v₂ − v₁ = −un·n + ut·n⊥.
struct Approach {
    /// The configuration time t_c.
    tc: f64,
    /// The gap along n at t_c minus the target (< 0: aimed to hit).
    gap: f64,
    /// The relative velocity's normal part (> 0: approaching).
    un: f64,
    /// The relative velocity's tangential part.
    ut: f64,
    /// Replace `un` by the normal speed that cancels the spins' effect on the gap along n at t_c:
    /// the distance then has a critical point there.
    cancel_rotation: bool,
}

impl Approach {
    /// The approach at `tc` with gap `gap` and relative velocity (`un`, `ut`) as drawn.
    fn new(tc: f64, gap: f64, un: f64, ut: f64) -> Self {
        Approach {
            tc,
            gap,
            un,
            ut,
            cancel_rotation: false,
        }
    }
}

/// An approach aimed to hit at t_c uniform in `tc`: normal speed `reach·U(speed)/t_c`, overlap
/// `size·U(0, depth)` at t_c, tangential speed up to `spread` times the normal one.
fn aimed(rng: &mut Rng, tc: (f64, f64), speed: (f64, f64), depth: f64, spread: f64, reach: f64, size: f64) -> Approach {
    let tc = rng.uniform(tc.0, tc.1);
    let un = reach * rng.uniform(speed.0, speed.1) / tc;
    let gap = -size * rng.uniform(0.0, depth);
    Approach::new(tc, gap, un, un * rng.uniform(-spread, spread))
}

/// A clear pass-by at 2–50 % of the size, mostly tangential.
fn pass_by(rng: &mut Rng, reach: f64, size: f64) -> Approach {
    let ut = reach * rng.uniform(1.0, 4.0) * rng.sign();
    let tc = rng.uniform(0.1, 0.9);
    let gap = size * rng.uniform(0.02, 0.5);
    Approach::new(tc, gap, ut.abs() * rng.uniform(-0.05, 0.05), ut)
}

/// A tangential pass whose distance has a critical point within ±1e-9..1e-3 of the size around
/// the target at t_c.
fn graze(rng: &mut Rng, reach: f64, size: f64) -> Approach {
    let eps = size * rng.log_uniform(1e-9, 1e-3) * rng.sign();
    let ut = reach * rng.uniform(1.0, 4.0) * rng.sign();
    Approach {
        tc: rng.uniform(0.2, 0.9),
        gap: eps,
        un: 0.0,
        ut,
        cancel_rotation: true,
    }
}

/// The approach of `kind`: for ordinary and fast-spin scenarios a hit inside the window (50 %),
/// a hit after it (30 %) or a pass-by.
fn draw_approach(rng: &mut Rng, kind: ScenarioKind, reach: f64, size: f64) -> Approach {
    match kind {
        ScenarioKind::Ordinary | ScenarioKind::FastSpin => {
            let u = rng.unit();
            if u < 0.5 {
                aimed(rng, (0.05, 0.97), (1.2, 3.0), 0.05, 1.0, reach, size)
            } else if u < 0.8 {
                aimed(rng, (1.05, 3.0), (1.2, 3.0), 0.05, 1.0, reach, size)
            } else {
                pass_by(rng, reach, size)
            }
        }
        ScenarioKind::MultiTurn => aimed(rng, (0.4, 1.6), (0.1, 1.5), 0.02, 0.5, reach, size),
        ScenarioKind::Grazing => graze(rng, reach, size),
        ScenarioKind::PassBy => pass_by(rng, reach, size),
    }
}

/// The poses at t_c: object 1 at the origin, object 2 along a random normal n with the support
/// points aligned along it, `gap_total` apart. Returns both poses, n and object 1's support point.
fn configuration(
    rng: &mut Rng,
    c1: &dyn ConvexCurve,
    c2: &dyn ConvexCurve,
    gap_total: f64,
) -> (Pose, Pose, Vector, Vector) {
    let (a1, a2) = (rng.uniform(0.0, TAU), rng.uniform(0.0, TAU));
    let n = rng.direction_tau();
    let pose1c = Pose::new(Vector::ZERO, a1);
    let rot2 = Pose::new(Vector::ZERO, a2);
    let x1 = pose1c * c1.support_point(pose1c.rotation.inverse_transform_vector(n));
    let x2_local = c2.support_point(rot2.rotation.inverse_transform_vector(-n));
    let p2 = x1 + n * gap_total - rot2.rotation * x2_local;
    let pose2c = Pose::new(p2, a2);
    let size = c1.bounding_radius().max(c2.bounding_radius());
    debug_assert!(((-world_support(c1, &pose1c, n) - world_support(c2, &pose2c, -n)) - gap_total).abs() <= 1e-9 * size);
    (pose1c, pose2c, n, x1)
}

/// Both motions: the configuration of `ap` at t_c (`gap_total` = target + gap along n), the
/// relative velocity of `ap` plus a common drift, run back from t_c to time 0. `centres` and
/// `spins` are the bodies' rotation centres (local) and angular velocities.
fn draw_motions(
    rng: &mut Rng,
    c1: &dyn ConvexCurve,
    c2: &dyn ConvexCurve,
    centres: (Vector, Vector),
    spins: (f64, f64),
    ap: &Approach,
    gap_total: f64,
) -> (NonlinearRigidMotion, NonlinearRigidMotion) {
    let ((lc1, lc2), (w1, w2)) = (centres, spins);
    let reach = c1.bounding_radius() + c2.bounding_radius();
    let (pose1c, pose2c, n, x1) = configuration(rng, c1, c2, gap_total);
    // Velocities: v_rel = v2 − v1 = −un·n + ut·n⊥ (+ the normal part cancelling the spins' effect
    // on the gap along n when requested: then the distance has a critical point at tc).
    let mut un = ap.un;
    if ap.cancel_rotation {
        let (cc1, cc2) = (pose1c * lc1, pose2c * lc2);
        let x2 = x1 + n * gap_total;
        // d/dt g(n) = v_rel·n + [ω2 (x2 − c2)⊥ − ω1 (x1 − c1)⊥]·n must vanish.
        let rot_term = (perp(x2 - cc2) * w2 - perp(x1 - cc1) * w1).dot(n);
        un = rot_term; // v_rel·n = −un.
    }
    let v_rel = -n * un + perp(n) * ap.ut;
    let v_common = rng.in_disc(2.0 * reach);
    let (v1, v2) = (v_common, v_common + v_rel);

    let m1c = NonlinearRigidMotion::new(pose1c, lc1, v1, w1);
    let m2c = NonlinearRigidMotion::new(pose2c, lc2, v2, w2);
    (
        NonlinearRigidMotion::new(m1c.position_at_time(-ap.tc), lc1, v1, w1),
        NonlinearRigidMotion::new(m2c.position_at_time(-ap.tc), lc2, v2, w2),
    )
}

/// One attempt; `None` when the drawn scenario does not start separated.
fn try_generate(class: ScenarioClass, seed: u64, rng: &mut Rng) -> Option<Scenario> {
    let scale = rng.log_uniform(0.01, 100.0);
    let (shape1, shape2) = shapes(class, rng, scale);
    let kind = pick_kind(rng);
    let (c1, c2) = (shape1.curve(), shape2.curve());
    let (br1, br2) = (c1.bounding_radius(), c2.bounding_radius());
    let size = br1.max(br2);
    let reach = br1 + br2;
    let target = draw_target(rng, size);
    let spins = draw_spins(rng, kind);
    let lc1 = draw_centre(rng, br1);
    let lc2 = draw_centre(rng, br2);
    let ap = draw_approach(rng, kind, reach, size);
    let (motion1, motion2) = draw_motions(rng, c1, c2, (lc1, lc2), spins, &ap, target + ap.gap);

    let sc = Scenario {
        class,
        kind,
        seed,
        shape1,
        shape2,
        motion1,
        motion2,
        t0: 0.0,
        t1: 1.0,
        target,
        scale,
        tc: ap.tc,
        aimed_gap: ap.gap,
    };
    if !sc.is_finite() {
        return None;
    }
    let d0 = sc.distance_at(0.0);
    if !(d0.is_finite() && d0 - target > 1e-4 * size) {
        return None;
    }
    Some(sc)
}

/// The scenario of `class` for `seed` (deterministic). Draws are repeated (from the same
/// generator stream) until the pair starts separated by more than 1e-4·size above the target.
pub fn generate(class: ScenarioClass, seed: u64) -> Scenario {
    let mut rng = Rng::new(seed ^ class.salt());
    for _ in 0..10_000 {
        if let Some(s) = try_generate(class, seed, &mut rng) {
            return s;
        }
    }
    panic!("no separated scenario for {} seed {seed}", class.name());
}

/// `count` scenarios of `class` for seeds `first_seed..first_seed + count`.
pub fn scenarios(class: ScenarioClass, first_seed: u64, count: usize) -> Vec<Scenario> {
    (0..count as u64).map(|i| generate(class, first_seed + i)).collect()
}

/// Runs `f` over `items` on all available cores (scoped threads pulling indices from a shared
/// counter), returning the results in the order of `items`.
pub fn par_map<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let threads = std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1)
        .max(1);
    let next = AtomicUsize::new(0);
    let mut out: Vec<(usize, R)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|_| {
                scope.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let i = next.fetch_add(1, Ordering::Relaxed);
                        if i >= items.len() {
                            break mine;
                        }
                        mine.push((i, f(&items[i])));
                    }
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    out.sort_by_key(|(i, _)| *i);
    out.into_iter().map(|(_, r)| r).collect()
}
