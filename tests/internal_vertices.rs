//! Smooth bodies over the inner vertices of one-sided level geometry: an oriented polyline
//! (`PolylineFlags::ORIENTED`, a 2D level's usual floor) and a compound with its internal edges
//! fixed (`CompoundFlags::FIX_INTERNAL_EDGES`, a floor of boxes). Where two segments (two boxes)
//! meet, the one a body has not reached yet is nearest it at the shared vertex, along a normal
//! that leaves that part's cone of pseudo-normals; the constraint turns it up, and the contact is
//! re-derived along it as parry does for its `Ball`: the body's support point along the new
//! normal, and where the line through it meets the part — it does not, so that part holds no
//! contact. Before, the part kept a point at the vertex with the turned normal: a ghost contact a
//! fraction of a millimetre under the body, off its centre, which rapier's solver loaded — a disc
//! rolling at 2 m/s on a flat chain of 0.25 m segments lost a third of its speed in 3 s (as on a
//! chain without the flag; on the floor of boxes 0.64 m short, more than without the flag), one
//! rolling over a hilly chain rolled back where parry's `Ball` went over, and a disc dropped 1 cm
//! onto the chain 5 mm to 2 cm from a vertex rolled 2.7 mm. And a wheel on a chain's tilted
//! segments: a segment has no core (its radius exactly 0), so no "core contact" at a segment's
//! middle (a car on this crate's disc wheels drives over hills as on parry's balls).

mod common;

use common::world::{World, GRAVITY};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
use parry2d_f64::shape::{Compound, CompoundFlags, Polyline, PolylineFlags};
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

/// A world with `floor` (its `friction`) on `SmoothDispatcher` (`smooth`) or rapier's default
/// narrow phase.
fn world_on(floor: SharedShape, friction: f64, smooth: bool) -> World {
    let narrow_phase = if smooth {
        NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
    } else {
        NarrowPhase::new()
    };
    let mut w = World::new(narrow_phase);
    w.colliders.insert(ColliderBuilder::new(floor).friction(friction));
    w
}

/// The body's pose after 2 s dropped from 1 cm above the floor with its centre `offset` from the
/// origin, turned by 0.001 rad, onto `floor`; `smooth` picks `SmoothDispatcher` (else rapier's
/// default narrow phase).
fn landed(shape: SharedShape, half_height: f64, offset: f64, floor: Polyline, smooth: bool) -> Pose {
    let mut w = world_on(SharedShape::new(floor), 0.5, smooth);
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

/// A hilly oriented chain: y = 0.3·sin x sampled every 0.2 m over x ∈ [−10, 10], facing up.
fn hills() -> Polyline {
    let points: Vec<Vector> = (-50..=50)
        .rev()
        .map(|i| {
            let x = i as f64 * 0.2;
            Vector::new(x, 0.3 * x.sin())
        })
        .collect();
    Polyline::with_flags(points, None, PolylineFlags::ORIENTED)
}

/// The body's position and velocity after 3 s launched from (−3, `height`) at `speed` along x,
/// spinning at `spin`, CCD on, on `floor` (friction 0.5); `smooth` picks `SmoothDispatcher`.
fn rolled(
    shape: SharedShape,
    height: f64,
    speed: f64,
    spin: f64,
    floor: SharedShape,
    smooth: bool,
) -> (Vector, Vector) {
    let mut w = world_on(floor, 0.5, smooth);
    let (h, _) = w.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(-3.0, height))
            .linvel(Vector::new(speed, 0.0))
            .angvel(spin)
            .ccd_enabled(true),
        ColliderBuilder::new(shape).friction(0.5),
    );
    for _ in 0..180 {
        w.step(GRAVITY, &());
    }
    (w.bodies[h].translation(), w.bodies[h].linvel())
}

