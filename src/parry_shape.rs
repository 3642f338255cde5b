//! parry `Shape` implementations for the crate's shapes: [`Ellipse`], [`RoundedPolygon`],
//! [`CapsuleEllipse`] and [`CustomCurve`].
//!
//! Each implements parry's `Shape`, `RayCast`, `PointQuery`, `SupportMap` and
//! `PolygonalFeatureMap`, reports `ShapeType::Custom` / `TypedShape::Custom(self)`, and so can be
//! wrapped in a `SharedShape` and used by parry's `DefaultQueryDispatcher` (through the support
//! map and the polygonal feature map) as well as by [`crate::SmoothDispatcher`].
//!
//! # Design choices
//!
//! * **Polygonal feature map.** parry builds contact manifolds between two convex shapes from
//!   one "polygonal feature" of each (at most two vertices) and panics (`unimplemented!`) when
//!   both are single vertices, so every feature returned here has two vertices, and
//!   `as_polygonal_feature_map` returns `(self, 0.0)` for all four shapes:
//!   * at a smooth support point: a tangent segment centred on the support point, of half-length
//!     min(10⁻⁴·R, ρ/4) (R the bounding radius, ρ the radius of curvature there; at least
//!     10⁻⁹·R). Both vertices project onto the direction exactly as the support point, so the
//!     distances parry derives from them are the exact gap, and the segment is too short to make
//!     a smooth body balance on a "flat patch";
//!   * within [`FLAT_FEATURE_MAX_ANGLE`] of the normal of a flat piece (the segment of a
//!     [`CapsuleEllipse`], a flat piece of a [`CustomCurve`]): that flat piece, or, when the
//!     support point has already left it, the chord from the piece's far end to the support
//!     point. Both vertices are boundary points, so every contact distance is exact, and a body
//!     resting on a flat side gets a two-point manifold;
//!   * for a [`RoundedPolygon`]: the core edge whose normal is best aligned with the direction
//!     (parry's choice for `ConvexPolygon`), translated by r·n̂. Clipping along n̂ is unchanged
//!     by a translation along n̂, so the contacts are exactly those parry computes for its
//!     `RoundConvexPolygon` (core feature, then shifted by the border radius); the vertex on
//!     the support side is the true support point. Feature ids follow parry's `ConvexPolygon`
//!     (vertex i → 2i, edge i → 2i + 1).
//! * **CCD thickness** follows parry: the smallest half-extent of the local AABB — min(a, b) for
//!   the ellipse; for the rounded polygon parry's `RoundConvexPolygon` value (smallest half-extent
//!   of the core polygon's AABB plus the corner radius). **CCD angular thickness**: π/2 for the
//!   ellipse (π for a circle), as parry's cuboid/capsule; π/4 for the rounded polygon (parry's
//!   convex-polygon value, which a border radius does not change); π/2 for the capsule-ellipse;
//!   π/4 (conservative) for custom curves.
//! * **Mass properties** are exact: the ellipse in closed form; the rounded polygon as core
//!   polygon + one rectangle r × Lᵢ on each edge + one circular sector (radius r, angle αᵢ) at
//!   each corner, every piece's area, first moment and polar second moment summed in closed form
//!   (note that parry's own `RoundConvexPolygon` ignores the border radius in its mass); the
//!   capsule-ellipse in closed form (half ellipse + rectangle + two quarter discs); custom curves
//!   by adaptive Gauss–Legendre quadrature of Green's theorem over each piece between
//!   breakpoints (area ½∮P×P′, first moment ⅓∮P (P×P′), polar moment ¼∮|P|²(P×P′)).
//! * **Ray casts**: closed form for the ellipse (scaled to the unit circle, stable quadratic).
//!   The other shapes use an exact generic method: with u the unit ray direction and
//!   m = (u_y, −u_x), f(φ) = (P(φ) − o) × u is monotone on each of the two arcs between the
//!   support points in ±m (increasing on the arc facing the ray, decreasing on the other), so
//!   the entry and exit points are the roots of f on those arcs, found by bracketed Newton.
//!   parry's `solid` semantics: a ray starting inside hits at time 0 (normal −u) when solid,
//!   otherwise at its exit point with the inward normal.
//! * **Point projection**: Eberly's robust bisection for the ellipse (exact also for 1:1000
//!   axes); exact for the rounded polygon (the signed distance of a dilated convex polygon is
//!   the core's minus r); for the capsule-ellipse and custom curves the closest point is a root
//!   of g(φ) = (x − P)·T where g changes sign from + to − (T the tangent); roots are bracketed
//!   on a grid over each piece (at least 4 cells per piece, 64 in all) and polished by
//!   bracketed Newton, and the closest of all candidates wins.
//! * **Scaling** (`scale_dyn`): an ellipse scales to an ellipse by any non-zero factors; a
//!   rounded polygon by a uniform factor (or any factors when its radius is 0); the
//!   capsule-ellipse by a uniform positive factor (a mirror in y is allowed: the shape is
//!   symmetric); a custom curve not at all (`None`).

use crate::capsule_ellipse::CapsuleEllipse;
use crate::curve::{ccw_angle, wrap_phi, ConvexCurve, CurvePoint};
use crate::custom_curve::CustomCurve;
use crate::ellipse::Ellipse;
use crate::math::{cross, perp, Real, Vector};
use crate::rounded_polygon::RoundedPolygon;
use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
use parry2d_f64::bounding_volume::{Aabb, BoundingSphere};
use parry2d_f64::mass_properties::MassProperties;
use parry2d_f64::query::{PointProjection, PointQuery, Ray, RayCast, RayIntersection};
use parry2d_f64::shape::{
    FeatureId, PackedFeatureId, PolygonalFeature, PolygonalFeatureMap, Shape, ShapeType, SupportMap, TypedShape,
};

/// Largest angle (radians) between a direction and the normal of a flat piece for which the
/// polygonal feature map returns that flat piece (or the chord from its far end to the support
/// point) instead of a short tangent segment.
pub const FLAT_FEATURE_MAX_ANGLE: f64 = 0.02;

/// Half-length of a tangent feature, relative to the bounding radius, at most.
const TANGENT_FEATURE_REL: f64 = 1e-4;
/// Half-length of a tangent feature, relative to the bounding radius, at least.
const TANGENT_FEATURE_MIN_REL: f64 = 1e-9;

// ---------------------------------------------------------------------------------------------
// Small helpers
// ---------------------------------------------------------------------------------------------

/// `d` normalised; +x for a zero, non-finite or NaN vector. Robust to under/overflow.
#[inline]
pub(crate) fn unit_or_x(d: Vector) -> Vector {
    if !d.is_finite() {
        return Vector::X;
    }
    let m = d.x.abs().max(d.y.abs());
    if m == 0.0 {
        return Vector::X;
    }
    let s = d / m;
    s / s.length()
}

/// `x + 2πk`, the representative of x in `[base, base + 2π)`.
#[inline]
fn unwrap_after(base: f64, x: f64) -> f64 {
    let mut y = x;
    if !(y.is_finite() && base.is_finite()) {
        return base;
    }
    let k = ((base - y) / (2.0 * PI)).ceil();
    if k > 0.0 {
        y += k * 2.0 * PI;
    }
    while y < base {
        y += 2.0 * PI;
    }
    while y >= base + 2.0 * PI {
        y -= 2.0 * PI;
    }
    y
}

