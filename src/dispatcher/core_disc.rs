//! A shape's *core*: the largest disc about its centroid that lies inside it (centre and
//! radius, the inradius about the centroid), as the dispatcher's rapier rules use it.
//!
//! The core moves with the body's centre of mass and does not change when the body turns about
//! it, so what happens to it is what the body's translation does, whatever its spin:
//!
//! * rapier's CCD ([`super::rapier_rule`]) keeps a smaller disc about the body's rotation centre
//!   off every target — the centre of a body never reaches a wall, so it cannot pass it;
//! * the contact manifold ([`super::manifold`]) adds a *core contact*: a speculative point of
//!   the core facing the other shape, which rapier's solver takes only when the body's centre
//!   would close it within the step. A body whose one contact point a spin carries away from a
//!   wall while its centre moves into the wall is then stopped by the solver, where a one-point
//!   manifold would leave the approach to the CCD alone. Both points of a core contact lie on
//!   one line through the core's centre and on the two bodies (rapier's solver acts on a
//!   contact at the middle of its two points): along the contact normal where that line meets
//!   the other body's face, else the core disc against a polygon's nearest point, else none
//!   ([`core_disc_manifolds`]).
//!
//! Each radius is exact for the shapes the contact query reads (polygons, discs, ellipses and
//! `CapsuleEllipse`s): the inradius about the centroid in closed form.

use super::support_shape::{support_shape, SupportScratch};
use crate::parry_shape::vertex_id;
use crate::parry_shape::{capsule_ellipse_core, polygon_core, Core};
use crate::query::contact::{Contact, ContactPoint, Feature, SupportShape};
use crate::{CustomCurve, RoundedPolygon};
use parry2d_f64::math::{Pose, Real, Vector};
use parry2d_f64::query::{ContactManifold, TrackedContact};
use parry2d_f64::shape::Shape;

/// The core contact's disc, as a fraction of the core's radius (the inradius about the
/// centroid). Larger than rapier's CCD core ([`super::rapier_rule::CastPolicy::CORE`]): the
/// solver stops a centre heading for a wall before the CCD would have to.
pub(crate) const CORE_CONTACT_FRACTION: f64 = 0.5;

/// The core contact of a pair whose exact contact is `c` (body 1 at the origin, body 2 at
/// `pos12`), in body 1's frame: a speculative point pair along the contact normal n between a
/// body's core disc ([`CORE_CONTACT_FRACTION`] of its core) and the other body's supporting line
/// (the line through its witness, normal to n), with the gap between them along n.
///
/// The core's point lies on its body's *centre line* (the line through its centroid along n),
/// the other point on the other body's supporting line opposite it: the pair acts along one
/// line, as a contact does. A velocity along n at a point of a body's centre line is its
/// centre's, so the constraint the pair makes — the core may not close the gap along n faster
/// than the step allows — holds the core's body by its translation, whatever its spin (the
/// other point moves with the other body's spin: a convex pair gets both bodies' core
/// contacts, [`core_contacts`]). The gap is a lower bound on the core's distance to the other
/// body (the other body lies beyond its supporting line), so the constraint never holds back a
/// translation that keeps the core off the other body along n.
///
/// Of the two bodies the smaller one (its reach about its centroid) is taken, for a manifold
/// that holds one core contact (the part of a composite shape: a compact body against a piece
/// of level geometry; a segment has no core at all); `contact_manifolds` of a convex pair gives
/// both bodies' in manifolds of their own ([`core_disc_manifolds`]). `None` when neither body has a
/// core. `cores` are the two shapes' cores ([`core_of`]), which the caller has already computed
/// (a polygon's is its centroid and inradius: a sum over its edges, worth computing once a call).
pub(crate) fn core_contact(
    s1: SupportShape,
    s2: SupportShape,
    cores: [Option<Core>; 2],
    pos12: &Pose,
    c: &Contact,
) -> Option<CoreContact> {
    match core_contacts(cores, pos12, c) {
        [Some(a), Some(b)] => {
            let reach1 = reach(s1, cores[0].map_or(Vector::ZERO, |k| k.centre));
            let reach2 = reach(s2, cores[1].map_or(Vector::ZERO, |k| k.centre));
            Some(if reach2 < reach1 { b } else { a })
        }
        [a, b] => a.or(b),
    }
}

