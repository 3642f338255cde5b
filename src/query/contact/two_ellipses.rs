//! The minimum of F over an arc on which both sides are ellipses: branch and bound with a
//! second-order bound, and Newton's method where F is certified convex.
//!
//! On such an arc F(n) = q·n + r + k₁(n) + k₂(n) (k₁, k₂ the support functions of the two
//! centred ellipses): F − r is the support function of the Minkowski sum of the two ellipses
//! moved to q. With ψ the direction's angle and ρᵢ(ψ) = aᵢ²bᵢ²/kᵢ(ψ)³ the ellipses' radii of
//! curvature at the normal ψ,
//!
//!   F′(ψ) = (q + s₁(n) + s₂(n))·n⊥ (sᵢ the centred support points),  F″ = ρ₁ + ρ₂ − (F − r).
//!
//! On a sub-arc of half-width at most h (h = tan of the true half-width, which is larger):
//!
//! * ρᵢ ≥ aᵢ²bᵢ²/max kᵢ³, max kᵢ in closed form (the major axis's normal if it is in the arc,
//!   else the larger end), and F − r ≤ U, U = max(F(a), F(b)) − r scaled by 1/cos(half-width)
//!   when positive (F − r is sublinear), so F″ ≥ μ = Σ aᵢ²bᵢ²/max kᵢ³ − U;
//! * hence F ≥ F(m) + F′(m)·x + μx²/2 for |x| ≤ h about the midpoint m: a lower bound whose
//!   error shrinks with the square of the width; and about either end e, F ≥ F(e) ± F′(e)·x +
//!   μx²/2 for 0 ≤ x ≤ 2h into the sub-arc, least at x = 0 or x = 2h when μ ≤ 0, which bounds the
//!   sub-arcs next to an end of the arc where F rises into the arc by F(e) itself (the midpoint
//!   bound stays below F(e) there, however narrow the sub-arc);
//! * when μ > 0, F is convex on the sub-arc: its minimum is at an end unless F′ changes sign
//!   inside, where the one root of the increasing F′ is found by Newton's method kept inside a
//!   shrinking bracket (bisection when a step leaves it).
//!
//! The search starts with a descent to a local minimum (Newton's method from the lowest of the
//! first directions of the arc, or over the whole circle from the previous normal when rapier
//! hands one back): it is the answer at once when it lies in the arc and is certified (apart, or
//! shallower than the two smallest radii of curvature: [`TwoEllipses::minimum`]); otherwise,
//! over the whole circle, the widest of a few neighbourhoods of it on which μ > 0 (F convex, so
//! the minimum there is this one) is left out of the search.
//!
//! A sub-arc is discarded when its bound reaches the best value of F seen (at any end, midpoint
//! or root: that point is kept), solved when convex, split in two otherwise. Discarding compares
//! with the best value without tolerance, so the answer is the global minimum up to rounding; at
//! a strict local minimum F″ > 0, so every sub-arc near one is eventually certified convex, and
//! next to a minimum at an end of the arc the end's bound discards it. A budget of
//! sub-arcs ([`MAX_ARCS`]) bounds degenerate inputs (the caller then answers otherwise).

use super::arc::in_arc;
use super::side::Axes;
use crate::numerics::math::{cross, perp, sin_cos, Vector};

/// Sub-arcs examined at most per arc.
pub(crate) const MAX_ARCS: usize = 4000;
/// Newton or bisection steps at most in a convex sub-arc.
const MAX_STEPS: usize = 100;
/// Steps at most of the descent to a local minimum before the search.
const DESCENT_STEPS: usize = 20;
/// Halvings at most of a descent step that does not lower F.
const HALVINGS: usize = 8;
/// Half-widths (radians) of the neighbourhoods of a local minimum tried for convexity, widest
/// first.
const NEIGHBOURHOODS: [f64; 4] = [0.2, 0.05, 0.012, 0.003];
/// Widest sub-arc the search starts from (radians).
const START_WIDTH: f64 = core::f64::consts::FRAC_PI_4;
/// Sub-arcs of a cover at most: the whole circle in sub-arcs of [`START_WIDTH`] (8), and one
/// more should the division round up.
const COVER: usize = 9;
/// Depth of the search's stack of sub-arcs.
const STACK: usize = 64;

/// F on an arc where both pieces are ellipses.
pub(crate) struct TwoEllipses {
    pub q: Vector,
    pub r: f64,
    pub e1: Axes,
    pub e2: Axes,
}

/// Keeps `p` as the answer when it is lower than the answer so far, and lowers the bound.
#[inline]
fn note(p: &Point, bound: &mut f64, found: &mut Option<(f64, Vector)>) {
    if found.is_none_or(|f| p.f < f.0) {
        *found = Some((p.f, p.n));
    }
    *bound = bound.min(p.f);
}

