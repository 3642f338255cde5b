//! The fuzz generator, shared by `crates/dev/tests/adversarial.rs`, `tests/threads.rs` and `tests/golden.rs`
//! (each declares `mod common;` beside `mod reliability;`): a deterministic generator of random
//! and adversarial inputs ([`generate`], drawing from the common splitmix64 generator of
//! `tests/common/rng.rs` seeded with [`Rng::mixed`]), and [`run_case`], which puts one input
//! through every query of the crate (stationary distance, time of impact, half-space queries,
//! every `SmoothDispatcher` query, the shapes' parry methods), checks each answer against what
//! the crate documents, and returns the violations with a digest of every number returned (for
//! the bit-for-bit comparisons of the determinism, thread and golden tests).
#![allow(dead_code)]

mod cases;
mod checks;
pub mod hostile;

pub use cases::*;
pub use checks::*;

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
