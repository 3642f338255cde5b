//! [`CastPolicy`]: what `SmoothDispatcher::cast_shapes_nonlinear` answers, and the rules it
//! follows for rapier's CCD ([`CastPolicy::Rapier`], the default).
//!
//! # What rapier does with a cast (rapier2d 0.36, `dynamics/ccd`)
//!
//! rapier asks the dispatcher to cast a *fast* body (shape 1, its motion built from the solved
//! velocities of the step) against a target held at its end-of-step pose (shape 2, a constant
//! motion), over one step, with `stop_at_penetration = false` for solid bodies. It discards a
//! hit at exactly the start of the step, takes the earliest hit over all targets, and puts the
//! body at `Sweep::from_poses(start, end).transform_at(fraction)`: the rotation centre at that
//! fraction of its straight path, the rotation *nlerped* between the step's end rotations (the
//! short way round) — not the constant spin it asked about. Velocities are kept; the next step's
//! solver resolves the contact.
//!
//! # The rules of [`CastPolicy::Rapier`]
//!
//! 1. **The path rapier applies.** Every cast follows [`crate::MotionPath::Nlerp`], the path the
//!    clamp puts the body on, so a reported contact is a contact on the pose rapier will apply,
//!    and the body got there without meeting anything before: its rotation may differ from
//!    the constant spin by up to 0.008 rad at a quarter turn of π/4 per step, by any amount
//!    beyond π/2, and the whole way round once a step's rotation exceeds half a turn.
//! 2. **Apart at the start**: the exact time of impact along that path (the shapes touching).
//! 3. **In contact at the start** (penetrating, or within [`CastPolicy::START_CONTACT_GAP`] of
//!    the pair's size): rapier's solver has just seen this contact, and the cast answers for
//!    what the step's *translation* does to it. The fast body's *core* — the disc of
//!    [`CastPolicy::CORE`] of its inradius r about its rotation centre, which its rotation does
//!    not move — must not reach the target: the centre of a body never passes a wall of any
//!    thickness, a segment included (a core that starts touching the target may go a quarter
//!    of its radius deeper a step, never past half of it: `core_level`). And the translation
//!    alone (the motion without its spin) may deepen the contact by at most the *allowance*
//!    [`CastPolicy::ALLOWANCE`]·r a step, below the start's depth, so a body driven into a
//!    wall is stopped and one sliding or resting on it moves freely (against a `Segment`, on
//!    the contact from the side of the body's centre that the manifold gives the solver:
//!    `centre_side`). The answer is the earlier of the two, at least
//!    [`CastPolicy::START_NUDGE`] of the window after the start (rapier would discard the start
//!    itself), or no hit.
//!
//! With [`CastPolicy::RapierConstantSpin`] (the moving-pairs pass's casts), rule 1 takes
//! parry's constant-spin path, and where *both* bodies move, rule 3 measures the deepening on
//! the *whole* motions, rotation included, rather than on the translation alone: the pass puts
//! a body it stops on that path, whose spin is the solver's own spin, so a contact the solver
//! sees leaving is one the rule sees leaving too (the freeze described below comes from the
//! nlerp path turning the other way, which this policy never takes). Measured on the
//! translation alone, two spinning bodies whose contact points the spin carries apart while
//! their centres approach were stopped at the start of every step, frozen in each other.
//! Against a body that stands still (no velocity, no spin: a fixed wall the pass sweeps a body
//! turning past rapier's regime against) rule 3 stays on the translation, as for rapier's own
//! casts: measured on the whole motions, a sliver spun past rapier's regime whose spin digs a
//! tip into a wall its centre is leaving was stopped at the start of every step (the solver,
//! with one contact point a step, never took the spin off it: 10 frozen cases of the CCD scene
//! suite, chain box and bouncing box, at 1000–3000 m/s), while the core keeps the centre off
//! the wall on either measure.
//!
//! What rule 3 leaves to the solver — the overlap a spin brings in at a start contact — the
//! solver sees at the next step: the contact manifold's two points where faces face each other,
//! and its *core contact* (`core_disc`), a speculative point of the body's core that stops a
//! centre heading for a wall whatever the spin does to the contact point. Why the rotation is
//! left out of rule 3: where a step's rotation exceeds half a turn, rapier's clamp path turns
//! the other way from the solver's spin, and a rule on the rotated path clamps a body again and
//! again at a contact the solver sees leaving: the body freezes.
//!
//! r is the fast body's distance from its rotation centre to its boundary (its *inradius*
//! about that centre, the `ccd_thickness` of this crate's shapes). Which body is the fast one:
//! the one that moves (rapier's shape 1; parry's composite helpers hand a composite target's
//! parts over as shape 1, still).

