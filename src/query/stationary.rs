//! The distance between two stationary objects ("Distance Between Two Stationary Objects" and
//! "Distance functions analysis" of the specification).
//!
//! For every φ, F(φ) = d·N is the gap between the two shapes along the axis N(φ): a lower bound
//! on the signed distance, and its maximum over φ *is* the signed distance (docs/theory.md, § 3). Since
//! ∂F/∂φ = −ω₁·S, the maxima of F are roots of S where S goes from negative to positive.
//!
//! 1. **Local solve.** Starting from the normal that points from object1's centre to
//!    object2's (the role of eq. 5), a bracket [a, b] with S(a) < 0 < S(b) is grown, then
//!    Halley/Newton steps on S are taken inside it, falling back to bisection whenever a step
//!    leaves the bracket or fails to halve it (derivatives jump at piece ends).
//! 2. **Global test.** If the root has F > 0 it is the global maximum (the positive part of F is
//!    concave in the normal angle: a theorem, docs/theory.md § 4) and the shapes are apart. If
//!    0 ≥ F > −(r₁ + r₂), with rᵢ the smallest radii of curvature, it is also global: the same
//!    theorem applied to the shapes shrunk by rᵢ (a shallow penetration).
//! 3. **Otherwise** (penetration, or a bad start on a very thin ellipse) a branch and bound over
//!    the normal angle θ bisects the intervals not yet searched, the specification's "bisection
//!    of intervals". Intervals whose upper bound on F cannot beat the best value found (by more
//!    than the tolerance) are dropped; an interval with a sign change of S gets a local solve,
//!    and is split at its root. The bounds are below ("Bounds on an interval").
//!
//! ## Bounds on an interval
//!
//! Take an interval [a, b] of θ of width δ < π, with end values F_a, F_b and slopes into it
//! g_a = F_θ(a⁺), g_b = F_θ(b⁻) (F_θ = −S). Write h₁, h₂ for the support functions of the two
//! shapes; F(θ) = −h₁(n) − h₂(−n) + (a term linear in n), and h + h'' = ρ (the radius of
//! curvature at the support point, a measure: a flat piece is an atom), so
//!
//! ```text
//! F_θθ + F = −ρ₁ − ρ₂ ≤ −r,     r = a lower bound on ρ₁ + ρ₂ over the interval's directions.
//! ```
//!
//! A flat piece of object1 (an atom of ρ₁) only makes F_θθ more negative: a concave kink, where
//! any slope between the two one-sided ones keeps every bound below valid.
//!
//! * **Parabolas.** F ≥ F_low := (F_a + F_b)/2 − Lδ/2 on the interval (|F_θ| ≤ L = R₁ + R₂ + |q|,
//!   the bounding radii and the offset of the origins), so F_θθ ≤ M := max(0, −F_low − r) and F
//!   lies below both F_a + g_a(θ − a) + M(θ − a)²/2 and F_b + g_b(θ − b) + M(θ − b)²/2, whose
//!   lower envelope has an exact maximum ([`envelope_max`]). With r the global smallest radii this
//!   costs nothing; a shape whose curvature varies gets r over the interval's directions
//!   ([`ConvexCurve::min_radius_of_curvature_near`]) when the first try fails. Where M = 0 the
//!   envelope is that of the tangent lines, exact at a maximum at an end.
//! * **Sinusoids.** w = F + r satisfies w'' + w ≤ 0, hence (variation of constants: the
//!   difference e from the solution with the same value and slope at a has e'' + e ≤ 0, e(a) = 0,
//!   e'(a) = 0, and e(a + x) = ∫₀ˣ sin(x − s)·(e'' + e)(a + s) ds ≤ 0 for x ≤ π)
//!
//!   ```text
//!   F(a + x) ≤ (F_a + r)·cos x + g_a·sin x − r,    F(b − x) ≤ (F_b + r)·cos x − g_b·sin x − r,
//!   ```
//!
//!   for 0 ≤ x ≤ δ. Where ρ₁ + ρ₂ = r on the interval (a disc against a polygon's corner: its
//!   support point fixed, F + r a pure sinusoid) these are F itself, and the maximum of their
//!   lower envelope ([`sine_envelope_max`]) is F's maximum over the interval exactly, across one
//!   kink too. This is what makes the degenerate starts cheap: a disc of radius R centred on a
//!   sharp vertex has F ≡ −R over the vertex's whole cone of normals, a flat maximum that the
//!   parabolas (M ≥ Lδ/2 > 0 there) could only drop in intervals of width about √(tol/L),
//!   some 10⁵ of them (the evaluation cap ended it, after 1.7 ms); a disc concentric with a
//!   polygon has its maxima at kinks, which the parabolas bracketed to 1e-6 rad each.
//!
//! A node on a flat piece of object1 carries both one-sided slopes (S at each end of the piece:
//! one more evaluation), and a split at a root found on a flat piece takes the piece's own normal
//! (not its angle recomputed, which may fall an ulp into the neighbouring corner and carry the
//! slope of the wrong side): the interval beside a face–point maximum is then bounded by F's own
//! value and dropped at once, where the slope of the other side kept it open down to 1e-6 rad.

