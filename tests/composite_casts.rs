//! Casts against a composite at rest (rapier's CCD against level geometry: a polyline, a
//! heightfield, a compound of the static world), which `SmoothDispatcher` answers part by part,
//! walking the composite's BVH from the earliest time the body can reach a node and culling the
//! parts it cannot reach: the answer must be the earliest hit over *every* part, each cast on its
//! own (the brute force), to the bit, whatever the culling skipped. And a body sliding over a
//! long polyline without touching it must not cast the segments under its path.

#[path = "common/curves.rs"]
mod curves;
#[path = "common/rng.rs"]
mod rng;

use curves::EccentricEllipse;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{NonlinearRigidMotion, QueryDispatcher};
use parry2d_f64::shape::{Compound, HeightField, Polyline, Segment, Shape, SharedShape};
use rng::Rng;
use smooth_ccd2d::{
    CapsuleEllipse, ConvexCurve, CurvePoint, CustomCurve, Ellipse, RoundedPolygon, SmoothDispatcher, ToiOptions,
};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

const DT: f64 = 1.0 / 60.0;

/// The moving bodies: every family of the crate and a user's curve with only `eval` (parry's own
/// shapes against a composite are parry's to answer, with its own composite cast).
fn bodies() -> Vec<(&'static str, Box<dyn Shape>)> {
    let sliver: Vec<Vector> = [(-0.5, 0.0), (-0.25, 0.0), (0.5, 0.125)]
        .iter()
        .map(|&(x, y)| Vector::new(x, y))
        .collect();
    vec![
        ("ellipse", Box::new(Ellipse::new(0.5, 0.2))),
        ("disc", Box::new(Ellipse::new(0.3, 0.3))),
        ("rounded hexagon", Box::new(RoundedPolygon::regular(6, 0.4, 0.05))),
        ("sliver", Box::new(RoundedPolygon::new(&sliver, 0.0))),
        ("capsule-ellipse", Box::new(CapsuleEllipse::new(0.2, 0.3, 0.4))),
        (
            "user curve",
            Box::new(CustomCurve::new(EccentricEllipse {
                a: 0.5,
                b: 0.2,
                center: Vector::new(0.05, 0.0),
            })),
        ),
    ]
}

/// A jagged terrain over −10 ≤ x ≤ 10, heights within ±0.3: `n` + 1 heights.
fn heights(rng: &mut Rng, n: usize) -> Vec<f64> {
    (0..=n).map(|_| rng.uniform(-0.3, 0.3)).collect()
}

/// A composite at rest and its parts with their poses in its frame.
struct Ground {
    name: &'static str,
    shape: Box<dyn Shape>,
    parts: Vec<(Pose, Box<dyn Shape>)>,
}

fn grounds(rng: &mut Rng) -> Vec<Ground> {
    let n = rng.int(8, 60);
    let h = heights(rng, n);
    let xs: Vec<f64> = (0..=n).map(|i| -10.0 + 20.0 * i as f64 / n as f64).collect();
    let points: Vec<Vector> = xs.iter().zip(&h).map(|(&x, &y)| Vector::new(x, y)).collect();
    let segments = |pts: &[Vector]| -> Vec<(Pose, Box<dyn Shape>)> {
        pts.windows(2)
            .map(|w| (Pose::IDENTITY, Box::new(Segment::new(w[0], w[1])) as Box<dyn Shape>))
            .collect()
    };
    let polyline = Ground {
        name: "polyline",
        shape: Box::new(Polyline::new(points.clone(), None)),
        parts: segments(&points),
    };
    let hf = HeightField::new(h.clone(), Vector::new(20.0, 1.0));
    let hf_parts = hf
        .segments()
        .map(|s| (Pose::IDENTITY, Box::new(s) as Box<dyn Shape>))
        .collect();
    let heightfield = Ground {
        name: "heightfield",
        shape: Box::new(hf),
        parts: hf_parts,
    };
    let mut children = Vec::new();
    for _ in 0..rng.int(3, 8) {
        let pose = Pose::new(Vector::new(rng.uniform(-9.0, 9.0), rng.uniform(-0.5, 0.2)), rng.angle());
        let child = if rng.chance(0.5) {
            SharedShape::cuboid(rng.log_uniform(0.02, 2.0), rng.log_uniform(0.02, 0.5))
        } else {
            SharedShape::new(Ellipse::new(rng.log_uniform(0.05, 1.0), rng.log_uniform(0.05, 1.0)))
        };
        children.push((pose, child));
    }
    let compound_parts = children.iter().map(|(p, s)| (*p, s.clone_dyn())).collect();
    let compound = Ground {
        name: "compound",
        shape: Box::new(Compound::new(children)),
        parts: compound_parts,
    };
    vec![polyline, heightfield, compound]
}

