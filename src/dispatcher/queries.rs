//! [`SmoothDispatcher`] as parry's `QueryDispatcher`: each query routed ([`route`]) to this
//! crate's algorithms, to a half-space query, to parry's composite helpers, or to parry.

use super::cast::{toi_to_parry, NonlinearCast};
use super::composite::{
    composite_cast, composite_closest_points, composite_contact, composite_distance, composite_intersection,
};
use super::input_guard;
use super::parry_fallback::parry_contact;
use super::route::{curves_toi, own_curve, route, CurveOf, Route, RouteScratch};
use super::support_shape::exact_contact;
use super::SmoothDispatcher;
use crate::curve::ConvexCurve;
use crate::numerics::math::{Pose, Real, Vector};
use crate::query::gap::{gap_distance, gap_time_of_impact};
use crate::query::toi::{bounding_circles_part, ToiOptions};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{
    ClosestPoints, Contact, DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit, ShapeDistance,
    ShapeIntersection, Unsupported,
};
use parry2d_f64::shape::Shape;

/// The exact signed distance of a pair of this crate's shapes with no strictly convex side:
/// (distance, witness on shape 1 and on shape 2 in their frames, shape 1's normal and shape 2's).
type GapDistance = (Real, Vector, Vector, Vector, Vector);

/// The exact signed distance at `pos12` of a pair the gap tracker takes ([`Route::Gap`]); `None`
/// for non-finite input or answer.
fn gap_pair_distance(c1: &CurveOf, c2: &CurveOf, pos12: &Pose) -> Option<GapDistance> {
    let (a, b) = (c1.gap_side()?, c2.gap_side()?);
    if !pos12.is_finite() {
        return None;
    }
    let (d, p1, p2, n1) = gap_distance(a, b, pos12)?;
    let n2 = pos12.rotation.inverse() * -n1;
    (d.is_finite() && p1.is_finite() && p2.is_finite() && n2.is_finite()).then_some((d, p1, p2, n1, n2))
}

/// A time after which two shapes, shape 2 translating from `pos12` at `vel12` in shape 1's
/// frame, are never within `delta` of each other: twice the time for the centres' distance to
/// grow past |pos12| plus both bounding radii and δ (at that time it is at least |vel12|·t − |pos12|).
/// `None` when it is not a finite positive number (no motion, or one too slow to measure).
fn linear_horizon(a: &dyn ConvexCurve, b: &dyn ConvexCurve, pos12: &Pose, vel12: Vector, delta: Real) -> Option<Real> {
    let reach = pos12.translation.length() + a.bounding_radius() + b.bounding_radius() + delta.max(0.0);
    let h = 2.0 * reach / vel12.length();
    (h.is_finite() && h > 0.0).then_some(h)
}

/// The window's end `t1` cut at the horizon `h` when there is one; a NaN end stays NaN (the
/// tracker refuses it, as it refuses any non-finite input).
fn bounded(t1: Real, h: Option<Real>) -> Real {
    match h {
        Some(h) if !t1.is_nan() => t1.min(h),
        _ => t1,
    }
}

