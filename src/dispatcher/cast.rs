//! `SmoothDispatcher::cast_shapes_nonlinear`: every pair of convex shapes the dispatcher can
//! convert gets the crate's exact time of impact ([`route_cast`]) — the φ–t tracker when one side
//! is strictly convex, the gap tracker otherwise, the half-space cast — with the
//! [`StartContactPolicy`] applied for `stop_at_penetration = false`; composites are decomposed
//! with this dispatcher inside, and the shapes it cannot convert go to parry.

use super::composite::composite_cast_nonlinear;
use super::input_guard;
use super::parry_fallback::{pair_size, parry_cast_nonlinear};
use super::route::{curves_toi, pair_distance, route_cast, CurveOf, Route, RouteScratch};
use super::start_contact::{parry_nonlinear_without_stop, pos12_at, rapier_rule, StartContact, StartContactPolicy};
use super::support_shape::exact_contact;
use super::SmoothDispatcher;
use crate::error::QueryError;
use crate::numerics::math::Real;
use crate::query::gap::{gap_distance, gap_time_of_impact};
use crate::query::halfspace::{halfspace_distance, time_of_impact_halfspace};
use crate::query::toi::{bounding_circles_part, TimeOfImpact, ToiOptions, ToiStatus};
use parry2d_f64::query::{NonlinearRigidMotion, ShapeCastHit, Unsupported};
use parry2d_f64::shape::{HalfSpace, Shape};

/// The arguments of one nonlinear cast.
pub(crate) struct NonlinearCast<'a> {
    pub m1: &'a NonlinearRigidMotion,
    pub g1: &'a dyn Shape,
    pub m2: &'a NonlinearRigidMotion,
    pub g2: &'a dyn Shape,
    pub t0: Real,
    pub t1: Real,
    pub stop: bool,
}

/// parry's hit for this crate's answer.
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

/// parry's answer for this crate's result (a reversed window: no hit; other errors:
/// `Unsupported`).
pub(crate) fn toi_to_parry(r: Result<Option<TimeOfImpact>, QueryError>) -> Result<Option<ShapeCastHit>, Unsupported> {
    match r {
        Ok(r) => Ok(r.as_ref().and_then(hit_from)),
        Err(QueryError::EmptyWindow) => Ok(None),
        Err(_) => Err(Unsupported),
    }
}

/// The time of impact of the parry shape `shape1` moving by `motion1` and `shape2` moving by
/// `motion2` in `[start_time, end_time]`, for every pair of convex shapes the crate can take —
/// its own shapes and parry's `Ball`, `Cuboid`, `Capsule`, `Segment`, `Triangle`,
/// `ConvexPolygon` and their round versions, strictly convex or not — and a half-space: the
/// φ–t tracker of [`crate::time_of_impact`] when one side is strictly convex, the gap tracker
/// when neither is (two polygons, a capsule-ellipse against a box, …; docs/theory.md), the
/// half-space cast. The semantics, statuses and cost counters are those of
/// [`crate::time_of_impact`] (no rapier rule: that is [`SmoothDispatcher`]'s
/// `cast_shapes_nonlinear`); the result is in the caller's order, each witness in its shape's
/// frame.
///
/// ```
/// use parry2d_f64::math::{Pose, Vector};
/// use parry2d_f64::query::NonlinearRigidMotion;
/// use parry2d_f64::shape::Cuboid;
/// use smooth_ccd2d::{shape_time_of_impact, RoundedPolygon, ToiOptions, ToiStatus};
///
/// // A rounded heptagon spinning at 30 rad/s flying at a box: neither side is strictly convex.
/// let hept = RoundedPolygon::regular(7, 0.5, 0.05);
/// let wall = Cuboid::new(Vector::new(0.05, 2.0));
/// let m1 = NonlinearRigidMotion::new(Pose::translation(-2.0, 0.0), Vector::ZERO, Vector::new(10.0, 0.0), 30.0);
/// let m2 = NonlinearRigidMotion::identity();
/// let r = shape_time_of_impact(&hept, &m1, &wall, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
/// assert_eq!(r.status, ToiStatus::Hit);
/// assert!(r.time > 0.13 && r.time < 0.15);
/// ```
///
/// # Errors
/// [`QueryError::UnsupportedShape`] for a shape it cannot take (composites, other custom
/// shapes, two half-spaces, a parry box whose half-extents are not both positive);
/// otherwise as [`crate::time_of_impact`]: [`QueryError::NonFinite`] for a non-finite motion,
/// time or option, [`QueryError::EmptyWindow`] for a reversed window,
/// [`QueryError::Degenerate`] where finite but absurd input overflows (never a NaN answer;
/// `tests/shape_time_of_impact.rs`).
pub fn shape_time_of_impact(
    shape1: &dyn Shape,
    motion1: &NonlinearRigidMotion,
    shape2: &dyn Shape,
    motion2: &NonlinearRigidMotion,
    start_time: Real,
    end_time: Real,
    options: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    let (m1, m2, t0, t1) = (motion1, motion2, start_time, end_time);
    match route_cast(shape1, shape2, &mut RouteScratch::default()) {
        Route::Curves { c1, c2, swapped } => {
            let (a, b) = if swapped { (&c2, &c1) } else { (&c1, &c2) };
            curves_toi(a, m1, b, m2, t0, t1, options)
        }
        Route::Gap { c1, c2 } => match (c1.gap_side(), c2.gap_side()) {
            (Some(p1), Some(p2)) => gap_time_of_impact(p1, m1, p2, m2, t0, t1, options),
            _ => Err(QueryError::UnsupportedShape),
        },
        Route::HalfSpace {
            curve,
            hs,
            curve_first: true,
        } => time_of_impact_halfspace(curve.get(), m1, hs, m2, t0, t1, options),
        Route::HalfSpace { curve, hs, .. } => {
            time_of_impact_halfspace(curve.get(), m2, hs, m1, t0, t1, options).map(TimeOfImpact::swapped)
        }
        Route::Composite | Route::Parry { .. } => Err(QueryError::UnsupportedShape),
    }
}

