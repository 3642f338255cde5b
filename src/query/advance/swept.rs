//! A certified miss before any contact query: lower bounds of the separation along a few fixed
//! axes over the whole window, from the turning body's swept positions alone.
//!
//! # The bound
//!
//! In A's frame (the body that does not turn, at the origin) B's rotation centre moves on the
//! segment from x_a = x(t₀) to x_b = x(t₁) and B turns monotonically from θ_a to θ_b, by less
//! than half a turn (the nlerp path; a longer turn counts as every rotation). For a unit axis n
//! and each piece of the separation S_n (module docs of `query::advance`),
//!
//!   S_n(t) = n·x(t) + min over B of w(t)·(q − c) − h_A(n),    w(t) = R(θ(t))ᵀ·n,
//!
//! the translation and the rotation are bounded apart: n·x(t) ≥ min(n·x_a, n·x_b) (x is on the
//! segment), and w(t) stays on the arc of directions from w_a to w_b, over which
//!
//! * a vertex p = v − c (dilated by r) has min of w·p = −|p| when −p lies on the arc, else
//!   min(w_a·p, w_b·p) (w·p = |p|·cos of the angle between them, which has no interior minimum
//!   elsewhere), minus r;
//! * an ellipse of semi-axes a ≥ b has max of k(w) = √(a²w_x² + b²w_y²) = √(b² + (a² − b²)w_x²)
//!   equal to a when ±x̂ lies on the arc, else the larger of its values at the ends (|w_x| has
//!   no interior maximum elsewhere); the same with the axes exchanged when b > a; its centre
//!   term −w·c is a vertex at −c.
//!
//! So L(n) = min(n·x_a, n·x_b) + min over B's pieces of their bounds − h_A(n) ≤ S_n(t) ≤ D(t)
//! for every t of the window (D the signed distance; S_n ≤ D by the separating-axis theorem).
//! When L(n) exceeds the caller's level for one axis, the shapes never come within it: no
//! impact, and no contact at the start. The axes tried: from A's centre to the nearest point
//! of the segment, the segment's two normals, against its direction, and A's face normals —
//! the ones a body passing by, stopping short or moving away is separated along.

use super::{Kinematics, PairOnPath};
use crate::numerics::math::{cross, perp, Real, Vector};
use crate::query::contact::separation::support_bound;
use crate::query::contact::SupportShape;
use core::f64::consts::PI;

/// A's face normals tried at most (the contact query's largest polygon).
const MAX_FACE_AXES: usize = 16;

/// The turning body's reach over the window: the ends of its centre's segment and the arc of
/// the axis seen from it.
struct Sweep<'a> {
    body: SupportShape<'a>,
    /// B's rotation centre in its frame.
    centre: Vector,
    xa: Vector,
    xb: Vector,
    /// R(θ_a), R(θ_b) as (cos, sin).
    ra: (Real, Real),
    rb: (Real, Real),
    /// w turns clockwise from w_a to w_b (θ increasing).
    clockwise: bool,
    /// The turn may cover half a turn or more: every direction is on the arc.
    full: bool,
}

impl Sweep<'_> {
    /// w = R(θ)ᵀ·n for the rotation (cos, sin).
    #[inline]
    fn seen(r: (Real, Real), n: Vector) -> Vector {
        let (c, s) = r;
        Vector::new(c * n.x + s * n.y, -s * n.x + c * n.y)
    }

    /// Whether the direction `v` lies on the arc from `wa` to `wb` (module docs).
    #[inline]
    fn on_arc(&self, wa: Vector, wb: Vector, v: Vector) -> bool {
        if self.full {
            return true;
        }
        if self.clockwise {
            cross(wb, v) >= 0.0 && cross(v, wa) >= 0.0
        } else {
            cross(wa, v) >= 0.0 && cross(v, wb) >= 0.0
        }
    }

    /// The least of w·p over the arc (module docs).
    #[inline]
    fn vertex_min(&self, wa: Vector, wb: Vector, p: Vector) -> Real {
        if self.on_arc(wa, wb, -p) {
            -p.length()
        } else {
            wa.dot(p).min(wb.dot(p))
        }
    }

    /// A lower bound of min over B of w·(q − c) over the arc of the axis `n`, or a value at
    /// most −`above` as soon as the bound is known not to exceed it (a polygon's vertices are
    /// read until one does); `None` for a body the bound does not take (a `CapsuleEllipse`).
    fn body_min(&self, n: Vector, above: Real) -> Option<Real> {
        let (wa, wb) = (Self::seen(self.ra, n), Self::seen(self.rb, n));
        match self.body {
            SupportShape::Polygon { vertices, radius, .. } => {
                let mut low = Real::INFINITY;
                for v in vertices {
                    low = low.min(self.vertex_min(wa, wb, *v - self.centre));
                    if low.is_nan() || low - radius <= -above {
                        break;
                    }
                }
                Some(low - radius)
            }
            SupportShape::Disc(r) => Some(self.vertex_min(wa, wb, -self.centre) - r),
            SupportShape::Ellipse(a, b) => {
                let major = if a >= b { Vector::X } else { Vector::Y };
                let k = |w: Vector| ((a * w.x).powi(2) + (b * w.y).powi(2)).sqrt();
                let kmax = if self.on_arc(wa, wb, major) || self.on_arc(wa, wb, -major) {
                    a.max(b)
                } else {
                    k(wa).max(k(wb))
                };
                Some(self.vertex_min(wa, wb, -self.centre) - kmax)
            }
            SupportShape::CapsuleEllipse(..) => None,
        }
    }
}

