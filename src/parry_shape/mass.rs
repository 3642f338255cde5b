//! Exact mass properties (module docs of `parry_shape`): closed forms for the rounded polygon
//! and the capsule-ellipse, adaptive Gauss–Legendre quadrature of Green's theorem for any curve.

// The negated comparison (`!(area < chord)`) is deliberate: it is true for NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::curve::pieces::piece_bounds;
use crate::curve::ConvexCurve;
use crate::numerics::angle::ccw_angle;
use crate::numerics::math::{cross, Real, Vector};
use crate::numerics::quadrature::gauss_legendre;
use core::f64::consts::PI;
use parry2d_f64::mass_properties::MassProperties;

/// The quadrature of the moments is refined until each is within this fraction of the size's
/// power (area r², first moments r³, polar moment r⁴) …
const MOMENT_TOLERANCE: f64 = 1e-14;
/// … or this many halvings deep …
const MAX_DEPTH: u32 = 30;
/// … or when the evaluations reach this many, plus [`EVALUATIONS_PER_PIECE`] per piece (then
/// every panel not yet refined keeps its 12-point estimate, and the quadrature says it was
/// capped: [`QuadratureStatus::OutOfEvaluations`]). A curve that converges takes a few hundred
/// per piece; one whose `eval` is noisy (computed in f32, or with a relative noise of 1e-13)
/// never converges, and without this cap refined every panel to `MAX_DEPTH` (2³⁰ panels per
/// piece: issue 32). About 5 ms of a curve as costly as an ellipse.
const BASE_EVALUATIONS: usize = 1 << 17;
/// The evaluations a piece adds to [`BASE_EVALUATIONS`] (a curve of many pieces, a wrapped
/// polygon, needs 36 per piece at least).
const EVALUATIONS_PER_PIECE: usize = 256;
/// A smooth curve (no breakpoints) is integrated in this many equal pieces of φ.
const SMOOTH_PIECES: usize = 8;
/// Evaluations of one refinement (two panels of [`gauss_legendre`]'s 12 nodes, and the point at
/// the middle) …
const REFINEMENT: usize = 25;
/// … and of a piece's first panel (its 12 nodes and both ends).
const ROOT_PANEL: usize = 14;
/// The chord test allows the area this many times |P(a)|·|P(b)| below the chord's: the rounding
/// of the cross product (64 ε), which where the chord is short and far from the origin (a
/// flat side) exceeds the tolerance's share of the panel.
const CHORD_ROUNDING: f64 = 64.0 * f64::EPSILON;

pub(crate) type Moments = [f64; 4];

/// Whether the quadrature of a curve's mass properties met its tolerance.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum QuadratureStatus {
    /// Every moment is within 1e-14 of the size's power (r², r³, r⁴, r the bounding radius), as
    /// the 12-point Gauss–Legendre estimates of halved panels agree.
    Converged,
    /// The evaluation budget (2¹⁷ plus 256 per piece) ran out first: the moments are the
    /// estimates reached, as accurate as the curve's `eval` allows (a curve computed in f32:
    /// about 1e-7 of the size's power).
    OutOfEvaluations,
}

/// How the mass properties of a [`crate::CustomCurve`] were integrated (once, when it was
/// wrapped): Green's theorem by adaptive Gauss–Legendre quadrature over each piece.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct MassQuadrature {
    /// Whether it met its tolerance.
    pub status: QuadratureStatus,
    /// The curve's evaluations it took.
    pub evaluations: usize,
}

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

/// A panel [a, b] of the adaptive quadrature (with the points at its ends), its 12-point
/// estimate `whole`, the halvings left, and once decided either its two halves (indices of the
/// arena) or its value.
#[derive(Copy, Clone)]
struct Panel {
    a: (f64, Vector),
    b: (f64, Vector),
    whole: Moments,
    depth: u32,
    halves: Option<(usize, usize)>,
    value: Moments,
}