use crate::curve::ConvexCurve;
use crate::error::{finite, tolerance_ok, AllFinite, QueryError};
use crate::numerics::angle::{ccw_angle, wrap_phi};
use crate::numerics::math::{sin_cos, unit, Pose, Vector};
use crate::numerics::motion::PairFrame;
use crate::query::pair::PairPoint;
use crate::query::polish::polish;
use crate::query::solver::Solver;
use core::f64::consts::PI;

/// Tolerances and caps of the stationary distance. Tolerances are relative to the size s of the
/// pair (the larger bounding radius).
///
/// Build them from the default with the `with_*` methods (the struct is `#[non_exhaustive]`).
#[derive(Copy, Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct DistanceOptions {
    /// |distanceSide| at which a root is accepted, relative to s (default 1e-10: an error δ in φ
    /// costs only O(δ²) in distance).
    pub side_tolerance: f64,
    /// How far below the best value an interval's bound must stay to be dropped, relative to s
    /// (default 1e-12).
    pub distance_tolerance: f64,
    /// Cap on Newton/Halley/bisection iterations of one local solve (default 100).
    pub max_local_iterations: usize,
    /// Cap on pair evaluations of one query (default 4000).
    pub max_evaluations: usize,
}

impl Default for DistanceOptions {
    fn default() -> Self {
        Self {
            side_tolerance: 1e-10,
            distance_tolerance: 1e-12,
            max_local_iterations: 100,
            max_evaluations: 4000,
        }
    }
}

/// How a stationary distance query ([`stationary_distance`], and
/// [`crate::halfspace_distance`]) ended. Whatever the status, every number of the
/// [`StationaryDistance`] is finite and the normals are unit vectors; bad input is a
/// [`QueryError`] instead. s below is the size of the pair (the larger bounding radius).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum DistanceStatus {
    /// The shapes are apart: a root of distanceSide with distanceFwd > 0, certified global (the
    /// positive part of distanceFwd is concave in the normal angle). `distance` > 0 is the
    /// Euclidean distance and the witnesses realise it (to about 1e-12·s in our tests).
    Separated,
    /// The shapes touch or overlap: the global maximum of distanceFwd (≤ 0) was found — by the
    /// local solve when the overlap is shallower than the sum of the smallest radii of curvature
    /// ([`crate::ConvexCurve::min_radius_of_curvature`], which certifies it), otherwise bracketed
    /// by the branch and bound over the normal angle to `distance_tolerance`·s; `distance` ≤ 0
    /// is minus the penetration depth. (Against a half-space: the support point is on or below
    /// the plane.)
    Penetrating,
    /// The evaluation cap (`max_evaluations`) was reached before the branch and bound could
    /// certify its answer: `distance` is the best value found, a lower bound on the signed
    /// distance, of either sign. Deep overlaps whose maximum is flat or tied (coincident or
    /// concentric shapes, a disc centred on a polygon's corner) reached it before the search's
    /// sinusoid bound (module docs); none of the 336 coincident and concentric pairs of
    /// `crates/dev/tests/adversarial.rs` does now (13 did). A caller's small `max_evaluations` still can.
    OutOfIterations,
}

/// The result of [`stationary_distance`].
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct StationaryDistance {
    /// Signed distance: > 0 apart, < 0 minus the penetration depth.
    pub distance: f64,
    /// φ of object1's witness point.
    pub phi: f64,
    /// Witness point on object1, in object1's frame.
    pub point1: Vector,
    /// Witness point on object2, in object2's frame.
    pub point2: Vector,
    /// Object1's outward normal at its witness, in object1's frame (towards object2 when apart).
    pub normal1: Vector,
    /// Object2's outward normal at its witness, in object2's frame.
    pub normal2: Vector,
    /// How the query ended.
    pub status: DistanceStatus,
    /// Newton/Halley iterations taken (bisection steps not counted).
    pub newton_iterations: usize,
    /// Pair evaluations.
    pub evaluations: usize,
}

