//! The contact of a body with a wall of no thickness (a parry `Segment`, standalone or a part of
//! a polyline) from the side the body's centre is on.
//!
//! A segment has no inside, so the exact contact query's normal — the direction of the least
//! translation that separates the shapes — may point to either side of it: a body sunk past
//! the middle of its own thickness is pushed *through* the wall, and a thin body wedged into the
//! apex of two segments is pushed out through the apex (their shared end), where the body
//! cannot go. rapier's CCD under this crate's rule keeps a body's centre on its own side of
//! every wall (its *core*, `rapier_rule`), so that side is the one the body came from. When the
//! centre lies over the segment (its projection falls between the ends) and the exact normal
//! is not the segment's normal on the centre's side, the contact is taken against the
//! segment's line from the centre's side instead: the normal is the line's
//! normal towards the centre, the depth is how far the body reaches past the line (its support
//! along the other normal), the point is the body's deepest point and its foot on the line —
//! if that foot lies on the segment. When the foot lies beyond an end, the depth is how far
//! the body reaches past the line over the segment, greatest at that end (`beyond_end`: a thin
//! body wedged past the apex of two segments is pushed back into the wedge, not out through
//! the apex); a body that reaches past the line only beyond the end touches the end from
//! beyond it, as the exact contact has it. A contact along the segment's normal (a body on
//! the segment's face, where the exact manifold has its two points) is kept.

use crate::numerics::math::{perp, Pose, Real, Vector};
use crate::query::contact::{Contact, ContactPoint, Feature};
use parry2d_f64::query::Ray;
use parry2d_f64::shape::{Segment, Shape};

/// The contact `c` of `g1` (at the origin) and `g2` (at `pos12`), one of them a `Segment`, with
/// its normal from the centre's side (module docs); `c` itself otherwise. `centre1`, `centre2`:
/// the bodies' centroids in their own frames.
pub(crate) fn from_centre_side(
    c: Contact,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    centre1: Vector,
    centre2: Vector,
) -> Contact {
    centre_side_contact(&c, pos12, g1, g2, centre1, centre2).unwrap_or(c)
}

/// The contact from the centre's side of [`from_centre_side`] where it differs from the exact
/// contact `c` (module docs), `None` where `c` stands: neither shape a `Segment`, the centre not
/// over the segment, a contact along the segment's normal, or a body not reaching past the
/// line over the segment.
pub(crate) fn centre_side_contact(
    c: &Contact,
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    centre1: Vector,
    centre2: Vector,
) -> Option<Contact> {
    if let Some(seg) = g1.as_shape::<Segment>() {
        // The body is shape 2, at pos12 in the segment's frame.
        one_sided(seg, g2, pos12, pos12 * centre2, c.normal).map(|(normal, dist, on_seg, on_body)| Contact {
            dist,
            normal,
            points: [point(on_seg, on_body, dist, Feature::Face(0), Feature::Vertex(0)); 2],
            len: 1,
        })
    } else if let Some(seg) = g2.as_shape::<Segment>() {
        // The body is shape 1; work in the segment's frame and come back.
        let pos21 = pos12.inverse();
        one_sided(seg, g1, &pos21, pos21 * centre1, pos21.rotation * -c.normal).map(
            |(normal, dist, on_seg, on_body)| {
                let (on_seg, on_body) = (*pos12 * on_seg, *pos12 * on_body);
                Contact {
                    dist,
                    normal: pos12.rotation * -normal,
                    points: [point(on_body, on_seg, dist, Feature::Vertex(0), Feature::Face(0)); 2],
                    len: 1,
                }
            },
        )
    } else {
        None
    }
}

fn point(point1: Vector, point2: Vector, dist: Real, feature1: Feature, feature2: Feature) -> ContactPoint {
    ContactPoint {
        point1,
        point2,
        feature1,
        feature2,
        dist,
    }
}

/// The cosine of the largest angle between the exact normal and the wall's normal (towards the
/// body's centre) that keeps the exact contact: the exact normal *is* the wall's (a body on the
/// segment's face, with the exact manifold's two points). Any other normal, with the body
/// reaching past the wall's line over the wall, pushes it along or through the wall, or out
/// past an end it cannot pass (the apex of two segments).
const LEAN_COS: Real = 1.0 - 1e-9;

