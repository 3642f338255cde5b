//! What of a user's curve can be checked when it is wrapped ([`crate::CustomCurve::try_new`]):
//! the [`ConvexCurve`] contract on a fixed sample of the curve, each failure a
//! [`ShapeError::BrokenContract`] naming the method that answered wrongly.
//!
//! The sample is the uniform grid of [`GRID`] values of φ over [−π, π) with the start and the
//! middle of every piece between breakpoints, sorted by φ. On it:
//!
//! * `breakpoints`: finite, in [−π, π), strictly increasing;
//! * `bounding_radius`: finite, within [`crate::MIN_LENGTH`], 4·[`crate::MAX_LENGTH`] (the
//!   errors of the other shapes' lengths), and at least |P| at every sampled point;
//! * `eval`: every number finite; N unit; P′ and N′ along the tangent T = N⊥; ω = N × N′ ≥ 0 and
//!   σ = P′·T ≥ 0 (counter-clockwise, convex); N outward: every sampled point P with its normal N
//!   has the grid's reference points (every [`REFERENCE_STRIDE`]-th) behind its tangent line,
//!   N·(P − Q) ≥ 0, which is also convexity; φ outside [−π, π) wrapped (P(φ ± 2π) = P(φ)); the area
//!   ½∮P × P′ of Green's theorem (the mass quadrature, on P′) at least that of the sampled polygon
//!   inscribed in the curve and at most that of the bounding disc, π·`bounding_radius`²;
//! * `phi_range_of_normal`, `support_point` (at the grid's normals): an interval of φ within one
//!   turn, whose point is (as the support point is) as far along the normal as any grid point;
//! * `min_radius_of_curvature`: finite, ≥ 0, at most the radius of curvature σ/ω at the sampled
//!   points where the normal turns; `min_radius_of_curvature_near` the same, at each such point's
//!   normal over arcs of half-angle 0 and 2π/256;
//! * for a curve that says it is strictly convex: no flat piece sampled; `support_jet` at each
//!   sampled normal present, finite, with the support value of the sampled point and ρ ≥ 0;
//!   `max_radius_of_curvature` finite and at least every sampled ρ; `support_dd_bound` and
//!   `support_dd_bound_near` finite and at least the sampled |h″| = |ρ − h|.
//!
//! Each comparison allows [`CONTRACT_TOLERANCE`] (relative: of the bounding radius for lengths,
//! of 1 for unit vectors), so that a curve computed in f32 passes; the upper bounds on curvature
//! [`BOUND_TOLERANCE`]. What a sample cannot check is
//! the contract between its points: that the bounds (`bounding_radius`, `max_radius_of_curvature`,
//! `support_dd_bound`, `support_dd_bound_near`) hold at every φ and direction, that
//! `min_radius_of_curvature` and `min_radius_of_curvature_near` are lower bounds everywhere, that the derivatives are those of P and
//! N, that nothing changes between the sampled points. What breaks when they do not hold is
//! stated on each method of [`ConvexCurve`].

// The negated comparisons (`!(x >= y)`) are deliberate: they are true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::curve::pieces::piece_bounds;
use crate::curve::ConvexCurve;
use crate::error::{ShapeError, MAX_LENGTH, MIN_LENGTH};
use crate::numerics::math::{cross, unit_or_x, Vector};
use core::f64::consts::{PI, TAU};

