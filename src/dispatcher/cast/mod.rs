//! `SmoothDispatcher::cast_shapes_nonlinear`: every pair of convex shapes the dispatcher can
//! convert gets the crate's exact time of impact ([`route_cast`]) — the φ–t tracker when one side
//! is strictly convex, the gap tracker otherwise, the half-space cast — with the
//! [`crate::CastPolicy`] applied (rapier's clamp path and start-contact rule); composites are decomposed
//! with this dispatcher inside, and the shapes it cannot convert go to parry. Under rapier's
//! rules a disc turning about its centre against a polygon or a disc at rest is answered in
//! closed form first (`disc_cast`: its centre's straight path against the grown target).

use super::composite::{composite_cast_nonlinear, composite_casts_its_parts};
use super::disc_cast::{disc_cast, polygon_point_distance, translating_cast};
use super::input_guard;
use super::parry_fallback::parry_nonlinear_without_stop;
use super::parry_fallback::{parry_cast_nonlinear, size_of_radii};
use super::rapier_rule::{in_contact, out_of_reach, rapier_path, start_contact, start_contact_answer};
use super::route::{curves_toi, pair_distance, route_cast, CurveOf, Route, RouteScratch};
use super::support_shape::{exact_contact_of, support_shape, SupportScratch};
use super::SmoothDispatcher;
use crate::error::QueryError;
use crate::numerics::math::{Pose, Real, Vector};
use crate::numerics::motion::motion_is_finite;
use crate::query::advance::{advance_time_of_impact, certified_miss, face_separation, Advance, PairOnPath, Start};
use crate::query::contact::SupportShape;
use crate::query::gap::{gap_distance, gap_time_of_impact, gap_time_to_level};
use crate::query::halfspace::{halfspace_distance, time_of_impact_halfspace};
use crate::query::path::OnPath;
use crate::query::time_scale::rescaled;
use crate::query::toi::{bounding_circles_part, TimeOfImpact, ToiOptions};
use parry2d_f64::bounding_volume::BoundingSphere;
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
    /// Rule 3 of `rapier_rule` on the full motions, rotation included
    /// ([`crate::CastPolicy::RapierConstantSpin`] where both bodies move); false from
    /// [`NonlinearCast::new`].
    pub spin_at_start: bool,
    /// The shapes' local bounding spheres, read once a cast (the size, the reach and the
    /// tolerances of every rule take them).
    pub spheres: [BoundingSphere; 2],
}

impl<'a> NonlinearCast<'a> {
    /// The cast of `g1` moving by `m1` and `g2` by `m2` over `[t0, t1]`.
    pub(crate) fn new(
        m1: &'a NonlinearRigidMotion,
        g1: &'a dyn Shape,
        m2: &'a NonlinearRigidMotion,
        g2: &'a dyn Shape,
        (t0, t1): (Real, Real),
        stop: bool,
    ) -> Self {
        let spheres = [g1.compute_local_bounding_sphere(), g2.compute_local_bounding_sphere()];
        NonlinearCast {
            m1,
            g1,
            m2,
            g2,
            t0,
            t1,
            stop,
            spin_at_start: false,
            spheres,
        }
    }

    /// The pair's size ([`super::parry_fallback::pair_size`]) from its spheres.
    pub(crate) fn size(&self) -> Real {
        size_of_radii(self.spheres[0].radius, self.spheres[1].radius)
    }
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
    /// The nonlinear cast (module docs), behind the last guard of the dispatcher's casts: a hit
    /// holding a non-finite number is `Unsupported`, never handed on (a pose the motions reach
    /// only by overflowing — a spin of 1e160 rad/s over a window of 1e300 s — has no witnesses).
    pub(crate) fn nonlinear_cast(&self, c: &NonlinearCast) -> Result<Option<ShapeCastHit>, Unsupported> {
        if self.cast_policy.is_rapier() {
            // rapier's rules place points in the world frame (a body's core): the pair at the
            // origin, and rates far outside the normal range on a time scale where they are
            // about 1 (`query::time_scale`), so that neither the place nor the time scale of
            // the world changes an answer.
            if let Some(answer) = self.rapier_cast_rebased(c) {
                return input_guard::finite(answer);
            }
        }
        input_guard::finite(self.nonlinear_cast_here(c))
    }

