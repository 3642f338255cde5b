//! Degenerate starts: a shape whose centre sits exactly on (or within 1e-6 of) a polygon's
//! vertex, on one of its edges, or on its centre, the pair deep in contact at the start — the
//! issue's "pathological cast" (a unit disc centred on the corner of a unit box took 4,002
//! evaluations and 1.7 ms to answer `PenetratingAtStart`; at (1.01, 1) 10 evaluations) and its
//! neighbours. For disc–polygon and ellipse–polygon pairs (the φ–t tracker, through
//! `shape_time_of_impact` and `time_of_impact` with `BallCurve` and `CustomCurve` discs) and
//! polygon–polygon pairs (the gap tracker), both argument orders, `stop_at_penetration` true and
//! false, the bodies at rest or moving, each case pins:
//!
//! * the status (`PenetratingAtStart` whenever the start is a contact the query must report);
//! * an upper bound on `cost.evaluations` (not wall time: CI machines are noisy). The φ–t
//!   tracker counts pair evaluations; the gap tracker counts exact distances (each a walk over
//!   the features), so their bounds differ;
//! * the answer against the independent reference of `tests/common/reference.rs` (dense
//!   sampling of the gap over directions, golden-section refinement): the signed distance at the
//!   reported time, and the witnesses realising it along the normal.
//!
//! The evaluation bounds are about 1.3× what the cases take (`cargo test --release --test
//! degenerate_starts -- --nocapture` prints the largest per group).

mod common;

use common::reference::reference_distance;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use parry2d_f64::shape::{Ball, Cuboid, Shape};
use smooth_ccd2d::{
    shape_time_of_impact, stationary_distance, time_of_impact, BallCurve, ConvexCurve, CustomCurve, DistanceOptions,
    DistanceStatus, Ellipse, RoundedPolygon, TimeOfImpact, ToiOptions, ToiStatus,
};
use std::collections::BTreeMap;

/// The offset of the "near" placements.
const NEAR: f64 = 1e-6;
/// The answer's distance against the reference's, relative to the pair's size.
const DISTANCE_TOL: f64 = 1e-10;

/// Pair evaluations of the φ–t tracker with `stop_at_penetration` (or at rest): the stationary
/// distance at the start — its 16 seeds, a root solve, a few splits; 34 at most (the issue's
/// case took 4,002: the evaluation cap).
const CURVE_START_EVALUATIONS: usize = 44;
/// … and without it, moving apart: the walk out of the contact, up to seven stationary
/// distances over the window (1/64 of it, doubled each step); 195 at most.
const CURVE_LEAVE_EVALUATIONS: usize = 256;
/// Exact distances of the gap tracker at the start (one) …
const GAP_START_EVALUATIONS: usize = 1;
/// … and walking out of a contact (one per step of the walk, and the window's end); 9 at most.
const GAP_LEAVE_EVALUATIONS: usize = 12;

/// The unit box: the core square [0, 1]², sharp.
fn unit_box() -> RoundedPolygon {
    RoundedPolygon::new(
        &[
            Vector::new(0.0, 0.0),
            Vector::new(1.0, 0.0),
            Vector::new(1.0, 1.0),
            Vector::new(0.0, 1.0),
        ],
        0.0,
    )
}

/// A square of side 1 centred on its origin, dilated by `radius`.
fn centred_square(radius: f64) -> RoundedPolygon {
    RoundedPolygon::new(
        &[
            Vector::new(-0.5, -0.5),
            Vector::new(0.5, -0.5),
            Vector::new(0.5, 0.5),
            Vector::new(-0.5, 0.5),
        ],
        radius,
    )
}