/// A spin from none to far beyond half a turn a step.
fn spin(rng: &mut Rng) -> f64 {
    match rng.int(0, 3) {
        0 => 0.0,
        1 => rng.sign() * rng.uniform(0.0, 3.0),
        2 => rng.sign() * rng.uniform(3.0, 300.0),
        _ => rng.sign() * 1e4,
    }
}

/// The earliest hit of `body` moving by `mb` over every part of `ground` (at rest at `pose`), each
/// cast by itself: (time, status) or `None`.
fn brute_force(
    d: &SmoothDispatcher,
    mb: &NonlinearRigidMotion,
    body: &dyn Shape,
    ground: &Ground,
    pose: Pose,
    stop: bool,
) -> Option<f64> {
    let mut best: Option<f64> = None;
    for (part_pose, part) in &ground.parts {
        let mp = NonlinearRigidMotion::constant_position(pose).prepend(*part_pose);
        if let Ok(Some(hit)) = d.cast_shapes_nonlinear(mb, body, &mp, &**part, 0.0, DT, stop) {
            if best.is_none_or(|b| hit.time_of_impact < b) {
                best = Some(hit.time_of_impact);
            }
        }
    }
    best
}

#[test]
fn a_cast_against_a_composite_at_rest_is_the_earliest_hit_over_every_part() {
    let d = SmoothDispatcher::default();
    let mut rng = Rng::new(0x00C0_4D05_17E5);
    let (mut cases, mut hits, mut parts) = (0usize, 0usize, 0usize);
    for _ in 0..150 {
        let grounds = grounds(&mut rng);
        for ground in &grounds {
            for (name, body) in bodies() {
                let pose = Pose::new(
                    Vector::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)),
                    rng.uniform(-0.3, 0.3),
                );
                let start = pose * Pose::new(Vector::new(rng.uniform(-9.0, 9.0), rng.uniform(0.0, 1.2)), rng.angle());
                let dir = Vector::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 0.3)).normalize();
                let v = dir * rng.log_uniform(1.0, 3000.0);
                let centre = body.mass_properties(1.0).local_com;
                let mb = NonlinearRigidMotion::new(start, centre, v, spin(&mut rng));
                let stop = rng.chance(0.3);
                let mc = NonlinearRigidMotion::constant_position(pose);
                let got = d
                    .cast_shapes_nonlinear(&mb, body.as_ref(), &mc, ground.shape.as_ref(), 0.0, DT, stop)
                    .expect("a composite at rest is supported")
                    .map(|h| h.time_of_impact);
                let want = brute_force(&d, &mb, body.as_ref(), ground, pose, stop);
                assert_eq!(
                    got.map(f64::to_bits),
                    want.map(f64::to_bits),
                    "{name} against the {}: composite {got:?}, every part {want:?} ({mb:?}, stop {stop})",
                    ground.name
                );
                cases += 1;
                hits += usize::from(got.is_some());
                parts += ground.parts.len();
            }
        }
    }
    println!("{cases} composite casts ({hits} hits), each against {parts} part casts in all");
}

/// A user's ellipse that counts its evaluations.
#[derive(Debug)]
struct Counted(EccentricEllipse, Arc<AtomicUsize>);

impl ConvexCurve for Counted {
    fn eval(&self, phi: f64) -> CurvePoint {
        self.1.fetch_add(1, Ordering::Relaxed);
        self.0.eval(phi)
    }
    fn bounding_radius(&self) -> f64 {
        self.0.bounding_radius()
    }
}

