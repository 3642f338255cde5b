//! The fuzz generator, shared by `crates/dev/tests/adversarial.rs`, `tests/threads.rs` and `tests/golden.rs`
//! (each declares `mod common;` beside `mod reliability;`): a deterministic generator of random
//! and adversarial inputs ([`generate`], drawing from the common splitmix64 generator of
//! `tests/common/rng.rs` seeded with [`Rng::mixed`]), and [`run_case`], which puts one input
//! through every query of the crate (stationary distance, time of impact, half-space queries,
//! every `SmoothDispatcher` query, the shapes' parry methods), checks each answer against what
//! the crate documents, and returns the violations with a digest of every number returned (for
//! the bit-for-bit comparisons of the determinism, thread and golden tests).
#![allow(dead_code)]

pub mod hostile;

pub use crate::common::rng::Rng;

use parry2d_f64::math::{Pose, Rotation, Vector};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{
    ClosestPoints, ContactManifold, NonlinearRigidMotion, PersistentQueryDispatcher, QueryDispatcher, Ray,
    ShapeCastHit, ShapeCastStatus,
};
use parry2d_f64::shape::{
    Ball, Capsule, Compound, ConvexPolygon, Cuboid, HalfSpace, RoundConvexPolygon, Segment, Shape, SharedShape,
    Triangle,
};
use smooth_ccd2d::{halfspace_distance, time_of_impact_halfspace};
use smooth_ccd2d::{
    stationary_distance, time_of_impact, BallCurve, CapsuleEllipse, ConvexCurve, CustomCurve, DistanceOptions,
    DistanceStatus, Ellipse, QueryError, RoundedPolygon, ShapeError, SmoothDispatcher, StationaryDistance,
    TimeOfImpact, ToiOptions, ToiStatus,
};
use smooth_ccd2d::{MAX_LENGTH, MIN_LENGTH};
use std::f64::consts::PI;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A query call taking longer than this is a broken promise (issue 32: every loop of the crate
/// is bounded; the slowest calls measured, casts of 1:1e25 ellipses ending at
/// `max_evaluations`, take 0.2–0.3 s). A call that never returns is the watchdog's.
pub const CALL_LIMIT: Duration = Duration::from_secs(2);

// ---------------------------------------------------------------------------------------------
// Wild numbers
// ---------------------------------------------------------------------------------------------

/// Numbers that break naive code: NaN, infinities, signed zeros, the extremes of the range,
/// subnormals, values whose square overflows or underflows.
pub const WILD: [f64; 16] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    1e300,
    -1e300,
    1e-300,
    5e-324,
    f64::MAX,
    -f64::MAX,
    f64::EPSILON,
    1e160,
    1e-160,
    -1.0,
    1e20,
];

// ---------------------------------------------------------------------------------------------
// Shapes
// ---------------------------------------------------------------------------------------------

/// A shape to build, with the raw (possibly invalid) numbers given to its constructor.
#[derive(Clone, Debug)]
pub enum ShapeSpec {
    /// `Ellipse::try_new(a, b)`.
    Ellipse(f64, f64),
    /// `RoundedPolygon::try_regular(sides, circumradius, corner_radius)`.
    Regular(usize, f64, f64),
    /// `RoundedPolygon::try_new(vertices, corner_radius)`.
    Polygon(Vec<Vector>, f64),
    /// `CapsuleEllipse::try_new(r1, r2, r3)`.
    CapsuleEllipse(f64, f64, f64),
    /// `CustomCurve` around one of the crate's shapes (the generic parry paths).
    Custom(Box<ShapeSpec>),
    /// `BallCurve { radius }` as a curve, parry's `Ball` as a shape (no validation: a public field).
    Ball(f64),
    /// parry `Cuboid` (half extents).
    Cuboid(f64, f64),
    /// parry `Capsule` along y (half height, radius).
    Capsule(f64, f64),
    /// parry `ConvexPolygon` (radius 0) or `RoundConvexPolygon`.
    ParryPolygon(Vec<Vector>, f64),
    /// parry `Triangle`.
    Triangle([Vector; 3]),
    /// parry `Segment`.
    Segment(Vector, Vector),
    /// parry `HalfSpace` with outward normal at this angle.
    HalfSpace(f64),
    /// parry `Compound` holding one of the crate's shapes at a pose and a ball.
    Compound(Box<ShapeSpec>, Pose),
    /// `CustomCurve::try_new` of a curve of the crate telling a lie about its contract
    /// ([`hostile::Liar`]).
    Liar(hostile::Lie, hostile::Base),
}

impl ShapeSpec {
    /// Whether the crate's constructor must accept the numbers (all finite and in their domain).
    /// `None` for shapes without a validating constructor.
    pub fn valid_numbers(&self) -> Option<bool> {
        // Lengths: finite, positive and within the constructors' range [1e-50, 1e50].
        let pos = |x: f64| (MIN_LENGTH..=MAX_LENGTH).contains(&x);
        let nonneg = |x: f64| x == 0.0 || pos(x);
        match self {
            ShapeSpec::Ellipse(a, b) => Some(pos(*a) && pos(*b)),
            ShapeSpec::Regular(n, c, r) => Some(*n >= 3 && pos(*c) && nonneg(*r)),
            ShapeSpec::Polygon(v, r) => Some(
                v.len() >= 3
                    && v.iter().all(|p| p.x.abs().max(p.y.abs()) <= MAX_LENGTH)
                    && v.iter().any(|p| p.x.abs().max(p.y.abs()) >= MIN_LENGTH)
                    && nonneg(*r),
            ),
            ShapeSpec::CapsuleEllipse(a, b, c) => Some(pos(*a) && pos(*b) && pos(*c) && *a >= 1e-6 * *b),
            ShapeSpec::Custom(inner) => inner.valid_numbers(),
            _ => None,
        }
    }

    /// The crate's own shapes (not parry's).
    pub fn is_own(&self) -> bool {
        matches!(
            self,
            ShapeSpec::Ellipse(..)
                | ShapeSpec::Regular(..)
                | ShapeSpec::Polygon(..)
                | ShapeSpec::CapsuleEllipse(..)
                | ShapeSpec::Custom(..)
                | ShapeSpec::Liar(..)
        )
    }
}

/// A built shape: parry's view, the curve view when there is one.
#[derive(Clone)]
pub struct Built {
    /// One of the crate's shapes (its parry methods are the crate's code).
    pub own: bool,
    pub shape: SharedShape,
    pub curve: Option<Arc<dyn ConvexCurve>>,
    pub halfspace: Option<HalfSpace>,
}

fn own_shape<S: Shape + ConvexCurve + Clone>(s: S) -> Built {
    Built {
        own: true,
        shape: SharedShape::new(s.clone()),
        curve: Some(Arc::new(s)),
        halfspace: None,
    }
}

fn parry_shape<S: Shape>(s: S) -> Built {
    Built {
        own: false,
        shape: SharedShape::new(s),
        curve: None,
        halfspace: None,
    }
}

