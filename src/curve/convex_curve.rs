//! The parametric convex boundary: the trait every shape of this crate implements, and through
//! which users add their own convex curves.
//!
//! A curve gives, for φ ∈ [−π, π) (any counter-clockwise parametrisation), the boundary point
//! P(φ), the outward unit normal N(φ), and their first and second derivatives in φ — the four
//! quantities of the specification's Appendix A. Pieces of a piecewise curve end at
//! [`ConvexCurve::breakpoints`]; the point and normal are continuous everywhere, derivatives may
//! jump there.
//!
//! Writing ω(φ) = N × N' ≥ 0 (the rate at which the normal turns) and σ(φ) = |P'| (the speed),
//! P' = σ·T and N' = ω·T with T = N⊥ = (−N_y, N_x) the counter-clockwise tangent. A corner of a
//! sharp polygon is a φ-interval with σ = 0 < ω; a flat edge one with ω = 0 < σ.
//!
//! A curve is *strictly convex* when each unit vector m is the outward normal of exactly one
//! boundary point S(m) (eq. 4 for an ellipse). Such a curve can be object2 of the algorithms and
//! implements [`ConvexCurve::support_jet`]: S(m), the radius of curvature ρ(m) = h(ψ) + h''(ψ)
//! there (h the support function, ψ the angle of m) and dρ/dψ.

use crate::numerics::angle::ccw_angle;
use crate::numerics::math::{cross, perp, Vector};
use core::f64::consts::PI;
use core::fmt::Debug;

/// Bisections of the default [`ConvexCurve::phi_range_of_normal`] to the ends of a flat piece
/// (φ to the resolution of f64); its Newton search takes at most twice as many steps.
const NORMAL_BISECTIONS: usize = 64;

/// Boundary point and outward unit normal with their first and second derivatives in φ.
#[derive(Copy, Clone, Debug, PartialEq, Default)]
pub struct CurvePoint {
    /// P(φ).
    pub point: Vector,
    /// dP/dφ.
    pub d_point: Vector,
    /// d²P/dφ².
    pub dd_point: Vector,
    /// N(φ), unit, outward.
    pub normal: Vector,
    /// dN/dφ.
    pub d_normal: Vector,
    /// d²N/dφ².
    pub dd_normal: Vector,
}

impl CurvePoint {
    /// ω = N × N': how fast the normal angle turns with φ (≥ 0 for a convex curve).
    #[inline]
    pub fn normal_turn_rate(&self) -> f64 {
        cross(self.normal, self.d_normal)
    }
    /// dω/dφ = N × N''.
    #[inline]
    pub fn d_normal_turn_rate(&self) -> f64 {
        cross(self.normal, self.dd_normal)
    }
    /// σ = P' · T: the speed of the point along the counter-clockwise tangent.
    #[inline]
    pub fn speed(&self) -> f64 {
        self.d_point.dot(perp(self.normal))
    }
    /// True when every component is finite.
    pub fn is_finite(&self) -> bool {
        self.point.is_finite()
            && self.d_point.is_finite()
            && self.dd_point.is_finite()
            && self.normal.is_finite()
            && self.d_normal.is_finite()
            && self.dd_normal.is_finite()
    }
}

/// The support point of a strictly convex curve for an outward unit normal m, with what the
/// algorithms need of its derivatives in ψ = angle(m): dS/dψ = ρ·m⊥, d²S/dψ² = ρ'·m⊥ − ρ·m.
#[derive(Copy, Clone, Debug, PartialEq, Default)]
pub struct SupportJet {
    /// S(m): the boundary point whose outward normal is m.
    pub point: Vector,
    /// Radius of curvature ρ at S(m) (> 0 is not required, ≥ 0 is).
    pub radius_of_curvature: f64,
    /// dρ/dψ.
    pub d_radius_of_curvature: f64,
}