impl QueryDispatcher for SmoothDispatcher {
    fn intersection_test(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeIntersection, Unsupported> {
        if !pos12.is_finite() {
            // Before the bounding-circle rejection, which takes an infinite distance as apart.
            return Err(Unsupported);
        }
        match route(g1, g2, &mut RouteScratch::default()) {
            // The gap tracker's exact distance for pairs with no strictly convex side.
            Route::Gap { c1, c2 } => match gap_pair_distance(&c1, &c2, pos12) {
                Some(d) => Ok(ShapeIntersection::new(d.0 <= 0.0)),
                None => Err(Unsupported),
            },
            Route::Parry { .. } => input_guard::parry(pos12, g1, g2, 0.0, || {
                DefaultQueryDispatcher.intersection_test(pos12, g1, g2)
            }),
            Route::Composite => input_guard::parry(pos12, g1, g2, 0.0, || composite_intersection(self, pos12, g1, g2)),
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
        if !pos12.is_finite() {
            return Err(Unsupported);
        }
        match route(g1, g2, &mut RouteScratch::default()) {
            // The gap tracker's exact distance for pairs with no strictly convex side.
            Route::Gap { c1, c2 } => match gap_pair_distance(&c1, &c2, pos12) {
                Some(d) => Ok(ShapeDistance::new(d.0.max(0.0))),
                None => Err(Unsupported),
            },
            Route::Parry { .. } => {
                input_guard::parry(pos12, g1, g2, 0.0, || DefaultQueryDispatcher.distance(pos12, g1, g2))
            }
            Route::Composite => input_guard::parry(pos12, g1, g2, 0.0, || composite_distance(self, pos12, g1, g2)),
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
        if prediction.is_nan() || prediction < 0.0 || !pos12.is_finite() {
            // parry's contract (its composite helpers assert it): no negative or NaN margin; and
            // no non-finite pose (the bounding-circle rejection takes ±∞ as apart).
            return Err(Unsupported);
        }
        // The exact contact query where it applies (this crate's shapes with polygons, discs,
        // ellipses and capsule-ellipses): the deepest point of its manifold.
        if own_curve(g1).is_some() || own_curve(g2).is_some() {
            if Self::far_apart(pos12, g1, g2, prediction) {
                return Ok(None);
            }
            if let Some(c) = exact_contact(pos12, g1, g2, None) {
                let p = c.points[0];
                let (p2, n2) = (
                    pos12.inverse_transform_point(p.point2),
                    pos12.inverse_transform_vector(-c.normal),
                );
                if p2.is_finite() && n2.is_finite() {
                    return Ok((p.dist <= prediction).then(|| Contact::new(p.point1, p2, c.normal, n2, p.dist)));
                }
            }
        }
        match route(g1, g2, &mut RouteScratch::default()) {
            // The gap tracker's exact distance for pairs with no strictly convex side.
            Route::Gap { c1, c2 } => match gap_pair_distance(&c1, &c2, pos12) {
                Some((d, p1, p2, n1, n2)) if d <= prediction => Ok(Some(Contact::new(p1, p2, n1, n2, d))),
                Some(_) => Ok(None),
                None => Err(Unsupported),
            },
            // parry's, robust to nearly touching shapes (`parry_contact`).
            Route::Parry { ours: true } => {
                input_guard::parry(pos12, g1, g2, prediction, || parry_contact(pos12, g1, g2, prediction))
            }
            Route::Parry { ours: false } => input_guard::parry(pos12, g1, g2, prediction, || {
                DefaultQueryDispatcher.contact(pos12, g1, g2, prediction)
            }),
            Route::Composite => input_guard::parry(pos12, g1, g2, prediction, || {
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
        if max_dist.is_nan() || max_dist < 0.0 || !pos12.is_finite() {
            // parry's contract (it asserts it for balls and half-spaces): no negative or NaN
            // margin; and no non-finite pose (the bounding-circle rejection takes ±∞ as apart).
            return Err(Unsupported);
        }
        match route(g1, g2, &mut RouteScratch::default()) {
            // The gap tracker's exact distance for pairs with no strictly convex side.
            Route::Gap { c1, c2 } => match gap_pair_distance(&c1, &c2, pos12) {
                Some((d, ..)) if d <= 0.0 => Ok(ClosestPoints::Intersecting),
                Some((d, p1, p2, ..)) if d <= max_dist => Ok(ClosestPoints::WithinMargin(p1, p2)),
                Some(_) => Ok(ClosestPoints::Disjoint),
                None => Err(Unsupported),
            },
            Route::Parry { .. } => input_guard::parry(pos12, g1, g2, max_dist, || {
                DefaultQueryDispatcher.closest_points(pos12, g1, g2, max_dist)
            }),
            Route::Composite => input_guard::parry(pos12, g1, g2, max_dist, || {
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
        // Shape 1 at rest at the origin, shape 2 translating from `pos12`: the linear cast as a
        // time of impact, with the caller's target distance and penetration rule.
        let m1 = NonlinearRigidMotion::identity();
        let m2 = NonlinearRigidMotion::new(*pos12, Vector::ZERO, local_vel12, 0.0);
        let opts = ToiOptions {
            target_distance: options.target_distance,
            stop_at_penetration: options.stop_at_penetration,
            ..self.toi_options
        };
        let (t1, delta) = (options.max_time_of_impact, options.target_distance);
        match route(g1, g2, &mut RouteScratch::default()) {
            Route::Curves { c1, c2, swapped } => {
                // time_of_impact takes the shapes in the caller's order (it swaps roles itself).
                let (a, b) = if swapped { (&c2, &c1) } else { (&c1, &c2) };
                // An infinite window (parry takes one) ends where the bounding circles are past
                // each other; a finite one is the caller's.
                let t1 = if t1 == Real::INFINITY {
                    bounded(t1, linear_horizon(a.get(), b.get(), pos12, local_vel12, delta))
                } else {
                    t1
                };
                if bounding_circles_part(a.get(), &m1, b.get(), &m2, 0.0, t1, delta) {
                    return Ok(None);
                }
                let r = curves_toi(a, &m1, b, &m2, 0.0, t1, &opts);
                toi_to_parry(r.map(Some))
            }
            // No strictly convex side (a rounded polygon or a capsule-ellipse against a box, a
            // segment, a polygon…): the gap tracker, exact as the curves' tracker is. parry's
            // linear cast of such a pair (GJK on the support maps) stops short by up to about
            // 1e-8 of the size: a character controller sliding a rounded box over the ground
            // ended its casts 3e-8 m off its offset.
            Route::Gap { c1, c2 } => match (c1.gap_side(), c2.gap_side()) {
                (Some(p1), Some(p2)) => {
                    if bounding_circles_part(c1.get(), &m1, c2.get(), &m2, 0.0, t1, delta) {
                        return Ok(None);
                    }
                    // parry's default window is `Real::MAX`, which the gap tracker cannot step
                    // through: the window ends where the bounding circles are past each other.
                    let t1 = bounded(t1, linear_horizon(c1.get(), c2.get(), pos12, local_vel12, delta));
                    toi_to_parry(gap_time_of_impact(p1, &m1, p2, &m2, 0.0, t1, &opts).map(Some))
                }
                _ => input_guard::parry(pos12, g1, g2, 0.0, || {
                    DefaultQueryDispatcher.cast_shapes(pos12, local_vel12, g1, g2, options)
                }),
            },
            Route::Composite => input_guard::parry(pos12, g1, g2, 0.0, || {
                composite_cast(self, pos12, local_vel12, g1, g2, options)
            }),
            // Linear casts against half-spaces (a support point along the plane's normal) are
            // exact in parry.
            _ => input_guard::parry(pos12, g1, g2, 0.0, || {
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
        let mut cast = NonlinearCast::new(motion1, g1, motion2, g2, (start_time, end_time), stop_at_penetration);
        cast.spin_at_start = super::rapier_rule::spin_at_start(self.cast_policy, motion1, motion2);
        self.nonlinear_cast(&cast)
    }
}