use super::cast::{toi_to_parry, NonlinearCast};
use super::core_disc::{core_of, core_of_any};
use super::support_shape::{exact_contact, support_shape, SupportScratch};
use super::translation_level::{translation_time_to_level, LevelTime, Translating};
use crate::error::QueryError;
use crate::numerics::math::{Pose, Real, Vector};
use crate::query::contact::Contact;
use crate::query::path::MotionPath;
use crate::query::toi::{TimeOfImpact, ToiOptions, ToiStatus};
use parry2d_f64::bounding_volume::BoundingSphere;
use parry2d_f64::query::{NonlinearRigidMotion, ShapeCastHit, Unsupported};
use parry2d_f64::shape::{Ball, Shape};

/// What `SmoothDispatcher::cast_shapes_nonlinear` answers (module docs).
///
/// ```
/// use smooth_ccd2d::{CastPolicy, SmoothDispatcher};
/// let for_rapier = SmoothDispatcher::default();
/// assert_eq!(for_rapier.cast_policy, CastPolicy::Rapier);
/// let plain = SmoothDispatcher::default().with_cast_policy(CastPolicy::Plain);
/// assert_eq!(plain.cast_policy, CastPolicy::Plain);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum CastPolicy {
    /// rapier's CCD (the default, for `NarrowPhase::with_query_dispatcher`): every cast on the
    /// path rapier's clamp applies ([`MotionPath::Nlerp`]), and with
    /// `stop_at_penetration = false` a contact at the start answered by the core and the
    /// allowance (module docs). Pairs of two moving, turning bodies (never rapier's) are cast on
    /// their constant spins. An oriented polyline (`PolylineFlags::ORIENTED`) is one-sided, its
    /// segments skipped as rapier's own sweep skips them, the body's turn counted (a body behind
    /// one, or resting on or sliding along it: `docs/rapier.md`, rule 4); so under
    /// [`CastPolicy::RapierConstantSpin`].
    #[default]
    Rapier,
    /// rapier's rules of [`CastPolicy::Rapier`] on parry's constant-spin motions
    /// ([`MotionPath::ConstantSpin`]) whatever the bodies do: the casts of the moving-pairs
    /// pass (`MovingPairs`, feature `rapier`), which puts a body it stops on its constant spin,
    /// not on rapier's nlerp clamp path. Rule 1 of the module docs changes, and rule 3 where
    /// both bodies move: the deepening at a start contact measured on the whole motions, spin
    /// included (against a body standing still, on the translation, as
    /// [`CastPolicy::Rapier`] measures it).
    RapierConstantSpin,
    /// The crate's time of impact as it is ([`crate::time_of_impact`], [`crate::shape_time_of_impact`]):
    /// parry's constant-spin motions, and with `stop_at_penetration = false` a separating
    /// contact at the start looked past and an approaching one reported at the start time.
    Plain,
}

impl CastPolicy {
    /// Whether the policy applies rapier's rules ([`CastPolicy::Rapier`],
    /// [`CastPolicy::RapierConstantSpin`]).
    pub fn is_rapier(self) -> bool {
        matches!(self, CastPolicy::Rapier | CastPolicy::RapierConstantSpin)
    }

    /// Shapes closer than this fraction of the pair's size (the sum of the bounding radii) at
    /// the start of a cast are in contact there: rapier's CCD leaves a body it clamped at an
    /// impact about 10⁻¹⁰ from the other shape.
    pub const START_CONTACT_GAP: Real = 1e-6;

