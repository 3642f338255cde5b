//! Feet of the normals from a point to an ellipse.
//!
//! A *foot* of p on the ellipse E: x²/a² + y²/b² = 1 is a point e of E whose normal line passes
//! through p. The stationary points of any function of the form n ↦ q·n + h_E(n) (h_E the
//! support function of E, q a vector) over unit directions n are the normals of E at the feet of
//! p = −q, and its value there is (e − p)·m, m the outward normal at e. The contact query of
//! this folder minimises such functions over arcs of directions, so it needs every foot that can
//! be a local minimum.
//!
//! With a ≥ b, p = (x₀, y₀) reflected into the first quadrant and Eberly's multiplier t
//! (e = (a²x₀/(t + a²), b²y₀/(t + b²))), the feet are the roots of
//!
//!   Φ(t) = (a x₀/(t + a²))² + (b y₀/(t + b²))² − 1:
//!
//! * one root on (−b², ∞), where Φ is convex and decreasing: the **nearest** point (t > 0
//!   outside, t < 0 inside), in the quadrant of p;
//! * none or two roots on (−a², −b²), where Φ is convex with its minimum at a closed form:
//!   with u = t + a², w = −(t + b²), u + w = a² − b², Φ′ = 0 at (w/u)³ = (b y₀/(a x₀))². The
//!   stationary points of the support function alternate between minima and maxima around the
//!   circle, in the counter-clockwise order nearest, farthest, right root (w small, near the
//!   vertex (0, −b)), left root (near (a, 0)): the right root is a minimum, the left one a
//!   maximum, and only the right one is computed;
//! * one root below −a²: the farthest point. There the circle about p through e contains E, so
//!   E's radius of curvature is at most |e − p|: the farthest foot is never a strict local
//!   minimum of q·n + h_E(n), and is not computed.
//!
//! Every root is found by Newton's method started on the side of the root where the convex,
//! monotone Φ is positive: the iterates then increase monotonically to the root (the tangent of a
//! convex function lies below it), so no bracket can be lost and the loop stops when an iterate
//! no longer increases. The two middle roots are solved in the variable that vanishes at their
//! pole (u for the left one, w for the right one), so a foot next to an axis keeps its relative
//! precision. A point on an axis of E (x₀ = 0 or y₀ = 0) has symmetric pairs of feet that the
//! formulas above reach only as limits; they are written in closed form.

use crate::numerics::math::Vector;

/// Newton steps at most per root (the iterates increase monotonically; a handful suffice, the
/// cap only bounds pathological inputs).
const MAX_NEWTON: usize = 100;

/// A foot of a normal: the point e of the ellipse (in the ellipse's axes) and its outward unit
/// normal m.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct Foot {
    pub point: Vector,
    pub normal: Vector,
}

/// Up to six feet (the nearest, or its mirror pair, and the middle ones with their mirrors when
/// the point is on an axis).
#[derive(Copy, Clone, Debug)]
pub(crate) struct Feet {
    len: usize,
    feet: [Foot; 6],
}

impl Feet {
    fn new() -> Self {
        let f = Foot {
            point: Vector::ZERO,
            normal: Vector::X,
        };
        Feet { len: 0, feet: [f; 6] }
    }

    /// The feet found.
    pub(crate) fn as_slice(&self) -> &[Foot] {
        &self.feet[..self.len]
    }
}

/// The ellipse's semi-axes and the point, normalised: a ≥ b (axes swapped when needed), the
/// point reflected into the first quadrant; `push` undoes both for a foot.
struct Frame {
    a: f64,
    b: f64,
    x0: f64,
    y0: f64,
    swap: bool,
    sx: f64,
    sy: f64,
}

impl Frame {
    fn new(a: f64, b: f64, p: Vector) -> Self {
        let swap = b > a;
        let (a, b, px, py) = if swap { (b, a, p.y, p.x) } else { (a, b, p.x, p.y) };
        Frame {
            a,
            b,
            x0: px.abs(),
            y0: py.abs(),
            swap,
            sx: if px < 0.0 { -1.0 } else { 1.0 },
            sy: if py < 0.0 { -1.0 } else { 1.0 },
        }
    }

    /// Adds the foot at (x, y) of the normalised frame (and, when `mirror_x` / `mirror_y`, its
    /// mirror images across the axes the point lies on).
    fn push(&self, out: &mut Feet, x: f64, y: f64, mirror_x: bool, mirror_y: bool) {
        let xs: &[f64] = if mirror_x && x != 0.0 { &[1.0, -1.0] } else { &[1.0] };
        let ys: &[f64] = if mirror_y && y != 0.0 { &[1.0, -1.0] } else { &[1.0] };
        for &fx in xs {
            for &fy in ys {
                if out.len == out.feet.len() {
                    return;
                }
                let (ex, ey) = (self.sx * fx * x, self.sy * fy * y);
                // Normal ∝ (x/a², y/b²), scaled by a²b² to stay away from under/overflow.
                let (nx, ny) = (ex * self.b * self.b, ey * self.a * self.a);
                let (e, n) = if self.swap {
                    (Vector::new(ey, ex), Vector::new(ny, nx))
                } else {
                    (Vector::new(ex, ey), Vector::new(nx, ny))
                };
                let len = n.length();
                let normal = if len > 0.0 && len.is_finite() {
                    n * (1.0 / len)
                } else {
                    Vector::X
                };
                out.feet[out.len] = Foot { point: e, normal };
                out.len += 1;
            }
        }
    }
}

