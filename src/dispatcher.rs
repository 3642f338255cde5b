//! [`SmoothDispatcher`]: parry's `QueryDispatcher` that answers every query for pairs involving
//! this crate's shapes with the algorithms of [`crate::stationary`] and [`crate::toi`], and hands
//! every other pair to parry's `DefaultQueryDispatcher`.
//!
//! Which pairs it answers itself ("ours"): one shape is an [`Ellipse`], [`RoundedPolygon`],
//! [`CapsuleEllipse`] or [`CustomCurve`], and the other is one of those or a parry `Ball`,
//! `Cuboid`, `RoundCuboid`, `Capsule`, `Segment`, `Triangle`, `RoundTriangle`, `ConvexPolygon`
//! or `RoundConvexPolygon` (converted to a [`RoundedPolygon`] or [`BallCurve`]), provided one of
//! the two is strictly convex (object2 of the specification). Pairs where neither is strictly
//! convex (e.g. rounded polygon against a box) go to parry through the shapes' support maps,
//! which is exact for these polygonal pairs. Against a `HalfSpace` the distance is closed-form
//! and the nonlinear cast is [`crate::halfspace`]'s. A composite shape (compound, polyline,
//! trimesh, heightfield) on either side is decomposed by parry's composite helpers with *this*
//! dispatcher answering the sub-queries, so smooth shapes inside composites keep exact answers.
//!
//! Semantics are parry's: `pos12` is shape 2's pose in shape 1's frame, witnesses and normals are
//! in each shape's local frame, `distance` is 0 for touching or penetrating shapes, a cast hit's
//! status is `Converged`, `PenetratingOrWithinTargetDist` or `OutOfIterations`
//! ([`crate::ToiStatus::to_parry`]).
//!
//! One deliberate difference, for rapier: with `stop_at_penetration = false` (rapier's CCD of
//! solid bodies) and shapes in contact at the start (penetrating, or within [`START_CONTACT_GAP`]
//! of the pair's size), the nonlinear cast reports the first time the contact gets deeper than
//! the *allowance*, [`ALLOWANCE`] (a quarter) of the thinner shape's `ccd_thickness` — or, for a
//! contact already about that deep, [`DEEPER_FRACTION`] of the allowance deeper than at the start
//! — and no hit when it does not within the window (at the earliest [`START_NUDGE`] of the window
//! after the start). rapier discards hits at exactly the start time, so answering the start time
//! (as [`crate::time_of_impact`] does) would let a fast body in shallow contact pass through a
//! thin wall; answering just after it freezes a body that spins against a wall (rapier keeps its
//! velocity, its one-point contact does not see the spin, and the next step freezes it again);
//! answering "no hit" for a contact that approaches slowly at the start lets a spinning ellipse
//! turn its tip deep into the wall within the step. The allowance bounds the penetration a step
//! adds and lets the body move on. The deepening is found on the signed distance along the
//! motions (16 samples, then bisection), and for a fast approach no later than when the start
//! rate alone reaches the target. A separating contact at the start is looked past
//! ([`crate::time_of_impact`]), with the same bound on a later deepening.
//!
//! The same rule applies to pairs of this crate's shapes that parry answers (no strictly convex
//! side), whose start contact comes from parry's contact. For these pairs parry's support-map
//! contact and manifold can come back empty for shapes that nearly touch (GJK/EPA give up on
//! parallel faces 10⁻¹⁰ apart, exactly where rapier's CCD leaves a body); the dispatcher then
//! computes them on the shapes pushed 10⁻⁸ of their size into each other and measures the
//! distances at the true pose (`parry_contact`, and `touching_manifold` in [`crate::manifold`]).

use crate::curve::ConvexCurve;
use crate::halfspace::{halfspace_distance, time_of_impact_halfspace};
use crate::math::{Pose, Real, Vector};
use crate::stationary::{stationary_distance, DistanceOptions, QueryError, StationaryDistance};
use crate::toi::{bounding_circles_part, time_of_impact, TimeOfImpact, ToiOptions};
use crate::{BallCurve, CapsuleEllipse, CustomCurve, Ellipse, RoundedPolygon};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{
    self, ClosestPoints, Contact, DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit,
    ShapeCastStatus, ShapeDistance, ShapeIntersection, Unsupported,
};
pub(crate) mod guard;
mod inline_polygon;

use inline_polygon::InlinePolygon;
use parry2d_f64::shape::{
    Ball, Capsule, ConvexPolygon, Cuboid, HalfSpace, RoundConvexPolygon, RoundCuboid, RoundTriangle, Segment, Shape,
    ShapeType, Triangle,
};

/// The query dispatcher of this crate: exact smooth-shape queries, parry for everything else.
///
/// Drop it into rapier with `NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())`.
#[derive(Clone, Debug, Default)]
pub struct SmoothDispatcher {
    /// Options of the stationary distance (distance, contact, closest points, intersection).
    pub distance_options: DistanceOptions,
    /// Options of the casts (the target distance and `stop_at_penetration` come from the caller).
    pub toi_options: ToiOptions,
}

/// A shape seen as a convex curve: borrowed for this crate's shapes, built for parry's (on the
/// stack in a [`RouteScratch`], except for parry polygons with more than
/// [`inline_polygon::INLINE_VERTICES`] vertices).
pub(crate) enum CurveOf<'a> {
    /// An [`Ellipse`], kept by type so that queries can be compiled for it ([`curves_toi`]).
    Ellipse(&'a Ellipse),
    Borrowed(&'a dyn ConvexCurve),
    Ball(BallCurve),
    /// A parry polygon built in the caller's [`RouteScratch`].
    Inline(&'a InlinePolygon),
    Poly(RoundedPolygon),
}

/// Stack room for the polygons [`route`] builds from parry shapes, one per side. A query declares
/// one and routes into it: the polygons (about a kilobyte each) are written once, where they stay,
/// instead of being moved with every [`Route`] and [`CurveOf`] (which cost 6 % of an
/// ellipse–ball time of impact in copies when the polygons lived inside them).
#[derive(Default)]
pub(crate) struct RouteScratch {
    first: Option<InlinePolygon>,
    second: Option<InlinePolygon>,
}

impl CurveOf<'_> {
    pub(crate) fn get(&self) -> &dyn ConvexCurve {
        match self {
            CurveOf::Ellipse(e) => *e,
            CurveOf::Borrowed(c) => *c,
            CurveOf::Ball(b) => b,
            CurveOf::Inline(p) => *p,
            CurveOf::Poly(p) => p,
        }
    }
}

/// This crate's own shapes.
pub(crate) fn own_curve(s: &dyn Shape) -> Option<&dyn ConvexCurve> {
    // This crate's shapes are parry `Custom` shapes: one virtual call rules out all others
    // before the downcasts (two virtual calls each).
    if s.shape_type() != ShapeType::Custom {
        return None;
    }
    if let Some(e) = s.as_shape::<Ellipse>() {
        Some(e)
    } else if let Some(p) = s.as_shape::<RoundedPolygon>() {
        Some(p)
    } else if let Some(c) = s.as_shape::<CapsuleEllipse>() {
        Some(c)
    } else {
        s.as_shape::<CustomCurve>().map(|c| c.curve())
    }
}

/// Puts a triangle in counter-clockwise order; `None` when it is degenerate (or not finite).
fn ccw_triangle(mut v: [Vector; 3]) -> Option<[Vector; 3]> {
    let mut area2 = 0.0;
    for i in 0..3 {
        area2 += crate::math::cross(v[i], v[(i + 1) % 3]);
    }
    let scale = v.iter().fold(0.0f64, |m, p| m.max(p.length_squared()));
    // Also rejects NaN.
    if area2.abs().partial_cmp(&(1e-12 * scale)) != Some(core::cmp::Ordering::Greater) {
        return None;
    }
    if area2 < 0.0 {
        v.reverse();
    }
    Some(v)
}

/// The curve of a polygonal core dilated by `radius`: on the stack when it fits.
fn polygon_curve<'a>(verts: &[Vector], radius: f64, slot: &'a mut Option<InlinePolygon>) -> Option<CurveOf<'a>> {
    if verts.len() < 2 || !verts.iter().all(|v| v.is_finite()) || !radius.is_finite() {
        return None;
    }
    Some(match InlinePolygon::from_core_unchecked(verts, radius) {
        Some(p) => CurveOf::Inline(slot.insert(p)),
        None => CurveOf::Poly(RoundedPolygon::from_core_unchecked(verts.to_vec(), radius)),
    })
}

