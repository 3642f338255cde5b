//! rapier's CCD against walls of no thickness: parry's `Segment`, `Polyline`, `TriMesh` and
//! `HeightField` (`ccd_thickness` 0) and the `HalfSpace`, with this crate's disc resting on them.
//!
//! The reproduction of issue 29: a disc `Ellipse::new(0.2, 0.2)` at (0, 0.2) resting on the wall
//! y = 0, moving at (−6, −0.1) m/s and spinning at 4 rad/s, one step of 1/60 s, cast for rapier
//! (`stop_at_penetration = false`). An allowance taken from the thinner shape's `ccd_thickness`
//! (0 for these walls) answered a hit at the start's nudge on every step: the disc froze. Under
//! `CastPolicy::Rapier` the translation may take the contact a quarter of the disc's inradius
//! deeper (0.05) and the disc's core (a quarter of it about the centre) may not reach the wall:
//! sliding along (0.0017 deeper over the step) or away, no hit; driven in at 60 m/s, a hit where
//! the contact is 0.05 deep, well inside the step.

mod common;

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher};
use parry2d_f64::shape::{Ball, HalfSpace, HeightField, Polyline, Segment, Shape, TriMesh};
use smooth_ccd2d::{CastPolicy, Ellipse, SmoothDispatcher};

const DT: f64 = 1.0 / 60.0;

/// The walls, their top at y = 0 over −10 ≤ x ≤ 10, and whether parry gives them no thickness.
fn walls() -> Vec<(&'static str, Box<dyn Shape>)> {
    let (a, b) = (Vector::new(-10.0, 0.0), Vector::new(10.0, 0.0));
    vec![
        ("Segment", Box::new(Segment::new(a, b))),
        (
            "Polyline",
            Box::new(Polyline::new(
                vec![a, Vector::new(-2.0, 0.0), Vector::new(3.0, 0.0), b],
                None,
            )),
        ),
        (
            "TriMesh",
            Box::new(
                TriMesh::new(
                    vec![a, b, Vector::new(10.0, -1.0), Vector::new(-10.0, -1.0)],
                    vec![[0, 3, 1], [1, 3, 2]],
                )
                .expect("a mesh"),
            ),
        ),
        (
            "HeightField",
            Box::new(HeightField::new(vec![0.0; 9], Vector::new(20.0, 1.0))),
        ),
        ("HalfSpace", Box::new(HalfSpace::new(Vector::Y))),
    ]
}

/// The disc at (x, 0.2 − depth) with velocity `v`, spinning at 4 rad/s.
fn disc_motion(depth: f64, v: Vector) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(Pose::translation(0.3, 0.2 - depth), Vector::ZERO, v, 4.0)
}

/// The CCD scene suite's sliver: 1 m long, a sharp triangle whose long side runs from its tip
/// (−0.5, 0) to (0.5, 0.125), its centroid 0.03 from that side.
fn sliver() -> smooth_ccd2d::RoundedPolygon {
    smooth_ccd2d::RoundedPolygon::new(
        &[Vector::new(-0.5, 0.0), Vector::new(-0.25, 0.0), Vector::new(0.5, 0.125)],
        0.0,
    )
}

/// The sliver's pose with its tip (−0.5, 0) at (x, 0) on the wall y = 0 and its long side facing
/// the wall, turned `tilt` off it (the body above the wall).
fn tip_on_wall(x: f64, tilt: f64) -> Pose {
    let side = Vector::new(1.0, 0.125);
    let rot = parry2d_f64::math::Rotation::new(core::f64::consts::PI - tilt - side.y.atan2(side.x));
    Pose::from_parts(Vector::new(x, 0.0) - rot * Vector::new(-0.5, 0.0), rot)
}

#[test]
fn walls_of_no_thickness_have_parrys_zero_ccd_thickness() {
    for (name, wall) in walls() {
        let t = wall.ccd_thickness();
        println!("{name:<12} ccd_thickness {t:e}");
        if name != "HalfSpace" {
            assert_eq!(t, 0.0, "{name}");
        }
    }
}

