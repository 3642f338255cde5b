//! rapier's casts of an ellipse that does not turn, in closed form (the third cheap case of "a
//! disc is a disc": an ellipse body with its rotation locked, a character, a bullet fired
//! without spin).
//!
//! # The set the centre must not enter
//!
//! In the frame of a target that does not turn, a body that does not turn keeps its rotation:
//! its ellipse E (centred at its origin) has semi-axes a, b along fixed unit axes u, v (v = u⊥),
//! and its centre moves on the segment x(s) = x₀ + w·s, s ∈ [0, t₁ − t₀]. The target is its core
//! T (a convex polygon, a segment or a point) dilated by its radius ρ. Their signed distance is
//! the distance from x to
//!
//!   S = T ⊕ E ⊕ B_ρ
//!
//! (E is centrally symmetric: the body's points are x − E), and the first time the pair comes
//! down to a level L ≥ 0 is the first time the segment enters S grown by L, i.e. T ⊕ K with
//! K = E ⊕ B_g, g = ρ + L. T ⊕ K is the union of the vertex sets vⱼ + K and the strips between
//! them, whose outer boundaries are the edges moved out along their normals n by
//! h_K(n) = h_E(n) + g (h_E(n) = |(a·u·n, b·v·n)|, E's support function). Each piece lies in the
//! set, so from a start outside it the first piece the segment meets is where it enters
//! (`super::first_entry`'s argument, with K for the disc):
//!
//! * an edge line n·x = n·vᵢ + h_K(n), crossed inwards at a point whose foot x − s_E(n) (s_E(n)
//!   E's support point along n) falls on the edge: in closed form;
//! * a vertex set vⱼ + K: for g = 0 the ellipse vⱼ + E, which the linear map
//!   L(p) = (u·p / a, v·p / b) takes onto the unit disc about L·vⱼ — a straight motion stays
//!   straight, so the entry is the root of a quadratic (the unit circle's entry of the mapped
//!   segment, in its stable form); for g > 0 the offset ellipse, whose distance from the
//!   segment's points, f(s) = dist(x(s) − vⱼ, E) − g, is convex in s (the distance to a convex
//!   set along a line): Newton's iteration from the left, started where the segment enters the
//!   circle of radius max(a, b) + g about vⱼ (which holds the set), climbs monotonically to
//!   its first root (the tangent of a convex function lies below it), with the nearest point of
//!   the ellipse (`query::contact::feet`) for f and f′ = m·w (m its outward normal).
//!
//! # The answers
//!
//! Apart at the start (the pair's distance, from the same pieces, above the start-contact gap
//! and by more than the tolerance τ above the target distance δ): the first time the distance
//! comes down to δ, or, for a graze, to δ + τ (as the general path accepts), with the witnesses
//! of the piece entered — at an edge the ellipse's support point and its foot on the grown
//! edge, at a vertex the ellipse's nearest point to it and the vertex grown by ρ along the
//! normal there. Apart at the start is shown by a separating axis: one of the target's edge
//! normals, or the normal of the nearest piece (the least distance over the pieces, which holds
//! outside S), along which the pair's support separation is its distance; a start no axis shows
//! apart is the general path's, as are a contact at the start, a target that is not a polygon, a segment or a disc, an
//! ellipse past [`MAX_AXIS_RATIO`] and an iteration that does not settle are left to the
//! general path (`None`).

use super::translating::{sizes_ok, spheres_pass};
use super::{at_offset, first_entry, Core};
use crate::dispatcher::cast::{toi_to_parry, NonlinearCast};
use crate::dispatcher::rapier_rule::in_contact;
use crate::dispatcher::support_shape::SupportScratch;
use crate::numerics::math::{Real, Vector};
use crate::query::contact::feet::nearest_feet;
use crate::query::contact::MAX_BREAKPOINTS;
use crate::query::toi::{TimeOfImpact, ToiCost, ToiOptions, ToiStatus};
use parry2d_f64::math::Rotation;
use parry2d_f64::query::{ShapeCastHit, Unsupported};

/// The largest ratio of an ellipse's semi-axes the closed form takes: the mapped quadratic of a
/// sharp vertex loses about ε times the ratio of the pair's size, below 1e-12 of it up to here.
pub(crate) const MAX_AXIS_RATIO: Real = 1e3;

/// Newton's steps at most on a vertex's offset ellipse (module docs); past them the general
/// path answers. The iterates climb monotonically, a handful suffice but at a graze.
const VERTEX_NEWTON_STEPS: usize = 60;

