//! rapier's CCD casts, this crate against parry's Box2D-style `sweep_time_of_impact`, on every
//! pair kind the sweep accepts where this crate has a counterpart (section `rapier-casts` of
//! `cargo bench --bench ratios`).
//!
//! What rapier 0.36 asks (`dynamics/ccd/sweeps.rs`), one step of `DT`, the target held at its
//! pose:
//!
//! * for its own shapes (parry's `Ball`, `ConvexPolygon`, `RoundConvexPolygon`, …):
//!   `sweep_time_of_impact(target_proxy, Sweep::constant(target_pose), body_proxy,
//!   Sweep::from_poses(start, end, local_com), 1, linear_slop)`, a fraction in (0, 1) kept, and at
//!   a fraction of exactly 0 the same sweep again with the body's core circle
//!   (`ToiProxy::point(centroid, CORE_FRACTION · ccd_thickness)`) — [`parry_cast`];
//! * for this crate's shapes: `SmoothDispatcher::cast_shapes_nonlinear(body motion, body,
//!   constant target motion, target, 0, DT, false)`, `time_of_impact / DT` kept when in (0, 1) —
//!   [`ours_cast`].
//!
//! The body moves from its pose at 0 to its pose at `DT` (constant velocity and spin); rapier
//! clamps it on the nlerp path between them (`Sweep::transform_at`), which both follow.
//!
//! The references (`tests/common/reference.rs`, conservative advancement on support functions,
//! on the nlerp path) judge each answer:
//!
//! * starting apart: the first touching time; this crate must find it (a miss, a false impact,
//!   or a time off by more than 1e-6 of the step, `support::judge`). parry's sweep stops where
//!   the cores are `max(slop, R − slop) ± slop/4` apart (R the sum of the proxies' radii): a
//!   *miss* of parry's is a touching impact it does not report although the pair goes past the
//!   deep end of that band; a *false* impact one it reports where the shapes never touch and
//!   never come within the band's shallow end; *off* a hit outside the band's times;
//! * starting in contact, each against its own rule: this crate's (`CastPolicy::Rapier`: the
//!   earlier of the body's core disc, a quarter of its inradius about its rotation centre,
//!   touching the target, and its translation without spin taking the contact a quarter of that
//!   inradius deeper) and rapier's for parry (the sweep's band, or at a fraction 0 the core
//!   circle's band).
#![allow(clippy::too_many_arguments)]

use super::reference::{reference_distance, reference_toi_with, RefOutcome, RefToi, RefToiOptions};
use super::rng::Rng;
use super::scenarios::par_map;
use super::timing::{quantile, time_contenders};
use super::{judge, polygon_approximation, POLYGON_VERTICES};
use core::f64::consts::{FRAC_PI_4, PI, TAU};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::sweep_toi::CORE_FRACTION;
use parry2d_f64::query::{
    sweep_time_of_impact, NonlinearRigidMotion, QueryDispatcher, Sweep, SweepToiStatus, ToiProxy,
};
use parry2d_f64::shape::{Ball, Capsule, ConvexPolygon, Cuboid, Segment, Shape, Triangle};
use smooth_ccd2d::{BallCurve, ConvexCurve, CurvePoint, Ellipse, RoundedPolygon, SmoothDispatcher};
use std::sync::Arc;

/// One step (rapier's default).
pub const DT: f64 = 1.0 / 60.0;
/// rapier's `linear_slop` (`IntegrationParameters::allowed_linear_error()`, 0.005 × length unit 1).
pub const SLOP: f64 = 0.005;
/// Cases per pair kind and set (`RAPIER_CASTS_CASES` overrides it).
pub const CASES: usize = 80;

fn cases() -> usize {
    std::env::var("RAPIER_CASTS_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(CASES)
}

/// Whether `name` is selected by the environment variable `var`: unset, or `name` starts with
/// its value (`RAPIER_CASTS_BODY=disc`, `RAPIER_CASTS_SET=contact`, `RAPIER_CASTS_TARGET=Cuboid`;
/// a target's name without its backquotes).
fn selected(var: &str, name: &str) -> bool {
    std::env::var(var).map_or(true, |v| name.trim_start_matches('`').starts_with(v.as_str()))
}

/// With `RAPIER_CASTS_PROFILE` set, the section makes each selected cast once, ours then
/// parry's, and prints no table, only each row's hits and the digest of this crate's answers:
/// a run for instruction counts (`valgrind --tool=callgrind
/// --toggle-collect='*cast_shapes_nonlinear*'`) and for a change that keeps every answer.
fn profile_only() -> bool {
    std::env::var_os("RAPIER_CASTS_PROFILE").is_some()
}
/// The smallest start gap of the sets starting apart: two slops, so that parry's sweep starts
/// apart too.
const MIN_START_GAP: f64 = 2.0 * SLOP;
/// This crate's core and allowance, as fractions of the body's inradius (`CastPolicy::CORE`,
/// `CastPolicy::ALLOWANCE`).
const OUR_CORE: f64 = 0.25;
const OUR_ALLOWANCE: f64 = 0.25;

/// The moving body's kind.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Body {
    /// A disc: this crate's `Ellipse::new(r, r)`, parry's `Ball`.
    Disc,
    /// A random convex polygon of 3–8 vertices: `RoundedPolygon` of radius 0, parry's `ConvexPolygon`.
    Polygon,
    /// The same rounded (0.02–0.3 of its size): `RoundedPolygon`, parry's `RoundConvexPolygon`.
    Rounded,
    /// A sliver polygon (3–4 vertices, 1:10–1:50), sharp.
    Sliver,
    /// An ellipse (1:1.5–1:10): parry casts its inscribed 64-gon.
    Ellipse,
}