#[test]
fn a_disc_rolling_over_an_oriented_hilly_chain_follows_parry_s_ball() {
    // Launched 0.6 m up at 3 m/s, rolling (−12 rad/s), over hills 0.3 m high: it goes over them.
    let (ours, v_ours) = rolled(
        SharedShape::new(Ellipse::new(0.25, 0.25)),
        0.6,
        3.0,
        -12.0,
        SharedShape::new(hills()),
        true,
    );
    let (parry, v_parry) = rolled(
        SharedShape::ball(0.25),
        0.6,
        3.0,
        -12.0,
        SharedShape::new(hills()),
        false,
    );
    println!("after 3 s: this crate's disc at {ours:?} ({v_ours:?}), parry's Ball at {parry:?} ({v_parry:?})");
    assert!(parry.x > 4.0, "parry's Ball went over the hills: {parry:?}");
    assert!((ours - parry).length() < 1e-6, "{ours:?} against {parry:?}");
    assert!((v_ours - v_parry).length() < 1e-6, "{v_ours:?} against {v_parry:?}");
}

#[test]
fn a_body_rolling_or_sliding_on_an_oriented_flat_chain_goes_as_far_as_on_one_segment() {
    // One segment from x = 10 to −10, and the chain of 0.25 m segments over the same line.
    let one = Polyline::with_flags(
        vec![Vector::new(10.0, 0.0), Vector::new(-10.0, 0.0)],
        None,
        PolylineFlags::ORIENTED,
    );
    let bodies = [
        // Rolling without slipping at 2 m/s (1.1 m short with the ghost contacts); lying flat and
        // sliding at 2 m/s, braked by friction.
        ("disc", SharedShape::new(Ellipse::new(0.25, 0.25)), 0.25, -8.0, 1e-6),
        // An ellipse sliding with friction tips and rocks; each crossing of a vertex moves its
        // contact to a new segment's manifold, which starts without rapier's warm start: it ends
        // 4.4e-5 m from its place on one segment (with the ghost contacts, 6e-2 m).
        ("ellipse", SharedShape::new(Ellipse::new(0.5, 0.2)), 0.2, 0.0, 1e-3),
    ];
    for (name, shape, height, spin, tolerance) in bodies {
        let (on_one, _) = rolled(shape.clone(), height, 2.0, spin, SharedShape::new(one.clone()), true);
        let (on_chain, _) = rolled(shape, height, 2.0, spin, SharedShape::new(chain(0.25, true)), true);
        let apart = (on_chain - on_one).length();
        println!("{name}: on one segment at {on_one:?}, on the chain {apart:.1e} m from it");
        assert!(apart < tolerance, "{name}: {apart} m");
    }
}

#[test]
fn on_a_two_sided_chain_or_a_heightfield_a_rolling_disc_meets_the_ghost_contacts_as_parry_s_ball_does() {
    // Without pseudo-normals — a chain without the flag, a 2D heightfield (parry computes none
    // for it) — the segment ahead keeps its point at each vertex, for parry's shapes as for this
    // crate's (rapier's; docs/rapier.md, Pitfalls): the disc goes about 1.08 m less far in 3 s.
    let one = Polyline::new(vec![Vector::new(10.0, 0.0), Vector::new(-10.0, 0.0)], None);
    let disc = || SharedShape::new(Ellipse::new(0.25, 0.25));
    let roll = |shape, floor: &dyn Fn() -> SharedShape, smooth| rolled(shape, 0.25, 2.0, -8.0, floor(), smooth).0;
    let on_one = roll(disc(), &|| SharedShape::new(one.clone()), true);
    let floors: [(&str, &dyn Fn() -> SharedShape); 2] = [
        ("two-sided chain", &|| SharedShape::new(chain(0.25, false))),
        ("heightfield", &|| {
            SharedShape::heightfield(vec![0.0; 81], Vector::new(20.0, 1.0))
        }),
    ];
    for (name, floor) in floors {
        let ours = roll(disc(), floor, true);
        let parry = roll(SharedShape::ball(0.25), floor, false);
        println!(
            "{name}: this crate's disc {:.3} m short of one segment, parry's Ball {:.3} m",
            on_one.x - ours.x,
            on_one.x - parry.x
        );
        assert!(on_one.x - ours.x > 0.5, "{name}: {ours:?} against {on_one:?}");
        assert!((ours - parry).length() < 1e-4, "{name}: {ours:?} against {parry:?}");
    }
}