/// A bounding radius may reach this many times [`MAX_LENGTH`]: a shape of the crate built at
/// that length has its radius about twice it (a polygon's vertex plus its corner radius), and
/// products of six such radii stay finite.
const RADIUS_SPAN: f64 = 4.0;
/// Values of φ of the uniform grid every curve is sampled on (besides each piece's start and
/// middle).
const GRID: usize = 256;
/// Every this many grid points is a reference point of the outward-normal check (32 in all:
/// that check costs 32 dot products per sampled point).
const REFERENCE_STRIDE: usize = 8;
/// The grid points at which `eval` is also asked at φ ± 2π (every this many: 8 in all).
const WRAP_STRIDE: usize = 32;
/// The tolerance of every check: relative to the bounding radius for lengths, to 1 for unit
/// vectors and to the quantities compared otherwise. A curve computed in f32 (relative errors
/// about 1e-7) passes; one whose normals are off by a thousandth does not.
pub(crate) const CONTRACT_TOLERANCE: f64 = 1e-6;
/// The tolerance of the checks of upper bounds on curvature (`max_radius_of_curvature`,
/// `support_dd_bound`, `support_dd_bound_near`): relative. Looser than [`CONTRACT_TOLERANCE`]
/// because the bounds are computed from the shape's numbers, not measured on it: the crate's own
/// [`crate::Ellipse`] computes h² = b² + (a² − b²)cos²ψ in `support_dd_bound_near`, which loses
/// up to 3e-4 of |h″| along the thin axis of a 1:1e6 ellipse, and is wrapped in a
/// [`crate::CustomCurve`] by users and tests alike. A bound off by a factor (0, half the true
/// one) is still refused.
const BOUND_TOLERANCE: f64 = 1e-3;
/// Rounding in φ (a few ulps of π) turns a normal by up to this many times |N′|: the slack of the
/// check that compares two evaluations at the same φ reached two ways.
const PHI_ROUNDING: f64 = 1e-14;

/// What the checks of the curve's geometry learnt of it, for the checks that follow.
pub(crate) struct Checked {
    /// The largest |P| over the sample (at most the bounding radius, to the tolerance).
    pub sampled_radius: f64,
    /// The area of the polygon of the sampled points (a lower bound on the curve's area).
    pub inscribed_area: f64,
    /// The bounding radius.
    br: f64,
    samples: Vec<Sample>,
}

/// A [`ShapeError::BrokenContract`] of `method`.
fn broken(method: &'static str, reason: &'static str, at: f64) -> ShapeError {
    ShapeError::BrokenContract { method, reason, at }
}

/// One sampled point.
#[derive(Copy, Clone)]
struct Sample {
    phi: f64,
    /// A point of the uniform grid (not only a piece's start or middle).
    grid: bool,
    point: Vector,
    normal: Vector,
    /// σ/ω where the normal turns (0 at a corner); `None` on a flat piece.
    rho: Option<f64>,
}

/// The checks of the curve's geometry (the module docs' list up to `phi_range_of_normal` and
/// `support_point`), in their order; the first failure is the error. The area and the
/// curvature bounds follow ([`check_area`], [`check_curvature`]).
pub(crate) fn check_curve(c: &dyn ConvexCurve) -> Result<Checked, ShapeError> {
    check_breakpoints(c.breakpoints())?;
    let br = check_bounding_radius(c.bounding_radius())?;
    let samples = sample(c, br)?;
    check_wrapping(c, br)?;
    let grid: Vec<Sample> = samples.iter().copied().filter(|s| s.grid).collect();
    check_outward(&samples, &grid, br)?;
    check_normal_ranges(c, &grid, br)?;
    let sampled_radius = samples.iter().fold(0.0f64, |r, s| r.max(s.point.length()));
    let n = samples.len();
    let inscribed_area = 0.5
        * (0..n)
            .map(|k| cross(samples[k].point, samples[(k + 1) % n].point))
            .sum::<f64>();
    Ok(Checked {
        sampled_radius,
        inscribed_area,
        br,
        samples,
    })
}

/// The curvature bounds of the module docs, on the sample of [`check_curve`].
pub(crate) fn check_curvature(c: &dyn ConvexCurve, checked: &Checked) -> Result<(), ShapeError> {
    let grid: Vec<Sample> = checked.samples.iter().copied().filter(|s| s.grid).collect();
    check_curvature_bounds(c, &checked.samples, &grid, checked.br)
}