/// Builds a shape: `Err` carries the constructor's `ShapeError`, or a note when parry's own
/// constructor refuses (a degenerate polygon).
pub fn build(spec: &ShapeSpec) -> Result<Built, String> {
    let e = |e: ShapeError| format!("ShapeError: {e}");
    Ok(match spec {
        ShapeSpec::Ellipse(a, b) => own_shape(Ellipse::try_new(*a, *b).map_err(e)?),
        ShapeSpec::Regular(n, c, r) => own_shape(RoundedPolygon::try_regular(*n, *c, *r).map_err(e)?),
        ShapeSpec::Polygon(v, r) => own_shape(RoundedPolygon::try_new(v, *r).map_err(e)?),
        ShapeSpec::CapsuleEllipse(a, b, c) => own_shape(CapsuleEllipse::try_new(*a, *b, *c).map_err(e)?),
        ShapeSpec::Custom(inner) => {
            let b = build(inner)?;
            let curve = b.curve.ok_or("custom around a parry shape")?;
            own_shape(CustomCurve::try_from_arc(curve).map_err(e)?)
        }
        ShapeSpec::Liar(lie, base) => own_shape(
            CustomCurve::try_new(hostile::Liar {
                base: base.clone(),
                lie: *lie,
            })
            .map_err(e)?,
        ),
        ShapeSpec::Ball(r) => Built {
            own: false,
            shape: SharedShape::new(Ball::new(*r)),
            curve: Some(Arc::new(BallCurve { radius: *r })),
            halfspace: None,
        },
        ShapeSpec::Cuboid(x, y) => parry_shape(Cuboid::new(Vector::new(*x, *y))),
        ShapeSpec::Capsule(h, r) => parry_shape(Capsule::new_y(*h, *r)),
        ShapeSpec::ParryPolygon(v, r) => {
            let p = ConvexPolygon::from_convex_polyline(v.clone()).ok_or("parry rejects the polygon")?;
            if *r > 0.0 {
                parry_shape(RoundConvexPolygon {
                    inner_shape: p,
                    border_radius: *r,
                })
            } else {
                parry_shape(p)
            }
        }
        ShapeSpec::Triangle(t) => parry_shape(Triangle::new(t[0], t[1], t[2])),
        ShapeSpec::Segment(a, b) => parry_shape(Segment::new(*a, *b)),
        ShapeSpec::HalfSpace(a) => {
            let hs = HalfSpace::new(Vector::new(a.cos(), a.sin()));
            Built {
                own: false,
                shape: SharedShape::new(hs),
                curve: None,
                halfspace: Some(hs),
            }
        }
        ShapeSpec::Compound(inner, pose) => {
            let b = build(inner)?;
            let ball = SharedShape::new(Ball::new(0.1 * b.shape.compute_local_bounding_sphere().radius));
            parry_shape(Compound::new(vec![(*pose, b.shape), (Pose::IDENTITY, ball)]))
        }
    })
}

// ---------------------------------------------------------------------------------------------
// Cases
// ---------------------------------------------------------------------------------------------

/// One input for every query.
#[derive(Clone, Debug)]
pub struct Case {
    pub seed: u64,
    pub index: u64,
    /// The scenario class that produced it.
    pub class: &'static str,
    /// Every number finite, sizes within 1e-6..1e6, axis ratios to 1:1e6: the answers must be
    /// `Ok` and pass the accuracy checks, not only be free of NaN.
    pub supported: bool,
    /// Shape size (the larger bounding radius, roughly).
    pub scale: f64,
    pub s1: ShapeSpec,
    pub s2: ShapeSpec,
    pub pos12: Pose,
    pub m1: NonlinearRigidMotion,
    pub m2: NonlinearRigidMotion,
    pub t0: f64,
    pub t1: f64,
    pub target: f64,
    pub stop: bool,
    pub prediction: f64,
    pub local_vel12: Vector,
    pub ray: Ray,
    pub max_toi: f64,
    pub solid: bool,
    pub point: Vector,
    pub dir: Vector,
    pub density: f64,
    pub rescale: Vector,
    /// For grazing passes: the smallest distance over the window (exact).
    pub min_gap: Option<f64>,
}

fn pose(x: f64, y: f64, a: f64) -> Pose {
    Pose::new(Vector::new(x, y), a)
}

/// A random shape of the crate at scale `s`, axis ratios down to `min_ratio`.
fn own_spec(rng: &mut Rng, s: f64, min_ratio: f64) -> ShapeSpec {
    let ratio = rng.log_uniform(min_ratio, 1.0);
    match rng.int(0, 6) {
        0 | 1 => {
            if rng.chance(0.5) {
                ShapeSpec::Ellipse(s, s * ratio)
            } else {
                ShapeSpec::Ellipse(s * ratio, s)
            }
        }
        2 => {
            let r = if rng.chance(0.3) {
                0.0
            } else {
                s * rng.uniform(0.0, 0.4)
            };
            ShapeSpec::Regular(rng.int(3, 12), s, r)
        }
        3 => {
            // A random convex polygon around the origin: sorted angles on an ellipse.
            let n = rng.int(3, 9);
            let mut angles: Vec<f64> = (0..n).map(|_| rng.angle()).collect();
            angles.sort_by(f64::total_cmp);
            let r2 = rng.log_uniform(ratio.max(1e-3), 1.0);
            let v = angles
                .iter()
                .map(|a| Vector::new(s * a.cos(), s * r2 * a.sin()))
                .collect::<Vec<_>>();
            let r = if rng.chance(0.3) {
                0.0
            } else {
                s * rng.uniform(0.0, 0.3)
            };
            ShapeSpec::Polygon(v, r)
        }
        4 => ShapeSpec::CapsuleEllipse(
            s * rng.uniform(0.1, 0.6),
            s * rng.uniform(0.05, 0.6),
            s * rng.uniform(0.1, 0.8),
        ),
        5 => ShapeSpec::Ball(s * rng.uniform(0.2, 1.0)),
        _ => {
            let inner = match rng.int(0, 2) {
                0 => ShapeSpec::Ellipse(s, s * ratio),
                1 => ShapeSpec::Regular(rng.int(3, 8), s, s * rng.uniform(0.0, 0.3)),
                _ => ShapeSpec::CapsuleEllipse(s * 0.4, s * 0.3, s * 0.5),
            };
            ShapeSpec::Custom(Box::new(inner))
        }
    }
}

/// A random parry shape at scale `s` (also a half-space or a compound).
fn parry_spec(rng: &mut Rng, s: f64) -> ShapeSpec {
    match rng.int(0, 7) {
        0 => ShapeSpec::Ball(s * rng.uniform(0.1, 1.0)),
        1 => ShapeSpec::Cuboid(s * rng.uniform(0.05, 1.0), s * rng.uniform(0.05, 1.0)),
        2 => ShapeSpec::Capsule(s * rng.uniform(0.05, 0.8), s * rng.uniform(0.05, 0.5)),
        3 => {
            let n = rng.int(3, 7);
            let v = (0..n)
                .map(|i| {
                    Vector::new(
                        (2.0 * PI * i as f64 / n as f64).cos(),
                        (2.0 * PI * i as f64 / n as f64).sin(),
                    ) * s
                })
                .collect();
            ShapeSpec::ParryPolygon(v, if rng.chance(0.5) { 0.0 } else { s * 0.1 })
        }
        4 => ShapeSpec::Triangle([
            Vector::new(-s, -0.5 * s),
            Vector::new(s, -0.3 * s),
            Vector::new(0.1 * s, s),
        ]),
        5 => ShapeSpec::Segment(Vector::new(-s, 0.2 * s), Vector::new(s, -0.1 * s)),
        6 => ShapeSpec::HalfSpace(rng.angle()),
        _ => ShapeSpec::Compound(
            Box::new(ShapeSpec::Ellipse(0.6 * s, 0.3 * s)),
            pose(0.5 * s, 0.1 * s, rng.angle()),
        ),
    }
}

