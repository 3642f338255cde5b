//! The certificate of a crossing: at a time where the separation along an axis comes down to
//! the level, an upper bound of the signed distance from a support point's projection, which
//! settles the time of impact without a contact query when it is within the tolerance (module
//! docs of `query::advance`).

use super::project::project_on;
use crate::numerics::math::{Pose, Real, Vector};
use crate::query::contact::{Contact, SupportShape};
use parry2d_f64::shape::Shape;

/// A distance with its normal and witness points, all in A's frame.
#[derive(Copy, Clone)]
pub(super) struct Witnesses {
    pub dist: Real,
    pub normal: Vector,
    pub point_a: Vector,
    pub point_b: Vector,
}

impl Witnesses {
    pub(super) fn of(c: &Contact) -> Self {
        Witnesses {
            dist: c.dist,
            normal: c.normal,
            point_a: c.points[0].point1,
            point_b: c.points[0].point2,
        }
    }
}

/// The two shapes of a query as parry has them (A first), for the certificate of a crossing.
#[derive(Copy, Clone)]
pub(super) struct Parry<'a> {
    pub a: &'a dyn Shape,
    pub b: &'a dyn Shape,
    /// A and B as the contact query reads them: a polygon or a disc is projected on exactly
    /// (`project`), any other shape by its own projection.
    pub sa: SupportShape<'a>,
    pub sb: SupportShape<'a>,
    /// Whether B is a polygon (dilated or not).
    pub b_polygonal: bool,
}

/// At a crossing of S_n (B at `pose` in A's frame, `n` the axis), an upper bound of the signed
/// distance without a contact query: the distance from B's lowest point along n to A (or from
/// A's highest point along n to B) is at least D. When it is at most `enough` (the target and
/// the tolerance) the crossing is the time of impact (D is between S_n and it), with these
/// witnesses; otherwise the contact query decides.
pub(super) fn certificate(g: Parry, pose: &Pose, n: Vector, enough: Real) -> Option<Witnesses> {
    let (sa, sb) = (g.a.as_support_map()?, g.b.as_support_map()?);
    let ok = |w: &Witnesses| w.dist.is_finite() && w.point_a.is_finite() && w.point_b.is_finite();
    // A point's projection on a shape: exact for a polygon or a disc (parry's projection on a
    // support map works to absolute tolerances), the shape's own for this crate's curves.
    let project = |s: SupportShape, shape: &dyn Shape, p: Vector| {
        project_on(s, p).or_else(|| {
            let proj = shape.project_local_point(p, true);
            Some((proj.point, proj.is_inside))
        })
    };
    // B's lowest point along n, projected on A (a point of A on the axis when A's face holds it).
    let point_b = *pose * sb.local_support_point(pose.rotation.inverse() * -n);
    let (on_a, inside) = project(g.sa, g.a, point_b)?;
    let by_b = Witnesses {
        dist: if inside { 0.0 } else { (point_b - on_a).length() },
        normal: n,
        point_a: on_a,
        point_b,
    };
    if by_b.dist <= enough && ok(&by_b) {
        return Some(by_b);
    }
    // A's highest point along n, projected on B (B's face holds it): for a polygon B, whose
    // projection is cheap; a curved B's projection costs a contact query's time.
    if !g.b_polygonal {
        return None;
    }
    let point_a = sa.local_support_point(n);
    let local = pose.inverse_transform_point(point_a);
    let (on_b, inside) = project(g.sb, g.b, local)?;
    let by_a = Witnesses {
        dist: if inside { 0.0 } else { (local - on_b).length() },
        normal: n,
        point_a,
        point_b: *pose * on_b,
    };
    (by_a.dist <= enough && ok(&by_a)).then_some(by_a)
}
