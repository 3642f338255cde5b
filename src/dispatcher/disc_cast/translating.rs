//! rapier's casts of a polygon that does not turn, in closed form: the second cheap case of
//! "a disc is a disc" (a body with its rotation locked, a bullet fired without spin).
//!
//! # Why a closed form
//!
//! A body that does not turn (its spin exactly 0, on either path a cast may follow) keeps its
//! rotation R₁; against a target that does not turn either (rotation R₂), in the target's frame
//! its origin moves on the segment x(t) = x₀ + w·(t − t₀) and its core is the fixed polygon
//! P = R₂ᵀR₁·P₁ about that origin. With T the target's core, the body overlaps the target's core
//! exactly when x lies in the Minkowski difference M = T ⊖ P (`query::contact::minkowski`),
//! and for two cores dilated by r_T and r_P the pair's signed distance is
//!
//!   D(t) = sd_M(x(t)) − r_T − r_P,
//!
//! the signed distance of a point to a convex polygon: the disc cast of the parent module with
//! M as the target's core (radius r_T) and a "disc" of radius r_P — the first entry of a
//! segment into a dilated polygon, in closed form ([`super::first_entry`]).
//!
//! # The answers
//!
//! Apart at the start (D(t₀) − δ above the tolerance): the first time D comes down to the
//! target distance δ, as the disc's cast answers it (a graze within the tolerance τ above δ
//! enters the level δ + τ), with the witnesses of that time: the nearest point q of M to x(t)
//! is a − b for a point a of T and b of P — on an edge of T, P's vertex of that edge and
//! a = q + b; on an edge of P, T's vertex and b = a − q; at a vertex, both vertices — and the
//! target's witness a + r_T·n, the body's b − r_P·n (n the outward normal of M at q). Everything
//! else (a contact at the start, a body or a target that turns, shapes that are not polygons,
//! segments or a disc target, a start pose parry could not use: a rotation that is not unit,
//! coordinates beyond its range) is left to the general path (`None`), which answers such input
//! as it always has. A rotation centre (`local_center`) is not read: a body that does not turn
//! moves by its translation alone, wherever its centre is.

use super::{at_offset, first_entry, Core, Nearest};
use crate::dispatcher::cast::{is_window, toi_to_parry, NonlinearCast};
use crate::dispatcher::input_guard;
use crate::dispatcher::rapier_rule::in_contact;
use crate::dispatcher::support_shape::{support_shape, SupportScratch};
use crate::numerics::math::{Real, Vector};
use crate::numerics::motion::motion_is_finite;
use crate::query::contact::minkowski::{difference, Difference};
use crate::query::contact::{SupportShape, MAX_BREAKPOINTS};
use crate::query::toi::{TimeOfImpact, ToiCost, ToiOptions, ToiStatus};
use parry2d_f64::math::Rotation;
use parry2d_f64::query::{ShapeCastHit, Unsupported};
use parry2d_f64::shape::ShapeType;

/// rapier's cast of `c` when neither body turns and the body (shape 1) is a polygon, in closed
/// form (module docs), or an ellipse ([`super::translating_ellipse`]); `None` where the general
/// path answers.
pub(crate) fn translating_cast(
    c: &NonlinearCast,
    opts: &ToiOptions,
) -> Option<Result<Option<ShapeCastHit>, Unsupported>> {
    if !translating_guards(c, opts) {
        return None;
    }
    let mut body_scratch = SupportScratch::default();
    match support_shape(c.g1, &mut body_scratch)? {
        SupportShape::Polygon {
            vertices,
            normals,
            radius,
        } => polygon_cast(c, opts, vertices, normals, radius),
        SupportShape::Ellipse(a, b) => super::translating_ellipse::ellipse_cast(c, opts, a, b),
        _ => None,
    }
}

/// What both closed forms of a pair that does not turn ask of the cast `c`: neither body turns,
/// one of them is this crate's, finite motions from start poses parry can use, a finite
/// non-negative target distance and tolerance, a window.
fn translating_guards(c: &NonlinearCast, opts: &ToiOptions) -> bool {
    let ours = |t: ShapeType| t == ShapeType::Custom;
    c.m1.angvel == 0.0
        && c.m2.angvel == 0.0
        && (ours(c.g1.shape_type()) || ours(c.g2.shape_type()))
        && motion_is_finite(c.m1)
        && motion_is_finite(c.m2)
        && input_guard::pose_ok(&c.m1.start)
        && input_guard::pose_ok(&c.m2.start)
        && opts.target_distance >= 0.0
        && opts.target_distance.is_finite()
        && opts.distance_tolerance >= 0.0
        && opts.distance_tolerance.is_finite()
        && is_window(c.t0, c.t1)
}

