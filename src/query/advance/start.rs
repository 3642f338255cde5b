//! Where the advancement starts: the exact contact at the window's start, or the face normal of
//! the body at rest along which the pair is furthest apart ([`face_separation`]).

use super::{lowest_piece, turning_of, PairOnPath};
use crate::numerics::math::{Real, Vector};
use crate::query::contact::{Contact, SupportShape, MAX_BREAKPOINTS};

/// Where an advancement starts at t₀: from the exact contact there (the caller's, or computed),
/// or from a separating axis fixed in A's frame ([`face_separation`]) — any separating axis
/// bounds the distance from below, so the steps along it are safe whichever it is; the exact
/// normal only makes the first crossing the closest one.
#[derive(Copy, Clone)]
pub(crate) enum Start {
    /// The exact contact at t₀ (shape 1 first), or `None` to compute it.
    Contact(Option<Contact>),
    /// A unit axis n in A's frame (from A towards B) with A's support h_A(n) along it, the
    /// pair apart along it by more than the tolerance at t₀.
    Axis { n: Vector, support: Real },
}

/// The largest separation of the pair at path time `t` along A's face normals (A the body of
/// `pair` that does not turn, `s1`, `s2` in the caller's order): the advancement's start along
/// it ([`Start::Axis`]) and the separation S_n(t) = min over B of n·q − h_A(n) (module docs), a
/// lower bound of the signed distance. The separating-axis theorem makes it the signed distance
/// itself when a vertex or an arc of B is nearest a face of A, the usual start of a body flying
/// at a wall; the advancement from it then takes the exact contact's own first axis without the
/// contact query. (B's faces, turning with it, were tried as well: more instructions a cast on
/// every body kind, their scan costing more than the contacts it saved.) `None` where A is not
/// a polygon with at least two faces, a polygon has more vertices than the contact query reads
/// ([`MAX_BREAKPOINTS`]), or a value is not finite.
pub(crate) fn face_separation(s1: SupportShape, s2: SupportShape, pair: &PairOnPath, t: Real) -> Option<(Start, Real)> {
    let (sa, sb) = pair.ordered(s1, s2);
    let SupportShape::Polygon {
        vertices,
        normals,
        radius,
    } = sa
    else {
        return None;
    };
    let turning = turning_of(sb, pair.k.centre)?;
    // Polygons of the contact query's size only (the scan is |A's faces| × |B's vertices|; a
    // polygon of 100,000 sides goes to the trackers as before).
    let small = |s: SupportShape| match s {
        SupportShape::Polygon { vertices, .. } => vertices.len() <= MAX_BREAKPOINTS,
        _ => true,
    };
    if normals.len() < 2 || !(small(sa) && small(sb)) {
        return None;
    }
    let mut best: Option<(Start, Real)> = None;
    for n in normals {
        let support = vertices.iter().map(|v| v.dot(*n)).fold(Real::NEG_INFINITY, Real::max) + radius;
        let sep = lowest_piece(turning, &pair.k, *n, support, t).0;
        if !(sep.is_finite() && support.is_finite()) {
            return None;
        }
        if best.is_none_or(|b| sep > b.1) {
            best = Some((Start::Axis { n: *n, support }, sep));
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::math::{perp, Pose};
    use crate::query::advance::test_shapes::{random_pair, TestShapes};
    use crate::query::contact::contact;
    use crate::query::path::OnPath;
    use crate::MotionPath;
    use core::f64::consts::PI;
    use parry2d_f64::query::NonlinearRigidMotion;

    /// The start's separation is a lower bound of the exact signed distance on random poses
    /// (what makes the advancement from it safe), and equals it where a vertex of the body is
    /// nearest a face of the target (what makes it the exact contact's own first axis).
    #[test]
    fn the_face_separation_bounds_the_distance_and_meets_it_at_a_face() {
        let shapes = TestShapes::new();
        let target = shapes.flat_box();
        let bodies = shapes.bodies();
        let mut rng = crate::numerics::test_rng::Lcg(0x2545_F491_4F6C_DD1Du64);
        let mut uniform = |lo: Real, hi: Real| rng.range(lo, hi);
        let (mut cases, mut exact) = (0, 0);
        for &body in &bodies {
            for _ in 0..2000 {
                let (_, pair) = random_pair(&mut uniform, None);
                let (start, sep) = face_separation(target, body, &pair, 0.0).unwrap();
                assert!(matches!(start, Start::Axis { .. }));
                let d = contact(target, body, &pair.k.pose(0.0), 2.0, None).unwrap().dist;
                assert!(sep <= d + 1e-12, "separation {sep} above the distance {d}");
                cases += 1;
                if d - sep <= 1e-12 {
                    exact += 1;
                }
            }
        }
        println!("{exact} of {cases} starts at the exact distance");
        assert!(exact * 4 > cases, "{exact} of {cases}");
    }

    #[test]
    fn a_target_without_faces_or_a_polygon_beyond_the_contact_query_has_no_face_start() {
        let ma = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
        let mb = NonlinearRigidMotion::new(Pose::new(Vector::new(3.0, 0.0), 0.0), Vector::ZERO, -Vector::X, 1.0);
        let on = OnPath::new(&ma, &mb, 0.0, 1.0, MotionPath::Nlerp).unwrap();
        let pair = PairOnPath::of(&on).unwrap();
        let body = SupportShape::Ellipse(0.5, 0.2);
        assert!(face_separation(SupportShape::Disc(1.0), body, &pair, 0.0).is_none());
        let n = MAX_BREAKPOINTS + 1;
        let v: Vec<Vector> = (0..n)
            .map(|i| {
                let a = 2.0 * PI * i as Real / n as Real;
                Vector::new(a.cos(), a.sin())
            })
            .collect();
        let normals: Vec<Vector> = (0..n).map(|i| -perp(v[(i + 1) % n] - v[i]).normalize()).collect();
        let big = SupportShape::Polygon {
            vertices: &v,
            normals: &normals,
            radius: 0.0,
        };
        assert!(face_separation(big, body, &pair, 0.0).is_none());
    }
}