/// Where the placed shape's centre sits, in the world where the polygon's core is [0, 1]²: on
/// and within 1e-6 of a vertex (outside along the diagonal, inside, along an edge, outside along
/// an edge's line), of an edge's middle (on it, inside, outside, along it), of the centre.
fn places() -> Vec<(&'static str, Vector)> {
    let (v, o, m, c) = (
        Vector::new(1.0, 1.0),
        Vector::ZERO,
        Vector::new(1.0, 0.5),
        Vector::new(0.5, 0.5),
    );
    let e = NEAR;
    vec![
        ("on the vertex (1, 1)", v),
        ("on the vertex (0, 0)", o),
        ("1e-6 outside the vertex, diagonally", v + Vector::new(e, e)),
        ("1e-6 inside the vertex, diagonally", v - Vector::new(e, e)),
        ("1e-6 from the vertex along an edge", v - Vector::new(e, 0.0)),
        ("1e-6 from the vertex on an edge's line", v + Vector::new(0.0, e)),
        ("on an edge's middle", m),
        ("1e-6 inside an edge", m - Vector::new(e, 0.0)),
        ("1e-6 outside an edge", m + Vector::new(e, 0.0)),
        ("on an edge, 1e-6 from its middle", m + Vector::new(0.0, e)),
        ("on the centre", c),
        ("1e-6 from the centre", c + Vector::new(e, -e)),
    ]
}

/// A shape for the queries and its curve for the reference (parry's `Ball` and `Cuboid` as the
/// crate's curves of the same boundary), with the pose that puts it where the case wants it
/// relative to its local frame (a centred square's core on [0, 1]²: translated by (½, ½)).
struct Body {
    name: &'static str,
    shape: Box<dyn Shape>,
    curve: Box<dyn ConvexCurve>,
    offset: Vector,
}

fn body(name: &'static str, shape: Box<dyn Shape>, curve: Box<dyn ConvexCurve>, offset: Vector) -> Body {
    Body {
        name,
        shape,
        curve,
        offset,
    }
}

/// The shapes placed with their centre on the places (φ–t tracker side: strictly convex).
fn round_bodies() -> Vec<Body> {
    vec![
        body(
            "disc (Ellipse 1×1)",
            Box::new(Ellipse::new(1.0, 1.0)),
            Box::new(Ellipse::new(1.0, 1.0)),
            Vector::ZERO,
        ),
        body(
            "parry Ball(1)",
            Box::new(Ball::new(1.0)),
            Box::new(BallCurve { radius: 1.0 }),
            Vector::ZERO,
        ),
        body(
            "ellipse 1×0.5",
            Box::new(Ellipse::new(1.0, 0.5)),
            Box::new(Ellipse::new(1.0, 0.5)),
            Vector::ZERO,
        ),
    ]
}

/// The polygons whose core is [0, 1]² in the world.
fn polygons() -> Vec<Body> {
    let half = Vector::new(0.5, 0.5);
    vec![
        body("unit box", Box::new(unit_box()), Box::new(unit_box()), Vector::ZERO),
        body(
            "box rounded by 0.2",
            Box::new(centred_square(0.2)),
            Box::new(centred_square(0.2)),
            half,
        ),
        body(
            "parry Cuboid",
            Box::new(Cuboid::new(half)),
            Box::new(centred_square(0.0)),
            half,
        ),
    ]
}

/// The polygons placed with their centre on the places (gap tracker side).
fn square_bodies() -> Vec<Body> {
    vec![
        body(
            "square",
            Box::new(centred_square(0.0)),
            Box::new(centred_square(0.0)),
            Vector::ZERO,
        ),
        body(
            "square rounded by 0.1",
            Box::new(centred_square(0.1)),
            Box::new(centred_square(0.1)),
            Vector::ZERO,
        ),
        body(
            "parry Cuboid",
            Box::new(Cuboid::new(Vector::new(0.5, 0.5))),
            Box::new(centred_square(0.0)),
            Vector::ZERO,
        ),
    ]
}

/// The placed shape at rest, or moving (translating and spinning) out of the start.
fn motion(at: Vector, angle: f64, moving: bool) -> NonlinearRigidMotion {
    let (v, w) = if moving {
        (Vector::new(0.3, -0.2), 1.5)
    } else {
        (Vector::ZERO, 0.0)
    };
    NonlinearRigidMotion::new(Pose::new(at, angle), Vector::ZERO, v, w)
}

