//! The one row of an impact: where `CoreContactHooks` put a two-point contact's bounce so that
//! rapier's restitution cannot add energy (the math, on plain vectors, for both packages; the
//! hooks themselves are in [`super::core_hooks`] and in the f32 package).
//!
//! # Why two bouncing rows gain energy
//!
//! rapier's restitution is Box2D's: after the substeps, each contact row that pushed and was
//! approaching at the start of the step is driven, once, in order, to e times its own approach
//! velocity. Write u for the rows' relative normal velocities (negative: approaching), λ for the
//! rows' total normal impulses over the step, K for the rows' inverse effective mass matrix
//! (u changes by K λ). Kinetic energy is quadratic in the impulses, so for any impulses
//!
//! ```text
//! ΔE = λ·u₀ + ½ λᵀ K λ = ½ Σᵢ λᵢ (u₀ᵢ + u₁ᵢ),
//! ```
//!
//! exactly (u₁ = u₀ + K λ). A row that pushed (λᵢ > 0) and ends at u₁ᵢ = −e u₀ᵢ contributes
//! ½ λᵢ (1 − e) u₀ᵢ ≤ 0. With two bouncing rows of different lever arms (a spinning flat side:
//! two points with different approach velocities), the second row's correction moves the
//! first off its target (K₀₁ ≠ 0): the first ends faster apart than it came, its term is
//! positive, and the collision gains energy (up to ×1.34 with restitution 1 in the moving-pairs
//! head-on table before this rule).
//!
//! # One bouncing row cannot
//!
//! With a single bouncing row r among any number of inelastic rows (restitution 0: the core
//! contacts, rows not approaching), frictionless:
//!
//! * the substeps solve the inelastic problem; its solution minimises the kinetic energy over
//!   all non-negative impulses of the rows (the contact LCP is the optimality condition of that
//!   minimum), so it takes at least as much as row r alone could: E_s ≤ E₀ − u₀ᵣ² / (2 Kᵣᵣ);
//! * the restitution pass then applies one impulse on row r, from u_sᵣ (0 if it pushed) to the
//!   target −e u₀ᵣ, which adds (e² u₀ᵣ² − u_sᵣ²) / (2 Kᵣᵣ) ≤ e² u₀ᵣ² / (2 Kᵣᵣ) (if the row is
//!   already separating faster than the target, the clamp at zero impulse leaves it, and a
//!   pull back would only take energy);
//!
//! so E₁ ≤ E₀ − (1 − e²) u₀ᵣ² / (2 Kᵣᵣ) ≤ E₀ for e ≤ 1. What this leaves out: friction (a
//! Coulomb impulse is not the energy minimiser, and the restitution impulse changes the
//! tangential velocity it was solved against: Newton's restitution with friction can add energy
//! in exact rigid-body mechanics too, Kane's example), the substeps stopping short of the
//! inelastic solution, and the speculative slack (a row may close its gap within the step).
//!
//! # Which row
//!
//! The row put in place of the two carries their inelastic impulse: with both rows in contact,
//! the impulses λ ≥ 0 with u₀ + K λ ≥ 0, complementary (a 2×2 LCP: both rows, or one of them
//! alone), act as one impulse Λ = λ₀ + λ₁ along the normal at x* = (λ₀ x₀ + λ₁ x₁) / Λ — the same
//! force and the same torques on both bodies, since a torque is linear in the point. A row at x*
//! therefore reaches the same inelastic state as the two (both ends stopped along the normal),
//! and its bounce is the impact's at its centre of percussion. A flat side meeting a flat side
//! without relative spin gets x* at the point the symmetry gives (the middle of two equal
//! boxes' faces), not a corner. The gaps are read as closed (the hook does not know the step;
//! at an impact the approach within a step dwarfs the gaps): a slow landing on one corner with
//! the other end in the air gets its row between the two, with the gap interpolated.

use parry2d_f64::math::Vector;

/// One body of a contact as the restitution rule reads it (a side without a body, or a body
/// that is not dynamic, has zero inverse mass and inertia). Not a public API: the hooks of both
/// packages fill it.
#[doc(hidden)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ImpactSide {
    /// World centre of mass.
    pub com: Vector,
    /// Linear velocity.
    pub linvel: Vector,
    /// Angular velocity.
    pub angvel: f64,
    /// Inverse mass along x and y (rapier's `effective_inv_mass`: 0 on a locked axis).
    pub inv_mass: Vector,
    /// Inverse world angular inertia (rapier's `effective_world_inv_inertia`).
    pub inv_inertia: f64,
}

impl ImpactSide {
    /// Velocity of the body's material point at world point `p`.
    fn velocity_at(&self, p: Vector) -> Vector {
        let r = p - self.com;
        self.linvel + Vector::new(-r.y, r.x) * self.angvel
    }
}

/// det K ≤ SAME_ROW · K₀₀ K₁₁ (the rows' Jacobians parallel to within about 10⁻⁶ rad, where
/// rounding decides the 2×2 solve): the two rows are one, with equal weights.
const SAME_ROW: f64 = 1e-12;

