//! Pairs certainly further apart than a level, told before any exact query: by their bounding
//! circles, and — for a contact manifold asked beyond the prediction distance, as rapier's broad
//! phase asks for a fast body and whatever its swept box meets — by separating axes
//! (`query::contact::separation`).

use super::input_guard;
use crate::numerics::math::{Pose, Real, Vector};
use crate::query::contact::separation::apart_beyond;
use crate::query::contact::SupportShape;
use parry2d_f64::bounding_volume::BoundingSphere;
use parry2d_f64::shape::{HalfSpace, Shape};

/// True when the bounding circles are further apart than `margin` (never for a half-space).
pub(super) fn far_apart(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, margin: Real) -> bool {
    if g1.as_shape::<HalfSpace>().is_some() || g2.as_shape::<HalfSpace>().is_some() {
        return false;
    }
    spheres_apart(pos12, g1, g2, margin)
}

/// True when the bounding circles of two bounded shapes are further apart than `margin`. Never
/// for a non-finite pose (whose distance ∞ would read as apart: it goes on to the checks that
/// refuse it, issue 32); an infinite distance from a finite pose (an overflow) is apart.
fn spheres_apart(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, margin: Real) -> bool {
    circles_apart(pos12, &circles(pos12, g1, g2), margin)
}

/// The bounding circles of `g1` (at the origin) and `g2` (at `pos12`), in body 1's frame.
pub(super) fn circles(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> [BoundingSphere; 2] {
    [g1.compute_local_bounding_sphere(), g2.compute_bounding_sphere(pos12)]
}

/// [`spheres_apart`] of the circles `b` ([`circles`]).
pub(super) fn circles_apart(pos12: &Pose, b: &[BoundingSphere; 2], margin: Real) -> bool {
    let gap = (b[1].center - b[0].center).length() - b[0].radius - b[1].radius;
    gap > margin && (gap.is_finite() || pos12.is_finite())
}

/// Whether the exact contact of the shapes `s1` (at the origin) and `s2` (at `pos12`) is
/// certainly farther than `prediction`, with `b` their bounding circles ([`circles`]): the
/// separation along the pair's last contact normal `last` (the manifold's, kept from its
/// previous call) or along the line of the circles' centres exceeds it
/// (`query::contact::separation`). Both of the pair's manifolds then come out empty, as the
/// exact contact would leave them, but for their normal, which stays the previous call's. A
/// manifold without points has its normal read by nothing but the warm start of the contact of
/// two shapes with ellipse pieces ([`crate::SmoothDispatcher::warm_start`]), so such pairs are not
/// taken: every answer is the same to the bit. Any unit axis bounds the distance from below, so
/// a normal left by another pose or another order of the pair is no error, only a weaker
/// bound. The exact contact is skipped only where it would answer (a pose and shapes it reads,
/// within parry's coordinate range).
pub(super) fn beyond_prediction(
    s1: SupportShape,
    s2: SupportShape,
    pos12: &Pose,
    b: &[BoundingSphere; 2],
    last: Vector,
    prediction: Real,
) -> bool {
    let curved = |s: &SupportShape| matches!(s, SupportShape::Ellipse(..) | SupportShape::CapsuleEllipse(..));
    if (curved(&s1) && curved(&s2)) || !input_guard::pose_ok(pos12) {
        return false;
    }
    let line = b[1].center - b[0].center;
    let reach = |b: &BoundingSphere, origin: Vector| b.radius + (b.center - origin).length();
    let scale = line.length() + reach(&b[0], Vector::ZERO) + reach(&b[1], pos12.translation);
    // Within parry's coordinate range, where the exact contact's products stay finite and it
    // answers the pair (the input it refuses goes on to the checks that refuse it).
    scale <= input_guard::PARRY_MAX_COORDINATE
        && apart_beyond(s1, s2, pos12, &[last, line.normalize_or_zero()], prediction, scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CapsuleEllipse, Ellipse, RoundedPolygon, SmoothDispatcher};
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher, QueryDispatcher};
    use parry2d_f64::shape::{Cuboid, Segment};

    #[test]
    fn manifolds_skipped_beyond_the_prediction_are_empty_exactly_where_the_contact_is_beyond_it() {
        let d = SmoothDispatcher::default();
        let ours: [Box<dyn Shape>; 3] = [
            Box::new(RoundedPolygon::regular(5, 0.4, 0.05)),
            Box::new(Ellipse::new(0.5, 0.2)),
            Box::new(CapsuleEllipse::new(0.12, 0.15, 0.3)),
        ];
        let others: [Box<dyn Shape>; 3] = [
            Box::new(Segment::new(Vector::new(-2.0, 0.0), Vector::new(2.0, 0.0))),
            Box::new(Cuboid::new(Vector::new(0.3, 1.0))),
            Box::new(RoundedPolygon::regular(3, 0.5, 0.0)),
        ];
        let prediction = 0.02;
        let (mut steps, mut skipped) = (0, 0);
        for a in &ours {
            for b in &others {
                let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
                let mut workspace = None;
                let (mut st1, mut st2) = Default::default();
                let s1 = crate::dispatcher::support_shape::support_shape(&**b, &mut st1).unwrap();
                let s2 = crate::dispatcher::support_shape::support_shape(&**a, &mut st2).unwrap();
                // Body 2 passes over body 1 and back, turning, from far to touching to far.
                for k in 0..600 {
                    let s = k as Real / 600.0;
                    let x = 3.0 * (std::f64::consts::TAU * s).cos();
                    let y = 0.9 + 0.8 * (3.0 * std::f64::consts::TAU * s).sin();
                    let pos12 = Pose::new(Vector::new(x, y), 5.0 * s);
                    // Whether this call takes the skip (the exact manifold's own test).
                    let c = circles(&pos12, &**b, &**a);
                    let last = manifolds.first().map_or(Vector::ZERO, |m| m.local_n1);
                    let was_apart = manifolds.first().is_none_or(|m| m.points.is_empty());
                    if !circles_apart(&pos12, &c, prediction)
                        && was_apart
                        && beyond_prediction(s1, s2, &pos12, &c, last, prediction)
                    {
                        skipped += 1;
                    }
                    d.contact_manifolds(&pos12, &**b, &**a, prediction, &mut manifolds, &mut workspace)
                        .unwrap();
                    let contact = d.contact(&pos12, &**b, &**a, prediction).unwrap();
                    assert_eq!(manifolds[0].points.is_empty(), contact.is_none(), "step {k}");
                    if manifolds[0].points.is_empty() {
                        assert!(
                            manifolds[1].points.is_empty(),
                            "core contacts without a contact, step {k}"
                        );
                    } else if b.as_shape::<Segment>().is_none() {
                        let deepest = manifolds[0]
                            .points
                            .iter()
                            .map(|p| p.dist)
                            .fold(Real::INFINITY, Real::min);
                        assert!((deepest - contact.unwrap().dist).abs() <= 1e-12, "step {k}");
                    }
                    steps += 1;
                }
            }
        }
        assert_eq!(steps, 5400);
        // The path spends many steps beside the other shape but beyond the prediction.
        assert!(skipped > 500, "{skipped} calls skipped the exact contact");
    }

    #[test]
    fn a_pair_apart_along_its_last_normal_or_its_line_of_centres_is_beyond_the_prediction() {
        let square = RoundedPolygon::regular(4, 0.5, 0.0);
        let ellipse = Ellipse::new(0.5, 0.2);
        let (mut st1, mut st2) = Default::default();
        let s1 = crate::dispatcher::support_shape::support_shape(&square, &mut st1).unwrap();
        let s2 = crate::dispatcher::support_shape::support_shape(&ellipse, &mut st2).unwrap();
        // The ellipse's end 0.1 beyond the square's corner on +x.
        let pos12 = Pose::translation(1.1, 0.0);
        let b = circles(&pos12, &square, &ellipse);
        assert!(beyond_prediction(s1, s2, &pos12, &b, Vector::ZERO, 0.02));
        assert!(!beyond_prediction(s1, s2, &pos12, &b, Vector::ZERO, 0.2));
        // Along a last normal that does not separate them, the line of centres still does.
        assert!(beyond_prediction(s1, s2, &pos12, &b, Vector::Y, 0.02));
        // Two shapes with ellipse pieces are never taken (their contact reads the last normal).
        let (mut st3, mut st4) = Default::default();
        let e1 = crate::dispatcher::support_shape::support_shape(&ellipse, &mut st3).unwrap();
        let e2 = crate::dispatcher::support_shape::support_shape(&ellipse, &mut st4).unwrap();
        let far = Pose::translation(5.0, 0.0);
        let b2 = circles(&far, &ellipse, &ellipse);
        assert!(!beyond_prediction(e1, e2, &far, &b2, Vector::X, 0.02));
        // Nor a pose the contact query refuses (a rotation that is not unit).
        let mut skewed = pos12;
        skewed.rotation = parry2d_f64::math::Rotation::from_cos_sin_unchecked(2.0, 0.0);
        assert!(!beyond_prediction(s1, s2, &skewed, &b, Vector::ZERO, 0.02));
    }
}
