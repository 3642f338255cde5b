//! The two bodies at one time, in a frame with world axes centred on body 2's rotation centre,
//! and the gap G(θ, t) along an axis with its derivatives in (θ, t).
//!
//! Body X (rotation centre Cₓ(t) = Cₓ(0) + Vₓt, angle αₓ(t) = αₓ(0) + ωₓt, as parry's
//! `NonlinearRigidMotion`; on the nlerp path the centres run on the clock τ(t) instead of t,
//! `numerics::clock`, ΔV below becoming ΔC′ = ΔV·τ′ and G_tt gaining −ΔC″·u) maps its body point p to Cₓ(t) + R(αₓ)(p − cₓ), cₓ its local rotation
//! centre. For the unit world axis u = (cos θ, sin θ), pointing from body 1 to body 2,
//!
//! ```text
//! G(θ, t) = −ΔC·u − h̃₁(ψ₁) − h̃₂(ψ₂),   ψ₁ = θ − α₁,  ψ₂ = θ + π − α₂,  ΔC = C₁ − C₂,
//! ```
//!
//! with h̃ₓ the support function of body X about cₓ in its own frame. G is the gap between the
//! bodies along u: a lower bound on their signed distance D for every θ, and D = max over θ of G.
//! With h̃', h̃'' the derivatives in the angle (h̃'' = ρ − h̃, ρ the radius of curvature at the
//! support point):
//!
//! ```text
//! G_θ  = −ΔC·u⊥ − h̃₁' − h̃₂',            G_θθ = ΔC·u − h̃₁'' − h̃₂''  (= −G − ρ₁ − ρ₂),
//! G_t  = −ΔV·u + ω₁h̃₁' + ω₂h̃₂',          G_θt = −ΔV·u⊥ + ω₁h̃₁'' + ω₂h̃₂'',
//! G_tt = −ω₁²h̃₁'' − ω₂²h̃₂''.
//! ```

// The negated comparisons (`!(x > 0.0)`) are deliberate: they are true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::numerics::clock::{Clock, ClockBounds, ClockExt};
use crate::numerics::math::{perp, rotate_cs, sin_cos, Vector};
use crate::numerics::motion::{compose, unit_cs};
use parry2d_f64::query::NonlinearRigidMotion;

/// The motions of the two bodies, ready to produce a [`GapFrame`] at any time.
#[derive(Copy, Clone, Debug)]
pub(crate) struct GapMotion {
    /// (cos, sin) of each body's start rotation.
    rot0: [(f64, f64); 2],
    /// Angular velocities ω₁, ω₂.
    pub omega: [f64; 2],
    /// ΔC(0) = C₁(0) − C₂(0) and ΔV = V₁ − V₂ (world).
    dc0: Vector,
    pub dv: Vector,
    /// Each body's rotation centre in its own frame (`local_center`).
    pub centre: [Vector; 2],
    /// The translation clock of the path (`numerics::clock`): ΔC(t) = ΔC(0) + ΔV·τ(t); `None`
    /// for parry's motions (τ(t) = t).
    pub clock: Option<Clock>,
}

/// The bodies at one time.
#[derive(Copy, Clone, Debug)]
pub(crate) struct GapFrame {
    /// The time.
    pub time: f64,
    /// (cos, sin) of each body's rotation.
    pub rot: [(f64, f64); 2],
    /// ΔC = C₁ − C₂ (world).
    pub dc: Vector,
    /// ΔC′ and ΔC″ (ΔV and 0 for parry's motions; ΔV·τ′ and ΔV·τ″ on a clock).
    pub dc_t: Vector,
    pub dc_tt: Vector,
}

impl GapMotion {
    /// The motions of body 1 and body 2.
    pub(crate) fn new(m1: &NonlinearRigidMotion, m2: &NonlinearRigidMotion) -> Self {
        GapMotion {
            rot0: [unit_cs(&m1.start.rotation), unit_cs(&m2.start.rotation)],
            omega: [m1.angvel, m2.angvel],
            dc0: m1.start * m1.local_center - m2.start * m2.local_center,
            dv: m1.linvel - m2.linvel,
            centre: [m1.local_center, m2.local_center],
            clock: None,
        }
    }

    /// The same motions with the rotation centres on `clock` (the nlerp path).
    pub(crate) fn with_clock(mut self, clock: Option<Clock>) -> Self {
        self.clock = clock;
        self
    }

    /// ΔC(t).
    #[inline]
    pub(crate) fn dc(&self, t: f64) -> Vector {
        match &self.clock {
            None => self.dc0 + self.dv * t,
            Some(c) => self.dc0 + self.dv * c.jet(t).tau,
        }
    }