/// The φ-interval of piece `k` of a curve (unwrapped: `end > start`, the last piece wraps).
#[inline]
fn piece_bounds(bp: &[f64], k: usize) -> (f64, f64) {
    if bp.is_empty() {
        return (-PI, PI);
    }
    let s = bp[k];
    let e = if k + 1 < bp.len() { bp[k + 1] } else { bp[0] + 2.0 * PI };
    (s, e)
}

/// Index of the piece containing φ (pieces start at the breakpoints; the last one wraps).
#[inline]
fn piece_index(bp: &[f64], phi: f64) -> usize {
    if bp.is_empty() {
        return 0;
    }
    let phi = wrap_phi(phi);
    let k = bp.partition_point(|&b| b <= phi);
    if k == 0 {
        bp.len() - 1
    } else {
        k - 1
    }
}

/// Bracketed, safeguarded Newton for an increasing function: `f(a) ≤ 0 ≤ f(b)`. `eval`
/// returns (f, f′). Returns the best root estimate (never leaves `[a, b]`).
fn solve_increasing(mut a: f64, mut b: f64, mut fa: f64, mut fb: f64, mut eval: impl FnMut(f64) -> (f64, f64)) -> f64 {
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    if !(fa < 0.0 && fb > 0.0) {
        // Not a proper bracket (NaN or rounding): the end closer to zero.
        return if fa.abs() <= fb.abs() || fb.is_nan() { a } else { b };
    }
    let (mut best_x, mut best_f) = if -fa < fb { (a, -fa) } else { (b, fb) };
    // Regula falsi start.
    let mut x = a - fa * (b - a) / (fb - fa);
    if !(x > a && x < b) {
        x = 0.5 * (a + b);
    }
    let mut width_before = b - a;
    for iter in 0..200 {
        let (fx, dfx) = eval(x);
        if fx.is_nan() {
            // Outside the curve's domain of validity: bisect.
            x = 0.5 * (a + b);
            if b - a <= 4.0 * f64::EPSILON * (a.abs() + b.abs()) {
                break;
            }
            continue;
        }
        if fx.abs() < best_f {
            best_f = fx.abs();
            best_x = x;
        }
        if fx == 0.0 {
            return x;
        }
        if fx < 0.0 {
            a = x;
            fa = fx;
        } else {
            b = x;
            fb = fx;
        }
        let width = b - a;
        if width <= 4.0 * f64::EPSILON * (a.abs() + b.abs()).max(1e-300) {
            break;
        }
        let newton = x - fx / dfx;
        let force_bisect = iter % 3 == 2 && width > 0.5 * width_before;
        if iter % 3 == 2 {
            width_before = width;
        }
        let next = if !force_bisect && newton.is_finite() && newton > a && newton < b {
            newton
        } else {
            // Secant on the bracket when it is well inside, else bisection.
            let s = a - fa * (b - a) / (fb - fa);
            let lo = a + 0.1 * width;
            let hi = b - 0.1 * width;
            if !force_bisect && s > lo && s < hi {
                s
            } else {
                0.5 * (a + b)
            }
        };
        if (next - x).abs() <= 2.0 * f64::EPSILON * x.abs().max(1e-300) {
            // Converged: one more evaluation would not move x.
            let (fn_, _) = eval(next);
            if fn_.abs() <= best_f {
                return next;
            }
            return best_x;
        }
        x = next;
    }
    best_x
}

// ---------------------------------------------------------------------------------------------
// Flat pieces and features
// ---------------------------------------------------------------------------------------------

/// A flat piece of a curve: the boundary segment from `start` to `end` (counter-clockwise)
/// with outward unit normal `normal`; `index` is the piece's index (between breakpoints).
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct FlatPiece {
    /// Outward unit normal.
    pub normal: Vector,
    /// First end (counter-clockwise).
    pub start: Vector,
    /// Second end.
    pub end: Vector,
    /// Index of the piece.
    pub index: u32,
}

/// Detects the flat pieces of a curve: pieces between two breakpoints along which the normal
/// does not turn and the point moves.
pub(crate) fn flat_pieces(c: &dyn ConvexCurve) -> Vec<FlatPiece> {
    let bp = c.breakpoints();
    let mut out = Vec::new();
    if bp.is_empty() {
        return out;
    }
    let size = c.bounding_radius().abs().max(f64::MIN_POSITIVE);
    for k in 0..bp.len() {
        let (s, e) = piece_bounds(bp, k);
        if e <= s || e.is_nan() || s.is_nan() {
            continue;
        }
        let samples = [0.25, 0.5, 0.75].map(|t| c.eval(s + t * (e - s)));
        let n0 = samples[1].normal;
        let flat = samples.iter().all(|cp| {
            cp.is_finite() && cp.d_normal.length() <= 1e-12 && (cp.normal - n0).length() <= 1e-12 && cp.speed() > 0.0
        });
        if !flat {
            continue;
        }
        let (p0, p1) = (c.eval(s).point, c.eval(e).point);
        if !(p0.is_finite() && p1.is_finite()) || (p1 - p0).length() <= 1e-12 * size {
            continue;
        }
        out.push(FlatPiece {
            normal: unit_or_x(n0),
            start: p0,
            end: p1,
            index: k as u32,
        });
    }
    out
}

/// The support point in the unit direction `n` and the radius of curvature there (∞ on a flat
/// piece or where the normal does not turn).
fn support_and_curvature(c: &dyn ConvexCurve, n: Vector) -> (Vector, f64) {
    if let Some(j) = c.support_jet(n) {
        return (j.point, j.radius_of_curvature);
    }
    let (lo, hi) = c.phi_range_of_normal(n);
    let p = c.support_point(n);
    if hi > lo {
        return (p, f64::INFINITY);
    }
    let cp = c.eval(lo);
    let w = cp.normal_turn_rate();
    let rho = if w > 0.0 { cp.speed() / w } else { f64::INFINITY };
    (p, rho)
}

/// A tangent segment centred on `p` (outward normal `n`), of half-length set by the radius of
/// curvature `rho` and the size `size`.
fn tangent_feature(p: Vector, n: Vector, rho: f64, size: f64, out: &mut PolygonalFeature) {
    let size = if size.is_finite() && size > 0.0 { size } else { 1.0 };
    let mut half = TANGENT_FEATURE_REL * size;
    if rho.is_finite() && rho >= 0.0 {
        half = half.min(0.25 * rho);
    }
    half = half.max(TANGENT_FEATURE_MIN_REL * size);
    let t = perp(n) * half;
    *out = PolygonalFeature {
        vertices: [p - t, p + t],
        vids: [PackedFeatureId::vertex(0), PackedFeatureId::vertex(1)],
        fid: PackedFeatureId::face(0),
        num_vertices: 2,
    };
}

/// The feature for a direction within [`FLAT_FEATURE_MAX_ANGLE`] of the flat piece `f`:
/// the piece itself, or the chord from its far end to the support point `p` once `p` has
/// left it.
fn flat_feature(f: &FlatPiece, p: Vector, size: f64, out: &mut PolygonalFeature) {
    let t = perp(f.normal);
    let (s0, s1, sp) = (f.start.dot(t), f.end.dot(t), p.dot(t));
    let tol = 1e-12 * size.max(f64::MIN_POSITIVE);
    let vertices = if sp > s1 + tol {
        [f.start, p]
    } else if sp < s0 - tol {
        [p, f.end]
    } else {
        [f.start, f.end]
    };
    let k = f.index;
    *out = PolygonalFeature {
        vertices,
        vids: [PackedFeatureId::vertex(2 * k + 2), PackedFeatureId::vertex(2 * k + 3)],
        fid: PackedFeatureId::face(k + 1),
        num_vertices: 2,
    };
}