/// A closed convex curve parametrised counter-clockwise by φ ∈ [−π, π).
///
/// Implement it to add a shape; wrap the curve in [`crate::CustomCurve`] to use it with parry
/// and rapier. Implementations must keep P and N continuous over the whole circle (including
/// the wrap from π to −π), N unit and outward, and ω = N × N' ≥ 0.
///
/// # The contract, and what checks it
///
/// [`crate::CustomCurve::try_new`] checks what a fixed sample of the curve can show (256 values
/// of φ and the start and middle of every piece; a tolerance of 1e-6): every number finite,
/// the breakpoints sorted in [−π, π), the bounding radius at least every sampled |P|, the normals
/// unit and outward and the curve convex and counter-clockwise, φ wrapped, the area of Green's
/// theorem between the sampled polygon's and the bounding disc's, `phi_range_of_normal` and
/// `support_point` giving support points, and the curvature bounds not contradicted by a
/// sampled radius of curvature. A curve that fails is refused with
/// [`crate::ShapeError::BrokenContract`] naming the method.
///
/// What no sample can check is the contract between its points; each method says what breaks
/// when it does not hold. In short: the *upper bounds* (`bounding_radius`,
/// `max_radius_of_curvature`, `support_dd_bound`, `support_dd_bound_near`) are what the time of
/// impact's guard and bounding circles rely on to step over no contact — one too small makes a
/// cast miss a contact or report a late one; the *lower bounds* `min_radius_of_curvature` and
/// `min_radius_of_curvature_near` let the stationary distance skip its global search and bound
/// it — too large, a penetration is reported shallower than it is; `eval`'s derivatives steer the solvers and the mass quadrature —
/// wrong, the queries are slower or less accurate (never unbounded: every loop of the crate has
/// a cap and says when it reached it), and the mass is wrong. No broken contract makes a query
/// panic, hang or return a NaN.
pub trait ConvexCurve: Send + Sync + Debug + 'static {
    /// Point, normal and their derivatives at φ. φ outside [−π, π) must be wrapped.
    ///
    /// Checked at the sampled φ (finite, N unit and outward, P′ and N′ tangent, turning
    /// counter-clockwise, wrapped, the area of Green's theorem). Between them: a NaN makes the
    /// queries that meet it answer `Degenerate` / `Unsupported`; derivatives that are not those
    /// of P and N slow the solvers (bounded: their caps) and make the mass wrong; a noisy `eval`
    /// (computed in f32) stops the mass quadrature at its budget
    /// ([`crate::QuadratureStatus::OutOfEvaluations`]), as accurate as the noise.
    fn eval(&self, phi: f64) -> CurvePoint;

    /// φ values in [−π, π), sorted, where derivatives may jump (piece ends). Empty when smooth.
    ///
    /// Checked (every breakpoint). A jump of the derivatives elsewhere slows the solvers near
    /// it (they bisect where Newton stalls) and is integrated less accurately by the mass
    /// quadrature.
    fn breakpoints(&self) -> &[f64] {
        &[]
    }

    /// The largest distance from the local origin to a boundary point (an upper bound on it is
    /// allowed; the tolerances of the queries scale with it, so keep it tight).
    ///
    /// Checked against the sampled points (and a length in the accepted range). Too small
    /// between them: the bounding circles can part shapes that meet (a cast misses the
    /// contact), the dispatcher's quick rejections answer "apart" for touching shapes.
    fn bounding_radius(&self) -> f64;

    /// The φ-interval `[lo, hi]` of boundary points whose outward normal is the unit vector
    /// `n` (`lo == hi` except on a flat piece). `hi` may exceed π when a flat piece wraps.
    ///
    /// The default finds φ by Newton's steps on the normal angle, which is non-decreasing in φ,
    /// inside a bracket it bisects where a step would leave it (about ten evaluations of `eval`
    /// a call on a smooth curve; the ends of a flat piece by bisection); closed forms are
    /// faster still.
    ///
    /// Checked at the sampled normals. Elsewhere an answer beyond one turn is taken at its
    /// start (the ray cast), and a wrong one gives wrong support points: wrong distances and
    /// contacts, never a hang.
    fn phi_range_of_normal(&self, n: Vector) -> (f64, f64) {
        default_phi_range_of_normal(self, n)
    }

    /// For a strictly convex curve, S(m) with its curvature data (eq. 4); `None` otherwise.
    ///
    /// Checked at the sampled normals (present, finite, the support point's value). `None`
    /// elsewhere makes the queries of the pair answer `Degenerate` (rapier then gets no
    /// contact); a wrong point, wrong distances.
    fn support_jet(&self, _m: Vector) -> Option<SupportJet> {
        None
    }

    /// Whether [`ConvexCurve::support_jet`] is available (the curve can be object2).
    ///
    /// Checked: a strictly convex curve has no sampled flat piece.
    fn is_strictly_convex(&self) -> bool {
        false
    }

    /// An upper bound on the radius of curvature over the whole curve (used by the step guard
    /// of the time of impact); only needed for strictly convex curves.
    ///
    /// Checked against the sampled radii (to 1e-3). Too small between them: the guard's bound
    /// on how fast the distance can fall is too small, and a cast can step over a contact.
    fn max_radius_of_curvature(&self) -> f64 {
        f64::INFINITY
    }

    /// A lower bound on the radius of curvature over the whole curve (0 for a curve with sharp
    /// corners; a flat piece counts as infinite). The stationary distance uses it to certify a
    /// shallow penetration depth without its global search, and in the bounds of that search
    /// (a deep penetration, a disc centred on a polygon's corner: with 0 the search cannot tell
    /// that the distance is flat over the corner's normals, and runs to its evaluation cap). The
    /// default, 0, is always valid.
    ///
    /// Checked against the sampled radii. Too large between them: a penetration deeper than
    /// the true smallest radius can be reported shallower (a local maximum certified global).
    fn min_radius_of_curvature(&self) -> f64 {
        0.0
    }

    /// A lower bound on the radius of curvature over the boundary points whose outward normals
    /// lie within `half_angle` of the unit vector `m` (0 for a sharp corner among them; a flat
    /// piece counts as infinite). The stationary distance's global search bounds the distance
    /// over an arc of normals with it: where the curvature varies (an ellipse) the local bound
    /// lets it drop the arcs next to a deep maximum at once. The default is
    /// [`ConvexCurve::min_radius_of_curvature`], always valid when that is.
    ///
    /// Checked at the sampled normals over arcs of half-angle 0 and 2π/256 only: too large over
    /// wider arcs, a penetration can be reported shallower than it is.
    fn min_radius_of_curvature_near(&self, m: Vector, half_angle: f64) -> f64 {
        let _ = (m, half_angle);
        self.min_radius_of_curvature()
    }

    /// An upper bound on |h''(ψ)| = |ρ(ψ) − h(ψ)| over all directions, with h the support
    /// function about the local origin (strictly convex curves only). The time of impact's
    /// step guard multiplies it by the squared relative spin. The default,
    /// `max_radius_of_curvature() + bounding_radius()`, is always valid.
    ///
    /// Checked against |ρ − h| at the sampled directions (to 1e-3). Too small (0 for a curve
    /// that is not a circle about its origin): a spinning cast steps over the contact, or
    /// reports one early.
    fn support_dd_bound(&self) -> f64 {
        self.max_radius_of_curvature() + self.bounding_radius()
    }

    /// An upper bound on |h''(ψ)| over the directions within `half_angle` of the unit vector `m`
    /// (strictly convex curves only). The time of impact's step guard uses it over the
    /// directions one step sweeps. The default is [`ConvexCurve::support_dd_bound`].
    ///
    /// Checked at the sampled directions over arcs of half-angle 0 and 2π/256 only: too small
    /// over wider arcs, a cast can step over a contact.
    fn support_dd_bound_near(&self, m: Vector, half_angle: f64) -> f64 {
        let _ = (m, half_angle);
        self.support_dd_bound()
    }

    /// The support point in direction `n` (any unit vector): the boundary point furthest along n.
    ///
    /// Checked at the sampled normals. Wrong elsewhere: wrong bounding boxes and parry's
    /// answers (GJK) for the pairs parry answers.
    fn support_point(&self, n: Vector) -> Vector {
        if let Some(j) = self.support_jet(n) {
            return j.point;
        }
        let (lo, hi) = self.phi_range_of_normal(n);
        self.eval(0.5 * (lo + hi)).point
    }
}

