//! The signed distance of two sides at one time: the maximum over the axis θ of the gap G(θ)
//! (module docs of `frame`), exact to rounding.
//!
//! The circle of axes is cut at the kinks of either side (its faces' normals; for body 2,
//! reversed) into intervals on each of which the supports of both sides move continuously
//! (`side`), so that G is smooth there, with G_θ = −S and S_θ = G + ρ₁ + ρ₂ (S = d × u the side
//! distance, ρ the radii of curvature at the supports). At a kink G has a concave corner: S jumps
//! upwards. The maximum of G is therefore either a root of S inside an interval, or a kink where
//! S jumps from negative to positive (a face of one side against the other side's support).
//! When both supports are discs (two polygon vertices, dilated), G = (b − a)·u − r₁ − r₂ on the
//! interval: its maximum over the whole circle is at u = (b − a)/|b − a|, closed-form.
//!
//! **Separated shapes.** Where G > 0 it is concave in θ (a minimum of cosines within ±π/2 of
//! their peaks; docs/theory.md § 4), so a local maximum with G > 0 is the global one. The walk
//! starts at a given axis (the last step's), and moves towards the rising side interval by
//! interval: the closed-form peak when it lies inside the interval, else a safeguarded Newton
//! solve of S = 0 when S changes sign before the interval's end, else across the kink unless G
//! falls after it. A handful of intervals along a tracked path. Where the axis has moved far
//! since the last call across a side of many small cones (a polygon of 10⁵ vertices), the walk,
//! after 16 intervals, jumps ahead by doubling turns while G still rises (S keeps its sign
//! there: on the concave part of G, S increases with θ), the supports at each jump found by a
//! binary search of the polygon's normals, and goes on interval by interval from the last jump
//! that still rises: O(log n) jumps in place of n intervals, and the same tests decide where it
//! stops.
//!
//! **Overlapping shapes.** A local maximum with G > −(r₁ + r₂), rᵢ the smallest radii of
//! curvature, is still global: each side is a body swelled by a disc of radius rᵢ, whose gap
//! G + r₁ + r₂ is positive there (the shallow-penetration certificate of the stationary
//! distance). Deeper, two polygons take every candidate axis — each face normal and each
//! vertex–vertex direction inside its interval, which is exact — and a curve side a branch and
//! bound over θ with the stationary distance's envelope bound (G_θθ = −G − ρ₁ − ρ₂ ≤ −G, and the
//! concave kinks only lower G).

// The negated comparisons (`!(x > 0.0)`) are deliberate: they are true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::frame::{GapFrame, GapJet, GapMotion, SupportValue};
use super::side::Side;
use crate::numerics::angle::ccw_angle;
use crate::numerics::math::{cross, rotate_cs, sin_cos, Vector};
use crate::query::stationary::envelope_max;
use core::f64::consts::{FRAC_PI_2, PI, TAU};

/// Which configuration holds the maximum of G.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum Contact {
    /// Inside an interval: S = 0 (two vertices of polygons: the direction between them).
    Smooth,
    /// The face of body 1 after its feature `i` against feature `j` of body 2.
    Face1,
    /// Feature `i` of body 1 against the face of body 2 after its feature `j`.
    Face2,
    /// The faces after `i` and after `j`, parallel.
    Faces,
}

/// The maximum of the gap at one time.
#[derive(Copy, Clone, Debug)]
pub(crate) struct GapMax {
    /// The signed distance (negative: minus the penetration depth).
    pub d: f64,
    /// The world axis (unit, from body 1 to body 2) of the maximum.
    pub u: Vector,
    /// Features of body 1 and body 2 (for a face: the feature before it).
    pub i: usize,
    pub j: usize,
    /// The configuration.
    pub kind: Contact,
    /// G and its derivatives at the axis, with the supports of i and j.
    pub jet: GapJet,
}

/// Two sides and their motions: the exact distance at any time.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Pair<'a> {
    pub sides: [Side<'a>; 2],
    pub motion: GapMotion,
}

/// Signed angle from unit `a` to unit `b`, in (−π, π].
#[inline]
fn angle(a: Vector, b: Vector) -> f64 {
    cross(a, b).atan2(a.dot(b))
}

/// `u` turned by `x` radians.
#[inline]
fn turn(u: Vector, x: f64) -> Vector {
    let (s, c) = sin_cos(x);
    rotate_cs(c, s, u)
}

