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
//! solid bodies) and shapes already in contact and approaching at the start, the nonlinear cast
//! reports a hit at `start_time + START_NUDGE·(end_time − start_time)` when the approach over the
//! window exceeds a quarter of the thinner shape's `ccd_thickness`, and no hit otherwise. rapier
//! discards hits at exactly the start time, so answering the start time (as
//! [`crate::time_of_impact`] does) would let a fast body in shallow contact pass through a thin
//! wall; a slow approach (resting, sliding) is left to the contact solver.

use crate::curve::ConvexCurve;
use crate::halfspace::{halfspace_distance, time_of_impact_halfspace};
use crate::math::{Pose, Real, Vector};
use crate::stationary::{stationary_distance, DistanceOptions, QueryError, StationaryDistance};
use crate::toi::{time_of_impact, TimeOfImpact, ToiOptions};
use crate::{BallCurve, CapsuleEllipse, CustomCurve, Ellipse, RoundedPolygon};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{
    self, ClosestPoints, Contact, DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit,
    ShapeDistance, ShapeIntersection, Unsupported,
};
use parry2d_f64::shape::{
    Ball, Capsule, ConvexPolygon, Cuboid, HalfSpace, RoundConvexPolygon, RoundCuboid, RoundTriangle, Segment, Shape,
    Triangle,
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

/// A shape seen as a convex curve: borrowed for this crate's shapes, built for parry's.
pub(crate) enum CurveOf<'a> {
    Borrowed(&'a dyn ConvexCurve),
    Ball(BallCurve),
    Poly(RoundedPolygon),
}

impl CurveOf<'_> {
    pub(crate) fn get(&self) -> &dyn ConvexCurve {
        match self {
            CurveOf::Borrowed(c) => *c,
            CurveOf::Ball(b) => b,
            CurveOf::Poly(p) => p,
        }
    }
}