/// The largest distance from `centre` to a point of the shape (an upper bound for a
/// `CapsuleEllipse`: the larger of its half-ellipse's semi-axes plus the offset).
fn reach(s: SupportShape, centre: Vector) -> f64 {
    match s {
        SupportShape::Disc(r) => r + centre.length(),
        SupportShape::Ellipse(a, b) => a.max(b) + centre.length(),
        SupportShape::Polygon { vertices, radius, .. } => {
            vertices.iter().map(|v| (*v - centre).length()).fold(0.0, f64::max) + radius
        }
        SupportShape::CapsuleEllipse(r1, r2, r3) => r3.max(r1 + r2) + centre.length(),
    }
}

/// The core contacts of both bodies of a pair whose exact contact is `c` ([`core_contact`]), in
/// body 1's frame, from the bodies' cores `cores` ([`core_of`] of each shape, in its own frame);
/// `None` for a body without a core (a segment) or a value that is not finite.
pub(crate) fn core_contacts(cores: [Option<Core>; 2], pos12: &Pose, c: &Contact) -> [Option<CoreContact>; 2] {
    let n = c.normal;
    let w = &c.points[0];
    let [k1, k2] = cores;
    // A body's centroid (a segment's midpoint), or its witness when it has none.
    let c1 = k1.map_or(w.point1, |k| k.centre);
    let c2 = k2.map_or(w.point2, |k| pos12 * k.centre);
    let finite = |k: CoreContact| (k.point1.is_finite() && k.point2.is_finite() && k.dist.is_finite()).then_some(k);
    let one = k1.filter(|k| k.radius > 0.0).and_then(|k| {
        // Body 1's core towards body 2, and body 2's supporting line on its centre line.
        let q = c1 + n * (CORE_CONTACT_FRACTION * k.radius);
        let gap = (w.point2 - q).dot(n);
        finite(CoreContact {
            point1: q,
            point2: q + n * gap,
            dist: gap,
            centre: c1,
            radius: k.radius,
            body: 0,
        })
    });
    let two = k2.filter(|k| k.radius > 0.0).and_then(|k| {
        let q = c2 - n * (CORE_CONTACT_FRACTION * k.radius);
        let gap = (q - w.point1).dot(n);
        finite(CoreContact {
            point1: q - n * gap,
            point2: q,
            dist: gap,
            centre: c2,
            radius: k.radius,
            body: 1,
        })
    });
    [one, two]
}

/// The contact of body `body`'s core disc ([`CORE_CONTACT_FRACTION`] of its core `core`, in its
/// own frame) with the other shape `other` (body 1 at the origin, body 2 at `pos12`), in body
/// 1's frame: its normal from body 1 to body 2 and the point pair, the core's point on the line
/// through the core's centre and the other shape's nearest boundary point (its projection,
/// `PointQuery::project_local_point`), the other point that boundary point, the gap between
/// them along the normal (negative where the core's centre is inside the other shape).
///
/// Both points lie on one line through the core's centre, and rapier's solver acts on a
/// contact at the middle of its two points: the row holds the core's body by its translation
/// whatever its spin, and pushes the other body where its surface is, along that surface's
/// normal (the projection's direction lies in its normal cone) — a contact of the core disc,
/// a part of the body, with the other body, as rapier's CCD keeps its core off every target.
/// (The core contact was once taken along the pair's contact normal, its point on the other
/// body's supporting line opposite the core: where that line passes beside the other body, a
/// long floor's core contact, metres from a ball on it, braked the ball's spin through a lever
/// of metres.) `fallback` (the pair's contact normal) is the normal when the core's centre lies
/// on the other shape's boundary; `None` when a value is not finite.
pub(crate) fn core_disc_contact(
    core: Core,
    other: &dyn Shape,
    pos12: &Pose,
    body: usize,
    fallback: Vector,
) -> Option<(Vector, CoreContact)> {
    let r = CORE_CONTACT_FRACTION * core.radius;
    let (centre, proj) = if body == 0 {
        let centre = core.centre;
        let proj = other.project_local_point(pos12.inverse_transform_point(centre), false);
        (centre, (pos12 * proj.point, proj.is_inside))
    } else {
        let centre = pos12 * core.centre;
        (centre, {
            let proj = other.project_local_point(centre, false);
            (proj.point, proj.is_inside)
        })
    };
    let (b, inside) = proj;
    // From the core's centre to the other shape's boundary; the normal points from body 1 to
    // body 2, out of the other shape at b when the centre is outside it.
    let to_b = b - centre;
    let d = to_b.length();
    let towards = if d > 0.0 { to_b / d } else { Vector::ZERO };
    let along = if body == 0 { towards } else { -towards };
    let n = if d > 0.0 {
        if inside {
            -along
        } else {
            along
        }
    } else {
        fallback
    };
    let gap = if inside { -d - r } else { d - r };
    let k = if body == 0 {
        CoreContact {
            point1: centre + n * r,
            point2: b,
            dist: gap,
            centre,
            radius: core.radius,
            body,
        }
    } else {
        CoreContact {
            point1: b,
            point2: centre - n * r,
            dist: gap,
            centre,
            radius: core.radius,
            body,
        }
    };
    (n.is_finite() && k.point1.is_finite() && k.point2.is_finite() && gap.is_finite() && r > 0.0).then_some((n, k))
}