impl StationaryDistance {
    /// The same answer with the roles of the two shapes exchanged (witness points and normals
    /// swapped; distance, φ, status and counts unchanged).
    pub fn swapped(self) -> Self {
        Self {
            point1: self.point2,
            point2: self.point1,
            normal1: self.normal2,
            normal2: self.normal1,
            ..self
        }
    }
}

impl DistanceOptions {
    /// With this side tolerance (relative to the size).
    pub fn with_side_tolerance(mut self, side_tolerance: f64) -> Self {
        self.side_tolerance = side_tolerance;
        self
    }

    /// With this distance tolerance of the branch and bound (relative to the size).
    pub fn with_distance_tolerance(mut self, distance_tolerance: f64) -> Self {
        self.distance_tolerance = distance_tolerance;
        self
    }

    /// With this cap on iterations of one local solve.
    pub fn with_max_local_iterations(mut self, max_local_iterations: usize) -> Self {
        self.max_local_iterations = max_local_iterations;
        self
    }

    /// With this cap on pair evaluations of one query.
    pub fn with_max_evaluations(mut self, max_evaluations: usize) -> Self {
        self.max_evaluations = max_evaluations;
        self
    }

    /// Whether the tolerances are finite and ≥ 0 (otherwise the queries answer
    /// [`QueryError::NonFinite`]). Caps of 0 are allowed: the query then ends at once with
    /// `OutOfIterations`.
    pub(crate) fn is_valid(&self) -> bool {
        tolerance_ok(self.side_tolerance) && tolerance_ok(self.distance_tolerance)
    }
}

impl AllFinite for StationaryDistance {
    fn all_finite(&self) -> bool {
        self.distance.is_finite()
            && self.phi.is_finite()
            && self.point1.is_finite()
            && self.point2.is_finite()
            && self.normal1.is_finite()
            && self.normal2.is_finite()
    }
}

/// Capacity of the branch-and-bound node stack; reaching it ends the search with
/// [`DistanceStatus::OutOfIterations`] (never observed: the depth stays below 64).
const NODE_STACK: usize = 96;
/// Intervals of the normal angle narrower than this (radians) are not split further.
const MIN_INTERVAL: f64 = 1e-14;
/// An interval holding a local maximum is split at the maximum's normal angle unless it lies
/// within this fraction of the interval of an end (then at the midpoint).
const SPLIT_MARGIN: f64 = 1e-3;

/// One endpoint of a branch-and-bound interval over the normal angle θ.
#[derive(Copy, Clone)]
struct Node {
    theta: f64,
    /// The start of object1's φ-range with normal angle θ, and the pair there.
    phi: f64,
    jet: PairPoint,
    /// S at the end of that range: on a flat piece of object1 F has a concave kink at θ, and
    /// −S there is its slope from the right (−`jet.side` is the slope from the left); elsewhere
    /// `jet.side`.
    side_hi: f64,
}

/// The signed distance between object1 (`obj1`, any convex curve) and object2 (`obj2`, strictly
/// convex) with object2 at `pos12` in object1's frame, by the algorithm described in the module
/// documentation. The curves may be trait objects or of known types (then the search is compiled
/// for the pair, as for [`crate::time_of_impact`]).
///
/// An ellipse with semi-axes 2 × 1 and a disc of radius 0.5 centred 3 along x: the gap is
/// 3 − 2 − 0.5 = 0.5, certified global:
///
/// ```
/// use parry2d_f64::math::{Pose, Vector};
/// use smooth_ccd2d::{stationary_distance, BallCurve, DistanceOptions, DistanceStatus, Ellipse};
///
/// let pos12 = Pose::translation(3.0, 0.0); // the disc's pose in the ellipse's frame
/// let d = stationary_distance(&Ellipse::new(2.0, 1.0), &BallCurve { radius: 0.5 }, &pos12, &DistanceOptions::default())
///     .unwrap();
/// assert_eq!(d.status, DistanceStatus::Separated);
/// assert!((d.distance - 0.5).abs() < 1e-12);
/// assert!((d.point1 - Vector::new(2.0, 0.0)).length() < 1e-9);
/// ```
pub fn stationary_distance<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    obj1: &A,
    obj2: &B,
    pos12: &Pose,
    options: &DistanceOptions,
) -> Result<StationaryDistance, QueryError> {
    if !(pos12.is_finite() && options.is_valid()) {
        return Err(QueryError::NonFinite);
    }
    let frame = PairFrame::from_pos12(pos12);
    let phi0 = obj1.phi_range_of_normal(direction_or_x(pos12.translation)).0;
    finite(stationary_in_frame(obj1, obj2, frame, phi0, options))
}