/// The signed angles from `u` to the lower and upper boundaries of the cone [lo, hi] of the
/// given width that holds it: (≤ 0, ≥ 0). A `u` a rounding error outside the cone is taken at
/// its nearer boundary. (Measured from `lo` counter-clockwise, so that a half-plane cone, whose
/// boundaries are opposite, or a whole-circle one, is never taken as empty.)
#[inline]
fn cone_offsets(u: Vector, lo: Vector, width: f64) -> (f64, f64) {
    let mut off = ccw_angle(lo, u);
    if off > width {
        off = if off > 0.5 * (width + TAU) { 0.0 } else { width };
    }
    (-off, width - off)
}

/// How far (radians) a vertex–vertex direction may lie outside its interval and still be taken
/// as inside it (rounding of the cone boundaries).
const CONE_SLACK: f64 = 1e-15;
/// A feature whose cone is the whole circle (a curve with no face) is walked in intervals of at
/// most this half-width around the axis (not kinks: the walk goes on with the same feature).
const FREE_HALF_WIDTH: f64 = FRAC_PI_2;
/// The Newton solve of S = 0 inside an interval stops at |S| below this fraction of the size …
const SIDE_TOL: f64 = 1e-14;
/// … or a bracket narrower than this (radians) …
const ANGLE_TOL: f64 = 1e-15;
/// … or after this many iterations.
const NEWTON_STEPS: usize = 60;
/// After this many intervals the walk tries to jump ahead ([`Pair::gallop`]): every ordinary
/// walk (a handful of intervals) is left as it was, and a walk across the tiny cones of a
/// polygon of 10⁵ vertices (thousands of intervals when the axis has moved far since the last
/// call) takes O(log n) jumps instead.
const GALLOP_AFTER: usize = 16;
#[cfg(test)]
thread_local! {
    /// The intervals the walks of this thread have visited (tests read it).
    pub(crate) static WALK_INTERVALS: core::cell::Cell<usize> = const { core::cell::Cell::new(0) };
}
/// The smallest first jump of [`Pair::gallop`] (radians): degenerate cones of width 0.
const GALLOP_MIN_STEP: f64 = 1e-9;
/// Directions the branch and bound of a deep penetration starts from.
const SEEDS: usize = 32;
/// Capacity of the branch and bound's node stack (depth-first over sorted nodes).
const NODE_STACK: usize = 96;
/// The branch and bound drops an interval whose bound is within this fraction of the size of
/// the best value, or narrower than [`ANGLE_TOL`].
const BOUND_TOL: f64 = 1e-13;
/// The branch and bound evaluates at most this many nodes (then its best value, a lower bound
/// on the distance, stands: only absurd input — a rotation centre 1e20 sizes away — gets there).
const MAX_NODES: usize = 4096;

/// What the walk knows at one axis: the support of each side (world point, body point, radius
/// of curvature, body direction).
#[derive(Copy, Clone, Debug)]
struct Supports {
    x: [Vector; 2],
    p: [Vector; 2],
    rho: [f64; 2],
    m: [Vector; 2],
}

impl Supports {
    /// G, S and S_θ at the axis `u`.
    #[inline]
    fn gap(&self, u: Vector) -> (f64, f64, f64) {
        let d = self.x[1] - self.x[0];
        let g = d.dot(u);
        (g, cross(d, u), g + self.rho[0] + self.rho[1])
    }
}

/// Where a support is taken on its feature: inside its cone, or at one of its boundaries.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum At {
    Inside,
    Lower,
    Upper,
}

impl<'a> Pair<'a> {
    /// The body direction of side `k` for the world axis u (body 2's support is along −u).
    #[inline]
    fn body_dir(&self, fr: &GapFrame, k: usize, u: Vector) -> Vector {
        fr.to_body(k, if k == 0 { u } else { -u })
    }

    /// The world axis for which side `k` has the body direction `m`.
    #[inline]
    fn axis(&self, fr: &GapFrame, k: usize, m: Vector) -> Vector {
        let w = fr.to_world(k, m);
        if k == 0 {
            w
        } else {
            -w
        }
    }