#[test]
fn a_disc_resting_on_a_wall_of_no_thickness_slides_along_or_away_without_a_hit() {
    let d = SmoothDispatcher::default();
    let disc = Ellipse::new(0.2, 0.2);
    let wall_at = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    // parry's own dispatcher on a `Ball`, for the record.
    let issue = disc_motion(0.0, Vector::new(-6.0, -0.1));
    let parry = DefaultQueryDispatcher
        .cast_shapes_nonlinear(
            &issue,
            &Ball::new(0.2),
            &wall_at,
            &Segment::new(Vector::new(-10.0, 0.0), Vector::new(10.0, 0.0)),
            0.0,
            DT,
            false,
        )
        .unwrap();
    println!(
        "parry's dispatcher, Ball on the Segment: {:?}",
        parry.map(|h| h.time_of_impact)
    );
    let mut cases = 0;
    for (name, wall) in walls() {
        // Touching, and 1e-3 in (as rapier's solver leaves a resting body).
        for depth in [0.0, 1e-3] {
            for v in [
                Vector::new(-6.0, -0.1),
                Vector::new(-6.0, 0.1),
                Vector::new(6.0, 0.0),
                Vector::new(0.0, 0.5),
            ] {
                let hit = d
                    .cast_shapes_nonlinear(&disc_motion(depth, v), &disc, &wall_at, &*wall, 0.0, DT, false)
                    .unwrap_or_else(|_| panic!("{name}: answered"));
                assert!(hit.is_none(), "{name} depth {depth} v {v}: {hit:?}");
                cases += 1;
            }
        }
    }
    println!("{cases} slides and departures: no hit");
}

/// Driven into the wall at 60 m/s from contact: a hit within the step where the translation has
/// taken the contact the allowance (a quarter of the inradius, 0.05) deeper, 0.05/60 s in;
/// never at the start, which rapier discards.
#[test]
fn a_disc_driven_into_a_wall_of_no_thickness_is_stopped_the_allowance_deep() {
    let d = SmoothDispatcher::default();
    let disc = Ellipse::new(0.2, 0.2);
    let wall_at = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let allowance = CastPolicy::ALLOWANCE * 0.2;
    for (name, wall) in walls() {
        for depth in [0.0, 1e-3] {
            let m = disc_motion(depth, Vector::new(-6.0, -60.0));
            let hit = d
                .cast_shapes_nonlinear(&m, &disc, &wall_at, &*wall, 0.0, DT, false)
                .unwrap_or_else(|_| panic!("{name}: answered"))
                .unwrap_or_else(|| panic!("{name} depth {depth}: a hit"));
            let t = hit.time_of_impact;
            // The translation takes the contact from −depth down to min(−A, −depth − A), A
            // deeper, at 60 m/s.
            let expected = allowance / 60.0;
            println!(
                "{name:<12} depth {depth:e}: hit at {:.4} of the step (expected {:.4})",
                t / DT,
                expected / DT
            );
            assert!(t > 0.0 && t < DT, "{name}: {t}");
            assert!((t - expected).abs() < 1e-9, "{name} depth {depth}: {t} vs {expected}");
        }
    }
}

/// The wedge of the CCD scene suite (two `Segment`s, 20° apart, apex at (6, 0)) with the 8:1
/// thin ellipse jammed across the upper one near the apex, as the suite's case (acute wedge,
/// thin ellipse, 1000 m/s, 600 rad/s) left it: its centre over the segment, its deepest point
/// past the segment's line beyond the apex. The least translation that separates the two
/// shapes points out through the apex, where the body cannot go (its core keeps its centre in
/// the wedge); the contact is taken from the centre's side: the segment's own normal towards
/// the centre, and a depth that is the least translation along it clearing the segment.
#[test]
fn a_thin_ellipse_wedged_past_the_apex_of_two_segments_is_pushed_back_into_the_wedge() {
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher, PointQuery};
    let half = core::f64::consts::PI / 18.0;
    let apex = Vector::new(6.0, 0.0);
    let up = apex + Vector::new(-8.0 * half.cos(), 8.0 * half.sin());
    let wall = Segment::new(up, apex);
    let body = Ellipse::new(0.4, 0.05);
    let pose = Pose::new(Vector::new(5.803533, 0.021950), 0.8284);
    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
    SmoothDispatcher::default()
        .contact_manifolds(&pose, &wall, &body, 0.002, &mut manifolds, &mut None)
        .expect("answered");
    let m = &manifolds[0];
    // The segment's normal towards the body's centre (below the upper wall).
    let towards_centre = Vector::new(-half.sin(), -half.cos());
    assert!(
        (m.local_n1 - towards_centre).length() < 1e-12,
        "normal {:?}",
        m.local_n1
    );
    let depth = -m.points[0].dist;
    assert!(depth > 0.0, "depth {depth}");
    // That depth along that normal clears the segment; a little less does not (the segment
    // sampled every 0.1 mm, its ends included, against the ellipse's inside).
    let apart = |by: f64| {
        let moved = Pose::from_parts(pose.translation + towards_centre * by, pose.rotation);
        (0..=80_000).all(|k| {
            let q = up.lerp(apex, k as f64 / 80_000.0);
            !body.contains_local_point(moved.inverse_transform_point(q))
        })
    };
    println!("one-sided depth {depth:.6}");
    assert!(apart(depth + 1e-9) && !apart(depth - 1e-6), "depth {depth}");
}