/// Fills `manifold` with the core contact `k` of normal `n` ([`core_disc_contact`], body 1's
/// frame) when `with` (the pair has a contact point), its feature code `code` on both bodies and
/// its id kept from the previous point; empty otherwise. False, with the manifold left as it
/// was, when the normal is not finite in body 2's frame.
pub(crate) fn core_disc_manifold<M, C: Default + Copy>(
    pos12: &Pose,
    contact: Option<(Vector, CoreContact)>,
    code: u32,
    with: bool,
    manifold: &mut ContactManifold<M, C>,
) -> bool {
    let (old, n_old) = super::parry_pairs::previous_points(&manifold.points);
    manifold.clear();
    if let (true, Some((n, k))) = (with, contact) {
        let n2 = pos12.inverse_transform_vector(-n);
        let p2 = pos12.inverse_transform_point(k.point2);
        if !n2.is_finite() {
            return false;
        }
        manifold.local_n1 = n;
        manifold.local_n2 = n2;
        // A point that leaves f64 in body 2's frame (absurd input) is left out.
        if p2.is_finite() {
            let id = vertex_id(code);
            manifold.points.push(TrackedContact::new(k.point1, p2, id, id, k.dist));
        }
    }
    manifold.match_contacts(&old[..n_old]);
    true
}

/// Fills `cores` (two manifolds) with both bodies' core contacts, when `with` (the pair has a
/// contact point), for a pair whose contact is `c` (body 1's frame) and whose shapes, support
/// shapes (`None` where the contact query does not read a shape) and cores are `shapes`,
/// `supports` and `cores`. A body's core contact is taken along the pair's normal
/// ([`core_contacts`]) where its line meets the other body's surface ([`on_other_surface`]: a
/// flat face facing the core, or the witness); else, against a polygon, as the contact of its
/// core disc with the polygon's nearest point along its own normal ([`core_disc_contact`]), and
/// against a curved body its line misses, not at all. rapier's solver acts on a contact at the
/// middle of its two points, and each of these has both on one line through the core's centre
/// and on the other body's surface. (Against a curve the core disc's contact would add a row
/// along another normal at an impact: with restitution, two head-on bullets at 600 rad/s then
/// gained energy under `OneBounceHooks` in 2 of 648 shots, where none did before.) Both taken
/// along the normal share the first manifold (the second is then empty); otherwise each body's
/// is in its own, body 1's first. False when a manifold refused its contact (the caller then
/// answers as for a failed contact).
#[allow(clippy::too_many_arguments)]
pub(crate) fn core_disc_manifolds<M, C: Default + Copy>(
    pos12: &Pose,
    shapes: [&dyn Shape; 2],
    supports: [Option<SupportShape>; 2],
    cores: [Option<Core>; 2],
    c: &Contact,
    with: bool,
    manifolds: &mut [ContactManifold<M, C>],
) -> bool {
    let (n, w) = (c.normal, &c.points[0]);
    let [a1, a2] = core_contacts(cores, pos12, c);
    let a1 = a1.filter(|k| on_other_surface(shapes[1], supports[1], pos12, -n, n, k.centre, w.point2));
    let a2 = a2.filter(|k| on_other_surface(shapes[0], supports[0], &Pose::IDENTITY, n, n, k.centre, w.point1));
    let [m1, m2] = manifolds else {
        return false;
    };
    if a1.is_some() && a2.is_some() {
        return core_manifold(pos12, c, [a1, a2], with, m1) && core_disc_manifold(pos12, None, 0, false, m2);
    }
    let flat = |s: Option<SupportShape>| matches!(s, Some(SupportShape::Polygon { .. }));
    let one = match a1 {
        Some(k) => Some((n, k)),
        None if flat(supports[1]) => cores[0].and_then(|k| core_disc_contact(k, shapes[1], pos12, 0, n)),
        None => None,
    };
    let two = match a2 {
        Some(k) => Some((n, k)),
        None if flat(supports[0]) => cores[1].and_then(|k| core_disc_contact(k, shapes[0], pos12, 1, n)),
        None => None,
    };
    core_disc_manifold(pos12, one, CORE_FEATURE, with, m1) && core_disc_manifold(pos12, two, CORE_FEATURE - 1, with, m2)
}

