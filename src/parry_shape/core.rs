//! A shape's *core*: the largest disc about its centroid that lies inside it — the centroid and
//! the inradius about it, in closed form for polygons (dilated or not) and the `CapsuleEllipse`.
//!
//! The inradius about the centroid is the shapes' `ccd_thickness` (rapier sweeps a body that
//! moves more than half of it in a step, so a body's centre cannot cross a wall in a step it
//! does not sweep) and the scale of the dispatcher's rapier rules (`dispatcher::core_disc`).

use crate::numerics::math::Vector;

/// A disc inside a shape: its centre (the shape's centroid) and radius (the distance from the
/// centroid to the boundary).
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct Core {
    pub centre: Vector,
    pub radius: f64,
}

impl Core {
    /// The radius of a disc about `c` that lies inside the shape: the core's radius less the
    /// distance from its centre (0 when `c` is not inside the core).
    pub(crate) fn radius_about(&self, c: Vector) -> f64 {
        (self.radius - (c - self.centre).length()).max(0.0)
    }
}

/// The core of a convex polygon (counter-clockwise, its edge normals) dilated by `r`: the
/// centroid of the dilated region — the core polygon, a rectangle r wide on each edge, a
/// circular sector at each corner — and its distance to the nearest edge line plus r. A segment
/// (two vertices) has no area of its own: its core is its midpoint with radius r.
pub(crate) fn polygon_core(v: &[Vector], normals: &[Vector], r: f64) -> Option<Core> {
    let n = v.len();
    if n < 2 || normals.len() != n {
        return None;
    }
    // Moments about the vertex mean (less cancellation), without allocating.
    let c0 = v.iter().copied().sum::<Vector>() / n as f64;
    let (mut area, mut m) = (0.0, Vector::ZERO);
    // The signed area and first moment of the triangle (c0, p, q), c0 at the origin.
    let fan = |p: Vector, q: Vector| {
        let c = p.perp_dot(q);
        (0.5 * c, (p + q) * (c / 6.0))
    };
    for i in 0..n {
        let (a, mm) = fan(v[i] - c0, v[(i + 1) % n] - c0);
        area += a;
        m += mm;
    }
    if r > 0.0 {
        for i in 0..n {
            let (p, q, e) = (v[i] - c0, v[(i + 1) % n] - c0, normals[i]);
            // The rectangle on edge i (as a fan about c0: its signed pieces sum to it).
            let (pe, qe) = (p + e * r, q + e * r);
            for (a, b) in [(p, pe), (pe, qe), (qe, q), (q, p)] {
                let (da, dm) = fan(a, b);
                area += da;
                m += dm;
            }
            // The sector at vertex i, from the previous edge's normal to this one's.
            let u0 = normals[(i + n - 1) % n];
            let alpha = u0.perp_dot(e).atan2(u0.dot(e)).rem_euclid(core::f64::consts::TAU);
            let sector = 0.5 * alpha * r * r;
            area += sector;
            m += Vector::new(e.y - u0.y, u0.x - e.x) * (r * r * r / 3.0) + p * sector;
        }
    }
    let centre = if area > 0.0 {
        c0 + m / area
    } else if n == 2 || r > 0.0 {
        c0
    } else {
        return None;
    };
    // A segment's midpoint lies on its line: its distance to it is 0, not the rounding of the
    // dot products below (which can be 1e-17 either way for a segment off the axes, and made a
    // bare segment a core of that radius: a core contact at its midpoint, against the other
    // body's tangent line, a ghost support where that body is not).
    let inner = if area > 0.0 {
        (0..n)
            .map(|i| normals[i].dot(v[i] - centre))
            .fold(f64::INFINITY, f64::min)
    } else {
        0.0
    };
    let radius = inner + r;
    Some(Core {
        centre,
        radius: radius.max(0.0),
    })
}

/// The core of the `CapsuleEllipse` (r1, r2, r3): its centroid (cx, 0) on the axis of symmetry,
/// from its closed-form moments, and the distance from there to each piece of the boundary —
/// the segment x = r1 (r1 − cx); the two arcs, whose nearest points are their ends (the squared
/// distance to a point of an arc, as a function of the arc's angle, is a cosine with its maximum
/// inside the arc); the half ellipse x ≤ 0, semi-axes r3 and B = r1 + r2, where the squared
/// distance is the quadratic (r3² − B²)c² − 2r3·cx·c + cx² + B² of c = cos φ ∈ [−1, 0].
pub(crate) fn capsule_ellipse_core(r1: f64, r2: f64, r3: f64) -> Core {
    let m = super::mass::capsule_ellipse_moments(r1, r2, r3);
    let cx = m[1] / m[0];
    let b = r1 + r2;
    let segment = r1 - cx;
    let arcs = ((r1 - cx).powi(2) + r2 * r2).sqrt().min((cx * cx + b * b).sqrt());
    let quad = |c: f64| (r3 * r3 - b * b) * c * c - 2.0 * r3 * cx * c + cx * cx + b * b;
    let mut best = quad(-1.0).min(quad(0.0));
    let k = r3 * r3 - b * b;
    if k > 0.0 {
        let c = (r3 * cx / k).clamp(-1.0, 0.0);
        best = best.min(quad(c));
    }
    let ellipse = best.max(0.0).sqrt();
    Core {
        centre: Vector::new(cx, 0.0),
        radius: segment.min(arcs).min(ellipse).max(0.0),
    }
}