impl SmoothDispatcher {
    /// The nonlinear cast (module docs).
    pub(crate) fn nonlinear_cast(&self, c: &NonlinearCast) -> Result<Option<ShapeCastHit>, Unsupported> {
        let opts = ToiOptions {
            stop_at_penetration: c.stop,
            ..self.toi_options
        };
        match route_cast(c.g1, c.g2, &mut RouteScratch::default()) {
            Route::Curves { c1, c2, swapped } => self.cast_curves(c, &c1, &c2, swapped, &opts),
            Route::Gap { c1, c2 } => self.cast_gap(c, &c1, &c2, &opts),
            Route::HalfSpace { curve, hs, curve_first } => self.cast_halfspace(c, &curve, hs, curve_first, &opts),
            // parry's composite helper casts bounding balls itself: the same guards as parry's casts.
            Route::Composite => match input_guard::cast_window_ok(c.m1, c.g1, c.m2, c.g2, c.t0, c.t1) {
                Ok(true) => input_guard::finite(composite_cast_nonlinear(
                    self, c.m1, c.g1, c.m2, c.g2, c.t0, c.t1, c.stop,
                )),
                Ok(false) => Ok(None),
                Err(e) => Err(e),
            },
            Route::Parry { ours: true } if !c.stop && self.start_contact == StartContactPolicy::RapierAllowance => {
                input_guard::finite(parry_nonlinear_without_stop(c.m1, c.g1, c.m2, c.g2, c.t0, c.t1))
            }
            Route::Parry { .. } => parry_cast_nonlinear(c.m1, c.g1, c.m2, c.g2, c.t0, c.t1, c.stop),
        }
    }

    /// Whether the answer `r` goes out as it is (`stop_at_penetration`, or the plain policy)
    /// rather than through the rapier rule.
    fn plain(&self, c: &NonlinearCast) -> bool {
        c.stop || self.start_contact == StartContactPolicy::Plain
    }

    /// A pair with a strictly convex side: the φ–t tracker.
    fn cast_curves(
        &self,
        c: &NonlinearCast,
        c1: &CurveOf,
        c2: &CurveOf,
        swapped: bool,
        opts: &ToiOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let (a, b) = if swapped { (c2, c1) } else { (c1, c2) };
        if !self.plain(c) {
            if let Some(r) = self.rapier_cast(c, a, b, opts, |o| curves_toi(a, c.m1, b, c.m2, c.t0, c.t1, o)) {
                return r;
            }
        }
        // The specification's inexpensive test first: circles that never meet, no impact
        // (and no contact at the start for the rapier rule below).
        if bounding_circles_part(a.get(), c.m1, b.get(), c.m2, c.t0, c.t1, opts.target_distance) {
            return Ok(None);
        }
        let thickness = c.g1.ccd_thickness().min(c.g2.ccd_thickness());
        let r = curves_toi(a, c.m1, b, c.m2, c.t0, c.t1, opts);
        let dopts = &self.distance_options;
        let at = |t: Real| pair_distance(c1, c2, swapped, &pos12_at(c.m1, c.m2, t), dopts).ok();
        self.answer(
            c,
            r,
            thickness,
            |gap| {
                let pos12 = pos12_at(c.m1, c.m2, c.t0);
                if Self::far_apart(&pos12, c.g1, c.g2, gap) {
                    return None;
                }
                pair_distance(c1, c2, swapped, &pos12, dopts)
                    .ok()
                    .map(|d| StartContact::from_distance(&d))
            },
            |t| at(t).map(|d| d.distance),
        )
    }