/// The pose of a motion at t (parry's own).
fn pose_at(m: &NonlinearRigidMotion, t: f64) -> Pose {
    m.position_at_time(t)
}

/// One query and what it is checked against.
struct Case<'a> {
    what: String,
    /// The shapes in the call's order, their curves and motions.
    curves: [&'a dyn ConvexCurve; 2],
    motions: [NonlinearRigidMotion; 2],
    stop: bool,
    moving: bool,
}

/// What went wrong with one answer, if anything: the status, the distance at `time` against the
/// reference, the witnesses along the normal, every number finite.
fn check(case: &Case, r: &TimeOfImpact) -> Option<String> {
    let size = case.curves[0].bounding_radius().max(case.curves[1].bounding_radius());
    let finite = [r.time, r.distance, r.distance_rate].iter().all(|x| x.is_finite())
        && [r.point1, r.point2, r.normal1, r.normal2].iter().all(|v| v.is_finite());
    if !finite {
        return Some(format!("a number is not finite: {r:?}"));
    }
    // Every case starts deep in contact: with the stop, or at rest (D' = 0), the answer is the
    // start; moving apart without it, the walk out of the contact ends at the window's end in
    // contact (`NoHit`), or where the shapes approach again (`Hit`, still in contact).
    match (case.stop || !case.moving, r.status) {
        (true, ToiStatus::PenetratingAtStart) if r.time == 0.0 => {}
        (false, ToiStatus::NoHit) if r.time == 1.0 => {}
        (false, ToiStatus::Hit | ToiStatus::PenetratingAtStart) => {}
        (_, s) => return Some(format!("status {s:?} at t = {}", r.time)),
    }
    let poses = [pose_at(&case.motions[0], r.time), pose_at(&case.motions[1], r.time)];
    let reference = reference_distance(case.curves[0], &poses[0], case.curves[1], &poses[1]).distance;
    if (r.distance - reference).abs() > DISTANCE_TOL * size {
        return Some(format!(
            "distance {} at t = {}, the reference {reference} ({:.1e} off)",
            r.distance,
            r.time,
            (r.distance - reference).abs()
        ));
    }
    if r.status == ToiStatus::Hit && r.distance > 1e-10 * size {
        return Some(format!("a Hit out of contact: distance {}", r.distance));
    }
    // The witnesses realise the distance along shape 1's normal (and shape 2's is opposite).
    let (p1, p2) = (poses[0] * r.point1, poses[1] * r.point2);
    let (n1, n2) = (poses[0].rotation * r.normal1, poses[1].rotation * r.normal2);
    let along = (p2 - p1).dot(n1);
    if (along - r.distance).abs() > DISTANCE_TOL * size || (n1 + n2).length() > 1e-9 {
        return Some(format!(
            "witnesses {p1} – {p2} give {along} along {n1} (shape 2's normal {n2}), distance {}",
            r.distance
        ));
    }
    None
}

/// The cases' outcomes, by group: count, largest evaluation count, the failures.
#[derive(Default)]
struct Tally {
    groups: BTreeMap<String, (usize, usize, usize)>,
    failures: Vec<String>,
}

impl Tally {
    /// Records the answer `r` (or error) of `case` in `group` with its evaluation `bound`.
    fn record(&mut self, group: &str, bound: usize, case: &Case, r: Result<TimeOfImpact, smooth_ccd2d::QueryError>) {
        let g = self.groups.entry(group.to_string()).or_insert((0, 0, bound));
        g.0 += 1;
        let problem = match r {
            Err(e) => Some(format!("error {e:?}")),
            Ok(r) => {
                g.1 = g.1.max(r.cost.evaluations);
                if r.cost.evaluations > bound {
                    Some(format!("{} evaluations (bound {bound}): {r:?}", r.cost.evaluations))
                } else {
                    check(case, &r)
                }
            }
        };
        if let Some(p) = problem {
            self.failures.push(format!("{}: {p}", case.what));
        }
    }