/// Whether a core contact of the body whose core centre is `centre` (body 1's frame) acts on a
/// point of the other body's surface: the shape `g`, placed at `pose` in that frame, with its
/// witness `witness` and `toward` the outward normal its surface would have there facing the
/// core (−n for body 2, n for body 1). rapier's solver acts on a contact at the middle of its
/// two points, here on the core's centre line along n; the other body's point there moves along
/// n as that body's surface does only where the surface is there: at the witness itself (to a
/// rounding margin of [`CROSSING_MARGIN`] of the sizes: a disc's centre line holds its
/// witness and the other's), or on a flat face of a polygon facing the core (within a cosine of
/// [`FACE_COSINE`] of `toward`) whose extent along the tangent holds the line. Elsewhere the
/// point is off the body (beside a curve, or past a face's end), and a spin of that body moves
/// it along n with nothing of the body there. A shape the contact query does not read keeps the
/// contact as before.
fn on_other_surface(
    g: &dyn Shape,
    s: Option<SupportShape>,
    pose: &Pose,
    toward: Vector,
    n: Vector,
    centre: Vector,
    witness: Vector,
) -> bool {
    let t = Vector::new(-n.y, n.x);
    let at = centre.dot(t);
    let size = g.compute_local_bounding_sphere();
    let margin = CROSSING_MARGIN * (size.radius + size.center.length() + centre.length() + witness.length());
    let off = (at - witness.dot(t)).abs();
    // NaN (absurd input) keeps the contact as it was.
    if off <= margin || off.is_nan() || margin.is_nan() {
        return true;
    }
    match s {
        Some(SupportShape::Polygon { vertices, normals, .. }) => {
            let len = vertices.len();
            normals.iter().enumerate().any(|(i, normal)| {
                (pose.rotation * *normal).dot(toward) >= FACE_COSINE && {
                    let (a, b) = ((*pose * vertices[i]).dot(t), (*pose * vertices[(i + 1) % len]).dot(t));
                    at >= a.min(b) - margin && at <= a.max(b) + margin
                }
            })
        }
        Some(_) => false,
        None => true,
    }
}

/// The rounding margin of [`on_other_surface`], of the sizes involved.
const CROSSING_MARGIN: f64 = 1e-9;

/// The cosine between a face's normal and the contact normal above which [`on_other_surface`]
/// takes the face as the one facing the core (a face contact's normal is the face's, to
/// rounding).
const FACE_COSINE: f64 = 1.0 - 1e-9;

/// Fills `manifold` with both bodies' core contacts ([`core_contacts`]) of a pair whose exact
/// contact is `c`, in a manifold of their own beside the exact points' (the normal of `c`), when
/// `with` (the pair has a contact point): speculative points that rapier's solver keeps only
/// when the bodies' velocities would close them within the step. Their ids are kept from the
/// previous points. False, with the manifold left as it was, when the normal is not finite in
/// body 2's frame.
pub(crate) fn core_manifold<M, C: Default + Copy>(
    pos12: &Pose,
    c: &Contact,
    cores: [Option<CoreContact>; 2],
    with: bool,
    manifold: &mut ContactManifold<M, C>,
) -> bool {
    let n2 = pos12.inverse_transform_vector(-c.normal);
    if !n2.is_finite() {
        return false;
    }
    let (old, n_old) = super::parry_pairs::previous_points(&manifold.points);
    manifold.clear();
    manifold.local_n1 = c.normal;
    manifold.local_n2 = n2;
    if with {
        for (k, code) in cores.iter().zip([CORE_FEATURE, CORE_FEATURE - 1]) {
            if let Some(k) = k {
                let id = vertex_id(code);
                let p2 = pos12.inverse_transform_point(k.point2);
                // A point that leaves f64 in body 2's frame (absurd input: a pose whose rotation
                // is not unit, a shape of 1e160) is left out rather than handed on.
                if p2.is_finite() {
                    manifold.points.push(TrackedContact::new(k.point1, p2, id, id, k.dist));
                }
            }
        }
    }
    manifold.match_contacts(&old[..n_old]);
    true
}