/// Whether a radius or a bounding sphere's radius is one the contact query reads (finite, not
/// negative), for the body's and the target's radii and both bounding spheres of `c`.
pub(super) fn sizes_ok(c: &NonlinearCast, radii: &[Real]) -> bool {
    let size_ok = |r: Real| r.is_finite() && r >= 0.0;
    radii.iter().all(|r| size_ok(*r)) && c.spheres.iter().all(|b| size_ok(b.radius) && b.center.is_finite())
}

/// The polygon body's closed form (module docs): its core `vertices` and `normals` and radius
/// `r_p`.
fn polygon_cast(
    c: &NonlinearCast,
    opts: &ToiOptions,
    vertices: &[Vector],
    normals: &[Vector],
    r_p: Real,
) -> Option<Result<Option<ShapeCastHit>, Unsupported>> {
    let mut target_scratch = SupportScratch::default();
    let target = Core::of(c.g2, &mut target_scratch)?;
    // Shapes the contact query would refuse are the general path's (it answers them as it
    // always has).
    if !sizes_ok(c, &[r_p, target.radius]) {
        return None;
    }
    let delta = opts.target_distance;
    let tol = opts.distance_tolerance * c.size();
    if spheres_pass(c, delta + tol) {
        return Some(Ok(None));
    }
    // Built in place: the difference is a kilobyte.
    let mut pair = Translating::blank(target, r_p);
    if !pair.place(c, vertices, normals, target.normals) {
        return None;
    }
    // Apart at the start, and by more than the tolerance above δ: the edge lines' distance
    // (a lower bound of the distance) shows it, else the distance itself.
    let apart = |d: Real| d.is_finite() && !in_contact(c, d) && d - delta > tol;
    if !(apart(pair.line_distance(pair.p0)) || apart(pair.distance(pair.p0).0)) {
        return None;
    }
    let m = pair.core();
    let span = c.t1 - c.t0;
    let grow = r_p + target.radius + delta;
    let s = first_entry(&m, pair.p0, pair.w, span, grow).or_else(|| first_entry(&m, pair.p0, pair.w, span, grow + tol));
    Some(toi_to_parry(Ok(s.map(|s| pair.hit(c, at_offset(c, s))))))
}

/// The rounding allowed to [`spheres_pass`]'s closest approach, relative to the pair's size,
/// its travel and its start's distance (as `rapier_rule::out_of_reach` allows its bound).
const SPHERE_ROUNDING: Real = 1e-9;

/// Whether the bodies' bounding spheres (`c.spheres`, about points of the bodies that move by
/// their translations alone) stay more than `level` apart over the whole window: then no
/// impact, whatever the shapes inside them. The closest approach of the two centres, on the
/// segment of their relative motion, with a margin for its rounding.
pub(super) fn spheres_pass(c: &NonlinearCast, level: Real) -> bool {
    let centre =
        |m: &parry2d_f64::query::NonlinearRigidMotion, k: usize| m.start * c.spheres[k].center + m.linvel * c.t0;
    let d0 = centre(c.m1, 0) - centre(c.m2, 1);
    let w = c.m1.linvel - c.m2.linvel;
    let span = c.t1 - c.t0;
    let ww = w.length_squared();
    let s = if ww > 0.0 {
        (-d0.dot(w) / ww).clamp(0.0, span)
    } else {
        0.0
    };
    let closest = (d0 + w * s).length();
    let reach = c.spheres[0].radius + c.spheres[1].radius + level;
    let margin = SPHERE_ROUNDING * (c.size() + w.length() * span + d0.length());
    closest.is_finite() && closest > reach + margin
}

/// A polygon body and a target, neither turning, in the target's frame (module docs).
struct Translating<'a> {
    /// M = T ⊖ P, and T's and P's vertices (P in the target's frame, about the body's origin).
    m: Difference,
    t_vertices: &'a [Vector],
    p_vertices: [Vector; MAX_BREAKPOINTS],
    r_t: Real,
    r_p: Real,
    /// The body's origin at the start and its velocity relative to the target.
    p0: Vector,
    w: Vector,
    /// R₂ᵀR₁: from the body's frame to the target's.
    to_target: Rotation,
}

impl<'a> Translating<'a> {
    /// The pair with `target` (T, dilated by its radius) and a body of radius `r_p`, not placed.
    fn blank(target: Core<'a>, r_p: Real) -> Self {
        Translating {
            m: Difference::blank(),
            t_vertices: target.vertices,
            p_vertices: [Vector::ZERO; MAX_BREAKPOINTS],
            r_t: target.radius,
            r_p,
            p0: Vector::ZERO,
            w: Vector::ZERO,
            to_target: Rotation::IDENTITY,
        }
    }