/// The default [`ConvexCurve::phi_range_of_normal`]: the φ at which the normal's turn from N(−π),
///
///   θ(φ) = ccw angle from N(−π) to N(φ) ∈ [0, 2π), non-decreasing in φ,  θ′(φ) = N × N′ = ω,
///
/// reaches the target angle of `n`. Newton's steps on θ(φ) − target from the point where a
/// curve parametrised by its normal angle has it (φ = −π + target), kept inside a bracket that
/// every evaluation narrows, and a bisection of the bracket wherever a step would leave it or
/// not halve the step before: about ten evaluations on a smooth curve where the bisections
/// alone took about a hundred. Where θ meets the target exactly on a flat piece (ω = 0: its
/// normal's φ form an interval) the two ends of the interval are bisected from the bracket.
fn default_phi_range_of_normal<C: ConvexCurve + ?Sized>(c: &C, n: Vector) -> (f64, f64) {
    let n = n.normalize_or_zero();
    let n0 = c.eval(-PI).normal;
    let target = ccw_angle(n0, n);
    // Turning angle accumulated from φ = −π, in [0, 2π), and its rate ω = N × N′; near the end
    // of the circle an angle that wrapped to ~0 means "almost 2π".
    let turn = |phi: f64| {
        let p = c.eval(phi);
        let a = ccw_angle(n0, p.normal);
        let a = if phi > 0.0 && a < 1e-3 { a + 2.0 * PI } else { a };
        (a, cross(p.normal, p.d_normal))
    };
    if target == 0.0 {
        return (-PI, -PI);
    }
    // θ(a) < target ≤ θ(b).
    let (mut a, mut b) = (-PI, PI);
    let mut x = (-PI + target).clamp(-PI, PI);
    let mut last_step = 2.0 * PI;
    for _ in 0..2 * NORMAL_BISECTIONS {
        let (t, w) = turn(x);
        let f = t - target;
        if f == 0.0 {
            // On the target: a point where the normal turns, or a flat piece (ω = 0), whose
            // interval of φ about x the bisections find.
            return if w > 0.0 {
                (x, x)
            } else {
                range_about(&turn, target, (a, x), (x, b))
            };
        }
        if f < 0.0 {
            a = x;
        } else {
            b = x;
        }
        let newton = x - f / w;
        let step = (newton - x).abs();
        let next = if w > 0.0 && newton > a && newton < b && 2.0 * step <= last_step {
            newton
        } else {
            0.5 * (a + b)
        };
        last_step = (next - x).abs();
        // Converged: the step below the resolution of φ, or the bracket closed.
        if last_step <= 4.0 * f64::EPSILON * PI || b - a <= 4.0 * f64::EPSILON * PI || !next.is_finite() {
            let phi = if next.is_finite() && next > a && next <= b {
                next
            } else {
                b
            };
            return (phi, phi);
        }
        x = next;
    }
    range_about(&turn, target, (a, b), (a, b))
}

