//! The minimum of F(n) = h₁(n) + h₂(−n) over directions, walking the merged breakpoints of both
//! sides (see the folder's module docs for why it is exact).

use super::arc::{in_arc, Arc};
use super::feet::{middle_feet, nearest_feet, Feet};
use super::side::{Axes, Placed, MAX_BREAKPOINTS};
use super::two_ellipses::TwoEllipses;
use crate::numerics::math::{cross, perp, Vector};

/// A breakpoint of the merged walk: the side it belongs to (0 or 1), its index there, the pieces
/// active just after it and F there.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Entry {
    /// F at the breakpoint.
    pub value: f64,
    pub side: u8,
    pub index: u8,
    /// The indices of the pieces active just after the breakpoint (side 0, side 1).
    pub active: [u8; 2],
}

impl Entry {
    /// The side it belongs to.
    #[inline]
    pub(crate) fn side(&self) -> usize {
        self.side as usize
    }
    /// Its index on its side.
    #[inline]
    pub(crate) fn index(&self) -> usize {
        self.index as usize
    }
}

/// Where the minimum is.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) enum At {
    /// At merged breakpoint i.
    Breakpoint(usize),
    /// Inside the arc after merged breakpoint i (`usize::MAX`: the whole circle, no breakpoint).
    Inside(usize),
}

/// The minimum of F.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Minimum {
    pub value: f64,
    /// The minimising direction (body 1's frame, from body 1 towards body 2).
    pub normal: Vector,
    pub at: At,
    /// The indices of the pieces active at the minimum (side 0, side 1).
    pub active: [usize; 2],
}

/// Breakpoint values within this fraction of the largest |F| at a breakpoint of the best one
/// count as ties for the separated shortcut of [`Walk::minimum`] (rounding only; the shortcut
/// then looks at a few more arcs, never fewer).
pub(super) const TIE: f64 = 1e-9;

/// Which half-turn from `s` the unit direction `n` lies in (0: [0, π), 1: [π, 2π)).
#[inline]
pub(super) fn half(s: Vector, n: Vector) -> u8 {
    let c = cross(s, n);
    u8::from(!(c > 0.0 || (c == 0.0 && s.dot(n) > 0.0)))
}

/// Whether `a` comes before `b` counter-clockwise from `s` (their halves `ha`, `hb`).
#[inline]
pub(super) fn before(ha: u8, a: Vector, hb: u8, b: Vector) -> bool {
    ha < hb || (ha == hb && cross(a, b) > 0.0)
}

/// Each side's half-turns from `start` of its breakpoint normals, and the index of its first
/// breakpoint counter-clockwise from `start` (the normals are cyclically sorted): where the
/// merge of [`for_each_merged`] begins on each side.
#[inline(always)]
pub(super) fn first_breakpoints(
    start: Vector,
    normals: [&[Vector; MAX_BREAKPOINTS]; 2],
    lens: [usize; 2],
) -> ([usize; 2], [[u8; MAX_BREAKPOINTS]; 2]) {
    let mut first = [0usize; 2];
    let mut halves = [[0u8; MAX_BREAKPOINTS]; 2];
    for s in 0..2 {
        for k in 0..lens[s] {
            halves[s][k] = half(start, normals[s][k]);
            let f = first[s];
            if k > 0 && before(halves[s][k], normals[s][k], halves[s][f], normals[s][f]) {
                first[s] = k;
            }
        }
    }
    (first, halves)
}

/// Visits the breakpoints of both sides in counter-clockwise order from their `first`
/// ([`first_breakpoints`]), `visit(side, k)` each; of two equal directions side 0's comes first.
#[inline(always)]
pub(super) fn for_each_merged(
    first: [usize; 2],
    halves: &[[u8; MAX_BREAKPOINTS]; 2],
    normals: [&[Vector; MAX_BREAKPOINTS]; 2],
    lens: [usize; 2],
    mut visit: impl FnMut(usize, usize),
) {
    let (mut i0, mut i1) = (0, 0);
    while i0 < lens[0] || i1 < lens[1] {
        let k0 = wrap(first[0] + i0, lens[0]);
        let k1 = wrap(first[1] + i1, lens[1]);
        let take0 =
            i1 >= lens[1] || (i0 < lens[0] && !before(halves[1][k1], normals[1][k1], halves[0][k0], normals[0][k0]));
        if take0 {
            i0 += 1;
            visit(0, k0);
        } else {
            i1 += 1;
            visit(1, k1);
        }
    }
}