    /// [`Self::nonlinear_cast`] with the pair moved to the origin and its time rescaled, when
    /// either changes anything; `None` when neither does (or the input is not finite: the
    /// routes report it).
    fn rapier_cast_rebased(&self, c: &NonlinearCast) -> Option<Result<Option<ShapeCastHit>, Unsupported>> {
        if !(motion_is_finite(c.m1) && motion_is_finite(c.m2) && c.t0.is_finite() && c.t1.is_finite()) {
            return None;
        }
        let size = c.size();
        // parry's own cast answers on the caller's time scale: its conservative advancement,
        // with absolute time tolerances, does not end over a rescaled window of 1e302 s (two
        // points of radius 0 and 1e-300 passing at 100 m/s, fuzz seed 3004, case 157457); nor
        // does its composite helper's cast of bounding balls (a window of 5.7e20 s for bodies
        // at 1e20 m/s, fuzz seed 5032, case 79067).
        let scaled = rescaled(c.m1, c.m2, c.t0, c.t1, size).filter(|_| {
            !matches!(
                route_cast(c.g1, c.g2, &mut RouteScratch::default()),
                Route::Parry { .. } | Route::Composite
            )
        });
        let (m1, m2, t0, t1, scale) = match &scaled {
            Some(r) => (r.m1, r.m2, r.t0, r.t1, r.scale),
            None => (*c.m1, *c.m2, c.t0, c.t1, 1.0),
        };
        // Body 2's start at the origin (exactly: x₂ − x₂), body 1's start by the same shift.
        let shift = m2.start.translation;
        let far = shift.length() > size;
        if !far && scaled.is_none() {
            return None;
        }
        let moved = |m: NonlinearRigidMotion| NonlinearRigidMotion {
            start: Pose::from_parts(m.start.translation - shift, m.start.rotation),
            ..m
        };
        let (m1, m2) = if far { (moved(m1), moved(m2)) } else { (m1, m2) };
        let inner = NonlinearCast {
            m1: &m1,
            m2: &m2,
            t0,
            t1,
            ..*c
        };
        Some(self.nonlinear_cast_here(&inner).map(|h| {
            h.map(|mut h| {
                h.time_of_impact *= scale;
                h
            })
        }))
    }

    /// The nonlinear cast of `c` as it is (module docs): a moving disc in closed form
    /// (`disc_cast`) under rapier's rules, the general path otherwise.
    fn nonlinear_cast_here(&self, c: &NonlinearCast) -> Result<Option<ShapeCastHit>, Unsupported> {
        let (opts, rule) = self.cast_setup(c);
        if rule.rapier {
            if let Some(answer) = disc_cast(c, &opts, rule.start_contact) {
                return answer;
            }
            if let Some(answer) = translating_cast(c, &opts) {
                return answer;
            }
        }
        self.general_cast(c, &opts, rule)
    }

    /// The options and rules of the cast `c` under the dispatcher's policy.
    pub(crate) fn cast_setup(&self, c: &NonlinearCast) -> (ToiOptions, Rules) {
        let rapier = self.cast_policy.is_rapier();
        let mut opts = ToiOptions {
            stop_at_penetration: c.stop,
            ..self.toi_options
        };
        if rapier {
            opts = rapier_path(c, &opts, self.cast_policy);
        }
        // The start-contact rule of rapier's CCD applies to solid bodies.
        let rule = Rules {
            rapier: rapier && is_window(c.t0, c.t1),
            start_contact: rapier && !c.stop && is_window(c.t0, c.t1),
        };
        (opts, rule)
    }

