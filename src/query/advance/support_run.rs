//! The vertices of a polygon that can be its support point while the direction turns through a
//! small arc ([`support_run`]): the only pieces of a separation that can be its minimum over a
//! stretch of the advancement, so the only ones its steps need to bound.
//!
//! # Why the other pieces may be left out
//!
//! For a convex polygon with vertices v₀ … v_{n−1} counter-clockwise and outward edge normals
//! n₀ … n_{n−1} (nₖ the normal of the edge from vₖ to vₖ₊₁), vertex i is a support point along
//! a direction d exactly when d lies in its normal cone, the arc from n_{i−1} to nᵢ. As d turns
//! counter-clockwise from d₀, the support point stays i₀ (the support at d₀) until d passes
//! n_{i₀}, then is i₀ + 1 until it passes n_{i₀+1}, and so on; turning clockwise, it steps back
//! as d passes n_{i₀−1}, n_{i₀−2}, …. So while d stays on the arc from d₀ to d₁, the support
//! point is one of i₀ and the vertices beyond the normals that lie on the arc, a run of
//! consecutive indices; every other vertex is, along every direction of the arc, at most the
//! support value.
//!
//! The separations the advancement steps along are minima over a polygon's vertices of
//! w(u)·vᵢ plus terms common to all vertices, w(u) a direction turning with the clock: the
//! minimum is the support value along −w(u), taken by a vertex of the run for every u of the
//! stretch the arc covers. Dropping the other pieces changes neither the separation's value
//! nor the safety of a step (a step that keeps every piece of the run above the level keeps
//! their minimum, the separation, above it) and saves their evaluation at every step.
//!
//! Normals within [`SUPPORT_RUN_SLACK`] of the arc's ends count as on the arc, so that a tie
//! at d₀ or d₁ and the rounding of the directions keep both tied vertices.

use crate::numerics::math::{cross, Real, Vector};

/// Slack of the arc's ends (radians, the directions being unit): a normal within this angle of
/// an end of the arc counts as on it, so that ties and the rounding of the turning directions
/// never drop a vertex that can be the support point.
pub(super) const SUPPORT_RUN_SLACK: Real = 1e-9;

/// A cyclic run of a polygon's vertex indices: `len` of them from `start`.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(super) struct Run {
    start: usize,
    len: usize,
}

impl Run {
    /// Every vertex of a polygon of `n`.
    pub(super) fn all(n: usize) -> Run {
        Run { start: 0, len: n }
    }

    /// The run's vertices of `v` (which the run was made for), in order.
    #[inline]
    pub(super) fn of(self, v: &[Vector]) -> impl Iterator<Item = &Vector> {
        let n = v.len();
        let start = self.start.min(n);
        let end = start + self.len.min(n);
        let (head, tail) = if end <= n {
            (&v[start..end], &v[..0])
        } else {
            (&v[start..], &v[..end - n])
        };
        head.iter().chain(tail)
    }
}