/// Any shape this dispatcher can treat as a convex curve.
pub(crate) fn curve_of<'a>(s: &'a dyn Shape, slot: &'a mut Option<InlinePolygon>) -> Option<CurveOf<'a>> {
    match s.shape_type() {
        // An ellipse or a disc as `route`'s fast path takes them, then this crate's other shapes.
        ShapeType::Custom | ShapeType::Ball => {
            return ellipse_or_ball(s).or_else(|| own_curve(s).map(CurveOf::Borrowed));
        }
        _ => {}
    }
    if let Some(c) = s.as_shape::<Cuboid>() {
        polygon_curve(&box_vertices(c), 0.0, slot)
    } else if let Some(c) = s.as_shape::<RoundCuboid>() {
        polygon_curve(&box_vertices(&c.inner_shape), c.border_radius, slot)
    } else if let Some(c) = s.as_shape::<Capsule>() {
        if (c.segment.b - c.segment.a).length() <= 1e-12 * c.radius {
            return Some(CurveOf::Ball(BallCurve { radius: c.radius })).filter(|_| c.segment.a == Vector::ZERO);
        }
        polygon_curve(&[c.segment.a, c.segment.b], c.radius, slot)
    } else if let Some(sg) = s.as_shape::<Segment>() {
        if (sg.b - sg.a).length_squared() == 0.0 {
            return None;
        }
        polygon_curve(&[sg.a, sg.b], 0.0, slot)
    } else if let Some(t) = s.as_shape::<Triangle>() {
        polygon_curve(&ccw_triangle([t.a, t.b, t.c])?, 0.0, slot)
    } else if let Some(t) = s.as_shape::<RoundTriangle>() {
        let t2 = &t.inner_shape;
        polygon_curve(&ccw_triangle([t2.a, t2.b, t2.c])?, t.border_radius, slot)
    } else if let Some(p) = s.as_shape::<ConvexPolygon>() {
        polygon_curve(p.points(), 0.0, slot)
    } else if let Some(p) = s.as_shape::<RoundConvexPolygon>() {
        polygon_curve(p.inner_shape.points(), p.border_radius, slot)
    } else {
        None
    }
}

/// Evaluates `$body` with `$x` and `$y` bound to the curves of two [`CurveOf`]s: as concrete
/// types for the pairs where that pays — ellipses and discs, whose evaluations then inline into
/// a query compiled for the pair (about a fifth faster for two ellipses) — and as trait objects
/// otherwise. Every generic query of the crate ([`time_of_impact`], [`stationary_distance`])
/// takes either.
macro_rules! with_curves {
    ($a:expr, $b:expr, |$x:ident, $y:ident| $body:expr) => {
        match ($a, $b) {
            (CurveOf::Ellipse($x), CurveOf::Ellipse($y)) => {
                let ($x, $y): (&Ellipse, &Ellipse) = (*$x, *$y);
                $body
            }
            (CurveOf::Ellipse($x), CurveOf::Ball($y)) => {
                let $x: &Ellipse = *$x;
                $body
            }
            (CurveOf::Ball($x), CurveOf::Ellipse($y)) => {
                let $y: &Ellipse = *$y;
                $body
            }
            (a, b) => {
                let ($x, $y) = (a.get(), b.get());
                $body
            }
        }
    };
}

/// The time of impact of two curves ([`time_of_impact`], shapes in the caller's order).
#[allow(clippy::too_many_arguments)]
fn curves_toi(
    a: &CurveOf,
    motion1: &NonlinearRigidMotion,
    b: &CurveOf,
    motion2: &NonlinearRigidMotion,
    start_time: Real,
    end_time: Real,
    opts: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    with_curves!(a, b, |x, y| time_of_impact(
        x, motion1, y, motion2, start_time, end_time, opts
    ))
}

fn box_vertices(c: &Cuboid) -> [Vector; 4] {
    let h = c.half_extents;
    [
        Vector::new(-h.x, -h.y),
        Vector::new(h.x, -h.y),
        Vector::new(h.x, h.y),
        Vector::new(-h.x, h.y),
    ]
}

/// How a pair is answered. Built once per query: parry shapes are converted to curves here and
/// nowhere else.
pub(crate) enum Route<'a> {
    /// Our algorithm; `swapped` when shape 1 plays object2 (then `c1` is shape 2's curve).
    Curves {
        c1: CurveOf<'a>,
        c2: CurveOf<'a>,
        swapped: bool,
    },
    /// Shape `curve` (ours) against a half-space; `curve_first` tells the order.
    HalfSpace {
        curve: CurveOf<'a>,
        hs: &'a HalfSpace,
        curve_first: bool,
    },
    /// Composite on one side: parry's helpers with this dispatcher.
    Composite,
    /// parry's default dispatcher; `ours` when one side is this crate's shape (the pair has no
    /// strictly convex side, or the other side is not convertible).
    Parry { ours: bool },
}

impl Route<'_> {
    /// The curves of shapes 1 and 2 in the caller's order (`None` for a half-space, or when the
    /// pair is not answered by curves).
    pub(crate) fn curves(&self) -> (Option<&dyn ConvexCurve>, Option<&dyn ConvexCurve>) {
        match self {
            Route::Curves { c1, c2, swapped: false } => (Some(c1.get()), Some(c2.get())),
            Route::Curves { c1, c2, swapped: true } => (Some(c2.get()), Some(c1.get())),
            Route::HalfSpace {
                curve,
                curve_first: true,
                ..
            } => (Some(curve.get()), None),
            Route::HalfSpace { curve, .. } => (None, Some(curve.get())),
            _ => (None, None),
        }
    }
}