    /// The supports of features (i, j) at the axis u; `at` says where each is taken.
    #[inline]
    fn supports(&self, fr: &GapFrame, u: Vector, f: [usize; 2], at: [At; 2]) -> Supports {
        let mut s = Supports {
            x: [Vector::ZERO; 2],
            p: [Vector::ZERO; 2],
            rho: [0.0; 2],
            m: [Vector::ZERO; 2],
        };
        for k in 0..2 {
            let m = self.body_dir(fr, k, u);
            let side = &self.sides[k];
            let (p, rho) = match (at[k], side) {
                (At::Inside, _) | (_, Side::Poly(_)) => side.support(f[k], m),
                (At::Upper, Side::Curve(_)) => (side.face_after(f[k]).0, 0.0),
                (At::Lower, Side::Curve(_)) => (side.face_after(side.prev(f[k])).1, 0.0),
            };
            s.x[k] = fr.point(&self.motion, k, p);
            s.p[k] = p;
            s.rho[k] = rho;
            s.m[k] = m;
        }
        s
    }

    /// The features of both sides at the axis u, from `hint`.
    pub(crate) fn features(&self, fr: &GapFrame, u: Vector, hint: (usize, usize)) -> (usize, usize) {
        (
            self.sides[0].feature_of(self.body_dir(fr, 0, u), hint.0),
            self.sides[1].feature_of(self.body_dir(fr, 1, u), hint.1),
        )
    }

    /// The offsets (≤ 0, ≥ 0) of feature `f` of side `k`'s interval around the axis u, and
    /// whether its boundaries are kinks.
    #[inline]
    fn offsets(&self, fr: &GapFrame, k: usize, f: usize, u: Vector) -> (f64, f64, bool) {
        match self.sides[k].cone(f) {
            Some((lo, _, width)) => {
                let (a, b) = cone_offsets(u, self.axis(fr, k, lo), width);
                (a, b, true)
            }
            None => (-FREE_HALF_WIDTH, FREE_HALF_WIDTH, false),
        }
    }

    /// The maximum of the gap at the frame's time, walking from the axis `u0` with the feature
    /// hint `hint` (module docs). `None` only for non-finite input.
    pub(crate) fn max_gap(&self, fr: &GapFrame, u0: Vector, hint: (usize, usize)) -> Option<GapMax> {
        let found = self.walk(fr, u0, hint);
        let certified =
            |g: &(Vector, usize, usize, Contact, f64)| g.4 > -(self.sides[0].min_radius() + self.sides[1].min_radius());
        let (u, i, j, kind, d) = match found {
            Some(w) if certified(&w) => w,
            _ => match self.sides {
                [Side::Poly(_), Side::Poly(_)] => self.exhaustive(fr)?,
                _ => self.branch_and_bound(fr, found)?,
            },
        };
        if !(d.is_finite() && u.is_finite()) {
            return None;
        }
        let jet = self.jet(fr, u, i, j, kind);
        Some(GapMax {
            d,
            u,
            i,
            j,
            kind,
            jet: GapJet { g: d, ..jet },
        })
    }