/// In the segment's frame, with the body at `pose`, its centre at `centre` and the exact
/// contact's normal `n` (from the segment to the body): the one-sided contact (normal, signed
/// distance, point on the segment, point on the body, all in the segment's frame) when the
/// centre lies over the segment, the exact normal is not the segment's normal towards the
/// centre, and the body's deepest point past the segment's line lies over the
/// segment too; `None` otherwise.
fn one_sided(
    seg: &Segment,
    body: &dyn Shape,
    pose: &Pose,
    centre: Vector,
    n: Vector,
) -> Option<(Vector, Real, Vector, Vector)> {
    let along = seg.b - seg.a;
    let len2 = along.length_squared();
    if !(len2 > 0.0 && len2.is_finite()) {
        return None;
    }
    let s = (centre - seg.a).dot(along) / len2;
    let mut m = perp(along / len2.sqrt());
    let side = (centre - seg.a).dot(m);
    if side < 0.0 {
        m = -m;
    }
    if !(0.0..=1.0).contains(&s) || side == 0.0 || n.dot(m) >= LEAN_COS {
        return None;
    }
    // The body's deepest point past the line: its support along −m.
    let sm = body.as_support_map()?;
    let p = *pose * sm.local_support_point(pose.rotation.inverse() * -m);
    let dist = (p - seg.a).dot(m);
    let foot = p - m * dist;
    let t = (foot - seg.a).dot(along) / len2;
    if (0.0..=1.0).contains(&t) {
        return (dist.is_finite() && p.is_finite()).then_some((m, dist, foot, p));
    }
    let unit = along / len2.sqrt();
    if t < 0.0 {
        beyond_end(body, pose, seg.a, -unit, m)
    } else {
        beyond_end(body, pose, seg.b, unit, m)
    }
}

/// The one-sided contact (as [`one_sided`]) of a body whose deepest point past the segment's
/// line lies beyond the segment's end `end` (`along`: the unit direction of the segment
/// towards that end), or `None` when the body does not reach past the line over the segment
/// (it touches the end from beyond, as a free end is touched: the exact contact stands).
///
/// With h the height past the line (along −m) and τ the position along it, the body's upper
/// boundary U(τ) (its highest point over τ) is concave where the body spans τ, greatest at the
/// deepest point's foot τ*, beyond the end here: U grows towards the end over the segment. A
/// translation δ along m clears the segment when δ ≥ U(τ) for every τ of the segment the body
/// spans, so the depth is −max U over them: U at the end when the body spans the end's τ (the
/// ray along m from beyond the line down through the end enters the body at that height —
/// whether the end is inside the body, a body straddling the apex of two segments, or below
/// it, a thin body past the apex), else U at the body's extreme point towards the end.
fn beyond_end(
    body: &dyn Shape,
    pose: &Pose,
    end: Vector,
    along: Vector,
    m: Vector,
) -> Option<(Vector, Real, Vector, Vector)> {
    let sm = body.as_support_map()?;
    let height = |p: Vector| (p - end).dot(-m);
    // The body's extreme point towards the end, and whether the body spans the end's τ.
    let q = *pose * sm.local_support_point(pose.rotation.inverse() * along);
    let (on_body, h) = if (q - end).dot(along) <= 0.0 {
        (q, height(q))
    } else {
        // Down along m from beyond the body's reach: the entry point is U at the end.
        let reach = body.compute_local_bounding_sphere();
        let far = (pose * reach.center - end).length() + reach.radius;
        let from = end - m * (2.0 * far);
        let ray = Ray::new(pose.inverse_transform_point(from), pose.rotation.inverse() * m);
        let toi = body.cast_local_ray(&ray, 4.0 * far, true)?;
        let p = from + m * toi;
        (p, height(p))
    };
    let foot = on_body + m * h;
    (h > 0.0 && h.is_finite() && on_body.is_finite()).then_some((m, -h, foot, on_body))
}
