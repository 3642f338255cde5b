//! The contact manifolds of parry's commonest pairs (box–box, disc–disc, and a disc against a box
//! or another of parry's convex shapes), the same bits as parry's, without parry's dispatch.
//!
//! These are parry's own pairs, which [`crate::SmoothDispatcher`] hands on unchanged; a rapier
//! scene is full of them, so the dispatcher must not cost more than parry there. Through parry's
//! `DefaultQueryDispatcher` each goes through two matches on the shape types and four downcasts;
//! here the types are read once and parry's routine for the pair is called directly (a disc
//! against a box or another convex shape), behind the dispatcher's guards (read off the fields
//! of a box or a disc). Disc–disc is parry's routine with its face id written in place.
//!
//! Box–box is parry's `contact_manifold_cuboid_cuboid` rewritten in one routine: parry's goes
//! through functions that do not inline across crates (the separating-axis test twice, the
//! support face twice, the clipping of two segments, the feature-id constructors, whose
//! assertion keeps them out of line, and the copy of the previous points), which together cost
//! about a third of its time. [`box_box_manifold`] performs the same floating-point operations,
//! in the same order, on the same types:
//!
//! 1. the previous manifold is reused as it stands when parry's coherence test accepts it
//!    (`try_update_contacts`: the normal turned by less than 1°, each point moved by less than
//!    10⁻³ along the face);
//! 2. separating axes: for each box, the largest of `(R·s₂)ᵢ·σᵢ + tᵢ·σᵢ − h₁ᵢ` over its two face
//!    normals `σᵢ eᵢ` (σᵢ the sign of the other centre's coordinate, s₂ the other box's support
//!    vertex), or, when two axes separate, the separation along their weighted sum; a separation
//!    beyond the prediction ends with no point;
//! 3. the reference face is the first box's unless the second's separates more; the two support
//!    faces are clipped to each other along the reference normal's tangent, and the two clipped
//!    ends are the contact points, each with the feature ids of the vertex or face it lies on;
//! 4. the previous points' solver data is carried over to the new points with the same ids.
//!
//! `tests::the_box_manifold_is_parrys_to_the_bit` compares every bit against parry's routine, and
//! `tests::the_dispatcher_answers_parrys_own_pairs_as_parry_does_to_the_bit` the dispatcher's
//! manifolds against parry's dispatcher's.

use super::input_guard;
use super::manifold::guarded;
use crate::numerics::math::{Pose, Real, Vector};
use crate::parry_shape::{face_id, vertex_id};
use parry2d_f64::math::VectorExt;
use parry2d_f64::query::details::contact_manifold_convex_ball;
use parry2d_f64::query::{ContactManifold, TrackedContact, Unsupported};
use parry2d_f64::shape::{Ball, Cuboid, PackedFeatureId, Shape, ShapeType};