/// The feature code of a core contact on both bodies: the largest vertex code but one, which no
/// shape's vertex numbering reaches (body 2's core: the code below it).
pub(crate) const CORE_FEATURE: u32 = 0x3fff_fffe;

/// Whether a packed feature id (parry's `PackedFeatureId.0`, of the f64 or the f32 build) is a
/// core contact's: `CoreContactHooks` of both packages. Not a public API.
#[doc(hidden)]
pub fn is_core_feature(packed: u32) -> bool {
    packed == vertex_id(CORE_FEATURE).0 || packed == vertex_id(CORE_FEATURE - 1).0
}

/// A core contact ([`core_contact`]): its points on bodies 1 and 2 in body 1's frame, its gap
/// along the contact normal, the core's centre (body 1's frame) and radius, and its body (0 or
/// 1).
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) struct CoreContact {
    pub point1: Vector,
    pub point2: Vector,
    pub dist: f64,
    pub centre: Vector,
    /// The core's radius.
    pub radius: f64,
    pub body: usize,
}

impl CoreContact {
    /// Whether the two points `p` (of the core's body, body 1's frame) lie on either side of the
    /// core's centre along the tangent of the normal `n`: the centre's motion then shows in
    /// their own, and a two-point manifold keeps them both.
    pub(crate) fn straddled_by(&self, n: Vector, p: [Vector; 2]) -> bool {
        let t = Vector::new(-n.y, n.x);
        (p[0] - self.centre).dot(t) * (p[1] - self.centre).dot(t) <= 0.0
    }
}

/// [`core_of`] the support shape `s` of the shape `g`: a [`RoundedPolygon`]'s core as it was
/// stored when the polygon was built ([`RoundedPolygon::core`]: `polygon_core` of the same
/// vertices, normals and radius that `s` holds, so the same value to the bit), else computed.
pub(crate) fn core_of_shape(g: &dyn Shape, s: SupportShape) -> Option<Core> {
    match g.as_shape::<RoundedPolygon>() {
        Some(p) => p.core().and_then(usable),
        None => core_of(s),
    }
}

/// The core of any shape the dispatcher reads: [`core_of_shape`] of a shape the contact query
/// reads, a [`CustomCurve`]'s core computed when it was wrapped (its centroid and the distance
/// from it to the curve), `None` otherwise.
pub(crate) fn core_of_any(g: &dyn Shape) -> Option<Core> {
    let mut scratch = SupportScratch::default();
    match support_shape(g, &mut scratch) {
        Some(s) => core_of_shape(g, s),
        None => g.as_shape::<CustomCurve>().and_then(|c| c.core()).and_then(usable),
    }
}

/// The contact a manifold stands for: its normal and its deepest point (body 1's frame); `None`
/// when it has no point or no finite normal.
fn contact_of<M, C: Default + Copy>(pos12: &Pose, main: &ContactManifold<M, C>) -> Option<Contact> {
    let p = main.points.iter().min_by(|a, b| a.dist.total_cmp(&b.dist))?;
    let point = ContactPoint {
        point1: p.local_p1,
        point2: pos12 * p.local_p2,
        feature1: Feature::Vertex(0),
        feature2: Feature::Vertex(0),
        dist: p.dist,
    };
    main.local_n1.is_finite().then_some(Contact {
        dist: p.dist,
        normal: main.local_n1,
        points: [point; 2],
        len: 1,
    })
}

/// Fills `cores` (two manifolds) with both bodies' core contacts ([`core_disc_manifolds`]) of a
/// pair whose manifold `main` does not come from the exact contact query (a user's
/// [`CustomCurve`], a polygon of more than 16 vertices): each body's core by [`core_of_any`],
/// when `main` has a point. A spinning body whose contact points its spin carries off a wall
/// while its centre drives in is then held by the solver as the crate's own shapes are
/// (without them a user's curve spinning into a wall froze). `cores` are emptied when `main`
/// has no point or no finite normal.
pub(crate) fn core_manifold_of<M, C: Default + Copy>(
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    main: &ContactManifold<M, C>,
    cores: &mut [ContactManifold<M, C>],
) {
    let Some(c) = contact_of(pos12, main) else {
        cores.iter_mut().for_each(|m| m.clear());
        return;
    };
    let k = [core_of_any(g1), core_of_any(g2)];
    let (mut st1, mut st2) = (SupportScratch::default(), SupportScratch::default());
    let supports = [support_shape(g1, &mut st1), support_shape(g2, &mut st2)];
    if !core_disc_manifolds(pos12, [g1, g2], supports, k, &c, true, cores) {
        cores.iter_mut().for_each(|m| m.clear());
    }
}