/// A direction with F and F′ there.
#[derive(Copy, Clone, Debug)]
struct Point {
    n: Vector,
    f: f64,
    df: f64,
    /// k₁(n), k₂(n).
    k: [f64; 2],
}

impl TwoEllipses {
    #[inline]
    fn at(&self, n: Vector) -> Point {
        let (k1, s1) = self.e1.k_and_support(n);
        let (k2, s2) = self.e2.k_and_support(n);
        Point {
            n,
            f: self.q.dot(n) + self.r + k1 + k2,
            df: (self.q + s1 + s2).dot(perp(n)),
            k: [k1, k2],
        }
    }

    /// Newton's method on F′ from `p`, steps at most half of [`START_WIDTH`] (a gradient step
    /// where F″ ≤ 0): the lowest point met, and whether it is a local minimum (F″ > 0, the last
    /// step below 1e-15 rad).
    fn descend(&self, mut p: Point) -> (Point, bool) {
        for _ in 0..DESCENT_STEPS {
            let d2 = self.d2f(&p);
            let newton = d2 > 0.0;
            let mut step = if newton {
                -p.df / d2
            } else {
                -p.df.signum() * START_WIDTH
            };
            step = step.clamp(-0.5 * START_WIDTH, 0.5 * START_WIDTH);
            // Quadratic convergence: after a Newton step this small the iterate is exact to
            // rounding (F may no longer decrease).
            if newton && step.abs() <= 1e-8 {
                let (s, c) = sin_cos(step);
                let q = self.at(p.n * c + perp(p.n) * s);
                return (q, q.f.is_finite() && self.d2f(&q) > 0.0);
            }
            // Halve the step until F decreases.
            let mut next = None;
            for _ in 0..HALVINGS {
                let (s, c) = sin_cos(step);
                let q = self.at(p.n * c + perp(p.n) * s);
                if q.f < p.f {
                    next = Some(q);
                    break;
                }
                step *= 0.5;
            }
            match next {
                Some(q) => p = q,
                None => break,
            }
        }
        (p, false)
    }

    /// F″ at a point.
    #[inline]
    fn d2f(&self, p: &Point) -> f64 {
        let rho = |e: &Axes, k: f64| (e.a * e.b) * (e.a * e.b) / (k * k * k);
        rho(&self.e1, p.k[0]) + rho(&self.e2, p.k[1]) - (p.f - self.r)
    }