    /// The walk of the module docs: (axis, i, j, configuration, distance), or `None` when it
    /// does not settle (only with overlapping shapes or rounding).
    fn walk(&self, fr: &GapFrame, u0: Vector, hint: (usize, usize)) -> Option<(Vector, usize, usize, Contact, f64)> {
        let [s1, s2] = self.sides;
        let size = s1.radius_about(Vector::ZERO).max(s2.radius_about(Vector::ZERO));
        let mut u = u0;
        let (mut i, mut j) = self.features(fr, u, hint);
        for steps in 0..2 * (s1.features() + s2.features()) + 8 {
            #[cfg(test)]
            WALK_INTERVALS.with(|c| c.set(c.get() + 1));
            let (lo1, hi1, k1) = self.offsets(fr, 0, i, u);
            let (lo2, hi2, k2) = self.offsets(fr, 1, j, u);
            let (o_lo, o_hi) = (lo1.max(lo2), hi1.min(hi2));
            // Which way G rises, and whether its peak lies inside the interval.
            let rising_up = match (s1.disc(i), s2.disc(j)) {
                (Some((a, ra)), Some((b, rb))) => {
                    let w = fr.point(&self.motion, 1, b) - fr.point(&self.motion, 0, a);
                    let len = w.length();
                    if !(len > 0.0) {
                        return None;
                    }
                    let o_w = angle(u, w / len);
                    if o_w >= o_lo - CONE_SLACK && o_w <= o_hi + CONE_SLACK {
                        return Some((w / len, i, j, Contact::Smooth, len - ra - rb));
                    }
                    o_w > o_hi
                }
                _ => {
                    // At a cone boundary the support is the one of this feature's side of it.
                    let here = |lo: f64, hi: f64, kink: bool| match (kink, lo == 0.0, hi == 0.0) {
                        (true, true, false) => At::Lower,
                        (true, false, true) => At::Upper,
                        _ => At::Inside,
                    };
                    let s = self.supports(fr, u, [i, j], [here(lo1, hi1, k1), here(lo2, hi2, k2)]);
                    let (g, side, _) = s.gap(u);
                    if side.abs() <= SIDE_TOL * size {
                        return Some((u, i, j, Contact::Smooth, g));
                    }
                    let up = side < 0.0;
                    let o_b = if up { o_hi } else { o_lo };
                    let at = if up { At::Upper } else { At::Lower };
                    let ends = [
                        if (if up { hi1 } else { lo1 }) == o_b && k1 {
                            at
                        } else {
                            At::Inside
                        },
                        if (if up { hi2 } else { lo2 }) == o_b && k2 {
                            at
                        } else {
                            At::Inside
                        },
                    ];
                    let kappa = turn(u, o_b);
                    let s_b = if o_b == 0.0 {
                        side
                    } else {
                        self.supports(fr, kappa, [i, j], ends).gap(kappa).1
                    };
                    if o_b != 0.0 && ((up && s_b >= 0.0) || (!up && s_b <= 0.0)) {
                        let (lo, hi) = if up { (0.0, o_b) } else { (o_b, 0.0) };
                        let (x, g) = self.newton(fr, u, lo, hi, [i, j], size);
                        return Some((turn(u, x), i, j, Contact::Smooth, g));
                    }
                    up
                }
            };
            // A long walk (a side of many small cones, an axis far from the last one): ahead
            // by doubling jumps while G still rises, then on interval by interval.
            if steps >= GALLOP_AFTER {
                if let Some((ug, ig, jg)) = self.gallop(fr, u, (i, j), o_hi - o_lo, rising_up) {
                    u = ug;
                    (i, j) = (ig, jg);
                    continue;
                }
            }
            // Cross to the boundary on the rising side: a kink of either side, or (a curve with
            // no face) a free boundary where the walk goes on with the same features.
            let (o_b, on1, on2) = if rising_up {
                (o_hi, k1 && hi1 <= hi2, k2 && hi2 <= hi1)
            } else {
                (o_lo, k1 && lo1 >= lo2, k2 && lo2 >= lo1)
            };
            let kappa = turn(u, o_b);
            let step = |side: &Side, f: usize, on: bool| match (on, rising_up) {
                (false, _) => f,
                (true, true) => side.next(f),
                (true, false) => side.prev(f),
            };
            let (ni, nj) = (step(&s1, i, on1), step(&s2, j, on2));
            if !(on1 || on2) {
                u = kappa;
                continue;
            }
            // Does G fall beyond the kink? S just past it, on the new features.
            let past = if rising_up { At::Lower } else { At::Upper };
            let ends = [if on1 { past } else { At::Inside }, if on2 { past } else { At::Inside }];
            let (g_next, s_next, _) = self.supports(fr, kappa, [ni, nj], ends).gap(kappa);
            let falls = if rising_up { s_next >= 0.0 } else { s_next <= 0.0 };
            if falls {
                let (fi, fj) = if rising_up { (i, j) } else { (ni, nj) };
                let kind = match (on1, on2) {
                    (true, true) => Contact::Faces,
                    (true, false) => Contact::Face1,
                    _ => Contact::Face2,
                };
                let (ki, kj) = match kind {
                    Contact::Face1 => (fi, j),
                    Contact::Face2 => (i, fj),
                    _ => (fi, fj),
                };
                return Some((kappa, ki, kj, kind, g_next));
            }
            u = kappa;
            (i, j) = (ni, nj);
        }
        None
    }

