//! [`StepPath`]: the path the moving-pairs pass gives a body over one step of rapier, from its
//! pose before `PhysicsPipeline::step` to its pose after it.
//!
//! # The path
//!
//! rapier integrates a body over a step with its solved velocities: the centre of mass moves at
//! the linear velocity, the body turns at the angular velocity about it (`RigidBodyVelocity::
//! integrate`). Its CCD then builds a body's motion from the poses at the step's two ends: the
//! velocity `RigidBodyPosition::interpolate_velocity` gives (the centre of mass's displacement
//! over `dt`, the turn *wrapped into (−π, π]* over `dt`) for its nonlinear casts, and
//! `Sweep::from_poses(start, end, local_com)` — the centre of mass on its segment, the rotation
//! *nlerped* the short way round — where it clamps a body.
//!
//! The pass takes the path of parry's `NonlinearRigidMotion` between the same two poses: the
//! centre of mass at constant velocity c(t) = c₀ + (c₁ − c₀)·t/dt, the body at constant spin
//! θ(t) = θ₀ + Δθ·t/dt about it, so that the path ends at the end pose. The turn Δθ is the
//! rotation from the start pose to the end pose *unwrapped* to the turn rapier integrated:
//! Δθ ≡ arg(R₁R₀⁻¹) (mod 2π), the representative nearest to ω·dt·s, where ω is the body's
//! angular velocity after the step and s the fraction of the step its centre of mass covered
//! (|c₁ − c₀| / (|v|·dt), at most 1; 1 for a body that does not translate). A body that moved
//! freely has s = 1 and turned by ω·dt, which may be many turns (600 rad/s is 10 rad in a step
//! of 1/60 s, where the short way round of rapier's own casts turns the other way); a body
//! rapier's CCD stopped at the fraction f of its step has s = f and its nlerped rotation, a turn
//! near ω·dt·f. The representative is the nearest, so an error ε in the estimate of ω·dt·s
//! cannot change it unless the true turn is within ε of the midpoint between two
//! representatives (ε is rapier's rounding and the gravity of a step for a free body).
//!
//! A body the pass stops at time t is put at this path's pose at t (the pose the time of impact
//! was computed on): [`StepPath::pose_at`].

use crate::numerics::math::{Pose, Vector};
use core::f64::consts::TAU;
use parry2d_f64::query::NonlinearRigidMotion;

/// The largest turn a path takes in one step, in radians: 10⁶ turns. A spin past it keeps its
/// rotation modulo 2π within the bound (the time of impact of such a spin reports
/// `OutOfIterations` long before).
const MAX_TURN: f64 = 1e6 * TAU;

/// A body's path over one step: parry's constant-velocity, constant-spin motion from its start
/// pose to its end pose (module docs), on the window [0, `dt`].
///
/// ```
/// use parry2d_f64::math::{Pose, Vector};
/// use smooth_ccd2d::__moving_pairs::StepPath;
///
/// // A body spinning at 600 rad/s for a step of 1/60 s turns by 10 rad: the end pose's
/// // rotation is 10 − 4π, and the path turns the whole 10 rad.
/// let dt = 1.0 / 60.0;
/// let start = Pose::translation(0.0, 0.0);
/// let end = Pose::new(Vector::new(5.0, 0.0), 10.0);
/// let path = StepPath::new(&start, &end, Vector::ZERO, Vector::new(300.0, 0.0), 600.0, dt).unwrap();
/// assert!((path.turn() - 10.0).abs() < 1e-9);
/// assert!((path.pose_at(dt).translation - end.translation).length() < 1e-12);
/// ```
#[derive(Copy, Clone, Debug)]
pub struct StepPath {
    /// The motion: start pose, local centre of mass, linear velocity (c₁ − c₀)/dt, angular
    /// velocity Δθ/dt.
    pub motion: NonlinearRigidMotion,
    /// The step's length.
    pub dt: f64,
}