impl Body {
    /// Every kind.
    pub const ALL: [Body; 5] = [Body::Disc, Body::Polygon, Body::Rounded, Body::Sliver, Body::Ellipse];

    fn name(self) -> &'static str {
        match self {
            Body::Disc => "disc",
            Body::Polygon => "polygon",
            Body::Rounded => "rounded polygon",
            Body::Sliver => "sliver polygon",
            Body::Ellipse => "ellipse (parry: 64-gon)",
        }
    }
}

/// The target's kind (parry's shapes, for both).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Target {
    Ball,
    Cuboid,
    Segment,
    Capsule,
    Triangle,
    Polygon,
}

impl Target {
    /// Every kind.
    pub const ALL: [Target; 6] = [
        Target::Ball,
        Target::Cuboid,
        Target::Segment,
        Target::Capsule,
        Target::Triangle,
        Target::Polygon,
    ];

    fn name(self) -> &'static str {
        match self {
            Target::Ball => "`Ball`",
            Target::Cuboid => "`Cuboid`",
            Target::Segment => "`Segment`",
            Target::Capsule => "`Capsule`",
            Target::Triangle => "`Triangle`",
            Target::Polygon => "`ConvexPolygon`",
        }
    }
}

/// The set a case belongs to.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Set {
    /// Apart at the start, |ω|·DT ≤ π/4 (rapier's regime).
    Apart,
    /// Apart at the start, |ω|·DT in [π/4, 4π] (up to two turns a step).
    Beyond,
    /// In contact at the start (touching or up to a tenth of the inradius deep), |ω|·DT ≤ π/4.
    Contact,
    /// Apart at the start, no spin at all (a body with its rotation locked, a bullet fired
    /// without spin): rapier's cast of a body that does not turn.
    Still,
}

impl Set {
    /// Every set.
    pub const ALL: [Set; 4] = [Set::Apart, Set::Beyond, Set::Contact, Set::Still];

    fn name(self) -> &'static str {
        match self {
            Set::Apart => "apart, ≤ π/4",
            Set::Beyond => "apart, π/4–4π",
            Set::Contact => "contact, ≤ π/4",
            Set::Still => "apart, no spin",
        }
    }
}

/// A parry shape as a curve for the reference: its support points shifted by `shift` and pushed
/// out along the direction by `offset` (negative: eroded), so that the reference's signed
/// distance is the pair's minus the offset. Only `support_point` and `bounding_radius` are read
/// by the reference.
#[derive(Clone)]
pub struct ParryCurve {
    shape: Arc<dyn Shape>,
    shift: Vector,
    offset: f64,
}

impl core::fmt::Debug for ParryCurve {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "ParryCurve({:?}, shift {:?}, offset {})",
            self.shape.shape_type(),
            self.shift,
            self.offset
        )
    }
}

impl ConvexCurve for ParryCurve {
    fn eval(&self, _phi: f64) -> CurvePoint {
        unreachable!("the reference reads support points only")
    }
    fn bounding_radius(&self) -> f64 {
        let s = self.shape.compute_local_bounding_sphere();
        s.center.length() + s.radius + self.shift.length() + self.offset.max(0.0)
    }
    fn support_point(&self, n: Vector) -> Vector {
        let m = self.shape.as_support_map().expect("a support-map shape");
        self.shift + m.local_support_point_toward(n) + n * self.offset
    }
}

/// One rapier cast.
pub struct RCase {
    pub body: Body,
    pub target: Target,
    pub set: Set,
    pub seed: u64,
    /// The body as this crate's shape, as a parry shape and as a curve.
    pub ours: Arc<dyn Shape>,
    pub ours_curve: Arc<dyn ConvexCurve>,
    /// The body as parry's shape (for the ellipse, its inscribed 64-gon).
    pub parry: Arc<dyn Shape>,
    /// The target (a parry shape, for both).
    pub target_shape: Arc<dyn Shape>,
    pub target_pose: Pose,
    /// The body's motion (rotation about its centre of mass), from its pose at 0 to its pose at `DT`.
    pub motion: NonlinearRigidMotion,
    /// rapier's sweep of the body (`Sweep::from_poses(start, end, local_com)`).
    pub sweep: Sweep,
    /// parry's centroid and `ccd_thickness` of its body shape (its core circle).
    pub parry_centroid: Vector,
    pub parry_thickness: f64,
    /// The body's inradius about its centre of mass (this crate's rule).
    pub inradius: f64,
    /// The reference signed distance at the start.
    pub d0: f64,
}

/// What parry's sweep and rapier's use of it answer: the fraction kept (rapier's
/// `cast_sub_shape` for a solid pair and a point-cloud target).
#[inline]
pub fn parry_cast(c: &RCase) -> Option<f64> {
    let target = ToiProxy::from_shape(&*c.target_shape)?;
    let body = ToiProxy::from_shape(&*c.parry)?;
    let target_sweep = Sweep::constant(&c.target_pose, Vector::ZERO);
    let out = sweep_time_of_impact(&target, &target_sweep, &body, &c.sweep, 1.0, SLOP);
    if 0.0 < out.fraction && out.fraction < 1.0 {
        return Some(out.fraction);
    }
    if out.fraction == 0.0 {
        let core = ToiProxy::point(c.parry_centroid, CORE_FRACTION * c.parry_thickness);
        let out = sweep_time_of_impact(&target, &target_sweep, &core, &c.sweep, 1.0, SLOP);
        if 0.0 < out.fraction && out.fraction < 1.0 {
            return Some(out.fraction);
        }
    }
    None
}