fn motion(rng: &mut Rng, start: Pose, s: f64, window: f64) -> NonlinearRigidMotion {
    let speed = s * rng.uniform(0.0, 6.0) / window;
    let spin = if rng.chance(0.3) { 0.0 } else { rng.uniform(-60.0, 60.0) };
    let center = if rng.chance(0.7) {
        Vector::ZERO
    } else {
        Vector::new(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)) * s
    };
    NonlinearRigidMotion::new(start, center, rng.direction() * speed, spin)
}

/// Replaces a number by a [`WILD`] one with probability `p`.
fn wild(rng: &mut Rng, x: f64, p: f64) -> f64 {
    if rng.chance(p) {
        rng.pick(&WILD)
    } else {
        x
    }
}

fn wild_vec(rng: &mut Rng, v: Vector, p: f64) -> Vector {
    Vector::new(wild(rng, v.x, p), wild(rng, v.y, p))
}

fn wild_pose(rng: &mut Rng, q: Pose, p: f64) -> Pose {
    let t = wild_vec(rng, q.translation, p);
    if rng.chance(p) {
        // A rotation that is not a unit complex number, or a non-finite one.
        let re = rng.pick(&WILD);
        Pose::from_parts(t, Rotation::from_cos_sin_unchecked(re, q.rotation.im))
    } else {
        Pose::from_parts(t, q.rotation)
    }
}

fn wild_motion(rng: &mut Rng, m: &NonlinearRigidMotion, p: f64) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(
        wild_pose(rng, m.start, p),
        wild_vec(rng, m.local_center, p),
        wild_vec(rng, m.linvel, p),
        wild(rng, m.angvel, p),
    )
}

fn wild_spec(rng: &mut Rng, spec: &ShapeSpec, p: f64) -> ShapeSpec {
    match spec {
        ShapeSpec::Ellipse(a, b) => ShapeSpec::Ellipse(wild(rng, *a, p), wild(rng, *b, p)),
        ShapeSpec::Regular(n, c, r) => ShapeSpec::Regular(
            if rng.chance(p) { rng.int(0, 2) } else { *n },
            wild(rng, *c, p),
            wild(rng, *r, p),
        ),
        ShapeSpec::Polygon(v, r) => {
            let mut v = v.clone();
            if rng.chance(p) && !v.is_empty() {
                // Break it: a non-finite vertex, a repeated vertex, a reversed order or too few.
                match rng.int(0, 3) {
                    0 => {
                        let i = rng.int(0, v.len() - 1);
                        v[i] = wild_vec(rng, v[i], 1.0);
                    }
                    1 => {
                        let i = rng.int(0, v.len() - 1);
                        let x = v[i];
                        v.insert(i, x);
                    }
                    2 => v.reverse(),
                    _ => v.truncate(2),
                }
            }
            ShapeSpec::Polygon(v, wild(rng, *r, p))
        }
        ShapeSpec::CapsuleEllipse(a, b, c) => {
            ShapeSpec::CapsuleEllipse(wild(rng, *a, p), wild(rng, *b, p), wild(rng, *c, p))
        }
        ShapeSpec::Custom(inner) => ShapeSpec::Custom(Box::new(wild_spec(rng, inner, p))),
        ShapeSpec::Ball(r) => ShapeSpec::Ball(wild(rng, *r, p)),
        ShapeSpec::Cuboid(x, y) => ShapeSpec::Cuboid(wild(rng, *x, p), wild(rng, *y, p)),
        ShapeSpec::Capsule(h, r) => ShapeSpec::Capsule(wild(rng, *h, p), wild(rng, *r, p)),
        ShapeSpec::HalfSpace(a) => ShapeSpec::HalfSpace(wild(rng, *a, p)),
        ShapeSpec::Compound(inner, q) => ShapeSpec::Compound(Box::new(wild_spec(rng, inner, p)), wild_pose(rng, *q, p)),
        other => other.clone(),
    }
}

/// The scenario classes of [`generate`].
pub const CLASSES: [&str; 9] = [
    "random",
    "parry-pair",
    "wild",
    "coincident",
    "concentric",
    "touching-at-t0",
    "grazing",
    "extreme-scale",
    "thin-ellipse",
];

/// A case being drawn: the shapes, poses, motions and window, before the numbers every case gets
/// ([`finish_case`]).
struct Draft {
    class: &'static str,
    supported: bool,
    /// The size.
    s: f64,
    s1: ShapeSpec,
    s2: ShapeSpec,
    pos12: Pose,
    m1: NonlinearRigidMotion,
    m2: NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    target: f64,
    /// Probability that [`finish_case`] makes a number wild (0 but for the `wild` class).
    p: f64,
    min_gap: Option<f64>,
}

/// Case `index` of the batch `seed`: every class in turn.
pub fn generate(seed: u64, index: u64) -> Case {
    let mut rng = Rng::mixed(seed.wrapping_mul(0x2545_F491_4F6C_DD1D) ^ index.wrapping_mul(0x9E37_79B9));
    let class = CLASSES[(index % CLASSES.len() as u64) as usize];
    // Sizes 1e-6..1e6 (extreme-scale also goes beyond).
    let s = rng.log_uniform(1e-6, 1e6);
    let (s1, s2) = draw_shapes(&mut rng, class, s);
    let (window, t0, t1) = draw_window(&mut rng);
    let mut d = draw_motions(&mut rng, class, s, (s1, s2), window, (t0, t1));
    match class {
        "coincident" => make_coincident(&mut rng, &mut d),
        "concentric" => make_concentric(&mut d),
        "touching-at-t0" | "grazing" => make_discs_touch_or_graze(&mut rng, &mut d, window),
        "extreme-scale" => make_extreme_scale(&mut rng, &mut d, window),
        "wild" => make_wild(&mut rng, &mut d),
        _ => {}
    }
    finish_case(&mut rng, seed, index, d)
}

/// The two shapes of `class` at size `s` (ratios down to 1e-6 for thin ellipses; a parry shape on
/// either side for parry pairs).
fn draw_shapes(rng: &mut Rng, class: &str, s: f64) -> (ShapeSpec, ShapeSpec) {
    let mut min_ratio = 1e-3;
    if class == "thin-ellipse" {
        min_ratio = 1e-6;
    }
    let mut s1 = own_spec(rng, s, min_ratio);
    let mut s2 = if class == "parry-pair" {
        parry_spec(rng, s)
    } else {
        let s2 = s * rng.log_uniform(0.3, 3.0);
        own_spec(rng, s2, min_ratio)
    };
    if class == "thin-ellipse" {
        let ratio = rng.log_uniform(1e-6, 1e-3);
        s1 = if rng.chance(0.3) {
            // A thin capsule-ellipse: arcs of radius down to 1e-6 of the segment's half-length.
            ShapeSpec::CapsuleEllipse(s * rng.log_uniform(1e-6, 1e-3), s, s * rng.uniform(0.1, 1.0))
        } else {
            ShapeSpec::Ellipse(s, s * ratio)
        };
        if rng.chance(0.5) {
            s2 = ShapeSpec::Ellipse(s * ratio * rng.uniform(1.0, 10.0), s * rng.uniform(0.5, 2.0));
        }
    }
    if class == "parry-pair" && rng.chance(0.5) {
        std::mem::swap(&mut s1, &mut s2);
    }
    (s1, s2)
}