    /// Prints the groups and fails with the first failures.
    fn finish(self, title: &str) {
        let total: usize = self.groups.values().map(|g| g.0).sum();
        println!("{title}: {total} cases");
        for (name, (n, most, bound)) in &self.groups {
            println!("  {name}: {n} cases, at most {most} evaluations (bound {bound})");
        }
        println!("  failures: {}", self.failures.len());
        assert!(
            self.failures.is_empty(),
            "{} of {total} cases failed; the first:\n{}",
            self.failures.len(),
            self.failures.iter().take(12).cloned().collect::<Vec<_>>().join("\n")
        );
    }
}

/// The options of the cases.
fn options(stop: bool) -> ToiOptions {
    ToiOptions::default().with_stop_at_penetration(stop)
}

/// The group and bound of a case: by route, stop and motion.
fn group(route: &str, stop: bool, moving: bool, start: usize, leave: usize) -> (String, usize) {
    let leaving = !stop && moving;
    let name = format!(
        "{route}, {}",
        if leaving {
            "without stop, moving apart"
        } else if stop {
            "with stop"
        } else {
            "without stop, at rest"
        }
    );
    (name, if leaving { leave } else { start })
}

#[test]
fn the_unit_disc_on_the_unit_boxs_corner_is_penetrating_at_start_in_a_few_evaluations() {
    // The case exactly: a unit disc (`Ellipse` 1 × 1) centred on the corner (1, 1) of the
    // unit box, `stop_at_penetration`, both orders, at rest and moving.
    let (disc, bx) = (Ellipse::new(1.0, 1.0), unit_box());
    let (mut cases, mut most) = (0, 0);
    for moving in [false, true] {
        let m_disc = motion(Vector::new(1.0, 1.0), 0.0, moving);
        let m_box = NonlinearRigidMotion::identity();
        for swapped in [false, true] {
            let r = if swapped {
                shape_time_of_impact(&bx, &m_box, &disc, &m_disc, 0.0, 1.0, &options(true))
            } else {
                shape_time_of_impact(&disc, &m_disc, &bx, &m_box, 0.0, 1.0, &options(true))
            }
            .unwrap();
            assert_eq!(r.status, ToiStatus::PenetratingAtStart);
            assert_eq!(r.time, 0.0);
            assert!((r.distance + 1.0).abs() < 1e-12, "{}", r.distance);
            assert!(r.cost.evaluations <= 32, "{} evaluations", r.cost.evaluations);
            most = most.max(r.cost.evaluations);
            cases += 1;
        }
    }
    // The stationary distance under it: certified (`Penetrating`), not the evaluation cap.
    let d = stationary_distance(&bx, &disc, &Pose::translation(1.0, 1.0), &DistanceOptions::default()).unwrap();
    assert_eq!(d.status, DistanceStatus::Penetrating);
    assert_eq!(d.distance, -1.0);
    assert!(d.evaluations <= 24, "{} evaluations", d.evaluations);
    println!(
        "the issue's corner cast: {cases} cases, at most {most} evaluations (4,002 before); the stationary distance \
         under it {} evaluations (4,000, the cap, before)",
        d.evaluations
    );
}

#[test]
fn discs_and_ellipses_on_a_polygons_vertex_edge_or_centre_answer_exactly_in_bounded_evaluations() {
    // shape_time_of_impact, the φ–t tracker's route (the placed shape strictly convex).
    let mut tally = Tally::default();
    for placed in round_bodies() {
        for poly in polygons() {
            for (where_, at) in places() {
                for (stop, moving, swapped) in flags() {
                    let m_placed = motion(at, 0.0, moving);
                    let m_poly = motion(poly.offset, 0.0, false);
                    let (g1, g2, m1, m2, c1, c2) = if swapped {
                        (&poly.shape, &placed.shape, m_poly, m_placed, &poly.curve, &placed.curve)
                    } else {
                        (&placed.shape, &poly.shape, m_placed, m_poly, &placed.curve, &poly.curve)
                    };
                    let case = Case {
                        what: format!(
                            "{} {where_} of the {} (swapped {swapped}, stop {stop}, moving {moving})",
                            placed.name, poly.name
                        ),
                        curves: [&**c1, &**c2],
                        motions: [m1, m2],
                        stop,
                        moving,
                    };
                    let r = shape_time_of_impact(&**g1, &m1, &**g2, &m2, 0.0, 1.0, &options(stop));
                    let (name, bound) = group(
                        "disc/ellipse – polygon",
                        stop,
                        moving,
                        CURVE_START_EVALUATIONS,
                        CURVE_LEAVE_EVALUATIONS,
                    );
                    tally.record(&name, bound, &case, r);
                }
            }
        }
    }
    tally.finish("disc and ellipse starts on a polygon (shape_time_of_impact)");
}