/// The half-space `s` is, if it is one (its type first: one virtual call for the others).
fn half_space(s: &dyn Shape) -> Option<&HalfSpace> {
    (s.shape_type() == ShapeType::HalfSpace)
        .then(|| s.as_shape::<HalfSpace>())
        .flatten()
}

/// An [`Ellipse`] or a parry `Ball` of positive radius as a curve; `None` for any other shape.
#[inline]
fn ellipse_or_ball(s: &dyn Shape) -> Option<CurveOf<'_>> {
    match s.shape_type() {
        ShapeType::Custom => s.as_shape::<Ellipse>().map(CurveOf::Ellipse),
        ShapeType::Ball => {
            let b = s.as_shape::<Ball>()?;
            (b.radius > 0.0).then_some(CurveOf::Ball(BallCurve { radius: b.radius }))
        }
        _ => None,
    }
}

/// Chooses how the pair `(g1, g2)` is answered, converting parry shapes to curves when ours.
pub(crate) fn route<'a>(g1: &'a dyn Shape, g2: &'a dyn Shape, scratch: &'a mut RouteScratch) -> Route<'a> {
    // The commonest smooth pairs first: an ellipse with an ellipse or a disc (both strictly
    // convex, no composite, no half-space), recognised with one shape-type call and one downcast
    // per side instead of the general checks below.
    if let (Some(c1), Some(c2)) = (ellipse_or_ball(g1), ellipse_or_ball(g2)) {
        if matches!(c1, CurveOf::Ellipse(_)) || matches!(c2, CurveOf::Ellipse(_)) {
            return Route::Curves { c1, c2, swapped: false };
        }
    }
    route_general(g1, g2, scratch)
}

/// [`route`] without its fast path (every pair; the fast path's answers are these, pinned by
/// `route_fast_path_agrees_with_the_general_route`).
fn route_general<'a>(g1: &'a dyn Shape, g2: &'a dyn Shape, scratch: &'a mut RouteScratch) -> Route<'a> {
    let RouteScratch { first, second } = scratch;
    let ours = own_curve(g1).is_some() || own_curve(g2).is_some();
    if !ours {
        return Route::Parry { ours: false };
    }
    if g1.as_composite_shape().is_some() || g2.as_composite_shape().is_some() {
        return Route::Composite;
    }
    if let Some(hs) = half_space(g2) {
        return match curve_of(g1, first) {
            Some(curve) => Route::HalfSpace {
                curve,
                hs,
                curve_first: true,
            },
            None => Route::Parry { ours },
        };
    }
    if let Some(hs) = half_space(g1) {
        return match curve_of(g2, second) {
            Some(curve) => Route::HalfSpace {
                curve,
                hs,
                curve_first: false,
            },
            None => Route::Parry { ours },
        };
    }
    match (curve_of(g1, first), curve_of(g2, second)) {
        (Some(c1), Some(c2)) => {
            if c2.get().is_strictly_convex() {
                Route::Curves { c1, c2, swapped: false }
            } else if c1.get().is_strictly_convex() {
                Route::Curves {
                    c1: c2,
                    c2: c1,
                    swapped: true,
                }
            } else {
                Route::Parry { ours }
            }
        }
        _ => Route::Parry { ours },
    }
}

/// Stationary distance of a routed pair, in the caller's order.
fn pair_distance(
    c1: &CurveOf,
    c2: &CurveOf,
    swapped: bool,
    pos12: &Pose,
    opts: &DistanceOptions,
) -> Result<StationaryDistance, QueryError> {
    if swapped {
        Ok(with_curves!(c1, c2, |x, y| stationary_distance(x, y, &pos12.inverse(), opts))?.swapped())
    } else {
        with_curves!(c1, c2, |x, y| stationary_distance(x, y, pos12, opts))
    }
}