/// (window length, t0, t1): one time in ten an empty window, one in ten a reversed one.
fn draw_window(rng: &mut Rng) -> (f64, f64, f64) {
    let window = if rng.chance(0.5) {
        1.0
    } else {
        rng.log_uniform(1e-3, 10.0)
    };
    let t0 = if rng.chance(0.5) { 0.0 } else { rng.uniform(-5.0, 5.0) };
    let mut t1 = t0 + window;
    match rng.int(0, 9) {
        0 => t1 = t0,
        1 => t1 = t0 - window,
        _ => {}
    }
    (window, t0, t1)
}

/// The random pose and motions of the shapes (shape 1 starting at the origin) and the target.
fn draw_motions(
    rng: &mut Rng,
    class: &'static str,
    s: f64,
    (s1, s2): (ShapeSpec, ShapeSpec),
    window: f64,
    (t0, t1): (f64, f64),
) -> Draft {
    let reach = 2.0 * s + s * rng.uniform(0.0, 2.0);
    let mut pos12 = pose(0.0, 0.0, rng.angle());
    pos12.translation = rng.direction() * (reach * rng.uniform(0.0, 1.5));
    let mut m1 = motion(rng, Pose::IDENTITY, s, window);
    let m2 = motion(rng, pos12, s, window);
    m1.start = pose(0.0, 0.0, 0.0);
    let target = if rng.chance(0.7) {
        0.0
    } else {
        s * rng.uniform(0.0, 0.05)
    };
    Draft {
        class,
        supported: true,
        s,
        s1,
        s2,
        pos12,
        m1,
        m2,
        t0,
        t1,
        target,
        p: 0.0,
        min_gap: None,
    }
}

/// `coincident`: shape 2 a copy of shape 1 at its pose (or 1e-13 of the size away), on the same
/// motion.
fn make_coincident(rng: &mut Rng, d: &mut Draft) {
    d.s2 = d.s1.clone();
    d.pos12 = if rng.chance(0.5) {
        Pose::IDENTITY
    } else {
        pose(1e-13 * d.s, 0.0, 0.0)
    };
    // Same motion: coincident over the whole window.
    d.m2 = NonlinearRigidMotion::new(d.m1.start * d.pos12, d.m1.local_center, d.m1.linvel, d.m1.angvel);
}

/// `concentric`: the same centre, moving together; the spins differ.
fn make_concentric(d: &mut Draft) {
    d.pos12.translation = Vector::ZERO;
    d.m2.start = d.pos12;
    d.m2.local_center = Vector::ZERO;
    d.m1.local_center = Vector::ZERO;
    // Same velocity: the centres stay together; the spins differ.
    d.m2.linvel = d.m1.linvel;
}

/// `touching-at-t0` and `grazing`: two discs (exact distance) or one of ours against a disc,
/// placed at an exact gap: touching at t0, or sliding past with the smallest gap inside the window.
fn make_discs_touch_or_graze(rng: &mut Rng, d: &mut Draft, window: f64) {
    let (s, t0) = (d.s, d.t0);
    let touching = d.class == "touching-at-t0";
    let r1 = s * rng.uniform(0.3, 1.0);
    let r2 = s * rng.uniform(0.3, 1.0);
    d.s1 = if rng.chance(0.5) {
        ShapeSpec::Ball(r1)
    } else {
        ShapeSpec::Ellipse(r1, r1)
    };
    d.s2 = ShapeSpec::Ball(r2);
    let gap = if touching {
        0.0
    } else {
        rng.pick(&[-1e-9, -1e-12, 0.0, 1e-12, 1e-9, 1e-6]) * s
    };
    let n = rng.direction();
    let tan = Vector::new(-n.y, n.x);
    let dist = r1 + r2 + gap;
    d.t1 = t0 + window;
    if touching {
        // Touching at t0, approaching, separating or sliding.
        d.pos12 = Pose::new(n * (r1 + r2), rng.angle());
        let v = (n * rng.uniform(-3.0, 3.0) + tan * rng.uniform(-3.0, 3.0)) * (s / window);
        let w = rng.uniform(-5.0, 5.0);
        d.m1 = NonlinearRigidMotion::new(Pose::new(Vector::ZERO, rng.angle()), Vector::ZERO, Vector::ZERO, 0.0);
        // `start` is the pose at time 0; the window starts at t0.
        d.m2 = NonlinearRigidMotion::new(Pose::new(n * (r1 + r2) - v * t0, -w * t0), Vector::ZERO, v, w);
        d.min_gap = Some(0.0);
    } else {
        // Sliding past along the tangent: the centre distance is smallest (= dist) at
        // tc, inside the window.
        let tc = t0 + window * rng.uniform(0.2, 0.8);
        let speed = s * rng.uniform(0.5, 4.0) / window;
        let start = n * dist - tan * (speed * (tc - t0));
        d.m1 = NonlinearRigidMotion::new(Pose::new(Vector::ZERO, rng.angle()), Vector::ZERO, Vector::ZERO, 0.0);
        d.m2 = NonlinearRigidMotion::new(
            Pose::new(start - tan * (speed * t0), 0.0),
            Vector::ZERO,
            tan * speed,
            0.0,
        );
        d.pos12 = Pose::new(n * dist, 0.0);
        d.min_gap = Some(gap);
    }
    d.target = 0.0;
}

/// `extreme-scale`: sizes and positions beyond the supported range, in both directions: up to
/// the constructors' limits (1e±50), and beyond them (the constructors refuse, parry's shapes are
/// taken as they are).
fn make_extreme_scale(rng: &mut Rng, d: &mut Draft, window: f64) {
    let s = rng.pick(&[
        1e-12, 1e-9, 1e9, 1e12, 1e-45, 1e45, 1e-50, 1e50, 1e-60, 1e60, 1e-100, 1e100, 1e-200, 1e200, 1e-300, 1e300,
    ]);
    d.s = s;
    d.supported = false;
    let min_ratio = if rng.chance(0.3) { 1e-40 } else { 1e-3 };
    d.s1 = own_spec(rng, s, min_ratio);
    let s2_size = s * rng.uniform(0.5, 2.0);
    d.s2 = if rng.chance(0.3) {
        parry_spec(rng, s2_size)
    } else {
        own_spec(rng, s2_size, min_ratio)
    };
    d.pos12.translation = rng.direction() * (s * rng.uniform(0.0, 4.0));
    d.m1 = motion(rng, Pose::IDENTITY, s, window);
    d.m2 = motion(rng, d.pos12, s, window);
    d.target *= s;
}

/// `wild`: every number of the case a [`WILD`] one with probability 0.12 (the target 0.06).
fn make_wild(rng: &mut Rng, d: &mut Draft) {
    let p = 0.12;
    d.supported = false;
    if rng.chance(0.3) {
        d.s2 = parry_spec(rng, d.s);
    }
    d.s1 = wild_spec(rng, &d.s1, p);
    d.s2 = wild_spec(rng, &d.s2, p);
    d.pos12 = wild_pose(rng, d.pos12, p);
    d.m1 = wild_motion(rng, &d.m1, p);
    d.m2 = wild_motion(rng, &d.m2, p);
    d.t0 = wild(rng, d.t0, p);
    d.t1 = wild(rng, d.t1, p);
    d.target = wild(rng, d.target, p * 0.5);
    d.p = p;
}