    /// The earliest a contact at the start is reported to rapier, as a fraction of the window:
    /// far below any motion rapier resolves, yet after the start time, which rapier discards.
    pub const START_NUDGE: f64 = 1e-9;

    /// How much deeper the translation of a step may take a contact at the start, as a
    /// fraction of the fast body's inradius about its rotation centre.
    pub const ALLOWANCE: Real = 0.25;

    /// The radius of the core the CCD keeps off every target, as a fraction of the fast body's
    /// inradius about its rotation centre (smaller than the manifold's core contact, half, so
    /// that the solver stops a centre before the CCD has to).
    pub const CORE: Real = 0.25;
}

/// Whether rule 3 measures the deepening at a start contact on the whole motions
/// ([`NonlinearCast::spin_at_start`]): under [`CastPolicy::RapierConstantSpin`], where both
/// bodies move; against a body standing still over the window (no velocity, no spin: a fixed
/// wall, a body at rest, or a body the moving-pairs pass has stopped earlier in the step and
/// casts again from its stop), on the translation, as under [`CastPolicy::Rapier`] (module
/// docs): for that cast the still body is a wall.
pub(crate) fn spin_at_start(policy: CastPolicy, m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion) -> bool {
    policy == CastPolicy::RapierConstantSpin && !still(m1) && !still(m2)
}

/// The fast body of a cast: shape, motion, and the other shape and motion.
struct Fast<'a> {
    g: &'a dyn Shape,
    m: &'a NonlinearRigidMotion,
    other_g: &'a dyn Shape,
    other_m: &'a NonlinearRigidMotion,
}

/// Whether a motion stays put.
fn still(m: &NonlinearRigidMotion) -> bool {
    m.linvel == Vector::ZERO && m.angvel == 0.0
}

/// The fast body of `c` (module docs).
fn fast<'a>(c: &NonlinearCast<'a>) -> Fast<'a> {
    if still(c.m1) && !still(c.m2) {
        Fast {
            g: c.g2,
            m: c.m2,
            other_g: c.g1,
            other_m: c.m1,
        }
    } else {
        Fast {
            g: c.g1,
            m: c.m1,
            other_g: c.g2,
            other_m: c.m2,
        }
    }
}

/// The distance from `centre` to the boundary of `g` (0 when `centre` is not inside): exact from
/// the shape's core for the shapes the contact query reads, else by point projection.
pub(crate) fn inradius_about(g: &dyn Shape, centre: Vector) -> Real {
    use crate::query::contact::SupportShape;
    let mut scratch = SupportScratch::default();
    match support_shape(g, &mut scratch) {
        // A polygon's edge lines give the exact distance about any point inside.
        Some(SupportShape::Polygon {
            vertices,
            normals,
            radius,
        }) => {
            let d = (0..vertices.len())
                .map(|i| normals[i].dot(vertices[i] - centre))
                .fold(Real::INFINITY, Real::min);
            (d + radius).max(0.0)
        }
        // Other cores are discs about the centroid; other shapes by point projection.
        s => match s.and_then(core_of) {
            Some(k) => k.radius_about(centre),
            None => {
                let p = g.project_local_point(centre, false);
                if p.is_inside {
                    (p.point - centre).length()
                } else {
                    0.0
                }
            }
        },
    }
}

/// The options of a cast on rapier's clamp path: nlerp, unless both bodies turn (a pair rapier
/// never casts; the constant spins then) or the policy is [`CastPolicy::RapierConstantSpin`].
pub(crate) fn rapier_path(c: &NonlinearCast, opts: &ToiOptions, policy: CastPolicy) -> ToiOptions {
    let path = if policy != CastPolicy::RapierConstantSpin && (c.m1.angvel == 0.0 || c.m2.angvel == 0.0) {
        MotionPath::Nlerp
    } else {
        MotionPath::ConstantSpin
    };
    ToiOptions { path, ..*opts }
}

/// The exact contact of the cast's shapes at its start, or `None` when the contact query does
/// not read the pair.
pub(crate) fn start_contact(c: &NonlinearCast) -> Option<Contact> {
    let pos12 = super::cast::pos12_at(c.m1, c.m2, c.t0);
    exact_contact(&pos12, c.g1, c.g2, None)
}