/// A sliver (the suite's: 1 m long, its centroid 0.03 from its long side) meeting a `Polyline`
/// wall with the tip of its long side, the side 0.3 rad off the wall: the part has two
/// manifolds, its points first — the tip's contact and the side's far end (0.3 away, beyond the
/// prediction: a speculative point rapier keeps only when the velocities close it, a face that
/// a spin turns into the wall) — and then the sliver's core contact, in a manifold of its own,
/// which holds its centre whatever the spin (the chain box of the CCD scene suite, a sliver at
/// 3000 m/s: frozen with the far end's point alone). Both manifolds carry the part's sub-shape
/// id. A side resting flat on the wall (both ends within the prediction) keeps both ends and no
/// core contact: one manifold. (Before the part had a second manifold, the core contact took the
/// far end's place: a square tumbling onto a two-sided chain met its corner a step late.)
#[test]
fn a_polyline_part_holds_the_core_contact_of_a_body_whose_far_face_point_is_beyond_the_prediction() {
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
    use smooth_ccd2d::__is_core_feature as is_core;
    let sliver = sliver();
    let wall = Polyline::new(
        vec![Vector::new(-10.0, 0.0), Vector::new(0.0, 0.0), Vector::new(10.0, 0.0)],
        None,
    );
    // The long side (−0.5, 0)–(0.5, 0.125) facing the wall (its outward normal turned down),
    // turned by `tilt` from it, its end (−0.5, 0) on the wall at x = 2 (the second segment)
    // and the body above.
    let at = |tilt: f64| tip_on_wall(2.0, tilt);
    let d = SmoothDispatcher::default();
    for (wall_first, tilt) in [(true, 0.3), (false, 0.3), (true, 0.0), (false, 0.0)] {
        let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
        let mut workspace = None;
        // Twice, the second from the first's manifolds and workspace (rapier's next step).
        for call in 0..2 {
            if wall_first {
                d.contact_manifolds(&at(tilt), &wall, &sliver, 0.002, &mut manifolds, &mut workspace)
            } else {
                d.contact_manifolds(
                    &at(tilt).inverse(),
                    &sliver,
                    &wall,
                    0.002,
                    &mut manifolds,
                    &mut workspace,
                )
            }
            .expect("answered");
            let what = format!("wall first {wall_first}, tilt {tilt}, call {call}: {manifolds:?}");
            // One part reached (the second segment): its points, then its core where it has one.
            assert_eq!(manifolds.len(), if tilt > 0.0 { 2 } else { 1 }, "{what}");
            let part = |m: &ContactManifold<(), ()>| if wall_first { m.subshape1 } else { m.subshape2 };
            assert!(manifolds.iter().all(|m| part(m) == 1), "{what}");
            let fid = |p: &parry2d_f64::query::TrackedContact<()>| if wall_first { p.fid2.0 } else { p.fid1.0 };
            let points = &manifolds[0].points;
            assert_eq!(points.len(), 2, "{what}");
            assert!(points.iter().all(|p| !is_core(fid(p))), "{what}");
            let far = points.iter().map(|p| p.dist).fold(f64::NEG_INFINITY, f64::max);
            if tilt > 0.0 {
                let cores = &manifolds[1].points;
                assert!(far > 0.2, "the far end kept: {what}");
                assert_eq!(cores.len(), 1, "{what}");
                assert!(is_core(fid(&cores[0])), "{what}");
                assert_eq!(manifolds[1].local_n1, manifolds[0].local_n1, "{what}");
            } else {
                assert!(far <= 0.002, "{what}");
            }
        }
    }
}