fn direction_or_x(v: Vector) -> Vector {
    let l = v.length();
    if l > 0.0 && l.is_finite() {
        v / l
    } else {
        Vector::X
    }
}

/// As [`stationary_distance`] in a prepared frame, starting the local solve at `phi0`.
pub(crate) fn stationary_in_frame<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    obj1: &A,
    obj2: &B,
    frame: PairFrame,
    phi0: f64,
    options: &DistanceOptions,
) -> Result<StationaryDistance, QueryError> {
    if !obj2.is_strictly_convex() {
        return Err(QueryError::NotStrictlyConvex);
    }
    crate::error::curves_sized(&[obj1.bounding_radius(), obj2.bounding_radius()])?;
    let size = obj1.bounding_radius().max(obj2.bounding_radius());
    let mut sv = Solver {
        obj1,
        obj2,
        frame,
        side_tol: options.side_tolerance * size,
        max_iter: options.max_local_iterations,
        evaluations: 0,
        newton: 0,
    };
    let j0 = sv.eval(phi0).ok_or(QueryError::Degenerate)?;
    let local = sv.local_root(phi0, j0);
    if let Some((phi, j)) = local {
        if j.fwd > 0.0 {
            return Ok(finish(&sv, phi, &j, DistanceStatus::Separated));
        }
        // Shallow penetration: with r = r₁ + r₂ the smallest radii of curvature, each shape is
        // a convex body swelled by a disc of radius rᵢ, so F = F' − r with F' the gap function
        // of the shrunk bodies. A local maximum with F > −r has F' > 0, where F' has a single
        // local maximum (the positive part is concave): it is the global one, no search needed.
        let r = obj1.min_radius_of_curvature() + obj2.min_radius_of_curvature();
        if j.fwd > -r {
            return Ok(finish(&sv, phi, &j, DistanceStatus::Penetrating));
        }
    }
    let (best, status) = global_search(&mut sv, local, size, options)?;
    let (phi, j) = polish_on_flat(&mut sv, best, size, options);
    let status = if j.fwd > 0.0 && status != DistanceStatus::OutOfIterations {
        DistanceStatus::Separated
    } else {
        status
    };
    Ok(finish(&sv, phi, &j, status))
}