/// h_A(n), the support function of A along the unit `n` (`query::contact::separation`'s, the same
/// float operations); `None` for a `CapsuleEllipse`, for which that function gives an upper bound
/// only.
fn support(sa: SupportShape, n: Vector) -> Option<Real> {
    match sa {
        SupportShape::CapsuleEllipse(..) => None,
        _ => Some(support_bound(sa, n)),
    }
}

/// Whether the shapes `s1`, `s2` moving as `pair` says stay farther apart than `level` over
/// all of `[t0, t1]`, by the bounds of the module docs along a few axes (false: not shown, the
/// caller's exact queries decide). One body at most may turn.
pub(crate) fn certified_miss(
    s1: SupportShape,
    s2: SupportShape,
    pair: &PairOnPath,
    t0: Real,
    t1: Real,
    level: Real,
) -> bool {
    let (sa, sb) = pair.ordered(s1, s2);
    let Some(sweep) = sweep_of(sb, &pair.k, t0, t1) else {
        return false;
    };
    // L(n) > level along `n` (module docs).
    let apart = |n: Vector| -> bool {
        let reach = n.dot(sweep.xa).min(n.dot(sweep.xb));
        // A polygon's first vertex first: h_A(n) ≥ v₀·n + r (to the bit: the largest dot is at
        // least v₀'s, and the rounded sums and differences are monotone), so where the part
        // below is not above the level neither is the one with h_A(n).
        if let SupportShape::Polygon {
            vertices: [v0, ..],
            radius,
            ..
        } = sa
        {
            if reach - (v0.dot(n) + radius) - level <= 0.0 {
                return false;
            }
        }
        let Some(h) = support(sa, n) else { return false };
        // The translation's and A's part first: B's part is at most 0 about a centre inside B,
        // so an axis where this part is not above the level is not worth B's bound.
        let base = reach - h - level;
        if base.is_nan() || base <= 0.0 {
            return false;
        }
        sweep.body_min(n, base).is_some_and(|low| base + low > 0.0)
    };
    let chord = sweep.xb - sweep.xa;
    let len = chord.length();
    // From A's centre to the nearest point of the centre's segment.
    let s = if len > 0.0 {
        (-sweep.xa.dot(chord) / (len * len)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let nearest = sweep.xa + chord * s;
    let dist = nearest.length();
    if dist > 0.0 && apart(nearest / dist) {
        return true;
    }
    if len > 0.0 {
        let u = chord / len;
        if apart(perp(u)) || apart(-perp(u)) || apart(-u) {
            return true;
        }
    }
    if let SupportShape::Polygon { normals, .. } = sa {
        return normals.iter().take(MAX_FACE_AXES).any(|n| apart(*n));
    }
    false
}

/// B's sweep over `[t0, t1]` from its kinematics; `None` when a value is not finite.
fn sweep_of<'a>(body: SupportShape<'a>, k: &Kinematics, t0: Real, t1: Real) -> Option<Sweep<'a>> {
    let (ra, _) = k.turn(t0);
    let (rb, _) = k.turn(t1);
    // The turn over the window: Δ on the nlerp path (|Δ| < π), ω·T on parry's.
    let turn = k.omega * (t1 - t0);
    let full = k.clock.is_none() && turn.abs() >= PI;
    let sweep = Sweep {
        body,
        centre: k.centre,
        xa: k.x0 + k.d * t0,
        xb: k.x0 + k.d * t1,
        ra: (ra.re, ra.im),
        rb: (rb.re, rb.im),
        clockwise: k.omega > 0.0,
        full,
    };
    let finite =
        sweep.xa.is_finite() && sweep.xb.is_finite() && [ra.re, ra.im, rb.re, rb.im].iter().all(|v| v.is_finite());
    finite.then_some(sweep)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::advance::test_shapes::{random_pair, TestShapes};
    use crate::query::contact::contact;

    /// A certified miss is a miss: wherever the bounds answer one, the exact distance sampled
    /// densely on the nlerp path stays above the level; and the bounds do certify most of the
    /// pairs passing well clear of each other.
    #[test]
    fn certified_misses_stay_above_the_level_on_the_path() {
        let shapes = TestShapes::new();
        let bodies = shapes.bodies();
        let targets = [shapes.flat_box(), SupportShape::Disc(0.4)];
        let mut rng = crate::numerics::test_rng::Lcg(0x9E37_79B9_7F4A_7C15u64);
        let mut uniform = |lo: Real, hi: Real| rng.range(lo, hi);
        let (level, mut certified, mut cases) = (1e-3, 0, 0);
        for &sa in &targets {
            for &sb in &bodies {
                for _ in 0..400 {
                    let (mb, pair) = random_pair(&mut uniform, Some(0.1));
                    cases += 1;
                    if !certified_miss(sa, sb, &pair, 0.0, 1.0, level) {
                        continue;
                    }
                    certified += 1;
                    let k = &pair.k;
                    for i in 0..=2000 {
                        let t = i as Real / 2000.0;
                        let c = contact(sa, sb, &k.pose(t), 2.0, None).unwrap();
                        assert!(c.dist > level, "{:?} at t = {t}: distance {}", mb, c.dist);
                    }
                }
            }
        }
        println!("{certified} of {cases} casts certified");
        assert!(certified * 3 > cases, "{certified} of {cases}");
    }
}
