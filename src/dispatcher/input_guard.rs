//! Guards around the queries [`crate::SmoothDispatcher`] hands to parry's
//! `DefaultQueryDispatcher` (pairs with no strictly convex side, parry's own pairs, shapes a
//! curve could not be built from).
//!
//! parry asserts that margins are non-negative (`closest_points` of two balls, of a half-space),
//! asserts inside GJK that support points are finite, and otherwise passes NaN and infinities
//! through to its answers. The dispatcher answers `Err(Unsupported)` instead, so that no query
//! through it panics on bad numbers or returns a non-finite value:
//!
//! * before parry runs: `pos12` not finite, beyond ±1e100, or its rotation not a unit complex
//!   number (to 1e-6), a shape whose local bounding box is not finite, beyond ±1e100 or inverted
//!   (a negative size), or a margin (prediction, `max_dist`) that is negative or NaN;
//! * after: any non-finite number in parry's answer.

use crate::numerics::math::{Pose, Real};
use crate::numerics::motion::motion_is_finite;
use parry2d_f64::query::{NonlinearRigidMotion, Unsupported};
use parry2d_f64::shape::{Shape, ShapeType};

/// The largest coordinate (of a pose's translation, of a shape's bounding box) handed to parry:
/// its GJK squares and sums coordinates, and asserts that the results are finite.
pub(crate) const PARRY_MAX_COORDINATE: Real = 1e100;

/// A pose parry can use: finite, within ±[`PARRY_MAX_COORDINATE`], with a unit rotation (to
/// 1e-6).
pub(crate) fn pose_ok(p: &Pose) -> bool {
    let r = p.rotation;
    p.is_finite()
        && p.translation.x.abs().max(p.translation.y.abs()) <= PARRY_MAX_COORDINATE
        && ((r.re * r.re + r.im * r.im) - 1.0).abs() <= 1e-6
}

/// Shapes parry can use: local bounding boxes finite, within ±[`PARRY_MAX_COORDINATE`] (a
/// half-space's is a placeholder and is not checked) and not inverted (a parry shape built with
/// a negative size has `mins > maxs`, and a negative `ccd_thickness` that makes parry's
/// nonlinear cast walk backwards for ever).
pub(crate) fn shapes_ok(g1: &dyn Shape, g2: &dyn Shape) -> bool {
    shapes_ok_typed(g1, g1.shape_type(), g2, g2.shape_type())
}

/// [`shapes_ok`] for shapes whose types (`t1`, `t2`) the caller already has.
pub(crate) fn shapes_ok_typed(g1: &dyn Shape, t1: ShapeType, g2: &dyn Shape, t2: ShapeType) -> bool {
    shape_ok(g1, t1) && shape_ok(g2, t2)
}

/// One shape of [`shapes_ok`], of type `t`.
pub(crate) fn shape_ok(g: &dyn Shape, t: ShapeType) -> bool {
    if t == ShapeType::HalfSpace {
        return g
            .as_shape::<parry2d_f64::shape::HalfSpace>()
            .is_some_and(|hs| hs.normal.is_finite());
    }
    let a = g.compute_local_aabb();
    let m = a.mins.abs().max(a.maxs.abs());
    a.mins.is_finite()
        && a.maxs.is_finite()
        && m.x.max(m.y) <= PARRY_MAX_COORDINATE
        && a.mins.x <= a.maxs.x
        && a.mins.y <= a.maxs.y
}

/// [`shapes_ok`] for one of parry's boxes, read in place: half extents in `[0, PARRY_MAX_COORDINATE]`
/// (NaN fails the comparisons).
#[inline]
pub(crate) fn cuboid_ok(c: &parry2d_f64::shape::Cuboid) -> bool {
    let h = c.half_extents;
    (0.0..=PARRY_MAX_COORDINATE).contains(&h.x) && (0.0..=PARRY_MAX_COORDINATE).contains(&h.y)
}

/// [`shapes_ok`] for one of parry's discs, read in place: radius in `[0, PARRY_MAX_COORDINATE]`.
#[inline]
pub(crate) fn ball_ok(b: &parry2d_f64::shape::Ball) -> bool {
    (0.0..=PARRY_MAX_COORDINATE).contains(&b.radius)
}

pub(crate) use crate::error::AllFinite;

