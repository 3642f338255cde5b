//! How a pair is answered ([`route`]): this crate's algorithm on two curves (parry's shapes
//! converted, on the stack when small), a curve against a half-space, a composite shape
//! decomposed by parry's helpers, or parry itself.

use super::inline_polygon::InlinePolygon;
use crate::curve::ConvexCurve;
use crate::error::QueryError;
use crate::numerics::math::{cross, Pose, Real, Vector};
use crate::query::gap::{CurveSide, PolySide, Side};
use crate::query::stationary::{stationary_distance, DistanceOptions, StationaryDistance};
use crate::query::toi::{time_of_impact, TimeOfImpact, ToiOptions};
use crate::{BallCurve, CapsuleEllipse, CustomCurve, Ellipse, RoundedPolygon};
use parry2d_f64::query::NonlinearRigidMotion;
use parry2d_f64::shape::{
    Ball, Capsule, ConvexPolygon, Cuboid, HalfSpace, RoundConvexPolygon, RoundCuboid, RoundTriangle, Segment, Shape,
    ShapeType, Triangle,
};

/// A triangle's doubled area below this fraction of its squared size is degenerate.
const FLAT_TRIANGLE: f64 = 1e-12;
/// A capsule whose segment is shorter than this fraction of its radius is a ball.
const CAPSULE_AS_BALL: f64 = 1e-12;