/// The case: `d` with the numbers of the other queries (ray, point, direction, margins, density,
/// scaling), each made wild with probability `d.p`.
fn finish_case(rng: &mut Rng, seed: u64, index: u64, d: Draft) -> Case {
    let (s, p) = (d.s, d.p);
    let o = rng_vec(rng, 3.0 * s);
    let o = wild_vec(rng, o, p);
    let dir = rng_vec(rng, 1.0);
    let dir = wild_vec(rng, dir, p);
    let ray = Ray::new(o, dir);
    let stop = rng.chance(0.5);
    let prediction = s * rng.uniform(0.0, 0.5);
    let prediction = wild(rng, prediction, p);
    let v = rng.direction() * (s * rng.uniform(0.0, 5.0));
    let local_vel12 = wild_vec(rng, v, p);
    let max_toi = rng.pick(&[1.0, 10.0, f64::MAX]);
    let max_toi = wild(rng, max_toi, p);
    let solid = rng.chance(0.5);
    let point = rng_vec(rng, 2.0 * s);
    let point = wild_vec(rng, point, p);
    let dir = rng.direction();
    let dir = wild_vec(rng, dir, p);
    let density = rng.log_uniform(1e-3, 1e3);
    let density = wild(rng, density, p);
    let rescale = Vector::new(rng.log_uniform(0.1, 10.0), rng.log_uniform(0.1, 10.0));
    let rescale = wild_vec(rng, rescale, p);
    Case {
        seed,
        index,
        class: d.class,
        supported: d.supported,
        scale: s,
        s1: d.s1,
        s2: d.s2,
        pos12: d.pos12,
        m1: d.m1,
        m2: d.m2,
        t0: d.t0,
        t1: d.t1,
        target: d.target,
        stop,
        prediction,
        local_vel12,
        ray,
        max_toi,
        solid,
        point,
        dir,
        density,
        rescale,
        min_gap: d.min_gap,
    }
}

fn rng_vec(rng: &mut Rng, r: f64) -> Vector {
    Vector::new(rng.uniform(-r, r), rng.uniform(-r, r))
}

// ---------------------------------------------------------------------------------------------
// Checks
// ---------------------------------------------------------------------------------------------

/// What one case produced.
#[derive(Clone, Debug, Default)]
pub struct Outcome {
    /// Broken promises, each naming the query.
    pub violations: Vec<String>,
    /// Every number and status returned, as bits (FNV-1a).
    pub digest: u64,
    /// Tags such as `toi:Hit`, `dist:Err(Degenerate)` for the summary.
    pub tags: Vec<String>,
    /// The slowest call of the case and which query it was.
    pub slowest: (Duration, &'static str),
}

struct Ctx<'a> {
    case: &'a Case,
    out: Outcome,
}

impl Ctx<'_> {
    fn bad(&mut self, what: impl Into<String>) {
        self.out.violations.push(what.into());
    }
    /// `f()`, timed: a call beyond [`CALL_LIMIT`] is a violation; the slowest is kept.
    fn timed<T>(&mut self, what: &'static str, f: impl FnOnce() -> T) -> T {
        let t = Instant::now();
        let r = f();
        let dt = t.elapsed();
        if dt > self.out.slowest.0 {
            self.out.slowest = (dt, what);
        }
        if dt > CALL_LIMIT {
            self.bad(format!("{what}: one call took {dt:?} (limit {CALL_LIMIT:?})"));
        }
        r
    }
    fn tag(&mut self, t: impl Into<String>) {
        self.out.tags.push(t.into());
    }
    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.out.digest ^= b as u64;
            self.out.digest = self.out.digest.wrapping_mul(0x100_0000_01B3);
        }
    }
    fn num(&mut self, x: f64) {
        self.word(x.to_bits());
    }
    fn vec(&mut self, v: Vector) {
        self.num(v.x);
        self.num(v.y);
    }
    /// Records `x` and flags it when NaN (or infinite, when `finite` is asked).
    fn finite(&mut self, what: &str, x: f64) {
        self.num(x);
        if !x.is_finite() {
            self.bad(format!("{what}: non-finite value {x}"));
        }
    }
    fn finite_vec(&mut self, what: &str, v: Vector) {
        self.vec(v);
        if !v.is_finite() {
            self.bad(format!("{what}: non-finite vector {v:?}"));
        }
    }
    /// Flags the answer `r` of query `what` unless it is the `expected` error, or `Ok` where none
    /// is expected (or `Degenerate` on an unsupported case).
    fn expect_error<T: std::fmt::Debug>(
        &mut self,
        what: &str,
        r: &Result<T, QueryError>,
        expected: Option<QueryError>,
    ) {
        match (r, expected) {
            (Err(e), Some(x)) if *e == x => {}
            (Err(QueryError::Degenerate), None) if !self.case.supported => {}
            (Ok(_), None) => {}
            _ => self.bad(format!("{what}: got {r:?}, expected error {expected:?}")),
        }
    }
    /// Tags the answer `r` as `prefix:<status>` or `prefix:Err(<error>)`.
    fn tag_answer<T, S: std::fmt::Debug>(&mut self, prefix: &str, r: &Result<T, QueryError>, status: impl Fn(&T) -> S) {
        self.tag(match r {
            Ok(d) => format!("{prefix}:{:?}", status(d)),
            Err(e) => format!("{prefix}:Err({e:?})"),
        });
    }
}

fn motion_finite(m: &NonlinearRigidMotion) -> bool {
    m.start.is_finite() && m.local_center.is_finite() && m.linvel.is_finite() && m.angvel.is_finite()
}

/// Runs every query on `case` and checks the answers.
pub fn run_case(case: &Case) -> Outcome {
    let mut cx = Ctx {
        case,
        out: Outcome {
            digest: 0xCBF2_9CE4_8422_2325,
            ..Outcome::default()
        },
    };
    let b1 = check_constructor(&mut cx, &case.s1, "shape1");
    let b2 = check_constructor(&mut cx, &case.s2, "shape2");
    let (Some(b1), Some(b2)) = (b1, b2) else {
        return cx.out;
    };
    for (b, name) in [(&b1, "shape1"), (&b2, "shape2")] {
        check_shape_methods(&mut cx, b, name);
    }
    if let (Some(c1), Some(c2)) = (&b1.curve, &b2.curve) {
        check_stationary(&mut cx, &**c1, &**c2);
        check_toi(&mut cx, &**c1, &**c2);
    }
    if let (Some(c), Some(hs)) = (&b1.curve, &b2.halfspace) {
        check_halfspace(&mut cx, &**c, hs, true);
    }
    if let (Some(hs), Some(c)) = (&b1.halfspace, &b2.curve) {
        check_halfspace(&mut cx, &**c, hs, false);
    }
    check_dispatcher(&mut cx, &*b1.shape, &*b2.shape, "d12");
    check_dispatcher(&mut cx, &*b2.shape, &*b1.shape, "d21");
    cx.out
}

fn check_constructor(cx: &mut Ctx, spec: &ShapeSpec, name: &str) -> Option<Built> {
    let built = cx.timed("constructor", || build(spec));
    cx.word(built.is_ok() as u64);
    match (spec.valid_numbers(), &built) {
        (Some(false), Ok(_)) => cx.bad(format!("{name}: invalid numbers {spec:?} built a shape")),
        (Some(true), Err(e)) if cx.case.supported => cx.bad(format!("{name}: valid {spec:?} rejected: {e}")),
        _ => {}
    }
    if let Err(e) = &built {
        cx.tag(format!("ctor:{}", e.split(':').next().unwrap_or("")));
    }
    built.ok()
}