/// The manifold of two of parry's commonest shapes, answered without parry's dispatch: box–box
/// ([`box_box_manifold`]), disc–disc ([`disc_disc_manifold`]), and a disc against a box, a
/// capsule, a segment, a triangle or a polygon, round or not (parry's routine for a convex shape
/// against a disc, called directly). The guards are the dispatcher's for every pair parry
/// answers (a box's half extents and a disc's radius read off their fields, in `[0, 1e100]`;
/// another shape's bounding box); the answer is parry's, bit for bit. `None` when the pair is not
/// one of these (the caller goes on to its other routes); `prediction` is checked by the caller.
/// Not inlined: the dispatcher's other routes then keep the code they had (inlined, rounded
/// polygon – box measured 3–8 % slower, box – box 8 % faster).
#[inline(never)]
pub(crate) fn common_manifold<M: Default, C: Default + Copy>(
    pos12: &Pose,
    g1: &dyn Shape,
    t1: ShapeType,
    g2: &dyn Shape,
    t2: ShapeType,
    prediction: Real,
    manifolds: &mut Vec<ContactManifold<M, C>>,
) -> Option<Result<(), Unsupported>> {
    use input_guard::{ball_ok, cuboid_ok, pose_ok, shape_ok};
    /// The pair, its shapes read once (another convex shape against a disc: the disc).
    enum Pair<'s> {
        Boxes(&'s Cuboid, &'s Cuboid),
        Discs(&'s Ball, &'s Ball),
        BoxDisc(&'s Cuboid, &'s Ball),
        DiscBox(&'s Ball, &'s Cuboid),
        ConvexDisc(&'s Ball),
        DiscConvex(&'s Ball),
    }
    // parry's convex shapes other than a disc, which parry answers against a disc by projecting
    // the disc's centre.
    let convex = |t: ShapeType| {
        matches!(
            t,
            ShapeType::Capsule
                | ShapeType::Segment
                | ShapeType::Triangle
                | ShapeType::ConvexPolygon
                | ShapeType::RoundCuboid
                | ShapeType::RoundTriangle
                | ShapeType::RoundConvexPolygon
        )
    };
    let pair = match (t1, t2) {
        (ShapeType::Cuboid, ShapeType::Cuboid) => Pair::Boxes(g1.as_cuboid()?, g2.as_cuboid()?),
        (ShapeType::Ball, ShapeType::Ball) => Pair::Discs(g1.as_ball()?, g2.as_ball()?),
        (ShapeType::Cuboid, ShapeType::Ball) => Pair::BoxDisc(g1.as_cuboid()?, g2.as_ball()?),
        (ShapeType::Ball, ShapeType::Cuboid) => Pair::DiscBox(g1.as_ball()?, g2.as_cuboid()?),
        (t, ShapeType::Ball) if convex(t) => Pair::ConvexDisc(g2.as_ball()?),
        (ShapeType::Ball, t) if convex(t) => Pair::DiscConvex(g1.as_ball()?),
        _ => return None,
    };
    let ok = pose_ok(pos12)
        && match pair {
            Pair::Boxes(c1, c2) => cuboid_ok(c1) && cuboid_ok(c2),
            Pair::Discs(b1, b2) => ball_ok(b1) && ball_ok(b2),
            Pair::BoxDisc(c, b) | Pair::DiscBox(b, c) => cuboid_ok(c) && ball_ok(b),
            Pair::ConvexDisc(b) => ball_ok(b) && shape_ok(g1, t1),
            Pair::DiscConvex(b) => ball_ok(b) && shape_ok(g2, t2),
        };
    if !ok {
        return Some(guarded(manifolds, false));
    }
    if manifolds.is_empty() {
        manifolds.push(ContactManifold::new());
    }
    let m = &mut manifolds[0];
    match pair {
        Pair::Boxes(c1, c2) => box_box_manifold(pos12, c1, c2, prediction, m),
        Pair::Discs(b1, b2) => disc_disc_manifold(pos12, b1, b2, prediction, m),
        // parry's `contact_manifold_convex_ball_shapes`, without its downcast again.
        Pair::ConvexDisc(b2) | Pair::BoxDisc(_, b2) => {
            contact_manifold_convex_ball(pos12, g1, b2, None, None, prediction, m, false)
        }
        Pair::DiscConvex(b1) | Pair::DiscBox(b1, _) => {
            contact_manifold_convex_ball(&pos12.inverse(), g2, b1, None, None, prediction, m, true)
        }
    }
    let finite = input_guard::AllFinite::all_finite(&manifolds[0]);
    Some(guarded(manifolds, finite))
}

/// parry's `contact_manifold_ball_ball`, bit for bit, with its face id written in place (parry's
/// constructor does not inline across crates: it was a fifth of a disc pair's time). Centres
/// `d = t` apart: distance `|d| − r₁ − r₂`, normal `d/|d|` (`y` for coincident centres), the
/// point on each disc along it; one point, kept (with its solver data) when there was one.
#[inline]
fn disc_disc_manifold<M, C: Default + Copy>(
    pos12: &Pose,
    ball1: &Ball,
    ball2: &Ball,
    prediction: Real,
    manifold: &mut ContactManifold<M, C>,
) {
    let (radius_a, radius_b) = (ball1.radius, ball2.radius);
    let dcenter = pos12.translation;
    let center_dist = dcenter.length();
    let dist = center_dist - radius_a - radius_b;
    if dist < prediction {
        let local_n1 = if center_dist != 0.0 {
            dcenter / center_dist
        } else {
            Vector::Y
        };
        let local_n2 = pos12.rotation.inverse() * -local_n1;
        let local_p1 = local_n1 * radius_a;
        let local_p2 = local_n2 * radius_b;
        let fid = face_id(0);
        let contact = TrackedContact::new(local_p1, local_p2, fid, fid, dist);
        if !manifold.points.is_empty() {
            manifold.points[0].copy_geometry_from(contact);
        } else {
            manifold.points.push(contact);
        }
        manifold.local_n1 = local_n1;
        manifold.local_n2 = local_n2;
    } else {
        manifold.points.clear();
    }
}

/// parry's `contact_manifold_cuboid_cuboid(pos12, c1, c2, prediction, manifold)`, bit for bit
/// (module docs). `prediction` must not be negative (parry's contract, checked by the caller).
/// Not inlined: inlined into the dispatcher, it measured 15 % slower.
#[inline(never)]
pub(crate) fn box_box_manifold<M, C: Default + Copy>(
    pos12: &Pose,
    c1: &Cuboid,
    c2: &Cuboid,
    prediction: Real,
    manifold: &mut ContactManifold<M, C>,
) {
    if manifold.try_update_contacts(pos12) {
        return;
    }
    let pos21 = pos12.inverse();
    let sep1 = separation_oneway(c1.half_extents, c2.half_extents, pos12);
    if sep1.0 > prediction {
        manifold.clear();
        return;
    }
    let sep2 = separation_oneway(c2.half_extents, c1.half_extents, &pos21);
    if sep2.0 > prediction {
        manifold.clear();
        return;
    }
    // parry's third candidate, an edge–edge axis, does not exist in 2D: (−MAX, x).
    let sep3 = (-Real::MAX, Vector::X);
    let mut best = sep1;
    if sep2.0 > sep1.0 && sep2.0 > sep3.0 {
        best = (sep2.0, pos12.rotation * -sep2.1);
    } else if sep3.0 > sep1.0 {
        best = sep3;
    }

    // The previous points, for their solver data (parry clones them; a copy, without the call).
    let (old, n_old) = previous_points(&manifold.points);
    manifold.clear();

    let local_n2 = pos21.rotation * -best.1;
    let face1 = support_face(c1.half_extents, best.1);
    let face2 = support_face(c2.half_extents, local_n2);
    face_face_contacts(pos12, &face1, best.1, &face2, manifold);
    manifold.local_n1 = best.1;
    manifold.local_n2 = local_n2;

    manifold.match_contacts(&old[..n_old]);
}

/// A copy of a manifold's points (at most two in 2D) and their number, to match the new points
/// against once the manifold is rebuilt ([`ContactManifold::match_contacts`]).
#[inline]
pub(crate) fn previous_points<C: Default + Copy>(points: &[TrackedContact<C>]) -> ([TrackedContact<C>; 2], usize) {
    match points {
        [a, b, ..] => ([*a, *b], 2),
        [a] => ([*a; 2], 1),
        [] => {
            let unknown = PackedFeatureId::UNKNOWN;
            (
                [TrackedContact::new(Vector::ZERO, Vector::ZERO, unknown, unknown, 0.0); 2],
                0,
            )
        }
    }
}

/// parry's `cuboid_cuboid_find_local_separating_normal_oneway` in 2D: the largest separation of
/// box 2 (half extents `h2`, pose `pos12`) from box 1's face normals, and that normal; when both
/// axes separate, the separation along their sum weighted by the separations.
#[inline]
fn separation_oneway(h1: Vector, h2: Vector, pos12: &Pose) -> (Real, Vector) {
    let mut best_separation = -Real::MAX;
    let mut best_dir = Vector::ZERO;
    let mut axis_acc = Vector::ZERO;
    let mut num_positive = 0;
    for i in 0..2 {
        let sign = 1.0_f64.copysign(pos12.translation[i]);
        let axis1 = Vector::ith(i, sign);
        let axis2 = pos12.rotation.inverse() * -axis1;
        let pt2 = pos12 * signs_of(axis2, h2);
        let separation = pt2[i] * sign - h1[i];
        if separation > best_separation {
            best_separation = separation;
            best_dir = axis1;
        }
        if separation >= 0.0 {
            axis_acc[i] += sign * separation.max(Real::EPSILON);
            num_positive += 1;
        }
    }
    if num_positive > 1 {
        let dir = axis_acc.normalize();
        let pt1 = signs_of(dir, h1);
        let local_dir = pos12.rotation.inverse() * -dir;
        let pt2 = pos12 * signs_of(local_dir, h2);
        ((pt2 - pt1).dot(dir), dir)
    } else {
        (best_separation, best_dir)
    }
}

/// A box's support vertex towards `dir`: `h` with the signs of `dir`'s coordinates.
#[inline]
fn signs_of(dir: Vector, h: Vector) -> Vector {
    Vector::new(h.x.copysign(dir.x), h.y.copysign(dir.y))
}

/// A box's face whose normal is nearest `dir` (parry's `Cuboid::support_face` in 2D): its two
/// vertices, their ids and the face's id.
struct Face {
    vertices: [Vector; 2],
    vids: [PackedFeatureId; 2],
    fid: PackedFeatureId,
}

/// parry's `Cuboid::vertex_feature_id`, bit for bit. It was meant to read the signs of the
/// vertex's coordinates (bit 31 of an f32); on an f64 it reads bit 31 of each coordinate, a
/// mantissa bit, so a box's four corners often get the same code (for half extents 0.5 × 0.3 all four
/// are 0), and so do its faces. Kept as parry has it: these are parry's own pairs, answered to the
/// bit (`the_box_manifold_is_parrys_to_the_bit`).
#[inline]
fn vertex_code(v: Vector) -> u32 {
    (((v.x.to_bits() >> 31) & 0b001) | ((v.y.to_bits() >> 30) & 0b010)) as u32
}

/// parry's `Cuboid::support_face` in 2D (module docs).
#[inline]
fn support_face(he: Vector, dir: Vector) -> Face {
    let vertices = match dir.abs().min_position() {
        0 => [
            Vector::new(he.x, he.y.copysign(dir.y)),
            Vector::new(-he.x, he.y.copysign(dir.y)),
        ],
        _ => [
            Vector::new(he.x.copysign(dir.x), he.y),
            Vector::new(he.x.copysign(dir.x), -he.y),
        ],
    };
    let (v1, v2) = (vertex_code(vertices[0]), vertex_code(vertices[1]));
    let fid = (v1.max(v2) << 2) | v1.min(v2) | 0b11_00_00;
    Face {
        vertices,
        vids: [vertex_id(v1), vertex_id(v2)],
        fid: face_id(fid),
    }
}

/// parry's `PolygonalFeature::face_face_contacts` with `clip_segment_segment_with_normal`
/// inlined: face 2 (box 2's frame) is moved into box 1's frame, both faces are projected on
/// the tangent `t = (−n.y, n.x)` of the reference normal `n`, and each end of the overlap of the
/// two intervals gives a point pair (the end of one face and the point of the other face at the
/// same tangent coordinate), with the ids of the vertex or face each point lies on. No overlap,
/// no point.
#[inline]
fn face_face_contacts<M, C: Default + Copy>(
    pos12: &Pose,
    face1: &Face,
    normal1: Vector,
    face2: &Face,
    manifold: &mut ContactManifold<M, C>,
) {
    let mut seg1 = (face1.vertices[0], face1.vertices[1]);
    let mut seg2 = (pos12 * face2.vertices[0], pos12 * face2.vertices[1]);
    let tangent = Vector::new(-normal1.y, normal1.x);
    let mut range1 = [seg1.0.dot(tangent), seg1.1.dot(tangent)];
    let mut range2 = [seg2.0.dot(tangent), seg2.1.dot(tangent)];
    let mut features1 = [0, 2];
    let mut features2 = [0, 2];
    if range1[1] < range1[0] {
        range1.swap(0, 1);
        features1.swap(0, 1);
        core::mem::swap(&mut seg1.0, &mut seg1.1);
    }
    if range2[1] < range2[0] {
        range2.swap(0, 1);
        features2.swap(0, 1);
        core::mem::swap(&mut seg2.0, &mut seg2.1);
    }
    if range2[0] > range1[1] || range1[0] > range2[1] {
        return;
    }
    let inv = |v: Real| if v == 0.0 { 0.0 } else { 1.0 / v };
    let ca = if range2[0] > range1[0] {
        let bcoord = (range2[0] - range1[0]) * inv(range1[1] - range1[0]);
        (seg1.0 + (seg1.1 - seg1.0) * bcoord, seg2.0, 1, features2[0])
    } else {
        let bcoord = (range1[0] - range2[0]) * inv(range2[1] - range2[0]);
        (seg1.0, seg2.0 + (seg2.1 - seg2.0) * bcoord, features1[0], 1)
    };
    let cb = if range2[1] < range1[1] {
        let bcoord = (range2[1] - range1[0]) * inv(range1[1] - range1[0]);
        (seg1.0 + (seg1.1 - seg1.0) * bcoord, seg2.1, 1, features2[1])
    } else {
        let bcoord = (range1[1] - range2[0]) * inv(range2[1] - range2[0]);
        (seg1.1, seg2.0 + (seg2.1 - seg2.0) * bcoord, features1[1], 1)
    };
    let fids1 = [face1.vids[0], face1.fid, face1.vids[1]];
    let fids2 = [face2.vids[0], face2.fid, face2.vids[1]];
    for (p1, p2, f1, f2) in [ca, cb] {
        let dist = (p2 - p1).dot(normal1);
        let local_p2 = pos12.inverse_transform_point(p2);
        manifold
            .points
            .push(TrackedContact::new(p1, local_p2, fids1[f1], fids2[f2], dist));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::test_rng::Lcg;
    use parry2d_f64::query::details::contact_manifold_cuboid_cuboid;

    type Manifold = ContactManifold<(), u32>;

    /// Every number of two manifolds as bits, with the ids and the carried solver data.
    fn bits(m: &Manifold) -> Vec<u64> {
        let mut v = vec![
            m.local_n1.x.to_bits(),
            m.local_n1.y.to_bits(),
            m.local_n2.x.to_bits(),
            m.local_n2.y.to_bits(),
        ];
        for p in &m.points {
            v.extend([p.local_p1.x, p.local_p1.y, p.local_p2.x, p.local_p2.y, p.dist].map(Real::to_bits));
            v.extend([p.fid1.0 as u64, p.fid2.0 as u64, p.data as u64]);
        }
        v
    }

    /// A box half extent: mostly ordinary, sometimes 0, tiny or huge beside the other.
    fn extent(rng: &mut Lcg) -> Real {
        match below(rng, 10) {
            0 => 0.0,
            1 => 1e-9 * rng.range(0.5, 2.0),
            2 => 1e3 * rng.range(0.5, 2.0),
            _ => rng.range(0.05, 2.0),
        }
    }

    /// A relative pose: random, or axis-aligned (rotation exactly 0 or a quarter turn), or a
    /// copy of the other box's pose (centres coincide).
    fn pose(rng: &mut Lcg, reach: Real) -> Pose {
        let angle = match below(rng, 6) {
            0 => 0.0,
            1 => core::f64::consts::FRAC_PI_2,
            _ => rng.range(-3.2, 3.2),
        };
        let t = match below(rng, 12) {
            0 => Vector::ZERO,
            1 => Vector::new(rng.range(-reach, reach), 0.0),
            _ => Vector::new(rng.range(-reach, reach), rng.range(-reach, reach)),
        };
        Pose::new(t, angle)
    }

    /// Uniform in 0..n.
    fn below(rng: &mut Lcg, n: usize) -> usize {
        ((rng.next() * n as Real) as usize).min(n - 1)
    }

    /// A prediction, a previous pose and the pose now (the same, nearby, or anywhere): the
    /// previous manifold exercises parry's coherence shortcut and the transfer of solver data.
    fn draw_motion(rng: &mut Lcg, reach: Real) -> (Real, Pose, Pose) {
        let prediction = [0.0, 1e-3, 0.1 * reach][below(rng, 3)];
        let before = pose(rng, reach);
        let now = match below(rng, 3) {
            0 => before,
            1 => Pose::new(
                before.translation + Vector::new(1e-5, -1e-5),
                before.rotation.angle() + 1e-4,
            ),
            _ => pose(rng, reach),
        };
        (prediction, before, now)
    }

    #[test]
    fn the_box_manifold_is_parrys_to_the_bit() {
        let mut rng = Lcg(0xB0C5);
        let mut cases = 0;
        let mut with_points = 0;
        for _ in 0..100_000 {
            let c1 = Cuboid::new(Vector::new(extent(&mut rng), extent(&mut rng)));
            let c2 = Cuboid::new(Vector::new(extent(&mut rng), extent(&mut rng)));
            let reach = (c1.half_extents.length() + c2.half_extents.length()) + 1e-6;
            let (prediction, before, now) = draw_motion(&mut rng, reach);
            let mut ours = Manifold::new();
            if below(&mut rng, 4) != 0 {
                contact_manifold_cuboid_cuboid(&before, &c1, &c2, prediction, &mut ours);
                for (k, p) in ours.points.iter_mut().enumerate() {
                    p.data = 7 + k as u32;
                }
            }
            let mut theirs = ours.clone();
            box_box_manifold(&now, &c1, &c2, prediction, &mut ours);
            contact_manifold_cuboid_cuboid(&now, &c1, &c2, prediction, &mut theirs);
            assert_eq!(bits(&ours), bits(&theirs), "boxes {c1:?} {c2:?} at {now:?}");
            cases += 1;
            with_points += usize::from(!theirs.points.is_empty());
        }
        println!("box–box manifolds compared bit for bit: {cases} cases, {with_points} with points");
        assert!(with_points > cases / 4, "too few touching cases: {with_points}");
    }

    #[test]
    fn the_dispatcher_answers_parrys_own_pairs_as_parry_does_to_the_bit() {
        use parry2d_f64::query::{DefaultQueryDispatcher, PersistentQueryDispatcher};
        use parry2d_f64::shape::{Ball, Capsule, RoundTriangle, Segment, Triangle};
        let d = crate::SmoothDispatcher::default();
        let mut rng = Lcg(0xD15C);
        let mut cases = 0;
        let mut with_points = 0;
        for _ in 0..60_000 {
            // Discs and boxes most often (the pairs the dispatcher answers without parry's
            // dispatch), and the other convex shapes parry answers against a disc.
            let shape = |rng: &mut Lcg| -> Box<dyn Shape> {
                let point = |rng: &mut Lcg| Vector::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)) * extent(rng);
                match below(rng, 8) {
                    0..=2 => Box::new(Ball::new(extent(rng))),
                    3..=4 => Box::new(Cuboid::new(Vector::new(extent(rng), extent(rng)))),
                    5 => Box::new(Capsule::new(point(rng), point(rng), extent(rng))),
                    6 => Box::new(Segment::new(point(rng), point(rng))),
                    _ => {
                        let t = Triangle::new(point(rng), point(rng), point(rng));
                        if below(rng, 2) == 0 {
                            Box::new(t)
                        } else {
                            Box::new(RoundTriangle {
                                inner_shape: t,
                                border_radius: extent(rng),
                            })
                        }
                    }
                }
            };
            let (g1, g2) = (shape(&mut rng), shape(&mut rng));
            let size = |g: &dyn Shape| g.compute_local_bounding_sphere().radius;
            let reach = size(&*g1) + size(&*g2) + 1e-6;
            let (prediction, before, now) = draw_motion(&mut rng, reach);
            let mut ours: Vec<Manifold> = vec![];
            let mut workspace = None;
            if below(&mut rng, 4) != 0 {
                let _ = DefaultQueryDispatcher.contact_manifolds(
                    &before,
                    &*g1,
                    &*g2,
                    prediction,
                    &mut ours,
                    &mut workspace,
                );
                for (k, p) in ours.iter_mut().flat_map(|m| m.points.iter_mut()).enumerate() {
                    p.data = 7 + k as u32;
                }
            }
            let mut theirs = ours.clone();
            let a = d.contact_manifolds(&now, &*g1, &*g2, prediction, &mut ours, &mut None);
            let b = DefaultQueryDispatcher.contact_manifolds(&now, &*g1, &*g2, prediction, &mut theirs, &mut None);
            assert_eq!(a, b);
            assert_eq!(ours.len(), theirs.len());
            for (m, n) in ours.iter().zip(&theirs) {
                assert_eq!(
                    bits(m),
                    bits(n),
                    "{:?} {:?} at {now:?}",
                    g1.shape_type(),
                    g2.shape_type()
                );
            }
            cases += 1;
            with_points += usize::from(theirs.iter().any(|m| !m.points.is_empty()));
        }
        println!("parry's own pairs through the dispatcher, bit for bit: {cases} cases, {with_points} with points");
        assert!(with_points > cases / 4, "too few touching cases: {with_points}");
    }

    #[test]
    fn bad_shapes_and_poses_of_parrys_pairs_are_refused_with_the_manifolds_cleared() {
        use parry2d_f64::query::PersistentQueryDispatcher;
        use parry2d_f64::shape::{Ball, Capsule, Segment, Triangle};
        let d = crate::SmoothDispatcher::default();
        let good: [Box<dyn Shape>; 2] = [Box::new(Ball::new(0.5)), Box::new(Cuboid::new(Vector::new(0.5, 0.3)))];
        let bad: Vec<Box<dyn Shape>> = vec![
            Box::new(Ball::new(-0.1)),
            Box::new(Ball::new(Real::NAN)),
            Box::new(Ball::new(1e101)),
            Box::new(Cuboid::new(Vector::new(-0.5, 0.3))),
            Box::new(Cuboid::new(Vector::new(0.5, Real::NAN))),
            Box::new(Cuboid::new(Vector::new(Real::INFINITY, 0.3))),
            Box::new(Capsule::new(Vector::ZERO, Vector::X, Real::NAN)),
            Box::new(Capsule::new(Vector::ZERO, Vector::X, -2.0)),
            Box::new(Segment::new(Vector::ZERO, Vector::new(Real::NAN, 1.0))),
            Box::new(Triangle::new(Vector::ZERO, Vector::X, Vector::new(0.0, 2e100))),
        ];
        let at = Pose::new(Vector::new(0.6, 0.1), 0.3);
        let mut bad_poses = vec![
            Pose::new(Vector::new(Real::NAN, 0.0), 0.0),
            Pose::new(Vector::new(2e100, 0.0), 0.0),
            Pose::new(Vector::ZERO, Real::NAN),
        ];
        let mut stretched = at;
        stretched.rotation.re *= 2.0; // not a unit complex number
        bad_poses.push(stretched);
        let run = |pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape| {
            let mut m: Vec<Manifold> = vec![];
            let mut w = None;
            // A manifold with a point, which a refused query must clear.
            d.contact_manifolds(&at, &*good[1], &*good[1], 0.0, &mut m, &mut w)
                .unwrap();
            assert!(!m[0].points.is_empty());
            let r = d.contact_manifolds(pos12, g1, g2, 0.0, &mut m, &mut w);
            (r, m.iter().all(|m| m.points.is_empty()))
        };
        let mut refused = 0;
        for b in &bad {
            for g in &good {
                for (g1, g2) in [(&**b, &**g), (&**g, &**b)] {
                    assert_eq!(
                        run(&at, g1, g2),
                        (Err(Unsupported), true),
                        "{:?} {:?}",
                        g1.shape_type(),
                        g2.shape_type()
                    );
                    refused += 1;
                }
            }
        }
        for p in &bad_poses {
            for g1 in &good {
                for g2 in &good {
                    assert_eq!(run(p, &**g1, &**g2), (Err(Unsupported), true), "{p:?}");
                    refused += 1;
                }
            }
        }
        println!("refused {refused} bad queries of parry's own pairs");
    }
}