    /// The nonlinear cast of `c` by the general path (module docs), with `opts` and `rule` from
    /// [`Self::cast_setup`].
    pub(crate) fn general_cast(
        &self,
        c: &NonlinearCast,
        opts: &ToiOptions,
        rule: Rules,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let opts = *opts;
        if rule.rapier {
            if let Some(answer) = rapier_fast_path(c, &opts, rule) {
                return answer;
            }
        }
        match route_cast(c.g1, c.g2, &mut RouteScratch::default()) {
            Route::Curves { c1, c2, swapped } => self.cast_curves(c, &c1, &c2, swapped, &opts, rule),
            Route::Gap { c1, c2 } => self.cast_gap(c, &c1, &c2, &opts, rule),
            Route::HalfSpace { curve, hs, curve_first } => self.cast_halfspace(c, &curve, hs, curve_first, &opts, rule),
            // A composite at rest (rapier's CCD against level geometry): its parts cast by this
            // dispatcher, under their own guards. Otherwise parry's composite helper casts
            // bounding balls itself: the same guards as parry's casts, and positions that rounding
            // resolves (`input_guard::resolved_motions`), as for parry's.
            Route::Composite if composite_casts_its_parts(c.m1, c.g1, c.m2, c.g2) => {
                match input_guard::cast_input_ok(c.m1, c.g1, c.m2, c.g2, c.t0, c.t1)? {
                    true => input_guard::finite(composite_cast_nonlinear(
                        self, c.m1, c.g1, c.m2, c.g2, c.t0, c.t1, c.stop,
                    )),
                    false => Ok(None),
                }
            }
            Route::Composite => match input_guard::cast_window_ok(c.m1, c.g1, c.m2, c.g2, c.t0, c.t1).and_then(|ok| {
                if ok {
                    input_guard::resolved_motions(c.m1, c.g1, c.m2, c.g2, c.t0, c.t1)
                } else {
                    Ok(None)
                }
            }) {
                Ok(Some((m1, m2))) => {
                    input_guard::finite(composite_cast_nonlinear(self, &m1, c.g1, &m2, c.g2, c.t0, c.t1, c.stop))
                }
                Ok(None) => Ok(None),
                Err(e) => Err(e),
            },
            Route::Parry { ours: true } if rule.start_contact => {
                input_guard::finite(parry_nonlinear_without_stop(c.m1, c.g1, c.m2, c.g2, c.t0, c.t1))
            }
            Route::Parry { .. } => parry_cast_nonlinear(c.m1, c.g1, c.m2, c.g2, c.t0, c.t1, c.stop),
        }
    }

    /// A pair with a strictly convex side: the φ–t tracker, under rapier's rule when `rule`
    /// (module docs of `rapier_rule`).
    fn cast_curves(
        &self,
        c: &NonlinearCast,
        c1: &CurveOf,
        c2: &CurveOf,
        swapped: bool,
        opts: &ToiOptions,
        rule: Rules,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let (a, b) = if swapped { (c2, c1) } else { (c1, c2) };
        // The specification's inexpensive test first: circles that never meet, no impact
        // (and no contact at the start either).
        if bounding_circles_part(a.get(), c.m1, b.get(), c.m2, c.t0, c.t1, opts.target_distance) {
            return Ok(None);
        }
        if rule.rapier {
            let k0 = start_contact(c);
            let d0 = k0.map(|k| k.dist).or_else(|| {
                pair_distance(c1, c2, swapped, &pos12_at(c.m1, c.m2, c.t0), &self.distance_options)
                    .ok()
                    .map(|d| d.distance)
            });
            if let Some(d0) = d0 {
                if out_of_reach(c, d0, opts.target_distance) {
                    return Ok(None);
                }
                if let (true, Some(sa), Some(sb)) =
                    (rule.start_contact && in_contact(c, d0), a.any_side(), b.any_side())
                {
                    return start_contact_answer(c, d0, k0, opts, |m1, m2, level| {
                        gap_time_to_level(sa, m1, sb, m2, c.t0, c.t1, level, &plain(opts))
                    });
                }
            }
        }
        toi_to_parry(curves_toi(a, c.m1, b, c.m2, c.t0, c.t1, opts).map(Some))
    }