    /// The furthest axis ahead of `u` on the rising side (`up`: counter-clockwise) at which G
    /// still rises (S < 0 going up, S > 0 going down), among the turns 2w, 4w, 8w, … up to π/2
    /// (w the width of the current interval, at least [`GALLOP_MIN_STEP`]), with its features;
    /// `None` when G no longer rises two widths ahead. Only where the walk goes on from: the
    /// walk's own tests at the axis it ends on decide the maximum (and the certificate of
    /// [`Pair::max_gap`] whether it is global), so a jump changes which intervals it visits,
    /// not the maximum it finds (to rounding; of two flat sides in contact, the witnesses may
    /// be another pair on the same faces).
    fn gallop(
        &self,
        fr: &GapFrame,
        u: Vector,
        f: (usize, usize),
        width: f64,
        up: bool,
    ) -> Option<(Vector, usize, usize)> {
        let sign = if up { 1.0 } else { -1.0 };
        let mut best = None;
        let mut hint = f;
        let mut step = (2.0 * width).max(GALLOP_MIN_STEP);
        while step <= FRAC_PI_2 {
            let kappa = turn(u, sign * step);
            let (i, j) = (
                self.sides[0].feature_far(self.body_dir(fr, 0, kappa), hint.0),
                self.sides[1].feature_far(self.body_dir(fr, 1, kappa), hint.1),
            );
            let (_, side, _) = self.supports(fr, kappa, [i, j], [At::Inside; 2]).gap(kappa);
            let rises = if up { side < 0.0 } else { side > 0.0 };
            if !rises {
                break;
            }
            best = Some((kappa, i, j));
            hint = (i, j);
            step *= 2.0;
        }
        best
    }

    /// The root of S on the interval [u + lo, u + hi] of features f (S(lo) < 0 < S(hi)):
    /// safeguarded Newton (S_θ = G + ρ₁ + ρ₂ > 0 where G > −ρ₁ − ρ₂), bisection when a step leaves
    /// the bracket or does not halve |S|. (offset, G) at the root.
    fn newton(&self, fr: &GapFrame, u: Vector, mut lo: f64, mut hi: f64, f: [usize; 2], size: f64) -> (f64, f64) {
        let mut x = 0.5 * (lo + hi);
        let mut last = f64::INFINITY;
        let mut best = (x, f64::NEG_INFINITY);
        for _ in 0..NEWTON_STEPS {
            let ux = turn(u, x);
            let (g, s, s_th) = self.supports(fr, ux, f, [At::Inside; 2]).gap(ux);
            if g > best.1 {
                best = (x, g);
            }
            if s.abs() <= SIDE_TOL * size || hi - lo <= ANGLE_TOL {
                return (x, g);
            }
            if s < 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            let newton = x - s / s_th;
            x = if s_th > 0.0 && newton > lo && newton < hi && s.abs() <= 0.5 * last {
                newton
            } else {
                0.5 * (lo + hi)
            };
            last = s.abs();
        }
        best
    }

    /// Every candidate axis of two polygons (module docs): each face normal and each
    /// vertex–vertex direction inside both vertices' cones. Exact whether they overlap or not.
    ///
    /// O(n + m) for polygons of n and m vertices: the kinks of each side are taken in
    /// counter-clockwise order, and the other side's feature at each is found by hill climbing
    /// from the one at the previous kink (the axis turns once round, and so does the climb);
    /// the vertex pairs are those whose cones overlap — for each vertex of side 1, the features
    /// of side 2 from the one at its cone's lower boundary to the one at its upper boundary
    /// (and one more each way, for cones that meet only within [`CONE_SLACK`]), again by
    /// climbing from the previous vertex's. (Trying every face against a fresh climb and every
    /// vertex pair cost n·(n + m): 0.23 s for a polygon of 30,000 vertices against a box,
    /// 2.5 s at 100,000; issue 32.)
    fn exhaustive(&self, fr: &GapFrame) -> Option<(Vector, usize, usize, Contact, f64)> {
        let [s1, s2] = self.sides;
        let mut best: Option<(Vector, usize, usize, Contact, f64)> = None;
        let mut consider = |cand: (Vector, usize, usize, Contact, f64)| {
            if best.is_none_or(|b| cand.4 > b.4) {
                best = Some(cand);
            }
        };
        for k in 0..2 {
            let mut hint = (0, 0);
            for e in 0..self.sides[k].features() {
                // The kink after feature e of side k.
                let (_, hi, _) = self.sides[k].cone(e)?;
                let u = self.axis(fr, k, hi);
                let (i, j) = self.features(fr, u, hint);
                hint = (i, j);
                let (i, j) = if k == 0 { (e, j) } else { (i, e) };
                let at = if k == 0 {
                    [At::Upper, At::Inside]
                } else {
                    [At::Inside, At::Upper]
                };
                let (g, _, _) = self.supports(fr, u, [i, j], at).gap(u);
                if !g.is_finite() {
                    return None;
                }
                consider((u, i, j, if k == 0 { Contact::Face1 } else { Contact::Face2 }, g));
            }
        }
        let mut j_lo = 0;
        for i in 0..s1.features() {
            let Some((a, ra)) = s1.disc(i) else {
                continue;
            };
            let (lo, hi, _) = s1.cone(i)?;
            j_lo = s2.feature_of(self.body_dir(fr, 1, self.axis(fr, 0, lo)), j_lo);
            let j_hi = s2.feature_of(self.body_dir(fr, 1, self.axis(fr, 0, hi)), j_lo);
            // From the one before j_lo to the one after j_hi, counter-clockwise (at most all).
            let n2 = s2.features();
            let count = ((j_hi + n2 - j_lo) % n2 + 3).min(n2);
            let mut j = s2.prev(j_lo);
            for _ in 0..count {
                if let Some((b, rb)) = s2.disc(j) {
                    let w = fr.point(&self.motion, 1, b) - fr.point(&self.motion, 0, a);
                    let len = w.length();
                    if len > 0.0 {
                        let u = w / len;
                        if self.in_cone(fr, 0, i, u) && self.in_cone(fr, 1, j, u) {
                            consider((u, i, j, Contact::Smooth, len - ra - rb));
                        }
                    }
                }
                j = s2.next(j);
            }
        }
        best
    }