/// The merged walk of two placed sides.
pub(crate) struct Walk<'a> {
    pub sides: [&'a Placed; 2],
    pub entries: [Entry; 2 * MAX_BREAKPOINTS],
    pub len: usize,
    /// Where the search of an arc between two ellipses starts, if it is lower there.
    pub hint: Option<Vector>,
}

impl<'a> Walk<'a> {
    /// A blank walk, merged ([`Walk::merge`]): the tests' shorthand.
    #[cfg(test)]
    pub(crate) fn new(s0: &'a Placed, s1: &'a Placed) -> Self {
        let mut w = Walk::blank(s0, s1);
        w.merge();
        w
    }

    /// A walk of the two sides with no breakpoint merged yet.
    #[inline(always)]
    pub(crate) fn blank(s0: &'a Placed, s1: &'a Placed) -> Self {
        let blank = Entry {
            value: 0.0,
            side: 0,
            index: 0,
            active: [0, 0],
        };
        Walk {
            sides: [s0, s1],
            entries: [blank; 2 * MAX_BREAKPOINTS],
            len: 0,
            hint: None,
        }
    }

    /// Merges the breakpoints of both sides counter-clockwise and evaluates F at each, in place
    /// on a blank walk (the walk is half a kilobyte: built and returned by value, it was copied).
    #[inline(always)]
    pub(crate) fn merge(&mut self) {
        let w = self;
        let sides = w.sides;
        let [s0, s1] = sides;
        let start = if s0.len > 0 {
            s0.normals[0]
        } else if s1.len > 0 {
            s1.normals[0]
        } else {
            Vector::X
        };
        w.len = 0;
        // Each side's breakpoints from the first after `start` on (they are cyclically sorted).
        let (normals, lens) = ([&s0.normals, &s1.normals], [s0.len, s1.len]);
        let (first, halves) = first_breakpoints(start, normals, lens);
        let prev = |s: &Placed, k: usize| (if k == 0 { s.len.max(1) - 1 } else { k - 1 }) as u8;
        let mut active = [prev(s0, first[0]), prev(s1, first[1])];
        for_each_merged(first, &halves, normals, lens, |side, k| {
            active[side] = k as u8;
            let value = w.value([active[0] as usize, active[1] as usize], sides[side].normals[k]);
            w.entries[w.len] = Entry {
                value,
                side: side as u8,
                index: k as u8,
                active,
            };
            w.len += 1;
        });
    }

    /// The indices of the pieces active after merged breakpoint i (the only pieces with no
    /// breakpoint).
    #[inline]
    pub(crate) fn active(&self, i: usize) -> [usize; 2] {
        if self.len == 0 {
            return [0, 0];
        }
        let a = self.entries[i].active;
        [a[0] as usize, a[1] as usize]
    }

    /// The direction of merged breakpoint i.
    #[inline]
    pub(crate) fn normal(&self, i: usize) -> Vector {
        let e = &self.entries[i];
        self.sides[e.side()].normals[e.index()]
    }

    /// F at n on the pieces `p`.
    #[inline]
    pub(crate) fn value(&self, p: [usize; 2], n: Vector) -> f64 {
        self.sides[0].value(p[0], n) + self.sides[1].value(p[1], n)
    }

    /// The linear coefficient and the radius of F on the pieces `p`.
    #[inline]
    fn linear(&self, p: [usize; 2]) -> (Vector, f64) {
        let [s0, s1] = self.sides;
        (s0.q[p[0]] + s1.q[p[1]], s0.r[p[0]] + s1.r[p[1]])
    }

    /// The arc after merged breakpoint i: its end directions, or `None` when it is empty (two
    /// breakpoints in the same direction). With no breakpoint, the whole circle.
    fn arc(&self, i: usize) -> Option<Arc> {
        if self.len == 0 {
            return Some(Arc::Full);
        }
        let (a, b) = (self.normal(i), self.normal(wrap(i + 1, self.len)));
        let empty = self.len > 1 && cross(a, b) == 0.0 && a.dot(b) > 0.0;
        (!empty).then_some(Arc::Between(a, b))
    }

