//! The Minkowski difference of two convex polygons, as a polygon that remembers where each of
//! its vertices comes from.
//!
//! For convex polygons T and P (P placed in T's frame), T ⊖ P = {a − b : a ∈ T, b ∈ P} is the
//! convex polygon whose support function is h_T(n) + h_P(−n): its edge normals are T's and the
//! negated normals of P, merged counter-clockwise, and its vertex between two consecutive
//! merged normals is the difference of T's and P's support vertices there — the walk of the
//! contact query ([`super::walk`]) with P as its second side. A body of core P whose origin is
//! at x overlaps T exactly when x lies in T ⊖ P: a body that translates without turning meets
//! T when the straight path of its origin enters T ⊖ P (dilated by both radii), which is how
//! `dispatcher::disc_cast` casts it in closed form.

use super::side::{polygon_is_walkable, MAX_BREAKPOINTS};
use super::walk::{first_breakpoints, for_each_merged, wrap};
use crate::numerics::math::Vector;

/// The most vertices a difference has: both polygons' edges.
pub(crate) const MAX_DIFFERENCE: usize = 2 * MAX_BREAKPOINTS;

/// T ⊖ P (module docs): `len` vertices, counter-clockwise, edge i from vertex i to vertex i + 1
/// with outward unit normal `normals[i]`; vertex i is the difference of T's vertex `from[i].0`
/// and P's vertex `from[i].1`, and edge i is an edge of T (P's vertex the same at both ends) or
/// of P, negated (`of_t[i]`). Built in place ([`difference`]): it is a kilobyte.
#[derive(Clone, Debug)]
pub(crate) struct Difference {
    pub len: usize,
    /// One more than the vertices: the merge writes each vertex one place on (module code).
    pub vertices: [Vector; MAX_DIFFERENCE + 1],
    pub normals: [Vector; MAX_DIFFERENCE],
    /// The indices in T and in P of the two vertices whose difference is vertex i.
    pub from: [(u8, u8); MAX_DIFFERENCE + 1],
    /// Whether edge i is an edge of T (else of P).
    pub of_t: [bool; MAX_DIFFERENCE],
}

impl Difference {
    /// A difference with no vertex yet.
    pub(crate) fn blank() -> Self {
        Difference {
            len: 0,
            vertices: [Vector::ZERO; MAX_DIFFERENCE + 1],
            normals: [Vector::X; MAX_DIFFERENCE],
            from: [(0, 0); MAX_DIFFERENCE + 1],
            of_t: [false; MAX_DIFFERENCE],
        }
    }
}

