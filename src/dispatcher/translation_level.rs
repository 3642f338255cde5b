//! The first time two *translating* shapes come down to a level of signed distance: Newton's
//! iteration from the left on a convex function, for rapier's rule at a start contact
//! (`rapier_rule`).
//!
//! # Why it is exact
//!
//! Under translations alone the signed distance of two convex shapes A and B is a convex
//! function of time. By the separating-axis theorem it is the largest separation over unit
//! directions n,
//!
//!   D(t) = max over n of [ min over b ∈ B(t) of n·b − max over a ∈ A(t) of n·a ],
//!
//! the Euclidean distance when the shapes are apart and minus the penetration depth when they
//! overlap; when both shapes translate, each term is affine in t, and a maximum of affine
//! functions is convex. A tangent of a convex function lies below it, so from a time t where D
//! is above the level L, Newton's step
//!
//!   t ← t + (D(t) − L) / (−D′(t)),   D′(t) = n(t)·(v₂ − v₁)
//!
//! (n(t) the contact normal from shape 1 to shape 2, v₁ and v₂ the velocities) never passes
//! the first time D reaches L: D > L on the whole step. The iterates rise monotonically to that
//! time, quadratically where D is smooth and in finitely many steps where it is piecewise
//! affine (a corner against a flat side); at a kink any subgradient keeps the property. When
//! D′(t) ≥ 0 the minimum of D is behind: D never comes down to L; a step past the window's end
//! means it does not within the window.
//!
//! Each iterate costs one exact contact query (`query::contact`); pairs that query does not read
//! (custom curves, two curved sides of ellipses) are [`LevelTime::Unread`], for the caller's
//! general search.

use super::support_shape::{support_shape, SupportScratch};
use crate::numerics::math::{Pose, Real, Vector};
use crate::query::contact::{contact, Contact, SupportShape};
use parry2d_f64::query::NonlinearRigidMotion;
use parry2d_f64::shape::Shape;

/// Newton iterations of one search at most (it takes 1 to 6 on rapier's scenes; a level met
/// tangentially converges linearly, halving the gap to the crossing each iteration).
pub(crate) const LEVEL_MAX_ITERATIONS: usize = 64;

/// The contact query's cosine between facing faces that asks for no second point.
const NO_SECOND_POINT: Real = 2.0;

/// What [`translation_time_to_level`] found.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) enum LevelTime {
    /// D comes down to the level (within the tolerance) at this time, and is above it before
    /// (the window's start when it is there already and coming down).
    Reached(Real),
    /// D stays above the level over the window.
    Never,
    /// [`LEVEL_MAX_ITERATIONS`] ran out at this time: D is above the level until then.
    Capped(Real),
    /// The exact contact query does not read this pair (or a value was not finite).
    Unread,
}

/// The two shapes of a search, each read once (support shapes) with its translating motion.
pub(crate) struct Translating<'a> {
    /// Shape 1 and its motion (its spin ignored: a translation).
    pub g1: &'a dyn Shape,
    pub m1: &'a NonlinearRigidMotion,
    /// Shape 2 and its motion (its spin ignored).
    pub g2: &'a dyn Shape,
    pub m2: &'a NonlinearRigidMotion,
}

impl Translating<'_> {
    /// Shape 2's pose in shape 1's frame at `t` (the start rotations kept).
    fn pos12(&self, t: Real) -> Pose {
        let at = |m: &NonlinearRigidMotion| Pose::from_parts(m.start.translation + m.linvel * t, m.start.rotation);
        at(self.m1).inv_mul(&at(self.m2))
    }

    /// v₂ − v₁ in shape 1's frame: the rate of pos12's translation.
    fn local_velocity(&self) -> Vector {
        self.m1.start.rotation.inverse() * (self.m2.linvel - self.m1.linvel)
    }
}