    /// A lower bound of F over `arc` on the pieces `p` (one an ellipse with axes `ax`): the
    /// minimum of the linear part plus the minimum of k over the arc, each exact.
    fn lower_bound(&self, arc: Arc, p: [usize; 2], ax: &Axes) -> f64 {
        let (q, r) = self.linear(p);
        self.linear_min(arc, q) + k_min(arc, ax) + r
    }

    /// The minimum of F over every direction. `None` when a value is not finite or the search
    /// between two ellipse pieces runs out of its budget.
    pub(crate) fn minimum(&self) -> Option<Minimum> {
        let mut best: Option<Minimum> = None;
        let mut scale = 0.0f64;
        for (i, e) in self.entries[..self.len].iter().enumerate() {
            scale = scale.max(e.value.abs());
            let m = Minimum {
                value: e.value,
                normal: self.normal(i),
                at: At::Breakpoint(i),
                active: self.active(i),
            };
            if !keep(&mut best, m) {
                return None;
            }
        }
        // Two polygons (discs, segments): F − r is the support function of the cores' Minkowski
        // difference, r = r₁ + r₂ the same on every arc. When the cores overlap along every
        // breakpoint (F ≥ r there) and every arc is narrower than π (a side with three edges or
        // more), no arc holds a lower value: its only candidate, r − |q| at n = −q/|q|, would
        // be a direction separating the cores. (An arc of exactly π — a segment against a disc
        // or a parallel segment — can hold it with both ends at r.)
        let [s0, s1] = self.sides;
        let polygons = s0.axes.is_none() && s1.axes.is_none() && s0.len.max(s1.len) >= 3;
        let r_core = if polygons { s0.r[0] + s1.r[0] } else { 0.0 };
        if polygons && best.is_some_and(|b| b.value >= r_core) {
            return best;
        }
        // Apart along a breakpoint's direction (the cores, for two polygons): the separation is
        // concave where positive, so the maximum is next to the best breakpoint (or to one tied
        // with it).
        let cut = best.map(|b| b.value + TIE * scale);
        let separated = best.is_some_and(|b| b.value < r_core);
        // The arcs between two ellipse pieces (at most two: where the two ellipses' ranges of
        // directions meet) cost a search each: they come last, when the best value is lowest,
        // and are skipped when a lower bound of F on them exceeds it.
        let mut deferred = [(0usize, Arc::Full); 2];
        let mut n_deferred = 0;
        for i in 0..self.len.max(1) {
            if separated {
                let next = wrap(i + 1, self.len);
                let near = |j: usize| cut.is_some_and(|c| self.entries[j].value <= c);
                if !(near(i) || near(next)) {
                    continue;
                }
            }
            let Some(arc) = self.arc(i) else { continue };
            let p = self.active(i);
            if s0.is_ellipse(p[0]) && s1.is_ellipse(p[1]) && n_deferred < deferred.len() {
                deferred[n_deferred] = (i, arc);
                n_deferred += 1;
                continue;
            }
            if !self.arc_minimum(&mut best, arc, p, self.inside(i)) {
                return None;
            }
        }
        for &(i, arc) in &deferred[..n_deferred] {
            let p = self.active(i);
            if let (Some(e1), Some(e2), Some(b)) = (s0.axes, s1.axes, best) {
                if self.two_ellipse_bound(arc, p, &e1, &e2) > b.value {
                    continue;
                }
            }
            if !self.arc_minimum(&mut best, arc, p, self.inside(i)) {
                return None;
            }
        }
        best
    }

    /// Where an interior minimum of the arc after merged breakpoint i is.
    #[inline]
    fn inside(&self, i: usize) -> At {
        if self.len == 0 {
            At::Inside(usize::MAX)
        } else {
            At::Inside(i)
        }
    }

    /// A lower bound of F over `arc` on the pieces `p`, both ellipses (`e1`, `e2`): the minimum
    /// of the linear part plus the minima of k₁ and k₂ over the arc, each exact.
    fn two_ellipse_bound(&self, arc: Arc, p: [usize; 2], e1: &Axes, e2: &Axes) -> f64 {
        let (q, r) = self.linear(p);
        self.linear_min(arc, q) + k_min(arc, e1) + k_min(arc, e2) + r
    }

    /// The minimum of q·n over the directions n of `arc`, exact.
    #[inline]
    fn linear_min(&self, arc: Arc, q: Vector) -> f64 {
        match arc {
            Arc::Between(a, b) if !arc.contains(-q) => q.dot(a).min(q.dot(b)),
            _ => -q.length(),
        }
    }