/// The status of parry's first sweep of `c`.
pub fn parry_status(c: &RCase) -> Option<SweepToiStatus> {
    let target = ToiProxy::from_shape(&*c.target_shape)?;
    let body = ToiProxy::from_shape(&*c.parry)?;
    let target_sweep = Sweep::constant(&c.target_pose, Vector::ZERO);
    Some(sweep_time_of_impact(&target, &target_sweep, &body, &c.sweep, 1.0, SLOP).status)
}

/// What `SmoothDispatcher` answers rapier for the same cast (`fallback_nonlinear_fraction`).
#[inline]
pub fn ours_cast(c: &RCase, d: &SmoothDispatcher) -> Option<f64> {
    let target = NonlinearRigidMotion::constant_position(c.target_pose);
    let hit = d
        .cast_shapes_nonlinear(&c.motion, &*c.ours, &target, &*c.target_shape, 0.0, DT, false)
        .ok()??;
    let f = hit.time_of_impact / DT;
    (0.0 < f && f < 1.0).then_some(f)
}

/// Points on the ellipse of semi-axes `a`, `b` at `n` sorted random angles at least `gap` apart
/// (in convex position, counter-clockwise), shifted by `shift`.
fn ellipse_points(rng: &mut Rng, n: usize, a: f64, b: f64, gap: f64, shift: Vector) -> Vec<Vector> {
    loop {
        let mut t: Vec<f64> = (0..n).map(|_| rng.uniform(0.0, TAU)).collect();
        t.sort_by(f64::total_cmp);
        let ok = (0..n).all(|i| {
            let next = if i + 1 < n { t[i + 1] } else { t[0] + TAU };
            next - t[i] >= gap && next - t[i] <= PI - gap
        });
        if ok {
            return t
                .iter()
                .map(|&t| Vector::new(a * t.cos(), b * t.sin()) + shift)
                .collect();
        }
    }
}

/// The body shapes of `kind`: this crate's, parry's.
fn body_shapes(rng: &mut Rng, kind: Body) -> (Arc<dyn Shape>, Arc<dyn ConvexCurve>, Arc<dyn Shape>) {
    let s = rng.log_uniform(0.1, 1.0);
    let shift = rng.in_disc(0.2 * s);
    let polygon = |pts: Vec<Vector>, radius: f64| {
        let p = RoundedPolygon::new(&pts, radius);
        let parry: Arc<dyn Shape> = if radius > 0.0 {
            Arc::new(p.to_parry().expect("a polygon"))
        } else {
            Arc::new(p.to_parry().expect("a polygon").inner_shape)
        };
        (
            Arc::new(p.clone()) as Arc<dyn Shape>,
            Arc::new(p) as Arc<dyn ConvexCurve>,
            parry,
        )
    };
    match kind {
        Body::Disc => {
            let e = Ellipse::new(s, s);
            (Arc::new(e), Arc::new(e), Arc::new(Ball::new(s)))
        }
        Body::Polygon => {
            let n = rng.int(3, 8);
            let (a, b) = (s, s * rng.uniform(0.5, 1.0));
            let pts = ellipse_points(rng, n, a, b, 0.2, shift);
            polygon(pts, 0.0)
        }
        Body::Rounded => {
            let n = rng.int(3, 8);
            let (a, b) = (s, s * rng.uniform(0.5, 1.0));
            let pts = ellipse_points(rng, n, a, b, 0.2, shift);
            let r = s * rng.uniform(0.02, 0.3);
            polygon(pts, r)
        }
        Body::Sliver => {
            let n = rng.int(3, 4);
            let (a, b) = (s, s / rng.uniform(10.0, 50.0));
            let pts = ellipse_points(rng, n, a, b, 0.5, shift);
            polygon(pts, 0.0)
        }
        Body::Ellipse => {
            let e = Ellipse::new(s, s / rng.uniform(1.5, 10.0));
            let poly = polygon_approximation(&e, POLYGON_VERTICES);
            (Arc::new(e), Arc::new(e), Arc::new(poly))
        }
    }
}

/// The target shape of `kind`.
fn target_shape(rng: &mut Rng, kind: Target) -> Arc<dyn Shape> {
    match kind {
        Target::Ball => Arc::new(Ball::new(rng.log_uniform(0.1, 2.0))),
        Target::Cuboid => Arc::new(Cuboid::new(Vector::new(
            rng.log_uniform(0.02, 2.0),
            rng.log_uniform(0.02, 2.0),
        ))),
        Target::Segment => {
            let h = rng.log_uniform(0.2, 4.0);
            Arc::new(Segment::new(Vector::new(-h, 0.0), Vector::new(h, 0.0)))
        }
        Target::Capsule => {
            let h = rng.log_uniform(0.1, 2.0);
            Arc::new(Capsule::new(
                Vector::new(-h, 0.0),
                Vector::new(h, 0.0),
                rng.log_uniform(0.05, 0.5),
            ))
        }
        Target::Triangle => {
            let r = rng.log_uniform(0.2, 2.0);
            let p = ellipse_points(rng, 3, r, r, 0.3, Vector::ZERO);
            Arc::new(Triangle::new(p[0], p[1], p[2]))
        }
        Target::Polygon => {
            let n = rng.int(3, 8);
            let r = rng.log_uniform(0.2, 2.0);
            let b = r * rng.uniform(0.3, 1.0);
            let p = ellipse_points(rng, n, r, b, 0.2, Vector::ZERO);
            Arc::new(ConvexPolygon::from_convex_polyline(p).expect("a polygon"))
        }
    }
}

