//! A smooth body resting on an oriented polyline (`PolylineFlags::ORIENTED`, a one-sided chain)
//! next to one of its inner vertices. The segment beyond the vertex is nearest the body at the
//! vertex itself, along a normal that leaves the segment's cone of pseudo-normals; the
//! constraint turns it up, and the contact is re-derived along it as parry does for its `Ball`:
//! the body's lowest point, and where the vertical line through it meets that segment — it does
//! not, so the segment holds no contact. Before, the segment kept a point at the vertex, a
//! fraction of a millimetre under the body and off its centre: rapier's solver loaded it once
//! the body settled, and a disc dropped 1 cm onto the chain 5 mm to 2 cm from a vertex rolled
//! 2.7 mm and turned by up to 0.0096 rad (parry's `Ball`: not at all), an ellipse rocked to
//! 0.0055–0.0099 rad.

mod common;

use common::world::{World, GRAVITY};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
use parry2d_f64::shape::{Polyline, PolylineFlags};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{Ellipse, SmoothDispatcher};

/// A flat chain along y = 0 from x = −5 to 5 facing up (vertices right to left), with an inner
/// vertex at x = 0 when its segments are `length` long (5 divisible by it), oriented or not.
fn chain(length: f64, oriented: bool) -> Polyline {
    let n = (5.0 / length).round() as i64;
    let points: Vec<Vector> = (-n..=n).rev().map(|i| Vector::new(i as f64 * length, 0.0)).collect();
    let flags = if oriented {
        PolylineFlags::ORIENTED
    } else {
        PolylineFlags::empty()
    };
    Polyline::with_flags(points, None, flags)
}

/// The body's pose after 2 s dropped from 1 cm above the floor with its centre `offset` from the
/// origin, turned by 0.001 rad, onto `floor`; `smooth` picks `SmoothDispatcher` (else rapier's
/// default narrow phase).
fn landed(shape: SharedShape, half_height: f64, offset: f64, floor: Polyline, smooth: bool) -> Pose {
    let narrow_phase = if smooth {
        NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
    } else {
        NarrowPhase::new()
    };
    let mut w = World::new(narrow_phase);
    w.colliders
        .insert(ColliderBuilder::new(SharedShape::new(floor)).friction(0.5));
    let (h, _) = w.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(offset, half_height + 0.01))
            .rotation(0.001),
        ColliderBuilder::new(shape).friction(0.5),
    );
    for _ in 0..120 {
        w.step(GRAVITY, &());
    }
    *w.bodies[h].position()
}

#[test]
fn a_smooth_body_near_an_inner_vertex_of_an_oriented_chain_lands_as_on_one_segment() {
    let bodies = [
        ("disc", SharedShape::new(Ellipse::new(0.25, 0.25)), 0.25),
        ("ellipse", SharedShape::new(Ellipse::new(0.5, 0.2)), 0.2),
    ];
    let mut cases = 0;
    for (name, shape, half_height) in bodies {
        for offset in [0.005, 0.01, 0.02, -0.02] {
            let on_chain = landed(shape.clone(), half_height, offset, chain(0.25, true), true);
            let on_segment = landed(shape.clone(), half_height, offset, chain(5.0, true), true);
            let moved = (on_chain.translation - on_segment.translation).length();
            let turned = (on_chain.rotation.angle() - on_segment.rotation.angle()).abs();
            println!("{name} {offset} m from the vertex: chain against one segment {moved:.1e} m, {turned:.1e} rad");
            assert!(
                moved < 1e-12 && turned < 1e-12,
                "{name} at {offset}: {moved} m, {turned} rad"
            );
            cases += 1;
        }
    }
    println!("{cases} drops");
}

#[test]
fn this_crate_s_disc_near_an_inner_vertex_of_an_oriented_chain_lands_as_parry_s_ball() {
    for offset in [0.005, 0.01, 0.02] {
        let ours = landed(
            SharedShape::new(Ellipse::new(0.25, 0.25)),
            0.25,
            offset,
            chain(0.25, true),
            true,
        );
        let parry = landed(SharedShape::ball(0.25), 0.25, offset, chain(0.25, true), false);
        let moved = (ours.translation - parry.translation).length();
        // parry's Ball stays where it landed: no sideways roll.
        assert!(
            (parry.translation.x - offset).abs() < 1e-12,
            "parry's Ball rolled: {parry:?}"
        );
        assert!(moved < 1e-9, "{offset}: {moved} m from parry's Ball");
    }
}

#[test]
fn an_oriented_chain_holds_an_ellipse_near_its_inner_vertex_by_one_point() {
    let d = SmoothDispatcher::default();
    let ellipse = Ellipse::new(0.5, 0.2);
    // The ellipse 0.1 mm above the floor, its lowest point 2 cm left of the vertex at the origin.
    let pos12 = Pose::translation(-0.02, 0.2 + 1e-4);
    // The segments holding a point (each part's manifold: its exact point and its core contact).
    let holding = |oriented: bool| {
        let floor = chain(0.25, oriented);
        let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
        PersistentQueryDispatcher::<(), ()>::contact_manifolds(
            &d,
            &pos12,
            &floor,
            &ellipse,
            0.002,
            &mut manifolds,
            &mut None,
        )
        .expect("supported");
        let mut parts: Vec<u32> = manifolds
            .iter()
            .filter(|m| !m.points.is_empty())
            .map(|m| m.subshape1)
            .collect();
        parts.sort_unstable();
        parts
    };
    // The segment under the lowest point is the chain's 20th (vertices right to left: segment
    // k spans x from 5 − 0.25·k to 5 − 0.25·(k + 1)), the one right of the vertex the 19th.
    // Two-sided, that one keeps a point at the vertex (its exact nearest point: rapier's ghost
    // contact); oriented, its pseudo-normals turn the normal up and the vertical line through
    // the ellipse's lowest point misses it.
    assert_eq!(holding(false), vec![19, 20]);
    assert_eq!(holding(true), vec![20]);
}