/// The weights (w₀, w₁), w ≥ 0, w₀ + w₁ = 1, of the single row that replaces two approaching
/// rows at world points `points` (normal `normal`, from body 1 towards body 2; module docs:
/// their inelastic impulses, normalised). `None` when a row is not approaching (rapier then
/// bounces at most one row: nothing to replace), when neither body can move, or when a value is
/// not finite.
///
/// The 2×2 LCP u₀ + K λ ≥ 0, λ ≥ 0, λᵢ (u₀ + K λ)ᵢ = 0 has a unique solution (K is positive
/// semi-definite; a P-matrix when the rows differ): both rows pushing, λ = −K⁻¹ u₀, when that is
/// non-negative; otherwise the one row whose own impulse −u₀ᵢ / Kᵢᵢ leaves the other at
/// u ≥ 0. Two rows with the same Jacobian (det K ≤ `SAME_ROW`·K₀₀K₁₁) are one row: equal weights.
#[doc(hidden)]
pub fn impact_weights(normal: Vector, points: [Vector; 2], sides: [ImpactSide; 2]) -> Option<[f64; 2]> {
    let [s1, s2] = sides;
    let u = points.map(|p| (s2.velocity_at(p) - s1.velocity_at(p)).dot(normal));
    if !(u[0] < 0.0 && u[1] < 0.0) {
        return None;
    }
    // Row i's angular Jacobians: (xᵢ − c) × n on each body.
    let arm = |s: &ImpactSide, p: Vector| (p - s.com).perp_dot(normal);
    let (a, b) = (points.map(|p| arm(&s1, p)), points.map(|p| arm(&s2, p)));
    let linear = normal.dot((s1.inv_mass + s2.inv_mass) * normal);
    let k = |i: usize, j: usize| linear + s1.inv_inertia * a[i] * a[j] + s2.inv_inertia * b[i] * b[j];
    let (k00, k01, k11) = (k(0, 0), k(0, 1), k(1, 1));
    if !(k00 > 0.0 && k11 > 0.0 && [k01, u[0], u[1]].iter().all(|v| v.is_finite())) {
        return None;
    }
    let det = k00 * k11 - k01 * k01;
    if det <= SAME_ROW * k00 * k11 {
        return Some([0.5, 0.5]);
    }
    let both = [(-k11 * u[0] + k01 * u[1]) / det, (-k00 * u[1] + k01 * u[0]) / det];
    if both[0] >= 0.0 && both[1] >= 0.0 {
        let sum = both[0] + both[1];
        return (sum > 0.0).then(|| [both[0] / sum, both[1] / sum]);
    }
    // One row alone: row 0 if its impulse leaves row 1 at u ≥ 0, else row 1.
    if u[1] - k01 * u[0] / k00 >= 0.0 {
        Some([1.0, 0.0])
    } else {
        Some([0.0, 1.0])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn side(com: Vector, linvel: Vector, angvel: f64) -> ImpactSide {
        ImpactSide {
            com,
            linvel,
            angvel,
            inv_mass: Vector::splat(1.0),
            inv_inertia: 3.0,
        }
    }

    /// Two equal bodies meeting face to face without spin: the row in the middle of the face.
    #[test]
    fn a_symmetric_face_impact_puts_the_row_in_the_middle() {
        let s1 = side(Vector::new(-1.0, 0.0), Vector::new(5.0, 0.0), 0.0);
        let s2 = side(Vector::new(1.0, 0.0), Vector::new(-5.0, 0.0), 0.0);
        let w = impact_weights(Vector::X, [Vector::new(0.0, -0.5), Vector::new(0.0, 0.5)], [s1, s2]).unwrap();
        assert!((w[0] - 0.5).abs() < 1e-12 && (w[1] - 0.5).abs() < 1e-12, "{w:?}");
    }

    /// The weights' row stops both points along the normal: the two rows' inelastic state.
    #[test]
    fn the_weighted_row_stops_both_points_like_the_two_rows() {
        let s1 = side(Vector::new(-1.0, 0.1), Vector::new(5.0, 0.3), 4.0);
        let s2 = side(Vector::new(1.2, -0.2), Vector::new(-4.0, 0.0), -2.0);
        let n = Vector::X;
        let p = [Vector::new(0.0, -0.4), Vector::new(0.0, 0.3)];
        let w = impact_weights(n, p, [s1, s2]).unwrap();
        let x = p[0] * w[0] + p[1] * w[1];
        // The single row's inelastic impulse at x, applied to both bodies.
        let arm = |s: &ImpactSide| (x - s.com).perp_dot(n);
        let kk = 2.0 + 3.0 * (arm(&s1).powi(2) + arm(&s2).powi(2));
        let u = (s2.velocity_at(x) - s1.velocity_at(x)).dot(n);
        let l = -u / kk;
        let after = |s: &ImpactSide, sign: f64| ImpactSide {
            linvel: s.linvel + n * (sign * l),
            angvel: s.angvel + sign * 3.0 * arm(s) * l,
            ..*s
        };
        let (t1, t2) = (after(&s1, -1.0), after(&s2, 1.0));
        let ends: Vec<f64> = p
            .iter()
            .map(|q| (t2.velocity_at(*q) - t1.velocity_at(*q)).dot(n))
            .collect();
        // Both rows push in this case (λ ≈ (3.61, 0.75)): the one row stops both ends.
        assert!(w[0] > 0.0 && w[1] > 0.0, "{w:?}");
        assert!(ends.iter().all(|e| e.abs() < 1e-12), "{w:?} {ends:?}");
    }

    /// A row moving apart: nothing to replace.
    #[test]
    fn a_separating_row_leaves_the_manifold_alone() {
        let s1 = side(Vector::new(-1.0, 0.0), Vector::ZERO, 20.0);
        let s2 = side(Vector::new(1.0, 0.0), Vector::ZERO, 0.0);
        assert_eq!(
            impact_weights(Vector::X, [Vector::new(0.0, -0.5), Vector::new(0.0, 0.5)], [s1, s2]),
            None
        );
    }
}