/// A thin body falling fast and spinning slowly is stopped by every wall as by a `Segment`
/// (found by a hostile-scene hunt in rapier: a sliver `Ellipse::new(0.5, 0.0005)` at 400 m/s,
/// 1 rad/s, fell through polylines, meshes, heightfields and compounds and was held by segments
/// and boxes). The cast of a composite at rest refused its window as parry's step count would
/// (more than 10⁴ of the summed `ccd_thickness` a step: 300 m/s for this sliver, 1.2e5 m/s for
/// an `Ellipse::new(0.5, 0.2)`), and rapier reads a refusal as no hit; the parts are cast by this
/// dispatcher, which bounds its own work. Every wall's hit is the segment's (the half-space's by
/// its own exact cast).
#[test]
fn a_fast_thin_spinning_body_is_stopped_by_every_composite_wall_as_by_a_segment() {
    use parry2d_f64::shape::{Compound, SharedShape};
    let d = SmoothDispatcher::default();
    let mut all = walls();
    let compound = Compound::new(vec![(
        Pose::IDENTITY,
        SharedShape::segment(Vector::new(-10.0, 0.0), Vector::new(10.0, 0.0)),
    )]);
    all.push(("Compound", Box::new(compound)));
    for (body, speed) in [(Ellipse::new(0.5, 0.0005), 400.0), (Ellipse::new(0.5, 0.2), 2e5)] {
        let m1 = NonlinearRigidMotion::new(Pose::translation(0.0, 3.0), Vector::ZERO, Vector::new(0.0, -speed), 1.0);
        let m2 = NonlinearRigidMotion::identity();
        let segment = d
            .cast_shapes_nonlinear(&m1, &body, &m2, &*all[0].1, 0.0, DT, false)
            .expect("a supported cast")
            .expect("a hit on the segment")
            .time_of_impact;
        for (name, wall) in &all {
            for (g1, g2, swap) in [
                (&body as &dyn Shape, &**wall, false),
                (&**wall, &body as &dyn Shape, true),
            ] {
                let (ma, mb) = if swap { (&m2, &m1) } else { (&m1, &m2) };
                let hit = d.cast_shapes_nonlinear(ma, g1, mb, g2, 0.0, DT, false);
                let t = match hit {
                    Ok(Some(h)) => h.time_of_impact,
                    other => panic!("{name} (swapped {swap}), {speed} m/s: {other:?}"),
                };
                // Each time within 1e-9 of the window of the true one (the README's guarantee).
                assert!(
                    (t - segment).abs() <= 2e-9 * DT,
                    "{name} (swapped {swap}): {t} against {segment}"
                );
            }
        }
    }
}

/// The sliver of the CCD scene suite's chain box (a closed polyline, the square of side 10 about
/// the origin), its tip pushed by a spin of thousands of rad/s 0.24 past the left wall just
/// under the top-left corner, its centre inside and moving away from both walls (rapier's CCD
/// motion of that step, 937 m/s right and 581 m/s down, at a tenth of its speed: the step's
/// translation then stays inside the box). The exact contact of the left wall's
/// segment is its end, the corner, inside the sliver, and a translation away from the wall takes
/// that end deeper into the body: rule 3 on it answered a start contact at 3.6e-6 of the step on
/// every step, and the sliver froze there with its velocity (found when the parts of a
/// composite came to have two manifolds, which changed the suite's trajectories). The contact
/// from the centre's side — the one the manifold hands rapier's solver, the tip 0.24 past the
/// wall's line — rises as the body moves away: no hit from the wall alone, the segment or the
/// whole box. Driven into the wall instead, the same pose is stopped where the tip has gone the
/// allowance (a quarter of the sliver's inradius) deeper.
#[test]
fn a_body_whose_tip_is_past_a_polyline_corner_moves_away_from_the_walls_without_a_hit() {
    let sliver = sliver();
    let h = 5.0;
    let corners = vec![
        Vector::new(-h, -h),
        Vector::new(h, -h),
        Vector::new(h, h),
        Vector::new(-h, h),
    ];
    let closed = Polyline::new(corners, Some(vec![[0, 1], [1, 2], [2, 3], [3, 0]]));
    let left = Segment::new(Vector::new(-h, h), Vector::new(-h, -h));
    let start = Pose::from_parts(
        Vector::new(-4.723181169219112, 4.985461368345202),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.9995653339982303, -0.029481232487913404),
    );
    let centre = Vector::new(-0.08333333333333352, 0.04166666666666709);
    let motion = |v: Vector| NonlinearRigidMotion::new(start, centre, v, 10.993200391483791);
    let still = NonlinearRigidMotion::identity();
    let d = SmoothDispatcher::default();
    // The tip is past the left wall's line by 0.24 (the manifold's contact).
    let tip = (start * Vector::new(0.5, 0.125)).x;
    assert!(tip < -h - 0.2, "tip at x = {tip}");
    let away = motion(Vector::new(93.74335566216045, -58.09257767207714));
    for (name, wall) in [("left segment", &left as &dyn Shape), ("closed polyline", &closed)] {
        let hit = d
            .cast_shapes_nonlinear(&away, &sliver, &still, wall, 0.0, DT, false)
            .expect("supported");
        assert!(hit.is_none(), "{name}: {hit:?}");
    }
    // Driven into the left wall (and along it, down): stopped once the tip is the allowance
    // deeper, a quarter of the sliver's inradius about its centre.
    let into = motion(Vector::new(-30.0, -5.0));
    let hit = d
        .cast_shapes_nonlinear(&into, &sliver, &still, &left, 0.0, DT, false)
        .expect("supported")
        .expect("a hit");
    // The inradius about the centroid: its distance to the nearest edge line.
    let v = [Vector::new(-0.5, 0.0), Vector::new(-0.25, 0.0), Vector::new(0.5, 0.125)];
    let inradius = (0..3)
        .map(|k| {
            let (a, b) = (v[k], v[(k + 1) % 3]);
            let e = (b - a).normalize();
            (centre - a).perp_dot(e).abs()
        })
        .fold(f64::INFINITY, f64::min);
    let allowance = smooth_ccd2d::CastPolicy::ALLOWANCE * inradius;
    // The tip's depth past x = −5 grows by what the centre moves left (the translation).
    let deeper = 30.0 * hit.time_of_impact;
    assert!(
        (deeper - allowance).abs() < 1e-9 * allowance.max(1.0),
        "{deeper} against {allowance}"
    );
}