    /// No strictly convex side: the gap tracker.
    fn cast_gap(
        &self,
        c: &NonlinearCast,
        c1: &CurveOf,
        c2: &CurveOf,
        opts: &ToiOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let (Some(p1), Some(p2)) = (c1.gap_side(), c2.gap_side()) else {
            return Err(Unsupported);
        };
        if !self.plain(c) {
            if let Some(r) = self.rapier_cast(c, c1, c2, opts, |o| gap_time_of_impact(p1, c.m1, p2, c.m2, c.t0, c.t1, o)) {
                return r;
            }
        }
        if bounding_circles_part(c1.get(), c.m1, c2.get(), c.m2, c.t0, c.t1, opts.target_distance) {
            return Ok(None);
        }
        let r = gap_time_of_impact(p1, c.m1, p2, c.m2, c.t0, c.t1, opts);
        let thickness = c.g1.ccd_thickness().min(c.g2.ccd_thickness());
        let at = |t: Real| gap_distance(p1, p2, &pos12_at(c.m1, c.m2, t));
        self.answer(
            c,
            r,
            thickness,
            |_| {
                at(c.t0).map(|(distance, point1, point2, normal1)| StartContact {
                    distance,
                    point1,
                    point2,
                    normal1,
                })
            },
            |t| at(t).map(|d| d.0),
        )
    }