/// A floor of `n` boxes side by side over x ∈ [−10, 10], its top at y = 0, its internal edges
/// fixed (`CompoundFlags::FIX_INTERNAL_EDGES`) or not.
fn boxes(n: usize, fixed: bool) -> Compound {
    let w = 20.0 / n as f64;
    let parts = (0..n)
        .map(|i| {
            let centre = Vector::new(-10.0 + w * (i as f64 + 0.5), -0.5);
            (Pose::from_translation(centre), SharedShape::cuboid(w / 2.0, 0.5))
        })
        .collect();
    let mut floor = Compound::new(parts);
    if fixed {
        floor.set_flags(CompoundFlags::FIX_INTERNAL_EDGES, None);
    }
    floor
}

#[test]
fn a_disc_rolls_over_a_floor_of_boxes_with_fixed_internal_edges_as_over_one_box() {
    // Rolling without slipping at 2 m/s over 40 boxes 0.5 m wide (before: 0.64 m short in 3 s).
    let disc = || SharedShape::new(Ellipse::new(0.25, 0.25));
    let roll = |shape, floor: Compound, smooth| rolled(shape, 0.25, 2.0, -8.0, SharedShape::new(floor), smooth).0;
    let on_one = roll(disc(), boxes(1, true), true);
    let ours = roll(disc(), boxes(40, true), true);
    let parry = roll(SharedShape::ball(0.25), boxes(40, true), false);
    println!(
        "floor of boxes: one box {on_one:?}, 40 boxes {:.1e} m from it, parry's Ball {:.1e} m",
        (ours - on_one).length(),
        (parry - on_one).length()
    );
    assert!((ours - on_one).length() < 1e-6, "{ours:?} against {on_one:?}");
    assert!((ours - parry).length() < 1e-9, "{ours:?} against {parry:?}");
}

/// A car — a box chassis on two wheels of radius 0.3 driven by revolute motors — crossing
/// hills made of 0.2 m segments (oriented) for 5 s: with this crate's discs as wheels it drives
/// as with parry's `Ball`s, to 1e-8 m. Before a segment's core got its radius 0 exactly, the
/// rounding of a tilted segment's dot products (about 1e-17) passed for a core, and the wheel
/// got a "core contact" at the middle of the segment under it, against its tangent line: a ghost
/// support 6 cm from the true contact, and the car went as far as 7.4 cm from parry's.
#[test]
fn a_car_on_this_crate_s_discs_drives_over_oriented_hills_as_on_parry_s_balls() {
    let hills = || {
        let points: Vec<Vector> = (-100..=100)
            .rev()
            .map(|i| {
                let x = i as f64 * 0.2;
                Vector::new(x, 0.3 * (0.7 * x).sin())
            })
            .collect();
        SharedShape::new(Polyline::with_flags(points, None, PolylineFlags::ORIENTED))
    };
    let drive = |wheel: SharedShape, smooth: bool| {
        let mut w = world_on(hills(), 0.9, smooth);
        let (chassis, _) = w.insert(
            RigidBodyBuilder::dynamic().translation(Vector::new(-8.0, 1.2)),
            ColliderBuilder::cuboid(0.8, 0.15),
        );
        for x in [-0.6, 0.6] {
            let (h, _) = w.insert(
                RigidBodyBuilder::dynamic().translation(Vector::new(-8.0 + x, 0.8)),
                ColliderBuilder::new(wheel.clone()).friction(0.9),
            );
            let motor = RevoluteJointBuilder::new()
                .local_anchor1(Vector::new(x, -0.4))
                .motor_velocity(-12.0, 50.0)
                .contacts_enabled(false);
            w.impulse_joints.insert(chassis, h, motor, true);
        }
        (0..300)
            .map(|_| {
                w.step(GRAVITY, &());
                w.bodies[chassis].translation()
            })
            .collect::<Vec<_>>()
    };
    let ours = drive(SharedShape::new(Ellipse::new(0.3, 0.3)), true);
    let parry = drive(SharedShape::ball(0.3), false);
    let worst = ours
        .iter()
        .zip(&parry)
        .map(|(a, b)| (*a - *b).length())
        .fold(0.0, f64::max);
    println!(
        "car over oriented hills: {:.1} m driven, this crate's wheels within {worst:.1e} m of parry's",
        ours[299].x + 8.0
    );
    assert!(ours[299].x > 0.0, "the car crossed the hills: {:?}", ours[299]);
    assert!(worst < 1e-8, "{worst} m from the car on parry's balls");
}