    /// Whether the axis u lies in the cone of feature `f` of side `k` (to [`CONE_SLACK`]).
    fn in_cone(&self, fr: &GapFrame, k: usize, f: usize, u: Vector) -> bool {
        match self.sides[k].cone(f) {
            Some((lo, _, width)) => ccw_angle(self.axis(fr, k, lo), u) <= width + CONE_SLACK,
            None => true,
        }
    }

    /// G and its slope −S at the axis u (features found from scratch): a node of the branch
    /// and bound.
    fn node(&self, fr: &GapFrame, theta: f64) -> (f64, f64, usize, usize) {
        let u = Vector::new(theta.cos(), theta.sin());
        let (i, j) = self.features(fr, u, (0, 0));
        let (g, s, _) = self.supports(fr, u, [i, j], [At::Inside; 2]).gap(u);
        (g, -s, i, j)
    }

    /// The global maximum over θ by branch and bound (module docs), seeded with the walk's
    /// answer when there is one: (axis, i, j, configuration, distance).
    fn branch_and_bound(
        &self,
        fr: &GapFrame,
        seed: Option<(Vector, usize, usize, Contact, f64)>,
    ) -> Option<(Vector, usize, usize, Contact, f64)> {
        let [s1, s2] = self.sides;
        let size = s1.radius_about(Vector::ZERO).max(s2.radius_about(Vector::ZERO));
        // |G_θ| = |S| is at most the distance of the support points: the radii plus the distance
        // of the local origins.
        let origins = fr.point(&self.motion, 1, Vector::ZERO) - fr.point(&self.motion, 0, Vector::ZERO);
        let lip = s1.radius_about(Vector::ZERO) + s2.radius_about(Vector::ZERO) + origins.length();
        let mut best = seed;
        let consider =
            |best: &mut Option<(Vector, usize, usize, Contact, f64)>, theta: f64, n: &(f64, f64, usize, usize)| {
                if best.is_none_or(|b| n.0 > b.4) {
                    *best = Some((Vector::new(theta.cos(), theta.sin()), n.2, n.3, Contact::Smooth, n.0));
                }
            };
        let mut nodes = [(0.0, (0.0, 0.0, 0, 0)); NODE_STACK];
        let mut n = 0;
        for k in 0..=SEEDS {
            let th = -PI + TAU * k as f64 / SEEDS as f64;
            let node = if k == SEEDS { nodes[0].1 } else { self.node(fr, th) };
            if !(node.0.is_finite() && node.1.is_finite()) {
                return None;
            }
            consider(&mut best, th, &node);
            nodes[n] = (th, node);
            n += 1;
        }
        let mut evaluated = SEEDS;
        while n >= 2 && evaluated < MAX_NODES {
            let (a, b) = (nodes[n - 2], nodes[n - 1]);
            let best_v = best.map_or(f64::NEG_INFINITY, |b| b.4);
            let delta = b.0 - a.0;
            let m = (-(a.1 .0 + b.1 .0) * 0.5 + lip * delta * 0.5).max(0.0);
            let ub = envelope_max(a.1 .0, a.1 .1, b.1 .0, b.1 .1, m, delta);
            if ub <= best_v + BOUND_TOL * size || delta < ANGLE_TOL || n == NODE_STACK {
                n -= 1;
                continue;
            }
            let mid = 0.5 * (a.0 + b.0);
            let node = self.node(fr, mid);
            evaluated += 1;
            if !(node.0.is_finite() && node.1.is_finite()) {
                return None;
            }
            consider(&mut best, mid, &node);
            nodes[n - 1] = (mid, node);
            nodes[n] = b;
            n += 1;
        }
        best
    }

