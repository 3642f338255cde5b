//! rapier's CCD against an oriented polyline (`PolylineFlags::ORIENTED`, `ColliderBuilder::
//! oriented_polyline`: a one-sided chain, the usual floor of a 2D level). For its own shapes
//! rapier's sweep skips a segment when the fast body's centroid starts behind it, or stays in
//! front of it by more than a quarter of the body's `ccd_thickness` while coming closer by less
//! than that (parry's `sweep_time_of_impact_composite`); `SmoothDispatcher` under its rapier
//! policies does the same, counting what the body's turn moves a point as approach too (a
//! spinning sliver's tip is not let into the chain). Before, every segment was cast: a box sliding along a flat chain of
//! 0.15 m segments was stopped at the segments' shared ends (its corner, sunk a fraction of a
//! millimetre by the soft contact, met the next segment's end): of the 6 m it slides
//! frictionless in 2 s it travelled 5.85–5.90 m, rounded by 0.02 4.57 m, its velocity kept —
//! held in place by the CCD for steps on end.

mod common;

use common::world::{World, GRAVITY};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{NonlinearRigidMotion, QueryDispatcher};
use parry2d_f64::shape::{Polyline, PolylineFlags, Shape};
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{CastPolicy, Ellipse, RoundedPolygon, SmoothDispatcher};

const DT: f64 = 1.0 / 60.0;

/// A flat chain along y = 0 from x = −5 to 5 of segments `length` long, facing up (its vertices
/// from right to left: parry's outward normal of a segment a → b is its counter-clockwise one),
/// oriented or not.
fn chain(length: f64, oriented: bool) -> Polyline {
    let n = (10.0 / length).round() as usize;
    let points: Vec<Vector> = (0..=n)
        .rev()
        .map(|i| Vector::new(-5.0 + i as f64 * length, 0.0))
        .collect();
    let flags = if oriented {
        PolylineFlags::ORIENTED
    } else {
        PolylineFlags::empty()
    };
    Polyline::with_flags(points, None, flags)
}

/// The bodies slid along the chain: a sharp box 1 × 0.1 and the same rounded by 0.02 (this
/// crate's `RoundedPolygon`), and an ellipse 0.5 × 0.1 lying flat; each with its half height.
fn bodies() -> Vec<(&'static str, SharedShape, f64)> {
    let boxed = |r: f64| {
        let (w, h) = (0.5 - r, 0.05 - r);
        let square = [
            Vector::new(-w, -h),
            Vector::new(w, -h),
            Vector::new(w, h),
            Vector::new(-w, h),
        ];
        SharedShape::new(RoundedPolygon::new(&square, r))
    };
    vec![
        ("box", boxed(0.0), 0.05),
        ("rounded box", boxed(0.02), 0.05),
        ("flat ellipse", SharedShape::new(Ellipse::new(0.5, 0.1)), 0.1),
    ]
}

/// `body` set on `floor` at x = −3 with velocity (3, 0), friction `mu` on both, sleeping off;
/// its x after 2 s, with rapier's CCD on or off, with `SmoothDispatcher`.
fn slide(body: &SharedShape, half_height: f64, floor: SharedShape, mu: f64, ccd: bool) -> f64 {
    slide_in(
        NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
        body,
        half_height,
        floor,
        mu,
        ccd,
    )
}

/// [`slide`] in a world of this narrow phase.
fn slide_in(
    narrow_phase: NarrowPhase,
    body: &SharedShape,
    half_height: f64,
    floor: SharedShape,
    mu: f64,
    ccd: bool,
) -> f64 {
    let mut w = World::new(narrow_phase);
    if !ccd {
        w.params.max_ccd_substeps = 0;
    }
    let fixed = w.bodies.insert(RigidBodyBuilder::fixed());
    w.colliders
        .insert_with_parent(ColliderBuilder::new(floor).friction(mu), fixed, &mut w.bodies);
    let (h, _) = w.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(-3.0, half_height))
            .linvel(Vector::new(3.0, 0.0))
            .can_sleep(false),
        ColliderBuilder::new(body.clone()).friction(mu),
    );
    for _ in 0..120 {
        w.step(GRAVITY, &());
    }
    w.bodies[h].translation().x
}

#[test]
fn a_body_sliding_along_an_oriented_chain_travels_as_far_as_with_ccd_off() {
    for (name, body, half_height) in bodies() {
        for length in [0.15, 0.2, 0.35] {
            for mu in [0.0, 0.3] {
                let floor = || SharedShape::new(chain(length, true));
                let with_ccd = slide(&body, half_height, floor(), mu, true);
                let without = slide(&body, half_height, floor(), mu, false);
                println!("{name:<13} segments {length} m, friction {mu}: x {with_ccd:.6} (CCD off {without:.6})");
                // Frictionless it slides the whole 6 m; with friction it stops where it does
                // without CCD (1.523 m on).
                assert!(
                    (with_ccd - without).abs() < 1e-3,
                    "{name}, segments {length} m, friction {mu}: x {with_ccd} with rapier's CCD, {without} without"
                );
                if mu == 0.0 {
                    assert!((with_ccd - 3.0).abs() < 1e-3, "{name}: x {with_ccd} after 2 s at 3 m/s");
                }
            }
        }
    }
}