/// The core contact of the smaller body of a pair (by each shape's bounding circle's reach about
/// its core's centre, as [`core_contact`] chooses) whose manifold does not come from the exact
/// contact query, from its normal and deepest point, put into `manifold` as the exact path puts
/// it for a part of a composite shape ([`insert_core_point`]): a user's curve against the
/// segments of a polyline, the triangles of a mesh, the parts of a compound.
pub(crate) fn add_part_core<M, C: Default + Copy>(
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    prediction: Real,
    manifold: &mut ContactManifold<M, C>,
    own: Option<&mut ContactManifold<M, C>>,
) {
    let Some(c) = contact_of(pos12, manifold) else {
        if let Some(m) = own {
            m.clear();
        }
        return;
    };
    let cores = [core_of_any(g1), core_of_any(g2)];
    let reach = |g: &dyn Shape, k: Option<Core>| {
        let s = g.compute_local_bounding_sphere();
        s.radius + (s.center - k.map_or(Vector::ZERO, |k| k.centre)).length()
    };
    let k = match core_contacts(cores, pos12, &c) {
        [Some(a), Some(b)] => Some(if reach(g2, cores[1]) < reach(g1, cores[0]) {
            b
        } else {
            a
        }),
        [a, b] => a.or(b),
    };
    place_part_core(pos12, c.normal, k, prediction, manifold, own);
}

/// Places the core contact `k` (if any) of a part of a composite shape whose manifold is
/// `manifold` (its points the pair's, its normal `n` in body 1's frame): with no manifold of its
/// own (`own` is `None`: parry's composite helpers, one manifold a part), into `manifold` by
/// [`insert_core_point`]; with one (the dispatcher's own bookkeeping of a composite against a
/// convex shape, two manifolds a part), beside a lone point as [`insert_core_point`] puts it,
/// and where [`insert_core_point`] would take the place of the second of two points, into `own`
/// instead, both points kept (a face that a spin turns into the part keeps its speculative far
/// point, which rapier's solver takes when the velocities close it within the step). `own` is
/// emptied otherwise; its point keeps its id's impulse from the last call while it stays in `own`
/// (rapier's warm start; a core contact that moves between the points' manifold, beside a lone
/// point, and `own` starts afresh). (Tried the other way round, the core contact in place of the
/// far point and the far point in `own`: the CCD scene suite's chain box took 4 % more
/// instructions, not fewer.)
pub(crate) fn place_part_core<M, C: Default + Copy>(
    pos12: &Pose,
    n: Vector,
    k: Option<CoreContact>,
    prediction: Real,
    manifold: &mut ContactManifold<M, C>,
    own: Option<&mut ContactManifold<M, C>>,
) {
    let Some(own) = own else {
        if let Some(k) = k {
            insert_core_point(pos12, n, k, prediction, manifold);
        }
        return;
    };
    let (old, n_old) = super::parry_pairs::previous_points(&own.points);
    own.clear();
    match k {
        Some(k) if manifold.points.len() > 1 => {
            let p2 = pos12.inverse_transform_point(k.point2);
            let n2 = pos12.inverse_transform_vector(-n);
            if p2.is_finite() && n2.is_finite() && replaces_second(pos12, n, &k, prediction, manifold) {
                own.local_n1 = n;
                own.local_n2 = n2;
                let id = vertex_id(CORE_FEATURE);
                own.points.push(TrackedContact::new(k.point1, p2, id, id, k.dist));
            }
        }
        Some(k) => insert_core_point(pos12, n, k, prediction, manifold),
        None => {}
    }
    own.match_contacts(&old[..n_old]);
}

/// Whether the core contact `k` of a two-point manifold takes the place of its second point
/// ([`insert_core_point`]): unless the two points straddle the core's centre along the tangent
/// with the second within the prediction (a flat side resting on a part keeps both its ends,
/// which hold its centre).
fn replaces_second<M, C: Default + Copy>(
    pos12: &Pose,
    n: Vector,
    k: &CoreContact,
    prediction: Real,
    manifold: &ContactManifold<M, C>,
) -> bool {
    // The points on the core's body.
    let on_body = |p: &TrackedContact<C>| {
        if k.body == 0 {
            p.local_p1
        } else {
            pos12 * p.local_p2
        }
    };
    let pts = [on_body(&manifold.points[0]), on_body(&manifold.points[1])];
    !k.straddled_by(n, pts) || manifold.points[1].dist > prediction
}