/// Newton's method on a convex function that decreases through its root, from `x` where it is
/// ≥ 0, never beyond `hi`: `f` returns (value, derivative).
fn newton_increasing(mut x: f64, hi: f64, f: impl Fn(f64) -> (f64, f64)) -> f64 {
    for _ in 0..MAX_NEWTON {
        let (v, d) = f(x);
        if v <= 0.0 || d >= 0.0 || !v.is_finite() || !d.is_finite() {
            break;
        }
        let next = (x - v / d).min(hi);
        if next <= x {
            break;
        }
        x = next;
    }
    x
}

/// The nearest point of the ellipse with semi-axes `a` (along x), `b` (along y) to `p` — with
/// its mirror image when p is on an axis and the two are equally near — as feet.
pub(crate) fn nearest_feet(a: f64, b: f64, p: Vector) -> Feet {
    let f = Frame::new(a, b, p);
    let mut out = Feet::new();
    let (a, b, x0, y0) = (f.a, f.b, f.x0, f.y0);
    let d = (a - b) * (a + b);
    if x0 > 0.0 && y0 > 0.0 {
        // Eberly's multiplier in units of b², shifted: v = t/b² + 1, root of
        // G(v) = (r₀z₀/(v + r₀ − 1))² + (z₁/v)² − 1 on (0, ∞), r₀ = a²/b² (v itself, not
        // t/b², is solved for: it is small for a point near the major axis inside the evolute).
        let (z0, z1) = (x0 / a, y0 / b);
        let r0 = (a / b) * (a / b);
        // r₀ − 1 without cancellation (near-circles).
        let rm1 = ((a - b) / b) * ((a + b) / b);
        let g = |v: f64| {
            let (i0, i1) = (1.0 / (v + rm1), 1.0 / v);
            let (p0, p1) = (r0 * z0 * i0, z1 * i1);
            let (q0, q1) = (p0 * p0, p1 * p1);
            (q0 + q1 - 1.0, -2.0 * (q0 * i0 + q1 * i1))
        };
        // G ≥ 0 at v_lo (one of the two terms is ≥ 1 there). The start is v = 1 (t = 0, the
        // point on the ellipse) when G(1) ≥ 0 (the point outside), else one Newton step from
        // it, which lands left of the root (G is convex) but not below v_lo: near the ellipse —
        // a resting contact — a few steps then suffice.
        let v_lo = z1.max(r0 * z0 - rm1);
        let hi = ((r0 * z0) * (r0 * z0) + z1 * z1).sqrt();
        let (g1, d1) = g(1.0);
        let v0 = if g1 >= 0.0 {
            1.0f64.max(v_lo)
        } else {
            (1.0 - g1 / d1).max(v_lo)
        };
        let v0 = if v0.is_finite() { v0.min(hi) } else { v_lo };
        let v = newton_increasing(v0, hi.max(v0), g);
        f.push(&mut out, r0 * x0 / (v + rm1), y0 / v, false, false);
    } else if y0 > 0.0 {
        // On the minor axis (x₀ = 0): the vertex of that side.
        f.push(&mut out, 0.0, b, false, false);
    } else if x0 * a < d {
        // On the major axis, inside the evolute: the symmetric pair.
        let ex = a * a * x0 / d;
        let ey = b * (1.0 - (ex / a) * (ex / a)).max(0.0).sqrt();
        f.push(&mut out, ex, ey, false, true);
    } else {
        // On the major axis beyond the evolute's cusp (or a circle's centre): the vertex.
        f.push(&mut out, a, 0.0, false, false);
    }
    out
}