/// The distance from `c` to the boundary of the body (inside it): the inradius about `c`.
fn inradius(kind: Body, ours: &dyn Shape, c: Vector) -> f64 {
    match kind {
        Body::Disc | Body::Ellipse => {
            let b = ours.compute_local_aabb();
            0.5 * (b.maxs - b.mins).min_element()
        }
        _ => {
            // The least distance from `c` to the core polygon's edge lines, plus the corner radius.
            let p = ours.as_shape::<RoundedPolygon>().expect("a rounded polygon");
            let v = p.vertices();
            let n = v.len();
            (0..n)
                .map(|i| {
                    let e = v[(i + 1) % n] - v[i];
                    let out = Vector::new(e.y, -e.x).normalize();
                    out.dot(v[i] - c)
                })
                .fold(f64::INFINITY, f64::min)
                + p.corner_radius()
        }
    }
}

/// A pose whose `local_center` point is at `centre`, turned by `angle`.
fn pose_with_centre(angle: f64, local_center: Vector, centre: Vector) -> Pose {
    let r = Pose::rotation(angle);
    Pose::from_parts(centre - r * local_center, r.rotation)
}

/// The reference signed distance of the body at `pose` and the target.
fn distance(body: &dyn ConvexCurve, pose: &Pose, target: &dyn ConvexCurve, target_pose: &Pose) -> f64 {
    reference_distance(body, pose, target, target_pose).distance
}

/// The first distance along `u` from `from` at which the body (turned by `angle`, its centre at
/// the point) touches the target, by conservative advancement on the reference distance
/// (1-Lipschitz in the translation); `None` when it passes.
fn translation_contact(
    body: &dyn ConvexCurve,
    com: Vector,
    angle: f64,
    target: &dyn ConvexCurve,
    target_pose: &Pose,
    from: Vector,
    u: Vector,
    reach: f64,
) -> Option<f64> {
    let mut s = 0.0;
    for _ in 0..10_000 {
        let d = distance(body, &pose_with_centre(angle, com, from + u * s), target, target_pose);
        if d < 1e-13 * reach {
            return Some(s);
        }
        s += d;
        if s > reach {
            return None;
        }
    }
    None
}

/// The case of `seed` for a body of `body` kind against a `target` in `set`.
pub fn make_case(body: Body, target: Target, set: Set, seed: u64) -> RCase {
    let mut rng = Rng::mixed(seed);
    loop {
        let (ours, ours_curve, parry) = body_shapes(&mut rng, body);
        let target_shape = target_shape(&mut rng, target);
        let target_curve = ParryCurve {
            shape: target_shape.clone(),
            shift: Vector::ZERO,
            offset: 0.0,
        };
        let target_pose = Pose::new(
            Vector::new(rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0)),
            rng.angle(),
        );
        let com = ours.mass_properties(1.0).local_com;
        let rb = ours_curve.bounding_radius() + com.length();
        let rt = target_curve.bounding_radius();
        let speed = rng.log_uniform(1.0, 3000.0);
        let turn = match set {
            Set::Apart | Set::Contact => rng.uniform(-FRAC_PI_4, FRAC_PI_4),
            Set::Beyond => rng.sign() * rng.uniform(FRAC_PI_4, 4.0 * PI),
            Set::Still => 0.0,
        };
        let angle = rng.angle();
        let u = rng.direction();
        let side = Vector::new(-u.y, u.x);
        let aimed = rng.chance(0.6);
        let reach = rb + rt;
        let lateral = if aimed {
            rng.uniform(-0.5, 0.5) * reach
        } else {
            rng.sign() * rng.uniform(0.5, 1.3) * reach
        };
        let far = reach + 1.0;
        let from = target_pose.translation + side * lateral - u * far;
        let travel = speed * DT;
        let contact = translation_contact(
            &*ours_curve,
            com,
            angle,
            &target_curve,
            &target_pose,
            from,
            u,
            2.0 * far,
        );
        let (centre, velocity) = match set {
            Set::Apart | Set::Beyond | Set::Still => {
                // Touching (without spin) at fraction f of the step, or stopping short, or
                // passing by.
                let f = if contact.is_some() && rng.chance(0.3) {
                    rng.uniform(1.02, 2.0)
                } else {
                    rng.uniform(0.02, 0.98)
                };
                let s = match contact {
                    Some(s) => s - f * travel,
                    None => far - f * travel,
                };
                (from + u * s, u * speed)
            }
            Set::Contact => {
                let Some(s) = contact else { continue };
                let depth = if rng.chance(0.3) { 0.0 } else { rng.uniform(0.0, 0.1) };
                // Pushed in along u by up to a tenth of the inradius, then any direction.
                let r = inradius(body, &*ours, com);
                (from + u * (s + depth * r), rng.direction() * speed)
            }
        };
        let start = pose_with_centre(angle, com, centre);
        let d0 = distance(&*ours_curve, &start, &target_curve, &target_pose);
        let ok = match set {
            Set::Apart | Set::Beyond | Set::Still => d0 >= MIN_START_GAP,
            Set::Contact => d0 <= 1e-9 * reach,
        };
        if !ok {
            continue;
        }
        let motion = NonlinearRigidMotion::new(start, com, velocity, turn / DT);
        let sweep = Sweep::from_poses(&start, &motion.position_at_time(DT), com);
        let inradius = inradius(body, &*ours, com);
        let parry_centroid = parry.mass_properties(1.0).local_com;
        let parry_thickness = parry.ccd_thickness();
        return RCase {
            body,
            target,
            set,
            seed,
            ours,
            ours_curve,
            parry,
            target_shape,
            target_pose,
            motion,
            sweep,
            parry_centroid,
            parry_thickness,
            inradius,
            d0,
        };
    }
}

fn nlerp_opts() -> RefToiOptions {
    RefToiOptions {
        nlerp: true,
        ..RefToiOptions::default()
    }
}