/// The polygonal feature of a curve with flat pieces `flats` in direction `dir`.
fn curve_feature(c: &dyn ConvexCurve, flats: &[FlatPiece], dir: Vector, out: &mut PolygonalFeature) {
    let n = unit_or_x(dir);
    let size = c.bounding_radius();
    let cos_max = FLAT_FEATURE_MAX_ANGLE.cos();
    let mut best: Option<&FlatPiece> = None;
    let mut best_dot = cos_max;
    for f in flats {
        let d = f.normal.dot(n);
        if d >= best_dot {
            best_dot = d;
            best = Some(f);
        }
    }
    if let Some(f) = best {
        let p = c.support_point(n);
        flat_feature(f, p, size, out);
        return;
    }
    let (p, rho) = support_and_curvature(c, n);
    tangent_feature(p, n, rho, size, out);
}

// ---------------------------------------------------------------------------------------------
// Generic AABB, ray cast, projection and mass for curves
// ---------------------------------------------------------------------------------------------

fn curve_aabb(c: &dyn ConvexCurve) -> Aabb {
    let xp = c.support_point(Vector::X).x;
    let xm = c.support_point(-Vector::X).x;
    let yp = c.support_point(Vector::Y).y;
    let ym = c.support_point(-Vector::Y).y;
    Aabb::new(Vector::new(xm, ym), Vector::new(xp, yp))
}

/// A ray hit on a curve: time of impact, normal (parry's convention) and boundary parameter.
#[derive(Copy, Clone, Debug)]
struct CurveHit {
    toi: f64,
    normal: Vector,
    phi: f64,
}

/// The root of f(φ) = P(φ)·m − c0 on the arc `[a, b]` on which it is monotone (increasing when
/// `sign = 1`, decreasing when `sign = −1`).
fn ray_arc_root(c: &dyn ConvexCurve, m: Vector, c0: f64, a: f64, b: f64, sign: f64) -> (f64, CurvePoint) {
    let f = |phi: f64| {
        let cp = c.eval(phi);
        (sign * (cp.point.dot(m) - c0), sign * cp.d_point.dot(m))
    };
    let (fa, fb) = (f(a).0, f(b).0);
    let phi = solve_increasing(a, b, fa, fb, f);
    (phi, c.eval(phi))
}

/// Exact ray cast on a convex curve (see the module documentation).
fn curve_ray(c: &dyn ConvexCurve, ray: &Ray, max_toi: Real, solid: bool) -> Option<CurveHit> {
    let (o, d) = (ray.origin, ray.dir);
    if !(o.is_finite() && d.is_finite()) || max_toi.is_nan() {
        return None;
    }
    if d.x == 0.0 && d.y == 0.0 {
        let pr = curve_project(c, o);
        return (pr.signed_dist <= 0.0 && max_toi >= 0.0).then_some(CurveHit {
            toi: 0.0,
            normal: -pr.normal,
            phi: pr.phi,
        });
    }
    let u = unit_or_x(d);
    let len = d.dot(u);
    if !(len > 0.0 && len.is_finite()) {
        return None;
    }
    let m = Vector::new(u.y, -u.x);
    let c0 = cross(o, u);
    let (lo_m, hi_m) = c.phi_range_of_normal(m);
    let (lo_n, hi_n) = c.phi_range_of_normal(-m);
    // f is at its maximum at S(m) and its minimum at S(−m); the line misses the curve unless
    // f_max ≥ 0 ≥ f_min.
    let f_max = c.eval(lo_m).point.dot(m) - c0;
    let f_min = c.eval(hi_n).point.dot(m) - c0;
    if !(f_max >= 0.0 && f_min <= 0.0) {
        return None;
    }
    // Entry: the arc from S(−m) to S(m) counter-clockwise (normals through −u), f increasing.
    let b_in = unwrap_after(hi_n, lo_m);
    let (phi_in, cp_in) = ray_arc_root(c, m, c0, hi_n, b_in, 1.0);
    // Exit: the arc from S(m) to S(−m) (normals through +u), f decreasing.
    let b_out = unwrap_after(hi_m, lo_n);
    let (phi_out, cp_out) = ray_arc_root(c, m, c0, hi_m, b_out, -1.0);
    let s_in = (cp_in.point - o).dot(u);
    let s_out = (cp_out.point - o).dot(u);
    if s_out < 0.0 || s_out.is_nan() {
        return None;
    }
    let hit = if s_in >= 0.0 {
        CurveHit {
            toi: s_in / len,
            normal: cp_in.normal,
            phi: wrap_phi(phi_in),
        }
    } else if solid {
        CurveHit {
            toi: 0.0,
            normal: -u,
            phi: wrap_phi(phi_in),
        }
    } else {
        CurveHit {
            toi: s_out / len,
            normal: -cp_out.normal,
            phi: wrap_phi(phi_out),
        }
    };
    (hit.toi <= max_toi && hit.toi.is_finite()).then_some(hit)
}

/// The closest boundary point of a curve to a point.
#[derive(Copy, Clone, Debug)]
struct CurveProjection {
    point: Vector,
    /// Outward unit normal at `point`.
    normal: Vector,
    phi: f64,
    /// Signed distance (negative inside).
    signed_dist: f64,
}

/// Closest boundary point by bracketing the sign changes of g(φ) = (x − P)·T on a grid and
/// polishing with bracketed Newton (see the module documentation).
fn curve_project(c: &dyn ConvexCurve, x: Vector) -> CurveProjection {
    let x = if x.is_finite() { x } else { Vector::ZERO };
    let bp = c.breakpoints();
    let np = bp.len().max(1);
    let sub = 64usize.div_ceil(np).max(4);
    let g_of = |cp: &CurvePoint| (x - cp.point).dot(perp(cp.normal));
    let mut best: Option<(f64, f64, CurvePoint)> = None;
    let mut consider = |phi: f64, cp: CurvePoint| {
        let d2 = (x - cp.point).length_squared();
        if d2.is_finite() && best.as_ref().is_none_or(|b| d2 < b.0) {
            best = Some((d2, phi, cp));
        }
    };
    for k in 0..np {
        let (s, e) = piece_bounds(bp, k);
        if e <= s || e.is_nan() || s.is_nan() {
            continue;
        }
        let h = (e - s) / sub as f64;
        let mut phi_a = s;
        let mut cp_a = c.eval(s);
        let mut g_a = g_of(&cp_a);
        consider(phi_a, cp_a);
        for j in 1..=sub {
            let phi_b = if j == sub { e } else { s + j as f64 * h };
            let cp_b = c.eval(phi_b);
            let g_b = g_of(&cp_b);
            consider(phi_b, cp_b);
            if g_a > 0.0 && g_b < 0.0 {
                // −g is increasing through the root.
                let root = solve_increasing(phi_a, phi_b, -g_a, -g_b, |phi| {
                    let cp = c.eval(phi);
                    let g = (x - cp.point).dot(perp(cp.normal));
                    let dg = -cp.d_point.dot(perp(cp.normal)) + (x - cp.point).dot(perp(cp.d_normal));
                    (-g, -dg)
                });
                consider(root, c.eval(root));
            }
            phi_a = phi_b;
            cp_a = cp_b;
            g_a = g_b;
        }
    }
    match best {
        Some((d2, phi, cp)) => {
            let n = unit_or_x(cp.normal);
            let side = (x - cp.point).dot(n);
            let dist = d2.sqrt();
            CurveProjection {
                point: cp.point,
                normal: n,
                phi: wrap_phi(phi),
                signed_dist: if side <= 0.0 { -dist } else { dist },
            }
        }
        None => {
            let p = c.support_point(Vector::X);
            CurveProjection {
                point: p,
                normal: Vector::X,
                phi: 0.0,
                signed_dist: 0.0,
            }
        }
    }
}