/// Whether shapes at signed distance `d0` at the start of `c` are in contact there.
pub(crate) fn in_contact(c: &NonlinearCast, d0: Real) -> bool {
    d0 <= CastPolicy::START_CONTACT_GAP * c.size()
}

/// Whether shapes at signed distance `d0` at the start of `c` cannot come within `target` of
/// each other in its window: no point of a body moves by more than its translation plus the
/// chord of its turn (at most its radius about its rotation centre times the turn, and twice
/// the radius), on the constant-spin path as on the nlerp path, and the signed distance of two
/// apart shapes changes by no more than their points move.
pub(crate) fn out_of_reach(c: &NonlinearCast, d0: Real, target: Real) -> bool {
    let window = c.t1 - c.t0;
    let reach = |m: &NonlinearRigidMotion, sphere: &BoundingSphere| {
        let radius = sphere.radius + (sphere.center - m.local_center).length();
        m.linvel.length() * window + radius * (m.angvel.abs() * window).min(2.0)
    };
    let both = reach(c.m1, &c.spheres[0]) + reach(c.m2, &c.spheres[1]);
    // A relative margin for the rounding of the distance and of the bound.
    let margin = 1e-9 * (c.size() + both);
    both.is_finite() && d0 - target > both + margin
}

/// A motion without its spin from `t0` on: the body translates from its pose at `t0` (the
/// rotation it has reached there kept), so that at `t0` it is where the whole motion puts it
/// and the start contact (taken on the whole motion at `t0`) is the translating pair's. With
/// the rotation at t = 0 instead, a window that does not start at 0 would translate a body
/// turned by ω·t₀ from where it is: the rule's levels would be searched in the wrong frame.
/// At t0 = 0 the motion is kept as it is (its pose at 0 is its start, to the bit).
fn spinless_from(m: &NonlinearRigidMotion, t0: Real) -> NonlinearRigidMotion {
    let start = if t0 == 0.0 || m.angvel == 0.0 {
        m.start
    } else {
        let p = m.position_at_time(t0);
        Pose::from_parts(p.translation - m.linvel * t0, p.rotation)
    };
    NonlinearRigidMotion {
        start,
        angvel: 0.0,
        ..*m
    }
}

/// The first time a level search of the translating pair `p` reports, with `general` for the
/// pairs the exact contact query does not read (the cast's own trackers).
fn first_time(
    p: &Translating,
    c: &NonlinearCast,
    level: Real,
    tol: Real,
    first: Option<Contact>,
    general: impl FnOnce() -> Result<TimeOfImpact, QueryError>,
) -> Result<Option<Real>, QueryError> {
    match translation_time_to_level(p, c.t0, c.t1, level, tol, first) {
        LevelTime::Reached(t) | LevelTime::Capped(t) => Ok(Some(t)),
        LevelTime::Never => Ok(None),
        LevelTime::Unread => general().map(|t| (t.status != ToiStatus::NoHit).then_some(t.time)),
    }
}