/// The first time in `[t0, t1]` at which the signed distance of the translating pair `p` comes
/// down to `level` (within `tol` above it), by Newton's iteration from the left (module docs).
/// `first`, the pair's exact contact at `t0` when the caller has it.
pub(crate) fn translation_time_to_level(
    p: &Translating,
    t0: Real,
    t1: Real,
    level: Real,
    tol: Real,
    first: Option<Contact>,
) -> LevelTime {
    let (mut st1, mut st2) = (SupportScratch::default(), SupportScratch::default());
    let (Some(s1), Some(s2)) = (support_shape(p.g1, &mut st1), support_shape(p.g2, &mut st2)) else {
        return LevelTime::Unread;
    };
    descend(s1, s2, p, t0, t1, level, tol, first)
}

/// [`translation_time_to_level`] of two shapes already read.
#[allow(clippy::too_many_arguments)]
fn descend(
    s1: SupportShape,
    s2: SupportShape,
    p: &Translating,
    t0: Real,
    t1: Real,
    level: Real,
    tol: Real,
    first: Option<Contact>,
) -> LevelTime {
    let w = p.local_velocity();
    if !(w.is_finite() && level.is_finite() && tol >= 0.0) {
        return LevelTime::Unread;
    }
    let mut t = t0;
    let mut k = first;
    for _ in 0..LEVEL_MAX_ITERATIONS {
        let c = match k.take() {
            Some(c) => c,
            // The distance and normal only: no second manifold point (a cosine above 1).
            None => match contact(s1, s2, &p.pos12(t), NO_SECOND_POINT, None) {
                Some(c) => c,
                None => return LevelTime::Unread,
            },
        };
        let gap = c.dist - level;
        let rate = c.normal.dot(w);
        if !(gap.is_finite() && rate.is_finite()) {
            return LevelTime::Unread;
        }
        if gap <= tol {
            // At the level (or below it, at the start only): reached if coming down.
            return if t > t0 || rate < 0.0 {
                LevelTime::Reached(t)
            } else {
                LevelTime::Never
            };
        }
        if rate >= 0.0 {
            return LevelTime::Never;
        }
        let next = t + gap / -rate;
        // Past the window (or not a number): no crossing within it.
        if next > t1 || next.is_nan() {
            return LevelTime::Never;
        }
        if next <= t {
            // No progress in floating point: the crossing is here, to rounding.
            return LevelTime::Reached(t);
        }
        t = next;
    }
    LevelTime::Capped(t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Ellipse, RoundedPolygon};
    use parry2d_f64::query::DefaultQueryDispatcher;
    use parry2d_f64::query::QueryDispatcher as _;
    use parry2d_f64::shape::{Ball, Cuboid, Segment};

    fn motion(x: Real, y: Real, angle: Real, vx: Real, vy: Real) -> NonlinearRigidMotion {
        NonlinearRigidMotion::new(
            Pose::new(Vector::new(x, y), angle),
            Vector::ZERO,
            Vector::new(vx, vy),
            0.0,
        )
    }

    /// A disc falling onto a box: the closed form of a constant rate.
    #[test]
    fn disc_onto_a_box_reaches_each_level_at_the_closed_form_time() {
        let disc = Ball::new(0.5);
        let floor = Cuboid::new(Vector::new(5.0, 0.5));
        let m1 = motion(0.3, 2.0, 0.0, 1.0, -2.0);
        let m2 = motion(0.0, 0.0, 0.0, 0.0, 0.0);
        let p = Translating {
            g1: &disc,
            m1: &m1,
            g2: &floor,
            m2: &m2,
        };
        for level in [0.5, 0.0, -0.25] {
            let LevelTime::Reached(t) = translation_time_to_level(&p, 0.0, 2.0, level, 1e-12, None) else {
                panic!("level {level}");
            };
            assert!((t - (1.0 - level) / 2.0).abs() < 1e-12, "level {level}: {t}");
        }
        assert_eq!(
            translation_time_to_level(&p, 0.0, 0.4, 0.0, 1e-12, None),
            LevelTime::Never
        );
    }

    /// A thin ellipse turned off its axes sliding past the corner of a box, then a sliver
    /// against a segment: the answer against dense sampling of parry's signed distance (the
    /// first sample at or below the level is within a sample after the answer), and parry's
    /// distance on each side of it.
    #[test]
    fn first_crossing_agrees_with_dense_sampling_of_parrys_distance() {
        type Case = (
            Box<dyn Shape>,
            Box<dyn Shape>,
            NonlinearRigidMotion,
            NonlinearRigidMotion,
        );
        let cases: Vec<Case> = vec![
            (
                Box::new(Ellipse::new(0.4, 0.05)),
                Box::new(Cuboid::new(Vector::new(1.0, 1.0))),
                motion(-2.0, 1.3, 0.7, 3.0, -0.5),
                motion(0.0, 0.0, 0.2, 0.0, 0.0),
            ),
            (
                Box::new(RoundedPolygon::new(
                    &[Vector::new(-0.5, 0.0), Vector::new(-0.25, 0.0), Vector::new(0.5, 0.125)],
                    0.0,
                )),
                Box::new(Segment::new(Vector::new(-3.0, 0.0), Vector::new(3.0, 0.5))),
                motion(-1.0, 1.0, 2.0, 1.5, -2.0),
                motion(0.0, 0.0, 0.0, 0.0, 0.0),
            ),
        ];
        let mut reached = 0;
        for (g1, g2, m1, m2) in &cases {
            let p = Translating {
                g1: &**g1,
                m1,
                g2: &**g2,
                m2,
            };
            // parry's distance apart, its contact's depth in overlap (GJK and EPA).
            let signed = |t: Real| {
                let pos12 = p.pos12(t);
                let d = DefaultQueryDispatcher.distance(&pos12, &**g1, &**g2).unwrap().distance;
                if d > 0.0 {
                    d
                } else {
                    DefaultQueryDispatcher
                        .contact(&pos12, &**g1, &**g2, 1.0)
                        .unwrap()
                        .map_or(0.0, |c| c.dist.min(0.0))
                }
            };
            for level in [0.05, 0.0, -0.02] {
                let n = 20_000;
                let first = (0..=n).map(|i| i as Real / n as Real).find(|&t| signed(t) <= level);
                match translation_time_to_level(&p, 0.0, 1.0, level, 1e-12, None) {
                    LevelTime::Reached(t) => {
                        reached += 1;
                        let s = first.expect("sampling reaches the level");
                        assert!(
                            s >= t - 1e-9 && s <= t + 1.0 / n as Real + 1e-9,
                            "level {level}: {t} vs {s}"
                        );
                        // Above the level just before, below it just after.
                        assert!(
                            signed(t - 1e-6) > level && signed(t + 1e-6) < level,
                            "level {level} at {t}"
                        );
                    }
                    LevelTime::Never => assert!(first.is_none(), "level {level}: sampled at {first:?}"),
                    other => panic!("{other:?}"),
                }
            }
        }
        assert!(reached >= 4, "{reached}");
    }

    #[test]
    fn leaving_or_sliding_contacts_never_reach_a_deeper_level() {
        let sq = RoundedPolygon::regular(4, 0.5, 0.0);
        let seg = Segment::new(Vector::new(-10.0, 0.0), Vector::new(10.0, 0.0));
        let m2 = motion(0.0, 0.0, 0.0, 0.0, 0.0);
        // Resting 0.01 deep on its flat side (turned by π/4), sliding, then rising.
        let y = 0.5 * core::f64::consts::FRAC_1_SQRT_2 - 0.01;
        for v in [Vector::new(-50.0, 0.0), Vector::new(3.0, 1.0)] {
            let m1 = motion(0.0, y, core::f64::consts::FRAC_PI_4, v.x, v.y);
            let p = Translating {
                g1: &sq,
                m1: &m1,
                g2: &seg,
                m2: &m2,
            };
            assert_eq!(
                translation_time_to_level(&p, 0.0, 1.0, -0.1, 1e-12, None),
                LevelTime::Never
            );
        }
    }
}