    /// No strictly convex side: the gap tracker, under rapier's rule when `rule`.
    fn cast_gap(
        &self,
        c: &NonlinearCast,
        c1: &CurveOf,
        c2: &CurveOf,
        opts: &ToiOptions,
        rule: Rules,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        let (Some(p1), Some(p2)) = (c1.gap_side(), c2.gap_side()) else {
            return Err(Unsupported);
        };
        if bounding_circles_part(c1.get(), c.m1, c2.get(), c.m2, c.t0, c.t1, opts.target_distance) {
            return Ok(None);
        }
        if rule.rapier {
            let k0 = start_contact(c);
            let d0 = k0
                .map(|k| k.dist)
                .or_else(|| gap_distance(p1, p2, &pos12_at(c.m1, c.m2, c.t0)).map(|d| d.0));
            if let Some(d0) = d0 {
                if out_of_reach(c, d0, opts.target_distance) {
                    return Ok(None);
                }
                if rule.start_contact && in_contact(c, d0) {
                    return start_contact_answer(c, d0, k0, opts, |m1, m2, level| {
                        gap_time_to_level(p1, m1, p2, m2, c.t0, c.t1, level, &plain(opts))
                    });
                }
            }
        }
        toi_to_parry(gap_time_of_impact(p1, c.m1, p2, c.m2, c.t0, c.t1, opts).map(Some))
    }

    /// A curve against a half-space: the half-space cast, under rapier's rule when `rule` (the
    /// translation's deepening below a level is the cast against the plane moved by the level).
    fn cast_halfspace(
        &self,
        c: &NonlinearCast,
        curve: &CurveOf,
        hs: &HalfSpace,
        curve_first: bool,
        opts: &ToiOptions,
        rule: Rules,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        // The half-space cast in the caller's order, the plane moved by `shift` along its normal.
        let cast = |m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion, shift: Real, o: &ToiOptions| {
            let (mc, mh) = if curve_first { (m1, m2) } else { (m2, m1) };
            let moved = NonlinearRigidMotion {
                start: mh.start * Pose::from_translation(hs.normal * shift),
                ..*mh
            };
            let r = time_of_impact_halfspace(curve.get(), mc, hs, &moved, c.t0, c.t1, o);
            if curve_first {
                r
            } else {
                r.map(TimeOfImpact::swapped)
            }
        };
        if rule.start_contact {
            let d0 = halfspace_distance(curve.get(), hs, &pos12_at(c.m1, c.m2, c.t0), curve_first)
                .ok()
                .map(|d| d.distance);
            if let Some(d0) = d0.filter(|d0| in_contact(c, *d0)) {
                return start_contact_answer(c, d0, None, opts, |m1, m2, level| cast(m1, m2, level, &plain(opts)));
            }
        }
        toi_to_parry(cast(c.m1, c.m2, 0.0, opts).map(Some))
    }
}