/// Area, first moments and polar second moment (about the origin) of the region bounded by a
/// convex curve, by adaptive Gauss–Legendre quadrature of Green's theorem over each piece, with
/// tolerances from `scale` (the curve's size) and a budget of evaluations.
///
/// A panel is accepted when its two halves' estimates agree with its own (to the tolerance's
/// share of the interval) and each half's area is at least its chord's; otherwise both halves
/// are panels. The chord test: the region swept from the origin over a convex arc holds the
/// triangle of the origin and the arc's chord, so its area ½∫P × P′ is at least ½ P(a) × P(b)
/// (less the rounding of that product, [`CHORD_ROUNDING`]). Halved estimates agree when all their nodes miss a
/// narrow peak of the integrand — a thin ellipse in its normal angle packs its long flat side,
/// and nearly all its area, into a φ-interval of about b/a — and only the chord sees what lies
/// between them (without it the area of a 1:1e-9 ellipse "converged" to 1.6e-15 for 3.1e-9).
///
/// Panels are decided in the order they are made (breadth first, over all pieces at once), so
/// that a budget that runs out leaves every region refined to about the same depth instead of
/// one region to the last halving and the others not at all (depth first, a thin ellipse in its
/// normal angle, whose area sits in φ-intervals of about b/a at its flat sides, spent the budget
/// on the first of them and got a quarter of its area); each panel's value is then its halves'
/// sum (as a recursion adds them: a query that converges keeps its bits), or, undecided, its own
/// estimate.
pub(crate) fn curve_quadrature(c: &dyn ConvexCurve, scale: f64) -> (Moments, MassQuadrature) {
    let bp = c.breakpoints();
    let r = scale.abs().max(f64::MIN_POSITIVE);
    let tol: Moments = [r * r, r * r * r, r * r * r, r * r * r * r].map(|s| MOMENT_TOLERANCE * s);
    let nodes = gauss_legendre::<12>();
    let pieces: Vec<(f64, f64)> = if bp.is_empty() {
        (0..SMOOTH_PIECES)
            .map(|i| {
                let a = -PI + 2.0 * PI * i as f64 / SMOOTH_PIECES as f64;
                (a, a + 2.0 * PI / SMOOTH_PIECES as f64)
            })
            .collect()
    } else {
        (0..bp.len())
            .map(|k| piece_bounds(bp, k))
            .filter(|(s, e)| e > s)
            .collect()
    };
    let budget = BASE_EVALUATIONS.saturating_add(EVALUATIONS_PER_PIECE.saturating_mul(pieces.len()));
    let mut spent = 0usize;
    let mut panels: Vec<Panel> = pieces
        .iter()
        .map(|&(a, b)| {
            spent += ROOT_PANEL;
            let whole = gl_moments(c, a, b, &nodes);
            Panel {
                a: (a, c.eval(a).point),
                b: (b, c.eval(b).point),
                whole,
                depth: MAX_DEPTH,
                halves: None,
                value: whole,
            }
        })
        .collect();
    let roots = panels.len();
    let mut capped = false;
    let mut i = 0;
    while i < panels.len() {
        let p = panels[i];
        i += 1;
        if spent.saturating_add(REFINEMENT) > budget {
            capped = true;
            break;
        }
        spent += REFINEMENT;
        let (a, b) = (p.a.0, p.b.0);
        let m = 0.5 * (a + b);
        let pm = c.eval(m).point;
        let left = gl_moments(c, a, m, &nodes);
        let right = gl_moments(c, m, b, &nodes);
        let sum = [0, 1, 2, 3].map(|k| left[k] + right[k]);
        let frac = (b - a) / (2.0 * PI);
        let ok = (0..4).all(|k| {
            let err = (sum[k] - p.whole[k]).abs();
            err <= tol[k] * frac || err.is_nan()
        });
        let chord = |area: f64, u: Vector, v: Vector| {
            let c = 0.5 * cross(u, v);
            !(area < c - tol[0] * frac - CHORD_ROUNDING * u.length() * v.length())
        };
        if (ok && chord(left[0], p.a.1, pm) && chord(right[0], pm, p.b.1)) || p.depth == 0 {
            panels[i - 1].value = sum;
            continue;
        }
        let half = |lo: (f64, Vector), hi: (f64, Vector), whole: Moments| Panel {
            a: lo,
            b: hi,
            whole,
            depth: p.depth - 1,
            halves: None,
            value: whole,
        };
        let n = panels.len();
        panels[i - 1].halves = Some((n, n + 1));
        panels.push(half(p.a, (m, pm), left));
        panels.push(half((m, pm), p.b, right));
    }
    // Halves come after their panel: sum them from the last.
    for k in (0..panels.len()).rev() {
        if let Some((l, r)) = panels[k].halves {
            let (l, r) = (panels[l].value, panels[r].value);
            panels[k].value = [0, 1, 2, 3].map(|j| l[j] + r[j]);
        }
    }
    let mut total = [0.0; 4];
    for p in &panels[..roots] {
        for (t, v) in total.iter_mut().zip(p.value) {
            *t += v;
        }
    }
    let status = if capped {
        QuadratureStatus::OutOfEvaluations
    } else {
        QuadratureStatus::Converged
    };
    (
        total,
        MassQuadrature {
            status,
            evaluations: spent,
        },
    )
}