    /// G's jet at the axis u with features i (body 1) and j (body 2); at a kink the face side's
    /// support is the face's end before it (its terms cancel in the rates along the kink).
    fn jet(&self, fr: &GapFrame, u: Vector, i: usize, j: usize, kind: Contact) -> GapJet {
        let at = match kind {
            Contact::Smooth => [At::Inside; 2],
            Contact::Face1 => [At::Upper, At::Inside],
            Contact::Face2 => [At::Inside, At::Upper],
            Contact::Faces => [At::Upper; 2],
        };
        let s = self.supports(fr, u, [i, j], at);
        let v1 = SupportValue::at(s.p[0], s.rho[0], s.m[0], self.motion.centre[0]);
        let v2 = SupportValue::at(s.p[1], s.rho[1], s.m[1], self.motion.centre[1]);
        GapJet::new(&self.motion, fr, u, &v1, &v2)
    }

    /// D' and D'' at a maximum: along the kink's body for a face (its normal turns with it),
    /// along the moving maximum otherwise.
    pub(crate) fn rates(&self, at: &GapMax) -> (f64, f64) {
        let rate = match at.kind {
            Contact::Smooth => None,
            Contact::Face1 | Contact::Faces => Some(self.motion.omega[0]),
            Contact::Face2 => Some(self.motion.omega[1]),
        };
        at.jet.distance_rates(rate)
    }