/// Where Newton's iteration on a vertex's offset ellipse stops: the distance within this
/// fraction of the tolerance τ of the level, or within [`ENTRY_ROUNDING`] of the pair's size
/// (for τ = 0).
const STOP_OF_TOLERANCE: Real = 1e-3;

/// The rounding of the distance to an offset ellipse, relative to the pair's size.
const ENTRY_ROUNDING: Real = 1e-14;

/// rapier's cast of `c` when neither body turns and the body (shape 1) is an ellipse with
/// semi-axes `a`, `b` (module docs); the caller has checked the rest (`translating_guards`).
/// `None` where the general path answers.
pub(super) fn ellipse_cast(
    c: &NonlinearCast,
    opts: &ToiOptions,
    a: Real,
    b: Real,
) -> Option<Result<Option<ShapeCastHit>, Unsupported>> {
    let (lo, hi) = (a.min(b), a.max(b));
    if !(lo > 0.0 && hi <= MAX_AXIS_RATIO * lo && sizes_ok(c, &[a, b])) {
        return None;
    }
    let mut scratch = SupportScratch::default();
    let target = Core::of(c.g2, &mut scratch)?;
    if !sizes_ok(c, &[target.radius]) {
        return None;
    }
    let delta = opts.target_distance;
    let tol = opts.distance_tolerance * c.size();
    if spheres_pass(c, delta + tol) {
        return Some(Ok(None));
    }
    let stop = (STOP_OF_TOLERANCE * tol).max(ENTRY_ROUNDING * c.size());
    let pair = Sweep::new(c, a, b, target, stop)?;
    if !pair.apart_at_start(|d| d.is_finite() && !in_contact(c, d) && d - delta > tol) {
        return None;
    }
    let span = c.t1 - c.t0;
    let (s, level) = match pair.first_entry(span, delta)? {
        Some(entry) => (Some(entry), delta),
        None => (pair.first_entry(span, delta + tol)?, delta + tol),
    };
    Some(toi_to_parry(Ok(
        s.map(|(s, piece)| pair.hit(c, at_offset(c, s), piece, level))
    )))
}

/// The piece of S a segment enters (module docs): an edge or a vertex of the target's core.
#[derive(Copy, Clone)]
enum Piece {
    Edge(usize),
    Vertex(usize),
}

/// An ellipse body and a target, neither turning, in the target's frame (module docs).
struct Sweep<'a> {
    target: Core<'a>,
    /// The ellipse's semi-axes, its axes in the target's frame and the larger semi-axis.
    a: Real,
    b: Real,
    u: Vector,
    v: Vector,
    reach: Real,
    /// The body's centre at the start and its velocity relative to the target.
    p0: Vector,
    w: Vector,
    /// R₂ᵀR₁: from the body's frame to the target's.
    to_target: Rotation,
    /// Where Newton's iteration stops ([`STOP_OF_TOLERANCE`]).
    stop: Real,
}

impl<'a> Sweep<'a> {
    /// The pair of the cast `c` with an ellipse of semi-axes `a`, `b` and the target's core
    /// `target`; `None` where a value is not finite or the target has more vertices than the
    /// contact query reads.
    fn new(c: &NonlinearCast, a: Real, b: Real, target: Core<'a>, stop: Real) -> Option<Self> {
        let n = target.vertices.len();
        if n > MAX_BREAKPOINTS || (n > 1 && target.normals.len() != n) {
            return None;
        }
        let (m1, m2) = (c.m1, c.m2);
        let inv = m2.start.rotation.inverse();
        let to_target = inv * m1.start.rotation;
        let w = inv * (m1.linvel - m2.linvel);
        let p0 = inv * (m1.start.translation - m2.start.translation) + w * c.t0;
        let pair = Sweep {
            target,
            a,
            b,
            u: to_target * Vector::X,
            v: to_target * Vector::Y,
            reach: a.max(b),
            p0,
            w,
            to_target,
            stop,
        };
        // |w|² enters the quadratics: a speed whose square overflows is the general path's.
        (p0.is_finite() && w.length_squared().is_finite()).then_some(pair)
    }

    /// `p` in the ellipse's axes.
    fn local(&self, p: Vector) -> Vector {
        Vector::new(self.u.dot(p), self.v.dot(p))
    }