fn check_shape_methods(cx: &mut Ctx, b: &Built, name: &str) {
    let c = cx.case;
    let g = &*b.shape;
    if b.halfspace.is_some() || g.as_composite_shape().is_some() {
        return;
    }
    // Shapes whose own numbers are out of range (parry shapes with wild sizes): no panic, no
    // check of the values.
    let sane = b.curve.as_ref().is_none_or(|cv| {
        let r = cv.bounding_radius();
        r.is_finite() && r > 0.0
    });
    let aabb = cx.timed("compute_local_aabb", || g.compute_local_aabb());
    let bs = cx.timed("compute_local_bounding_sphere", || g.compute_local_bounding_sphere());
    // Mass properties scale with the density: their values are checked for densities in
    // 1e-100..1e100.
    let density = if (1e-100..=1e100).contains(&c.density) {
        c.density
    } else {
        1.0
    };
    let m = cx.timed("mass_properties", || g.mass_properties(density));
    let _ = cx.timed("mass_properties", || g.mass_properties(c.density));
    let thick = cx.timed("ccd_thickness", || g.ccd_thickness());
    let ang = cx.timed("ccd_angular_thickness", || g.ccd_angular_thickness());
    let sp = cx.timed("local_support_point", || {
        g.as_support_map().map(|s| s.local_support_point(c.dir))
    });
    let ray = cx.timed("cast_local_ray", || {
        g.cast_local_ray_and_get_normal(&c.ray, c.max_toi, c.solid)
    });
    // A parry shape's own methods are parry's, under parry's contract: its `Capsule` asserts
    // (panics) in `project_local_point` at a non-finite point when its segment has no length
    // (parry 0.31, `point_segment.rs`), which no query of this crate reaches. Parry's shapes are
    // asked at finite points; this crate's at every point.
    let point_ok = b.own || c.point.is_finite();
    let proj = point_ok.then(|| cx.timed("project_local_point", || g.project_local_point(c.point, c.solid)));
    if point_ok {
        let _ = cx.timed("contains_local_point", || g.contains_local_point(c.point));
    }
    let world = cx.timed("compute_aabb", || g.compute_aabb(&c.pos12));
    let scaled = cx.timed("scale_dyn", || {
        g.scale_dyn(c.rescale, 8).map(|s| s.compute_local_aabb())
    });
    if !sane {
        return;
    }
    let (true, Some(proj)) = (b.own, proj) else {
        return;
    };
    cx.finite_vec(&format!("{name}.aabb.mins"), aabb.mins);
    cx.finite_vec(&format!("{name}.aabb.maxs"), aabb.maxs);
    if !(aabb.mins.x <= aabb.maxs.x && aabb.mins.y <= aabb.maxs.y) {
        cx.bad(format!("{name}.aabb: mins > maxs {aabb:?}"));
    }
    cx.finite(&format!("{name}.bounding_sphere.radius"), bs.radius);
    cx.finite(&format!("{name}.mass"), m.mass());
    cx.finite(&format!("{name}.inv_mass"), m.inv_mass);
    cx.finite_vec(&format!("{name}.local_com"), m.local_com);
    cx.finite(&format!("{name}.inv_inertia"), m.inv_principal_inertia);
    let positive_mass = m.mass() > 0.0;
    if !positive_mass && c.supported {
        cx.bad(format!("{name}: mass {} not positive", m.mass()));
    }
    cx.finite(&format!("{name}.ccd_thickness"), thick);
    cx.finite(&format!("{name}.ccd_angular_thickness"), ang);
    if let Some(p) = sp {
        cx.finite_vec(&format!("{name}.support_point({:?})", c.dir), p);
    }
    if let Some(h) = ray {
        cx.finite(&format!("{name}.ray.toi"), h.time_of_impact);
        cx.finite_vec(&format!("{name}.ray.normal"), h.normal);
        if !(h.time_of_impact >= 0.0 && h.time_of_impact <= c.max_toi) {
            cx.bad(format!(
                "{name}.ray: toi {} outside [0, {}]",
                h.time_of_impact, c.max_toi
            ));
        }
    } else {
        cx.word(0);
    }
    if c.point.is_finite() {
        cx.finite_vec(&format!("{name}.project_point({:?})", c.point), proj.point);
    }
    cx.word(proj.is_inside as u64);
    if c.pos12.is_finite() && c.supported {
        cx.finite_vec(&format!("{name}.world_aabb.mins"), world.mins);
        cx.finite_vec(&format!("{name}.world_aabb.maxs"), world.maxs);
    }
    if let Some(a) = scaled {
        if c.rescale.is_finite() && c.supported {
            cx.finite_vec(&format!("{name}.scaled_aabb.mins"), a.mins);
            cx.finite_vec(&format!("{name}.scaled_aabb.maxs"), a.maxs);
        }
    }
}

fn size_of(c1: &dyn ConvexCurve, c2: &dyn ConvexCurve) -> f64 {
    c1.bounding_radius().max(c2.bounding_radius())
}

fn check_distance_value(cx: &mut Ctx, what: &str, d: &StationaryDistance) {
    cx.finite(&format!("{what}.distance"), d.distance);
    cx.finite(&format!("{what}.phi"), d.phi);
    cx.finite_vec(&format!("{what}.point1"), d.point1);
    cx.finite_vec(&format!("{what}.point2"), d.point2);
    cx.finite_vec(&format!("{what}.normal1"), d.normal1);
    cx.finite_vec(&format!("{what}.normal2"), d.normal2);
    cx.word(d.status as u64);
    match d.status {
        DistanceStatus::Separated if d.distance.is_nan() || d.distance <= 0.0 => {
            cx.bad(format!("{what}: Separated with distance {}", d.distance))
        }
        DistanceStatus::Penetrating if d.distance.is_nan() || d.distance > 0.0 => {
            cx.bad(format!("{what}: Penetrating with distance {}", d.distance))
        }
        _ => {}
    }
    // Poses are taken as given: a rotation that is not a unit complex number (built with
    // `from_cos_sin_unchecked`) is outside the contract and scales the answer.
    let r = cx.case.pos12.rotation;
    let unit_rotation = ((r.re * r.re + r.im * r.im) - 1.0).abs() < 1e-9;
    // A user's curve gives its normals unit to the checks' tolerance (1e-6: computed in f32),
    // and the answer's normal is its own.
    let liar = |s: &ShapeSpec| matches!(s, ShapeSpec::Liar(..));
    let tol = if liar(&cx.case.s1) || liar(&cx.case.s2) {
        1e-6
    } else {
        1e-9
    };
    for (n, v) in [("normal1", d.normal1), ("normal2", d.normal2)] {
        if unit_rotation && (v.length() - 1.0).abs() > tol {
            cx.bad(format!("{what}.{n} not unit: {v:?}"));
        }
    }
}