/// The global branch and bound of [`stationary_in_frame`] over θ, the angle of N in object2's
/// frame, from the local maximum `local` when there is one (module docs): the largest F found
/// and the status the search ended with (`Penetrating` unless it ran out of evaluations or of
/// its stack).
fn global_search<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    sv: &mut Solver<A, B>,
    local: Option<(f64, PairPoint)>,
    size: f64,
    options: &DistanceOptions,
) -> Result<((f64, PairPoint), DistanceStatus), QueryError> {
    let (obj1, obj2, frame) = (sv.obj1, sv.obj2, sv.frame);
    // The node at θ whose normal on object1 is n1. On a flat piece, S at its end gives F's slope
    // from the right (failing that, the slope from the left is a valid bound too: F has a
    // concave kink there).
    let node_at = |sv: &mut Solver<A, B>, theta: f64, n1: Vector| -> Option<Node> {
        let (phi, hi) = sv.obj1.phi_range_of_normal(n1);
        let jet = sv.eval(phi)?;
        let side_hi = if hi > phi {
            sv.eval(hi).map_or(jet.side, |j| j.side)
        } else {
            jet.side
        };
        Some(Node {
            theta,
            phi,
            jet,
            side_hi,
        })
    };
    let normal_at = |theta: f64| frame.unrotate(unit(theta));
    let mut best: Option<(f64, PairPoint)> = local;
    let theta_start = match local {
        Some((_, j)) => j.normal_in_2.y.atan2(j.normal_in_2.x),
        None => 0.0,
    };
    let lip = obj1.bounding_radius() + obj2.bounding_radius() + (frame.q - frame.rotate(frame.center1)).length();
    let tol = options.distance_tolerance * size;
    // ρ₁ + ρ₂ ≥ r_min everywhere (module docs, "Bounds on an interval").
    let r_min = radius_bound(obj1.min_radius_of_curvature()) + radius_bound(obj2.min_radius_of_curvature());
    const SEEDS: usize = 16;
    // Depth-first search over the intervals between consecutive nodes of a fixed-size stack
    // (no heap allocation): nodes[..n] are sorted by θ and the interval being examined is the
    // last pair. Each split adds one node and each pruned interval removes one, so the stack
    // holds SEEDS + 1 nodes plus the current depth, about 45 for midpoint splits to 1e-14.
    let first = node_at(sv, theta_start, normal_at(theta_start)).ok_or(QueryError::Degenerate)?;
    let mut nodes = [first; NODE_STACK];
    let mut n = 1;
    for k in 1..=SEEDS {
        let th = theta_start + 2.0 * PI * k as f64 / SEEDS as f64;
        let node = if k == SEEDS {
            Node { theta: th, ..first }
        } else {
            node_at(sv, th, normal_at(th)).ok_or(QueryError::Degenerate)?
        };
        consider(&mut best, node.phi, &node.jet);
        nodes[n] = node;
        n += 1;
    }
    let mut status = DistanceStatus::Penetrating;
    while n >= 2 {
        let (a, b) = (nodes[n - 2], nodes[n - 1]);
        if sv.evaluations >= options.max_evaluations || n == NODE_STACK {
            status = DistanceStatus::OutOfIterations;
            break;
        }
        let best_v = best.map_or(f64::NEG_INFINITY, |(_, j)| j.fwd);
        let delta = b.theta - a.theta;
        // Upper bounds on F over the interval (module docs, "Bounds on an interval"), the
        // cheapest first; F's slopes into it: from the right at a, from the left at b.
        let (ga, gb) = (-a.side_hi, -b.jet.side);
        let f_low = (a.jet.fwd + b.jet.fwd) * 0.5 - lip * delta * 0.5;
        let prune = |ub: f64| ub <= best_v + tol;
        let parabolas = |r: f64| envelope_max(a.jet.fwd, ga, b.jet.fwd, gb, (-f_low - r).max(0.0), delta);
        let sinusoids = |r: f64| sine_envelope_max(a.jet.fwd + r, ga, b.jet.fwd + r, gb, delta) - r;
        let pruned = delta < MIN_INTERVAL || prune(parabolas(r_min)) || {
            let mid = unit(0.5 * (a.theta + b.theta));
            let half = 0.5 * delta;
            let r = (radius_bound(obj1.min_radius_of_curvature_near(frame.unrotate(mid), half))
                + radius_bound(obj2.min_radius_of_curvature_near(-mid, half)))
            .max(r_min);
            (r > r_min && prune(parabolas(r))) || prune(sinusoids(r))
        };
        if pruned {
            n -= 1;
            continue;
        }
        // A sign change S(a) < 0 < S(b) holds a local maximum: solve for it.
        let mut split = (0.5 * (a.theta + b.theta), None);
        if a.side_hi < 0.0 && b.jet.side > 0.0 {
            let (pa, mut pb) = (a.phi, b.phi);
            if pb < pa {
                pb += 2.0 * PI;
            }
            if let Some((phi, j)) = sv.bracketed_root(pa, a.jet, pb, b.jet) {
                consider(&mut best, phi, &j);
                let th = j.normal_in_2.y.atan2(j.normal_in_2.x);
                let th = a.theta + ccw_angle(unit(a.theta), unit(th));
                if th > a.theta + SPLIT_MARGIN * delta && th < b.theta - SPLIT_MARGIN * delta {
                    // The node takes the root's own normal: on a flat piece that is the
                    // piece's normal to the bit, so the node gets both of F's slopes.
                    split = (th, Some(j.curve1.normal));
                }
            }
        }
        let (th, n1) = split;
        let mid = match node_at(sv, th, n1.unwrap_or_else(|| normal_at(th))) {
            Some(n) => n,
            None => return Err(QueryError::Degenerate),
        };
        consider(&mut best, mid.phi, &mid.jet);
        nodes[n - 1] = mid;
        nodes[n] = b;
        n += 1;
    }
    Ok((best.ok_or(QueryError::Degenerate)?, status))
}

/// The best point `best` of [`global_search`], its witness moved opposite object2's point when
/// it lies on a flat piece of object1: there F does not depend on φ, so the search may end
/// anywhere along it; S is linear there (S_φ = σ), and one clamped Newton step puts it there
/// (kept only where F stays within the tolerance).
fn polish_on_flat<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    sv: &mut Solver<A, B>,
    best: (f64, PairPoint),
    size: f64,
    options: &DistanceOptions,
) -> (f64, PairPoint) {
    let (mut phi, mut j) = best;
    let tol = options.distance_tolerance * size;
    if j.curve1.normal_turn_rate() == 0.0 && j.side.abs() > sv.side_tol && j.side_p > 0.0 {
        let (lo, hi) = sv.obj1.phi_range_of_normal(j.curve1.normal);
        let w = wrap_phi(phi);
        if lo <= w && w <= hi {
            let target = (w - j.side / j.side_p).clamp(lo, hi);
            if let Some(jt) = sv.eval(target) {
                if (jt.fwd - j.fwd).abs() <= tol.max(1e-12 * size) {
                    phi = target;
                    j = jt;
                }
            }
        }
    }
    (phi, j)
}

