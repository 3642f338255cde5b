//! [`SmoothDispatcher`] as parry's `QueryDispatcher`: each query routed ([`route`]) to this
//! crate's algorithms, to a half-space query, to parry's composite helpers, or to parry.

use super::composite::{
    composite_cast, composite_cast_nonlinear, composite_closest_points, composite_contact, composite_distance,
    composite_intersection,
};
use super::input_guard;
use super::parry_fallback::{pair_size, parry_cast_nonlinear, parry_contact};
use super::route::{curves_toi, pair_distance, route, Route, RouteScratch};
use super::start_contact::{parry_nonlinear_without_stop, pos12_at, rapier_rule, StartContact, StartContactPolicy};
use super::SmoothDispatcher;
use crate::error::QueryError;
use crate::numerics::math::{Pose, Real, Vector};
use crate::query::halfspace::{halfspace_distance, time_of_impact_halfspace};
use crate::query::toi::{bounding_circles_part, TimeOfImpact, ToiOptions};
use parry2d_f64::query::details::ShapeCastOptions;
use parry2d_f64::query::{
    ClosestPoints, Contact, DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit, ShapeDistance,
    ShapeIntersection, Unsupported,
};
use parry2d_f64::shape::Shape;

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
        match route(g1, g2, &mut RouteScratch::default()) {
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
        if prediction.is_nan() || prediction < 0.0 {
            // parry's contract (its composite helpers assert it): no negative or NaN margin.
            return Err(Unsupported);
        }
        match route(g1, g2, &mut RouteScratch::default()) {
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
        if max_dist.is_nan() || max_dist < 0.0 {
            // parry's contract (it asserts it for balls and half-spaces): no negative or NaN margin.
            return Err(Unsupported);
        }
        match route(g1, g2, &mut RouteScratch::default()) {
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
            Route::Composite => input_guard::parry(pos12, g1, g2, 0.0, || {
                composite_cast(self, pos12, local_vel12, g1, g2, options)
            }),
            // Linear casts against half-spaces and polygonal pairs are exact in parry.
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
                if stop_at_penetration || self.start_contact == StartContactPolicy::Plain {
                    return toi_to_parry(r.map(Some));
                }
                let dopts = &self.distance_options;
                let at = |t: Real| pair_distance(&c1, &c2, swapped, &pos12_at(motion1, motion2, t), dopts).ok();
                let gap = StartContactPolicy::START_CONTACT_GAP * pair_size(g1, g2);
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
                if stop_at_penetration || self.start_contact == StartContactPolicy::Plain {
                    return toi_to_parry(r.map(Some));
                }
                let at =
                    |t: Real| halfspace_distance(curve.get(), hs, &pos12_at(motion1, motion2, t), curve_first).ok();
                let gap = StartContactPolicy::START_CONTACT_GAP * pair_size(g1, g2);
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
            Route::Composite => match input_guard::cast_window_ok(motion1, g1, motion2, g2, start_time, end_time) {
                Ok(true) => input_guard::finite(composite_cast_nonlinear(
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
            Route::Parry { ours: true }
                if !stop_at_penetration && self.start_contact == StartContactPolicy::RapierAllowance =>
            {
                input_guard::finite(parry_nonlinear_without_stop(
                    motion1, g1, motion2, g2, start_time, end_time,
                ))
            }
            Route::Parry { .. } => {
                parry_cast_nonlinear(motion1, g1, motion2, g2, start_time, end_time, stop_at_penetration)
            }
        }
    }
}