/// One answer judged: (miss, false, off, |Δf| where both hit).
#[derive(Copy, Clone, Debug, Default)]
pub struct Verdict {
    pub miss: bool,
    pub false_hit: bool,
    pub off: bool,
    pub undecided: bool,
    pub err: Option<f64>,
}

/// The judged case: the answers, the reference's hit and the verdicts.
pub struct Judged {
    pub ours: Option<f64>,
    pub parry: Option<f64>,
    /// The reference's fraction of this crate's event (touching, or its rule), if any.
    pub ref_hit: Option<f64>,
    pub ours_v: Verdict,
    pub parry_v: Verdict,
}

/// The sum of the proxies' radii of parry's cast of `body` (a `ToiProxy`) against the target.
fn proxy_radii(body: &dyn Shape, target: &dyn Shape) -> f64 {
    let r = |s: &dyn Shape| ToiProxy::from_shape(s).map_or(0.0, |p| p.radius);
    r(body) + r(target)
}

/// The reference of `body` (a curve) moving by `m` against the target, down to `level` of the
/// signed distance: the target's support pushed out by `level` (the pair's signed distance less
/// `level`) at target 0 where that keeps a genuine shape (an erosion by at most `erodible`, the
/// pair's rounding), else the reference's own target (a slower search below 0).
fn reference_level(c: &RCase, body: &dyn ConvexCurve, m: &NonlinearRigidMotion, level: f64, erodible: f64) -> RefToi {
    let fixed = NonlinearRigidMotion::constant_position(c.target_pose);
    if level >= -erodible {
        let target = ParryCurve {
            shape: c.target_shape.clone(),
            shift: Vector::ZERO,
            offset: level,
        };
        reference_toi_with(body, m, &target, &fixed, 0.0, DT, 0.0, &nlerp_opts())
    } else {
        let target = ParryCurve {
            shape: c.target_shape.clone(),
            shift: Vector::ZERO,
            offset: 0.0,
        };
        reference_toi_with(body, m, &target, &fixed, 0.0, DT, level, &nlerp_opts())
    }
}

/// parry's answer judged against its band: `body` the curve of the proxy it casts, `radii` the
/// sum of the proxies' radii, `d0` their signed distance at the start.
fn judge_parry_band(
    c: &RCase,
    body: &dyn ConvexCurve,
    m: &NonlinearRigidMotion,
    radii: f64,
    answer: Option<f64>,
    physical: bool,
) -> Verdict {
    let tau = SLOP.max(radii - SLOP);
    let (lo, hi) = (tau - 0.25 * SLOP - radii, tau + 0.25 * SLOP - radii);
    let size = body
        .bounding_radius()
        .max(c.target_shape.compute_local_bounding_sphere().radius);
    let mut v = Verdict::default();
    let touch = physical.then(|| reference_level(c, body, m, 0.0, radii));
    let crossed = |r: &RefToi| matches!(r.outcome, RefOutcome::Hit { crossed: true, .. });
    let capped = |r: &RefToi| r.is_capped();
    match answer {
        None => {
            // A miss: the pair goes past the band's deep end (and, physically, touches).
            let need = touch.as_ref().is_none_or(crossed);
            if need {
                let r_lo = if physical && lo >= 0.0 {
                    touch.unwrap()
                } else {
                    reference_level(c, body, m, lo, radii)
                };
                v.undecided = capped(&r_lo);
                v.miss = crossed(&r_lo);
            }
        }
        Some(f) => {
            let r_hi = reference_level(c, body, m, hi, radii);
            let r_lo = reference_level(c, body, m, lo, radii);
            v.undecided = capped(&r_hi) || capped(&r_lo);
            let t = f * DT;
            match r_hi.hit_time() {
                // Never within the band's shallow end: a false impact; physically, only where
                // the shapes never touch either (else a hit outside the band).
                None => {
                    let touches = touch.as_ref().is_some_and(|r| r.is_hit());
                    v.false_hit = r_hi.min_gap >= 1e-9 * size && !touches;
                    v.off = touches;
                }
                Some(th) => {
                    let tol = 1e-6 * DT;
                    let tl = r_lo.hit_time().unwrap_or(DT);
                    v.off = t < th - tol || t > tl + tol;
                }
            }
            if let Some(tr) = touch.as_ref().and_then(|r| r.hit_time()) {
                v.err = Some((f - tr / DT).abs());
            } else if !physical {
                let th = r_hi.hit_time().unwrap_or(t);
                let tl = r_lo.hit_time().unwrap_or(DT);
                v.err = Some(((th - t).max(t - tl)).max(0.0) / DT);
            }
        }
    }
    v
}

/// This crate's answer judged against a reference of its event (`support::judge`).
fn judge_ours(answer: Option<f64>, rf: &RefToi, size: f64) -> Verdict {
    let mut v = Verdict::default();
    let Some(right) = judge(answer.map(|f| f * DT), rf, size, DT) else {
        v.undecided = true;
        return v;
    };
    let ref_hit = rf.hit_time();
    if let (Some(f), Some(t)) = (answer, ref_hit) {
        v.err = Some((f - t / DT).abs());
    }
    if !right {
        match (answer, ref_hit) {
            (None, Some(_)) => v.miss = true,
            (Some(_), None) => v.false_hit = true,
            _ => v.off = true,
        }
    }
    v
}

/// The earlier-hitting of two references (the first when neither hits), with the smaller least
/// gap.
fn earlier(a: RefToi, b: RefToi) -> RefToi {
    let mut e = match (a.hit_time(), b.hit_time()) {
        (Some(x), Some(y)) if y < x => b,
        (None, Some(_)) => b,
        _ => a,
    };
    if a.is_capped() || b.is_capped() {
        e.outcome = RefOutcome::Capped { reached: 0.0 };
    }
    e.min_gap = a.min_gap.min(b.min_gap);
    e
}