/// Puts the core contact `k` of a pair with normal `n` (body 1's frame) into `manifold`, whose
/// points are the pair's: beside a lone point; in place of the second of two unless the two
/// straddle the core's centre along the tangent with the second within the prediction (a flat
/// side resting on a part keeps both its ends). Nothing when the manifold has no point or the
/// core's point is not finite in body 2's frame.
pub(crate) fn insert_core_point<M, C: Default + Copy>(
    pos12: &Pose,
    n: Vector,
    k: CoreContact,
    prediction: Real,
    manifold: &mut ContactManifold<M, C>,
) {
    let p2 = pos12.inverse_transform_point(k.point2);
    // Nothing to add to no point, nor a point that leaves f64 in body 2's frame.
    if manifold.points.is_empty() || !p2.is_finite() {
        return;
    }
    let core_point = TrackedContact::new(k.point1, p2, vertex_id(CORE_FEATURE), vertex_id(CORE_FEATURE), k.dist);
    match manifold.points.len() {
        1 => manifold.points.push(core_point),
        _ => {
            if replaces_second(pos12, n, &k, prediction, manifold) {
                manifold.points[1] = core_point;
            }
        }
    }
}

/// A core with a finite centre and a finite radius ≥ 0, else `None`.
fn usable(core: Core) -> Option<Core> {
    (core.centre.is_finite() && core.radius.is_finite() && core.radius >= 0.0).then_some(core)
}