/// Gauss–Legendre nodes and weights on [−1, 1].
fn gauss_legendre<const N: usize>() -> ([f64; N], [f64; N]) {
    let mut x = [0.0; N];
    let mut w = [0.0; N];
    let n = N as f64;
    for i in 0..N {
        let mut z = (PI * (i as f64 + 0.75) / (n + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            // Legendre recurrence.
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=N {
                let kf = k as f64;
                let p2 = ((2.0 * kf - 1.0) * z * p1 - (kf - 1.0) * p0) / kf;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() <= 1e-16 {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

type Moments = [f64; 4];

/// Gauss–Legendre estimate of ∫ [½ c, ⅓ x c, ⅓ y c, ¼ |P|² c] dφ over [a, b], c = P × P′.
fn gl_moments(c: &dyn ConvexCurve, a: f64, b: f64, nodes: &([f64; 12], [f64; 12])) -> Moments {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let mut acc = [0.0; 4];
    for (z, w) in nodes.0.iter().zip(nodes.1.iter()) {
        let cp = c.eval(mid + half * z);
        let p = cp.point;
        let cr = cross(p, cp.d_point);
        acc[0] += w * 0.5 * cr;
        acc[1] += w * p.x * cr / 3.0;
        acc[2] += w * p.y * cr / 3.0;
        acc[3] += w * 0.25 * p.length_squared() * cr;
    }
    acc.map(|v| v * half)
}

fn adaptive_moments(
    c: &dyn ConvexCurve,
    a: f64,
    b: f64,
    whole: Moments,
    tol: &Moments,
    depth: u32,
    nodes: &([f64; 12], [f64; 12]),
) -> Moments {
    let m = 0.5 * (a + b);
    let left = gl_moments(c, a, m, nodes);
    let right = gl_moments(c, m, b, nodes);
    let sum = [0, 1, 2, 3].map(|k| left[k] + right[k]);
    let frac = (b - a) / (2.0 * PI);
    let ok = (0..4).all(|k| {
        let err = (sum[k] - whole[k]).abs();
        err <= tol[k] * frac || err.is_nan()
    });
    if ok || depth == 0 {
        return sum;
    }
    let l = adaptive_moments(c, a, m, left, tol, depth - 1, nodes);
    let r = adaptive_moments(c, m, b, right, tol, depth - 1, nodes);
    [0, 1, 2, 3].map(|k| l[k] + r[k])
}

/// Area, first moments and polar second moment (about the origin) of the region bounded by a
/// convex curve, by adaptive Gauss–Legendre quadrature of Green's theorem over each piece.
pub(crate) fn curve_moments(c: &dyn ConvexCurve) -> Moments {
    let nodes = gauss_legendre::<12>();
    let bp = c.breakpoints();
    let r = c.bounding_radius().abs().max(f64::MIN_POSITIVE);
    let tol = [r * r, r * r * r, r * r * r, r * r * r * r].map(|s| 1e-14 * s);
    let mut total = [0.0; 4];
    let mut add = |a: f64, b: f64| {
        let whole = gl_moments(c, a, b, &nodes);
        let m = adaptive_moments(c, a, b, whole, &tol, 30, &nodes);
        for k in 0..4 {
            total[k] += m[k];
        }
    };
    if bp.is_empty() {
        for i in 0..8 {
            let a = -PI + 2.0 * PI * i as f64 / 8.0;
            add(a, a + PI / 4.0);
        }
    } else {
        for k in 0..bp.len() {
            let (s, e) = piece_bounds(bp, k);
            if e > s {
                add(s, e);
            }
        }
    }
    total
}

/// parry mass properties from the moments (about the origin) of a uniform region.
fn mass_from_moments(density: Real, m: Moments) -> MassProperties {
    let area = m[0];
    if !m.iter().all(|v| v.is_finite()) || area <= 0.0 {
        return MassProperties::new(Vector::ZERO, 0.0, 0.0);
    }
    let com = Vector::new(m[1], m[2]) / area;
    let inertia = (m[3] - area * com.length_squared()).max(0.0);
    MassProperties::new(com, density * area, density * inertia)
}

fn curve_mass(c: &dyn ConvexCurve, density: Real) -> MassProperties {
    mass_from_moments(density, curve_moments(c))
}

fn aabb_ccd_thickness(aabb: &Aabb) -> Real {
    let h = aabb.half_extents();
    h.x.min(h.y)
}

// ---------------------------------------------------------------------------------------------
// Ellipse
// ---------------------------------------------------------------------------------------------

/// Closest point on the ellipse with semi-axes `a`, `b` to `p` (Eberly, "Distance from a Point
/// to an Ellipse, an Ellipsoid, or a Hyperellipsoid"): robust bisection on the Lagrange
/// multiplier, exact for any axis ratio, inside and outside.
pub(crate) fn ellipse_closest_point(a: f64, b: f64, p: Vector) -> Vector {
    let swap = b > a;
    let (e0, e1) = if swap { (b, a) } else { (a, b) };
    let (q0, q1) = if swap { (p.y, p.x) } else { (p.x, p.y) };
    let (y0, y1) = (q0.abs(), q1.abs());
    // A coordinate below 1e-290 of its semi-axis is 0 to rounding; kept, the bisection below
    // divides one underflowed number by another (an infinite closest point).
    let y0 = if y0 < 1e-290 * e0 { 0.0 } else { y0 };
    let y1 = if y1 < 1e-290 * e1 { 0.0 } else { y1 };
    let (x0, x1);
    if y1 > 0.0 {
        if y0 > 0.0 {
            let z0 = y0 / e0;
            let z1 = y1 / e1;
            let g = z0.hypot(z1) - 1.0;
            if g != 0.0 {
                let r0 = (e0 / e1) * (e0 / e1);
                // r0 − 1 without cancellation (near-circles).
                let rm1 = ((e0 - e1) / e1) * ((e0 + e1) / e1);
                let u = ellipse_root(r0, rm1, z0, z1, g);
                x0 = r0 * y0 / (u + rm1);
                x1 = y1 / u;
            } else {
                x0 = y0;
                x1 = y1;
            }
        } else {
            x0 = 0.0;
            x1 = e1;
        }
    } else {
        let numer0 = e0 * y0;
        let denom0 = (e0 - e1) * (e0 + e1);
        if numer0 < denom0 {
            let xde0 = numer0 / denom0;
            x0 = e0 * xde0;
            x1 = e1 * ((1.0 - xde0) * (1.0 + xde0)).max(0.0).sqrt();
        } else {
            x0 = e0;
            x1 = 0.0;
        }
    }
    let (x0, x1) = (x0.copysign(q0), x1.copysign(q1));
    if swap {
        Vector::new(x1, x0)
    } else {
        Vector::new(x0, x1)
    }
}

/// Eberly's root of G(s) = (r0 z0/(s + r0))² + (z1/(s + 1))² − 1, bisected in u = s + 1 (so
/// that s + 1 = u and s + r0 = u + (r0 − 1) keep full relative precision when the closest
/// point is near the end of the minor axis).
fn ellipse_root(r0: f64, rm1: f64, z0: f64, z1: f64, g: f64) -> f64 {
    let n0 = r0 * z0;
    let mut u0 = z1;
    let mut u1 = if g < 0.0 { 1.0 } else { n0.hypot(z1) };
    let mut u = u1;
    for _ in 0..1100 {
        u = 0.5 * (u0 + u1);
        if u == u0 || u == u1 {
            break;
        }
        let ratio0 = n0 / (u + rm1);
        let ratio1 = z1 / u;
        let gg = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
        if gg > 0.0 {
            u0 = u;
        } else if gg < 0.0 {
            u1 = u;
        } else {
            break;
        }
    }
    u
}

impl Ellipse {
    /// Outward unit normal at a boundary point `p` (the normalised gradient of x²/a² + y²/b²).
    fn normal_at_point(&self, p: Vector) -> Vector {
        let (a, b) = (self.half_x(), self.half_y());
        unit_or_x(Vector::new(p.x / (a * a), p.y / (b * b)))
    }

    fn contains(&self, p: Vector) -> bool {
        let (u, v) = (p.x / self.half_x(), p.y / self.half_y());
        u * u + v * v <= 1.0
    }
}

impl SupportMap for Ellipse {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        self.point_with_normal(unit_or_x(dir))
    }
}

impl PolygonalFeatureMap for Ellipse {
    fn local_support_feature(&self, dir: Vector, out_feature: &mut PolygonalFeature) {
        let n = unit_or_x(dir);
        let (a2, b2) = (self.half_x() * self.half_x(), self.half_y() * self.half_y());
        let h = (a2 * n.x * n.x + b2 * n.y * n.y).sqrt();
        let p = Vector::new(a2 * n.x, b2 * n.y) / h;
        let rho = a2 * b2 / (h * h * h);
        tangent_feature(p, n, rho, self.half_x().max(self.half_y()), out_feature);
    }
}

impl RayCast for Ellipse {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        let (a, b) = (self.half_x(), self.half_y());
        let (o, d) = (ray.origin, ray.dir);
        if !(o.is_finite() && d.is_finite()) || max_time_of_impact.is_nan() {
            return None;
        }
        let o2 = Vector::new(o.x / a, o.y / b);
        let d2 = Vector::new(d.x / a, d.y / b);
        let cc = (o2.length() - 1.0) * (o2.length() + 1.0);
        let inside = cc <= 0.0;
        if d.x == 0.0 && d.y == 0.0 {
            if !inside || max_time_of_impact < 0.0 {
                return None;
            }
            let p = ellipse_closest_point(a, b, o);
            return Some(RayIntersection::new(0.0, -self.normal_at_point(p), FeatureId::Face(0)));
        }
        // Scale the quadratic to avoid under/overflow for tiny or huge directions.
        let scale = d2.x.abs().max(d2.y.abs());
        let d2s = d2 / scale;
        let aa = d2s.length_squared();
        let bb = o2.dot(d2s);
        if !inside && bb >= 0.0 {
            return None;
        }
        let disc = bb * bb - aa * cc;
        if disc < 0.0 {
            return None;
        }
        let sq = disc.sqrt();
        let q = -(bb + sq.copysign(bb));
        let (r1, r2) = if q == 0.0 { (0.0, 0.0) } else { (q / aa, cc / q) };
        let (t_in, t_out) = (r1.min(r2) / scale, r1.max(r2) / scale);
        let hit = if !inside {
            let p = o + d * t_in;
            (t_in, self.normal_at_point(p))
        } else if solid {
            (0.0, -unit_or_x(d))
        } else {
            let p = o + d * t_out;
            (t_out, -self.normal_at_point(p))
        };
        (hit.0 <= max_time_of_impact && hit.0.is_finite())
            .then(|| RayIntersection::new(hit.0.max(0.0), hit.1, FeatureId::Face(0)))
    }
}

impl PointQuery for Ellipse {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        if !pt.is_finite() {
            return PointProjection::new(false, Vector::new(self.half_x(), 0.0));
        }
        // A point beyond 1e50 sizes (where Eberly's scaled coordinates overflow): its closest
        // point is the one whose normal points at it, to within 1e-50 of the size.
        if pt.x.abs().max(pt.y.abs()) > 1e50 * self.half_x().max(self.half_y()) {
            return PointProjection::new(false, self.point_with_normal(unit_or_x(pt)));
        }
        let inside = self.contains(pt);
        if inside && solid {
            return PointProjection::new(true, pt);
        }
        PointProjection::new(inside, ellipse_closest_point(self.half_x(), self.half_y(), pt))
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        (self.project_local_point(pt, false), FeatureId::Face(0))
    }

    fn contains_local_point(&self, pt: Vector) -> bool {
        self.contains(pt)
    }
}

impl Shape for Ellipse {
    fn compute_local_aabb(&self) -> Aabb {
        let h = Vector::new(self.half_x(), self.half_y());
        Aabb::new(-h, h)
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::new(Vector::ZERO, self.bounding_radius())
    }

    fn clone_dyn(&self) -> Box<dyn Shape> {
        Box::new(*self)
    }

    fn scale_dyn(&self, scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        let e = Ellipse::try_new(self.half_x() * scale.x.abs(), self.half_y() * scale.y.abs()).ok()?;
        Some(Box::new(e))
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        let (a, b) = (self.half_x(), self.half_y());
        let mass = density * PI * a * b;
        MassProperties::new(Vector::ZERO, mass, mass * (a * a + b * b) / 4.0)
    }

    fn shape_type(&self) -> ShapeType {
        ShapeType::Custom
    }

    fn as_typed_shape(&self) -> TypedShape<'_> {
        TypedShape::Custom(self)
    }

    fn ccd_thickness(&self) -> Real {
        self.half_x().min(self.half_y())
    }

    fn ccd_angular_thickness(&self) -> Real {
        if self.half_x() == self.half_y() {
            PI
        } else {
            FRAC_PI_2
        }
    }

    fn is_convex(&self) -> bool {
        true
    }

    fn as_support_map(&self) -> Option<&dyn SupportMap> {
        Some(self as &dyn SupportMap)
    }

    fn as_polygonal_feature_map(&self) -> Option<(&dyn PolygonalFeatureMap, Real)> {
        Some((self as &dyn PolygonalFeatureMap, 0.0))
    }
}

// ---------------------------------------------------------------------------------------------
// RoundedPolygon
// ---------------------------------------------------------------------------------------------

/// Adds the moments (about the origin) of the convex polygon `v` (counter-clockwise) to `acc`.
fn add_polygon_moments(v: &[Vector], acc: &mut Moments) {
    let n = v.len();
    for i in 0..n {
        let (p, q) = (v[i], v[(i + 1) % n]);
        let c = cross(p, q);
        acc[0] += 0.5 * c;
        acc[1] += c * (p.x + q.x) / 6.0;
        acc[2] += c * (p.y + q.y) / 6.0;
        acc[3] += c * (p.dot(p) + p.dot(q) + q.dot(q)) / 12.0;
    }
}

/// Exact moments (about the origin) of a convex polygon dilated by `r`: core polygon, a
/// rectangle on each edge and a circular sector at each corner.
pub(crate) fn rounded_polygon_moments(vertices: &[Vector], normals: &[Vector], r: f64) -> Moments {
    let n = vertices.len();
    if n == 0 {
        return [0.0; 4];
    }
    // Work about the vertex centroid to limit cancellation, shift at the end.
    let c0 = vertices.iter().copied().sum::<Vector>() / n as f64;
    let mut acc = [0.0; 4];
    let local: Vec<Vector> = vertices.iter().map(|v| *v - c0).collect();
    add_polygon_moments(&local, &mut acc);
    if r > 0.0 {
        for i in 0..n {
            let (p, q, e) = (local[i], local[(i + 1) % n], normals[i]);
            add_polygon_moments(&[p, p + e * r, q + e * r, q], &mut acc);
            // Sector at vertex i from the previous edge's normal to this edge's normal.
            let u0 = normals[(i + n - 1) % n];
            let alpha = ccw_angle(u0, e);
            let area = 0.5 * alpha * r * r;
            let mc = Vector::new(e.y - u0.y, u0.x - e.x) * (r * r * r / 3.0);
            let jc = 0.25 * alpha * r * r * r * r;
            acc[0] += area;
            acc[1] += mc.x + area * p.x;
            acc[2] += mc.y + area * p.y;
            acc[3] += jc + 2.0 * p.dot(mc) + area * p.length_squared();
        }
    }
    // Shift from c0 to the origin: J_O = J_c0 + 2 c0·M_c0 + A |c0|².
    let (area, m) = (acc[0], Vector::new(acc[1], acc[2]));
    [
        area,
        m.x + area * c0.x,
        m.y + area * c0.y,
        acc[3] + 2.0 * c0.dot(m) + area * c0.length_squared(),
    ]
}

impl RoundedPolygon {
    /// Exact closest boundary point, its outward normal and feature (vertex i: corner arc i;
    /// face i: edge i), and whether `x` is inside.
    fn project_exact(&self, x: Vector) -> (Vector, Vector, FeatureId, bool) {
        let v = self.vertices();
        let e = self.edge_normals();
        let r = self.corner_radius();
        let n = v.len();
        // Largest signed distance to an edge line.
        let (mut imax, mut smax) = (0usize, f64::NEG_INFINITY);
        for i in 0..n {
            let s = (x - v[i]).dot(e[i]);
            if s > smax {
                smax = s;
                imax = i;
            }
        }
        if smax <= 0.0 {
            // Inside the core (or on its boundary): the nearest edge line.
            let p = x + e[imax] * (r - smax);
            return (p, e[imax], FeatureId::Face(imax as u32), true);
        }
        // Outside the core: the closest point of the core's boundary.
        let (mut best_d2, mut best_q, mut best_f) = (f64::INFINITY, v[0], FeatureId::Vertex(0));
        for i in 0..n {
            let (a, b) = (v[i], v[(i + 1) % n]);
            let ab = b - a;
            let t = ((x - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
            let (q, f) = if t <= 0.0 {
                (a, FeatureId::Vertex(i as u32))
            } else if t >= 1.0 {
                (b, FeatureId::Vertex(((i + 1) % n) as u32))
            } else {
                (a + ab * t, FeatureId::Face(i as u32))
            };
            let d2 = (x - q).length_squared();
            if d2 < best_d2 {
                best_d2 = d2;
                best_q = q;
                best_f = f;
            }
        }
        let dist = best_d2.sqrt();
        let nrm = match best_f {
            FeatureId::Face(i) => e[i as usize],
            _ => {
                if dist > 0.0 {
                    (x - best_q) / dist
                } else {
                    e[imax]
                }
            }
        };
        (best_q + nrm * r, nrm, best_f, dist <= r)
    }

    fn feature_of_phi(&self, phi: f64) -> FeatureId {
        let k = piece_index(self.breakpoints(), phi);
        if k.is_multiple_of(2) {
            FeatureId::Vertex((k / 2) as u32)
        } else {
            FeatureId::Face((k / 2) as u32)
        }
    }
}

impl SupportMap for RoundedPolygon {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        ConvexCurve::support_point(self, unit_or_x(dir))
    }
}

impl PolygonalFeatureMap for RoundedPolygon {
    fn local_support_feature(&self, dir: Vector, out_feature: &mut PolygonalFeature) {
        let n_hat = unit_or_x(dir);
        let v = self.vertices();
        let e = self.edge_normals();
        let n = v.len();
        let mut best = 0usize;
        let mut best_dot = f64::NEG_INFINITY;
        for (i, ei) in e.iter().enumerate() {
            let d = ei.dot(n_hat);
            if d > best_dot {
                best_dot = d;
                best = i;
            }
        }
        let shift = n_hat * self.corner_radius();
        let j = (best + 1) % n.max(1);
        *out_feature = PolygonalFeature {
            vertices: [v[best] + shift, v[j] + shift],
            vids: [
                PackedFeatureId::vertex(2 * best as u32),
                PackedFeatureId::vertex(2 * j as u32),
            ],
            fid: PackedFeatureId::face(2 * best as u32 + 1),
            num_vertices: 2,
        };
    }
}

impl RayCast for RoundedPolygon {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        if ray.dir.x == 0.0 && ray.dir.y == 0.0 {
            if !ray.origin.is_finite() || max_time_of_impact < 0.0 || max_time_of_impact.is_nan() {
                return None;
            }
            let (_, nrm, f, inside) = self.project_exact(ray.origin);
            return inside.then(|| RayIntersection::new(0.0, -nrm, f));
        }
        let hit = curve_ray(self, ray, max_time_of_impact, solid)?;
        Some(RayIntersection::new(hit.toi, hit.normal, self.feature_of_phi(hit.phi)))
    }
}

impl PointQuery for RoundedPolygon {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        if !pt.is_finite() {
            return PointProjection::new(false, ConvexCurve::support_point(self, Vector::X));
        }
        let (p, _, _, inside) = self.project_exact(pt);
        if inside && solid {
            PointProjection::new(true, pt)
        } else {
            PointProjection::new(inside, p)
        }
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        if !pt.is_finite() {
            let p = ConvexCurve::support_point(self, Vector::X);
            return (PointProjection::new(false, p), FeatureId::Unknown);
        }
        let (p, _, f, inside) = self.project_exact(pt);
        (PointProjection::new(inside, p), f)
    }
}

impl Shape for RoundedPolygon {
    fn compute_local_aabb(&self) -> Aabb {
        let v = self.vertices();
        let (mut lo, mut hi) = (v[0], v[0]);
        for p in v {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        let r = Vector::splat(self.corner_radius());
        Aabb::new(lo - r, hi + r)
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::new(Vector::ZERO, self.bounding_radius())
    }

    fn clone_dyn(&self) -> Box<dyn Shape> {
        Box::new(self.clone())
    }

    fn scale_dyn(&self, scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        if !scale.is_finite() || scale.x == 0.0 || scale.y == 0.0 {
            return None;
        }
        let uniform = scale.x.abs() == scale.y.abs();
        let r = self.corner_radius();
        if !uniform && r != 0.0 {
            return None;
        }
        let mut v: Vec<Vector> = self.vertices().iter().map(|p| *p * scale).collect();
        if scale.x * scale.y < 0.0 {
            // A mirror reverses the orientation.
            v.reverse();
        }
        let r = if uniform { r * scale.x.abs() } else { 0.0 };
        let p = RoundedPolygon::try_new(&v, r).ok()?;
        Some(Box::new(p))
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        let m = rounded_polygon_moments(self.vertices(), self.edge_normals(), self.corner_radius());
        mass_from_moments(density, m)
    }

    fn shape_type(&self) -> ShapeType {
        ShapeType::Custom
    }

    fn as_typed_shape(&self) -> TypedShape<'_> {
        TypedShape::Custom(self)
    }

    fn ccd_thickness(&self) -> Real {
        // parry's RoundConvexPolygon: the core polygon's smallest AABB half-extent + radius.
        let v = self.vertices();
        let (mut lo, mut hi) = (v[0], v[0]);
        for p in v {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        aabb_ccd_thickness(&Aabb::new(lo, hi)) + self.corner_radius()
    }

    fn ccd_angular_thickness(&self) -> Real {
        FRAC_PI_4
    }

    fn is_convex(&self) -> bool {
        true
    }

    fn as_support_map(&self) -> Option<&dyn SupportMap> {
        Some(self as &dyn SupportMap)
    }

    fn as_polygonal_feature_map(&self) -> Option<(&dyn PolygonalFeatureMap, Real)> {
        Some((self as &dyn PolygonalFeatureMap, 0.0))
    }
}

// ---------------------------------------------------------------------------------------------
// CapsuleEllipse
// ---------------------------------------------------------------------------------------------

/// Exact moments (about the origin) of the capsule-ellipse: half ellipse (x ≤ 0, semi-axes r3
/// and r1 + r2), rectangle [0, r1] × [−r2, r2] and two quarter discs of radius r1 centred at
/// (0, ±r2).
pub(crate) fn capsule_ellipse_moments(r1: f64, r2: f64, r3: f64) -> Moments {
    let bb = r1 + r2;
    let area = 0.5 * PI * r3 * bb + 2.0 * r1 * r2 + 0.5 * PI * r1 * r1;
    let mx = -2.0 / 3.0 * bb * r3 * r3 + r1 * r1 * r2 + 2.0 / 3.0 * r1 * r1 * r1;
    let j = PI * r3 * bb * (r3 * r3 + bb * bb) / 8.0
        + 2.0 / 3.0 * (r1 * r1 * r1 * r2 + r1 * r2 * r2 * r2)
        + PI * r1.powi(4) / 4.0
        + 4.0 / 3.0 * r2 * r1 * r1 * r1
        + PI * r1 * r1 * r2 * r2 / 2.0;
    [area, mx, 0.0, j]
}

impl CapsuleEllipse {
    fn flat_piece(&self) -> FlatPiece {
        let (r1, r2, _) = self.params();
        FlatPiece {
            normal: Vector::X,
            start: Vector::new(r1, -r2),
            end: Vector::new(r1, r2),
            // Pieces: 0 = lower arc, 1 = segment, 2 = upper arc, 3 = half ellipse (wrapping).
            index: 1,
        }
    }
}

impl SupportMap for CapsuleEllipse {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        ConvexCurve::support_point(self, unit_or_x(dir))
    }
}

impl PolygonalFeatureMap for CapsuleEllipse {
    fn local_support_feature(&self, dir: Vector, out_feature: &mut PolygonalFeature) {
        curve_feature(self, &[self.flat_piece()], dir, out_feature);
    }
}

impl RayCast for CapsuleEllipse {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        let hit = curve_ray(self, ray, max_time_of_impact, solid)?;
        let f = FeatureId::Face(piece_index(self.breakpoints(), hit.phi) as u32);
        Some(RayIntersection::new(hit.toi, hit.normal, f))
    }
}