/// The area given by Green's theorem on the curve (`area`) against the sample's bounds: at
/// least the inscribed polygon's, at most the bounding disc's. (An `eval` whose derivatives are
/// not those of its points fails here: a `d_point` of 0 gives a body with no mass.)
pub(crate) fn check_area(area: f64, checked: &Checked) -> Result<(), ShapeError> {
    let br = checked.br;
    let lo = checked.inscribed_area * (1.0 - CONTRACT_TOLERANCE);
    let hi = PI * br * br * (1.0 + CONTRACT_TOLERANCE);
    if !(area.is_finite() && area > 0.0 && area >= lo && area <= hi) {
        return Err(broken(
            "eval",
            "the area ½∮P × P′ (Green's theorem on its points and derivatives) is not between that of \
             the sampled polygon and that of the bounding disc",
            area,
        ));
    }
    Ok(())
}

/// φ of grid point k.
fn grid_phi(k: usize) -> f64 {
    -PI + TAU * k as f64 / GRID as f64
}

fn check_breakpoints(bp: &[f64]) -> Result<(), ShapeError> {
    for (k, &b) in bp.iter().enumerate() {
        if !(b.is_finite() && (-PI..PI).contains(&b)) {
            return Err(broken("breakpoints", "a breakpoint outside [−π, π)", b));
        }
        if k > 0 && !(bp[k - 1] < b) {
            return Err(broken("breakpoints", "not strictly increasing", b));
        }
    }
    Ok(())
}

fn check_bounding_radius(br: f64) -> Result<f64, ShapeError> {
    let name = "bounding_radius";
    if !br.is_finite() {
        Err(ShapeError::NotFinite { name, value: br })
    } else if br <= 0.0 {
        Err(ShapeError::NotPositive { name, value: br })
    } else if !(MIN_LENGTH..=RADIUS_SPAN * MAX_LENGTH).contains(&br) {
        Err(ShapeError::OutOfRange { name, value: br })
    } else {
        Ok(br)
    }
}

/// The sampled points, sorted by φ, each checked on its own (finite, unit normal, derivatives
/// along the tangent, turning counter-clockwise, within the bounding radius).
fn sample(c: &dyn ConvexCurve, br: f64) -> Result<Vec<Sample>, ShapeError> {
    let bp = c.breakpoints();
    let mut phis: Vec<(f64, bool)> = (0..GRID).map(|k| (grid_phi(k), true)).collect();
    for k in 0..bp.len() {
        let (s, e) = piece_bounds(bp, k);
        let mid = s + 0.5 * (e - s);
        phis.push((s, false));
        phis.push((if mid >= PI { mid - TAU } else { mid }, false));
    }
    // By φ, a grid point before a piece's point at the same φ (which the dedup then drops).
    phis.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.cmp(&a.1)));
    phis.dedup_by(|later, kept| later.0 == kept.0);
    let tol = CONTRACT_TOLERANCE;
    let mut out = Vec::with_capacity(phis.len());
    for (phi, grid) in phis {
        let cp = c.eval(phi);
        if !cp.is_finite() {
            return Err(broken("eval", "a non-finite number", phi));
        }
        if (cp.normal.length() - 1.0).abs() > tol {
            return Err(broken("eval", "a normal that is not a unit vector", phi));
        }
        let (dp, dn) = (cp.d_point.length(), cp.d_normal.length());
        // The scales the derivatives' components are compared with (a corner has P′ = 0).
        let (len_scale, turn_scale) = (dp + br * dn, dn + dp / br);
        if cp.d_point.dot(cp.normal).abs() > tol * len_scale {
            return Err(broken("eval", "a d_point that is not along the tangent", phi));
        }
        if cp.d_normal.dot(cp.normal).abs() > tol * turn_scale {
            return Err(broken("eval", "a d_normal that is not along the tangent", phi));
        }
        let (omega, sigma) = (cp.normal_turn_rate(), cp.speed());
        if omega < -tol * turn_scale {
            return Err(broken("eval", "a normal turning clockwise (ω = N × N′ < 0)", phi));
        }
        if sigma < -tol * len_scale {
            return Err(broken("eval", "a point moving clockwise (σ = P′·N⊥ < 0)", phi));
        }
        if cp.point.length() > br * (1.0 + tol) {
            return Err(broken(
                "bounding_radius",
                "below the distance of a boundary point from the origin",
                phi,
            ));
        }
        // Where the normal turns at all: a thin ellipse's flat side turns slowly, not never.
        let rho = if omega > 0.0 {
            Some((sigma / omega).max(0.0)).filter(|r| r.is_finite())
        } else {
            None
        };
        out.push(Sample {
            phi,
            grid,
            point: cp.point,
            normal: cp.normal,
            rho,
        });
    }
    Ok(out)
}