/// The core of a shape the contact query reads; `None` for a degenerate polygon (no area).
pub(crate) fn core_of(s: SupportShape) -> Option<Core> {
    let core = match s {
        SupportShape::Disc(r) => Core {
            centre: Vector::ZERO,
            radius: r,
        },
        SupportShape::Ellipse(a, b) => Core {
            centre: Vector::ZERO,
            radius: a.min(b),
        },
        SupportShape::Polygon {
            vertices,
            normals,
            radius,
        } => polygon_core(vertices, normals, radius)?,
        SupportShape::CapsuleEllipse(r1, r2, r3) => capsule_ellipse_core(r1, r2, r3),
    };
    usable(core)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};
    use parry2d_f64::shape::{Ball, Cuboid, Segment, Shape};

    /// The centroid of parry's mass properties and, the reference's radius, the smallest
    /// support value about it over 200,000 directions (the distance from an inner point to the
    /// boundary of a convex shape is the minimum of its support function about the point).
    fn reference(s: &dyn Shape) -> Core {
        let centre = s.mass_properties(1.0).local_com;
        assert!(s.contains_local_point(centre));
        let sm = s.as_support_map().unwrap();
        let radius = (0..200_000)
            .map(|k| {
                let a = core::f64::consts::TAU * k as f64 / 200_000.0;
                let u = Vector::new(a.cos(), a.sin());
                (sm.local_support_point(u) - centre).dot(u)
            })
            .fold(f64::INFINITY, f64::min);
        Core { centre, radius }
    }

    #[test]
    fn cores_are_the_centroid_and_its_distance_to_the_boundary() {
        let shapes: Vec<Box<dyn Shape>> = vec![
            Box::new(Ellipse::new(0.5, 0.2)),
            Box::new(Ellipse::new(0.3, 0.3)),
            Box::new(RoundedPolygon::regular(7, 0.4, 0.06)),
            Box::new(RoundedPolygon::regular(4, 0.35, 0.0)),
            Box::new(RoundedPolygon::new(
                &[Vector::new(-0.5, 0.0), Vector::new(-0.25, 0.0), Vector::new(0.5, 0.125)],
                0.0,
            )),
            Box::new(RoundedPolygon::new(
                &[Vector::new(0.3, -0.2), Vector::new(2.1, 0.1), Vector::new(1.2, 1.4)],
                0.2,
            )),
            Box::new(CapsuleEllipse::new(0.12, 0.15, 0.3)),
            Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8)),
            Box::new(CapsuleEllipse::new(0.3, 0.05, 2.0)),
            Box::new(Ball::new(0.7)),
            Box::new(Cuboid::new(Vector::new(0.6, 0.25))),
        ];
        for s in &shapes {
            let mut scratch = SupportScratch::default();
            let ours = core_of(support_shape(&**s, &mut scratch).unwrap()).unwrap();
            let want = reference(&**s);
            let size = s.compute_local_bounding_sphere().radius;
            assert!(
                (ours.centre - want.centre).length() <= 1e-12 * size,
                "{:?}: centre {:?} vs {:?}",
                s.shape_type(),
                ours.centre,
                want.centre
            );
            // Sampling overestimates the minimum by at most the support function's slope
            // (≤ the size) times half the spacing of the directions.
            let sampling = core::f64::consts::PI / 200_000.0 * 2.0 * size;
            assert!(
                ours.radius <= want.radius + 1e-12 * size && want.radius - ours.radius <= sampling,
                "{:?}: radius {} vs {}",
                s.shape_type(),
                ours.radius,
                want.radius
            );
        }
        // A segment has no inside: its core is its midpoint with radius 0 — exactly, at every
        // angle (the rounding of a tilted segment's dot products once gave it a radius of 1e-17,
        // and the manifolds a core contact at its midpoint: a ghost support under a wheel on a
        // chain of them, where the wheel is not).
        let mut scratch = SupportScratch::default();
        let seg = Segment::new(Vector::new(-1.0, 2.0), Vector::new(3.0, 2.0));
        let core = core_of(support_shape(&seg, &mut scratch).unwrap()).unwrap();
        assert_eq!(core.centre, Vector::new(1.0, 2.0));
        assert_eq!(core.radius, 0.0);
        let mut positive_before = 0;
        for k in 0..1000 {
            let angle = 0.0123 * k as f64;
            let (a, b) = (
                Vector::new(-2.4, 0.3 * angle.sin()),
                Vector::new(-2.4 + 0.2 * angle.cos(), 0.2 * angle.sin()),
            );
            let (mut scratch, seg) = (SupportScratch::default(), Segment::new(a, b));
            let SupportShape::Polygon { vertices, normals, .. } = support_shape(&seg, &mut scratch).unwrap() else {
                panic!("a segment is a polygon of two vertices");
            };
            let c = (a + b) / 2.0;
            positive_before += usize::from(
                (0..2)
                    .map(|i| normals[i].dot(vertices[i] - c))
                    .fold(f64::INFINITY, f64::min)
                    > 0.0,
            );
            let mut scratch = SupportScratch::default();
            let core = core_of(support_shape(&seg, &mut scratch).unwrap()).unwrap();
            assert_eq!(core.radius, 0.0, "segment {a:?} – {b:?}");
        }
        // The rounding the old formula read as a radius, on this sample.
        assert!(positive_before > 0);
    }

    /// A user's curve wrapping one of the crate's shapes has that shape's core: the centroid
    /// of its integrated mass and the projected distance to the curve, against the closed forms.
    #[test]
    fn a_user_curves_core_is_the_core_of_the_shape_it_wraps() {
        /// A shape, and the same shape wrapped as a user's curve.
        type Pair = (&'static str, Box<dyn Shape>, Box<dyn Shape>);
        let shapes: [Pair; 3] = [
            (
                "ellipse",
                Box::new(Ellipse::new(0.5, 0.2)),
                Box::new(CustomCurve::new(Ellipse::new(0.5, 0.2))),
            ),
            (
                "rounded heptagon",
                Box::new(RoundedPolygon::regular(7, 1.0, 0.15)),
                Box::new(CustomCurve::new(RoundedPolygon::regular(7, 1.0, 0.15))),
            ),
            (
                "capsule-ellipse",
                Box::new(CapsuleEllipse::new(0.3, 0.6, 0.8)),
                Box::new(CustomCurve::new(CapsuleEllipse::new(0.3, 0.6, 0.8))),
            ),
        ];
        for (name, own, custom) in &shapes {
            let (a, b) = (core_of_any(&**own).unwrap(), core_of_any(&**custom).unwrap());
            assert!(
                (a.centre - b.centre).length() < 1e-9,
                "{name}: {:?} vs {:?}",
                a.centre,
                b.centre
            );
            assert!(
                (a.radius - b.radius).abs() < 1e-9,
                "{name}: {} vs {}",
                a.radius,
                b.radius
            );
        }
        // A shape the dispatcher does not read has none.
        assert!(core_of_any(&parry2d_f64::shape::HalfSpace::new(Vector::Y)).is_none());
    }
}