#[test]
fn ball_and_custom_curves_take_the_same_bounded_path_through_time_of_impact() {
    // `time_of_impact` on the curves themselves: a `BallCurve` and a `CustomCurve` wrapping the
    // unit disc (its curvature bounds delegated), against the unit box and the rounded box.
    let ball = BallCurve { radius: 1.0 };
    let custom = CustomCurve::new(Ellipse::new(1.0, 1.0));
    let round: [(&str, &dyn ConvexCurve); 2] = [("BallCurve", &ball), ("CustomCurve disc", &custom)];
    let (bx, rounded) = (unit_box(), centred_square(0.2));
    let boxes: [(&str, &dyn ConvexCurve, Vector); 2] = [
        ("unit box", &bx, Vector::ZERO),
        ("box rounded by 0.2", &rounded, Vector::new(0.5, 0.5)),
    ];
    let mut tally = Tally::default();
    for (rn, r) in round {
        for (bn, b, offset) in boxes {
            for (where_, at) in places() {
                for (stop, moving, swapped) in flags() {
                    let m_r = motion(at, 0.0, moving);
                    let m_b = motion(offset, 0.0, false);
                    let (c1, c2, m1, m2) = if swapped { (b, r, m_b, m_r) } else { (r, b, m_r, m_b) };
                    let case = Case {
                        what: format!("{rn} {where_} of the {bn} (swapped {swapped}, stop {stop}, moving {moving})"),
                        curves: [c1, c2],
                        motions: [m1, m2],
                        stop,
                        moving,
                    };
                    let res = time_of_impact(c1, &m1, c2, &m2, 0.0, 1.0, &options(stop));
                    let (name, bound) = group(
                        "BallCurve/CustomCurve – polygon",
                        stop,
                        moving,
                        CURVE_START_EVALUATIONS,
                        CURVE_LEAVE_EVALUATIONS,
                    );
                    tally.record(&name, bound, &case, res);
                }
            }
        }
    }
    tally.finish("BallCurve and CustomCurve starts on a polygon (time_of_impact)");
}

#[test]
fn polygons_on_a_polygons_vertex_edge_or_centre_answer_exactly_in_bounded_evaluations() {
    // The gap tracker's route: squares (sharp, rounded, parry's Cuboid) centred on the places,
    // turned by 0, 0.3 rad and π/4, against the polygons of [0, 1]².
    let mut tally = Tally::default();
    for placed in square_bodies() {
        for poly in polygons() {
            for (where_, at) in places() {
                for angle in [0.0, 0.3, core::f64::consts::FRAC_PI_4] {
                    for (stop, moving, swapped) in flags() {
                        let m_placed = motion(at, angle, moving);
                        let m_poly = motion(poly.offset, 0.0, false);
                        let (g1, g2, m1, m2, c1, c2) = if swapped {
                            (&poly.shape, &placed.shape, m_poly, m_placed, &poly.curve, &placed.curve)
                        } else {
                            (&placed.shape, &poly.shape, m_placed, m_poly, &placed.curve, &poly.curve)
                        };
                        let case = Case {
                            what: format!(
                                "{} turned {angle:.2} {where_} of the {} (swapped {swapped}, stop {stop}, moving \
                                 {moving})",
                                placed.name, poly.name
                            ),
                            curves: [&**c1, &**c2],
                            motions: [m1, m2],
                            stop,
                            moving,
                        };
                        let r = shape_time_of_impact(&**g1, &m1, &**g2, &m2, 0.0, 1.0, &options(stop));
                        let (name, bound) = group(
                            "polygon – polygon",
                            stop,
                            moving,
                            GAP_START_EVALUATIONS,
                            GAP_LEAVE_EVALUATIONS,
                        );
                        tally.record(&name, bound, &case, r);
                    }
                }
            }
        }
    }
    tally.finish("polygon starts on a polygon (shape_time_of_impact, the gap tracker)");
}