impl SmoothDispatcher {
    /// The signed distance, witnesses and normals of a pair this dispatcher answers itself, in
    /// the caller's order; `None` when the pair goes to parry.
    pub fn signed_distance(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Option<Result<StationaryDistance, QueryError>> {
        self.routed_distance(&route(g1, g2, &mut RouteScratch::default()), pos12)
    }

    /// [`SmoothDispatcher::signed_distance`] of an already routed pair.
    pub(crate) fn routed_distance(
        &self,
        route: &Route,
        pos12: &Pose,
    ) -> Option<Result<StationaryDistance, QueryError>> {
        match route {
            Route::Curves { c1, c2, swapped } => Some(pair_distance(c1, c2, *swapped, pos12, &self.distance_options)),
            Route::HalfSpace { curve, hs, curve_first } => {
                Some(halfspace_distance(curve.get(), hs, pos12, *curve_first))
            }
            _ => None,
        }
    }

    /// Quick rejection on bounding circles: true when the shapes are surely further apart than
    /// `margin`.
    fn far_apart(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, margin: Real) -> bool {
        let b1 = g1.compute_local_bounding_sphere();
        let b2 = g2.compute_bounding_sphere(pos12);
        (b2.center - b1.center).length() - b1.radius - b2.radius > margin
    }
}

/// The earliest a contact at the start is reported to rapier, as a fraction of the window
/// (module docs): far below any motion rapier resolves, yet strictly after the start time.
pub const START_NUDGE: f64 = 1e-9;

/// Samples on which [`deepening_time`] looks for the penetration getting deeper.
const DEEPENING_SAMPLES: usize = 16;

/// Most bisection steps of [`deepening_time`] (it stops at 10⁻⁹ of the window).
const DEEPENING_BISECTIONS: usize = 48;

/// The penetration a cast for rapier lets a contact at the start reach within the step, as a
/// fraction of the thinner shape's `ccd_thickness` (module docs).
pub const ALLOWANCE: Real = 0.25;

/// Once a contact at the start is about as deep as the allowance, a cast for rapier lets it get
/// deeper by this fraction of the allowance (module docs).
pub const DEEPER_FRACTION: Real = 0.1;

/// For a contact at the start (signed distance `d0`, rate `distance_rate`): the first time in
/// `(t0, t1]` at which the signed distance `signed(t)` drops below the target (at least
/// [`START_NUDGE`] of the window after `t0`), or `None` when it does not within the window.
///
/// The target is minus the *allowance* ([`ALLOWANCE`] of the thinner shape's `ccd_thickness`)
/// or, for a contact already about that deep, [`DEEPER_FRACTION`] of the allowance below `d0`:
/// a step adds at most the allowance to a shallow contact, and a deep one (rapier's solver
/// pushes a one-point contact out slowly while a spin keeps turning the body in) still moves on
/// a little each step rather than freezing. The search runs up to `t_lin`, when the start rate
/// alone would have reached the target (or the end of the window): [`DEEPENING_SAMPLES`]
/// samples, then bisection (to 10⁻⁹ of the window) between the last sample above and the first
/// below. A spinning body whose contact approaches slowly at the start can dive deep within the
/// step (an ellipse's tip turning into a wall), which the samples see; a fast body that would
/// pass a thin wall within one sample interval is stopped at `t_lin`.
fn deepening_time(
    d0: Real,
    distance_rate: Real,
    t0: Real,
    t1: Real,
    thickness: Real,
    signed: impl Fn(Real) -> Option<Real>,
) -> Option<Real> {
    let window = t1 - t0;
    let allowance = ALLOWANCE * thickness;
    let target = (-allowance).min(d0 - DEEPER_FRACTION * allowance);
    let t_lin = if distance_rate < 0.0 {
        t0 + (d0 - target) / -distance_rate
    } else {
        Real::INFINITY
    };
    let end = t_lin.min(t1);
    let below = |t: Real| signed(t).is_some_and(|d| d < target);
    let mut lo = t0;
    let mut hit = None;
    for k in 1..=DEEPENING_SAMPLES {
        let t = t0 + (end - t0) * k as Real / DEEPENING_SAMPLES as Real;
        if below(t) {
            hit = Some(t);
            break;
        }
        lo = t;
    }
    let t = match hit {
        Some(mut hi) => {
            for _ in 0..DEEPENING_BISECTIONS {
                if hi - lo <= 1e-9 * window {
                    break;
                }
                let mid = 0.5 * (lo + hi);
                if below(mid) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            hi
        }
        None if t_lin <= t1 => t_lin,
        None => return None,
    };
    Some(t.max(t0 + START_NUDGE * window))
}

/// The contact of a pair at the start of a cast: signed distance, witnesses in each shape's
/// frame and shape 1's normal.
#[derive(Clone, Copy)]
struct StartContact {
    distance: Real,
    point1: Vector,
    point2: Vector,
    normal1: Vector,
}

impl StartContact {
    fn from_distance(d: &StationaryDistance) -> Self {
        StartContact {
            distance: d.distance,
            point1: d.point1,
            point2: d.point2,
            normal1: d.normal1,
        }
    }

    /// The rate of the signed distance at `t0`: the relative velocity of the witness points
    /// along the normal (negative: approaching).
    fn rate(&self, m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion, t0: Real) -> Real {
        let (p1, p2) = (m1.position_at_time(t0), m2.position_at_time(t0));
        let normal = p1.rotation * self.normal1;
        (point_velocity(m2, t0, p2 * self.point2) - point_velocity(m1, t0, p1 * self.point1)).dot(normal)
    }
}

/// The rapier rule (module docs) for a cast with `stop_at_penetration = false` whose answer is
/// `r` (this crate's time of impact, in the caller's order); `start()` is the pair's contact at
/// `t0` (`None` when surely further than `gap` apart) and `signed(t)` its signed distance at `t`.
///
/// * Penetrating and approaching at the start ([`crate::ToiStatus::PenetratingAtStart`]): the
///   answer is [`deepening_time`] (no hit when the contact does not get a quarter of the thinner
///   `ccd_thickness` deeper within the window).
/// * Within `gap` at the start and approaching: the same (it replaces a hit that only closes
///   the gap, which would clamp the body a hair further every step).
/// * Within `gap` at the start and separating: the earlier of a hit from a separated state
///   (`r` with its distance at the target) and [`deepening_time`]; a hit that came while still
///   in contact (the time of impact reports the contact turning back to approach) is replaced.
/// * Otherwise `r`.
#[allow(clippy::too_many_arguments)]
fn rapier_rule(
    r: TimeOfImpact,
    m1: &NonlinearRigidMotion,
    m2: &NonlinearRigidMotion,
    t0: Real,
    t1: Real,
    thickness: Real,
    gap: Real,
    start: impl Fn() -> Option<StartContact>,
    signed: impl Fn(Real) -> Option<Real>,
) -> Option<TimeOfImpact> {
    if r.status == crate::ToiStatus::PenetratingAtStart {
        return deepening_time(r.distance, r.distance_rate, t0, t1, thickness, signed)
            .map(|time| TimeOfImpact { time, ..r });
    }
    if !is_window(t0, t1) {
        return Some(r);
    }
    let Some(c) = start().filter(|c| c.distance <= gap) else {
        return Some(r);
    };
    let rate = c.rate(m1, m2, t0);
    // A deepening contact is a penetrating one whatever `r` was (parry's
    // `PenetratingOrWithinTargetDist`).
    let deeper = deepening_time(c.distance, rate, t0, t1, thickness, signed).map(|time| TimeOfImpact {
        time,
        status: crate::ToiStatus::PenetratingAtStart,
        ..r
    });
    if rate < 0.0 {
        return deeper;
    }
    let hit = r.status.to_parry().is_some() && r.time > t0;
    let from_separated = hit && r.distance >= -gap;
    match (from_separated, deeper) {
        (true, Some(d)) if d.time < r.time => Some(d),
        (true, _) => Some(r),
        (false, Some(d)) => Some(d),
        (false, None) if hit => None,
        (false, None) => Some(r),
    }
}

/// Whether `[t0, t1]` is a non-empty finite window (false for NaN).
fn is_window(t0: Real, t1: Real) -> bool {
    t1 > t0 && (t1 - t0).is_finite()
}

/// Shape 2's pose in shape 1's frame at time `t`.
fn pos12_at(m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion, t: Real) -> Pose {
    m1.position_at_time(t).inv_mul(&m2.position_at_time(t))
}

/// Velocity at time `t` of the body-fixed point that is at world position `p` then.
fn point_velocity(m: &NonlinearRigidMotion, t: Real, p: Vector) -> Vector {
    let centre = m.position_at_time(t) * m.local_center;
    m.linvel + crate::math::perp(p - centre) * m.angvel
}

/// Relative depths by which [`parry_contact`] pushes touching shapes into each other.
pub(crate) const TOUCH_PUSH: [Real; 3] = [1e-8, 1e-6, 1e-4];

/// `pos12` with shape 2 moved towards shape 1 (along the line of their origins) by `push`.
pub(crate) fn pushed_together(pos12: &Pose, push: Real) -> Pose {
    let u = pos12.translation.try_normalize().unwrap_or(Vector::X);
    Pose::from_parts(pos12.translation - u * push, pos12.rotation)
}

/// The size of a pair: the sum of the bounding radii (of the bounded shapes: a half-space
/// counts for nothing).
pub(crate) fn pair_size(g1: &dyn Shape, g2: &dyn Shape) -> Real {
    let r = |g: &dyn Shape| {
        let r = g.compute_local_bounding_sphere().radius;
        if r.is_finite() && r < 0.5 * Real::MAX {
            r
        } else {
            0.0
        }
    };
    r(g1) + r(g2)
}

/// Whether parry's distance (GJK) puts the shapes within `prediction` of each other.
pub(crate) fn parry_within(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, prediction: Real) -> bool {
    DefaultQueryDispatcher
        .distance(pos12, g1, g2)
        .is_ok_and(|d| d.distance <= prediction)
}

/// parry's contact, robust to shapes that (nearly) touch.
///
/// parry's support-map contact sometimes reports no contact at all for shapes its own distance
/// puts within the prediction: when the shapes touch or nearly touch (a gap of 1e-10, two
/// parallel faces), GJK stops on a degenerate simplex and EPA gives up. This is exactly how
/// rapier's CCD leaves a body after clamping it at an impact, so both the next step's contact and
/// its cast would miss the wall. Then the contact is computed with the shapes pushed into each
/// other by a tiny fraction of their size ([`TOUCH_PUSH`]), and its distance recomputed at the
/// true pose from the witnesses.
pub(crate) fn parry_contact(
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    prediction: Real,
) -> Result<Option<Contact>, Unsupported> {
    if let Some(c) = DefaultQueryDispatcher.contact(pos12, g1, g2, prediction)? {
        return Ok(Some(c));
    }
    if !parry_within(pos12, g1, g2, prediction) {
        return Ok(None);
    }
    let size = pair_size(g1, g2);
    for push in TOUCH_PUSH {
        let deeper = pushed_together(pos12, push * size);
        if let Ok(Some(c)) = DefaultQueryDispatcher.contact(&deeper, g1, g2, prediction + push * size) {
            let dist = (pos12.transform_point(c.point2) - c.point1).dot(c.normal1);
            return Ok((dist <= prediction && dist.is_finite())
                .then(|| Contact::new(c.point1, c.point2, c.normal1, c.normal2, dist)));
        }
    }
    Ok(None)
}

/// parry's nonlinear cast with the window moved to start at time 0 (both motions re-based at
/// `t0`, the hit moved back by `t0`). parry's cast of a pair in contact at the start walks the
/// window with `next_time += increment` and, when the increment is 0 (no relative spin, or two
/// balls), uses `end_time` itself as the increment: with `end_time ≤ 0` (a window before time 0)
/// it never ends, and far from 0 a small increment is lost to rounding. From 0 the walk always
/// moves forward. `t0 = 0` (rapier's CCD) calls parry unchanged.
///
/// That walk takes one contact query per step of min(ccd thickness sum / relative speed,
/// (π − angular thickness) / relative spin, window / 10), and parry's conservative advancement
/// steps of about a distance over an approach speed: a window holding more than
/// [`PARRY_MAX_STEPS`] such steps, relative turns, or travels of the pair's size (a spin of
/// 1e300 rad/s, a window of 1e160 s) would run for hours, so it is refused with `Unsupported`,
/// as are non-finite motions
/// and times; poses and shapes go through the guards of [`guard`] (`Unsupported` for a
/// non-unit rotation, a non-finite bounding box or a non-finite answer), and a reversed window
/// has no hit.
#[allow(clippy::too_many_arguments)]
fn parry_cast_nonlinear(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
    stop: bool,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    if !guard::cast_window_ok(m1, g1, m2, g2, t0, t1)? {
        // A reversed window holds no time: no hit, as for the crate's own casts.
        return Ok(None);
    }
    let hit = if t0 == 0.0 {
        DefaultQueryDispatcher.cast_shapes_nonlinear(m1, g1, m2, g2, t0, t1, stop)?
    } else {
        let at_t0 = |m: &NonlinearRigidMotion| {
            NonlinearRigidMotion::new(m.position_at_time(t0), m.local_center, m.linvel, m.angvel)
        };
        DefaultQueryDispatcher
            .cast_shapes_nonlinear(&at_t0(m1), g1, &at_t0(m2), g2, 0.0, t1 - t0, stop)?
            .map(|h| ShapeCastHit {
                time_of_impact: t0 + h.time_of_impact,
                ..h
            })
    };
    if guard::AllFinite::all_finite(&hit) {
        Ok(hit)
    } else {
        Err(Unsupported)
    }
}

/// The most steps of parry's nonlinear cast (`parry_cast_nonlinear`) lets it take, and the
/// most relative turns, and travels of the pair's size (sum of bounding radii), in its window.
pub const PARRY_MAX_STEPS: Real = 1e4;

/// Shapes closer than this fraction of the pair's size (the sum of the bounding radii) at the
/// start of a cast for rapier are in contact there (module docs): rapier's CCD leaves a body
/// clamped at an impact about 10⁻¹⁰ from the other shape.
pub const START_CONTACT_GAP: Real = 1e-6;

/// parry's nonlinear cast with `stop_at_penetration = false`, under the same start-contact rule
/// as this crate's own casts (module docs), for pairs of this crate's shapes that parry answers
/// (no strictly convex side: a rounded polygon against a box, …).
///
/// parry answers a pair in contact at the start and approaching faster than the sum of the
/// `ccd_thickness`es with `time_of_impact = start_time`, which rapier discards: the body would
/// pass through a thin wall; and when the shapes touch exactly (after rapier's CCD clamped the
/// body at the previous step's impact), parry's contact fails and the cast answers no hit at
/// all. Here a contact at the start (parry's hit at the start time, or a contact from
/// [`parry_contact`] with a gap of at most [`START_CONTACT_GAP`] of the size) is reported at `START_NUDGE` of the window when the approach over the
/// window, from the relative velocity of the witness points along the normal, exceeds a quarter
/// of the thinner shape's `ccd_thickness`; otherwise the cast answers no hit, as the crate's own
/// casts do. A later hit of parry's is returned unchanged.
#[allow(clippy::too_many_arguments)]
fn parry_nonlinear_without_stop(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    let hit = parry_cast_nonlinear(m1, g1, m2, g2, t0, t1, false)?;
    // Reversed, empty or non-finite windows: parry's answer.
    if !is_window(t0, t1) {
        return Ok(hit);
    }
    // parry's answer, but a hit at the start (which rapier discards) only through the rule.
    let later = hit.filter(|h| h.time_of_impact > t0);
    let pos12 = pos12_at(m1, m2, t0);
    let gap = START_CONTACT_GAP * pair_size(g1, g2);
    let start = if SmoothDispatcher::far_apart(&pos12, g1, g2, gap) {
        None
    } else {
        parry_contact(&pos12, g1, g2, gap).ok().flatten().map(|c| StartContact {
            distance: c.dist,
            point1: c.point1,
            point2: c.point2,
            normal1: c.normal1,
        })
    };
    // parry's hit at the start says the shapes touch even if the contact could not be had.
    let start = start.or_else(|| {
        hit.filter(|h| h.time_of_impact <= t0).map(|h| StartContact {
            distance: 0.0,
            point1: h.witness1,
            point2: h.witness2,
            normal1: h.normal1,
        })
    });
    let Some(c) = start else {
        return Ok(later);
    };
    let rate = c.rate(m1, m2, t0);
    let thickness = g1.ccd_thickness().min(g2.ccd_thickness());
    let signed = |t: Real| {
        parry_contact(&pos12_at(m1, m2, t), g1, g2, 0.0)
            .ok()
            .flatten()
            .map(|c| c.dist)
    };
    let deeper = deepening_time(c.distance, rate, t0, t1, thickness, signed);
    // Separating at the start: the earlier of parry's later hit and a deepening of the contact.
    if rate.is_nan() || rate >= 0.0 {
        return Ok(match (later, deeper) {
            (Some(h), Some(t)) if t >= h.time_of_impact => Some(h),
            (Some(h), None) => Some(h),
            (_, Some(t)) => Some(ShapeCastHit {
                time_of_impact: t,
                witness1: c.point1,
                witness2: c.point2,
                normal1: c.normal1,
                normal2: pos12.rotation.inverse() * -c.normal1,
                status: ShapeCastStatus::PenetratingOrWithinTargetDist,
                subshape1: 0,
                subshape2: 0,
            }),
            (None, None) => None,
        });
    }
    let Some(time) = deeper else {
        return Ok(None);
    };
    Ok(Some(ShapeCastHit {
        time_of_impact: time,
        witness1: c.point1,
        witness2: c.point2,
        normal1: c.normal1,
        normal2: pos12.rotation.inverse() * -c.normal1,
        status: ShapeCastStatus::PenetratingOrWithinTargetDist,
        subshape1: 0,
        subshape2: 0,
    }))
}

fn hit_from(r: &TimeOfImpact) -> Option<ShapeCastHit> {
    let status = r.status.to_parry()?;
    Some(ShapeCastHit {
        time_of_impact: r.time,
        witness1: r.point1,
        witness2: r.point2,
        normal1: r.normal1,
        normal2: r.normal2,
        status,
        subshape1: 0,
        subshape2: 0,
    })
}

fn toi_to_parry(r: Result<Option<TimeOfImpact>, QueryError>) -> Result<Option<ShapeCastHit>, Unsupported> {
    match r {
        Ok(r) => Ok(r.as_ref().and_then(hit_from)),
        Err(QueryError::EmptyWindow) => Ok(None),
        Err(_) => Err(Unsupported),
    }
}

impl QueryDispatcher for SmoothDispatcher {
    fn intersection_test(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeIntersection, Unsupported> {
        match route(g1, g2, &mut RouteScratch::default()) {
            Route::Parry { .. } => guard::parry(pos12, g1, g2, 0.0, || {
                DefaultQueryDispatcher.intersection_test(pos12, g1, g2)
            }),
            Route::Composite => guard::parry(pos12, g1, g2, 0.0, || composite_intersection(self, pos12, g1, g2)),
            r => {
                if Self::far_apart(pos12, g1, g2, 0.0) {
                    return Ok(ShapeIntersection::new(false));
                }
                match self.routed_distance(&r, pos12) {
                    Some(Ok(d)) => Ok(ShapeIntersection::new(d.distance <= 0.0)),
                    _ => Err(Unsupported),
                }
            }
        }
    }

    fn distance(&self, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> Result<ShapeDistance, Unsupported> {
        match route(g1, g2, &mut RouteScratch::default()) {
            Route::Parry { .. } => guard::parry(pos12, g1, g2, 0.0, || DefaultQueryDispatcher.distance(pos12, g1, g2)),
            Route::Composite => guard::parry(pos12, g1, g2, 0.0, || composite_distance(self, pos12, g1, g2)),
            r => match self.routed_distance(&r, pos12) {
                Some(Ok(d)) => Ok(ShapeDistance::new(d.distance.max(0.0))),
                _ => Err(Unsupported),
            },
        }
    }

    fn contact(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
    ) -> Result<Option<Contact>, Unsupported> {
        if prediction.is_nan() || prediction < 0.0 {
            // parry's contract (its composite helpers assert it): no negative or NaN margin.
            return Err(Unsupported);
        }
        match route(g1, g2, &mut RouteScratch::default()) {
            // parry's, robust to nearly touching shapes (`parry_contact`).
            Route::Parry { ours: true } => {
                guard::parry(pos12, g1, g2, prediction, || parry_contact(pos12, g1, g2, prediction))
            }
            Route::Parry { ours: false } => guard::parry(pos12, g1, g2, prediction, || {
                DefaultQueryDispatcher.contact(pos12, g1, g2, prediction)
            }),
            Route::Composite => guard::parry(pos12, g1, g2, prediction, || {
                composite_contact(self, pos12, g1, g2, prediction)
            }),
            r => {
                if Self::far_apart(pos12, g1, g2, prediction) {
                    return Ok(None);
                }
                match self.routed_distance(&r, pos12) {
                    Some(Ok(d)) if d.distance <= prediction => {
                        Ok(Some(Contact::new(d.point1, d.point2, d.normal1, d.normal2, d.distance)))
                    }
                    Some(Ok(_)) => Ok(None),
                    _ => Err(Unsupported),
                }
            }
        }
    }

    fn closest_points(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        max_dist: Real,
    ) -> Result<ClosestPoints, Unsupported> {
        if max_dist.is_nan() || max_dist < 0.0 {
            // parry's contract (it asserts it for balls and half-spaces): no negative or NaN margin.
            return Err(Unsupported);
        }
        match route(g1, g2, &mut RouteScratch::default()) {
            Route::Parry { .. } => guard::parry(pos12, g1, g2, max_dist, || {
                DefaultQueryDispatcher.closest_points(pos12, g1, g2, max_dist)
            }),
            Route::Composite => guard::parry(pos12, g1, g2, max_dist, || {
                composite_closest_points(self, pos12, g1, g2, max_dist)
            }),
            r => {
                if Self::far_apart(pos12, g1, g2, max_dist) {
                    return Ok(ClosestPoints::Disjoint);
                }
                match self.routed_distance(&r, pos12) {
                    Some(Ok(d)) if d.distance <= 0.0 => Ok(ClosestPoints::Intersecting),
                    Some(Ok(d)) if d.distance <= max_dist => Ok(ClosestPoints::WithinMargin(d.point1, d.point2)),
                    Some(Ok(_)) => Ok(ClosestPoints::Disjoint),
                    _ => Err(Unsupported),
                }
            }
        }
    }

    fn cast_shapes(
        &self,
        pos12: &Pose,
        local_vel12: Vector,
        g1: &dyn Shape,
        g2: &dyn Shape,
        options: ShapeCastOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        match route(g1, g2, &mut RouteScratch::default()) {
            Route::Curves { c1, c2, swapped } => {
                let m1 = NonlinearRigidMotion::identity();
                let m2 = NonlinearRigidMotion::new(*pos12, Vector::ZERO, local_vel12, 0.0);
                let opts = ToiOptions {
                    target_distance: options.target_distance,
                    stop_at_penetration: options.stop_at_penetration,
                    ..self.toi_options
                };
                // time_of_impact takes the shapes in the caller's order (it swaps roles itself).
                let (a, b) = if swapped { (&c2, &c1) } else { (&c1, &c2) };
                let (t1, delta) = (options.max_time_of_impact, options.target_distance);
                if bounding_circles_part(a.get(), &m1, b.get(), &m2, 0.0, t1, delta) {
                    return Ok(None);
                }
                let r = curves_toi(a, &m1, b, &m2, 0.0, t1, &opts);
                toi_to_parry(r.map(Some))
            }
            Route::Composite => guard::parry(pos12, g1, g2, 0.0, || {
                composite_cast(self, pos12, local_vel12, g1, g2, options)
            }),
            // Linear casts against half-spaces and polygonal pairs are exact in parry.
            _ => guard::parry(pos12, g1, g2, 0.0, || {
                DefaultQueryDispatcher.cast_shapes(pos12, local_vel12, g1, g2, options)
            }),
        }
    }

    fn cast_shapes_nonlinear(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: Real,
        end_time: Real,
        stop_at_penetration: bool,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let opts = ToiOptions {
            stop_at_penetration,
            ..self.toi_options
        };
        match route(g1, g2, &mut RouteScratch::default()) {
            Route::Curves { c1, c2, swapped } => {
                let (a, b) = if swapped { (&c2, &c1) } else { (&c1, &c2) };
                // The specification's inexpensive test first: circles that never meet, no impact
                // (and no contact at the start for the rapier rule below).
                if bounding_circles_part(
                    a.get(),
                    motion1,
                    b.get(),
                    motion2,
                    start_time,
                    end_time,
                    opts.target_distance,
                ) {
                    return Ok(None);
                }
                let thickness = g1.ccd_thickness().min(g2.ccd_thickness());
                let r = curves_toi(a, motion1, b, motion2, start_time, end_time, &opts);
                if stop_at_penetration {
                    return toi_to_parry(r.map(Some));
                }
                let dopts = &self.distance_options;
                let at = |t: Real| pair_distance(&c1, &c2, swapped, &pos12_at(motion1, motion2, t), dopts).ok();
                let gap = START_CONTACT_GAP * pair_size(g1, g2);
                toi_to_parry(r.map(|r| {
                    rapier_rule(
                        r,
                        motion1,
                        motion2,
                        start_time,
                        end_time,
                        thickness,
                        gap,
                        || {
                            let pos12 = pos12_at(motion1, motion2, start_time);
                            if Self::far_apart(&pos12, g1, g2, gap) {
                                return None;
                            }
                            pair_distance(&c1, &c2, swapped, &pos12, dopts)
                                .ok()
                                .map(|d| StartContact::from_distance(&d))
                        },
                        |t| at(t).map(|d| d.distance),
                    )
                }))
            }
            Route::HalfSpace { curve, hs, curve_first } => {
                let r = if curve_first {
                    time_of_impact_halfspace(curve.get(), motion1, hs, motion2, start_time, end_time, &opts)
                } else {
                    time_of_impact_halfspace(curve.get(), motion2, hs, motion1, start_time, end_time, &opts)
                        .map(TimeOfImpact::swapped)
                };
                let thickness = if curve_first {
                    g1.ccd_thickness()
                } else {
                    g2.ccd_thickness()
                };
                if stop_at_penetration {
                    return toi_to_parry(r.map(Some));
                }
                let at =
                    |t: Real| halfspace_distance(curve.get(), hs, &pos12_at(motion1, motion2, t), curve_first).ok();
                let gap = START_CONTACT_GAP * pair_size(g1, g2);
                toi_to_parry(r.map(|r| {
                    rapier_rule(
                        r,
                        motion1,
                        motion2,
                        start_time,
                        end_time,
                        thickness,
                        gap,
                        || at(start_time).map(|d| StartContact::from_distance(&d)),
                        |t| at(t).map(|d| d.distance),
                    )
                }))
            }
            // parry's composite helper casts bounding balls itself: the same guards as parry's casts.
            Route::Composite => match guard::cast_window_ok(motion1, g1, motion2, g2, start_time, end_time) {
                Ok(true) => guard::finite(composite_cast_nonlinear(
                    self,
                    motion1,
                    g1,
                    motion2,
                    g2,
                    start_time,
                    end_time,
                    stop_at_penetration,
                )),
                Ok(false) => Ok(None),
                Err(e) => Err(e),
            },
            Route::Parry { ours: true } if !stop_at_penetration => guard::finite(parry_nonlinear_without_stop(
                motion1, g1, motion2, g2, start_time, end_time,
            )),
            Route::Parry { .. } => {
                parry_cast_nonlinear(motion1, g1, motion2, g2, start_time, end_time, stop_at_penetration)
            }
        }
    }
}

fn composite_intersection(
    d: &SmoothDispatcher,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
) -> Result<ShapeIntersection, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::intersection_test_composite_shape_shape(
            d, pos12, c1, g2,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::intersection_test_shape_composite_shape(
            d, pos12, g1, c2,
        ))
    } else {
        Err(Unsupported)
    }
}

fn composite_distance(
    d: &SmoothDispatcher,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
) -> Result<ShapeDistance, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::distance_composite_shape_shape(d, pos12, c1, g2))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::distance_shape_composite_shape(d, pos12, g1, c2))
    } else {
        Err(Unsupported)
    }
}