/// rapier's casts of the shapes the contact query reads, one of them this crate's, without
/// routing them to the trackers: a miss the bounds over the whole window certify
/// (`query::advance::swept`); the exact contact at the start; the pair out of reach; a
/// contact at the start by rapier's rule; apart, the separating-axis advancement
/// (`query::advance`). `None` where the trackers answer (another pair, non-finite input, an
/// advancement declined, a contact at the start with `stop_at_penetration`, two turning bodies
/// outside the start-contact rule).
fn rapier_fast_path(
    c: &NonlinearCast,
    opts: &ToiOptions,
    rule: Rules,
) -> Option<Result<Option<ShapeCastHit>, Unsupported>> {
    let ours = |g: &dyn Shape| g.shape_type() == parry2d_f64::shape::ShapeType::Custom;
    if !(ours(c.g1) || ours(c.g2)) || !(motion_is_finite(c.m1) && motion_is_finite(c.m2)) {
        return None;
    }
    // Both bodies turning, the advancement declines (`PairOnPath::of`); without the start-contact
    // rule this path would only tell a pair out of reach, which the routes' own bounds (the
    // trackers' bounding circles) tell as well: the route takes the cast at once (two bodies cast
    // with `stop_at_penetration`, which rapier's CCD never asks).
    if !rule.start_contact && c.m1.angvel != 0.0 && c.m2.angvel != 0.0 {
        return None;
    }
    let (mut st1, mut st2) = (SupportScratch::default(), SupportScratch::default());
    let s1 = support_shape(c.g1, &mut st1)?;
    let s2 = support_shape(c.g2, &mut st2)?;
    // The bounding spheres first: a pair they keep out of reach needs no exact contact (a gap
    // that overflows proves nothing).
    let gap = sphere_gap(c);
    if gap.is_finite() && out_of_reach(c, gap, opts.target_distance) {
        return Some(Ok(None));
    }
    // Bounds over the whole window along a few axes, before any contact query: a pair they
    // keep apart is no impact and no contact at the start (`query::advance::swept`).
    // Tried only where the spheres are apart at the start (shapes in contact there, rapier's
    // other common cast, never pay for it), and where the contact query would take the pair
    // (the same guards), so that input it refuses keeps its answer.
    let pos12 = pos12_at(c.m1, c.m2, c.t0);
    // The pair on its path (B's kinematics in A's frame), computed once for the certified miss
    // and the advancement; `None` where the advancement declines (both bodies turn).
    let pair = || PairOnPath::of(&OnPath::new(c.m1, c.m2, c.t0, c.t1, opts.path).ok()?);
    let try_miss = (gap > 0.0 || polygon_gap(c, s1, s2, &pos12) > 0.0) && input_guard::pose_ok(&pos12) && centres_ok(c);
    let frame = if try_miss { pair() } else { None };
    if let Some(f) = &frame {
        if certified_miss(s1, s2, f, c.t0, c.t1, miss_level(c, opts)) {
            return Some(Ok(None));
        }
        // A's face normal along which the pair is furthest apart at the start: apart by more
        // than the start-contact gap and the advancement's tolerance along it, the shapes are
        // apart (the separation bounds the distance from below) and the advancement starts from
        // it without the exact contact (`query::advance::face_separation`).
        if let Some((start, sep)) = face_separation(s1, s2, f, c.t0) {
            if out_of_reach(c, sep, opts.target_distance) {
                return Some(Ok(None));
            }
            let apart = sep - opts.target_distance > advance_tolerance(c, opts) && !in_contact(c, sep);
            if apart {
                return advanced(c, f, s1, s2, opts, start);
            }
        }
    }
    let k0 = exact_contact_of(s1, s2, &pos12, None)?;
    let d0 = k0.dist;
    if out_of_reach(c, d0, opts.target_distance) {
        return Some(Ok(None));
    }
    if in_contact(c, d0) {
        return rule.start_contact.then(|| {
            start_contact_answer(c, d0, Some(k0), opts, |m1, m2, level| {
                level_by_route(c, m1, m2, level, opts)
            })
        });
    }
    advanced(c, &frame.or_else(pair)?, s1, s2, opts, Start::Contact(Some(k0)))
}

/// Whether both motions start at poses parry can use ([`input_guard::pose_ok`]: a unit rotation
/// among them) with rotation centres within its coordinate range
/// ([`input_guard::PARRY_MAX_COORDINATE`]): otherwise the certified miss is not tried and the
/// routes answer such input as they always have.
fn centres_ok(c: &NonlinearCast) -> bool {
    let ok = |m: &NonlinearRigidMotion| {
        input_guard::pose_ok(&m.start) && m.local_center.abs().max_element() <= input_guard::PARRY_MAX_COORDINATE
    };
    ok(c.m1) && ok(c.m2)
}

/// Relative rounding allowed to the certified miss's bounds, of the pair's size plus the
/// bodies' travel over the window.
const MISS_ROUNDING: Real = 1e-9;