    /// The rapier rule (experimental form): separated at the start, the exact time of impact
    /// `full(opts)`; in contact, the first time the signed distance drops below
    /// min(−A, d₀ − A/10), A a quarter of the thinner positive `ccd_thickness`, by the gap
    /// tracker at that level. `None`: not answerable this way (the caller goes on).
    fn rapier_cast(
        &self,
        c: &NonlinearCast,
        c1: &CurveOf,
        c2: &CurveOf,
        opts: &ToiOptions,
        full: impl Fn(&ToiOptions) -> Result<TimeOfImpact, QueryError>,
    ) -> Option<Result<Option<ShapeCastHit>, Unsupported>> {
        if std::env::var("NO_RULE").is_ok() {
            return None;
        }
        if !crate::dispatcher::start_contact::is_window(c.t0, c.t1) {
            return None;
        }
        if bounding_circles_part(c1.get(), c.m1, c2.get(), c.m2, c.t0, c.t1, opts.target_distance) {
            return Some(Ok(None));
        }
        let pos12 = pos12_at(c.m1, c.m2, c.t0);
        let gap = StartContactPolicy::START_CONTACT_GAP * pair_size(c.g1, c.g2);
        let d0 = exact_contact(&pos12, c.g1, c.g2, None).map(|k| k.dist)?;
        let nlerp = ToiOptions {
            path: if c.m2.angvel == 0.0 || c.m1.angvel == 0.0 {
                crate::MotionPath::Nlerp
            } else {
                crate::MotionPath::ConstantSpin
            },
            ..*opts
        };
        if d0 > gap {
            return Some(toi_to_parry(full(&nlerp).map(Some)));
        }
        // The fast body: the one that moves (rapier's is shape 1, but parry's composite helpers
        // hand a composite target's parts over as shape 1).
        let still = |m: &NonlinearRigidMotion| m.linvel == parry2d_f64::math::Vector::ZERO && m.angvel == 0.0;
        let (fast_g, fast_m, other_g, other_m) = if still(c.m1) && !still(c.m2) {
            (c.g2, c.m2, c.g1, c.m1)
        } else {
            (c.g1, c.m1, c.g2, c.m2)
        };
        // The inradius of the fast body about its rotation centre.
        let centre = fast_m.local_center;
        let proj = fast_g.project_local_point(centre, false);
        let r_in = if proj.is_inside { (proj.point - centre).length() } else { 0.0 };
        let r_in = if r_in > 0.0 { r_in } else { fast_g.ccd_thickness().max(gap) };
        let approaching = || {
            let Some(k) = exact_contact(&pos12, c.g1, c.g2, None) else {
                return false;
            };
            let span = c.t1 - c.t0;
            let eff = |m: &NonlinearRigidMotion| {
                let d = crate::wrap_phi(m.angvel * span);
                NonlinearRigidMotion { angvel: d.sin() / span, ..*m }
            };
            let sc = StartContact {
                distance: k.dist,
                point1: k.points[0].point1,
                point2: pos12.inverse_transform_point(k.points[0].point2),
                normal1: k.normal,
            };
            sc.rate(&eff(c.m1), &eff(c.m2), c.t0) < 0.0
        };
        let rule = std::env::var("RULE").unwrap_or_default();
        let nudge = c.t0 + StartContactPolicy::START_NUDGE * (c.t1 - c.t0);
        // The core: a disc about the fast body's rotation centre, moving with it.
        let core_frac: f64 = std::env::var("CORE_FRAC").ok().and_then(|s| s.parse().ok()).unwrap_or(0.5);
        let core = parry2d_f64::shape::Ball::new(core_frac * r_in);
        let com0 = fast_m.start * fast_m.local_center;
        let mc = NonlinearRigidMotion::new(
            parry2d_f64::math::Pose::from_translation(com0),
            parry2d_f64::math::Vector::ZERO,
            fast_m.linvel,
            0.0,
        );
        let core_r = match shape_time_of_impact(&core, &mc, other_g, other_m, c.t0, c.t1, &ToiOptions { stop_at_penetration: true, ..*opts }) {
            Ok(r) => r,
            Err(e) => return Some(toi_to_parry(Err(e))),
        };
        let t_core = (core_r.status != ToiStatus::NoHit).then_some(core_r.time);
        let use_pen = !(rule == "core" || (rule == "mixed" && approaching()));
        let t_pen = if use_pen {
            let allowance = StartContactPolicy::ALLOWANCE * r_in;
            let floor = -0.9 * r_in;
            let mut level = (-allowance).min(d0 - StartContactPolicy::DEEPER_FRACTION * allowance);
            if level < floor {
                level = floor.min(d0 - 1e-3 * allowance);
            }
            if rule == "trans" {
                level = (-allowance).min(d0 - allowance);
            }
            let (s1, s2) = (c1.any_side()?, c2.any_side()?);
            let (mut m1, mut m2) = (*c.m1, *c.m2);
            if rule == "trans" {
                m1.angvel = 0.0;
                m2.angvel = 0.0;
            }
            match crate::query::gap::gap_time_to_level(s1, &m1, s2, &m2, c.t0, c.t1, level, &nlerp) {
                Ok(r) if r.status == ToiStatus::NoHit => None,
                Ok(r) => Some(r),
                Err(e) => return Some(toi_to_parry(Err(e))),
            }
        } else {
            None
        };
        let pick = match (t_pen, t_core) {
            (Some(p), Some(tc)) if tc < p.time => Some(TimeOfImpact { time: tc, ..p }),
            (Some(p), _) => Some(p),
            (None, Some(tc)) => Some(TimeOfImpact { time: tc, status: ToiStatus::PenetratingAtStart, ..core_r }),
            (None, None) => None,
        };
        Some(toi_to_parry(Ok(pick.map(|r| TimeOfImpact {
            time: r.time.max(nudge),
            status: ToiStatus::PenetratingAtStart,
            ..r
        }))))
    }

    /// A curve against a half-space: the half-space cast.
    fn cast_halfspace(
        &self,
        c: &NonlinearCast,
        curve: &CurveOf,
        hs: &HalfSpace,
        curve_first: bool,
        opts: &ToiOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let r = if curve_first {
            time_of_impact_halfspace(curve.get(), c.m1, hs, c.m2, c.t0, c.t1, opts)
        } else {
            time_of_impact_halfspace(curve.get(), c.m2, hs, c.m1, c.t0, c.t1, opts).map(TimeOfImpact::swapped)
        };
        let thickness = if curve_first {
            c.g1.ccd_thickness()
        } else {
            c.g2.ccd_thickness()
        };
        let at = |t: Real| halfspace_distance(curve.get(), hs, &pos12_at(c.m1, c.m2, t), curve_first).ok();
        self.answer(
            c,
            r,
            thickness,
            |_| at(c.t0).map(|d| StartContact::from_distance(&d)),
            |t| at(t).map(|d| d.distance),
        )
    }