impl StepPath {
    /// The path from `start` to `end` of a body whose centre of mass is `local_com` (in its
    /// local frame) and whose velocities after the step are `linvel`, `angvel` (module docs).
    /// `None` when an input is not finite, `dt` is not positive, or the path's velocities
    /// overflow.
    pub fn new(start: &Pose, end: &Pose, local_com: Vector, linvel: Vector, angvel: f64, dt: f64) -> Option<Self> {
        if !(dt > 0.0 && dt.is_finite() && linvel.is_finite() && angvel.is_finite()) {
            return None;
        }
        let (c0, c1) = (*start * local_com, *end * local_com);
        let wrapped = (end.rotation * start.rotation.inverse()).angle();
        if !(c0.is_finite() && c1.is_finite() && wrapped.is_finite()) {
            return None;
        }
        let shift = c1 - c0;
        let travel = linvel.length() * dt;
        let covered = if travel > 0.0 {
            (shift.length() / travel).min(1.0)
        } else {
            1.0
        };
        let aim = (angvel * dt * covered).clamp(-MAX_TURN, MAX_TURN);
        let turns = ((aim - wrapped) / TAU).round();
        let turn = wrapped + TAU * turns;
        let motion = NonlinearRigidMotion::new(*start, local_com, shift / dt, turn / dt);
        (motion.linvel.is_finite() && motion.angvel.is_finite()).then_some(StepPath { motion, dt })
    }

    /// A body that stays at `pose` over the step.
    pub fn still(pose: &Pose, dt: f64) -> Self {
        StepPath {
            motion: NonlinearRigidMotion::constant_position(*pose),
            dt,
        }
    }

    /// The turn Δθ over the step.
    pub fn turn(&self) -> f64 {
        self.motion.angvel * self.dt
    }

    /// Whether the body moves over the step (its velocities are not both zero).
    pub fn moves(&self) -> bool {
        self.motion.linvel != Vector::ZERO || self.motion.angvel != 0.0
    }

    /// The body's pose at time `t` on the path: the centre of mass at c₀ + (c₁ − c₀)·t/dt, the
    /// rotation turned by Δθ·t/dt about it.
    pub fn pose_at(&self, t: f64) -> Pose {
        self.motion.position_at_time(t)
    }

    /// The centre of mass at the start and at the end of the step.
    pub fn com_ends(&self) -> (Vector, Vector) {
        let c0 = self.motion.start * self.motion.local_center;
        (c0, c0 + self.motion.linvel * self.dt)
    }

    /// An upper bound of the distance any point within `radius` of the centre of mass moves
    /// over the step: the centre's travel plus the chord of the turn, at most
    /// radius·min(|Δθ|, 2).
    pub fn max_point_travel(&self, radius: f64) -> f64 {
        self.motion.linvel.length() * self.dt + radius * self.turn().abs().min(2.0)
    }
}