impl PointQuery for CapsuleEllipse {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        let pr = curve_project(self, pt);
        let inside = pr.signed_dist <= 0.0 && pt.is_finite();
        if inside && solid {
            PointProjection::new(true, pt)
        } else {
            PointProjection::new(inside, pr.point)
        }
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        let pr = curve_project(self, pt);
        let inside = pr.signed_dist <= 0.0 && pt.is_finite();
        let f = FeatureId::Face(piece_index(self.breakpoints(), pr.phi) as u32);
        (PointProjection::new(inside, pr.point), f)
    }
}

impl Shape for CapsuleEllipse {
    fn compute_local_aabb(&self) -> Aabb {
        curve_aabb(self)
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::new(Vector::ZERO, self.bounding_radius())
    }

    fn clone_dyn(&self) -> Box<dyn Shape> {
        Box::new(self.clone())
    }

    fn scale_dyn(&self, scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        // Symmetric about the x axis only: a mirror in y is fine, one in x is not.
        if !(scale.x > 0.0 && scale.x.is_finite() && scale.y.abs() == scale.x) {
            return None;
        }
        let (r1, r2, r3) = self.params();
        let s = scale.x;
        Some(Box::new(CapsuleEllipse::try_new(r1 * s, r2 * s, r3 * s).ok()?))
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        let (r1, r2, r3) = self.params();
        mass_from_moments(density, capsule_ellipse_moments(r1, r2, r3))
    }