    /// The answer `r` of a cast, out to parry: as it is under `stop_at_penetration` or the plain
    /// policy, otherwise through the rapier rule (`start_contact`) with the pair's CCD
    /// `thickness`, its contact at the window start `start(gap)` (`gap` the policy's start-contact
    /// gap for the pair's size) and its signed distance `at(t)`.
    fn answer(
        &self,
        c: &NonlinearCast,
        r: Result<TimeOfImpact, QueryError>,
        thickness: Real,
        start: impl Fn(Real) -> Option<StartContact>,
        at: impl Fn(Real) -> Option<Real>,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        if self.plain(c) {
            return toi_to_parry(r.map(Some));
        }
        let gap = StartContactPolicy::START_CONTACT_GAP * pair_size(c.g1, c.g2);
        // The rule's search for a deepening contact evaluates the signed distance up to about 42
        // times (16 samples, then bisection of one sample interval to 1e-9 of the window): the
        // exact contact query gives the same quantity (the largest separation over all
        // directions, exact to rounding; `tests::exact_contact_is_each_routes_signed_distance`)
        // at a fraction of the route's own distance, for every pair it reads.
        let signed = |t: Real| match exact_contact(&pos12_at(c.m1, c.m2, t), c.g1, c.g2, None) {
            Some(k) => Some(k.dist),
            None => at(t),
        };
        toi_to_parry(r.map(|r| rapier_rule(r, c.m1, c.m2, c.t0, c.t1, thickness, gap, || start(gap), signed)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dispatcher::route::RouteScratch;
    use crate::numerics::math::{Pose, Vector};
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};
    use parry2d_f64::shape::{Ball, Cuboid};

    /// The route's own signed distance of a cast's pair (the curves' stationary distance or the
    /// gap tracker's), `None` for the other routes.
    fn route_distance(g1: &dyn Shape, g2: &dyn Shape, pos12: &Pose) -> Option<(&'static str, Real)> {
        let mut scratch = RouteScratch::default();
        match route_cast(g1, g2, &mut scratch) {
            Route::Curves { c1, c2, swapped } => pair_distance(&c1, &c2, swapped, pos12, &Default::default())
                .ok()
                .map(|d| ("curves", d.distance)),
            Route::Gap { c1, c2 } => {
                let (p1, p2) = (c1.gap_side()?, c2.gap_side()?);
                gap_distance(p1, p2, pos12).map(|d| ("gap", d.0))
            }
            _ => None,
        }
    }

    /// The rapier rule's samples take the exact contact query's signed distance in place of the
    /// route's: the same number to rounding, apart and overlapping, on both routes.
    #[test]
    fn exact_contact_is_each_routes_signed_distance() {
        let shapes: Vec<Box<dyn Shape>> = vec![
            Box::new(Ellipse::new(0.5, 0.2)),
            Box::new(CapsuleEllipse::new(0.3, 0.2, 0.4)),
            Box::new(RoundedPolygon::regular(5, 0.4, 0.05)),
            Box::new(Cuboid::new(Vector::new(0.6, 0.25))),
            Box::new(Ball::new(0.3)),
        ];
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut uniform = |lo: f64, hi: f64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            lo + (hi - lo) * (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut compared, mut routes) = (0, std::collections::BTreeSet::new());
        for g1 in &shapes {
            for g2 in &shapes {
                let size = g1.compute_local_bounding_sphere().radius + g2.compute_local_bounding_sphere().radius;
                for _ in 0..300 {
                    let (a, r) = (uniform(-3.2, 3.2), uniform(0.2, 1.3) * size);
                    let pos12 = Pose::new(Vector::new(a.cos(), a.sin()) * r, uniform(-3.2, 3.2));
                    let (Some(exact), Some((route, own))) = (
                        exact_contact(&pos12, &**g1, &**g2, None),
                        route_distance(&**g1, &**g2, &pos12),
                    ) else {
                        continue;
                    };
                    assert!(
                        (exact.dist - own).abs() <= 1e-12 * size,
                        "{route}: {:?} / {:?} at {pos12:?}: {} against {own}",
                        g1.shape_type(),
                        g2.shape_type(),
                        exact.dist
                    );
                    compared += 1;
                    routes.insert(route);
                }
            }
        }
        println!("{compared} poses compared on the routes {routes:?}");
        assert!(compared > 5000 && routes.len() == 2, "{compared} {routes:?}");
    }
}