/// The vertices of the convex polygon (`vertices` counter-clockwise, `normals[k]` the unit
/// outward normal of the edge from vertex k to k + 1) that are its support point along some
/// direction of the arc from the unit `d0` to the unit `d1`, turning counter-clockwise when
/// `ccw` (clockwise otherwise) through less than half a turn — the caller's guarantee, which
/// tells this arc from the one the other way round: module docs. Every vertex where the arc is
/// not below a quarter turn, the polygon has fewer than three vertices or its normals do not
/// match them, or a direction is not finite.
pub(super) fn support_run(vertices: &[Vector], normals: &[Vector], d0: Vector, d1: Vector, ccw: bool) -> Run {
    let n = vertices.len();
    let all = Run::all(n);
    // The arc from `lo` counter-clockwise to `hi`: the support walks forward from i₀ as d goes
    // from `lo` to `hi`, backward as it goes from `hi` to `lo`.
    let (lo, hi) = if ccw { (d0, d1) } else { (d1, d0) };
    // Less than half a turn from `lo` to `hi`: under a quarter turn exactly when the cosine is
    // positive (and the sine not negative: a rounding of a zero turn is taken as zero).
    let quarter = lo.dot(hi) > 0.0 && cross(lo, hi) >= -SUPPORT_RUN_SLACK;
    if n < 3 || normals.len() != n || !quarter || !(d0.is_finite() && d1.is_finite()) {
        return all;
    }
    let mut i0 = 0;
    let mut best = Real::NEG_INFINITY;
    for (i, v) in vertices.iter().enumerate() {
        let h = d0.dot(*v);
        if h > best {
            best = h;
            i0 = i;
        }
    }
    if !best.is_finite() {
        return all;
    }
    let mid = d0 + d1;
    // Whether normal k is on the arc from `from` counter-clockwise to `to` (less than a quarter
    // turn apart), ends widened by the slack.
    let on_arc = |k: usize, from: Vector, to: Vector| {
        let m = normals[k];
        cross(from, m) >= -SUPPORT_RUN_SLACK && cross(m, to) >= -SUPPORT_RUN_SLACK && m.dot(mid) > 0.0
    };
    let next = |k: usize| if k + 1 == n { 0 } else { k + 1 };
    let prev = |k: usize| if k == 0 { n - 1 } else { k - 1 };
    // Backward from i₀: the vertices beyond the normals on the arc before i₀'s cone.
    let mut start = i0;
    let mut len = 1;
    while len < n && on_arc(prev(start), lo, hi) {
        start = prev(start);
        len += 1;
    }
    // Forward from i₀.
    let mut k = i0;
    while len < n && on_arc(k, lo, hi) {
        k = next(k);
        len += 1;
    }
    Run { start, len }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::FRAC_PI_2;

    /// [`support_run`] from `d0` turning by the signed angle `turn` (less than half a turn).
    fn run_by(v: &[Vector], normals: &[Vector], d0: Vector, turn: Real) -> Run {
        let (s, c) = turn.sin_cos();
        let d1 = Vector::new(c * d0.x - s * d0.y, s * d0.x + c * d0.y);
        support_run(v, normals, d0, d1, turn >= 0.0)
    }

    /// A regular polygon of `n` vertices, counter-clockwise, with its edge normals.
    fn regular(n: usize, phase: Real) -> (Vec<Vector>, Vec<Vector>) {
        let v: Vec<Vector> = (0..n)
            .map(|i| {
                let a = phase + core::f64::consts::TAU * i as Real / n as Real;
                Vector::new(a.cos(), a.sin()) * (1.0 + 0.1 * (i % 3) as Real)
            })
            .collect();
        let normals = (0..n)
            .map(|k| {
                let e = v[(k + 1) % n] - v[k];
                Vector::new(e.y, -e.x).normalize()
            })
            .collect();
        (v, normals)
    }

    /// The index of the support vertex along `d`, by brute force.
    fn support(v: &[Vector], d: Vector) -> usize {
        (0..v.len())
            .max_by(|&i, &j| d.dot(v[i]).total_cmp(&d.dot(v[j])))
            .unwrap()
    }

    #[test]
    fn the_run_holds_the_support_vertex_of_every_direction_of_the_arc() {
        let mut checked = 0;
        for n in 3..=8 {
            for p in 0..7 {
                let (v, normals) = regular(n, 0.37 * p as Real);
                for a in 0..48 {
                    let angle = core::f64::consts::TAU * a as Real / 48.0 + 0.011;
                    let d0 = Vector::new(angle.cos(), angle.sin());
                    for turn in [-1.5, -0.7, -0.2, -1e-3, 0.0, 1e-3, 0.2, 0.7, 1.5] {
                        let run = run_by(&v, &normals, d0, turn);
                        let members: Vec<usize> = run.of(&v).map(|x| v.iter().position(|y| y == x).unwrap()).collect();
                        for s in 0..=64 {
                            let phi = angle + turn * s as Real / 64.0;
                            let i = support(&v, Vector::new(phi.cos(), phi.sin()));
                            assert!(
                                members.contains(&i),
                                "n {n} d0 {angle} turn {turn}: {i} not in {members:?}"
                            );
                            checked += 1;
                        }
                        // Not every vertex once the arc is short: the run leaves some out.
                        if turn.abs() <= 0.2 && n >= 5 {
                            assert!(run.len < n, "n {n} turn {turn}: {run:?}");
                        }
                    }
                }
            }
        }
        assert!(checked > 100_000);
    }

    #[test]
    fn a_direction_along_an_edge_normal_keeps_both_vertices_of_the_edge() {
        let (v, normals) = regular(6, 0.0);
        for (k, m) in normals.iter().enumerate() {
            for turn in [-0.1, 0.0, 0.1] {
                let run = run_by(&v, &normals, *m, turn);
                let members: Vec<&Vector> = run.of(&v).collect();
                assert!(
                    members.contains(&&v[k]) && members.contains(&&v[(k + 1) % 6]),
                    "edge {k} turn {turn}"
                );
            }
        }
    }

    #[test]
    fn a_quarter_turn_or_more_a_short_polygon_or_bad_input_takes_every_vertex() {
        let (v, normals) = regular(6, 0.0);
        assert_eq!(run_by(&v, &normals, Vector::X, FRAC_PI_2 + 1e-6), Run::all(6));
        assert_eq!(run_by(&v, &normals, Vector::X, -2.0), Run::all(6));
        assert_eq!(run_by(&v, &normals, Vector::X, 3.0), Run::all(6));
        assert_eq!(run_by(&v, &normals, Vector::X, Real::NAN), Run::all(6));
        assert_eq!(run_by(&v, &normals, Vector::new(Real::NAN, 0.0), 0.1), Run::all(6));
        assert_eq!(run_by(&v, &normals[..5], Vector::X, 0.1), Run::all(6));
        // The arc the other way round from what `ccw` says is three quarters of a turn.
        assert_eq!(support_run(&v, &normals, Vector::X, Vector::Y, false), Run::all(6));
        let (v2, n2) = (vec![Vector::ZERO, Vector::X], vec![-Vector::Y, Vector::Y]);
        assert_eq!(run_by(&v2, &n2, Vector::Y, 0.1), Run::all(2));
    }

    #[test]
    fn a_run_that_wraps_past_the_last_vertex_lists_its_vertices_in_order() {
        let v: Vec<Vector> = (0..5).map(|i| Vector::new(i as Real, 0.0)).collect();
        let run = Run { start: 3, len: 4 };
        let got: Vec<Real> = run.of(&v).map(|p| p.x).collect();
        assert_eq!(got, vec![3.0, 4.0, 0.0, 1.0]);
    }
}