#[test]
fn a_body_sliding_over_a_long_polyline_without_touching_it_casts_none_of_its_segments() {
    let d = SmoothDispatcher::default();
    let evals = Arc::new(AtomicUsize::new(0));
    let curve = CustomCurve::new(Counted(
        EccentricEllipse {
            a: 0.5,
            b: 0.2,
            center: Vector::new(0.05, 0.0),
        },
        evals.clone(),
    ));
    // 10⁴ segments of 1 cm; the body 10⁻⁴ above them, sliding 50 m in the step.
    let n = 10_000;
    let ground = Polyline::new(
        (0..=n)
            .map(|i| Vector::new(-50.0 + 100.0 * i as f64 / n as f64, 0.0))
            .collect(),
        None,
    );
    let y = -curve.compute_local_aabb().mins.y + 1e-4;
    let still = NonlinearRigidMotion::identity();
    // The evaluations of one cast of the curve from (x, y) at (v, 0) against `target`, and its hit.
    let cast = |x: f64, v: f64, target: &dyn Shape| {
        let motion = NonlinearRigidMotion::new(Pose::translation(x, y), Vector::ZERO, Vector::new(v, 0.0), 0.0);
        evals.store(0, Ordering::Relaxed);
        let hit = d
            .cast_shapes_nonlinear(&motion, &curve, &still, target, 0.0, DT, false)
            .unwrap();
        (evals.load(Ordering::Relaxed), hit)
    };
    let (sliding, hit) = cast(-40.0, 3000.0, &ground);
    assert!(hit.is_none(), "{hit:?}");
    // One segment's cast takes hundreds of evaluations; the swept box's two ends take a few
    // support points.
    let (single, _) = cast(
        -0.3,
        36.0,
        &Segment::new(Vector::new(-0.005, 0.0), Vector::new(0.005, 0.0)),
    );
    println!("evaluations: sliding over {n} segments {sliding}, over one segment {single}");
    assert!(
        sliding < single,
        "{sliding} evaluations over {n} segments, {single} over one"
    );
}

/// A flat heightfield turned upside down (a negative vertical scale: the one heightfield with a
/// negative scale whose bounding box is not inverted, so the dispatcher's guards take it) was
/// culled wrongly: the cast against it culled its segments with parry's
/// `map_elements_in_local_aabb`, which compares the box divided by the scale with the unscaled
/// heights, and a negative scale turns that comparison around — every segment under the
/// body's swept box was skipped and a body falling onto the ground went through it (found by a
/// hostile-input hunt over heightfields of extreme and negative scales: 45 of 500 casts missed).
/// The segments are now culled by their own boxes, whatever the scale's sign: the answer is the
/// earliest hit over every segment, and the falls hit.
#[test]
fn a_cast_against_a_flat_heightfield_of_negative_vertical_scale_is_the_earliest_hit_over_its_segments() {
    let d = SmoothDispatcher::default();
    let mut rng = Rng::new(0x0F1A_7D0E);
    let (mut cases, mut hits) = (0usize, 0usize);
    for _ in 0..40 {
        let n = rng.int(1, 40);
        let height = rng.uniform(-1.0, 1.0);
        let hf = HeightField::new(vec![height; n + 1], Vector::new(20.0, -rng.log_uniform(0.1, 10.0)));
        let ground = Ground {
            name: "upside-down heightfield",
            parts: hf
                .segments()
                .map(|s| (Pose::IDENTITY, Box::new(s) as Box<dyn Shape>))
                .collect(),
            shape: Box::new(hf.clone()),
        };
        let y = hf.local_aabb().maxs.y;
        for (name, body) in bodies() {
            // A fall from 0.5 to 2 above the ground at 60 to 300 m/s: a hit within the step.
            let start = Pose::new(
                Vector::new(rng.uniform(-9.0, 9.0), y + rng.uniform(0.5, 2.0)),
                rng.angle(),
            );
            let v = Vector::new(rng.uniform(-5.0, 5.0), -rng.uniform(180.0, 300.0));
            let centre = body.mass_properties(1.0).local_com;
            let mb = NonlinearRigidMotion::new(start, centre, v, spin(&mut rng));
            let stop = rng.chance(0.3);
            let mc = NonlinearRigidMotion::identity();
            let got = d
                .cast_shapes_nonlinear(&mb, body.as_ref(), &mc, ground.shape.as_ref(), 0.0, DT, stop)
                .expect("a heightfield at rest is supported")
                .map(|h| h.time_of_impact);
            let want = brute_force(&d, &mb, body.as_ref(), &ground, Pose::IDENTITY, stop);
            assert_eq!(
                got.map(f64::to_bits),
                want.map(f64::to_bits),
                "{name} against the {}: {got:?}, every segment {want:?} ({mb:?})",
                ground.name
            );
            assert!(got.is_some(), "{name} falls through the {}", ground.name);
            cases += 1;
            hits += usize::from(got.is_some());
        }
    }
    println!("{cases} casts against upside-down heightfields, {hits} hits");
}