/// `eval` wraps φ: at a few grid points, φ ± 2π gives the same point and normal.
fn check_wrapping(c: &dyn ConvexCurve, br: f64) -> Result<(), ShapeError> {
    for k in (0..GRID).step_by(WRAP_STRIDE) {
        let phi = grid_phi(k);
        let cp = c.eval(phi);
        for shifted in [phi + TAU, phi - TAU] {
            // The support value along the normal and the normal itself: well conditioned where
            // the point is not (a thin ellipse packs its flat side into 1e-20 of φ).
            let other = c.eval(shifted);
            let moved = (other.point - cp.point).dot(cp.normal).abs();
            let turned = (other.normal - cp.normal).length();
            let (slack, turn_slack) = (
                CONTRACT_TOLERANCE * br,
                CONTRACT_TOLERANCE + PHI_ROUNDING * cp.d_normal.length(),
            );
            if !(moved <= slack && turned <= turn_slack) {
                return Err(broken(
                    "eval",
                    "φ outside [−π, π) not wrapped: P(φ ± 2π) ≠ P(φ)",
                    shifted,
                ));
            }
        }
    }
    Ok(())
}

/// Every sampled normal is outward with the reference points behind its tangent line (the
/// support property: convex and outward).
fn check_outward(samples: &[Sample], grid: &[Sample], br: f64) -> Result<(), ShapeError> {
    let slack = CONTRACT_TOLERANCE * br;
    let refs: Vec<Vector> = grid.iter().step_by(REFERENCE_STRIDE).map(|s| s.point).collect();
    for s in samples {
        if refs.iter().any(|q| s.normal.dot(s.point - *q) < -slack) {
            return Err(broken(
                "eval",
                "a normal that is not outward, or a curve that is not convex (a boundary point beyond \
                 the tangent line)",
                s.phi,
            ));
        }
    }
    Ok(())
}

/// The largest support value over the grid's points along `n`.
fn grid_support(grid: &[Sample], n: Vector) -> f64 {
    grid.iter().fold(f64::NEG_INFINITY, |h, s| h.max(s.point.dot(n)))
}

/// `phi_range_of_normal` and `support_point` at the grid's normals.
fn check_normal_ranges(c: &dyn ConvexCurve, grid: &[Sample], br: f64) -> Result<(), ShapeError> {
    let slack = CONTRACT_TOLERANCE * br;
    for s in grid {
        let n = unit_or_x(s.normal);
        let angle = n.y.atan2(n.x);
        let h = grid_support(grid, n);
        let (lo, hi) = c.phi_range_of_normal(n);
        let in_turn = lo.is_finite() && hi.is_finite() && lo <= hi && hi - lo <= TAU && (-PI - 1e-9..=PI).contains(&lo);
        if !in_turn {
            return Err(broken(
                "phi_range_of_normal",
                "not an interval of φ within one turn",
                angle,
            ));
        }
        let p = c.eval(lo + 0.5 * (hi - lo)).point;
        if !(p.dot(n) >= h - slack) {
            return Err(broken(
                "phi_range_of_normal",
                "a φ whose point is not the support point of the normal",
                angle,
            ));
        }
        let sp = c.support_point(n);
        if !(sp.is_finite() && sp.dot(n) >= h - slack && sp.length() <= br * (1.0 + CONTRACT_TOLERANCE)) {
            return Err(broken("support_point", "not the support point of the direction", angle));
        }
    }
    Ok(())
}