/// Whether a body may be fast: false only when every point within `reach` of its centre of
/// mass moves at most `limit` on the path [`StepPath::new`] would build from `start` to `end`
/// (`spin_dt`: its angular velocity times the step), decided without building it.
///
/// The path's centre travels |c₁ − c₀| and it turns by Δθ, the representative of the rotation
/// q = R₁R₀⁻¹ nearest to ω·dt·s (s ≤ 1). With q's real part positive its angle lies within
/// (−π/2, π/2), |angle| ≤ (π/2)·|Im q|; with |ω·dt| < π/2 too, the nearest representative is the
/// angle itself (they differ by less than π). The bound is then
/// |c₁ − c₀| + reach·min((π/2)·|Im q|, 2) ≥ [`StepPath::max_point_travel`], less 10⁻⁹ of itself
/// for rounding; otherwise the body may be fast.
pub fn may_be_fast(start: &Pose, end: &Pose, local_com: Vector, spin_dt: f64, reach: f64, limit: f64) -> bool {
    let q = end.rotation * start.rotation.inverse();
    if !(q.re > 0.0 && spin_dt.abs() < 0.5 * core::f64::consts::PI) {
        return true;
    }
    let shift = (*end * local_com - *start * local_com).length();
    let bound = shift + reach * (0.5 * core::f64::consts::PI * q.im.abs()).min(2.0);
    // Not provably slow (a NaN included): may be fast.
    !matches!(
        (bound * (1.0 + 1e-9)).partial_cmp(&limit),
        Some(core::cmp::Ordering::Less | core::cmp::Ordering::Equal)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A free body: the path ends at the end pose and turns by ω·dt, several turns included.
    #[test]
    fn a_free_body_turns_as_integrated() {
        let dt = 1.0 / 60.0;
        for &omega in &[0.0, 3.0, -40.0, 200.0, -600.0, 1500.0] {
            let start = Pose::new(Vector::new(1.0, -2.0), 0.7);
            let com = Vector::new(0.1, 0.05);
            let v = Vector::new(120.0, -30.0);
            let m = NonlinearRigidMotion::new(start, com, v, omega);
            let end = m.position_at_time(dt);
            let p = StepPath::new(&start, &end, com, v, omega, dt).unwrap();
            assert!((p.turn() - omega * dt).abs() < 1e-9, "{omega}: {}", p.turn());
            let e = p.pose_at(dt);
            assert!((e.translation - end.translation).length() < 1e-12);
            assert!((e.rotation * end.rotation.inverse()).angle().abs() < 1e-12);
        }
    }

    /// A body stopped by rapier's CCD at a fraction of its step (nlerped rotation) turns by
    /// the short way near ω·dt·f, not by the whole step's spin.
    #[test]
    fn a_clamped_body_turns_by_its_covered_part() {
        let dt = 1.0 / 60.0;
        let start = Pose::new(Vector::ZERO, 0.0);
        // 600 rad/s, stopped at a tenth of the step: rotation 1 rad on the nlerp, centre at 0.1.
        let end = Pose::new(Vector::new(0.5, 0.0), 1.0);
        let p = StepPath::new(&start, &end, Vector::ZERO, Vector::new(300.0, 0.0), 600.0, dt).unwrap();
        assert!((p.turn() - 1.0).abs() < 1e-12);
    }

    /// The screen never calls a body slow that its path calls fast.
    #[test]
    fn the_screen_never_misses_a_fast_body() {
        let mut rng = crate::numerics::test_rng::Lcg(11);
        let dt = 1.0 / 60.0;
        let mut fast = 0;
        for _ in 0..20_000 {
            let start = Pose::new(
                Vector::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0)),
                rng.range(-3.0, 3.0),
            );
            let v = Vector::new(rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
            let omega = rng.range(-120.0, 120.0);
            let com = Vector::new(rng.range(-0.2, 0.2), rng.range(-0.2, 0.2));
            let end = NonlinearRigidMotion::new(start, com, v, omega).position_at_time(dt);
            let (reach, limit) = (rng.range(0.1, 2.0), rng.range(0.0, 0.2));
            let p = StepPath::new(&start, &end, com, v, omega, dt).unwrap();
            let is_fast = p.max_point_travel(reach) > limit;
            fast += usize::from(is_fast);
            assert!(!is_fast || may_be_fast(&start, &end, com, omega * dt, reach, limit));
        }
        assert!(fast > 1000 && fast < 19_000, "{fast}");
    }

    /// Bad input gives no path, never NaN.
    #[test]
    fn bad_input_gives_none() {
        let p = Pose::translation(0.0, 0.0);
        let v = Vector::new(1.0, 0.0);
        assert!(StepPath::new(&p, &p, Vector::ZERO, v, 1.0, 0.0).is_none());
        assert!(StepPath::new(&p, &p, Vector::ZERO, v, f64::NAN, 0.1).is_none());
        assert!(StepPath::new(&p, &Pose::translation(f64::INFINITY, 0.0), Vector::ZERO, v, 1.0, 0.1).is_none());
        assert!(StepPath::new(&p, &Pose::translation(1e300, 0.0), Vector::ZERO, v, 1.0, 1e-300).is_none());
        let huge = StepPath::new(&p, &p, Vector::ZERO, Vector::ZERO, 1e300, 0.1).unwrap();
        assert!(huge.turn().is_finite() && huge.turn().abs() <= MAX_TURN + TAU);
    }
}