    /// `p` from the ellipse's axes to the target's frame.
    fn world(&self, p: Vector) -> Vector {
        self.u * p.x + self.v * p.y
    }

    /// E's support function and support point along the unit vector `n` (target's frame).
    fn support(&self, n: Vector) -> (Real, Vector) {
        let m = self.local(n);
        let h = Vector::new(self.a * m.x, self.b * m.y).length();
        (
            h,
            self.world(Vector::new(self.a * self.a * m.x, self.b * self.b * m.y) / h),
        )
    }

    /// The distance from `p` (target's frame, about the ellipse's centre) to E and the outward
    /// unit normal at E's nearest point (target's frame), with that point.
    fn to_ellipse(&self, p: Vector) -> (Real, Vector, Vector) {
        let q = self.local(p);
        let foot = nearest_feet(self.a, self.b, q).as_slice()[0];
        (
            (q - foot.point).dot(foot.normal),
            self.world(foot.normal),
            self.world(foot.point),
        )
    }

    /// The pair's signed distance with the centre at `x`, outside S (module docs: the least over
    /// the vertex sets and over the edge lines whose foot falls on their edge), with the piece
    /// of it.
    fn distance(&self, x: Vector) -> (Real, Piece) {
        let (vs, ns, rho) = (self.target.vertices, self.target.normals, self.target.radius);
        let mut best = (Real::INFINITY, Piece::Vertex(0));
        for (j, v) in vs.iter().enumerate() {
            let d = self.to_ellipse(x - *v).0 - rho;
            if d < best.0 {
                best = (d, Piece::Vertex(j));
            }
        }
        for i in 0..self.edge_count() {
            let (h, s) = self.support(ns[i]);
            let d = ns[i].dot(x - vs[i]) - h - rho;
            if d >= 0.0 && self.faces_edge(i, x, s) && d < best.0 {
                best = (d, Piece::Edge(i));
            }
        }
        best
    }

    /// How many edges the target's core has: vᵢ → vᵢ₊₁ around a polygon, a segment's both ways
    /// (its two normals), none for a point.
    fn edge_count(&self) -> usize {
        let n = self.target.vertices.len();
        if n >= 2 {
            n
        } else {
            0
        }
    }

    /// Whether the centre at `x` faces edge `i` moved out by E: its foot x − s_E(n) (`support`,
    /// E's support point along the edge's normal) projects within the edge.
    fn faces_edge(&self, i: usize, x: Vector, support: Vector) -> bool {
        let vs = self.target.vertices;
        let e = vs[if i + 1 == vs.len() { 0 } else { i + 1 }] - vs[i];
        (0.0..=e.length_squared()).contains(&(x - support - vs[i]).dot(e))
    }

    /// The support separation of the pair along the unit `axis` (from the target towards the
    /// body) with the centre at `x`: a lower bound of the pair's signed distance, equal to it
    /// along the normal of its nearest piece outside S.
    fn separation(&self, x: Vector, axis: Vector) -> Real {
        let h_t = self
            .target
            .vertices
            .iter()
            .map(|p| axis.dot(*p))
            .fold(Real::NEG_INFINITY, Real::max);
        axis.dot(x) - h_t - self.support(axis).0 - self.target.radius
    }

    /// Whether the pair is apart at the start by a distance `far` accepts (a predicate that holds
    /// for every distance above one it holds for): along one of the target's edge normals, else
    /// along the normal of the nearest piece ([`Self::distance`]; rounding at S's boundary, or
    /// a start inside S, shows nothing there).
    fn apart_at_start(&self, far: impl Fn(Real) -> bool) -> bool {
        let (vs, ns) = (self.target.vertices, self.target.normals);
        if ns.iter().any(|n| far(self.separation(self.p0, *n))) {
            return true;
        }
        let axis = match self.distance(self.p0).1 {
            Piece::Edge(i) => ns[i],
            Piece::Vertex(j) => self.to_ellipse(self.p0 - vs[j]).1,
        };
        far(self.separation(self.p0, axis))
    }