    /// Keeps in `best` the interior minimum of F over `arc` on the pieces `p`, if lower; false
    /// for two ellipse pieces.
    fn arc_minimum(&self, best: &mut Option<Minimum>, arc: Arc, p: [usize; 2], at: At) -> bool {
        let [s0, s1] = self.sides;
        let ax = match (s0.is_ellipse(p[0]), s1.is_ellipse(p[1])) {
            (true, true) => {
                let (Some(e1), Some(e2)) = (s0.axes, s1.axes) else {
                    return false;
                };
                let (q, r) = self.linear(p);
                let (a, b) = match arc {
                    Arc::Between(a, b) => (a, b),
                    Arc::Full => (Vector::X, Vector::X),
                };
                let cut = best.map_or(f64::INFINITY, |b| b.value);
                return match (TwoEllipses { q, r, e1, e2 }).minimum(a, b, cut, self.hint) {
                    None => false,
                    Some(found) => {
                        if let Some((_, n)) = found {
                            keep(best, self.minimum_at(p, n, at));
                        }
                        true
                    }
                };
            }
            (true, false) => s0.axes,
            (false, true) => s1.axes,
            (false, false) => None,
        };
        let (q, _) = self.linear(p);
        match ax {
            None => {
                // F = q·n + r: its minimum r − |q| is at n = −q/|q| when that is in the arc.
                let ql = q.length();
                if ql > 0.0 && arc.contains(-q) {
                    let n = -q / ql;
                    keep(best, self.minimum_at(p, n, at));
                } else if arc == Arc::Full {
                    // Two concentric discs: any direction.
                    keep(best, self.minimum_at(p, Vector::X, at));
                }
            }
            Some(ax) => {
                if best.is_some_and(|b| self.lower_bound(arc, p, &ax) > b.value) {
                    return true;
                }
                if let (Arc::Between(a, b), At::Inside(i)) = (arc, at) {
                    let cut = best.map_or(f64::INFINITY, |b| b.value);
                    if self.arc_screened(i, (a, b), p, &ax, cut) {
                        return true;
                    }
                }
                // F − r is the support function of the ellipse centred at q: its stationary
                // directions are the normals at the feet of −q. From inside the ellipse every
                // foot has F − r ≥ 0, so none beats a best value below r.
                let pl = ax.local(-q);
                let (_, r) = self.linear(p);
                let inside = (pl.x / ax.a).powi(2) + (pl.y / ax.b).powi(2) < 1.0;
                if inside && best.is_some_and(|b| b.value < r) {
                    return true;
                }
                let try_feet = |best: &mut Option<Minimum>, feet: &Feet| {
                    let mut any = false;
                    for f in feet.as_slice() {
                        let n = ax.world(f.normal);
                        if arc.contains(n) {
                            any = true;
                            keep(best, self.minimum_at(p, n, at));
                        }
                    }
                    any
                };
                // The nearest foot is the minimum over every direction: when it is in the arc,
                // it is the arc's; otherwise the arc's is at an end or a middle foot. A middle
                // foot e (multiplier t ∈ (−a², −b²), p = e + t·(eₓ/a², e_y/b²)) has
                // F − r = (e − p)·m = −t·|(eₓ/a², e_y/b²)| > b²·(1/a) = ρ_min (a ≥ b): it can
                // only beat a best value above r + ρ_min.
                let nearest_in_arc = nearest_cone_meets(arc, &ax, pl) && try_feet(best, &nearest_feet(ax.a, ax.b, pl));
                if !nearest_in_arc {
                    let rho_min = ax.a.min(ax.b).powi(2) / ax.a.max(ax.b);
                    if best.is_none_or(|b| b.value > r + rho_min) && middle_quadrant_meets(arc, &ax, pl) {
                        try_feet(best, &middle_feet(ax.a, ax.b, pl));
                    }
                }
            }
        }
        true
    }