#[test]
fn the_stationary_distance_certifies_degenerate_overlaps_in_bounded_evaluations() {
    // Under the casts: the stationary distance of each placed disc or ellipse (and the discs'
    // curves) against each polygon's curve, in both roles where both can be object2, certified
    // (`Penetrating`) and equal to the reference.
    let placed: [(&str, Box<dyn ConvexCurve>); 4] = [
        ("Ellipse 1×1", Box::new(Ellipse::new(1.0, 1.0))),
        ("BallCurve 1", Box::new(BallCurve { radius: 1.0 })),
        ("CustomCurve disc", Box::new(CustomCurve::new(Ellipse::new(1.0, 1.0)))),
        ("Ellipse 1×0.5", Box::new(Ellipse::new(1.0, 0.5))),
    ];
    let (mut cases, mut most) = (0, 0);
    for (pn, p) in &placed {
        for poly in polygons() {
            for (where_, at) in places() {
                for angle in [0.0, 0.3] {
                    // object2 (the placed curve) at `at` in the polygon's frame.
                    let pos12 = Pose::new(at - poly.offset, angle);
                    let d = stationary_distance(&*poly.curve, &**p, &pos12, &DistanceOptions::default()).unwrap();
                    let reference = reference_distance(&*poly.curve, &Pose::IDENTITY, &**p, &pos12).distance;
                    let what = format!("{pn} turned {angle} {where_} of the {}", poly.name);
                    assert_eq!(d.status, DistanceStatus::Penetrating, "{what}: {d:?}");
                    assert!(
                        (d.distance - reference).abs() < DISTANCE_TOL * 1.5,
                        "{what}: {d:?} vs {reference}"
                    );
                    assert!(d.evaluations <= CURVE_START_EVALUATIONS, "{what}: {d:?}");
                    most = most.max(d.evaluations);
                    cases += 1;
                }
            }
        }
    }
    println!("stationary distances of degenerate overlaps: {cases} cases, at most {most} evaluations");
}

#[test]
fn a_start_in_contact_that_separates_for_the_whole_window_reports_the_distance_at_its_end() {
    // Without the stop, a disc centred on the box's corner and moving away keeps a contact
    // that separates until the window ends: `NoHit` at the window's end, with the distance (and
    // witnesses) there — the disc's centre at (1.3, 0.8), 0.3 right of the right face: depth
    // 0.7 — not those of the start.
    let (disc, bx) = (Ellipse::new(1.0, 1.0), unit_box());
    let m_disc = motion(Vector::new(1.0, 1.0), 0.0, true);
    let m_box = NonlinearRigidMotion::identity();
    for swapped in [false, true] {
        let r = if swapped {
            time_of_impact(&bx, &m_box, &disc, &m_disc, 0.0, 1.0, &options(false))
        } else {
            time_of_impact(&disc, &m_disc, &bx, &m_box, 0.0, 1.0, &options(false))
        }
        .unwrap();
        assert_eq!(r.status, ToiStatus::NoHit, "{r:?}");
        assert_eq!(r.time, 1.0);
        assert!((r.distance + 0.7).abs() < 1e-12, "{r:?}");
        assert!(r.distance_rate > 0.0, "{r:?}");
    }
    println!("a start that separates for the whole window: 2 cases");
}

/// (stop, moving, swapped) over all eight combinations.
fn flags() -> impl Iterator<Item = (bool, bool, bool)> {
    (0..8).map(|k| (k & 1 != 0, k & 2 != 0, k & 4 != 0))
}