/// The level a certified miss must keep the pair above for every path to answer no impact: the
/// target distance, twice the advancement's tolerance ([`advance_tolerance`]) — no contact the
/// advancement or the trackers would take as a graze —, the start-contact gap of rapier's rule
/// and [`MISS_ROUNDING`] of the pair's size and travel.
fn miss_level(c: &NonlinearCast, opts: &ToiOptions) -> Real {
    let window = c.t1 - c.t0;
    let travel = (c.m1.linvel.length() + c.m2.linvel.length()) * window;
    let size = c.size();
    opts.target_distance
        + 2.0 * advance_tolerance(c, opts)
        + crate::CastPolicy::START_CONTACT_GAP * size
        + MISS_ROUNDING * (size + travel)
}

/// The advancement's distance tolerance: `distance_tolerance` of the size s, the larger bounding
/// radius about the shapes' local origins.
fn advance_tolerance(c: &NonlinearCast, opts: &ToiOptions) -> Real {
    let radius = |b: &BoundingSphere| b.radius + b.center.length();
    opts.distance_tolerance * radius(&c.spheres[0]).max(radius(&c.spheres[1]))
}

/// A lower bound of the signed distance of the cast's shapes at its start: every point of a body
/// is within R = r + |s − c| of its rotation centre (r and s its bounding sphere's radius and
/// centre, c the rotation centre, all in its frame), so with p₁, p₂ the rotation centres at t₀
/// the shapes are at least |p₂ − p₁| − R₁ − R₂ apart (and, overlapping, no deeper than
/// R₁ + R₂ − |p₂ − p₁|: moving one along p₂ − p₁ by that much parts the circles).
fn sphere_gap(c: &NonlinearCast) -> Real {
    let at = |m: &NonlinearRigidMotion, s: &BoundingSphere| {
        let centre = m.start * m.local_center + m.linvel * c.t0;
        (centre, s.radius + (s.center - m.local_center).length())
    };
    let (p1, r1) = at(c.m1, &c.spheres[0]);
    let (p2, r2) = at(c.m2, &c.spheres[1]);
    (p2 - p1).length() - r1 - r2
}

/// A lower bound of the signed distance of the cast's shapes at its start where one of them is
/// a polygon (a segment, a wall, a box), when the bounding spheres say nothing (a long wall's
/// sphere holds everything near it): every point of the other body is within R = r + |s − c| of
/// its rotation centre c ([`sphere_gap`]), so the shapes are at least sd(c) − ρ − R apart, sd
/// the signed distance from c to the polygon's core and ρ its radius. Taken for the shape that
/// stays put (rapier's target); −∞ when it is not a polygon or both shapes move.
fn polygon_gap(c: &NonlinearCast, s1: SupportShape, s2: SupportShape, pos12: &Pose) -> Real {
    let reach = |m: &NonlinearRigidMotion, s: &BoundingSphere| s.radius + (s.center - m.local_center).length();
    let gap = |poly: SupportShape, centre: Vector, other_reach: Real| match poly {
        SupportShape::Polygon {
            vertices,
            normals,
            radius,
        } => polygon_point_distance(vertices, normals, centre) - radius - other_reach,
        _ => Real::NEG_INFINITY,
    };
    // The side that stays put (rapier's target): body 1's rotation centre in shape 2's frame,
    // or body 2's in shape 1's.
    let still = |m: &NonlinearRigidMotion| m.linvel == Vector::ZERO && m.angvel == 0.0;
    if still(c.m2) {
        gap(
            s2,
            pos12.inverse_transform_point(c.m1.local_center),
            reach(c.m1, &c.spheres[0]),
        )
    } else if still(c.m1) {
        gap(s1, *pos12 * c.m2.local_center, reach(c.m2, &c.spheres[1]))
    } else {
        Real::NEG_INFINITY
    }
}