/// A shape seen as a convex curve: borrowed for this crate's shapes, built for parry's (on the
/// stack in a [`RouteScratch`], except for parry polygons with more than
/// [`crate::dispatcher::inline_polygon::INLINE_VERTICES`] vertices).
pub(crate) enum CurveOf<'a> {
    /// An [`Ellipse`], kept by type so that queries can be compiled for it ([`curves_toi`]).
    Ellipse(&'a Ellipse),
    Borrowed(&'a dyn ConvexCurve),
    Ball(BallCurve),
    /// A parry polygon built in the caller's [`RouteScratch`].
    Inline(&'a InlinePolygon),
    Poly(RoundedPolygon),
    /// This crate's [`RoundedPolygon`], [`CapsuleEllipse`] and [`CustomCurve`], kept by type for
    /// the time of impact of pairs with no strictly convex side (their faces).
    Rounded(&'a RoundedPolygon),
    Capsule(&'a CapsuleEllipse),
    Custom(&'a CustomCurve),
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
            CurveOf::Rounded(p) => *p,
            CurveOf::Capsule(c) => *c,
            CurveOf::Custom(c) => c.curve(),
        }
    }

    /// The curve as a side of the gap tracker, a strictly convex curve included (a curve with no
    /// face); `None` for a curve known only as a trait object that is not strictly convex.
    pub(crate) fn any_side(&self) -> Option<Side<'_>> {
        self.gap_side().or_else(|| {
            let curve = self.get();
            curve
                .is_strictly_convex()
                .then_some(Side::Curve(CurveSide { curve, faces: &[] }))
        })
    }

    /// The curve as a side of the gap tracker (a dilated polygon, or a curve with its faces);
    /// `None` for a curve the dispatcher only knows as a trait object.
    pub(crate) fn gap_side(&self) -> Option<Side<'_>> {
        let poly = |v, n, r| PolySide::new(v, n, r).map(Side::Poly);
        match self {
            CurveOf::Inline(p) => poly(p.vertices(), p.edge_normals(), p.radius()),
            CurveOf::Poly(p) => poly(p.vertices(), p.edge_normals(), p.corner_radius()),
            CurveOf::Rounded(p) => poly(p.vertices(), p.edge_normals(), p.corner_radius()),
            CurveOf::Capsule(c) => Some(Side::Curve(CurveSide {
                curve: *c,
                faces: c.flats(),
            })),
            CurveOf::Custom(c) => Some(Side::Curve(CurveSide {
                curve: c.curve(),
                faces: c.flats(),
            })),
            CurveOf::Ellipse(_) | CurveOf::Ball(_) | CurveOf::Borrowed(_) => None,
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

/// A triangle as the polygon of its vertices counter-clockwise, with their count: the three
/// vertices ([`ccw_triangle`]), or, for a flat triangle — its doubled area, taken from its first
/// vertex, at most [`FLAT_TRIANGLE`] of its longest edge squared: its vertices on a line to
/// rounding — the segment between its two farthest vertices (a mesh's degenerate triangle, whose
/// hull that segment is; left to parry's conservative advancement, such a triangle's cast against
/// a turning user curve ran for more than 15 s). `None` when the three vertices coincide or one
/// is not finite.
pub(crate) fn triangle_hull(v: [Vector; 3]) -> Option<([Vector; 3], usize)> {
    if let Some(t) = ccw_triangle(v) {
        return Some((t, 3));
    }
    if !v.iter().all(|p| p.is_finite()) {
        return None;
    }
    let edge = |i: usize, j: usize| (v[j] - v[i]).length_squared();
    // The first longest edge (a triangle (p, q, q) is the segment from p to q).
    let (i, j) =
        [(1, 2), (2, 0)].into_iter().fold(
            (0, 1),
            |best, e| if edge(e.0, e.1) > edge(best.0, best.1) { e } else { best },
        );
    let longest = edge(i, j);
    if !(longest > 0.0 && longest.is_finite()) {
        return None;
    }
    let area2 = cross(v[1] - v[0], v[2] - v[0]);
    if area2.abs() > FLAT_TRIANGLE * longest {
        // Not flat: a triangle far from the origin, whose area about the origin the rounding of
        // its coordinates hides; in counter-clockwise order from its own first vertex.
        let t = if area2 > 0.0 { v } else { [v[2], v[1], v[0]] };
        return Some((t, 3));
    }
    Some(([v[i], v[j], v[j]], 2))
}

/// Puts a triangle in counter-clockwise order; `None` when it is degenerate (or not finite).
pub(crate) fn ccw_triangle(mut v: [Vector; 3]) -> Option<[Vector; 3]> {
    let mut area2 = 0.0;
    for i in 0..3 {
        area2 += cross(v[i], v[(i + 1) % 3]);
    }
    let scale = v.iter().fold(0.0f64, |m, p| m.max(p.length_squared()));
    // Also rejects NaN.
    if area2.abs().partial_cmp(&(FLAT_TRIANGLE * scale)) != Some(core::cmp::Ordering::Greater) {
        return None;
    }
    if area2 < 0.0 {
        v.reverse();
    }
    Some(v)
}

/// The curve of a polygonal core dilated by `radius`: on the stack when it fits.
fn polygon_curve<'a>(verts: &[Vector], radius: f64, slot: &'a mut Option<InlinePolygon>) -> Option<CurveOf<'a>> {
    // A negative or non-finite radius is not a shape (parry's guards refuse it).
    if verts.len() < 2 || !verts.iter().all(|v| v.is_finite()) || !(radius.is_finite() && radius >= 0.0) {
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
            return ellipse_or_ball(s)
                .or_else(|| s.as_shape::<RoundedPolygon>().map(CurveOf::Rounded))
                .or_else(|| s.as_shape::<CapsuleEllipse>().map(CurveOf::Capsule))
                .or_else(|| s.as_shape::<CustomCurve>().map(CurveOf::Custom))
                .or_else(|| own_curve(s).map(CurveOf::Borrowed));
        }
        _ => {}
    }
    // A box with a half-extent that is not positive is not one (its vertices would turn clockwise).
    let box_ok = |c: &Cuboid| c.half_extents.x > 0.0 && c.half_extents.y > 0.0;
    if let Some(c) = s.as_shape::<Cuboid>() {
        box_ok(c).then(|| polygon_curve(&box_vertices(c), 0.0, slot)).flatten()
    } else if let Some(c) = s.as_shape::<RoundCuboid>() {
        let inner = &c.inner_shape;
        box_ok(inner)
            .then(|| polygon_curve(&box_vertices(inner), c.border_radius, slot))
            .flatten()
    } else if let Some(c) = s.as_shape::<Capsule>() {
        if (c.segment.b - c.segment.a).length() <= CAPSULE_AS_BALL * c.radius {
            return Some(CurveOf::Ball(BallCurve { radius: c.radius })).filter(|_| c.segment.a == Vector::ZERO);
        }
        polygon_curve(&[c.segment.a, c.segment.b], c.radius, slot)
    } else if let Some(sg) = s.as_shape::<Segment>() {
        if (sg.b - sg.a).length_squared() == 0.0 {
            return None;
        }
        polygon_curve(&[sg.a, sg.b], 0.0, slot)
    } else if let Some(t) = s.as_shape::<Triangle>() {
        let (v, n) = triangle_hull([t.a, t.b, t.c])?;
        polygon_curve(&v[..n], 0.0, slot)
    } else if let Some(t) = s.as_shape::<RoundTriangle>() {
        let t2 = &t.inner_shape;
        let (v, n) = triangle_hull([t2.a, t2.b, t2.c])?;
        polygon_curve(&v[..n], t.border_radius, slot)
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
pub(crate) fn curves_toi(
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

pub(crate) fn box_vertices(c: &Cuboid) -> [Vector; 4] {
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
    /// No strictly convex side (polygons, capsule-ellipses, curves with faces), in the caller's
    /// order: the gap tracker (both sides have a [`CurveOf::gap_side`]). [`route`] gives it for
    /// pairs with one of this crate's shapes, [`route_cast`] for parry's own pairs too.
    Gap { c1: CurveOf<'a>, c2: CurveOf<'a> },
    /// Composite on one side: parry's helpers with this dispatcher.
    Composite,
    /// parry's default dispatcher; `ours` when one side is this crate's shape (the other side
    /// is not convertible, or a side with no strictly convex representation has no gap side).
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
pub(crate) fn half_space(s: &dyn Shape) -> Option<&HalfSpace> {
    (s.shape_type() == ShapeType::HalfSpace)
        .then(|| s.as_shape::<HalfSpace>())
        .flatten()
}

/// An [`Ellipse`] or a parry `Ball` of positive radius as a curve; `None` for any other shape.
#[inline]
pub(crate) fn ellipse_or_ball(s: &dyn Shape) -> Option<CurveOf<'_>> {
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
pub(crate) fn route_general<'a>(g1: &'a dyn Shape, g2: &'a dyn Shape, scratch: &'a mut RouteScratch) -> Route<'a> {
    route_for(g1, g2, scratch, false)
}

/// How a nonlinear cast of the pair is answered: as [`route`], and also every pair of convex
/// shapes the dispatcher can convert — parry's own pairs and this crate's — with polygon pairs
/// (no strictly convex side) as [`Route::Gap`] and half-spaces with the crate's exact cast.
pub(crate) fn route_cast<'a>(g1: &'a dyn Shape, g2: &'a dyn Shape, scratch: &'a mut RouteScratch) -> Route<'a> {
    if let (Some(c1), Some(c2)) = (ellipse_or_ball(g1), ellipse_or_ball(g2)) {
        if matches!(c1, CurveOf::Ellipse(_)) || matches!(c2, CurveOf::Ellipse(_)) {
            return Route::Curves { c1, c2, swapped: false };
        }
    }
    route_for(g1, g2, scratch, true)
}

/// [`route_general`], or [`route_cast`] when `cast`.
fn route_for<'a>(g1: &'a dyn Shape, g2: &'a dyn Shape, scratch: &'a mut RouteScratch, cast: bool) -> Route<'a> {
    let RouteScratch { first, second } = scratch;
    let ours = own_curve(g1).is_some() || own_curve(g2).is_some();
    if !ours && !cast {
        return Route::Parry { ours: false };
    }
    // A heightfield is no composite shape to parry, but the dispatcher's casts take one.
    let heightfield = |g: &dyn Shape| cast && g.shape_type() == ShapeType::HeightField;
    if g1.as_composite_shape().is_some() || g2.as_composite_shape().is_some() || heightfield(g1) || heightfield(g2) {
        return if ours { Route::Composite } else { Route::Parry { ours } };
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
            } else if c1.gap_side().is_some() && c2.gap_side().is_some() {
                Route::Gap { c1, c2 }
            } else {
                Route::Parry { ours }
            }
        }
        _ => Route::Parry { ours },
    }
}