fn consider(best: &mut Option<(f64, PairPoint)>, phi: f64, j: &PairPoint) {
    if best.is_none_or(|(_, b)| j.fwd > b.fwd) {
        *best = Some((phi, *j));
    }
}

/// Exact maximum over x ∈ [0, δ] of min(fa + ga·x + m x²/2, fb − gb·(δ − x) + m (δ − x)²/2).
/// The two parabolas share their quadratic coefficient, so their difference is linear and
/// they cross at most once; each is convex, so the envelope's maximum is at 0, δ or the crossing.
pub(crate) fn envelope_max(fa: f64, ga: f64, fb: f64, gb: f64, m: f64, delta: f64) -> f64 {
    let f1 = |x: f64| fa + ga * x + 0.5 * m * x * x;
    let f2 = |x: f64| fb - gb * (delta - x) + 0.5 * m * (delta - x) * (delta - x);
    let env = |x: f64| f1(x).min(f2(x));
    let mut best = env(0.0).max(env(delta));
    // f1 − f2 = (fa − fb − gb·δ + m δ²/2·(−1)) + (ga − gb + m δ)·x … solve linear.
    let c0 = f1(0.0) - f2(0.0);
    let c1 = (f1(delta) - f2(delta)) - c0;
    if c1 != 0.0 {
        let x = -c0 / c1 * delta;
        if x > 0.0 && x < delta {
            best = best.max(env(x));
        }
    }
    best
}

/// A curve's lower bound on its radius of curvature as the bounds take it: a negative or
/// non-finite one (a curve that breaks its contract) as 0, which is always valid.
fn radius_bound(r: f64) -> f64 {
    if r.is_finite() && r > 0.0 {
        r
    } else {
        0.0
    }
}

/// Exact maximum over x ∈ [0, δ] (0 < δ < π; ∞ otherwise) of the lower envelope of two
/// sinusoids, u_a(x) = wa·cos x + pa·sin x (value wa and slope pa at x = 0) and
/// u_b(x) = wb·cos(δ − x) − pb·sin(δ − x) (value wb and slope pb at x = δ).
///
/// The maximum of min(u_a, u_b) over the interval is at an end, at a crossing, or at an interior
/// maximum of the lower one of the two. Each is A·cos(x − α) with α = atan2(pa, wa) for u_a and
/// α = δ + atan2(pb, wb) for u_b, so each has at most one stationary point in an interval
/// shorter than π, and u_a − u_b = P·cos x + Q·sin x (P = wa − wb·cos δ + pb·sin δ,
/// Q = pa − wb·sin δ − pb·cos δ) vanishes at atan2(−P, Q) + kπ: at most one crossing. The envelope
/// is evaluated at those points inside the interval and at its ends.
pub(crate) fn sine_envelope_max(wa: f64, pa: f64, wb: f64, pb: f64, delta: f64) -> f64 {
    if !(delta > 0.0 && delta < PI) {
        return f64::INFINITY;
    }
    let ua = |x: f64| {
        let (s, c) = sin_cos(x);
        wa * c + pa * s
    };
    let ub = |x: f64| {
        let (s, c) = sin_cos(delta - x);
        wb * c - pb * s
    };
    let env = |x: f64| ua(x).min(ub(x));
    let mut best = env(0.0).max(env(delta));
    let mut at = |x: f64| {
        if x > 0.0 && x < delta {
            best = best.max(env(x));
        }
    };
    at(pa.atan2(wa));
    at(delta + pb.atan2(wb));
    let (sd, cd) = sin_cos(delta);
    let p = wa - wb * cd + pb * sd;
    let q = pa - wb * sd - pb * cd;
    if p != 0.0 || q != 0.0 {
        let x0 = (-p).atan2(q);
        at(x0);
        at(x0 + PI);
        at(x0 - PI);
    }
    best
}

