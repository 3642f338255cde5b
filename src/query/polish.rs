//! The stationary distance's last step where φ cannot resolve the contact: Newton's iteration
//! on distanceSide over the *normal angle* instead of over φ.
//!
//! # Why
//!
//! A root of distanceSide S(φ) is found to the side tolerance when φ can express it. It cannot
//! where object1's normal turns through a large angle over a tiny range of φ: the specification's
//! `CapsuleEllipse` gives its arcs of radius r1 the range arctan(r2/r1) ≤ |φ| ≤ π/2, about r1/r2
//! wide, and its normal turns at ω₁ = dθ/dφ ~ r2/r1 there, without bound at the arc's end
//! beside the segment (a square root's derivative). Near φ = π/2 one unit in the last place of
//! φ (2.2e-16) then turns the normal by ω₁·2.2e-16: at r1 : r2 = 1 : 9.3e5 about 1e-5 rad near
//! the segment, where S_φ reached 6e7 and one ulp of φ moved S by 1.3e-8. The bracketed solve
//! ends on two adjacent floats with |S| far above the tolerance, and distanceFwd, a lower bound
//! of the signed distance that is tangent to it only at the root, is short of it by about
//! S²/(2(ρ₁ + ρ₂)): 3.4e-13 for two needle tips of size 1.7e-5 (2e-8 of the size, where the
//! distance is promised to 1e-12 of it; adversarial fuzz seed 5014, case 44828).
//!
//! # The step
//!
//! Over a normal angle Δ from the solve's point P₁ with normal N, object1 is its osculating circle
//! there (ρ₁ = |P′|/ω₁ its radius of curvature): P₁(Δ) = P₁ + ρ₁(N(Δ) − N), exact on
//! a circular arc and at a polygon's sharp vertex (ρ₁ = 0), and off by O(ρ₁′Δ²) elsewhere over
//! the tiny angles taken here (at most [`SPAN_ULPS`] ulps of φ's turn). Object2 gives its support
//! point for −N(Δ) exactly ([`crate::ConvexCurve::support_jet`]). With d = S₂ − P₁ as in
//! `pair::eval_point`, F = d·N and S = d × N, and in the normal angle
//!
//! ```text
//! ∂S/∂Δ = ρ₁ + ρ₂ + F        (S_φ = ω₁(ρ₁ + ρ₂ + F): the φ-derivative of `pair` divided by ω₁),
//! ```
//!
//! so Newton's steps Δ ← Δ − S/(ρ₁ + ρ₂ + F) converge quadratically. The result is kept only when
//! it lowers |S| and raises F: F at any normal is the separation of the two shapes along it, a
//! lower bound of the signed distance (the separating-axis theorem), which the polish brings to
//! the maximum. It runs only where φ cannot resolve the root (a step of [`RESOLUTION_ULPS`] ulps
//! of φ moves S by more than the tolerance); every other solve (|S| within the tolerance, a root
//! φ resolves, a flat piece, a shape that gives no support jet) keeps its answer to the bit.

use super::pair::PairPoint;
use crate::curve::ConvexCurve;
use crate::numerics::math::{cross, perp, Vector};
use crate::numerics::motion::PairFrame;

/// How far the polish may turn the normal, in units in the last place of φ times object1's
/// turning rate ω₁: the solve ends within a few ulps of the root, and the osculating circle is
/// object1 only so near its point.
const SPAN_ULPS: f64 = 16.0;

/// φ cannot resolve a root where a step of this many ulps moves distanceSide by more than the
/// side tolerance.
const RESOLUTION_ULPS: f64 = 4.0;

/// Newton's steps at most (each one support jet of object2).
const MAX_STEPS: usize = 8;

/// A contact refined over the normal angle: every quantity in the frames `finish` reports them.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Polished {
    /// distanceFwd at the refined normal.
    pub fwd: f64,
    /// Object1's point, in its frame.
    pub point1: Vector,
    /// Object2's support point, in its frame.
    pub point2: Vector,
    /// The unit normal N, object1's frame.
    pub normal1: Vector,
    /// N in object2's frame.
    pub normal_in_2: Vector,
}

/// The contact of `j` (object1 at φ = `phi`) refined over the normal angle when its
/// distanceSide exceeds `side_tol` (module docs); `None` when it is within it, when object1 is
/// flat there (its normal does not turn), or when no step improves it.
pub(crate) fn polish<B: ConvexCurve + ?Sized>(
    obj2: &B,
    frame: &PairFrame,
    phi: f64,
    j: &PairPoint,
    side_tol: f64,
) -> Option<Polished> {
    let cp = &j.curve1;
    let w1 = cp.normal_turn_rate();
    // Only where φ cannot resolve the root: one step of RESOLUTION_ULPS ulps moves S by more than
    // the tolerance (a solve that ended above it elsewhere keeps its answer to the bit).
    let ulp = f64::EPSILON * phi.abs().max(1.0);
    let unresolved = j.side_p.abs() * RESOLUTION_ULPS * ulp > side_tol;
    if j.side.abs() <= side_tol || !unresolved || !(w1 > 0.0 && w1.is_finite()) {
        return None;
    }
    let rho1 = cp.d_point.length() / w1;
    let span = w1 * SPAN_ULPS * ulp;
    if !(rho1.is_finite() && span.is_finite()) {
        return None;
    }
    // F, S and ∂S/∂Δ at the normal N turned by Δ, with the points.
    let at = |delta: f64| -> Option<(f64, f64, f64, Polished)> {
        // N(Δ) − N = N⊥ sin Δ − 2N sin²(Δ/2), without the cancellation of cos Δ − 1; and P₁(Δ)
        // = P₁ + ρ₁(N(Δ) − N), without that of C + ρ₁N(Δ) where ρ₁ dwarfs the shape (the flank
        // of a needle ellipse: ρ₁ = a²/b).
        let (s, h) = (delta.sin(), (0.5 * delta).sin());
        let turn = perp(cp.normal) * s - cp.normal * (2.0 * h * h);
        let n = cp.normal + turn;
        let p1 = cp.point + turn * rho1;
        let n2 = frame.rotate(n);
        let sj = obj2.support_jet(-n2)?;
        let d = frame.to_frame1(sj.point) - p1;
        let (fwd, side) = (d.dot(n), cross(d, n));
        let slope = rho1 + sj.radius_of_curvature + fwd;
        let p = Polished {
            fwd,
            point1: p1,
            point2: sj.point,
            normal1: n,
            normal_in_2: n2,
        };
        (fwd.is_finite() && side.is_finite() && slope.is_finite()).then_some((fwd, side, slope, p))
    };
    let (mut delta, mut best): (f64, Option<(f64, f64, Polished)>) = (0.0, None);
    let (mut side, mut slope) = (j.side, j.side_p / w1);
    for _ in 0..MAX_STEPS {
        // A slope that is not positive (or NaN) gives no Newton step.
        if slope.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
            break;
        }
        let next = (delta - side / slope).clamp(-span, span);
        if next == delta {
            break;
        }
        delta = next;
        let (f, s, k, p) = at(delta)?;
        if best.is_none_or(|(_, bs, _)| s.abs() < bs.abs()) {
            best = Some((f, s, p));
        }
        (side, slope) = (s, k);
        if s.abs() <= side_tol {
            break;
        }
    }
    let (fwd, s, p) = best?;
    (fwd > j.fwd && s.abs() < j.side.abs()).then_some(p)
}