/// Implements the trait `$finite` (one method, `fn all_finite(&self) -> bool`: every number in the
/// answer is finite) for the answers of the `$parry` crate's queries: intersection, distance,
/// contact, closest points, cast hit, contact manifold, and an `Option` of any of them. Written
/// once for parry2d-f64 (here) and parry2d (the f32 package's guards); not a public API.
#[doc(hidden)]
#[macro_export]
macro_rules! all_finite_impls {
    ($parry:ident, $finite:path) => {
        impl $finite for $parry::query::ShapeIntersection {
            #[inline]
            fn all_finite(&self) -> bool {
                true
            }
        }

        impl $finite for $parry::query::ShapeDistance {
            #[inline]
            fn all_finite(&self) -> bool {
                self.distance.is_finite()
            }
        }

        impl $finite for $parry::query::Contact {
            #[inline]
            fn all_finite(&self) -> bool {
                self.dist.is_finite()
                    && self.point1.is_finite()
                    && self.point2.is_finite()
                    && self.normal1.is_finite()
                    && self.normal2.is_finite()
            }
        }

        impl $finite for $parry::query::ClosestPoints {
            #[inline]
            fn all_finite(&self) -> bool {
                match self {
                    $parry::query::ClosestPoints::WithinMargin(a, b) => a.is_finite() && b.is_finite(),
                    _ => true,
                }
            }
        }

        impl $finite for $parry::query::ShapeCastHit {
            #[inline]
            fn all_finite(&self) -> bool {
                self.time_of_impact.is_finite()
                    && self.witness1.is_finite()
                    && self.witness2.is_finite()
                    && self.normal1.is_finite()
                    && self.normal2.is_finite()
            }
        }

        impl<M, C> $finite for $parry::query::ContactManifold<M, C> {
            #[inline]
            fn all_finite(&self) -> bool {
                (self.points.is_empty() || (self.local_n1.is_finite() && self.local_n2.is_finite()))
                    && self
                        .points
                        .iter()
                        .all(|c| c.local_p1.is_finite() && c.local_p2.is_finite() && c.dist.is_finite())
            }
        }

        impl<T: $finite> $finite for Option<T> {
            #[inline]
            fn all_finite(&self) -> bool {
                self.as_ref().is_none_or(<T as $finite>::all_finite)
            }
        }
    };
}

all_finite_impls!(parry2d_f64, AllFinite);

/// Runs parry's `query` on `(pos12, g1, g2)` with `margin` (0 when the query has none) under
/// the guards of the module docs.
pub(crate) fn parry<T: AllFinite>(
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    margin: Real,
    query: impl FnOnce() -> Result<T, Unsupported>,
) -> Result<T, Unsupported> {
    if !(margin >= 0.0 && pose_ok(pos12) && shapes_ok(g1, g2)) {
        return Err(Unsupported);
    }
    let r = query()?;
    if r.all_finite() {
        Ok(r)
    } else {
        Err(Unsupported)
    }
}

/// `r`, or `Unsupported` when it holds a non-finite number.
pub(crate) fn finite<T: AllFinite>(r: Result<T, Unsupported>) -> Result<T, Unsupported> {
    match r {
        Ok(v) if !v.all_finite() => Err(Unsupported),
        r => r,
    }
}

/// Whether every pose of the finite motion `m` at the times `t0` and `t1` is one [`pose_ok`]
/// accepts, shown without computing them (a sufficient test, no sine or cosine): the pose at t
/// puts the origin at c + v·t + R(ω·t)·(x₀ − c), c = x₀ + R₀·ℓ the rotation centre (x₀ the start's
/// translation, ℓ the local centre), so each coordinate is at most |x₀| + 2|ℓ| + |v|·|t|, kept
/// below [`PARRY_MAX_COORDINATE`] with a margin for rounding; its rotation R₀·R(ω·t) is a
/// product of unit complex numbers, unit to rounding, when ω·t is finite (a start rotation
/// [`pose_ok`] accepted). `false` says nothing: the caller computes the poses.
fn poses_within_range(m: &NonlinearRigidMotion, t0: Real, t1: Real) -> bool {
    position_bound(m, t0, t1) <= 0.5 * PARRY_MAX_COORDINATE && (m.angvel * t0.abs().max(t1.abs())).is_finite()
}

/// A bound on the coordinates of the origin of the body moving by `m` at the times `t0` and
/// `t1` and between: |x₀| + 2|ℓ| + |v|·max(|t₀|, |t₁|) ([`poses_within_range`]).
fn position_bound(m: &NonlinearRigidMotion, t0: Real, t1: Real) -> Real {
    m.start.translation.length() + 2.0 * m.local_center.length() + m.linvel.length() * t0.abs().max(t1.abs())
}