    /// The witness points (each in its body's frame) of the maximum `at`: the support points at
    /// a smooth maximum; for a face, the point of the face opposite the other side's support
    /// point (clamped to the face).
    pub(crate) fn witnesses(&self, fr: &GapFrame, at: &GapMax) -> (Vector, Vector) {
        let att = match at.kind {
            Contact::Smooth => [At::Inside; 2],
            Contact::Face1 => [At::Upper, At::Inside],
            Contact::Face2 => [At::Inside, At::Upper],
            Contact::Faces => [At::Upper; 2],
        };
        let s = self.supports(fr, at.u, [at.i, at.j], att);
        let mo = &self.motion;
        // The point of side k's face after feature f nearest to the world point x.
        let on_face = |k: usize, f: usize, x: Vector| {
            let (a, b, _) = self.sides[k].face_after(f);
            let x = if k == 0 { x - fr.dc } else { x };
            let q = fr.to_body(k, x) + mo.centre[k];
            let d = b - a;
            let l2 = d.length_squared();
            let t = if l2 > 0.0 {
                ((q - a).dot(d) / l2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            a + d * t
        };
        match at.kind {
            Contact::Smooth => (s.p[0], s.p[1]),
            Contact::Face1 => (on_face(0, at.i, s.x[1]), s.p[1]),
            Contact::Face2 => (s.p[0], on_face(1, at.j, s.x[0])),
            Contact::Faces => {
                let (a2, b2, _) = self.sides[1].face_after(at.j);
                let mid = fr.point(mo, 1, (a2 + b2) * 0.5);
                let w1 = on_face(0, at.i, mid);
                let w2 = on_face(1, at.j, fr.point(mo, 0, w1));
                (w1, w2)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::math::{unit, Pose};
    use crate::query::gap::PolySide;
    use crate::{ConvexCurve, RoundedPolygon};
    use parry2d_f64::query::NonlinearRigidMotion;

    impl Pair<'_> {
        /// The scan [`Pair::exhaustive`] replaced (issue 32): every face against a fresh climb,
        /// every vertex pair — n·(n + m).
        fn every_candidate(&self, fr: &GapFrame) -> f64 {
            let [s1, s2] = self.sides;
            let mut best = f64::NEG_INFINITY;
            for k in 0..2 {
                for e in 0..self.sides[k].features() {
                    let (_, hi, _) = self.sides[k].cone(e).expect("a polygon");
                    let u = self.axis(fr, k, hi);
                    let (i, j) = self.features(fr, u, (0, 0));
                    let (f, at) = if k == 0 {
                        ([e, j], [At::Upper, At::Inside])
                    } else {
                        ([i, e], [At::Inside, At::Upper])
                    };
                    best = best.max(self.supports(fr, u, f, at).gap(u).0);
                }
            }
            for i in 0..s1.features() {
                for j in 0..s2.features() {
                    let ((a, ra), (b, rb)) = (s1.disc(i).expect("vertex"), s2.disc(j).expect("vertex"));
                    let w = fr.point(&self.motion, 1, b) - fr.point(&self.motion, 0, a);
                    let len = w.length();
                    if len > 0.0 && self.in_cone(fr, 0, i, w / len) && self.in_cone(fr, 1, j, w / len) {
                        best = best.max(len - ra - rb);
                    }
                }
            }
            best
        }
    }

    /// The merged sweep of [`Pair::exhaustive`] finds the same maximum as the scan of every face
    /// and every vertex pair it replaced, to 4 ulps of the size (to the bit but where faces tie):
    /// random polygons of 2 to 200 vertices, overlapping deeply, coincident, concentric or apart.
    #[test]
    fn exhaustive_sweep_equals_the_scan_of_every_candidate() {
        let mut seed = 0x32u64;
        let mut next = move || {
            seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = seed;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        };
        let polygon = |next: &mut dyn FnMut() -> f64| {
            let n = [2, 3, 4, 5, 8, 17, 64, 200][(next() * 8.0) as usize];
            let r = if next() < 0.3 { 0.0 } else { 0.3 * next() };
            let rad = 0.2 + next();
            let squash = 0.2 + 0.8 * next();
            let verts: Vec<Vector> = if n == 2 {
                vec![-unit(next() * 3.0) * rad, unit(next() * 3.0) * rad]
            } else if next() < 0.3 {
                (0..n).map(|i| unit(TAU * i as f64 / n as f64) * rad).collect()
            } else {
                (0..n)
                    .map(|i| {
                        let p = unit((i as f64 + 0.8 * next()) * TAU / n as f64) * rad;
                        Vector::new(p.x, squash * p.y)
                    })
                    .collect()
            };
            RoundedPolygon::from_core_unchecked(verts, r)
        };
        fn side(p: &RoundedPolygon) -> Side<'_> {
            Side::Poly(PolySide::new(p.vertices(), p.edge_normals(), p.corner_radius()).expect("a polygon"))
        }
        let (mut checked, mut exact) = (0, 0);
        for case in 0..3000 {
            let a = polygon(&mut next);
            let b = if case % 5 == 0 { a.clone() } else { polygon(&mut next) };
            let pose = match case % 5 {
                0 | 1 => Pose::IDENTITY,
                2 => Pose::new(Vector::ZERO, next() * TAU),
                _ => Pose::new(unit(next() * TAU) * (2.5 * next()), next() * TAU),
            };
            let pair = Pair {
                sides: [side(&a), side(&b)],
                motion: GapMotion::new(
                    &NonlinearRigidMotion::identity(),
                    &NonlinearRigidMotion::constant_position(pose),
                ),
            };
            let fr = pair.motion.frame(0.0);
            let fast = pair.exhaustive(&fr).expect("finite").4;
            let every = pair.every_candidate(&fr);
            // Where two candidates tie (parallel faces: coincident or concentric polygons) the
            // climbs may stop at the other vertex of the tie: the same gap to rounding.
            let size = a.bounding_radius().max(b.bounding_radius());
            assert!(
                (fast - every).abs() <= 4.0 * f64::EPSILON * size,
                "case {case}: {fast} vs {every}"
            );
            exact += usize::from(fast.to_bits() == every.to_bits());
            checked += 1;
        }
        println!("exhaustive sweep: {checked} pairs, {exact} to the bit");
        assert_eq!(checked, 3000);
    }
}
