//! The relative motion of the two objects and object1's placement in object2's frame at one
//! time, with the time derivatives the jets of the three distances need.
//!
//! At time t object1's boundary point maps into object2's frame as
//!
//! ```text
//! P(φ, t) = q(t) + R(β(t))·(P₁(φ) − c₁),     N(φ, t) = R(β(t))·N₁(φ),
//! ```
//!
//! where c₁ is object1's rotation centre (its `local_center`), β = α₁ − α₂ the relative angle
//! (β' = ω = ω₁ − ω₂) and q(t) = R(−α₂)(C₁ − C₂) + c₂ the position of object1's rotation centre
//! (C₁, C₂ the world rotation centres, moving linearly: ΔC = ΔC₀ + ΔV·τ(t) with τ the path's
//! translation clock, τ(t) = t for parry's motions, `numerics::clock`). q' and q'' follow from
//! Q = R(−α₂)ΔC: Q' = −ω₂Q⊥ + V, Q'' = −ω₂²Q − 2ω₂V⊥ + R(−α₂)ΔC'' with V = R(−α₂)ΔC',
//! ΔC' = ΔV·τ', ΔC'' = ΔV·τ''.

use crate::numerics::clock::{Clock, ClockBounds, ClockExt};
use crate::numerics::math::{perp, Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;

/// Every number of the motion is finite.
pub(crate) fn motion_is_finite(m: &NonlinearRigidMotion) -> bool {
    m.start.is_finite() && m.local_center.is_finite() && m.linvel.is_finite() && m.angvel.is_finite()
}

/// Object1's placement in object2's frame at one time t, with the time derivatives the jets need.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct PairFrame {
    /// cos β(t).
    pub cos_b: f64,
    /// sin β(t).
    pub sin_b: f64,
    /// ω = dβ/dt.
    pub omega: f64,
    /// Object1's rotation centre c₁ in its own frame.
    pub center1: Vector,
    /// q(t): object1's rotation centre in object2's frame.
    pub q: Vector,
    /// dq/dt.
    pub q_t: Vector,
    /// d²q/dt².
    pub q_tt: Vector,
    /// The time t.
    pub time: f64,
}

impl PairFrame {
    /// A fixed configuration: `pos12` is the pose of object2 in object1's frame (parry's
    /// convention). Time derivatives are zero.
    pub fn from_pos12(pos12: &Pose) -> Self {
        let pos21 = pos12.inverse();
        Self {
            cos_b: pos21.rotation.cos(),
            sin_b: pos21.rotation.sin(),
            omega: 0.0,
            center1: Vector::ZERO,
            q: pos21.translation,
            q_t: Vector::ZERO,
            q_tt: Vector::ZERO,
            time: 0.0,
        }
    }

    /// The frame at time `t` of object1 moving by `motion1` relative to object2 moving by
    /// `motion2` (parry's motions; times are absolute), with the time derivatives the jets of
    /// [`crate::method::eval_pair`] need.
    pub fn at_time(motion1: &NonlinearRigidMotion, motion2: &NonlinearRigidMotion, t: f64) -> Self {
        RelativeMotion::new(motion1, motion2).frame(t)
    }

    /// Rotates a vector of object1's frame into object2's frame.
    #[inline]
    pub fn rotate(&self, v: Vector) -> Vector {
        Vector::new(self.cos_b * v.x - self.sin_b * v.y, self.sin_b * v.x + self.cos_b * v.y)
    }

    /// Rotates a vector of object2's frame into object1's frame.
    #[inline]
    pub fn unrotate(&self, v: Vector) -> Vector {
        Vector::new(
            self.cos_b * v.x + self.sin_b * v.y,
            -self.sin_b * v.x + self.cos_b * v.y,
        )
    }

    /// Maps a point of object1's frame into object2's frame.
    #[inline]
    pub fn to_frame2(&self, p1: Vector) -> Vector {
        self.q + self.rotate(p1 - self.center1)
    }

    /// Maps a point of object2's frame into object1's frame.
    #[inline]
    pub fn to_frame1(&self, p2: Vector) -> Vector {
        self.center1 + self.unrotate(p2 - self.q)
    }

    /// The pose of object2 in object1's frame (parry's `pos12`) at this time.
    pub fn pos12(&self) -> Pose {
        // x₂ = q + R(x₁ − c₁)  ⇔  x₁ = Rᵀ(x₂ − q) + c₁.
        let rot = parry2d_f64::math::Rotation::from_cos_sin_unchecked(self.cos_b, -self.sin_b);
        Pose::from_parts(self.center1 - rot.transform_vector(self.q), rot)
    }
}