/// Rule 3 of the module docs for a cast whose shapes are at signed distance `d0` ≤ the contact
/// gap at its start (`k0`, their exact contact there when the contact query reads them): the
/// earlier of the core's contact and the translation's deepening below min(−A, d₀ − A), at
/// least [`CastPolicy::START_NUDGE`] of the window after the start. Both are first crossings of
/// a level by the signed distance of a translating pair, which is convex in time: Newton's
/// iteration from the left finds them exactly (`translation_level`). `level` answers for the
/// pairs the contact query does not read: the first time the signed distance of the pair
/// moving by the two given motions comes down to a level (the gap tracker, or the half-space
/// cast on a shifted plane); with `c.spin_at_start` it answers the deepening on the whole
/// motions ([`CastPolicy::RapierConstantSpin`]).
pub(crate) fn start_contact_answer(
    c: &NonlinearCast,
    d0: Real,
    k0: Option<Contact>,
    opts: &ToiOptions,
    level: impl Fn(&NonlinearRigidMotion, &NonlinearRigidMotion, Real) -> Result<TimeOfImpact, QueryError>,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    let f = fast(c);
    let r = inradius_about(f.g, f.m.local_center);
    let size = c.size();
    let window = c.t1 - c.t0;
    let nudge = c.t0 + CastPolicy::START_NUDGE * window;
    let tol = opts.distance_tolerance * size;
    // No point of a translating body moves further than this in the window.
    let travel = (c.m2.linvel - c.m1.linvel).length() * window;
    // The translation: the motions without their spins, down to min(−A, d₀ − A).
    let allowance = CastPolicy::ALLOWANCE * r.max(CastPolicy::START_CONTACT_GAP * size);
    let target = (-allowance).min(d0 - allowance);
    let (m1, m2) = (spinless_from(c.m1, c.t0), spinless_from(c.m2, c.t0));
    let side = k0.as_ref().and_then(|k| centre_side(c, k));
    let t_trans = if let (false, Some(k)) = (c.spin_at_start, side) {
        // A wall of no thickness with the body's centre on one side: the contact the manifold
        // gives the solver (`segment_side`), whose depth the translation changes linearly.
        let target = (-allowance).min(k.dist - allowance);
        Ok(line_time_to_level(c, &k, target))
    } else if c.spin_at_start {
        // The whole motions, rotation included, down to the same level.
        if out_of_reach(c, d0, target) {
            Ok(None)
        } else {
            level(c.m1, c.m2, target).map(|t| (t.status != ToiStatus::NoHit).then_some(t.time))
        }
    } else if travel < d0 - target {
        Ok(None)
    } else {
        let p = Translating {
            g1: c.g1,
            m1: &m1,
            g2: c.g2,
            m2: &m2,
        };
        first_time(&p, c, target, tol, k0, || level(&m1, &m2, target))
    };
    // The core: a disc about the rotation centre, moving with it (its spin does not move it).
    // Its centre is at least r + d₀ from the target (a point of the target is at most the
    // penetration depth inside the body), so it cannot reach the target before the pair's
    // relative travel covers (1 − CORE)·r + d₀.
    let t_core = if r <= 0.0 || (f.other_m.angvel == 0.0 && travel < (1.0 - CastPolicy::CORE) * r + d0) {
        Ok(None)
    } else {
        let core = Ball::new(CastPolicy::CORE * r);
        let centre = NonlinearRigidMotion::new(
            Pose::from_translation(f.m.start * f.m.local_center),
            Vector::ZERO,
            f.m.linvel,
            0.0,
        );
        let plain = ToiOptions {
            stop_at_penetration: false,
            path: MotionPath::ConstantSpin,
            ..*opts
        };
        let general = || super::cast::shape_time_of_impact(&core, &centre, f.other_g, f.other_m, c.t0, c.t1, &plain);
        // A point (the core's centre) entering a polygon or a disc grown by the core's radius
        // and level, in closed form (`disc_cast::core_entry`); other targets by the level
        // search of the translating core, or by the general cast when the target turns.
        if let Some(t) = super::disc_cast::core_entry(&centre, f.other_g, f.other_m, core.radius, (c.t0, c.t1), tol) {
            Ok(t)
        } else if f.other_m.angvel == 0.0 {
            let p = Translating {
                g1: &core,
                m1: &centre,
                g2: f.other_g,
                m2: f.other_m,
            };
            let k = exact_contact(&super::cast::pos12_at(&centre, f.other_m, c.t0), &core, f.other_g, None);
            first_time(
                &p,
                c,
                core_level(k.map(|k| k.dist), CastPolicy::CORE * r, tol),
                tol,
                k,
                general,
            )
        } else {
            general().map(|t| (t.status != ToiStatus::NoHit).then_some(t.time))
        }
    };
    let earliest = match (t_trans, t_core) {
        (Err(e), _) | (_, Err(e)) => return toi_to_parry(Err(e)),
        (Ok(a), Ok(b)) => match (a, b) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        },
    };
    toi_to_parry(earliest.map(|t| hit_at(c, t.max(nudge), d0)).transpose())
}