/// This crate's own shapes.
pub(crate) fn own_curve(s: &dyn Shape) -> Option<&dyn ConvexCurve> {
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

fn ccw(mut v: Vec<Vector>) -> Option<Vec<Vector>> {
    let n = v.len();
    let mut area2 = 0.0;
    for i in 0..n {
        area2 += crate::math::cross(v[i], v[(i + 1) % n]);
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

/// Any shape this dispatcher can treat as a convex curve.
pub(crate) fn curve_of(s: &dyn Shape) -> Option<CurveOf<'_>> {
    if let Some(c) = own_curve(s) {
        return Some(CurveOf::Borrowed(c));
    }
    if let Some(b) = s.as_shape::<Ball>() {
        return (b.radius > 0.0).then_some(CurveOf::Ball(BallCurve { radius: b.radius }));
    }
    let (verts, radius): (Vec<Vector>, f64) = if let Some(c) = s.as_shape::<Cuboid>() {
        (box_vertices(c), 0.0)
    } else if let Some(c) = s.as_shape::<RoundCuboid>() {
        (box_vertices(&c.inner_shape), c.border_radius)
    } else if let Some(c) = s.as_shape::<Capsule>() {
        if (c.segment.b - c.segment.a).length() <= 1e-12 * c.radius {
            return Some(CurveOf::Ball(BallCurve { radius: c.radius })).filter(|_| c.segment.a == Vector::ZERO);
        }
        return Some(CurveOf::Poly(RoundedPolygon::from_core_unchecked(
            vec![c.segment.a, c.segment.b],
            c.radius,
        )));
    } else if let Some(sg) = s.as_shape::<Segment>() {
        if (sg.b - sg.a).length_squared() == 0.0 {
            return None;
        }
        return Some(CurveOf::Poly(RoundedPolygon::from_core_unchecked(
            vec![sg.a, sg.b],
            0.0,
        )));
    } else if let Some(t) = s.as_shape::<Triangle>() {
        (ccw(vec![t.a, t.b, t.c])?, 0.0)
    } else if let Some(t) = s.as_shape::<RoundTriangle>() {
        let t2 = &t.inner_shape;
        (ccw(vec![t2.a, t2.b, t2.c])?, t.border_radius)
    } else if let Some(p) = s.as_shape::<ConvexPolygon>() {
        (p.points().to_vec(), 0.0)
    } else if let Some(p) = s.as_shape::<RoundConvexPolygon>() {
        (p.inner_shape.points().to_vec(), p.border_radius)
    } else {
        return None;
    };
    if verts.len() < 2 || !verts.iter().all(|v| v.is_finite()) || !radius.is_finite() {
        return None;
    }
    Some(CurveOf::Poly(RoundedPolygon::from_core_unchecked(verts, radius)))
}

fn box_vertices(c: &Cuboid) -> Vec<Vector> {
    let h = c.half_extents;
    vec![
        Vector::new(-h.x, -h.y),
        Vector::new(h.x, -h.y),
        Vector::new(h.x, h.y),
        Vector::new(-h.x, h.y),
    ]
}

/// How a pair is answered.
enum Route<'a> {
    /// Our algorithm; `swapped` when shape 1 plays object2.
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
    /// parry's default dispatcher.
    Parry,
}

fn route<'a>(g1: &'a dyn Shape, g2: &'a dyn Shape) -> Route<'a> {
    let ours = own_curve(g1).is_some() || own_curve(g2).is_some();
    if !ours {
        return Route::Parry;
    }
    if g1.as_composite_shape().is_some() || g2.as_composite_shape().is_some() {
        return Route::Composite;
    }
    if let Some(hs) = g2.as_shape::<HalfSpace>() {
        return match curve_of(g1) {
            Some(curve) => Route::HalfSpace {
                curve,
                hs,
                curve_first: true,
            },
            None => Route::Parry,
        };
    }
    if let Some(hs) = g1.as_shape::<HalfSpace>() {
        return match curve_of(g2) {
            Some(curve) => Route::HalfSpace {
                curve,
                hs,
                curve_first: false,
            },
            None => Route::Parry,
        };
    }
    match (curve_of(g1), curve_of(g2)) {
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
                Route::Parry
            }
        }
        _ => Route::Parry,
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
        let r = stationary_distance(c1.get(), c2.get(), &pos12.inverse(), opts)?;
        Ok(StationaryDistance {
            point1: r.point2,
            point2: r.point1,
            normal1: r.normal2,
            normal2: r.normal1,
            ..r
        })
    } else {
        stationary_distance(c1.get(), c2.get(), pos12, opts)
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
        match route(g1, g2) {
            Route::Curves { c1, c2, swapped } => Some(pair_distance(&c1, &c2, swapped, pos12, &self.distance_options)),
            Route::HalfSpace { curve, hs, curve_first } => {
                Some(halfspace_distance(curve.get(), hs, pos12, curve_first))
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

/// Fraction of the window at which an approaching start contact is reported to rapier (module
/// docs): far below any motion rapier resolves, yet strictly after the start time.
pub const START_NUDGE: f64 = 1e-9;

/// The rapier rule for an approaching contact at the start (module docs).
fn start_contact_rule(r: TimeOfImpact, stop: bool, t0: Real, t1: Real, thickness: Real) -> Option<TimeOfImpact> {
    if stop || r.status != crate::ToiStatus::PenetratingAtStart {
        return Some(r);
    }
    let travel = -r.distance_rate * (t1 - t0);
    if travel > 0.25 * thickness {
        Some(TimeOfImpact {
            time: t0 + START_NUDGE * (t1 - t0),
            ..r
        })
    } else {
        None
    }
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
        match route(g1, g2) {
            Route::Parry => DefaultQueryDispatcher.intersection_test(pos12, g1, g2),
            Route::Composite => composite_intersection(self, pos12, g1, g2),
            _ => {
                if Self::far_apart(pos12, g1, g2, 0.0) {
                    return Ok(ShapeIntersection::new(false));
                }
                match self.signed_distance(pos12, g1, g2) {
                    Some(Ok(d)) => Ok(ShapeIntersection::new(d.distance <= 0.0)),
                    _ => Err(Unsupported),
                }
            }
        }
    }

    fn distance(&self, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> Result<ShapeDistance, Unsupported> {
        match route(g1, g2) {
            Route::Parry => DefaultQueryDispatcher.distance(pos12, g1, g2),
            Route::Composite => composite_distance(self, pos12, g1, g2),
            _ => match self.signed_distance(pos12, g1, g2) {
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
        match route(g1, g2) {
            Route::Parry => DefaultQueryDispatcher.contact(pos12, g1, g2, prediction),
            Route::Composite => composite_contact(self, pos12, g1, g2, prediction),
            _ => {
                if Self::far_apart(pos12, g1, g2, prediction) {
                    return Ok(None);
                }
                match self.signed_distance(pos12, g1, g2) {
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
        match route(g1, g2) {
            Route::Parry => DefaultQueryDispatcher.closest_points(pos12, g1, g2, max_dist),
            Route::Composite => composite_closest_points(self, pos12, g1, g2, max_dist),
            _ => {
                if Self::far_apart(pos12, g1, g2, max_dist) {
                    return Ok(ClosestPoints::Disjoint);
                }
                match self.signed_distance(pos12, g1, g2) {
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
        match route(g1, g2) {
            Route::Curves { .. } => {
                let m1 = NonlinearRigidMotion::identity();
                let m2 = NonlinearRigidMotion::new(*pos12, Vector::ZERO, local_vel12, 0.0);
                let opts = ToiOptions {
                    target_distance: options.target_distance,
                    stop_at_penetration: options.stop_at_penetration,
                    ..self.toi_options
                };
                self.toi(&m1, g1, &m2, g2, 0.0, options.max_time_of_impact, &opts)
            }
            Route::Composite => composite_cast(self, pos12, local_vel12, g1, g2, options),
            // Linear casts against half-spaces and polygonal pairs are exact in parry.
            _ => DefaultQueryDispatcher.cast_shapes(pos12, local_vel12, g1, g2, options),
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
        match route(g1, g2) {
            Route::Curves { .. } => {
                let (Some(c1), Some(c2)) = (curve_of(g1), curve_of(g2)) else {
                    return Err(Unsupported);
                };
                let thickness = g1.ccd_thickness().min(g2.ccd_thickness());
                let r = time_of_impact(c1.get(), motion1, c2.get(), motion2, start_time, end_time, &opts);
                toi_to_parry(r.map(|r| start_contact_rule(r, stop_at_penetration, start_time, end_time, thickness)))
            }
            Route::HalfSpace { curve, hs, curve_first } => {
                let r = if curve_first {
                    time_of_impact_halfspace(curve.get(), motion1, hs, motion2, start_time, end_time, &opts)
                } else {
                    time_of_impact_halfspace(curve.get(), motion2, hs, motion1, start_time, end_time, &opts).map(|r| {
                        TimeOfImpact {
                            point1: r.point2,
                            point2: r.point1,
                            normal1: r.normal2,
                            normal2: r.normal1,
                            ..r
                        }
                    })
                };
                let thickness = if curve_first {
                    g1.ccd_thickness()
                } else {
                    g2.ccd_thickness()
                };
                toi_to_parry(r.map(|r| start_contact_rule(r, stop_at_penetration, start_time, end_time, thickness)))
            }
            Route::Composite => composite_cast_nonlinear(
                self,
                motion1,
                g1,
                motion2,
                g2,
                start_time,
                end_time,
                stop_at_penetration,
            ),
            Route::Parry => DefaultQueryDispatcher.cast_shapes_nonlinear(
                motion1,
                g1,
                motion2,
                g2,
                start_time,
                end_time,
                stop_at_penetration,
            ),
        }
    }
}

impl SmoothDispatcher {
    #[allow(clippy::too_many_arguments)]
    fn toi(
        &self,
        m1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        m2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        t0: Real,
        t1: Real,
        opts: &ToiOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let (Some(c1), Some(c2)) = (curve_of(g1), curve_of(g2)) else {
            return Err(Unsupported);
        };
        toi_to_parry(time_of_impact(c1.get(), m1, c2.get(), m2, t0, t1, opts).map(Some))
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
