//! The path a pair's bodies take over a query's window ([`MotionPath`]): parry's
//! `NonlinearRigidMotion` as it is, or the nlerp path between the poses it reaches at the
//! window's ends — parry's `Sweep` interpolation, on which rapier clamps a body after its CCD.
//!
//! The trackers run on motions with uniform rotation; the nlerp path is one of those on a
//! translation clock (`numerics::clock`). [`OnPath`] turns a query's motions into the motions
//! and clock a tracker runs on, and its answer back into the path's own time.

use crate::error::QueryError;
use crate::numerics::angle::wrap_phi;
use crate::numerics::clock::{Clock, NLERP_HALF_TURN};
use crate::query::toi::TimeOfImpact;
use core::f64::consts::PI;
use parry2d_f64::query::NonlinearRigidMotion;

/// The path each body takes between the poses at the ends of a query's window
/// ([`crate::ToiOptions::path`]).
///
/// ```
/// use parry2d_f64::math::{Pose, Vector};
/// use parry2d_f64::query::NonlinearRigidMotion;
/// use smooth_ccd2d::{time_of_impact, Ellipse, MotionPath, ToiOptions};
///
/// // A thin ellipse turning by 1.5 rad over the window while flying at a disc.
/// let e = Ellipse::new(1.0, 0.1);
/// let disc = Ellipse::new(0.2, 0.2);
/// let m1 = NonlinearRigidMotion::new(Pose::translation(-2.0, 0.0), Vector::ZERO, Vector::new(2.5, 0.0), 1.5);
/// let m2 = NonlinearRigidMotion::constant_position(Pose::translation(0.0, 0.5));
/// let spin = time_of_impact(&e, &m1, &disc, &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
/// let opts = ToiOptions::default().with_path(MotionPath::Nlerp);
/// let nlerp = time_of_impact(&e, &m1, &disc, &m2, 0.0, 1.0, &opts).unwrap();
/// // Same end poses, different paths in between: different first contacts.
/// assert!((spin.time - nlerp.time).abs() > 1e-3);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum MotionPath {
    /// parry's `NonlinearRigidMotion`: the rotation centre at constant velocity, the body at
    /// constant angular velocity (the default).
    #[default]
    ConstantSpin,
    /// The interpolation between the poses the motion reaches at the window's ends, as parry's
    /// `Sweep::transform_at` does and rapier applies when its CCD clamps a body: at the fraction
    /// s of the window the rotation centre is at the fraction s of its straight segment and the
    /// rotation is the normalised linear interpolation (nlerp) of the end rotations — the short
    /// way round, so a motion turning by more than half a turn over the window takes the other
    /// way. Within 10⁻⁶ rad of a half turn, the path of a turn of π − 10⁻⁶ is taken (nlerp is
    /// undefined at π, and its rotation jumps in the middle of the window as the turn nears π):
    /// there the rotation differs from the nlerp's by at most about 10⁻⁶·s/|1 − 2s| rad at the
    /// fraction s of the window, more within a few millionths of its middle. One body at most may turn (the other may translate); times and
    /// `distance_rate` are on the window's own clock. Pairs where both bodies turn answer
    /// [`QueryError::UnsupportedMotion`].
    Nlerp,
}

/// A query's motions as a tracker runs them, with the clock of the path.
#[derive(Copy, Clone, Debug)]
pub(crate) struct OnPath {
    pub m1: NonlinearRigidMotion,
    pub m2: NonlinearRigidMotion,
    pub clock: Option<Clock>,
}

/// The motion `m` with angular velocity `omega` instead of its own, its start rotated about its
/// rotation centre so that it has the same pose at `t0` (parry's motions turn by ω·t from the
/// start pose, t from 0, not from the window's start).
fn respun(m: &NonlinearRigidMotion, omega: f64, t0: f64) -> NonlinearRigidMotion {
    let angle = (m.angvel - omega) * t0;
    if angle == 0.0 && turn_of_zero_keeps(m) {
        // No turn (a window from t = 0): the pose is its own, without the sine and cosine of 0.
        return NonlinearRigidMotion { angvel: omega, ..*m };
    }
    turned(m, omega, angle)
}

/// Whether turning `m`'s start by a zero angle about its rotation centre ([`turned`]) gives its
/// start back to the bit: the rotation R(0) = (1, 0) and the centre's shift c − c = +0 give back
/// every finite component but a negative zero (+0 instead); a centre that is not finite gives
/// NaN.
fn turn_of_zero_keeps(m: &NonlinearRigidMotion) -> bool {
    let s = &m.start;
    let kept = |v: f64| v.is_finite() && v.to_bits() != (-0.0f64).to_bits();
    [s.translation.x, s.translation.y, s.rotation.re, s.rotation.im]
        .into_iter()
        .all(kept)
        && (m.start * m.local_center).is_finite()
}