fn check_stationary(cx: &mut Ctx, c1: &dyn ConvexCurve, c2: &dyn ConvexCurve) {
    let case = cx.case;
    let r = cx.timed("stationary_distance", || {
        stationary_distance(c1, c2, &case.pos12, &DistanceOptions::default())
    });
    let expected_err = if !case.pos12.is_finite() {
        Some(QueryError::NonFinite)
    } else if !c2.is_strictly_convex() {
        Some(QueryError::NotStrictlyConvex)
    } else {
        None
    };
    cx.expect_error("stationary_distance", &r, expected_err);
    cx.tag_answer("dist", &r, |d| d.status);
    let Ok(d) = r else {
        cx.word(0xE);
        return;
    };
    check_distance_value(cx, "stationary_distance", &d);
    if !case.supported {
        return;
    }
    let size = size_of(c1, c2);
    let sep = case.pos12.translation.length();
    // The shapes lie within their bounding radii of their origins: D ≥ |c2 − c1| − R1 − R2.
    let (r1, r2) = (c1.bounding_radius(), c2.bounding_radius());
    if d.distance < sep - r1 - r2 - 1e-9 * size {
        cx.bad(format!(
            "stationary_distance {} below |c2 − c1| − R1 − R2 = {}",
            d.distance,
            sep - r1 - r2
        ));
    }
    // The witnesses realise it.
    let w = case.pos12 * d.point2 - d.point1;
    if (w.dot(d.normal1) - d.distance).abs() > 1e-8 * size {
        cx.bad(format!(
            "stationary_distance: witnesses {w:?} do not realise {}",
            d.distance
        ));
    }
    // Both strictly convex: the other order agrees.
    if c1.is_strictly_convex() {
        if let Ok(e) = stationary_distance(c2, c1, &case.pos12.inverse(), &DistanceOptions::default()) {
            if (e.distance - d.distance).abs() > 1e-8 * size {
                cx.bad(format!("stationary_distance: swapped {} vs {}", e.distance, d.distance));
            }
        }
    }
    if let (Some(g), true) = (case.min_gap, case.class == "touching-at-t0") {
        if (d.distance - g).abs() > 1e-12 * size {
            cx.bad(format!("touching pair: distance {} (expected {g})", d.distance));
        }
    }
}

/// The signed distance at time t by the stationary distance (the check's own reference).
fn distance_at(c1: &dyn ConvexCurve, c2: &dyn ConvexCurve, case: &Case, t: f64) -> Option<f64> {
    let (o1, o2) = if c2.is_strictly_convex() { (c1, c2) } else { (c2, c1) };
    let (m1, m2) = if c2.is_strictly_convex() {
        (&case.m1, &case.m2)
    } else {
        (&case.m2, &case.m1)
    };
    let pos12 = m1.position_at_time(t).inv_mul(&m2.position_at_time(t));
    stationary_distance(o1, o2, &pos12, &DistanceOptions::default())
        .ok()
        .map(|d| d.distance)
}

fn check_toi_value(cx: &mut Ctx, what: &str, r: &TimeOfImpact, t0: f64, t1: f64) {
    cx.word(r.status as u64);
    cx.finite(&format!("{what}.time"), r.time);
    cx.finite(&format!("{what}.distance"), r.distance);
    cx.finite(&format!("{what}.distance_rate"), r.distance_rate);
    cx.finite_vec(&format!("{what}.point1"), r.point1);
    cx.finite_vec(&format!("{what}.point2"), r.point2);
    cx.finite_vec(&format!("{what}.normal1"), r.normal1);
    cx.finite_vec(&format!("{what}.normal2"), r.normal2);
    if !(r.time >= t0 && r.time <= t1) {
        cx.bad(format!("{what}: time {} outside [{t0}, {t1}]", r.time));
    }
    if r.status == ToiStatus::PenetratingAtStart && r.time != t0 {
        cx.bad(format!("{what}: PenetratingAtStart at {} ≠ t0 = {t0}", r.time));
    }
}

fn check_toi(cx: &mut Ctx, c1: &dyn ConvexCurve, c2: &dyn ConvexCurve) {
    let case = cx.case;
    let (t0, t1) = (case.t0, case.t1);
    let opts = ToiOptions::default()
        .with_target_distance(case.target)
        .with_stop_at_penetration(case.stop);
    let r = cx.timed("time_of_impact", || {
        time_of_impact(c1, &case.m1, c2, &case.m2, t0, t1, &opts)
    });
    let finite_in = motion_finite(&case.m1)
        && motion_finite(&case.m2)
        && t0.is_finite()
        && t1.is_finite()
        && case.target.is_finite()
        && case.target >= 0.0;
    let expected_err = if !(c1.is_strictly_convex() || c2.is_strictly_convex()) {
        Some(QueryError::NotStrictlyConvex)
    } else if !finite_in {
        Some(QueryError::NonFinite)
    } else if t1 < t0 {
        Some(QueryError::EmptyWindow)
    } else {
        None
    };
    cx.expect_error("time_of_impact", &r, expected_err);
    cx.tag_answer("toi", &r, |d| d.status);
    let Ok(r) = r else {
        cx.word(0xE);
        return;
    };
    check_toi_value(cx, "time_of_impact", &r, t0, t1);
    if t1 == t0 && !matches!(r.status, ToiStatus::NoHit | ToiStatus::PenetratingAtStart) {
        cx.bad(format!("time_of_impact: empty window answered {:?}", r.status));
    }
    if !case.supported {
        return;
    }
    let size = size_of(c1, c2);
    let slack = 1e-9 * size;
    let at = |t: f64| distance_at(c1, c2, case, t);
    // With `stop_at_penetration = false` and a contact at the start, a contact that separates
    // is ignored: the answer may be NoHit while the shapes still overlap, or a Hit, still in
    // contact, where the approach resumes (ToiStatus docs). Only the time range is checked.
    if !case.stop && at(t0).is_some_and(|d| d <= case.target + 1e-10 * size + slack) {
        if r.status == ToiStatus::Hit && at(r.time).is_some_and(|d| d > case.target + 1e-10 * size + slack) {
            cx.bad(format!(
                "time_of_impact: Hit at {} above the target after a start contact",
                r.time
            ));
        }
        return;
    }
    match r.status {
        ToiStatus::Hit => {
            if let Some(d) = at(r.time) {
                if d < case.target - slack || d > case.target + 1e-10 * size + slack {
                    cx.bad(format!(
                        "time_of_impact: Hit at {} with distance {d} (target {})",
                        r.time, case.target
                    ));
                }
            }
        }
        ToiStatus::PenetratingAtStart => {
            if let Some(d) = at(t0) {
                if d > case.target + 1e-10 * size + slack {
                    cx.bad(format!("time_of_impact: PenetratingAtStart with distance {d}"));
                }
            }
        }
        ToiStatus::NoHit => {
            // No missed contact at sampled times (and at the grazing pass's closest time).
            for k in 0..=16 {
                let t = t0 + (t1 - t0) * k as f64 / 16.0;
                if let Some(d) = at(t) {
                    if (case.stop || k != 0) && d < case.target - slack {
                        cx.bad(format!("time_of_impact: NoHit but distance {d} at t = {t}"));
                        break;
                    }
                }
            }
            if case.min_gap.is_some_and(|g| g < -slack) && case.class == "grazing" {
                cx.bad(format!(
                    "time_of_impact: grazing pass with gap {:?} reported NoHit",
                    case.min_gap
                ));
            }
        }
        ToiStatus::OutOfIterations => {}
    }
    if case.class == "grazing" && r.status == ToiStatus::Hit && case.min_gap.is_some_and(|g| g > 1e-10 * size + slack) {
        cx.bad(format!("time_of_impact: grazing gap {:?} reported a Hit", case.min_gap));
    }
}