/// The guards of a nonlinear cast handed to parry (`parry_cast_nonlinear`, and the composite
/// helper, which casts bounding balls itself): [`cast_input_ok`], then windows parry would need
/// more than [`super::SmoothDispatcher::PARRY_MAX_STEPS`] steps, turns or travels to cross
/// ([`parry_steps_ok`]); `Ok(false)` for a reversed window (no hit); `Ok(true)` to go on.
pub(crate) fn cast_window_ok(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
) -> Result<bool, Unsupported> {
    if !cast_input_ok(m1, g1, m2, g2, t0, t1)? {
        return Ok(false);
    }
    parry_steps_ok(m1, g1, m2, g2, t0, t1).map(|()| true)
}

/// The guards of any nonlinear cast's input: `Unsupported` for non-finite motions or times,
/// poses and shapes refused by [`pose_ok`] and [`shapes_ok`], positions leaving the range within
/// the window; `Ok(false)` for a reversed window (no hit); `Ok(true)` to go on. A cast of the
/// parts of a composite at rest, each by this dispatcher (`composite::composite_cast_nonlinear`),
/// takes these only: the parts' casts bound their own work, and parry's step count does not
/// apply (a sliver of 1:1000 spinning at 1 rad/s fell through a polyline at 400 m/s, refused).
pub(crate) fn cast_input_ok(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
) -> Result<bool, Unsupported> {
    if !(motion_is_finite(m1) && motion_is_finite(m2) && t0.is_finite() && t1.is_finite()) {
        return Err(Unsupported);
    }
    if !(pose_ok(&m1.start) && pose_ok(&m2.start) && shapes_ok(g1, g2)) {
        return Err(Unsupported);
    }
    if t1 < t0 {
        return Ok(false);
    }
    // Motions that leave f64's range within the window (1e300 m/s for 1e300 s) have no poses.
    let poses_ok = |m: &NonlinearRigidMotion| {
        poses_within_range(m, t0, t1) || (pose_ok(&m.position_at_time(t0)) && pose_ok(&m.position_at_time(t1)))
    };
    if !(poses_ok(m1) && poses_ok(m2)) {
        return Err(Unsupported);
    }
    Ok(true)
}

/// The step bound of a cast handed to parry ([`cast_window_ok`]): `Unsupported` for a window
/// parry's conservative advancement would need more than
/// [`super::SmoothDispatcher::PARRY_MAX_STEPS`] steps, turns or travels (in sizes) to cross.
fn parry_steps_ok(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
) -> Result<(), Unsupported> {
    if t1 > t0 {
        let inv = |x: Real| if x == 0.0 { 0.0 } else { 1.0 / x };
        let lin = (g1.ccd_thickness() + g2.ccd_thickness()) * inv((m2.linvel - m1.linvel).length());
        let max_ang = g1.ccd_angular_thickness().max(g2.ccd_angular_thickness());
        let ang = (core::f64::consts::PI - max_ang) * inv((m2.angvel - m1.angvel).abs());
        let step = ang.min(lin).min((t1 - t0) / 10.0);
        // A negative step (a shape with a negative size, an angular thickness above π) walks
        // backwards for ever.
        let few_steps = (t1 - t0) / step <= super::SmoothDispatcher::PARRY_MAX_STEPS;
        if step < 0.0 || (step != 0.0 && !few_steps) {
            return Err(Unsupported);
        }
        // parry's conservative advancement (no contact at the start) takes steps of about the
        // distance over the approach speed: bound the relative turns and the travel in sizes.
        let size = g1.compute_local_bounding_sphere().radius + g2.compute_local_bounding_sphere().radius;
        let turns = (m2.angvel - m1.angvel).abs() * (t1 - t0) / core::f64::consts::TAU;
        let travel = (m2.linvel - m1.linvel).length() * (t1 - t0) / size;
        if !(turns <= super::SmoothDispatcher::PARRY_MAX_STEPS
            && (travel <= super::SmoothDispatcher::PARRY_MAX_STEPS || size.is_nan()))
        {
            return Err(Unsupported);
        }
    }
    Ok(())
}

/// The rounding of positions a parry cast may meet, as a fraction of the pair's size, beyond
/// which the pair is not resolved ([`resolved_motions`]).
const RESOLUTION: Real = 1e-3;