    fn shape_type(&self) -> ShapeType {
        ShapeType::Custom
    }

    fn as_typed_shape(&self) -> TypedShape<'_> {
        TypedShape::Custom(self)
    }

    fn ccd_thickness(&self) -> Real {
        aabb_ccd_thickness(&self.compute_local_aabb())
    }

    fn ccd_angular_thickness(&self) -> Real {
        FRAC_PI_2
    }

    fn is_convex(&self) -> bool {
        true
    }

    fn as_support_map(&self) -> Option<&dyn SupportMap> {
        Some(self as &dyn SupportMap)
    }

    fn as_polygonal_feature_map(&self) -> Option<(&dyn PolygonalFeatureMap, Real)> {
        Some((self as &dyn PolygonalFeatureMap, 0.0))
    }
}

// ---------------------------------------------------------------------------------------------
// CustomCurve
// ---------------------------------------------------------------------------------------------

impl SupportMap for CustomCurve {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        self.curve().support_point(unit_or_x(dir))
    }
}

impl PolygonalFeatureMap for CustomCurve {
    fn local_support_feature(&self, dir: Vector, out_feature: &mut PolygonalFeature) {
        curve_feature(self.curve(), self.flats(), dir, out_feature);
    }
}

impl RayCast for CustomCurve {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &Ray,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        let c = self.curve();
        let hit = curve_ray(c, ray, max_time_of_impact, solid)?;
        let f = FeatureId::Face(piece_index(c.breakpoints(), hit.phi) as u32);
        Some(RayIntersection::new(hit.toi, hit.normal, f))
    }
}