/// A cast for rapier (`stop_at_penetration = false`) of an ellipse 0.5 × 0.1 moving by `motion`
/// against `floor` at rest, by a dispatcher of `policy`.
fn cast(policy: CastPolicy, motion: &NonlinearRigidMotion, floor: &dyn Shape) -> Option<f64> {
    let d = SmoothDispatcher::default().with_cast_policy(policy);
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    d.cast_shapes_nonlinear(motion, &Ellipse::new(0.5, 0.1), &still, floor, 0.0, DT, false)
        .expect("a supported pair")
        .map(|hit| hit.time_of_impact)
}

#[test]
fn a_body_behind_an_oriented_chain_is_not_stopped_by_it_under_rapier_s_policies() {
    // Coming up from below at 30 m/s, spinning: 0.2 m behind the chain at the start.
    let motion = NonlinearRigidMotion::new(
        Pose::new(Vector::new(0.07, -0.3), 0.2),
        Vector::ZERO,
        Vector::new(1.0, 30.0),
        5.0,
    );
    let oriented = chain(0.15, true);
    for policy in [CastPolicy::Rapier, CastPolicy::RapierConstantSpin] {
        assert_eq!(cast(policy, &motion, &oriented), None, "{policy:?}");
    }
    // Every segment cast: the two-sided chain, and the oriented one under the plain policy.
    let two_sided = cast(CastPolicy::Rapier, &motion, &chain(0.15, false)).expect("a hit");
    let plain = cast(CastPolicy::Plain, &motion, &oriented).expect("a hit");
    assert!(two_sided > 0.0 && two_sided < DT && plain > 0.0 && plain < DT);
}

#[test]
fn a_fast_body_falling_onto_an_oriented_chain_is_stopped_where_the_two_sided_chain_stops_it() {
    for (speed, spin) in [(30.0, 0.0), (300.0, 20.0), (300.0, -40.0)] {
        // Starting 0.02 to 4 m above the chain (its half-height 0.1 to the centre).
        let height = 0.12 + 0.6 * speed * DT;
        let motion = NonlinearRigidMotion::new(
            Pose::new(Vector::new(0.31, height), 0.1),
            Vector::ZERO,
            Vector::new(2.0, -speed),
            spin,
        );
        let one_sided = cast(CastPolicy::Rapier, &motion, &chain(0.15, true));
        let two_sided = cast(CastPolicy::Rapier, &motion, &chain(0.15, false));
        println!("{speed} m/s, {spin} rad/s: one-sided {one_sided:?}, two-sided {two_sided:?}");
        assert!(two_sided.is_some(), "{speed} m/s: the two-sided chain is hit");
        assert_eq!(one_sided, two_sided, "{speed} m/s, {spin} rad/s");
    }
}

#[test]
fn a_body_sliding_along_a_two_sided_chain_is_caught_at_its_joints_by_rapier_s_solver_as_parry_s_box_is() {
    // rapier's behaviour on a polyline without the flag, which `docs/rapier.md` (Pitfalls)
    // describes: the contacts of the segments ahead meet the box's corner at their shared ends,
    // CCD or not, with this crate's box as with parry's. If this fails, rapier changed.
    let two_sided = || SharedShape::new(chain(0.15, false));
    let ours = bodies().remove(0);
    for ccd in [true, false] {
        let x = slide(&ours.1, ours.2, two_sided(), 0.0, ccd);
        let parry = slide_in(
            NarrowPhase::new(),
            &SharedShape::cuboid(0.5, 0.05),
            0.05,
            two_sided(),
            0.0,
            ccd,
        );
        println!("two-sided chain, CCD {ccd}: this crate's box x {x:.4}, parry's box x {parry:.4} (6 m of slide: x 3)");
        assert!(x < 0.0 && parry < 0.0, "CCD {ccd}: x {x}, parry's {parry}");
    }
}

#[test]
fn a_spinning_sliver_whose_tip_swings_into_an_oriented_chain_is_stopped_where_the_two_sided_chain_stops_it() {
    // rapier's own early-out counts the centroid's approach only: a sliver 1 m long turning at
    // 60 rad/s (1 rad a step) with its centroid 0.3 m over the chain, not moving, would be skipped
    // and swing its tip 0.2 m into the chain. The turn is counted here: cast, and stopped.
    let sliver = RoundedPolygon::new(
        &[
            Vector::new(-0.5, -0.005),
            Vector::new(0.5, -0.005),
            Vector::new(0.5, 0.005),
            Vector::new(-0.5, 0.005),
        ],
        0.0,
    );
    let motion = NonlinearRigidMotion::new(
        Pose::new(Vector::new(0.02, 0.3), 0.1),
        Vector::ZERO,
        Vector::ZERO,
        -60.0,
    );
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let d = SmoothDispatcher::default();
    let hit = |floor: &Polyline| {
        d.cast_shapes_nonlinear(&motion, &sliver, &still, floor, 0.0, DT, false)
            .expect("a supported pair")
            .map(|h| h.time_of_impact)
    };
    let (one_sided, two_sided) = (hit(&chain(0.15, true)), hit(&chain(0.15, false)));
    assert!(two_sided.is_some(), "the tip reaches the chain within the step");
    assert_eq!(one_sided, two_sided);
}