/// The motions to hand a parry cast that [`cast_window_ok`] accepted, such that rounding of the
/// positions it computes stays below [`RESOLUTION`] of the pair's size (the sum of the bounding
/// radii): positions of 1e19 m (1e20 m/s over a window) round by 1e3 m, and parry's advancement,
/// its steps moved by that rounding, may never settle (fuzz seed 5032, case 79067: two bodies
/// of 0.1 m side by side at 1e20 m/s).
///
/// * Resolved as given: the motions, unchanged.
/// * Else, where one body does not turn (ω = 0), both motions seen from that body's
///   translation (its start translation and velocity taken off both): the same relative motion
///   (a pose T(x₀ + v·t)·R, with R constant, composes with the other's as the shift of both by
///   −(x₀ + v·t)), the same answer, and positions the size of the pair's separation.
/// * Else, where the rotation centres' straight paths (c₂ − c₁)(t) stay further apart over the
///   window than the bodies' reach about them (bounding radius plus the sphere's offset from the
///   rotation centre) and the rounding: `Ok(None)`, no hit.
/// * Else `Unsupported`.
pub(crate) fn resolved_motions(
    m1: &NonlinearRigidMotion,
    g1: &dyn Shape,
    m2: &NonlinearRigidMotion,
    g2: &dyn Shape,
    t0: Real,
    t1: Real,
) -> Result<Option<(NonlinearRigidMotion, NonlinearRigidMotion)>, Unsupported> {
    let (b1, b2) = (g1.compute_local_bounding_sphere(), g2.compute_local_bounding_sphere());
    let size = b1.radius + b2.radius;
    let far = |m: &NonlinearRigidMotion| position_bound(m, t0, t1);
    let rounding = |a: &NonlinearRigidMotion, b: &NonlinearRigidMotion| far(a).max(far(b)) * Real::EPSILON;
    // A size that is not a number (a shape parry reads so) passes as before.
    let resolved =
        |a: &NonlinearRigidMotion, b: &NonlinearRigidMotion| rounding(a, b) <= RESOLUTION * size || size.is_nan();
    if resolved(m1, m2) {
        return Ok(Some((*m1, *m2)));
    }
    // Seen from a body that does not turn.
    let from = |still: &NonlinearRigidMotion| {
        let (x, v) = (still.start.translation, still.linvel);
        let shift = |m: &NonlinearRigidMotion| {
            NonlinearRigidMotion::new(
                Pose::from_parts(m.start.translation - x, m.start.rotation),
                m.local_center,
                m.linvel - v,
                m.angvel,
            )
        };
        (shift(m1), shift(m2))
    };
    for still in [m2, m1] {
        if still.angvel == 0.0 {
            let (a, b) = from(still);
            if resolved(&a, &b) {
                return Ok(Some((a, b)));
            }
        }
    }
    // The rotation centres' closest approach over the window.
    let centre = |m: &NonlinearRigidMotion| m.start * m.local_center;
    let (d0, dv) = (centre(m2) - centre(m1), m2.linvel - m1.linvel);
    let v2 = dv.length_squared();
    let tc = if v2 > 0.0 { (-d0.dot(dv) / v2).clamp(t0, t1) } else { t0 };
    let closest = (d0 + dv * tc).length();
    let reach = b1.radius + (b1.center - m1.local_center).length() + b2.radius + (b2.center - m2.local_center).length();
    if closest - reach > 4.0 * rounding(m1, m2) {
        return Ok(None);
    }
    Err(Unsupported)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::math::Vector;
    use parry2d_f64::shape::{Ball, Cuboid};

    /// The guards read off a box's or a disc's fields ([`cuboid_ok`], [`ball_ok`]) refuse exactly
    /// what the shared bounding-box guard ([`shape_ok`]) refuses: signed zeros, tiny, huge,
    /// negative, infinite and NaN sizes.
    #[test]
    fn the_field_guards_agree_with_the_bounding_box_guard() {
        let sizes = [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            1e-300,
            0.5,
            -0.5,
            1e100,
            1.0000000000000002e100,
            -1e100,
            f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        let mut checked = 0;
        for &a in &sizes {
            let ball = Ball::new(a);
            assert_eq!(ball_ok(&ball), shape_ok(&ball, ShapeType::Ball), "radius {a}");
            for &b in &sizes {
                let c = Cuboid::new(Vector::new(a, b));
                assert_eq!(cuboid_ok(&c), shape_ok(&c, ShapeType::Cuboid), "half extents {a}, {b}");
                checked += 1;
            }
        }
        assert!(sizes.iter().any(|&a| !ball_ok(&Ball::new(a))) && ball_ok(&Ball::new(0.5)));
        assert_eq!(checked, sizes.len() * sizes.len());
    }

    /// The bound [`poses_within_range`] accepts only motions whose poses at both ends of the
    /// window [`pose_ok`] accepts (the test it saves), from ordinary motions to ones that leave
    /// the coordinate range within the window.
    #[test]
    fn poses_within_range_implies_the_computed_poses_are_ok() {
        let mut rng = crate::numerics::test_rng::Lcg(0x0123_4567_89AB_CDEFu64);
        let (mut accepted, mut refused) = (0, 0);
        for _ in 0..20_000 {
            let scale = 10f64.powf(rng.range(-3.0, 104.0));
            let mut v = || rng.range(-1.0, 1.0) * scale;
            let start = Pose::new(Vector::new(v(), v()), 0.7);
            let m = NonlinearRigidMotion::new(start, Vector::new(v(), v()), Vector::new(v(), v()), v());
            let (t0, t1) = (0.0, 10f64.powf(rng.range(-3.0, 3.0)));
            if poses_within_range(&m, t0, t1) {
                accepted += 1;
                assert!(
                    pose_ok(&m.position_at_time(t0)) && pose_ok(&m.position_at_time(t1)),
                    "{m:?} over [{t0}, {t1}]"
                );
            } else {
                refused += 1;
            }
        }
        println!("{accepted} motions within range by the bound, {refused} left to the computed poses");
        assert!(accepted > 1000 && refused > 500, "{accepted} {refused}");
    }

    /// The motions a parry cast gets: as given where rounding resolves the pair; seen from the
    /// body that does not turn where it does not (the same relative poses at every time, to the
    /// rounding of the smaller coordinates); no hit where both turn and stay far apart; refused
    /// where both turn side by side at coordinates that rounding blurs.
    #[test]
    fn parry_casts_get_positions_that_rounding_resolves() {
        let (a, b) = (Ball::new(0.05), Cuboid::new(Vector::new(0.1, 0.02)));
        let motion = |x: Vector, v: Vector, w: Real| NonlinearRigidMotion::new(Pose::new(x, 0.3), Vector::ZERO, v, w);
        // Ordinary positions: unchanged.
        let (m1, m2) = (
            motion(Vector::new(1.0, 2.0), Vector::X, 3.0),
            motion(Vector::ZERO, Vector::Y, 0.0),
        );
        let (r1, r2) = resolved_motions(&m1, &a, &m2, &b, 0.0, 1.0).unwrap().unwrap();
        assert_eq!(
            (r1.start, r1.linvel, r2.start, r2.linvel),
            (m1.start, m1.linvel, m2.start, m2.linvel)
        );
        // Side by side at 1e20 m/s, the box not turning: seen from the box.
        let fast = Vector::new(1e20, 0.0);
        let (m1, m2) = (
            motion(Vector::new(0.0, 0.3), fast + Vector::new(0.0, -0.5), 3.0),
            motion(Vector::ZERO, fast, 0.0),
        );
        let (r1, r2) = resolved_motions(&m1, &a, &m2, &b, 0.0, 1.0).unwrap().unwrap();
        assert_eq!((r2.start.translation, r2.linvel), (Vector::ZERO, Vector::ZERO));
        for k in 0..=4 {
            let t = k as Real / 4.0;
            let rel = r1.position_at_time(t).inv_mul(&r2.position_at_time(t));
            // The relative pose in closed form: the ball's centre at (0, 0.3 − 0.5·t) turned by
            // 0.3 + 3t, the box at the origin turned by 0.3.
            let want = Pose::new(Vector::new(0.0, 0.3 - 0.5 * t), 0.3 + 3.0 * t).inv_mul(&Pose::new(Vector::ZERO, 0.3));
            assert!(
                (rel.translation - want.translation).length() < 1e-12,
                "{t}: {rel:?} vs {want:?}"
            );
        }
        // Both turning at 1e20 m/s (positions round by 2e4 m): 1e6 m apart, no hit; 1e3 m apart
        // or side by side, refused.
        let (m1, m2) = (
            motion(Vector::new(0.0, 1e6), fast, 3.0),
            motion(Vector::ZERO, fast, 2.0),
        );
        assert_eq!(
            resolved_motions(&m1, &a, &m2, &b, 0.0, 1.0).map(|r| r.is_none()),
            Ok(true)
        );
        for gap in [1e3, 0.1] {
            let (m1, m2) = (
                motion(Vector::new(0.0, gap), fast, 3.0),
                motion(Vector::ZERO, fast, 2.0),
            );
            assert!(resolved_motions(&m1, &a, &m2, &b, 0.0, 1.0).is_err(), "{gap}");
        }
    }
}