/// The first time the signed distance of the cast's shapes moving by `m1`, `m2` comes down to
/// `level`, by the route's own search (the gap tracker, the half-space cast on a shifted plane):
/// the start-contact rule's fallback for the pairs the contact query does not read.
fn level_by_route(
    c: &NonlinearCast,
    m1: &NonlinearRigidMotion,
    m2: &NonlinearRigidMotion,
    level: Real,
    opts: &ToiOptions,
) -> Result<TimeOfImpact, QueryError> {
    let o = plain(opts);
    match route_cast(c.g1, c.g2, &mut RouteScratch::default()) {
        Route::Curves { c1, c2, swapped } => {
            let (a, b) = if swapped { (c2, c1) } else { (c1, c2) };
            match (a.any_side(), b.any_side()) {
                (Some(sa), Some(sb)) => gap_time_to_level(sa, m1, sb, m2, c.t0, c.t1, level, &o),
                _ => Err(QueryError::UnsupportedShape),
            }
        }
        Route::Gap { c1, c2 } => match (c1.gap_side(), c2.gap_side()) {
            (Some(p1), Some(p2)) => gap_time_to_level(p1, m1, p2, m2, c.t0, c.t1, level, &o),
            _ => Err(QueryError::UnsupportedShape),
        },
        Route::HalfSpace { curve, hs, curve_first } => {
            let (mc, mh) = if curve_first { (m1, m2) } else { (m2, m1) };
            let moved = NonlinearRigidMotion {
                start: mh.start * Pose::from_translation(hs.normal * level),
                ..*mh
            };
            let r = time_of_impact_halfspace(curve.get(), mc, hs, &moved, c.t0, c.t1, &o);
            if curve_first {
                r
            } else {
                r.map(TimeOfImpact::swapped)
            }
        }
        Route::Composite | Route::Parry { .. } => Err(QueryError::UnsupportedShape),
    }
}

/// The separating-axis advancement (`query::advance`) of a cast whose shapes (`s1`, `s2`, as the
/// contact query reads them) are apart at its start, moving as `pair` says, from `start` (their
/// contact there, or a separating axis); `None` where it declines (the trackers answer then).
fn advanced(
    c: &NonlinearCast,
    pair: &PairOnPath,
    s1: SupportShape,
    s2: SupportShape,
    opts: &ToiOptions,
    start: Start,
) -> Option<Result<Option<ShapeCastHit>, Unsupported>> {
    let tol = advance_tolerance(c, opts);
    match advance_time_of_impact(s1, s2, c.g1, c.g2, pair, c.t0, c.t1, opts.target_distance, tol, start) {
        Advance::Answer(t) => Some(toi_to_parry(Ok(Some(t)))),
        Advance::Declined => None,
    }
}

/// Which of rapier's rules a cast follows (`rapier_rule`): its start-distance tests (the
/// policy is rapier's and the window is not empty) and the start-contact rule (also solid
/// bodies, `stop_at_penetration = false`).
#[derive(Copy, Clone, Debug)]
pub(crate) struct Rules {
    pub rapier: bool,
    pub start_contact: bool,
}

/// `opts` on parry's own motions (the level searches of the start-contact rule run on motions
/// without spin, which the nlerp path would leave unchanged), reporting from the start.
fn plain(opts: &ToiOptions) -> ToiOptions {
    ToiOptions {
        path: crate::MotionPath::ConstantSpin,
        ..*opts
    }
}

/// Shape 2's pose in shape 1's frame at time `t`.
pub(crate) fn pos12_at(m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion, t: Real) -> Pose {
    // From the pair's relative motion, as the trackers place it: the world poses of two bodies
    // 1e15 from the origin carry 0.1 of rounding each.
    crate::numerics::motion::PairFrame::at_time(m1, m2, t).pos12()
}

/// Whether `[t0, t1]` is a non-empty finite window (false for NaN).
pub(crate) fn is_window(t0: Real, t1: Real) -> bool {
    t1 > t0 && (t1 - t0).is_finite()
}

#[cfg(test)]
mod tests;