impl PointQuery for CustomCurve {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        let pr = curve_project(self.curve(), pt);
        let inside = pr.signed_dist <= 0.0 && pt.is_finite();
        if inside && solid {
            PointProjection::new(true, pt)
        } else {
            PointProjection::new(inside, pr.point)
        }
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        let c = self.curve();
        let pr = curve_project(c, pt);
        let inside = pr.signed_dist <= 0.0 && pt.is_finite();
        let f = FeatureId::Face(piece_index(c.breakpoints(), pr.phi) as u32);
        (PointProjection::new(inside, pr.point), f)
    }
}

impl Shape for CustomCurve {
    fn compute_local_aabb(&self) -> Aabb {
        curve_aabb(self.curve())
    }

    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::new(Vector::ZERO, self.curve().bounding_radius())
    }

    fn clone_dyn(&self) -> Box<dyn Shape> {
        Box::new(self.clone())
    }

    fn scale_dyn(&self, _scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        None
    }

    fn mass_properties(&self, density: Real) -> MassProperties {
        curve_mass(self.curve(), density)
    }

    fn shape_type(&self) -> ShapeType {
        ShapeType::Custom
    }

    fn as_typed_shape(&self) -> TypedShape<'_> {
        TypedShape::Custom(self)
    }

    fn ccd_thickness(&self) -> Real {
        aabb_ccd_thickness(&self.compute_local_aabb())
    }

    fn ccd_angular_thickness(&self) -> Real {
        FRAC_PI_4
    }

    fn is_convex(&self) -> bool {
        true
    }

    fn as_support_map(&self) -> Option<&dyn SupportMap> {
        Some(self as &dyn SupportMap)
    }

    fn as_polygonal_feature_map(&self) -> Option<(&dyn PolygonalFeatureMap, Real)> {
        Some((self as &dyn PolygonalFeatureMap, 0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::unit;

    fn rel_close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * a.abs().max(b.abs()).max(1e-300)
    }

    #[test]
    fn gauss_legendre_integrates_polynomials_of_degree_23_exactly() {
        let (x, w) = gauss_legendre::<12>();
        assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14);
        for deg in 0..24 {
            let q: f64 = x.iter().zip(w.iter()).map(|(x, w)| w * x.powi(deg)).sum();
            let exact = if deg % 2 == 1 { 0.0 } else { 2.0 / (deg as f64 + 1.0) };
            assert!((q - exact).abs() < 1e-14, "degree {deg}: {q} vs {exact}");
        }
    }

    #[test]
    fn green_quadrature_of_ellipses_matches_closed_form_up_to_1_to_100() {
        for (a, b) in [(1.0, 1.0), (2.0, 0.5), (0.3, 1.7), (1.0, 0.01), (0.02, 2.0)] {
            let m = curve_moments(&Ellipse::new(a, b));
            assert!(rel_close(m[0], PI * a * b, 1e-13), "area {a} {b}: {}", m[0]);
            assert!(m[1].abs() < 1e-13 * a * a * b && m[2].abs() < 1e-13 * a * b * b.max(a));
            let j = PI * a * b * (a * a + b * b) / 4.0;
            assert!(rel_close(m[3], j, 1e-13), "J {a} {b}: {} vs {j}", m[3]);
        }
    }

    #[test]
    fn rounded_polygon_moments_match_green_quadrature() {
        let irregular = [
            Vector::new(0.3, -0.2),
            Vector::new(2.1, 0.1),
            Vector::new(2.4, 1.3),
            Vector::new(1.0, 2.2),
            Vector::new(0.1, 1.0),
        ];
        let mut polys = vec![
            RoundedPolygon::new(&irregular, 0.0),
            RoundedPolygon::new(&irregular, 0.37),
        ];
        for sides in 3..9 {
            for r in [0.0, 0.05, 1.5] {
                polys.push(RoundedPolygon::regular(sides, 1.3, r));
            }
        }
        for p in polys {
            let exact = rounded_polygon_moments(p.vertices(), p.edge_normals(), p.corner_radius());
            let quad = curve_moments(&p);
            let s = p.bounding_radius();
            let scale = [s * s, s * s * s, s * s * s, s.powi(4)];
            for k in 0..4 {
                assert!(
                    (exact[k] - quad[k]).abs() <= 1e-13 * scale[k],
                    "{p:?} moment {k}: {} vs {}",
                    exact[k],
                    quad[k]
                );
            }
        }
    }

    #[test]
    fn capsule_ellipse_moments_match_green_quadrature() {
        for (r1, r2, r3) in [(0.5, 1.0, 0.8), (1.0, 0.1, 3.0), (0.2, 2.0, 0.05), (1.0, 1.0, 1.0)] {
            let c = CapsuleEllipse::new(r1, r2, r3);
            let exact = capsule_ellipse_moments(r1, r2, r3);
            let quad = curve_moments(&c);
            let s = c.bounding_radius();
            let scale = [s * s, s * s * s, s * s * s, s.powi(4)];
            for k in 0..4 {
                assert!(
                    (exact[k] - quad[k]).abs() <= 1e-13 * scale[k],
                    "({r1}, {r2}, {r3}) moment {k}: {} vs {}",
                    exact[k],
                    quad[k]
                );
            }
        }
    }

    #[test]
    fn ellipse_closest_point_is_a_foot_of_perpendicular_for_extreme_ratios() {
        for (a, b) in [(1.0, 1e-3), (1e-3, 1.0), (2.0, 2.0), (3.0, 0.5)] {
            let e = Ellipse::new(a, b);
            for k in 0..200 {
                let ang = 0.031 * k as f64;
                for rad in [0.0, 1e-4, 0.3, 0.999, 1.0, 1.001, 2.0, 50.0] {
                    let x =
                        Vector::new(a * rad * ang.cos(), b * rad * ang.sin()) + Vector::new(0.0, 1e-3 * (k % 3) as f64);
                    let p = ellipse_closest_point(a, b, x);
                    // On the ellipse.
                    let g = (p.x / a).powi(2) + (p.y / b).powi(2) - 1.0;
                    assert!(g.abs() < 1e-12, "off the ellipse: {g} a={a} b={b} x={x} p={p}");
                    // x − p along the normal at p.
                    let n = e.normal_at_point(p);
                    let d = x - p;
                    assert!(cross(d, n).abs() <= 1e-12 * a.max(b), "not a foot: {x} -> {p}");
                }
            }
        }
    }

    #[test]
    fn solve_increasing_converges_across_a_kink_and_on_flat_ends() {
        // f = x for x < 0.3, 100 (x − 0.3) + 0.3 after: a derivative jump; root at 0.
        let f = |x: f64| {
            if x < 0.3 {
                (x, 1.0)
            } else {
                (100.0 * (x - 0.3) + 0.3, 100.0)
            }
        };
        let r = solve_increasing(-1.0, 2.0, f(-1.0).0, f(2.0).0, f);
        assert!(r.abs() < 1e-15);
        let g = |x: f64| ((x - 1.0).powi(3), 3.0 * (x - 1.0).powi(2));
        let r = solve_increasing(0.0, 3.0, g(0.0).0, g(3.0).0, g);
        assert!((r - 1.0).abs() < 1e-5);
        // Degenerate brackets return an end.
        assert_eq!(solve_increasing(0.0, 1.0, 0.0, 1.0, g), 0.0);
        assert_eq!(solve_increasing(0.0, 1.0, 1.0, 2.0, g), 0.0);
    }

    #[test]
    fn unwrap_after_and_piece_index_handle_the_wrap() {
        assert!((unwrap_after(3.0, -3.0) - (2.0 * PI - 3.0)).abs() < 1e-15);
        assert_eq!(unwrap_after(-1.0, 0.5), 0.5);
        assert!((unwrap_after(0.0, 100.0) - (100.0 - 15.0 * 2.0 * PI)).abs() < 1e-12);
        assert_eq!(unwrap_after(0.0, f64::NAN), 0.0);
        let bp = [-1.0, 0.0, 1.0];
        assert_eq!(piece_index(&bp, -0.5), 0);
        assert_eq!(piece_index(&bp, 0.0), 1);
        assert_eq!(piece_index(&bp, 2.0), 2);
        assert_eq!(piece_index(&bp, -2.0), 2);
        assert_eq!(piece_index(&[], 1.0), 0);
    }

    #[test]
    fn unit_or_x_survives_tiny_huge_and_bad_vectors() {
        assert_eq!(unit_or_x(Vector::ZERO), Vector::X);
        assert_eq!(unit_or_x(Vector::new(f64::NAN, 1.0)), Vector::X);
        assert_eq!(unit_or_x(Vector::new(f64::INFINITY, 1.0)), Vector::X);
        let t = unit_or_x(Vector::new(3e-320, 4e-320));
        assert!((t - Vector::new(0.6, 0.8)).length() < 1e-3);
        let h = unit_or_x(Vector::new(3e307, 4e307));
        assert!((h - Vector::new(0.6, 0.8)).length() < 1e-15);
        assert!((unit_or_x(unit(0.3) * 7.0) - unit(0.3)).length() < 1e-15);
    }
}