    /// Whether arc i (ends `a`, `b`, pieces `p`, one the ellipse `ax`) surely holds no interior
    /// minimum of F below `best`.
    ///
    /// F is the support function of the Minkowski difference D, so F″ + F = ρ_D, D's radius of
    /// curvature, which on the arc is at least ρ_E,arc + r: the ellipse's smallest radius there
    /// (a²b²/k³ at the largest k on the arc, in closed form) plus the vertex's radius. F is
    /// sublinear, so on an arc of width θ < π it is at most U = max(F(a), F(b))/cos(θ/2) (or that
    /// maximum, when negative): F″ ≥ μ = ρ_E,arc + r − U. When μ ≥ 0, F is convex on the arc and
    /// its minimum is inside only if F′ < 0 at the start and > 0 at the end
    /// (F′(n) = (q + s_E(n))·n⊥, s_E the support point of the centred ellipse). Otherwise
    /// F ≥ F(m) + F′(m)x + μx²/2 about the midpoint m, |x| ≤ tan(θ/2), whose minimum is compared
    /// with `best`.
    fn arc_screened(&self, i: usize, (a, b): (Vector, Vector), p: [usize; 2], ax: &Axes, best: f64) -> bool {
        let cos = a.dot(b);
        let narrower_than_pi = cos > -1.0;
        if !narrower_than_pi || self.len < 2 {
            return false;
        }
        let ch = (0.5 * (1.0 + cos)).sqrt();
        let top = self.entries[i].value.max(self.entries[wrap(i + 1, self.len)].value);
        let (q, r) = self.linear(p);
        let upper = if top - r > 0.0 { (top - r) / ch + r } else { top };
        let major = if ax.a >= ax.b { ax.u } else { ax.w };
        let kmax = if in_arc(a, b, major) || in_arc(a, b, -major) {
            ax.a.max(ax.b)
        } else {
            ax.k(a).max(ax.k(b))
        };
        let rho = (ax.a * ax.b) * (ax.a * ax.b) / (kmax * kmax * kmax);
        let mu = rho + r - upper;
        let slope = |n: Vector| (q + ax.support(n)).dot(perp(n));
        if mu >= 0.0 {
            return slope(a) >= 0.0 || slope(b) <= 0.0;
        }
        let m = (a + b) / (2.0 * ch);
        let h = 0.5 * (b - a).length() / ch;
        let lower = self.value(p, m) - slope(m).abs() * h + 0.5 * mu * h * h;
        lower > best
    }

    /// F at direction n on the pieces `p`, as a candidate minimum.
    #[inline]
    fn minimum_at(&self, p: [usize; 2], n: Vector, at: At) -> Minimum {
        Minimum {
            value: self.value(p, n),
            normal: n,
            at,
            active: p,
        }
    }
}

/// The minimum of the centred ellipse's support function k over the directions of `arc`,
/// exact: the minor semi-axis when the arc holds the minor axis's normal (either way), else the
/// smaller end (k has no other interior minimum).
#[inline]
fn k_min(arc: Arc, ax: &Axes) -> f64 {
    let minor = if ax.a >= ax.b { ax.w } else { ax.u };
    match arc {
        Arc::Between(a, b) if !(arc.contains(minor) || arc.contains(-minor)) => ax.k(a).min(ax.k(b)),
        _ => ax.a.min(ax.b),
    }
}

/// Whether `arc` may hold the normal of the nearest foot of `pl` (a point in the ellipse's axes,
/// not on an axis): false only when it surely does not, so that the foot's Newton solve is
/// skipped on arcs it cannot change.
///
/// The nearest foot's normal is ∝ (pₓ/(a² + t), p_y/(b² + t)) with its multiplier
/// t > −min(a², b²); as t grows the ratio of its minor to its major component falls
/// monotonically, so the normal turns within p's quadrant from the minor axis (on p's side,
/// t → −min(a², b²)) to p's own direction (t → ∞). The arc misses the normal when it misses that
/// cone, widened by `CONE_MARGIN` radians each side against the foot's rounding. A point on an
/// axis (two mirrored feet) or not finite meets every arc.
fn nearest_cone_meets(arc: Arc, ax: &Axes, pl: Vector) -> bool {
    /// The widening of the cone, in radians: far above the rounding of a computed foot's normal.
    const CONE_MARGIN: f64 = 1e-9;
    let Arc::Between(a, b) = arc else { return true };
    if pl.x == 0.0 || pl.y == 0.0 || !pl.is_finite() {
        return true;
    }
    let minor = if ax.a >= ax.b {
        Vector::new(0.0, pl.y.signum())
    } else {
        Vector::new(pl.x.signum(), 0.0)
    };
    let (c1, c2) = (ax.world(minor), ax.world(pl / pl.length()));
    let (lo, hi) = if cross(c1, c2) >= 0.0 { (c1, c2) } else { (c2, c1) };
    let (lo, hi) = (lo - perp(lo) * CONE_MARGIN, hi + perp(hi) * CONE_MARGIN);
    in_arc(a, b, lo) || in_arc(a, b, hi) || in_arc(lo, hi, a)
}