    /// Places the body (its core's vertices and normals in its own frame) and T ⊖ P in the
    /// target's frame for the cast `c`; false where the difference is refused (as the contact
    /// query would refuse the polygons) or a value is not finite. `target_normals`: T's.
    fn place(
        &mut self,
        c: &NonlinearCast,
        body_vertices: &[Vector],
        body_normals: &[Vector],
        target_normals: &[Vector],
    ) -> bool {
        let (m1, m2) = (c.m1, c.m2);
        let inv = m2.start.rotation.inverse();
        self.to_target = inv * m1.start.rotation;
        let n = body_vertices.len();
        if n > MAX_BREAKPOINTS || body_normals.len() != n {
            return false;
        }
        let mut p_normals = [Vector::X; MAX_BREAKPOINTS];
        for k in 0..n {
            self.p_vertices[k] = self.to_target * body_vertices[k];
            p_normals[k] = self.to_target * body_normals[k];
        }
        if !difference(
            &mut self.m,
            self.t_vertices,
            target_normals,
            &self.p_vertices[..n],
            &p_normals[..n],
        ) {
            return false;
        }
        let x0 = inv * (m1.start.translation - m2.start.translation);
        self.w = inv * (m1.linvel - m2.linvel);
        self.p0 = x0 + self.w * c.t0;
        self.p0.is_finite() && self.w.is_finite()
    }

    /// A lower bound of the pair's signed distance with the body's origin at `x`: the largest
    /// of M's edge lines' signed distances (the signed distance itself inside M), less the radii.
    fn line_distance(&self, x: Vector) -> Real {
        let m = &self.m;
        let mut best = Real::NEG_INFINITY;
        for i in 0..m.len {
            best = best.max(m.normals[i].dot(x - m.vertices[i]));
        }
        best - self.r_t - self.r_p
    }