fn finish<A: ConvexCurve + ?Sized, B: ConvexCurve + ?Sized>(
    sv: &Solver<A, B>,
    phi: f64,
    j: &PairPoint,
    status: DistanceStatus,
) -> StationaryDistance {
    let answer = StationaryDistance {
        distance: j.fwd,
        phi,
        point1: j.curve1.point,
        point2: j.support2.point,
        normal1: j.curve1.normal,
        normal2: -j.normal_in_2,
        status,
        newton_iterations: sv.newton,
        evaluations: sv.evaluations,
    };
    // Where φ could not resolve the root (|S| above the side tolerance on a turning piece of
    // object1), Newton's steps over the normal angle (`polish`).
    match polish(sv.obj2, &sv.frame, phi, j, sv.side_tol) {
        Some(p) => StationaryDistance {
            distance: p.fwd,
            // A penetration the polish shows apart is apart: F > 0 at a local maximum is the
            // global one (the positive part of F is concave in the normal angle).
            status: if p.fwd > 0.0 && status == DistanceStatus::Penetrating {
                DistanceStatus::Separated
            } else {
                status
            },
            point1: p.point1,
            point2: p.point2,
            normal1: p.normal1,
            normal2: -p.normal_in_2,
            ..answer
        },
        None => answer,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BallCurve, CapsuleEllipse, Ellipse, RoundedPolygon};

    fn d(o1: &dyn ConvexCurve, o2: &dyn ConvexCurve, x: f64, y: f64, a: f64) -> StationaryDistance {
        stationary_distance(o1, o2, &Pose::new(Vector::new(x, y), a), &DistanceOptions::default()).unwrap()
    }

    #[test]
    fn two_discs_match_the_closed_form() {
        let (a, b) = (BallCurve { radius: 0.7 }, BallCurve { radius: 0.4 });
        for (x, y) in [(2.0, 0.3), (0.5, -0.2), (-1.0, 0.05), (0.0, 0.3)] {
            let r = d(&a, &b, x, y, 0.4);
            let exact = (x * x + y * y).sqrt() - 1.1;
            assert!((r.distance - exact).abs() < 1e-12, "{x},{y}: {} vs {exact}", r.distance);
        }
    }

    #[test]
    fn coaxial_ellipses_match_the_closed_form() {
        let (e1, e2) = (Ellipse::new(0.5, 0.8), Ellipse::new(0.3, 2.0));
        for x in [3.0, 0.81, 0.7, 0.2] {
            let r = d(&e1, &e2, x, 0.0, 0.0);
            assert!((r.distance - (x - 0.8)).abs() < 1e-12, "x={x}: {}", r.distance);
        }
        // Along y, the other axis pair.
        let r = d(&e1, &e2, 0.0, 3.5, 0.0);
        assert!((r.distance - 0.7).abs() < 1e-12);
    }

    #[test]
    fn disc_against_a_box_face_matches_the_closed_form() {
        let bx = RoundedPolygon::new(
            &[
                Vector::new(-1.0, -1.0),
                Vector::new(1.0, -1.0),
                Vector::new(1.0, 1.0),
                Vector::new(-1.0, 1.0),
            ],
            0.0,
        );
        let ball = BallCurve { radius: 0.5 };
        for (x, y) in [(2.0, 0.3), (1.2, -0.9), (1.4, 0.0), (0.2, 1.3)] {
            let r = d(&bx, &ball, x, y, 0.0);
            let exact = if x.abs() > y.abs() {
                x.abs() - 1.5
            } else {
                y.abs() - 1.5
            };
            assert!(
                (r.distance - exact).abs() < 1e-12,
                "({x},{y}): {} vs {exact}",
                r.distance
            );
        }
    }

    #[test]
    fn witness_on_a_flat_face_is_opposite_the_other_shapes_point() {
        // A wide box whose top face overlaps a disc near x = 0.3: the witness on the box must be
        // straight below the disc's deepest point, not anywhere along the face.
        let bx = RoundedPolygon::new(
            &[
                Vector::new(-20.0, -0.5),
                Vector::new(20.0, -0.5),
                Vector::new(20.0, 0.5),
                Vector::new(-20.0, 0.5),
            ],
            0.0,
        );
        let r = d(&bx, &BallCurve { radius: 0.25 }, 0.3, 0.7, 0.0);
        assert!((r.distance + 0.05).abs() < 1e-12);
        assert!((r.point1 - Vector::new(0.3, 0.5)).length() < 1e-9, "{:?}", r.point1);
    }

    #[test]
    fn thin_ellipses_find_the_global_extremum() {
        // Appendix C: 1:1000 against 1:15, poses where the start guess lands on a wrong local max.
        let e1 = Ellipse::new(1.0, 0.001);
        let e2 = Ellipse::new(0.1, 1.5);
        for (x, y, a) in [(1.4, 0.9, 0.4), (0.3, 1.0, 1.2), (-1.2, -0.5, 2.0)] {
            let r = d(&e1, &e2, x, y, a);
            // Reference: dense search over θ of the gap F.
            let pos12 = Pose::new(Vector::new(x, y), a);
            let mut best = f64::NEG_INFINITY;
            for k in 0..200_000 {
                let th = -PI + 2.0 * PI * k as f64 / 200_000.0;
                let n = unit(th);
                let h1 = e1.support_point(n).dot(n);
                let n2 = pos12.rotation.inverse_transform_vector(-n);
                let s2 = pos12 * e2.support_point(n2);
                best = best.max(s2.dot(n) - h1);
            }
            assert!(
                (r.distance - best).abs() < 1e-6,
                "({x},{y},{a}): {} vs {best}",
                r.distance
            );
        }
    }

    #[test]
    fn sine_envelope_max_is_the_envelopes_maximum() {
        // Against dense sampling of min(u_a, u_b) over random values, slopes and widths: never
        // below the sampled maximum, and above it by no more than the sampling can miss.
        let mut seed = 3u64;
        let mut next = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..2000 {
            let (wa, pa, wb, pb) = (
                4.0 * next() - 2.0,
                4.0 * next() - 2.0,
                4.0 * next() - 2.0,
                4.0 * next() - 2.0,
            );
            let delta = [1e-6, 1e-3, 0.1, 0.4, 1.5, 3.1][(next() * 6.0) as usize];
            let got = sine_envelope_max(wa, pa, wb, pb, delta);
            let k = 20_000;
            let mut sampled = f64::NEG_INFINITY;
            for i in 0..=k {
                let x = delta * i as f64 / k as f64;
                let ua = wa * x.cos() + pa * x.sin();
                let ub = wb * (delta - x).cos() - pb * (delta - x).sin();
                sampled = sampled.max(ua.min(ub));
            }
            // Between samples the envelope moves by at most its slope (≤ 2√2·2) times half a step.
            let slack = 6.0 * delta / k as f64 + 1e-14;
            assert!(got >= sampled - 1e-14, "{wa} {pa} {wb} {pb} {delta}: {got} < {sampled}");
            assert!(got <= sampled + slack, "{wa} {pa} {wb} {pb} {delta}: {got} > {sampled}");
        }
        assert_eq!(sine_envelope_max(1.0, 0.0, 1.0, 0.0, PI), f64::INFINITY);
    }

    #[test]
    fn a_disc_centred_on_a_sharp_corner_is_certified_in_few_evaluations() {
        // F ≡ −R over the corner's whole cone of normals: a flat maximum the sinusoid bound drops
        // at once (the parabolas ran to the evaluation cap, 4,000, and `OutOfIterations`).
        let bx = RoundedPolygon::new(
            &[
                Vector::new(0.0, 0.0),
                Vector::new(1.0, 0.0),
                Vector::new(1.0, 1.0),
                Vector::new(0.0, 1.0),
            ],
            0.0,
        );
        for (o2, r) in [
            (&Ellipse::new(1.0, 1.0) as &dyn ConvexCurve, 1.0),
            (&BallCurve { radius: 0.3 }, 0.3),
        ] {
            for (x, y) in [(1.0, 1.0), (0.0, 0.0), (1.0, 0.0), (0.0, 1.0)] {
                let res = d(&bx, o2, x, y, 0.0);
                assert_eq!(res.status, DistanceStatus::Penetrating, "({x}, {y})");
                assert!((res.distance + r).abs() < 1e-12, "({x}, {y}): {}", res.distance);
                assert!(res.evaluations <= 40, "({x}, {y}): {} evaluations", res.evaluations);
            }
        }
    }

    #[test]
    fn penetration_depth_of_overlapping_discs() {
        let r = d(&BallCurve { radius: 1.0 }, &BallCurve { radius: 1.0 }, 1.5, 0.0, 0.0);
        assert!((r.distance + 0.5).abs() < 1e-12);
        assert_eq!(r.status, DistanceStatus::Penetrating);
        let r = d(
            &CapsuleEllipse::new(0.5, 1.0, 0.8),
            &Ellipse::new(0.5, 0.5),
            0.9,
            0.0,
            0.0,
        );
        assert!((r.distance + 0.1).abs() < 1e-12, "{}", r.distance);
    }
}