/// Whether `arc` meets the quadrant of directions where the middle feet of `pl` (a point in the
/// ellipse's axes) have their normals: same sign as `pl` along the major axis, opposite sign
/// along the minor axis (the multiplier t lies between −a² and −b²: the major coordinate keeps
/// its sign, the minor one flips). A point on an axis (a sign undefined) meets every arc.
fn middle_quadrant_meets(arc: Arc, ax: &Axes, pl: Vector) -> bool {
    let Arc::Between(a, b) = arc else { return true };
    let (major, minor) = if ax.a >= ax.b { (pl.x, pl.y) } else { (pl.y, pl.x) };
    if major == 0.0 || minor == 0.0 {
        return true;
    }
    let (u_major, u_minor) = if ax.a >= ax.b { (ax.u, ax.w) } else { (ax.w, ax.u) };
    let edge1 = u_major * major.signum();
    let edge2 = u_minor * -minor.signum();
    let inside = |d: Vector| d.dot(edge1) > 0.0 && d.dot(edge2) > 0.0;
    inside(a) || inside(b) || arc.contains(edge1) || arc.contains(edge2)
}

/// `k` reduced into 0..n for k < 2n (an index one lap past the end), without a division.
#[inline]
pub(crate) fn wrap(k: usize, n: usize) -> usize {
    if k >= n {
        k - n
    } else {
        k
    }
}