    /// The first time in `[0, span]` the centre enters S grown by `level`, with its piece
    /// (module docs); `Some(None)`: it does not; `None`: an iteration did not settle.
    fn first_entry(&self, span: Real, level: Real) -> Option<Option<(Real, Piece)>> {
        let (vs, ns) = (self.target.vertices, self.target.normals);
        let grow = self.target.radius + level;
        let mut first: Option<(Real, Piece)> = None;
        let before = |first: &Option<(Real, Piece)>| first.map_or(span, |(s, _)| s);
        // The edges moved out by h_K(n), crossed inwards within their extent.
        for i in 0..self.edge_count() {
            let (h, support) = self.support(ns[i]);
            let above = ns[i].dot(self.p0 - vs[i]) - h - grow;
            let rate = ns[i].dot(self.w);
            if above < 0.0 || rate >= 0.0 {
                continue;
            }
            let s = above / -rate;
            if s < before(&first) && self.faces_edge(i, self.p0 + self.w * s, support) {
                first = Some((s, Piece::Edge(i)));
            }
        }
        // The vertex sets.
        for (j, v) in vs.iter().enumerate() {
            if let Some(s) = self.vertex_entry(*v, grow, before(&first))? {
                first = Some((s, Piece::Vertex(j)));
            }
        }
        Some(first)
    }

    /// The first time in `[0, until]` the centre enters vⱼ + E ⊕ B_`grow` (vⱼ = `vertex`),
    /// module docs; `Some(None)`: not before `until`; `None`: Newton's iteration did not settle.
    fn vertex_entry(&self, vertex: Vector, grow: Real, until: Real) -> Option<Option<Real>> {
        let one = [vertex];
        if grow == 0.0 {
            // The ellipse itself: the unit circle about L·vⱼ, entered by the mapped segment.
            let map = |p: Vector| {
                let q = self.local(p);
                Vector::new(q.x / self.a, q.y / self.b)
            };
            let (mapped, w) = ([map(vertex)], map(self.w));
            if !(mapped[0].is_finite() && w.length_squared().is_finite()) {
                return None;
            }
            let core = Core {
                vertices: &mapped,
                normals: &[],
                radius: 0.0,
            };
            return Some(first_entry(&core, map(self.p0), w, until, 1.0));
        }
        // Newton's iteration from the entry into the circle of radius max(a, b) + g about vⱼ.
        let outer = self.reach + grow;
        let mut s = if (self.p0 - vertex).length() <= outer {
            0.0
        } else {
            let core = Core {
                vertices: &one,
                normals: &[],
                radius: 0.0,
            };
            match first_entry(&core, self.p0, self.w, until, outer) {
                Some(s) => s,
                None => return Some(None),
            }
        };
        for _ in 0..VERTEX_NEWTON_STEPS {
            let (d, m, _) = self.to_ellipse(self.p0 + self.w * s - vertex);
            let (f, slope) = (d - grow, m.dot(self.w));
            if !(f.is_finite() && slope.is_finite()) {
                return None;
            }
            if f <= self.stop {
                return Some(Some(s));
            }
            if slope >= 0.0 {
                // Convex and no longer falling: never down to the level.
                return Some(None);
            }
            let next = s - f / slope;
            if next > until {
                return Some(None);
            }
            if next <= s {
                // No progress above the stop: rounding the iteration cannot settle.
                return None;
            }
            s = next;
        }
        None
    }