/// The start contact `k0` of a cast with a `Segment` (a wall of no thickness: standalone, or a
/// part of a polyline) taken from the side of the other body's centre, where it differs from
/// the exact contact (`segment_side`): the normal of the contact the manifold hands rapier's
/// solver, its depth measured on the segment's whole line — the body's reach past the line
/// (its support point along the normal), which is the manifold's where the body's deepest point
/// lies over the segment and deeper where it lies beyond an end, and which a translation changes
/// linearly. The exact contact of a body whose tip a spin has pushed past a wall near its end
/// (past the corner of a box of segments) is the segment's end inside the body, which a
/// translation *away* from the wall takes deeper; rule 3 on it stopped such a body at the start
/// of every step while the solver, on the contact from the centre's side, saw it leaving.
fn centre_side(c: &NonlinearCast, k0: &Contact) -> Option<Contact> {
    let pos12 = super::cast::pos12_at(c.m1, c.m2, c.t0);
    line_contact(k0, &pos12, c.g1, c.g2)
}

/// [`centre_side`] of the start contact `k0` of `g1` and `g2` at `pos12`. The side is that of
/// the body's centroid, as the manifold takes it (`core_of_any`: the same centre, not the
/// rotation centre of the cast's motion, which differs for a collider off its body's centre of
/// mass); `None` for two segments (neither has a side).
fn line_contact(k0: &Contact, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> Option<Contact> {
    use parry2d_f64::shape::Segment;
    let (seg1, seg2) = (g1.as_shape::<Segment>(), g2.as_shape::<Segment>());
    if seg1.is_some() == seg2.is_some() {
        return None;
    }
    let (core1, core2) = (core_of_any(g1)?, core_of_any(g2)?);
    let k = super::segment_side::centre_side_contact(k0, pos12, g1, g2, core1.centre, core2.centre)?;
    let n = k.normal;
    // The body's reach past the line along n (body 1's frame, from body 1 to body 2).
    let dist = match (seg1, seg2) {
        (_, Some(seg)) => {
            let p = g1.as_support_map()?.local_support_point(n);
            (*pos12 * seg.a - p).dot(n)
        }
        (Some(seg), None) => {
            let p = *pos12 * g2.as_support_map()?.local_support_point(pos12.rotation.inverse() * -n);
            (p - seg.a).dot(n)
        }
        (None, None) => return None,
    };
    dist.is_finite().then_some(Contact { dist, ..k })
}

/// The contact rule 3 measures a start contact of `g1` and `g2` (`g2` at `pos12` in `g1`'s frame)
/// on, where it is not the exact contact: against a `Segment`, the contact from the side of the other body's centre, its
/// depth on the segment's line ([`centre_side`]), as (its normal from `g1` to `g2` in `g1`'s
/// frame, its signed distance).
/// `None` where rule 3 reads the exact contact (or the contact query does not read the pair).
/// Not a public API: the judge of rapier's casts in `cargo bench --bench ratios -- rapier-casts`
/// reads which contact the rule takes, and times it with its own reference.
#[doc(hidden)]
pub fn rule3_line_contact(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> Option<(Vector, Real)> {
    // The start contact as rapier's fast path computes it (`cast::rapier_fast_path`).
    let (mut st1, mut st2) = (SupportScratch::default(), SupportScratch::default());
    let (s1, s2) = (support_shape(g1, &mut st1)?, support_shape(g2, &mut st2)?);
    let k0 = super::support_shape::exact_contact_of(s1, s2, pos12, None)?;
    line_contact(&k0, pos12, g1, g2).map(|k| (k.normal, k.dist))
}

/// The first time in the window at which the translations of the cast (its motions without
/// their spins) take the contact `k` from the centre's side ([`centre_side`], body 1's frame at
/// the start) down to `level`: its depth is how far the body reaches past the wall's line, its
/// support point along the line's normal fixed while it does not turn, so the signed distance
/// is d(t) = d₀ + ((R₁ᵀ(v₂ − v₁))·n)(t − t₀), R₁ body 1's rotation at the start, n the normal.
/// `None` when it stays above the level over the window (a body moving along or away from the
/// wall).
fn line_time_to_level(c: &NonlinearCast, k: &Contact, level: Real) -> Option<Real> {
    let r1 = c.m1.position_at_time(c.t0).rotation;
    let rate = (r1.inverse() * (c.m2.linvel - c.m1.linvel)).dot(k.normal);
    let dt = (level - k.dist) / rate;
    (rate < 0.0 && dt <= c.t1 - c.t0).then(|| c.t0 + dt.max(0.0))
}

/// The level the core's signed distance may come down to in a step (rule 3 of the module
/// docs), `start` its signed distance to the target at the start (`None`: a pair the contact
/// query does not read, level 0), `radius` the core's: 0, the core reaching the target, when the
/// core starts apart; when it starts touching or in — a body the solver has left jammed with
/// its core against a wall, a residual approach of a few cm/s across a motion of tens of m/s
/// along the wall — [`CastPolicy::ALLOWANCE`] of its radius below where it starts, never below
/// [`CORE_DEPTH_LIMIT`] of it. The body's centre then stays at least (1 − CORE_DEPTH_LIMIT) of
/// the core's radius off every target, and a jammed body moves on along the wall instead of
/// being clamped at the start of every step for an approach the step barely takes (the
/// 8:1 ellipse jammed across the acute wedge of the CCD scene suite was held still for ten
/// steps, its 55 m/s along the wall lost to 1 mm of approach).
/// The disc cast's closed form takes it too (`disc_cast`).
pub(crate) fn core_level(start: Option<Real>, radius: Real, tol: Real) -> Real {
    match start {
        Some(d) if d <= tol => (d.min(0.0) - CastPolicy::ALLOWANCE * radius).max(-CORE_DEPTH_LIMIT * radius),
        _ => 0.0,
    }
}

/// How deep, as a fraction of its radius, the core of a body that starts touching a target may
/// go into it ([`core_level`]).
pub(crate) const CORE_DEPTH_LIMIT: Real = 0.5;

/// The hit of a start contact at time `t`, with the pair's exact contact there for its
/// witnesses and distance (rapier reads only the time; the witnesses are the pair's own, in
/// each shape's frame), or the start's distance `d0` and no witnesses when the contact query
/// does not read the pair. [`QueryError::Degenerate`] when the pair's pose at `t` is not finite.
pub(crate) fn hit_at(c: &NonlinearCast, t: Real, d0: Real) -> Result<TimeOfImpact, QueryError> {
    let pos12 = super::cast::pos12_at(c.m1, c.m2, t);
    if !pos12.is_finite() {
        // The motions reach time `t` only by overflowing (a spin of 1e160 rad/s over a window
        // of 1e300 s): no pose, no witnesses.
        return Err(QueryError::Degenerate);
    }
    let k = exact_contact(&pos12, c.g1, c.g2, None);
    let (distance, point1, point2, normal1) = match &k {
        Some(k) => (
            k.dist,
            k.points[0].point1,
            pos12.inverse_transform_point(k.points[0].point2),
            k.normal,
        ),
        None => (d0, Vector::ZERO, Vector::ZERO, Vector::X),
    };
    Ok(TimeOfImpact {
        status: ToiStatus::PenetratingAtStart,
        time: t,
        distance,
        distance_rate: 0.0,
        point1,
        point2,
        normal1,
        normal2: pos12.rotation.inverse() * -normal1,
        cost: Default::default(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_two_moving_bodies_take_the_whole_motions_under_the_moving_pairs_policy() {
        let pose = Pose::translation(1.0, 2.0);
        let moving = NonlinearRigidMotion::new(pose, Vector::ZERO, Vector::new(1.0, 0.0), 0.0);
        let spinning = NonlinearRigidMotion::new(pose, Vector::ZERO, Vector::ZERO, 3.0);
        let still = NonlinearRigidMotion::constant_position(pose);
        let pass = CastPolicy::RapierConstantSpin;
        assert!(spin_at_start(pass, &moving, &spinning));
        assert!(spin_at_start(pass, &spinning, &moving));
        assert!(!spin_at_start(pass, &spinning, &still));
        assert!(!spin_at_start(pass, &still, &moving));
        for other in [CastPolicy::Rapier, CastPolicy::Plain] {
            assert!(!spin_at_start(other, &moving, &spinning));
        }
    }
}