/// Stationary distance of a routed pair, in the caller's order.
pub(crate) fn pair_distance(
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
#[cfg(test)]
mod tests {
    use super::*;
    use crate::dispatcher::inline_polygon;
    use crate::numerics::math::unit;
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
                    CurveOf::Inline(_) | CurveOf::Poly(_) | CurveOf::Rounded(_) => "polygon".to_string(),
                    CurveOf::Capsule(_) | CurveOf::Custom(_) => "curve".to_string(),
                    CurveOf::Borrowed(_) => "borrowed".to_string(),
                };
                format!("curves {} / {} swapped {swapped}", d(&c1), d(&c2))
            }
            Route::HalfSpace { .. } => "half-space".to_string(),
            Route::Gap { .. } => "gap".to_string(),
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
            // Flat: the segment from 0 to 2x.
            (&Triangle::new(Vector::ZERO, Vector::X, Vector::X * 2.0), true),
        ];
        for (k, (shape, inline)) in shapes.into_iter().enumerate() {
            match curve_of(shape, &mut None) {
                Some(CurveOf::Inline(_)) => assert!(inline, "shape {k}"),
                Some(CurveOf::Poly(_)) => assert!(!inline && k == 5, "shape {k}"),
                None => panic!("shape {k}: not converted"),
                Some(_) => panic!("shape {k}: not a polygon"),
            }
        }
        let flat = Triangle::new(Vector::ZERO, Vector::X, Vector::X * 2.0);
        let mut slot = None;
        let c = curve_of(&flat, &mut slot).expect("a segment");
        assert_eq!(c.get().support_point(Vector::X), Vector::X * 2.0);
        assert_eq!(c.get().support_point(-Vector::X), Vector::ZERO);
        // Three coinciding vertices are no shape.
        assert!(curve_of(&Triangle::new(Vector::X, Vector::X, Vector::X), &mut None).is_none());
        // A triangle 1e7 from the origin is a triangle, in either order, rounded or not.
        let far = Vector::new(1e7, -1e7);
        let (x, y) = (far + Vector::new(1.0, 0.0), far + Vector::new(0.0, 1.0));
        for t in [Triangle::new(far, x, y), Triangle::new(far, y, x)] {
            let mut slot = None;
            let c = curve_of(&t, &mut slot).expect("a triangle");
            assert_eq!(c.get().support_point(Vector::new(-1.0, -1.0)), far);
            assert_eq!(c.get().support_point(Vector::new(1.0, -0.1)), x);
            assert_eq!(c.get().support_point(Vector::new(-0.1, 1.0)), y);
            let round = RoundTriangle {
                inner_shape: t,
                border_radius: 0.25,
            };
            let mut slot = None;
            let c = curve_of(&round, &mut slot).expect("a rounded triangle");
            let p = c.get().support_point(Vector::new(0.0, -1.0));
            assert!((p.y - (far.y - 0.25)).abs() < 1e-6, "{p:?}");
        }
        // The triangle's curve is counter-clockwise: the support along +x is the vertex (1, 0).
        let t = Triangle::new(Vector::ZERO, Vector::new(0.0, 1.0), Vector::new(1.0, 0.0));
        let mut slot = None;
        let c = curve_of(&t, &mut slot).expect("a triangle");
        assert_eq!(c.get().support_point(Vector::X), Vector::X);
    }
}