/// Judges both answers of `c`.
pub fn judge_case(c: &RCase, ours: Option<f64>, parry: Option<f64>) -> Judged {
    let size = c
        .ours_curve
        .bounding_radius()
        .max(c.target_shape.compute_local_bounding_sphere().radius);
    let parry_curve: Arc<dyn ConvexCurve> = if c.body == Body::Ellipse {
        Arc::new(ParryCurve {
            shape: c.parry.clone(),
            shift: Vector::ZERO,
            offset: 0.0,
        })
    } else {
        c.ours_curve.clone()
    };
    let radii = proxy_radii(&*c.parry, &*c.target_shape);
    match c.set {
        Set::Apart | Set::Beyond | Set::Still => {
            let rf = reference_level(c, &*c.ours_curve, &c.motion, 0.0, 0.0);
            let ours_v = judge_ours(ours, &rf, size);
            let parry_v = judge_parry_band(c, &*parry_curve, &c.motion, radii, parry, true);
            Judged {
                ours,
                parry,
                ref_hit: rf.hit_time().map(|t| t / DT),
                ours_v,
                parry_v,
            }
        }
        Set::Contact => {
            // This crate's rule: the core, and the translation's deepening.
            let r = c.inradius;
            let spinless = NonlinearRigidMotion {
                angvel: 0.0,
                ..c.motion
            };
            let level = (-OUR_ALLOWANCE * r).min(c.d0 - OUR_ALLOWANCE * r);
            let fixed = NonlinearRigidMotion::constant_position(c.target_pose);
            let target = ParryCurve {
                shape: c.target_shape.clone(),
                shift: Vector::ZERO,
                offset: 0.0,
            };
            let trans = reference_toi_with(
                &*c.ours_curve,
                &spinless,
                &target,
                &fixed,
                0.0,
                DT,
                level,
                &nlerp_opts(),
            );
            let centre = NonlinearRigidMotion::new(
                Pose::from_translation(c.motion.start * c.motion.local_center),
                Vector::ZERO,
                c.motion.linvel,
                0.0,
            );
            let core = BallCurve { radius: OUR_CORE * r };
            let core_ref = reference_toi_with(&core, &centre, &target, &fixed, 0.0, DT, 0.0, &nlerp_opts());
            let rule = earlier(trans, core_ref);
            let ours_v = judge_ours(ours, &rule, size);
            // rapier's rule for parry: the sweep's band, or its core circle's at a fraction 0.
            let tau = SLOP.max(radii - SLOP);
            let parry_d0 = if c.body == Body::Ellipse {
                distance(&*parry_curve, &c.motion.start, &target, &c.target_pose)
            } else {
                c.d0
            };
            let parry_v = if parry_d0 > tau + 0.25 * SLOP - radii {
                judge_parry_band(c, &*parry_curve, &c.motion, radii, parry, false)
            } else {
                let rc = CORE_FRACTION * c.parry_thickness;
                let core = ParryCurve {
                    shape: Arc::new(Ball::new(rc)),
                    shift: c.parry_centroid,
                    offset: 0.0,
                };
                let core_radii = rc + ToiProxy::from_shape(&*c.target_shape).map_or(0.0, |p| p.radius);
                judge_parry_band(c, &core, &c.motion, core_radii, parry, false)
            };
            Judged {
                ours,
                parry,
                ref_hit: rule.hit_time().map(|t| t / DT),
                ours_v,
                parry_v,
            }
        }
    }
}

/// A case's inputs, exactly (f64 `Debug` round-trips).
pub fn describe(c: &RCase) -> String {
    let body = if let Some(p) = c.ours.as_shape::<RoundedPolygon>() {
        format!("RoundedPolygon::new(&{:?}, {:?})", p.vertices(), p.corner_radius())
    } else if let Some(e) = c.ours.as_shape::<Ellipse>() {
        format!("Ellipse::new({:?}, {:?})", e.half_x(), e.half_y())
    } else {
        "?".into()
    };
    let t = &c.target_shape;
    let target = if let Some(b) = t.as_ball() {
        format!("Ball::new({:?})", b.radius)
    } else if let Some(b) = t.as_cuboid() {
        format!("Cuboid::new({:?})", b.half_extents)
    } else if let Some(s) = t.as_segment() {
        format!("Segment::new({:?}, {:?})", s.a, s.b)
    } else if let Some(s) = t.as_capsule() {
        format!("Capsule::new({:?}, {:?}, {:?})", s.segment.a, s.segment.b, s.radius)
    } else if let Some(s) = t.as_triangle() {
        format!("Triangle::new({:?}, {:?}, {:?})", s.a, s.b, s.c)
    } else if let Some(p) = t.as_convex_polygon() {
        format!("ConvexPolygon::from_convex_polyline({:?})", p.points())
    } else {
        "?".into()
    };
    let m = &c.motion;
    format!(
        "seed {} ({:?} – {:?}, {:?}): body {body}, motion NonlinearRigidMotion::new({:?}, {:?}, {:?}, {:?}) over [0, 1/60]; target {target} at {:?}",
        c.seed, c.body, c.target, c.set, m.start, m.local_center, m.linvel, m.angvel, c.target_pose
    )
}

/// One timed, judged case.
struct Row {
    ours_s: f64,
    parry_s: f64,
    j: Judged,
}

/// The seed of case `i` of a pair kind and set.
fn seed(body: Body, target: Target, set: Set, i: usize) -> u64 {
    let b = Body::ALL.iter().position(|&x| x == body).unwrap() as u64;
    let t = Target::ALL.iter().position(|&x| x == target).unwrap() as u64;
    let s = Set::ALL.iter().position(|&x| x == set).unwrap() as u64;
    0x7A91_0000_0000 + ((s * 8 + b) * 8 + t) * 10_000 + i as u64
}