/// The curvature bounds: `min_radius_of_curvature` and `min_radius_of_curvature_near` for every
/// curve; for a strictly convex one `support_jet`, `max_radius_of_curvature`, `support_dd_bound`
/// and `support_dd_bound_near`.
fn check_curvature_bounds(c: &dyn ConvexCurve, samples: &[Sample], grid: &[Sample], br: f64) -> Result<(), ShapeError> {
    let tol = CONTRACT_TOLERANCE;
    let min_rho = c.min_radius_of_curvature();
    if !(min_rho.is_finite() && min_rho >= 0.0) {
        return Err(broken("min_radius_of_curvature", "negative or not finite", min_rho));
    }
    for s in samples {
        if let Some(rho) = s.rho {
            let above_rho = |bound: f64| bound > rho * (1.0 + tol) + tol * br;
            if above_rho(min_rho) {
                return Err(broken(
                    "min_radius_of_curvature",
                    "above the radius of curvature σ/ω of a sampled point",
                    s.phi,
                ));
            }
            let n = unit_or_x(s.normal);
            for half_angle in [0.0, TAU / GRID as f64] {
                let near = c.min_radius_of_curvature_near(n, half_angle);
                if !(near >= 0.0) || near.is_infinite() || above_rho(near) {
                    return Err(broken(
                        "min_radius_of_curvature_near",
                        "negative, not finite, or above the radius of curvature σ/ω of a sampled point",
                        s.phi,
                    ));
                }
            }
        }
    }
    if !c.is_strictly_convex() {
        return Ok(());
    }
    let max_rho = c.max_radius_of_curvature();
    if !(max_rho.is_finite() && max_rho >= 0.0) {
        return Err(broken(
            "max_radius_of_curvature",
            "not a finite bound for a strictly convex curve",
            max_rho,
        ));
    }
    let dd = c.support_dd_bound();
    if !(dd.is_finite() && dd >= 0.0) {
        return Err(broken("support_dd_bound", "negative or not finite", dd));
    }
    let above = |bound: f64, x: f64| bound >= x * (1.0 - BOUND_TOLERANCE) - tol * br;
    if let Some(flat) = samples.iter().find(|s| s.rho.is_none()) {
        return Err(broken(
            "is_strictly_convex",
            "true for a curve with a flat piece (a normal that does not turn)",
            flat.phi,
        ));
    }
    for s in samples {
        let n = unit_or_x(s.normal);
        let angle = n.y.atan2(n.x);
        let rho = s.rho.unwrap_or(0.0);
        let Some(j) = c.support_jet(n) else {
            return Err(broken("support_jet", "None for a strictly convex curve", angle));
        };
        let j_rho = j.radius_of_curvature;
        if !(j.point.is_finite() && j_rho.is_finite() && j_rho >= 0.0 && j.d_radius_of_curvature.is_finite()) {
            return Err(broken(
                "support_jet",
                "a non-finite number or a negative radius of curvature",
                angle,
            ));
        }
        let h = j.point.dot(n);
        if (h - s.point.dot(n)).abs() > tol * br || h < grid_support(grid, n) - tol * br {
            return Err(broken("support_jet", "not the support point of the direction", angle));
        }
        if !above(max_rho, rho.max(j_rho)) {
            return Err(broken(
                "max_radius_of_curvature",
                "below the radius of curvature at a sampled direction",
                angle,
            ));
        }
        let h_dd = (j_rho - h).abs();
        if !above(dd, h_dd) {
            return Err(broken(
                "support_dd_bound",
                "below |h″| = |ρ − h| at a sampled direction",
                angle,
            ));
        }
        for half_angle in [0.0, TAU / GRID as f64] {
            // (∞ is a bound: the ellipse's, in the directions where a thin one's h² cancels.)
            let near = c.support_dd_bound_near(n, half_angle);
            if !above(near, h_dd) {
                return Err(broken(
                    "support_dd_bound_near",
                    "below |h″| = |ρ − h| at a sampled direction",
                    angle,
                ));
            }
        }
    }
    Ok(())
}