/// The feet with the multiplier between −a² and −b² that can be local minima of the support
/// function (none, or one — the other of the two there is a maximum — and, when the point is on
/// an axis, the symmetric pairs in closed form): with the nearest, every local minimum.
pub(crate) fn middle_feet(a: f64, b: f64, p: Vector) -> Feet {
    let f = Frame::new(a, b, p);
    let mut out = Feet::new();
    let (a, b, x0, y0) = (f.a, f.b, f.x0, f.y0);
    let d = (a - b) * (a + b);
    if d <= 0.0 || !d.is_finite() {
        // A circle: only the nearest and farthest points (every point when p is the centre,
        // where any direction gives the same value).
        return out;
    }
    let (ca, cb) = (a * x0, b * y0);
    match (x0 > 0.0, y0 > 0.0) {
        (true, true) => {
            // Φ(u) = (ca/u)² + (cb/w)² − 1, u + w = d; minimum where (w/u)³ = (cb/ca)².
            let kappa = ((cb / ca) * (cb / ca)).cbrt();
            let u_star = d / (1.0 + kappa);
            let w_star = d - u_star;
            let phi = |u: f64, w: f64| (ca / u) * (ca / u) + (cb / w) * (cb / w) - 1.0;
            // Not below the axis (or NaN): no middle root.
            let dips = phi(u_star, w_star) <= 0.0;
            if !dips {
                return out;
            }
            // The left root (u ∈ (0, u*]) is the foot next to the nearest one, towards the
            // vertex (a, 0): the stationary points of the support function alternate between
            // minima and maxima around the circle (nearest, farthest, right, left, in that
            // counter-clockwise order), so it is a maximum, never wanted. The right root, in
            // w ∈ (0, w*], from w = cb.
            let wr = newton_increasing(cb.min(w_star), w_star, |w| {
                let (iu, iw) = (1.0 / (d - w), 1.0 / w);
                let (qu, qw) = ((ca * iu).powi(2), (cb * iw).powi(2));
                (qu + qw - 1.0, 2.0 * qu * iu - 2.0 * qw * iw)
            });
            f.push(&mut out, a * a * x0 / (d - wr), -b * b * y0 / wr, false, false);
        }
        (false, true) => {
            // On the minor axis: the opposite vertex (w = cb) and, inside the evolute, the
            // pair with u → 0.
            if cb < d {
                let ey = -b * b * y0 / d;
                let ex = a * (1.0 - (ey / b) * (ey / b)).max(0.0).sqrt();
                f.push(&mut out, ex, ey, true, false);
                f.push(&mut out, 0.0, -b, false, false);
            }
        }
        (true, false) => {
            // On the major axis: the near vertex (u = ca) when the pair is the nearest.
            if ca < d {
                f.push(&mut out, a, 0.0, false, false);
            }
        }
        (false, false) => {
            // The centre: the four vertices are feet; the nearest pair is (0, ±b).
            f.push(&mut out, a, 0.0, true, false);
            f.push(&mut out, 0.0, b, false, true);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::TAU;

    /// Every foot of p by dense sampling of g(θ) = (e(θ) − p)·e′(θ) and bisection, with whether
    /// it is a local minimum of the distance (g from negative to positive).
    fn sampled_feet(a: f64, b: f64, p: Vector) -> Vec<(Vector, bool)> {
        let e = |t: f64| Vector::new(a * t.cos(), b * t.sin());
        let g = |t: f64| (e(t) - p).dot(Vector::new(-a * t.sin(), b * t.cos()));
        let n = 20_000;
        let mut out = Vec::new();
        for i in 0..n {
            let (mut lo, mut hi) = (TAU * i as f64 / n as f64, TAU * (i + 1) as f64 / n as f64);
            let (glo, ghi) = (g(lo), g(hi));
            if glo == 0.0 {
                let minimum = g(lo - 1e-9) < 0.0 && g(lo + 1e-9) > 0.0;
                out.push((e(lo), minimum));
                continue;
            }
            if glo * ghi < 0.0 {
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if g(mid) * glo > 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                out.push((e(0.5 * (lo + hi)), glo < 0.0));
            }
        }
        out
    }

    fn check(a: f64, b: f64, p: Vector) {
        let ours: Vec<Foot> = nearest_feet(a, b, p)
            .as_slice()
            .iter()
            .chain(middle_feet(a, b, p).as_slice())
            .copied()
            .collect();
        let size = a.max(b);
        for f in &ours {
            let on = (f.point.x / a).powi(2) + (f.point.y / b).powi(2) - 1.0;
            assert!(on.abs() < 1e-12, "{a} {b} {p:?}: {f:?} off the ellipse by {on}");
            let t = Vector::new(-f.normal.y, f.normal.x);
            assert!(
                (f.point - p).dot(t).abs() < 1e-12 * size,
                "{a} {b} {p:?}: {f:?} not a foot"
            );
        }
        let nearest = nearest_feet(a, b, p).as_slice()[0];
        let sampled = sampled_feet(a, b, p);
        let best = sampled.iter().map(|e| (e.0 - p).length()).fold(f64::INFINITY, f64::min);
        assert!(
            ((nearest.point - p).length() - best).abs() < 1e-9 * size,
            "{a} {b} {p:?}"
        );
        // Every sampled local minimum of the distance is found (a point on an axis may have
        // local maxima among ours too).
        for (s, minimum) in &sampled {
            if !minimum {
                continue;
            }
            assert!(
                ours.iter().any(|f| (f.point - *s).length() < 1e-6 * size),
                "{a} {b} {p:?}: sampled foot {s:?} missing from {ours:?}"
            );
        }
    }

    #[test]
    fn feet_match_dense_sampling_inside_outside_and_on_axes() {
        for (a, b) in [(1.0, 0.5), (0.5, 1.0), (1.0, 0.01), (2.0, 1.9), (1.0, 1.0)] {
            for i in 0..25 {
                for j in 0..25 {
                    let p = Vector::new(-1.5 * a + 0.125 * a * i as f64, -1.5 * b + 0.125 * b * j as f64);
                    check(a, b, p);
                }
            }
            check(a, b, Vector::new(0.3 * a, 1e-9 * b));
            check(a, b, Vector::new(1e-9 * a, 0.3 * b));
        }
    }
}