/// The relative motion of object1 with respect to object2 under parry's `NonlinearRigidMotion`
/// of each, ready to produce a [`PairFrame`] at any time.
///
/// Angles are kept as unit complex numbers (cos, sin): the rotation at t is the start rotation
/// composed with R(ωt), as parry's `NonlinearRigidMotion::position_at_time` composes it, so a
/// frame costs one sine and cosine per spinning angle and no arctangent.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RelativeMotion {
    /// (cos β₀, sin β₀): object1's start rotation relative to object2's, β₀ = α₁(0) − α₂(0).
    rot_b0: (f64, f64),
    omega: f64,
    /// (cos α₂(0), sin α₂(0)): object2's start rotation.
    rot_a2: (f64, f64),
    omega2: f64,
    dc0: Vector,
    dv: Vector,
    center1: Vector,
    center2: Vector,
    /// The translation clock of the path (`numerics::clock`): `None` for parry's motions, where
    /// the centres move on time itself.
    clock: Option<Clock>,
}

/// The unit complex number of a rotation (normalised: parry's rotations are unit up to rounding,
/// or not at all when built unchecked).
#[inline]
pub(crate) fn unit_cs(r: &parry2d_f64::math::Rotation) -> (f64, f64) {
    let (c, s) = (r.cos(), r.sin());
    let n = (c * c + s * s).sqrt();
    if n > 0.0 && n.is_finite() {
        (c / n, s / n)
    } else {
        (1.0, 0.0)
    }
}

/// The product of two unit complex numbers (cos, sin): the rotation by the sum of the angles.
#[inline]
pub(crate) fn compose(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    (a.0 * b.0 - a.1 * b.1, a.1 * b.0 + a.0 * b.1)
}

impl RelativeMotion {
    /// The relative motion of `m1` (object1) seen from `m2` (object2).
    pub fn new(m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion) -> Self {
        let r1 = unit_cs(&m1.start.rotation);
        let r2 = unit_cs(&m2.start.rotation);
        Self {
            rot_b0: compose(r1, (r2.0, -r2.1)),
            omega: m1.angvel - m2.angvel,
            rot_a2: r2,
            omega2: m2.angvel,
            dc0: m1.start * m1.local_center - m2.start * m2.local_center,
            dv: m1.linvel - m2.linvel,
            center1: m1.local_center,
            center2: m2.local_center,
            clock: None,
        }
    }

    /// The same motion with the rotation centres moving on `clock` (the nlerp path; the rotations
    /// stay uniform): C₁(t) − C₂(t) = ΔC₀ + ΔV·τ(t).
    pub(crate) fn with_clock(mut self, clock: Option<Clock>) -> Self {
        self.clock = clock;
        self
    }

    /// Bounds of the clock's derivatives between `ta` and `tb` (the identity's without a clock).
    pub(crate) fn clock_bounds(&self, ta: f64, tb: f64) -> ClockBounds {
        self.clock.bounds_over(ta, tb)
    }

    /// Object2's angular velocity.
    pub fn omega2(&self) -> f64 {
        self.omega2
    }

    /// World-frame offset between the rotation centres, C₁(t) − C₂(t) = ΔC₀ + ΔV·τ(t) (τ(t) = t
    /// without a clock).
    pub fn center_offset(&self, t: f64) -> Vector {
        match &self.clock {
            None => self.dc0 + self.dv * t,
            Some(c) => self.dc0 + self.dv * c.jet(t).tau,
        }
    }

    /// Relative linear velocity ΔV of the rotation centres (world frame), per unit of the clock.
    pub fn center_velocity(&self) -> Vector {
        self.dv
    }

    /// Object1's and object2's rotation centres in their own frames.
    pub fn centers(&self) -> (Vector, Vector) {
        (self.center1, self.center2)
    }

    /// The frame at time t.
    #[inline]
    pub fn frame(&self, t: f64) -> PairFrame {
        let (sw, cw) = crate::numerics::math::sin_cos(self.omega * t);
        let (cb, sb) = compose(self.rot_b0, (cw, sw));
        let (c2, s2) = if self.omega2 == 0.0 {
            self.rot_a2
        } else {
            let (sw2, cw2) = crate::numerics::math::sin_cos(self.omega2 * t);
            compose(self.rot_a2, (cw2, sw2))
        };
        // R(−α₂) v = (c v_x + s v_y, −s v_x + c v_y)
        let rinv = |v: Vector| crate::numerics::math::rotate_cs(c2, -s2, v);
        let w2 = self.omega2;
        let jet = self.clock.map(|c| c.jet(t));
        let (big_q, v) = match jet {
            None => (rinv(self.dc0 + self.dv * t), rinv(self.dv)),
            Some(j) => (rinv(self.dc0 + self.dv * j.tau), rinv(self.dv) * j.d1),
        };
        let q_t = -perp(big_q) * w2 + v;
        let mut q_tt = -big_q * (w2 * w2) - perp(v) * (2.0 * w2);
        if let Some(j) = jet {
            q_tt += rinv(self.dv) * j.d2;
        }
        PairFrame {
            cos_b: cb,
            sin_b: sb,
            omega: self.omega,
            center1: self.center1,
            q: big_q + self.center2,
            q_t,
            q_tt,
            time: t,
        }
    }
}