/// `m` with angular velocity `omega`, its start turned by `angle` about its rotation centre.
fn turned(m: &NonlinearRigidMotion, omega: f64, angle: f64) -> NonlinearRigidMotion {
    use parry2d_f64::math::Pose;
    let centre = Pose::from_translation(m.start * m.local_center);
    let turn = Pose::new(parry2d_f64::math::Vector::ZERO, angle);
    NonlinearRigidMotion {
        start: centre * turn * centre.inverse() * m.start,
        angvel: omega,
        ..*m
    }
}

impl OnPath {
    /// The motions `m1`, `m2` over [`t0`, `t1`] on `path`. For the nlerp path the turning body's
    /// angular velocity becomes the nlerp's turn Δ (the turn over the window wrapped into
    /// [−π, π)) over the window, and the clock runs its translation. Non-finite input is passed
    /// on for the tracker to refuse.
    pub(crate) fn new(
        m1: &NonlinearRigidMotion,
        m2: &NonlinearRigidMotion,
        t0: f64,
        t1: f64,
        path: MotionPath,
    ) -> Result<OnPath, QueryError> {
        let plain = OnPath {
            m1: *m1,
            m2: *m2,
            clock: None,
        };
        let span = t1 - t0;
        if path == MotionPath::ConstantSpin || !(span > 0.0 && span.is_finite()) {
            return Ok(plain);
        }
        let (w1, w2) = (m1.angvel, m2.angvel);
        if !(w1.is_finite() && w2.is_finite()) {
            return Ok(plain);
        }
        if w1 != 0.0 && w2 != 0.0 {
            return Err(QueryError::UnsupportedMotion);
        }
        let w = if w1 != 0.0 { w1 } else { w2 };
        if w == 0.0 {
            return Ok(plain);
        }
        let mut delta = wrap_phi(w * span);
        let limit = PI - NLERP_HALF_TURN;
        if delta.abs() > limit {
            delta = limit.copysign(if delta == -PI { 1.0 } else { delta });
        }
        let omega = delta / span;
        let (mut a, mut b) = (*m1, *m2);
        if w1 != 0.0 {
            a = respun(m1, omega, t0);
        } else {
            b = respun(m2, omega, t0);
        }
        Ok(OnPath {
            m1: a,
            m2: b,
            clock: Clock::nlerp(delta, t0, t1),
        })
    }

    /// The answer `r` of a tracker on this path, on the window's own clock: its time is the
    /// path's (the window start plus the fraction of the window), its `distance_rate` per unit
    /// of that time.
    pub(crate) fn answer(&self, r: TimeOfImpact) -> TimeOfImpact {
        match &self.clock {
            None => r,
            Some(c) => {
                let d1 = c.jet(r.time).d1;
                TimeOfImpact {
                    time: c.path_time(r.time),
                    distance_rate: if d1 > 0.0 {
                        r.distance_rate / d1
                    } else {
                        r.distance_rate
                    },
                    ..r
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use parry2d_f64::math::{Pose, Vector};

    /// The bits of a motion's start pose.
    fn bits(m: &NonlinearRigidMotion) -> [u64; 4] {
        let s = &m.start;
        [s.translation.x, s.translation.y, s.rotation.re, s.rotation.im].map(f64::to_bits)
    }

    /// A window from t = 0 turns no motion: the shortcut gives the bits the composition about the
    /// rotation centre gives, and leaves to it the starts it would change (a negative zero, a
    /// centre that is not finite).
    #[test]
    fn a_zero_turn_keeps_the_start_pose_to_the_bit() {
        let mut rng = crate::numerics::test_rng::Lcg(0x005E_ED0F_2E50);
        for _ in 0..2000 {
            let start = Pose::new(
                Vector::new(rng.range(-1e3, 1e3), rng.range(-1e3, 1e3)),
                rng.range(-4.0, 4.0),
            );
            let centre = Vector::new(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
            let m = NonlinearRigidMotion::new(start, centre, Vector::new(1.0, -2.0), 3.0);
            assert!(turn_of_zero_keeps(&m));
            assert_eq!(bits(&respun(&m, 0.5, 0.0)), bits(&turned(&m, 0.5, 0.0)));
        }
        let negative_zero = NonlinearRigidMotion::new(Pose::translation(-0.0, 1.0), Vector::ZERO, Vector::X, 1.0);
        assert!(!turn_of_zero_keeps(&negative_zero));
        assert_ne!(bits(&turned(&negative_zero, 0.5, 0.0)), bits(&negative_zero));
        let far = NonlinearRigidMotion::new(
            Pose::new(Vector::ZERO, 0.7),
            Vector::new(1.7e308, 1.7e308),
            Vector::X,
            1.0,
        );
        assert!(!turn_of_zero_keeps(&far));
        assert!(!turned(&far, 0.5, 0.0).start.is_finite());
    }
}