    /// Bounds of the clock's derivatives between `ta` and `tb`.
    pub(crate) fn clock_bounds(&self, ta: f64, tb: f64) -> ClockBounds {
        self.clock.bounds_over(ta, tb)
    }

    /// The bodies at time `t`.
    #[inline]
    pub(crate) fn frame(&self, t: f64) -> GapFrame {
        let rot = |k: usize| {
            if self.omega[k] == 0.0 {
                self.rot0[k]
            } else {
                let (s, c) = sin_cos(self.omega[k] * t);
                compose(self.rot0[k], (c, s))
            }
        };
        let (dc, dc_t, dc_tt) = match &self.clock {
            None => (self.dc0 + self.dv * t, self.dv, Vector::ZERO),
            Some(c) => {
                let j = c.jet(t);
                (self.dc0 + self.dv * j.tau, self.dv * j.d1, self.dv * j.d2)
            }
        };
        GapFrame {
            time: t,
            rot: [rot(0), rot(1)],
            dc,
            dc_t,
            dc_tt,
        }
    }
}

impl GapFrame {
    /// A body-frame vector of body `k` in the world.
    #[inline]
    pub(crate) fn to_world(self, k: usize, v: Vector) -> Vector {
        let (c, s) = self.rot[k];
        rotate_cs(c, s, v)
    }

    /// A world vector in body `k`'s frame.
    #[inline]
    pub(crate) fn to_body(self, k: usize, v: Vector) -> Vector {
        let (c, s) = self.rot[k];
        rotate_cs(c, -s, v)
    }

    /// The world position (relative to body 2's rotation centre) of body `k`'s point `p`.
    #[inline]
    pub(crate) fn point(&self, motion: &GapMotion, k: usize, p: Vector) -> Vector {
        let x = self.to_world(k, p - motion.centre[k]);
        if k == 0 {
            x + self.dc
        } else {
            x
        }
    }
}

/// G and its first and second derivatives in (θ, t) at one axis (module docs).
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub(crate) struct GapJet {
    pub g: f64,
    pub g_th: f64,
    pub g_thth: f64,
    pub g_t: f64,
    pub g_tht: f64,
    pub g_tt: f64,
}

/// The support function of one body about its rotation centre at the body direction m, with
/// its first two derivatives in the direction's angle: h̃ = (p − c)·m, h̃' = (p − c)·m⊥,
/// h̃'' = ρ − h̃.
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub(crate) struct SupportValue {
    pub h: f64,
    pub h1: f64,
    pub h2: f64,
}

impl SupportValue {
    /// At the support point `p` (body frame) with radius of curvature `rho`, rotation centre `c`.
    #[inline]
    pub(crate) fn at(p: Vector, rho: f64, m: Vector, c: Vector) -> Self {
        let q = p - c;
        let h = q.dot(m);
        SupportValue {
            h,
            h1: q.dot(perp(m)),
            h2: rho - h,
        }
    }
}

impl GapJet {
    /// The jet at the world axis `u` of the frame `fr` with each body's support data there.
    #[inline]
    pub(crate) fn new(motion: &GapMotion, fr: &GapFrame, u: Vector, s1: &SupportValue, s2: &SupportValue) -> Self {
        let up = perp(u);
        let [w1, w2] = motion.omega;
        let mut g_tt = -w1 * w1 * s1.h2 - w2 * w2 * s2.h2;
        if motion.clock.is_some() {
            g_tt -= fr.dc_tt.dot(u);
        }
        GapJet {
            g: -fr.dc.dot(u) - s1.h - s2.h,
            g_th: -fr.dc.dot(up) - s1.h1 - s2.h1,
            g_thth: fr.dc.dot(u) - s1.h2 - s2.h2,
            g_t: -fr.dc_t.dot(u) + w1 * s1.h1 + w2 * s2.h1,
            g_tht: -fr.dc_t.dot(up) + w1 * s1.h2 + w2 * s2.h2,
            g_tt,
        }
    }

    /// D' and D'' of the distance along a maximum that moves with the axis turning at `rate`
    /// (a kink of body k: its angular velocity) or, with `None`, at a smooth maximum
    /// (G_θ = 0: the axis follows θ*' = −G_θt/G_θθ).
    #[inline]
    pub(crate) fn distance_rates(&self, rate: Option<f64>) -> (f64, f64) {
        match rate {
            Some(w) => (
                self.g_t + w * self.g_th,
                self.g_tt + 2.0 * w * self.g_tht + w * w * self.g_thth,
            ),
            None => {
                let d2 = if self.g_thth < 0.0 {
                    self.g_tt - self.g_tht * self.g_tht / self.g_thth
                } else {
                    self.g_tt
                };
                (self.g_t, d2)
            }
        }
    }
}