fn fx(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else {
        format!("{x:.2}")
    }
}

fn sci(x: Option<f64>) -> String {
    x.map_or("–".into(), |x| format!("{x:.1e}"))
}

/// miss / false, with the off and undecided counts when not 0.
fn counts(v: &[&Verdict]) -> String {
    let n = |f: fn(&Verdict) -> bool| v.iter().filter(|x| f(x)).count();
    let mut s = format!("{} / {}", n(|x| x.miss), n(|x| x.false_hit));
    let off = n(|x| x.off);
    if off > 0 {
        s += &format!(" ({off} off)");
    }
    let und = n(|x| x.undecided);
    if und > 0 {
        s += &format!(" [{und} undecided]");
    }
    s
}

fn worst(v: &[&Verdict]) -> Option<f64> {
    v.iter()
        .filter_map(|x| x.err)
        .fold(None, |m, e| Some(m.map_or(e, |m: f64| m.max(e))))
}

/// Prints the section.
pub fn table() {
    let d = SmoothDispatcher::default();
    println!("\n## rapier's CCD casts: `SmoothDispatcher` against parry's `sweep_time_of_impact`\n");
    println!(
        "Per pair kind (body – target) and set, {} random casts of one step of 1/60 s (speeds 1–3000 m/s log-uniform, fixed seeds), the target at rest. Ours: rapier's call for this crate's shapes, `cast_shapes_nonlinear(body, constant target, 0, 1/60, stop_at_penetration = false)`, time/dt kept in (0, 1). parry: rapier's call for its own shapes, `sweep_time_of_impact(target, body, 1, linear_slop = {SLOP})` (with rapier's core-circle retry at a fraction 0), on the same body as parry's shape (disc: `Ball`; polygons: `ConvexPolygon` / `RoundConvexPolygon`; ellipse: its inscribed {POLYGON_VERTICES}-gon, against whose own reference parry's columns are judged). Times: mean µs per cast (each case the minimum of alternating rounds); ratio = parry / ours (≥ 1: ours at least as fast), of the means, then the per-case ratio's median and minimum. Apart sets: miss / false against the touching reference on the nlerp path (for parry, beyond its slop band; \"off\": a hit outside the tolerance, 1e-6 of the step for ours, parry's band for parry); worst |Δf|: |fraction − reference| where both hit (parry's includes its slop). Contact set: each against its own rule (ours: core or allowance; parry: band or core circle); parry's |Δf| is its distance outside its band.\n",
        cases()
    );
    println!("| pair kind | set | cases | hits (ref) | ours µs/cast | parry µs/cast | ratio (means) | per-case ratio median / min | ours miss / false | parry miss / false | worst \\|Δf\\| ours | worst \\|Δf\\| parry |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut all: Vec<(Body, Set, Row)> = Vec::new();
    let mut slow: Vec<(f64, f64, String)> = Vec::new();
    let mut wrong: Vec<String> = Vec::new();
    let mut parry_wrong: Vec<(Set, String)> = Vec::new();
    let sets = Set::ALL.into_iter().filter(|s| selected("RAPIER_CASTS_SET", s.name()));
    for set in sets {
        for body in Body::ALL
            .into_iter()
            .filter(|b| selected("RAPIER_CASTS_BODY", b.name()))
        {
            for target in Target::ALL
                .into_iter()
                .filter(|t| selected("RAPIER_CASTS_TARGET", t.name()))
            {
                let seeds: Vec<u64> = (0..cases()).map(|i| seed(body, target, set, i)).collect();
                let cases = par_map(&seeds, |&s| make_case(body, target, set, s));
                let answers: Vec<(Option<f64>, Option<f64>)> =
                    cases.iter().map(|c| (ours_cast(c, &d), parry_cast(c))).collect();
                if profile_only() {
                    let hits = answers.iter().filter(|a| a.0.is_some()).count();
                    // FNV-1a of this crate's fractions' bits (a miss as all ones): a change
                    // meant to keep every answer shows the same digests before and after.
                    let digest = answers.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, a| {
                        (h ^ a.0.map_or(u64::MAX, f64::to_bits)).wrapping_mul(0x0000_0100_0000_01b3)
                    });
                    println!(
                        "{} – {}, {}: {hits} hits, answers {digest:#018x}",
                        body.name(),
                        target.name(),
                        set.name()
                    );
                    continue;
                }
                let idx: Vec<usize> = (0..cases.len()).collect();
                let judged = par_map(&idx, |&i| judge_case(&cases[i], answers[i].0, answers[i].1));
                let mut rows = Vec::new();
                for (c, j) in cases.iter().zip(judged) {
                    let (o, p) = time_contenders(|| ours_cast(c, &d), || parry_cast(c));
                    if j.ours_v.miss || j.ours_v.false_hit || j.ours_v.off {
                        wrong.push(format!(
                            "ours {} (answer {:?}, reference {:?}): {}",
                            if j.ours_v.miss {
                                "miss"
                            } else if j.ours_v.false_hit {
                                "false"
                            } else {
                                "off"
                            },
                            j.ours,
                            j.ref_hit,
                            describe(c)
                        ));
                    }
                    if j.parry_v.miss || j.parry_v.false_hit {
                        parry_wrong.push((
                            set,
                            format!(
                                "parry {} (answer {:?}, sweep status {:?}, reference of this crate's event {:?}): {}",
                                if j.parry_v.miss { "miss" } else { "false" },
                                j.parry,
                                parry_status(c),
                                j.ref_hit,
                                describe(c)
                            ),
                        ));
                    }
                    slow.push((o, p, describe(c)));
                    rows.push(Row {
                        ours_s: o,
                        parry_s: p,
                        j,
                    });
                }
                print_row(
                    &format!("{} – {}", body.name(), target.name()),
                    set,
                    &rows.iter().collect::<Vec<_>>(),
                );
                all.extend(rows.into_iter().map(|r| (body, set, r)));
            }
        }
    }
    if profile_only() {
        return;
    }
    println!("\n### All pair kinds together\n");
    println!("| pair kind | set | cases | hits (ref) | ours µs/cast | parry µs/cast | ratio (means) | per-case ratio median / min | ours miss / false | parry miss / false | worst \\|Δf\\| ours | worst \\|Δf\\| parry |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for set in Set::ALL {
        for body in Body::ALL {
            let rows: Vec<&Row> = all.iter().filter(|x| x.0 == body && x.1 == set).map(|x| &x.2).collect();
            print_row(&format!("{} – all targets", body.name()), set, &rows);
        }
        let rows: Vec<&Row> = all.iter().filter(|x| x.1 == set).map(|x| &x.2).collect();
        print_row("all", set, &rows);
        for (label, hit) in [("all, reference hits", true), ("all, reference misses", false)] {
            let part: Vec<&Row> = rows.iter().copied().filter(|r| r.j.ref_hit.is_some() == hit).collect();
            print_row(label, set, &part);
        }
    }
    slow.sort_by(|a, b| b.0.total_cmp(&a.0));
    println!("\n### Slowest casts of ours\n");
    for (o, p, s) in slow.iter().take(8) {
        println!("- ours {:.2} µs, parry {:.2} µs: {s}", o * 1e6, p * 1e6);
    }
    println!("\n### parry's misses and false impacts\n");
    for set in Set::ALL {
        let w: Vec<&String> = parry_wrong.iter().filter(|x| x.0 == set).map(|x| &x.1).collect();
        println!("{} ({}; the first {}):\n", set.name(), w.len(), w.len().min(4));
        for w in w.iter().take(4) {
            println!("- {w}");
        }
        println!();
    }
    if wrong.is_empty() {
        println!("\nNo answer of ours was wrong against the reference.");
    } else {
        println!("\n### Answers of ours the reference contradicts\n");
        for w in &wrong {
            println!("- {w}");
        }
    }
}