    /// The minimum of F over the arc from `a` counter-clockwise to `b` (the whole circle when
    /// `a == b`), below `best`: (value, direction), or `Some(None)` when nothing is lower than
    /// `best`; `None` when the budget runs out or a value is not finite.
    ///
    /// `hint` (the previous normal, for rapier's warm start) replaces the lowest of the first
    /// directions as the descent's start when it is lower.
    ///
    /// Over the whole circle a local minimum (Newton from the lowest of eight directions) is
    /// certified global, without the search, when F < 0 there (apart: the separation is concave
    /// where positive) or F < ρ₁ + ρ₂ with ρᵢ = min(aᵢ, bᵢ)²/max(aᵢ, bᵢ) the ellipses' smallest
    /// radii of curvature (shallow: each ellipse is a convex body swelled by a disc of radius ρᵢ,
    /// so the shrunk bodies are apart there, and their separation has that one maximum). On a
    /// part of the circle the same local minimum, when the descent ends inside the part, is the
    /// part's minimum too: F on the part is the two whole ellipses' F, whose global minimum it is.
    pub(crate) fn minimum(
        &self,
        a: Vector,
        b: Vector,
        best: f64,
        hint: Option<Vector>,
    ) -> Option<Option<(f64, Vector)>> {
        let blank = Point {
            n: a,
            f: 0.0,
            df: 0.0,
            k: [0.0; 2],
        };
        // The first sub-arcs (a cover); the search's stack is filled from them only when the
        // search runs (a certified descent answers without it).
        let mut first = [(blank, blank); COVER];
        let mut found: Option<(f64, Vector)> = None;
        let mut bound = best;
        let full = a == b;
        // Warm start over the whole circle: the descent from the previous normal, and the search
        // over the rest of the circle only, when its minimum is certified or has a convex
        // neighbourhood (no first sampling of the circle).
        let warm = hint.filter(|_| full).map(|h| self.descend(self.at(h)));
        let mut top = 0;
        let mut covered = false;
        // A descent's end that is not a certified local minimum: a bound for the search, and the
        // answer only if the search finds nothing as low (a sub-arc dropped on a bound that ties
        // the minimum to rounding).
        let mut fallback: Option<Point> = None;
        if let Some((low, true)) = warm {
            if self.certified(&low) {
                return Some((low.f < best).then_some((low.f, low.n)));
            }
            if let Some((pa, pb)) = self.convex_neighbourhood(&low) {
                note(&low, &mut bound, &mut found);
                (top, _) = self.cover(pb.n, pa.n, &mut first);
                covered = true;
            }
        }
        if !covered {
            let (t, mut start) = self.cover(a, b, &mut first);
            top = t;
            if let Some((low, _)) = warm {
                bound = bound.min(low.f);
                fallback = Some(low);
            }
            if let Some(h) = hint.filter(|&h| full || in_arc(a, b, h)) {
                let ph = self.at(h);
                if ph.f < start.f {
                    start = ph;
                }
            }
            note(&start, &mut bound, &mut found);
            let (low, local) = self.descend(start);
            if full || in_arc(a, b, low.n) {
                if local && self.certified(&low) {
                    return Some((low.f < best).then_some((low.f, low.n)));
                }
                if local {
                    note(&low, &mut bound, &mut found);
                    if full {
                        // F convex on a neighbourhood of the local minimum: its minimum there is
                        // this one, and the search covers the rest of the circle only.
                        if let Some((pa, pb)) = self.convex_neighbourhood(&low) {
                            (top, _) = self.cover(pb.n, pa.n, &mut first);
                        }
                    }
                } else {
                    bound = bound.min(low.f);
                    fallback = fallback.filter(|f| f.f <= low.f).or(Some(low));
                }
            }
        }
        let mut stack = [(blank, blank); STACK];
        stack[..top].copy_from_slice(&first[..top]);
        let mut budget = MAX_ARCS;
        while top > 0 {
            top -= 1;
            let (pa, pb) = stack[top];
            budget = budget.checked_sub(1)?;
            if !(pa.f.is_finite() && pb.f.is_finite()) {
                return None;
            }
            note(&pa, &mut bound, &mut found);
            let sum = pa.n + pb.n;
            let ch = 0.5 * sum.length();
            let proper = ch > 0.0;
            if !proper {
                return None;
            }
            let h = 0.5 * (pb.n - pa.n).length() / ch;
            let pm = self.at(sum / (2.0 * ch));
            note(&pm, &mut bound, &mut found);
            let mu = self.curvature_bound(pa, pb, ch);
            if mu > 0.0 {
                // Convex: the minimum is at an end unless F′ changes sign inside.
                if pa.df < 0.0 && pb.df > 0.0 {
                    let p = self.convex_root(pa, pb)?;
                    note(&p, &mut bound, &mut found);
                } else {
                    note(&pb, &mut bound, &mut found);
                }
                continue;
            }
            // Second-order bounds about the midpoint and about either end (F ≥ F(e) ± F′(e)x +
            // μx²/2 over the sub-arc, μ ≤ 0: least at x = 0 or at the far end, x ≤ 2h): the
            // end bounds discard the sub-arcs next to an end where the arc's minimum is that end.
            let lower_mid = pm.f - pm.df.abs() * h + 0.5 * mu * h * h;
            let w = 2.0 * h;
            let lower_a = pa.f.min(pa.f + pa.df * w + 0.5 * mu * w * w);
            let lower_b = pb.f.min(pb.f - pb.df * w + 0.5 * mu * w * w);
            let lower = lower_mid.max(lower_a).max(lower_b);
            // Nothing on the sub-arc is lower than the best value seen (a point already kept,
            // or the caller's `best`): it may go.
            if lower >= bound || self.termwise_bound(&pa, &pb) > bound {
                continue;
            }
            if top + 2 > stack.len() {
                return None;
            }
            stack[top] = (pm, pb);
            stack[top + 1] = (pa, pm);
            top += 2;
        }
        let scale = self.q.length() + self.e1.a.max(self.e1.b) + self.e2.a.max(self.e2.b) + self.r.abs();
        let rounding = 64.0 * f64::EPSILON * scale;
        if let Some(l) = fallback.filter(|l| found.is_none_or(|f| l.f < f.0 - rounding)) {
            found = Some((l.f, l.n));
        }
        Some(found.filter(|f| f.0 < best))
    }

    /// A first-order lower bound of F on the sub-arc (pa, pb): the minimum of each term (q·n,
    /// k₁, k₂) over it, each exact (the smallest k at the minor axis's normal when it is in
    /// the sub-arc, else at an end; q·n at −q when it is in it, else at an end).
    fn termwise_bound(&self, pa: &Point, pb: &Point) -> f64 {
        let inside = |d: Vector| cross(pa.n, d) >= 0.0 && cross(d, pb.n) >= 0.0;
        let lin = if inside(-self.q) {
            -self.q.length()
        } else {
            self.q.dot(pa.n).min(self.q.dot(pb.n))
        };
        let kmin = |e: &Axes, i: usize| {
            let minor = if e.a >= e.b { e.w } else { e.u };
            if inside(minor) || inside(-minor) {
                e.a.min(e.b)
            } else {
                pa.k[i].min(pb.k[i])
            }
        };
        lin + kmin(&self.e1, 0) + kmin(&self.e2, 1) + self.r
    }