/// The same sliver turning from tilted to flat on the wall and back, one workspace across the
/// calls (rapier's steps): the part's core manifold comes and goes after its manifold of points,
/// whose points keep their data (rapier's impulses) by feature id throughout; the core contact's
/// data is kept while its manifold stays.
#[test]
fn a_polyline_part_keeps_its_points_data_while_its_core_manifold_comes_and_goes() {
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
    use smooth_ccd2d::__is_core_feature as is_core;
    let sliver = sliver();
    let wall = Polyline::new(vec![Vector::new(-10.0, 0.0), Vector::new(10.0, 0.0)], None);
    let at = |tilt: f64| tip_on_wall(0.0, tilt);
    let d = SmoothDispatcher::default();
    let mut manifolds: Vec<ContactManifold<(), u32>> = Vec::new();
    let mut workspace = None;
    let mut stamp = 0u32;
    for (call, tilt) in [0.3, 0.29, 0.0, 0.3, 0.31].into_iter().enumerate() {
        d.contact_manifolds(&at(tilt), &wall, &sliver, 0.002, &mut manifolds, &mut workspace)
            .expect("answered");
        let what = format!("call {call}, tilt {tilt}: {manifolds:?}");
        assert_eq!(manifolds.len(), if tilt > 0.0 { 2 } else { 1 }, "{what}");
        assert!(manifolds.iter().all(|m| m.subshape1 == 0), "{what}");
        // The tip (−0.5, 0) is the same feature in every call: its data is the last call's.
        let tip = manifolds[0]
            .points
            .iter()
            .min_by(|a, b| a.dist.total_cmp(&b.dist))
            .expect("a point");
        assert!(!is_core(tip.fid2.0), "{what}");
        assert_eq!(tip.data, stamp, "{what}");
        if tilt > 0.0 {
            let core = &manifolds[1].points[0];
            assert!(is_core(core.fid2.0), "{what}");
            // Kept from the previous call only where the previous call had a core manifold.
            let expected = if call == 0 || call == 3 { 0 } else { stamp };
            assert_eq!(core.data, expected, "{what}");
        }
        stamp += 1;
        for m in manifolds.iter_mut() {
            for p in m.points.iter_mut() {
                p.data = stamp;
            }
        }
    }
}