fn composite_contact(
    d: &SmoothDispatcher,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    prediction: Real,
) -> Result<Option<Contact>, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::contact_composite_shape_shape(
            d, pos12, c1, g2, prediction,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::contact_shape_composite_shape(
            d, pos12, g1, c2, prediction,
        ))
    } else {
        Err(Unsupported)
    }
}

fn composite_closest_points(
    d: &SmoothDispatcher,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    max_dist: Real,
) -> Result<ClosestPoints, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::closest_points_composite_shape_shape(
            d, pos12, c1, g2, max_dist,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::closest_points_shape_composite_shape(
            d, pos12, g1, c2, max_dist,
        ))
    } else {
        Err(Unsupported)
    }
}

fn composite_cast(
    d: &SmoothDispatcher,
    pos12: &Pose,
    vel12: Vector,
    g1: &dyn Shape,
    g2: &dyn Shape,
    options: ShapeCastOptions,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::cast_shapes_composite_shape_shape(
            d, pos12, vel12, c1, g2, options,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::cast_shapes_shape_composite_shape(
            d, pos12, vel12, g1, c2, options,
        ))
    } else {
        Err(Unsupported)
    }
}

#[allow(clippy::too_many_arguments)]
fn composite_cast_nonlinear(
    d: &SmoothDispatcher,
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
    stop: bool,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    if let Some(c1) = g1.as_composite_shape() {
        Ok(query::details::cast_shapes_nonlinear_composite_shape_shape(
            d, m1, c1, m2, g2, t0, t1, stop,
        ))
    } else if let Some(c2) = g2.as_composite_shape() {
        Ok(query::details::cast_shapes_nonlinear_shape_composite_shape(
            d, m1, g1, m2, c2, t0, t1, stop,
        ))
    } else {
        Err(Unsupported)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::unit;
    use core::f64::consts::PI;

    fn assert_same_curve(a: &dyn ConvexCurve, b: &dyn ConvexCurve, what: &str) {
        assert_eq!(a.breakpoints(), b.breakpoints(), "{what}");
        assert_eq!(a.bounding_radius().to_bits(), b.bounding_radius().to_bits(), "{what}");
        for k in 0..2000 {
            let phi = -4.0 + 8.0 * k as f64 / 1999.0;
            assert_eq!(a.eval(phi), b.eval(phi), "{what}: eval({phi})");
        }
        for k in 0..720 {
            let m = unit(PI * k as f64 / 360.0);
            assert_eq!(a.phi_range_of_normal(m), b.phi_range_of_normal(m), "{what}: normal {m}");
            assert_eq!(a.support_point(m), b.support_point(m), "{what}: support {m}");
        }
        assert_eq!(a.is_strictly_convex(), b.is_strictly_convex());
        assert_eq!(a.support_dd_bound().to_bits(), b.support_dd_bound().to_bits());
        // The shallow-penetration certificate of the stationary distance reads these.
        assert_eq!(
            a.min_radius_of_curvature().to_bits(),
            b.min_radius_of_curvature().to_bits(),
            "{what}"
        );
        assert_eq!(
            a.max_radius_of_curvature().to_bits(),
            b.max_radius_of_curvature().to_bits(),
            "{what}"
        );
    }

    /// The stack conversion of parry's polygonal shapes is the allocating `RoundedPolygon`
    /// conversion it replaces, bit for bit.
    #[test]
    fn inline_polygon_matches_rounded_polygon_bit_for_bit() {
        let cores: Vec<(Vec<Vector>, f64)> = vec![
            (box_vertices(&Cuboid::new(Vector::new(0.5, 0.3))).to_vec(), 0.0),
            (box_vertices(&Cuboid::new(Vector::new(2.0, 0.01))).to_vec(), 0.05),
            (vec![Vector::new(-0.3, 0.1), Vector::new(0.4, 0.2)], 0.2),
            (vec![Vector::new(-1.0, 0.0), Vector::new(0.5, 0.7)], 0.0),
            (vec![Vector::ZERO, Vector::new(1.0, 0.0), Vector::new(0.2, 0.8)], 0.1),
            (
                (0..inline_polygon::INLINE_VERTICES)
                    .map(|i| unit(0.3 + 2.0 * PI * i as f64 / inline_polygon::INLINE_VERTICES as f64) * 1.7)
                    .collect(),
                0.0,
            ),
        ];
        for (k, (v, r)) in cores.iter().enumerate() {
            let inline = InlinePolygon::from_core_unchecked(v, *r).expect("fits");
            let reference = RoundedPolygon::from_core_unchecked(v.clone(), *r);
            assert_same_curve(&inline, &reference, &format!("core {k}"));
        }
        let too_many: Vec<Vector> = (0..=inline_polygon::INLINE_VERTICES)
            .map(|i| unit(2.0 * PI * i as f64 / (inline_polygon::INLINE_VERTICES + 1) as f64))
            .collect();
        assert!(InlinePolygon::from_core_unchecked(&too_many, 0.0).is_none());
    }

    /// `route`'s shortcut for ellipses and discs answers what the general checks answer: the
    /// same curves in the same roles, and parry for two discs or a disc of radius 0.
    #[test]
    fn route_fast_path_agrees_with_the_general_route() {
        let e1 = Ellipse::new(0.5, 0.2);
        let e2 = Ellipse::new(0.1, 0.3);
        let (b, b0) = (Ball::new(0.25), Ball::new(0.0));
        let cube = Cuboid::new(Vector::new(0.5, 0.3));
        let shapes: [&dyn Shape; 5] = [&e1, &e2, &b, &b0, &cube];
        let describe = |r: Route| match r {
            Route::Curves { c1, c2, swapped } => {
                let d = |c: &CurveOf| match c {
                    CurveOf::Ellipse(e) => format!("ellipse {} {}", e.half_x(), e.half_y()),
                    CurveOf::Ball(b) => format!("ball {}", b.radius),
                    CurveOf::Inline(_) | CurveOf::Poly(_) => "polygon".to_string(),
                    CurveOf::Borrowed(_) => "borrowed".to_string(),
                };
                format!("curves {} / {} swapped {swapped}", d(&c1), d(&c2))
            }
            Route::HalfSpace { .. } => "half-space".to_string(),
            Route::Composite => "composite".to_string(),
            Route::Parry { ours } => format!("parry {ours}"),
        };
        let mut fast = 0;
        for g1 in shapes {
            for g2 in shapes {
                let (mut s1, mut s2) = (RouteScratch::default(), RouteScratch::default());
                let quick = describe(route(g1, g2, &mut s1));
                let general = describe(route_general(g1, g2, &mut s2));
                assert_eq!(quick, general);
                fast += usize::from(matches!(
                    (ellipse_or_ball(g1), ellipse_or_ball(g2)),
                    (Some(CurveOf::Ellipse(_)), Some(_)) | (Some(_), Some(CurveOf::Ellipse(_)))
                ));
            }
        }
        // Ellipse–ellipse (4), ellipse–disc and disc–ellipse (4) take the shortcut.
        assert_eq!(fast, 8);
    }

    /// Which conversion each parry shape gets: on the stack up to `INLINE_VERTICES` vertices.
    #[test]
    fn parry_shapes_convert_on_the_stack_when_small() {
        let small = ConvexPolygon::from_convex_polyline((0..6).map(|i| unit(PI * i as f64 / 3.0)).collect());
        let large = ConvexPolygon::from_convex_polyline((0..40).map(|i| unit(PI * i as f64 / 20.0)).collect());
        let shapes: [(&dyn Shape, bool); 7] = [
            (&Cuboid::new(Vector::new(0.5, 0.3)), true),
            (&Capsule::new(Vector::new(-0.3, 0.1), Vector::new(0.4, 0.2), 0.2), true),
            (&Segment::new(Vector::new(-1.0, 0.0), Vector::new(0.5, 0.7)), true),
            // Clockwise: reordered.
            (
                &Triangle::new(Vector::ZERO, Vector::new(0.0, 1.0), Vector::new(1.0, 0.0)),
                true,
            ),
            (small.as_ref().expect("convex"), true),
            (large.as_ref().expect("convex"), false),
            (&Triangle::new(Vector::ZERO, Vector::X, Vector::X * 2.0), false),
        ];
        for (k, (shape, inline)) in shapes.into_iter().enumerate() {
            match curve_of(shape, &mut None) {
                Some(CurveOf::Inline(_)) => assert!(inline, "shape {k}"),
                Some(CurveOf::Poly(_)) => assert!(!inline && k == 5, "shape {k}"),
                None => assert_eq!(k, 6, "only the flat triangle is rejected"),
                Some(_) => panic!("shape {k}: not a polygon"),
            }
        }
        // The triangle's curve is counter-clockwise: the support along +x is the vertex (1, 0).
        let t = Triangle::new(Vector::ZERO, Vector::new(0.0, 1.0), Vector::new(1.0, 0.0));
        let mut slot = None;
        let c = curve_of(&t, &mut slot).expect("a triangle");
        assert_eq!(c.get().support_point(Vector::X), Vector::X);
    }
}