fn check_halfspace(cx: &mut Ctx, c: &dyn ConvexCurve, hs: &HalfSpace, curve_first: bool) {
    let case = cx.case;
    let r = cx.timed("halfspace_distance", || {
        halfspace_distance(c, hs, &case.pos12, curve_first)
    });
    let finite_pose = case.pos12.is_finite() && hs.normal.is_finite();
    match &r {
        Err(QueryError::NonFinite) if !finite_pose => {}
        Err(QueryError::Degenerate) if !case.supported => {}
        Ok(_) if finite_pose => {}
        _ => cx.bad(format!(
            "halfspace_distance: got {r:?} (pose finite: {})",
            case.pos12.is_finite()
        )),
    }
    cx.tag_answer("hs-dist", &r, |d| d.status);
    if let Ok(d) = &r {
        check_distance_value(cx, "halfspace_distance", d);
    }
    let (mc, mh) = if curve_first {
        (&case.m1, &case.m2)
    } else {
        (&case.m2, &case.m1)
    };
    let opts = ToiOptions::default()
        .with_target_distance(case.target)
        .with_stop_at_penetration(case.stop);
    let r = cx.timed("time_of_impact_halfspace", || {
        time_of_impact_halfspace(c, mc, hs, mh, case.t0, case.t1, &opts)
    });
    let finite_in = motion_finite(mc)
        && motion_finite(mh)
        && hs.normal.is_finite()
        && case.t0.is_finite()
        && case.t1.is_finite()
        && case.target.is_finite()
        && case.target >= 0.0;
    let expected_err = if !finite_in {
        Some(QueryError::NonFinite)
    } else if case.t1 < case.t0 {
        Some(QueryError::EmptyWindow)
    } else {
        None
    };
    cx.expect_error("time_of_impact_halfspace", &r, expected_err);
    cx.tag_answer("hs-toi", &r, |d| d.status);
    if let Ok(r) = &r {
        check_toi_value(cx, "time_of_impact_halfspace", r, case.t0, case.t1);
        if case.t1 == case.t0 && !matches!(r.status, ToiStatus::NoHit | ToiStatus::PenetratingAtStart) {
            cx.bad(format!(
                "time_of_impact_halfspace: empty window answered {:?}",
                r.status
            ));
        }
    }
}

fn check_hit(cx: &mut Ctx, what: &str, h: &Option<ShapeCastHit>, lo: f64, hi: f64) {
    match h {
        None => cx.word(0),
        Some(h) => {
            cx.finite(&format!("{what}.time_of_impact"), h.time_of_impact);
            cx.finite_vec(&format!("{what}.witness1"), h.witness1);
            cx.finite_vec(&format!("{what}.witness2"), h.witness2);
            cx.finite_vec(&format!("{what}.normal1"), h.normal1);
            cx.finite_vec(&format!("{what}.normal2"), h.normal2);
            cx.word(match h.status {
                ShapeCastStatus::Converged => 1,
                ShapeCastStatus::OutOfIterations => 2,
                ShapeCastStatus::Failed => 3,
                ShapeCastStatus::PenetratingOrWithinTargetDist => 4,
            });
            if !(h.time_of_impact >= lo && h.time_of_impact <= hi) {
                cx.bad(format!("{what}: time {} outside [{lo}, {hi}]", h.time_of_impact));
            }
        }
    }
}

fn check_dispatcher(cx: &mut Ctx, g1: &dyn Shape, g2: &dyn Shape, tag: &str) {
    let case = cx.case;
    let d = SmoothDispatcher::default();
    let p = &case.pos12;
    match cx.timed("intersection_test", || d.intersection_test(p, g1, g2)) {
        Ok(i) => cx.word(i.intersecting as u64),
        Err(_) => cx.word(0xE),
    }
    match cx.timed("distance", || d.distance(p, g1, g2)) {
        Ok(r) => {
            cx.finite(&format!("{tag}.distance"), r.distance);
            if r.distance < 0.0 {
                cx.bad(format!("{tag}.distance negative: {}", r.distance));
            }
        }
        Err(_) => cx.word(0xE),
    }
    match cx.timed("contact", || d.contact(p, g1, g2, case.prediction)) {
        Ok(Some(c)) => {
            cx.finite(&format!("{tag}.contact.dist"), c.dist);
            cx.finite_vec(&format!("{tag}.contact.point1"), c.point1);
            cx.finite_vec(&format!("{tag}.contact.point2"), c.point2);
            cx.finite_vec(&format!("{tag}.contact.normal1"), c.normal1);
            cx.finite_vec(&format!("{tag}.contact.normal2"), c.normal2);
        }
        Ok(None) => cx.word(0),
        Err(_) => cx.word(0xE),
    }
    match cx.timed("closest_points", || d.closest_points(p, g1, g2, case.prediction)) {
        Ok(ClosestPoints::WithinMargin(a, b)) => {
            cx.finite_vec(&format!("{tag}.closest_points.1"), a);
            cx.finite_vec(&format!("{tag}.closest_points.2"), b);
        }
        Ok(ClosestPoints::Intersecting) => cx.word(1),
        Ok(ClosestPoints::Disjoint) => cx.word(2),
        Err(_) => cx.word(0xE),
    }
    let max_toi = if case.max_toi.is_nan() { 1.0 } else { case.max_toi };
    let opts = ShapeCastOptions {
        max_time_of_impact: max_toi,
        target_distance: if case.target.is_finite() { case.target } else { 0.0 },
        stop_at_penetration: case.stop,
        compute_impact_geometry_on_penetration: true,
    };
    match cx.timed("cast_shapes", || d.cast_shapes(p, case.local_vel12, g1, g2, opts)) {
        Ok(h) => check_hit(cx, &format!("{tag}.cast_shapes"), &h, 0.0, max_toi.max(0.0)),
        Err(_) => cx.word(0xE),
    }
    match cx.timed("cast_shapes_nonlinear", || {
        d.cast_shapes_nonlinear(&case.m1, g1, &case.m2, g2, case.t0, case.t1, case.stop)
    }) {
        Ok(h) => {
            let (lo, hi) = (case.t0, case.t1);
            if h.is_some() && (hi.is_nan() || lo.is_nan() || hi < lo) {
                cx.bad(format!("{tag}.cast_shapes_nonlinear: a hit in the window [{lo}, {hi}]"));
            }
            check_hit(cx, &format!("{tag}.cast_shapes_nonlinear"), &h, lo, hi)
        }
        Err(_) => cx.word(0xE),
    }
    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
    let mut ws = None;
    let pred = if case.prediction.is_finite() {
        case.prediction
    } else {
        0.0
    };
    match cx.timed("contact_manifolds", || {
        d.contact_manifolds(p, g1, g2, pred, &mut manifolds, &mut ws)
    }) {
        Ok(()) => {
            for m in &manifolds {
                if !m.points.is_empty() {
                    cx.finite_vec(&format!("{tag}.manifold.local_n1"), m.local_n1);
                    cx.finite_vec(&format!("{tag}.manifold.local_n2"), m.local_n2);
                }
                for c in &m.points {
                    cx.finite_vec(&format!("{tag}.manifold.p1"), c.local_p1);
                    cx.finite_vec(&format!("{tag}.manifold.p2"), c.local_p2);
                    cx.finite(&format!("{tag}.manifold.dist"), c.dist);
                }
            }
        }
        Err(_) => cx.word(0xE),
    }
}

/// A case's one-line description for failure reports.
pub fn describe(case: &Case) -> String {
    format!(
        "seed {} case {} [{}] s1 {:?} s2 {:?} pos12 {:?} m1 {:?} m2 {:?} window [{}, {}] target {} stop {}",
        case.seed,
        case.index,
        case.class,
        case.s1,
        case.s2,
        case.pos12,
        case.m1,
        case.m2,
        case.t0,
        case.t1,
        case.target,
        case.stop
    )
}