/// A heightfield's part, as a polyline's: the sliver's tip on it, its long side 0.3 rad off:
/// the part's two points (the far end 0.3 away), then its core contact in a manifold of its own,
/// both with the part's sub-shape id; the part is a `Segment` (the contact from the side of the
/// body's centre applies, as to a polyline's part).
#[test]
fn a_heightfield_part_keeps_the_far_point_and_its_core_contact_in_two_manifolds() {
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
    use smooth_ccd2d::__is_core_feature as is_core;
    let sliver = sliver();
    let pos12 = tip_on_wall(2.0, 0.3);
    let field = HeightField::new(vec![0.0, 0.0, 0.0], Vector::new(20.0, 1.0));
    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
    SmoothDispatcher::default()
        .contact_manifolds(&pos12, &field, &sliver, 0.002, &mut manifolds, &mut None)
        .expect("answered");
    let what = format!("{manifolds:?}");
    let held: Vec<&ContactManifold<(), ()>> = manifolds.iter().filter(|m| !m.points.is_empty()).collect();
    assert_eq!(held.len(), 2, "{what}");
    assert!(held.iter().all(|m| m.subshape1 == 1), "{what}");
    assert_eq!(held[0].points.len(), 2, "{what}");
    assert!(held[0].points.iter().all(|p| !is_core(p.fid2.0)), "{what}");
    assert!(held[0].points.iter().any(|p| p.dist > 0.2), "the far end: {what}");
    assert_eq!(held[1].points.len(), 1, "{what}");
    assert!(is_core(held[1].points[0].fid2.0), "{what}");
}

/// Rule 3 against a segment measures the body's reach past the segment's line, from the side of
/// its centre (where that contact is not the exact one): 200 seeded poses of the sliver over the
/// end of a segment (its centre over the segment, 2–5 cm above it, any angle, its tip past the
/// line), driven into the wall at 30 m/s with a sideways 0–20 m/s. Wherever the rule reads the
/// line (`__rule3_line_contact`), its depth is the sliver's support point past the line, and the
/// cast stops the body exactly where the translation has taken that point the allowance deeper
/// (the core, 2 cm off at least, comes later) — beyond the segment's end too, where the
/// manifold's one-sided depth is shallower than the line's.
#[test]
fn rule_3_against_a_segment_stops_a_body_the_allowance_past_the_line_from_its_centre_side() {
    use parry2d_f64::shape::SupportMap;
    let sliver = sliver();
    let seg = Segment::new(Vector::new(-1.0, 0.0), Vector::new(1.0, 0.0));
    let centroid = Vector::new(-0.25 / 3.0, 0.125 / 3.0);
    let v = [Vector::new(-0.5, 0.0), Vector::new(-0.25, 0.0), Vector::new(0.5, 0.125)];
    let inradius = (0..3)
        .map(|k| {
            let (a, b) = (v[k], v[(k + 1) % 3]);
            (centroid - a).perp_dot((b - a).normalize()).abs()
        })
        .fold(f64::INFINITY, f64::min);
    let allowance = smooth_ccd2d::CastPolicy::ALLOWANCE * inradius;
    let d = SmoothDispatcher::default();
    let still = NonlinearRigidMotion::identity();
    let mut rng = common::rng::Rng::new(777);
    let mut r = || rng.unit();
    let (mut read, mut beyond) = (0, 0);
    for _ in 0..200 {
        let rot = parry2d_f64::math::Rotation::new(core::f64::consts::TAU * r());
        let centre = Vector::new(0.5 + 0.49 * r(), 0.02 + 0.03 * r());
        let pose = Pose::from_parts(centre - rot * centroid, rot);
        let Some((n, depth)) = smooth_ccd2d::__rule3_line_contact(&pose, &seg, &sliver) else {
            continue;
        };
        read += 1;
        // The normal is the wall's (from the segment up to the body); the depth, the lowest
        // point's height.
        assert!((n - Vector::Y).length() < 1e-12, "{n:?}");
        let lowest = sliver.support_point(&pose, -Vector::Y);
        assert!((depth - lowest.y).abs() < 1e-12, "{depth} against {}", lowest.y);
        if lowest.x > 1.0 {
            beyond += 1;
        }
        let vel = Vector::new(20.0 * r(), -30.0);
        let m = NonlinearRigidMotion::new(pose, centroid, vel, 0.0);
        let hit = d
            .cast_shapes_nonlinear(&m, &sliver, &still, &seg, 0.0, DT, false)
            .expect("supported")
            .expect("a hit");
        let level = (-allowance).min(depth - allowance);
        let t = (depth - level) / 30.0;
        assert!(
            (hit.time_of_impact - t).abs() <= 1e-12,
            "{} against {t}",
            hit.time_of_impact
        );
    }
    println!("rule 3 on the line: {read} of 200 poses, {beyond} with the lowest point beyond the end");
    assert!(read >= 50 && beyond >= 10, "{read} read, {beyond} beyond the end");
}