    /// Whether a local minimum over the whole circle is the global one without a search: apart
    /// (F − r < 0) or shallow (F − r below the sum of the ellipses' smallest radii of curvature;
    /// see [`TwoEllipses::minimum`]).
    fn certified(&self, low: &Point) -> bool {
        let rho = |e: &Axes| {
            let (lo, hi) = if e.a < e.b { (e.a, e.b) } else { (e.b, e.a) };
            lo * lo / hi
        };
        low.f - self.r < 0.0 || low.f - self.r < rho(&self.e1) + rho(&self.e2)
    }

    /// Covers the arc from `a` counter-clockwise to `b` (the whole circle when `a == b`) with
    /// sub-arcs of at most [`START_WIDTH`] on `stack`: their number, and the lowest end.
    fn cover(&self, a: Vector, b: Vector, stack: &mut [(Point, Point); COVER]) -> (usize, Point) {
        let width = {
            let w = cross(a, b).atan2(a.dot(b));
            if w <= 0.0 {
                w + core::f64::consts::TAU
            } else {
                w
            }
        };
        let pieces = ((width / START_WIDTH).ceil().max(1.0) as usize).min(COVER);
        let (s, c) = sin_cos(width / pieces as f64);
        let first = self.at(a);
        let (mut prev, mut start) = (first, first);
        for (i, slot) in stack.iter_mut().enumerate().take(pieces) {
            let n = if i + 1 == pieces {
                b
            } else {
                Vector::new(c * prev.n.x - s * prev.n.y, s * prev.n.x + c * prev.n.y)
            };
            let next = self.at(n);
            if next.f < start.f {
                start = next;
            }
            *slot = (prev, next);
            prev = next;
        }
        (pieces, start)
    }

    /// The ends of an arc about the local minimum `low` on which F is certified convex (μ > 0,
    /// see [`TwoEllipses::curvature_bound`]), so that `low` is its minimum; the widest of a few
    /// tried.
    fn convex_neighbourhood(&self, low: &Point) -> Option<(Point, Point)> {
        let t = perp(low.n);
        for half in NEIGHBOURHOODS {
            let (s, c) = sin_cos(half);
            let (pa, pb) = (self.at(low.n * c - t * s), self.at(low.n * c + t * s));
            if self.curvature_bound(pa, pb, c) > 0.0 {
                return Some((pa, pb));
            }
        }
        None
    }

    /// μ, a lower bound of F″ on the sub-arc (pa, pb) (see the module docs); `ch` is the
    /// cosine of its half-width.
    fn curvature_bound(&self, pa: Point, pb: Point, ch: f64) -> f64 {
        let kmax = |e: &Axes, i: usize| {
            let major = if e.a >= e.b { e.u } else { e.w };
            let inside = |d: Vector| cross(pa.n, d) >= 0.0 && cross(d, pb.n) >= 0.0;
            if inside(major) || inside(-major) {
                e.a.max(e.b)
            } else {
                pa.k[i].max(pb.k[i])
            }
        };
        let rho = |e: &Axes, i: usize| {
            let k = kmax(e, i);
            (e.a * e.b) * (e.a * e.b) / (k * k * k)
        };
        let top = pa.f.max(pb.f) - self.r;
        let upper = if top > 0.0 { top / ch } else { top };
        rho(&self.e1, 0) + rho(&self.e2, 1) - upper
    }

    /// The root of the increasing F′ between `pa` (F′ < 0) and `pb` (F′ > 0), by Newton's
    /// method kept in the bracket.
    fn convex_root(&self, pa: Point, pb: Point) -> Option<Point> {
        let t = perp(pa.n);
        let width = cross(pa.n, pb.n).atan2(pa.n.dot(pb.n));
        let (mut lo, mut hi) = (0.0, width);
        let dir = |x: f64| {
            let (s, c) = sin_cos(x);
            pa.n * c + t * s
        };
        let mut x = 0.5 * width;
        let mut p = self.at(dir(x));
        for _ in 0..MAX_STEPS {
            if !p.df.is_finite() {
                return None;
            }
            if p.df == 0.0 {
                break;
            }
            if p.df < 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            let d2 = self.d2f(&p);
            let mut next = x - p.df / d2;
            if !(next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
            if next == x || hi - lo <= f64::EPSILON * width {
                break;
            }
            x = next;
            p = self.at(dir(x));
        }
        Some(p)
    }
}