/// Keeps `m` in `best` when it is lower; false when its value is not finite.
#[inline]
fn keep(best: &mut Option<Minimum>, m: Minimum) -> bool {
    if !m.value.is_finite() {
        return false;
    }
    if best.is_none_or(|b| m.value < b.value) {
        *best = Some(m);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::test_rng::Lcg;
    use core::f64::consts::PI;

    /// The screen of `nearest_cone_meets` never drops an arc holding the nearest foot's normal:
    /// the thinnest arc about the computed normal meets the cone, over random ellipses (axis
    /// ratios to 1:1000, turned), points inside and outside.
    #[test]
    fn the_nearest_foot_normal_lies_in_the_cone_that_screens_arcs() {
        let mut rng = Lcg(11);
        let mut checked = 0;
        for _ in 0..20_000 {
            let a = 10f64.powf(rng.range(-2.0, 2.0));
            let b = a * 10f64.powf(rng.range(-3.0, 3.0));
            let (s, c) = rng.range(-PI, PI).sin_cos();
            let ax = Axes {
                a,
                b,
                u: Vector::new(c, s),
                w: Vector::new(-s, c),
            };
            let r = a.max(b) * 10f64.powf(rng.range(-3.0, 1.0));
            let (ts, tc) = rng.range(-PI, PI).sin_cos();
            let pl = Vector::new(r * tc, r * ts);
            for f in nearest_feet(a, b, pl).as_slice() {
                let n = ax.world(f.normal);
                let arc = Arc::Between(n - perp(n) * 1e-12, n + perp(n) * 1e-12);
                assert!(nearest_cone_meets(arc, &ax, pl), "a {a} b {b} p {pl} normal {n}");
                checked += 1;
            }
        }
        assert!(checked >= 20_000);
    }

    /// A random ellipse (axis ratio to 1:100, turned) of size about `s`.
    fn random_axes(rng: &mut Lcg, s: f64) -> Axes {
        let a = s * rng.range(0.1, 1.0);
        let b = a * 10f64.powf(rng.range(-2.0, 0.5));
        let (sn, cs) = rng.range(-PI, PI).sin_cos();
        Axes {
            a,
            b,
            u: Vector::new(cs, sn),
            w: Vector::new(-sn, cs),
        }
    }

    /// A random arc: its start, end and width (up to a full turn less a little).
    fn random_arc(rng: &mut Lcg) -> (Vector, Vector, f64) {
        let start = rng.range(-PI, PI);
        let width = rng.range(0.01, 2.0 * PI - 0.01);
        let a = Vector::new(start.cos(), start.sin());
        let b = Vector::new((start + width).cos(), (start + width).sin());
        (a, b, width)
    }

    /// The bound that lets the walk skip an arc between two ellipses never exceeds F on the
    /// arc: random ellipses, offsets and arcs (any width), F sampled at 2,000 directions each.
    #[test]
    fn the_two_ellipse_bound_is_below_f_on_the_arc() {
        let mut rng = Lcg(5);
        let (mut s0, mut s1) = (Placed::blank(1.0), Placed::blank(-1.0));
        let mut samples = 0;
        for _ in 0..2_000 {
            let (e1, e2) = (random_axes(&mut rng, 1.0), random_axes(&mut rng, 1.0));
            let q = Vector::new(rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
            let r = rng.range(0.0, 0.3);
            // One piece each, placed by hand: the bound reads the sides' q and r only.
            s0.q[0] = q;
            s0.r[0] = r;
            s1.q[0] = Vector::ZERO;
            s1.r[0] = 0.0;
            let walk = Walk::new(&s0, &s1);
            let (a, b, width) = random_arc(&mut rng);
            let bound = walk.two_ellipse_bound(Arc::Between(a, b), [0, 0], &e1, &e2);
            let f = |n: Vector| q.dot(n) + r + e1.k(n) + e2.k(n);
            for k in 0..=2_000 {
                let t = width * k as f64 / 2_000.0;
                let n = a * t.cos() + perp(a) * t.sin();
                assert!(bound <= f(n) + 1e-12, "bound {bound} above F {} at {n}", f(n));
                samples += 1;
            }
            let _ = b;
        }
        println!("the_two_ellipse_bound_is_below_f_on_the_arc: {samples} samples");
    }

    /// The search between two ellipses on a part of the circle (as between a `CapsuleEllipse`'s
    /// half-ellipse and an ellipse) finds the arc's minimum, whether its descent's local
    /// minimum is certified at once or the branch and bound runs: against F sampled at 20,000
    /// directions refined by golden-section search, over random pairs, offsets (apart, shallow
    /// and deep) and arcs.
    #[test]
    fn the_search_on_a_part_of_the_circle_finds_its_minimum() {
        let mut rng = Lcg(9);
        let mut cases = 0;
        for _ in 0..400 {
            let (e1, e2) = (random_axes(&mut rng, 1.0), random_axes(&mut rng, 1.0));
            let reach = e1.a.max(e1.b) + e2.a.max(e2.b);
            let ang = rng.range(-PI, PI);
            let q = Vector::new(ang.cos(), ang.sin()) * reach * rng.range(0.0, 1.3);
            let te = TwoEllipses { q, r: 0.0, e1, e2 };
            let f = |t: f64, a: Vector| {
                let n = a * t.cos() + perp(a) * t.sin();
                q.dot(n) + e1.k(n) + e2.k(n)
            };
            let (a, b, width) = random_arc(&mut rng);
            let n_samples = 20_000;
            let mut best = (f64::INFINITY, 0.0);
            for k in 0..=n_samples {
                let t = width * k as f64 / n_samples as f64;
                let v = f(t, a);
                if v < best.0 {
                    best = (v, t);
                }
            }
            // Refine about the best sample (F is smooth on the arc).
            let h = width / n_samples as f64;
            let (mut lo, mut hi) = ((best.1 - h).max(0.0), (best.1 + h).min(width));
            for _ in 0..100 {
                let (m1, m2) = (lo + 0.382 * (hi - lo), hi - 0.382 * (hi - lo));
                if f(m1, a) < f(m2, a) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            let sampled = best.0.min(f(0.5 * (lo + hi), a));
            // Within the budget, an end of the arc included (its neighbourhood is discarded by
            // the end bounds when the arc's minimum is there).
            let found = te.minimum(a, b, f64::INFINITY, None).expect("within the budget");
            let (value, n) = found.expect("a minimum below +inf");
            assert!(in_arc(a, b, n), "the minimum's direction {n} is outside the arc");
            assert!(
                (value - sampled).abs() <= 1e-10 * reach,
                "search {value} sampled {sampled} (arc width {width})"
            );
            cases += 1;
        }
        println!("the_search_on_a_part_of_the_circle_finds_its_minimum: {cases} cases");
    }
}