/// The ends of the φ-interval on which the turn θ equals `target` by two bisections, `lo` the
/// first φ with θ ≥ target in the bracket `lo`, `hi` the first with θ > target in `hi`: they
/// share an evaluation wherever their midpoints agree (until a midpoint's turn equals the
/// target, on a flat piece), and a midpoint met again reuses its value.
fn range_about(turn: &impl Fn(f64) -> (f64, f64), target: f64, mut lo: (f64, f64), mut hi: (f64, f64)) -> (f64, f64) {
    let mut last = (f64::NAN, 0.0);
    let mut turn_at = |phi: f64| {
        if phi != last.0 {
            last = (phi, turn(phi).0);
        }
        last.1
    };
    for _ in 0..NORMAL_BISECTIONS {
        let m = 0.5 * (lo.0 + lo.1);
        if turn_at(m) >= target {
            lo.1 = m;
        } else {
            lo.0 = m;
        }
        let m = 0.5 * (hi.0 + hi.1);
        if turn_at(m) > target {
            hi.1 = m;
        } else {
            hi.0 = m;
        }
    }
    let (lo, hi) = (0.5 * (lo.0 + lo.1), 0.5 * (hi.0 + hi.1));
    (lo, hi.max(lo))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// A curve with only `eval`, `breakpoints` and `bounding_radius` (the defaults answer the
    /// rest), counting its evaluations.
    #[derive(Debug)]
    struct EvalOnly<C>(C, AtomicUsize);

    impl<C: ConvexCurve> ConvexCurve for EvalOnly<C> {
        fn eval(&self, phi: f64) -> CurvePoint {
            self.1.fetch_add(1, Ordering::Relaxed);
            self.0.eval(phi)
        }
        fn breakpoints(&self) -> &[f64] {
            self.0.breakpoints()
        }
        fn bounding_radius(&self) -> f64 {
            self.0.bounding_radius()
        }
    }

    fn unit(angle: f64) -> Vector {
        Vector::new(angle.cos(), angle.sin())
    }

    #[test]
    fn the_default_normal_search_finds_each_normals_point_in_about_ten_evaluations() {
        for (a, b) in [(0.5, 0.2), (1.0, 1.0), (1.0, 0.02), (3e-3, 7e-3)] {
            let c = EvalOnly(Ellipse::new(a, b), AtomicUsize::new(0));
            let n = 1000;
            for k in 0..n {
                let m = unit(-PI + 2.0 * PI * (k as f64 + 0.37) / n as f64);
                let (lo, hi) = c.phi_range_of_normal(m);
                let want = c.0.phi_range_of_normal(m);
                assert_eq!(lo, hi, "{a} × {b}: {m}");
                // The same point as the closed form's, its normal m.
                let (p, q) = (c.0.eval(lo), c.0.eval(want.0));
                assert!(
                    (p.point - q.point).length() <= 1e-14 * a.max(b),
                    "{a} × {b}: {m}: {lo} vs {want:?}"
                );
                assert!((p.normal - m).length() <= 1e-14, "{a} × {b}: {m}: normal {}", p.normal);
            }
            let per_call = c.1.load(Ordering::Relaxed) as f64 / n as f64;
            assert!(per_call <= 12.0, "{a} × {b}: {per_call} evaluations a call");
        }
    }

    #[test]
    fn the_default_normal_search_spans_a_flat_piece_and_turns_a_corner() {
        // A capsule-ellipse's flat side (normal +x) and a sharp polygon's corners and edges.
        let c = EvalOnly(CapsuleEllipse::new(0.5, 1.0, 0.8), AtomicUsize::new(0));
        for m in [Vector::X, unit(0.3), unit(2.0), unit(-1.0)] {
            let (lo, hi) = c.phi_range_of_normal(m);
            let (wlo, whi) = c.0.phi_range_of_normal(m);
            assert!(
                (lo - wlo).abs() <= 1e-13 && (hi - whi).abs() <= 1e-13,
                "{m}: {lo} {hi} vs {wlo} {whi}"
            );
        }
        let square = RoundedPolygon::regular(4, 1.0, 0.0);
        let s = EvalOnly(square.clone(), AtomicUsize::new(0));
        for k in 0..64 {
            let m = unit(-PI + 2.0 * PI * (k as f64 + 0.5) / 64.0);
            let (lo, hi) = s.phi_range_of_normal(m);
            assert!((s.0.eval(lo).point - square.support_point(m)).length() <= 1e-13, "{m}");
            assert!((s.0.eval(hi).point - square.support_point(m)).length() <= 1e-13, "{m}");
        }
    }
}