/// The culling of a composite's parts grew their boxes by the start-contact gap of rapier's rule
/// only, not by the level at which a part's own cast reports a hit: with a target distance
/// (`ToiOptions::target_distance`, here 0.05 to 0.5), a body passing within it of a polyline, a
/// heightfield or a compound got no hit where the part alone gave one; and a part far from its
/// composite's origin (a polyline at 10⁸ to 10¹³ m), whose casts take the tolerance of their
/// coordinates (10⁻¹⁰ of them), was culled where its cast reported a contact at the start
/// (found by a hostile-input hunt comparing the dispatcher with every part cast by itself:
/// about one cast in ten with a target distance, one in five far from the origin). The boxes
/// are now grown by that level (the target distance, twice the casts' tolerance at the scale of
/// the part's coordinates, and the start-contact gap): the answer is again the earliest hit over
/// every part, to the bit.
#[test]
fn a_cast_against_a_composite_at_rest_keeps_the_target_distance_and_the_tolerance_of_far_parts() {
    let mut rng = Rng::new(0x7A49_E7D1);
    let (mut cases, mut hits) = (0usize, 0usize);
    for round in 0..40 {
        let target = rng.log_uniform(0.05, 0.5);
        let d = SmoothDispatcher::default().with_toi_options(ToiOptions::default().with_target_distance(target));
        let plain = SmoothDispatcher::default();
        let far = if round % 2 == 0 {
            Vector::ZERO
        } else {
            rng.direction() * 10f64.powf(rng.uniform(8.0, 13.0))
        };
        let mut grounds = grounds(&mut rng);
        if far != Vector::ZERO {
            // The polyline moved far from its origin (its parts keep their coordinates).
            let points: Vec<Vector> = grounds[0]
                .parts
                .iter()
                .flat_map(|(_, s)| {
                    let s = s.as_shape::<Segment>().expect("a segment");
                    [s.a, s.b]
                })
                .map(|p| p + far)
                .collect();
            let points: Vec<Vector> = points
                .iter()
                .step_by(2)
                .copied()
                .chain(points.last().copied())
                .collect();
            grounds = vec![Ground {
                name: "far polyline",
                parts: points
                    .windows(2)
                    .map(|w| (Pose::IDENTITY, Box::new(Segment::new(w[0], w[1])) as Box<dyn Shape>))
                    .collect(),
                shape: Box::new(Polyline::new(points, None)),
            }];
        }
        for ground in &grounds {
            for (name, body) in bodies() {
                // Sliding 0.3 to 1.3 above the ground (within the target distance of its top
                // for some), or 0.35 to 0.5 above it at 10⁸ m and more, where the parts' own
                // tolerance (2·10⁻¹⁰ of their coordinates: 0.02 m to 2 km) makes most casts hits
                // at the start: the culling must keep those parts too.
                let lift = if far == Vector::ZERO {
                    rng.uniform(0.3, 1.3)
                } else {
                    rng.uniform(0.35, 0.5)
                };
                let start = Pose::new(far + Vector::new(rng.uniform(-9.0, 9.0), lift), rng.angle());
                let v = Vector::new(rng.sign() * rng.log_uniform(1.0, 300.0), 0.0);
                let centre = body.mass_properties(1.0).local_com;
                let mb = NonlinearRigidMotion::new(start, centre, v, spin(&mut rng));
                let stop = rng.chance(0.3);
                for d in [&d, &plain] {
                    let got = d
                        .cast_shapes_nonlinear(
                            &mb,
                            body.as_ref(),
                            &NonlinearRigidMotion::identity(),
                            ground.shape.as_ref(),
                            0.0,
                            DT,
                            stop,
                        )
                        .expect("a composite at rest is supported")
                        .map(|h| h.time_of_impact);
                    let want = brute_force(d, &mb, body.as_ref(), ground, Pose::IDENTITY, stop);
                    assert_eq!(
                        got.map(f64::to_bits),
                        want.map(f64::to_bits),
                        "{name} against the {} (target {}): composite {got:?}, every part {want:?} ({mb:?})",
                        ground.name,
                        d.toi_options.target_distance
                    );
                    cases += 1;
                    hits += usize::from(got.is_some());
                }
            }
        }
    }
    println!("{cases} casts with a target distance or far from the origin, {hits} hits");
}