/// [`curve_quadrature`] with the curve's bounding radius as its size (the built-in shapes).
#[cfg(test)]
pub(crate) fn curve_moments(c: &dyn ConvexCurve) -> Moments {
    curve_quadrature(c, c.bounding_radius()).0
}

/// parry mass properties from the moments (about the origin) of a uniform region.
pub(crate) fn mass_from_moments(density: Real, m: Moments) -> MassProperties {
    let area = m[0];
    if !m.iter().all(|v| v.is_finite()) || area <= 0.0 {
        return MassProperties::new(Vector::ZERO, 0.0, 0.0);
    }
    let com = Vector::new(m[1], m[2]) / area;
    let inertia = (m[3] - area * com.length_squared()).max(0.0);
    MassProperties::new(com, density * area, density * inertia)
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};

    fn rel_close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * a.abs().max(b.abs()).max(1e-300)
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

    /// Issue 32, item 1: the quadrature's tolerance came from the user's bounding radius (a
    /// radius of 0 made it 0) and nothing capped its evaluations. At any scale — 0, NaN, a
    /// fifth of the size, 1e-300 — it now ends within its budget, saying whether it converged;
    /// and its area stays right where the scale is too small for it to converge.
    #[test]
    fn quadrature_ends_within_its_budget_at_any_scale() {
        let e = Ellipse::new(0.6, 0.3);
        for scale in [0.6, 0.12, 0.0, f64::NAN, 1e-300, -1.0] {
            let (m, q) = curve_quadrature(&e, scale);
            assert!(
                q.evaluations <= BASE_EVALUATIONS + EVALUATIONS_PER_PIECE * SMOOTH_PIECES,
                "{q:?}"
            );
            assert!(rel_close(m[0], PI * 0.18, 1e-13), "scale {scale}: area {}", m[0]);
            if scale == 0.6 {
                assert_eq!(q.status, QuadratureStatus::Converged);
            }
        }
    }

    /// A thin ellipse's area sits in φ-intervals of about b/a at its flat sides: a depth-first
    /// refinement under a budget spent it on the first of them (a 1:1e-6 ellipse got a quarter
    /// of its area); breadth first, the quadrature finds it to 1e-14 of the size squared.
    #[test]
    fn quadrature_finds_the_area_of_thin_ellipses() {
        for (a, b) in [(1.0, 1e-3), (1.0, 1e-6), (1e-6, 1.0), (1.0, 1e-9)] {
            let (m, q) = curve_quadrature(&Ellipse::new(a, b), a.max(b));
            let exact = PI * a * b;
            assert!(
                (m[0] - exact).abs() <= 1e-14 * a.max(b).powi(2),
                "{a} × {b}: {} vs {exact} ({q:?})",
                m[0]
            );
        }
    }
}