fn print_row(label: &str, set: Set, rows: &[&Row]) {
    let n = rows.len();
    if n == 0 {
        return;
    }
    let hits = rows.iter().filter(|r| r.j.ref_hit.is_some()).count();
    let mo = rows.iter().map(|r| r.ours_s).sum::<f64>() / n as f64;
    let mp = rows.iter().map(|r| r.parry_s).sum::<f64>() / n as f64;
    let ratio: Vec<f64> = rows.iter().map(|r| r.parry_s / r.ours_s).collect();
    let ov: Vec<&Verdict> = rows.iter().map(|r| &r.j.ours_v).collect();
    let pv: Vec<&Verdict> = rows.iter().map(|r| &r.j.parry_v).collect();
    println!(
        "| {label} | {} | {n} | {hits} | {:.2} | {:.2} | {} | {} / {} | {} | {} | {} | {} |",
        set.name(),
        mo * 1e6,
        mp * 1e6,
        fx(mp / mo),
        fx(quantile(&ratio, 0.5)),
        fx(quantile(&ratio, 0.0)),
        counts(&ov),
        counts(&pv),
        sci(worst(&ov)),
        sci(worst(&pv)),
    );
}

/// rapier's casts of this crate's shapes only, for an instruction counter
/// (`cargo bench --bench ratios -- cast-calls` under `valgrind --tool=callgrind
/// --toggle-collect='*cast_shapes_nonlinear*'`): every case of the sets and body kinds that
/// `RAPIER_CASTS_SET` (`apart`, `beyond`, `contact`) and `RAPIER_CASTS_BODY` (`disc`, `polygon`,
/// `rounded`, `sliver`, `ellipse`) name (all when unset), cast `RAPIER_CASTS_PASSES` times (4),
/// no timing and no reference; prints the casts made, the hits and a digest of the answers' bits.
pub fn calls() {
    let d = SmoothDispatcher::default();
    let pick = |var: &str, name: &str| std::env::var(var).map_or(true, |v| name.starts_with(v.as_str()));
    let passes: usize = std::env::var("RAPIER_CASTS_PASSES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(4);
    let mut all = Vec::new();
    for set in Set::ALL {
        let set_name = match set {
            Set::Apart => "apart",
            Set::Beyond => "beyond",
            Set::Contact => "contact",
            Set::Still => "still",
        };
        for body in Body::ALL {
            if !(pick("RAPIER_CASTS_SET", set_name) && pick("RAPIER_CASTS_BODY", body.name())) {
                continue;
            }
            for target in Target::ALL {
                let seeds: Vec<u64> = (0..cases()).map(|i| seed(body, target, set, i)).collect();
                all.extend(par_map(&seeds, |&s| make_case(body, target, set, s)));
            }
        }
    }
    let (mut hits, mut digest) = (0usize, 0xCBF2_9CE4_8422_2325u64);
    for _ in 0..passes {
        for c in &all {
            let a = std::hint::black_box(ours_cast(c, &d));
            hits += usize::from(a.is_some());
            digest = (digest ^ a.map_or(u64::MAX, f64::to_bits)).wrapping_mul(0x0100_0000_01B3);
        }
    }
    println!(
        "cast-calls: {} cases × {passes} passes, {} hits a pass, answers' digest {digest:016x}",
        all.len(),
        hits / passes.max(1)
    );
}