    /// The hit at time `t` at the piece entered at the level `level` (module docs, the
    /// answers): the pair's separation along the normal, each witness and normal in its shape's
    /// frame (the body's from the target's frame by R₁ᵀR₂), the rate of the distance along the
    /// normal.
    fn hit(&self, c: &NonlinearCast, t: Real, piece: Piece, level: Real) -> TimeOfImpact {
        let x = self.p0 + self.w * (t - c.t0);
        let rho = self.target.radius;
        // The body's point (about its centre, target's frame), the target's, the normal from
        // the target to the body.
        let (body_point, point2, normal2) = match piece {
            Piece::Edge(i) => {
                let n = self.target.normals[i];
                let s = self.support(n).1;
                (-s, x - s - n * level, n)
            }
            Piece::Vertex(j) => {
                let v = self.target.vertices[j];
                let (_, m, foot) = self.to_ellipse(x - v);
                (-foot, v + m * rho, m)
            }
        };
        let to_body = self.to_target.inverse();
        TimeOfImpact {
            status: ToiStatus::Hit,
            time: t,
            distance: (x + body_point - point2).dot(normal2),
            distance_rate: normal2.dot(self.w),
            point1: to_body * body_point,
            point2,
            normal1: to_body * -normal2,
            normal2,
            cost: ToiCost::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::translating::tests::{against_the_general_path, Checked};
    use crate::dispatcher::SmoothDispatcher;
    use crate::numerics::math::{Pose, Vector};
    use crate::numerics::test_rng::Lcg;
    use crate::Ellipse;
    use parry2d_f64::query::{NonlinearRigidMotion, QueryDispatcher};
    use parry2d_f64::shape::{Ball, Cuboid, Shape};

    /// rapier's cast of `body` from `start` at velocity `v` (no spin) against `target` at rest
    /// at the origin over one step of 1/60 s: its time of impact, if any.
    fn cast(body: &Ellipse, start: Pose, v: Vector, target: &dyn Shape) -> Option<f64> {
        let m1 = NonlinearRigidMotion::new(start, Vector::ZERO, v, 0.0);
        let m2 = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
        let hit = SmoothDispatcher::default()
            .cast_shapes_nonlinear(&m1, body, &m2, target, 0.0, 1.0 / 60.0, false)
            .unwrap();
        hit.map(|h| h.time_of_impact)
    }

    #[test]
    fn an_ellipse_falling_flat_on_a_box_touches_when_its_support_reaches_the_top() {
        // A 0.5 × 0.2 ellipse turned by θ = 0.6 above a box of half-height 0.1, falling at
        // 60 m/s: it touches when its centre is h_E(y) = √(a² sin²θ + b² cos²θ) above the top.
        let (a, b, theta) = (0.5f64, 0.2f64, 0.6f64);
        let h = ((a * theta.sin()).powi(2) + (b * theta.cos()).powi(2)).sqrt();
        let t = cast(
            &Ellipse::new(a, b),
            Pose::new(Vector::new(0.3, 0.1 + h + 0.5), theta),
            Vector::new(0.0, -60.0),
            &Cuboid::new(Vector::new(2.0, 0.1)),
        )
        .expect("a hit");
        assert!((t - 0.5 / 60.0).abs() < 1e-15, "{t}");
    }

    #[test]
    fn an_ellipse_sliding_along_its_axis_touches_a_ball_at_the_sum_of_the_radii() {
        // Along its major axis at 30 m/s towards a ball of radius 0.25: its tip touches the
        // ball when the centres are a + r apart.
        let (a, r) = (0.4, 0.25);
        let t = cast(
            &Ellipse::new(a, 0.1),
            Pose::new(Vector::new(-(a + r + 0.2), 0.0), 0.0),
            Vector::new(30.0, 0.0),
            &Ball::new(r),
        )
        .expect("a hit");
        assert!((t - 0.2 / 30.0).abs() < 1e-15, "{t}");
        // Offset sideways by more than b + r, it passes.
        let by = cast(
            &Ellipse::new(a, 0.1),
            Pose::new(Vector::new(-(a + r + 0.2), 0.1 + r + 1e-6), 0.0),
            Vector::new(30.0, 0.0),
            &Ball::new(r),
        );
        assert_eq!(by, None);
    }

    /// The closed form against the general path on thousands of random casts of an ellipse
    /// (1:1.2 to 1:50) that does not turn, against every target kind (boxes, a segment, a
    /// triangle, polygons, rounded ones, a ball, a capsule): the same hit or miss and status,
    /// the same time (within 1e-12 of the window, or within the distance tolerance the general
    /// path accepts), its witnesses on each shape's boundary, apart along the normal by the
    /// pair's distance.
    #[test]
    fn casts_of_an_ellipse_that_does_not_turn_answer_as_the_general_path() {
        let mut rng = Lcg(43);
        let mut body = |rng: &mut Lcg| {
            let a = rng.range(0.05, 1.0);
            let b = a / rng.range(1.2, 50.0);
            if rng.range(0.0, 1.0) < 0.5 {
                Ellipse::new(a, b)
            } else {
                Ellipse::new(b, a)
            }
        };
        // How far a point of the body's frame is off its boundary, to first order: the level
        // (x/a)² + (y/b)² of the point, rescaled to a length.
        let on_body = |e: &Ellipse, p: Vector| {
            let (a, b) = (e.half_x(), e.half_y());
            (((p.x / a).powi(2) + (p.y / b).powi(2)).sqrt() - 1.0).abs() * a.min(b)
        };
        let Checked { hits, misses, general } = against_the_general_path(&mut rng, &mut body, on_body);
        println!("translating ellipse casts: {hits} hits, {misses} misses, {general} left to the general path");
        assert!(
            hits > 2500 && misses > 2000 && general < 300,
            "{hits} hits, {misses} misses, {general} general"
        );
    }
}