    /// M as the parent module's target core, dilated by the target's radius.
    fn core(&self) -> Core<'_> {
        Core {
            vertices: &self.m.vertices[..self.m.len],
            normals: &self.m.normals[..self.m.len],
            radius: self.r_t,
        }
    }

    /// The pair's signed distance with the body's origin at `x`, the target's witness, the
    /// body's (both in the target's frame, the body's about its origin) and M's outward normal
    /// there (module docs).
    fn distance(&self, x: Vector) -> (Real, Vector, Vector, Vector) {
        let (sd, normal, (a, b)) = self.nearest(x);
        (
            sd - self.r_t - self.r_p,
            a + normal * self.r_t,
            b - normal * self.r_p,
            normal,
        )
    }

    /// The signed distance from `x` to M, the outward normal at M's nearest point q
    /// ([`Core::nearest`]), and the points a of T and b of P with q = a − b: on an edge of T,
    /// P's vertex of that edge and a = q + b; on an edge of P, T's vertex and b = a − q; at a
    /// vertex, the two vertices it is the difference of.
    fn nearest(&self, x: Vector) -> (Real, Vector, (Vector, Vector)) {
        let m = &self.m;
        let pair = |i: usize| {
            let (ti, pi) = m.from[i];
            (self.t_vertices[ti as usize], self.p_vertices[pi as usize])
        };
        let ((sd, q, normal), at) = self.core().nearest(x);
        let ab = match at {
            Nearest::Vertex(k) => pair(k),
            Nearest::Edge(i) => {
                let (a, b) = pair(i);
                if m.of_t[i] {
                    (q + b, b)
                } else {
                    (a, a - q)
                }
            }
        };
        (sd, normal, ab)
    }

    /// The hit at time `t`: the pair's distance there, each witness and normal in its shape's
    /// frame (the body's from the target's frame by R₁ᵀR₂), and the rate of the distance along
    /// the normal.
    fn hit(&self, c: &NonlinearCast, t: Real) -> TimeOfImpact {
        let x = self.p0 + self.w * (t - c.t0);
        let (dist, point2, body_point, normal2) = self.distance(x);
        let to_body = self.to_target.inverse();
        let normal1 = to_body * -normal2;
        let point1 = to_body * body_point;
        TimeOfImpact {
            status: ToiStatus::Hit,
            time: t,
            distance: dist,
            distance_rate: normal2.dot(self.w),
            point1,
            point2,
            normal1,
            normal2,
            cost: ToiCost::default(),
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::dispatcher::SmoothDispatcher;
    use crate::numerics::math::Pose;
    use crate::numerics::test_rng::Lcg;
    use crate::{CastPolicy, RoundedPolygon};
    use parry2d_f64::query::NonlinearRigidMotion;
    use parry2d_f64::shape::{Ball, Capsule, ConvexPolygon, Cuboid, RoundCuboid, Segment, Shape, Triangle};

    /// Targets of every kind the closed forms read: boxes (thin ones too), a segment, a
    /// triangle, a convex polygon, a rounded box, this crate's polygons, a ball, a capsule.
    fn targets() -> Vec<Box<dyn Shape>> {
        let hull = |pts: &[Vector]| ConvexPolygon::from_convex_hull(pts).unwrap();
        let pent: Vec<Vector> = (0..5)
            .map(|i| Vector::new(0.7 * (1.3 * i as f64).cos(), 0.4 * (1.3 * i as f64).sin()))
            .collect();
        vec![
            Box::new(Cuboid::new(Vector::new(0.8, 0.05))),
            Box::new(Cuboid::new(Vector::new(0.5, 0.3))),
            Box::new(Segment::new(Vector::new(-0.6, 0.1), Vector::new(0.5, -0.2))),
            Box::new(Triangle::new(
                Vector::new(0.0, 0.0),
                Vector::new(0.9, 0.1),
                Vector::new(0.2, 0.7),
            )),
            Box::new(hull(&pent)),
            Box::new(RoundCuboid {
                inner_shape: Cuboid::new(Vector::new(0.4, 0.2)),
                border_radius: 0.1,
            }),
            Box::new(RoundedPolygon::regular(6, 0.5, 0.08)),
            Box::new(RoundedPolygon::regular(3, 0.6, 0.0)),
            Box::new(Ball::new(0.4)),
            Box::new(Capsule::new(Vector::new(-0.3, 0.0), Vector::new(0.4, 0.2), 0.15)),
        ]
    }

    /// A body: a regular polygon (3 to 8 sides), sharp or rounded, or a sliver.
    fn body(rng: &mut Lcg) -> RoundedPolygon {
        let size = rng.range(0.05, 1.0);
        match (rng.range(0.0, 3.0)) as u32 {
            0 => RoundedPolygon::regular(3 + (rng.range(0.0, 6.0) as usize), size, 0.0),
            1 => RoundedPolygon::regular(3 + (rng.range(0.0, 6.0) as usize), size, rng.range(0.01, 0.3) * size),
            _ => RoundedPolygon::new(
                &[
                    Vector::new(-size, 0.0),
                    Vector::new(size, -0.05 * size),
                    Vector::new(size, 0.05 * size),
                ],
                0.0,
            ),
        }
    }

    /// The distance of a point to the boundary of a polygon, a segment or a disc, from its core
    /// as the contact query reads it (parry's hollow projection of a point on a
    /// `ConvexPolygon`'s edge lands inside: not a reference here).
    fn off_boundary(s: &dyn Shape, p: Vector) -> Real {
        let mut scratch = SupportScratch::default();
        match support_shape(s, &mut scratch).unwrap() {
            SupportShape::Polygon {
                vertices,
                normals,
                radius,
            } => (super::super::polygon_point_distance(vertices, normals, p) - radius).abs(),
            SupportShape::Disc(r) => (p.length() - r).abs(),
            _ => unreachable!(),
        }
    }

    /// What [`against_the_general_path`] counted: the closed form's hits and misses, and the
    /// casts it left to the general path.
    pub(in crate::dispatcher::disc_cast) struct Checked {
        pub hits: usize,
        pub misses: usize,
        pub general: usize,
    }

    /// A closed form of a pair that does not turn ([`translating_cast`]) against the general
    /// path on 600 random casts per target of [`targets`], bodies from `body` (`on_body`: a
    /// body's distance to a point of its frame, for its witness): the same hit or miss and
    /// status, the same time (within 1e-12 of the window, or within the distance tolerance the
    /// general path accepts, τ/|D′|); its witnesses on each shape's boundary and apart along
    /// the normal by the pair's distance.
    pub(in crate::dispatcher::disc_cast) fn against_the_general_path<B: Shape>(
        rng: &mut Lcg,
        body: &mut impl FnMut(&mut Lcg) -> B,
        on_body: impl Fn(&B, Vector) -> Real,
    ) -> Checked {
        let (mut hits, mut misses, mut general) = (0, 0, 0);
        for target in targets() {
            for _ in 0..600 {
                let b = body(rng);
                let reach = target.compute_local_bounding_sphere().radius + b.compute_local_bounding_sphere().radius;
                let pose2 = Pose::new(
                    Vector::new(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0)),
                    rng.range(-3.2, 3.2),
                );
                let span = if rng.range(0.0, 1.0) < 0.5 { 1.0 / 60.0 } else { 1.0 };
                let t0 = if rng.range(0.0, 1.0) < 0.5 {
                    0.0
                } else {
                    rng.range(0.0, 0.5)
                };
                let a = rng.range(-3.2, 3.2);
                let centre = pose2.translation + Vector::new(a.cos(), a.sin()) * reach * rng.range(1.05, 3.0);
                let a = rng.range(-3.2, 3.2);
                let aim = pose2.translation + Vector::new(a.cos(), a.sin()) * rng.range(0.0, 1.2) * reach;
                let velocity = (aim - centre).normalize() * rng.range(0.2, 2.0) * (aim - centre).length() / span;
                let v2 = if rng.range(0.0, 1.0) < 0.3 {
                    Vector::new(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5)) * reach / span
                } else {
                    Vector::ZERO
                };
                let m1 = NonlinearRigidMotion::new(
                    Pose::new(centre - velocity * t0, rng.range(-3.2, 3.2)),
                    Vector::new(rng.range(-0.1, 0.1), 0.0),
                    velocity,
                    0.0,
                );
                let m2 = NonlinearRigidMotion::new(
                    Pose::from_parts(pose2.translation - v2 * t0, pose2.rotation),
                    Vector::ZERO,
                    v2,
                    0.0,
                );
                let policy = if rng.range(0.0, 1.0) < 0.7 {
                    CastPolicy::Rapier
                } else {
                    CastPolicy::RapierConstantSpin
                };
                let d = SmoothDispatcher::default().with_cast_policy(policy);
                let stop = rng.range(0.0, 1.0) < 0.2;
                let c = NonlinearCast::new(&m1, &b, &m2, &*target, (t0, t0 + span), stop);
                let (opts, rule) = d.cast_setup(&c);
                let Some(fast) = translating_cast(&c, &opts) else {
                    general += 1;
                    continue;
                };
                let slow = d.general_cast(&c, &opts, rule);
                let what = format!("{:?} {m1:?} {m2:?} {:?}", target.shape_type(), (t0, t0 + span));
                let (fast, slow) = (fast.unwrap(), slow.unwrap());
                assert_eq!(fast.is_some(), slow.is_some(), "{what}: {fast:?} / {slow:?}");
                let (Some(f), Some(g)) = (fast, slow) else {
                    misses += 1;
                    continue;
                };
                hits += 1;
                assert_eq!(f.status, g.status, "{what}");
                let w = pose2.rotation.inverse() * (m1.linvel - m2.linvel);
                let rate = f.normal2.dot(w).abs();
                let tol = opts.distance_tolerance * c.size();
                let dt = (f.time_of_impact - g.time_of_impact).abs();
                assert!(dt <= 1e-12 * span + tol / rate, "{what}: {f:?} / {g:?}");
                // The witnesses: on each shape's boundary, touching along the normals.
                let (p1, p2) = (
                    m1.position_at_time(f.time_of_impact),
                    m2.position_at_time(f.time_of_impact),
                );
                assert!(on_body(&b, f.witness1) <= 1e-9 * c.size(), "{what}: {f:?}");
                assert!(off_boundary(&*target, f.witness2) <= 1e-9 * c.size(), "{what}: {f:?}");
                let gap = (p1 * f.witness1 - p2 * f.witness2).length();
                assert!(gap <= 1e-9 * c.size() + tol, "{what}: witnesses {gap} apart: {f:?}");
                let n1 = p1.rotation * f.normal1;
                let n2 = p2.rotation * f.normal2;
                assert!((n1 + n2).length() <= 1e-12, "{what}: {f:?}");
                assert!((n2.length() - 1.0).abs() <= 1e-12, "{what}: {f:?}");
            }
        }
        Checked { hits, misses, general }
    }

    /// [`against_the_general_path`] for polygon bodies: sharp and rounded regular polygons and
    /// slivers.
    #[test]
    fn casts_of_a_polygon_that_does_not_turn_answer_as_the_general_path() {
        let mut rng = Lcg(41);
        let on_body = |b: &RoundedPolygon, p: Vector| off_boundary(b, p);
        let Checked { hits, misses, general } = against_the_general_path(&mut rng, &mut body, on_body);
        println!("translating casts: {hits} hits, {misses} misses, {general} left to the general path");
        assert!(hits > 1500 && misses > 1500, "{hits} hits, {misses} misses");
    }
}