/// Fills `d` with T ⊖ P for T a convex polygon (counter-clockwise vertices and the outward
/// normals of its edges vᵢ → vᵢ₊₁; two vertices and two opposite normals for a segment) or a
/// point (one vertex, no normal), and P a convex polygon or a segment in T's frame. False, `d`
/// unspecified, where the contact query's walk would refuse a polygon (more than
/// [`MAX_BREAKPOINTS`] vertices, normals that do not turn strictly), or a vertex is not finite.
pub(crate) fn difference(
    d: &mut Difference,
    t_vertices: &[Vector],
    t_normals: &[Vector],
    p_vertices: &[Vector],
    p_normals: &[Vector],
) -> bool {
    let t_point = t_vertices.len() == 1 && t_normals.is_empty();
    if !(t_point || polygon_is_walkable(t_vertices, t_normals)) || !polygon_is_walkable(p_vertices, p_normals) {
        return false;
    }
    let lens = [t_normals.len(), p_normals.len()];
    let mut sides = [[Vector::X; MAX_BREAKPOINTS]; 2];
    sides[0][..lens[0]].copy_from_slice(t_normals);
    for (k, n) in p_normals.iter().enumerate() {
        sides[1][k] = -*n;
    }
    let start = if lens[0] > 0 { sides[0][0] } else { sides[1][0] };
    let (first, halves) = first_breakpoints(start, [&sides[0], &sides[1]], lens);
    // Piece k (after breakpoint k) is vertex k + 1; a point has its one vertex.
    let vertex = |s: usize, piece: usize| if lens[s] == 0 { 0 } else { wrap(piece + 1, lens[s]) };
    let before = |s: usize, k: usize| if k == 0 { lens[s].max(1) - 1 } else { k - 1 };
    let mut active = [before(0, first[0]), before(1, first[1])];
    d.len = 0;
    // Edge i runs from W_{i−1} to W_i, W_i the vertex after merged breakpoint i: vertex i is
    // W_{i−1}, so W_i is written at i + 1 and the last moved to 0.
    for_each_merged(first, &halves, [&sides[0], &sides[1]], lens, |side, k| {
        active[side] = k;
        let (i, j) = (vertex(0, active[0]), vertex(1, active[1]));
        d.normals[d.len] = sides[side][k];
        d.of_t[d.len] = side == 0;
        d.len += 1;
        d.vertices[d.len] = t_vertices[i] - p_vertices[j];
        d.from[d.len] = (i as u8, j as u8);
    });
    d.vertices[0] = d.vertices[d.len];
    d.from[0] = d.from[d.len];
    d.vertices[..d.len].iter().all(|v| v.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::math::{cross, perp};
    use crate::numerics::test_rng::Lcg;
    use core::f64::consts::PI;

    /// A random convex polygon of `n` vertices about `c` (counter-clockwise) and its normals.
    fn polygon(rng: &mut Lcg, n: usize, c: Vector, size: f64) -> (Vec<Vector>, Vec<Vector>) {
        let mut angles: Vec<f64> = (0..n).map(|_| rng.range(0.0, 2.0 * PI)).collect();
        angles.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let v: Vec<Vector> = angles
            .iter()
            .map(|a| c + Vector::new(a.cos(), a.sin()) * size)
            .collect();
        let normals = (0..n).map(|i| -perp((v[(i + 1) % n] - v[i]).normalize())).collect();
        (v, normals)
    }

    /// The difference's support function is h_T(n) + h_P(−n) in every direction, its normals
    /// are its edges' outward normals, and each vertex is the difference of the vertices it
    /// names: random polygons of 2 (segments) to 9 vertices, and points.
    #[test]
    fn the_difference_has_the_support_function_of_t_minus_p() {
        let mut rng = Lcg(3);
        let mut checked = 0;
        for case in 0..3000 {
            let nt = [1, 2, 3, 4, 7][case % 5];
            let np = [2, 3, 5, 9][case % 4];
            let (c, size) = (
                Vector::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)),
                rng.range(0.1, 2.0),
            );
            let (tv, tn) = if nt == 1 {
                (vec![c], vec![])
            } else {
                polygon(&mut rng, nt, c, size)
            };
            let (c, size) = (Vector::new(0.2, rng.range(-1.0, 1.0)), rng.range(0.1, 2.0));
            let (pv, pn) = polygon(&mut rng, np, c, size);
            if !(tv.len() == 1 || polygon_is_walkable(&tv, &tn)) || !polygon_is_walkable(&pv, &pn) {
                continue;
            }
            let mut d = Difference::blank();
            assert!(difference(&mut d, &tv, &tn, &pv, &pn), "a difference");
            assert_eq!(d.len, tn.len() + pn.len());
            let h = |vs: &[Vector], n: Vector| vs.iter().map(|v| v.dot(n)).fold(f64::NEG_INFINITY, f64::max);
            for k in 0..64 {
                let a = 2.0 * PI * k as f64 / 64.0 + 0.01;
                let n = Vector::new(a.cos(), a.sin());
                let want = h(&tv, n) + h(&pv, -n);
                let got = h(&d.vertices[..d.len], n);
                assert!((got - want).abs() <= 1e-12, "support {got} vs {want}");
            }
            for i in 0..d.len {
                let (a, b) = (d.vertices[i], d.vertices[(i + 1) % d.len]);
                let n = d.normals[i];
                assert!((n.dot(b - a)).abs() <= 1e-12, "edge {i} not normal to its normal");
                let (ti, pi) = d.from[i];
                assert_eq!(d.vertices[i], tv[ti as usize] - pv[pi as usize]);
                // The edge moves only T's vertex (an edge of T) or only P's.
                let next = d.from[(i + 1) % d.len];
                if d.of_t[i] {
                    assert_eq!(next.1, pi, "an edge of T keeps P's vertex");
                } else {
                    assert_eq!(next.0, ti, "an edge of P keeps T's vertex");
                }
                assert!(cross(n, d.normals[(i + 1) % d.len]) >= 0.0 || d.len == 2);
            }
            checked += 1;
        }
        assert!(checked > 2000, "{checked}");
    }
}
