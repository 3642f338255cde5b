//! Coincident, concentric, touching and grazing shapes.

use super::*;

/// Signed distance by brute force over axes: max over θ of the gap along θ (exact support
/// functions), with a final golden-section refinement around the best sample.
fn gap_reference(c1: &dyn ConvexCurve, c2: &dyn ConvexCurve, pos12: &Pose) -> f64 {
    let gap = |th: f64| {
        let n = Vector::new(th.cos(), th.sin());
        let h1 = c1.support_point(n).dot(n);
        let m = pos12.rotation.inverse_transform_vector(-n);
        (*pos12 * c2.support_point(m)).dot(n) - h1
    };
    let k = 20_000;
    let step = std::f64::consts::TAU / k as f64;
    let (mut best, mut at) = (f64::NEG_INFINITY, 0.0);
    for i in 0..k {
        let th = i as f64 * step;
        let g = gap(th);
        if g > best {
            best = g;
            at = th;
        }
    }
    let (mut lo, mut hi) = (at - step, at + step);
    for _ in 0..100 {
        let (a, b) = (lo + 0.382 * (hi - lo), hi - 0.382 * (hi - lo));
        if gap(a) > gap(b) {
            hi = b
        } else {
            lo = a
        }
    }
    best.max(gap(0.5 * (lo + hi)))
}

/// Coincident and concentric shapes overlap as deeply as they can: the penetration depth is found
/// (checked against a brute-force search over axes) even when the branch and bound ends with
/// `OutOfIterations` (its curvature bound is loose for overlaps as deep as the shapes' radii).
#[test]
fn coincident_and_concentric_shapes_get_their_penetration_depth() {
    let shapes: Vec<Box<dyn ConvexCurve>> = vec![
        Box::new(Ellipse::new(1.0, 0.4)),
        Box::new(Ellipse::new(1.0, 1e-3)),
        Box::new(Ellipse::new(0.7, 0.7)),
        Box::new(BallCurve { radius: 0.5 }),
        Box::new(RoundedPolygon::regular(5, 0.8, 0.1)),
        Box::new(RoundedPolygon::regular(4, 1.0, 0.0)),
        Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8)),
    ];
    let (mut worst, mut cases, mut capped) = (0.0f64, 0, 0);
    for (i, a) in shapes.iter().enumerate() {
        for b in shapes.iter().filter(|b| b.is_strictly_convex()) {
            for angle in [0.0, 0.3, 1.2, 2.9] {
                for offset in [0.0, 1e-13, 1e-9] {
                    let pos12 = Pose::new(Vector::new(offset, 0.0), angle);
                    let d = stationary_distance(&**a, &**b, &pos12, &DistanceOptions::default()).unwrap();
                    let reference = gap_reference(&**a, &**b, &pos12);
                    let size = a.bounding_radius().max(b.bounding_radius());
                    let err = (d.distance - reference).abs() / size;
                    assert!(d.distance <= 0.0 && d.distance.is_finite());
                    assert!(
                        err <= 1e-9,
                        "shape {i} angle {angle} offset {offset}: {} vs {reference}",
                        d.distance
                    );
                    worst = worst.max(err);
                    cases += 1;
                    capped += (d.status == DistanceStatus::OutOfIterations) as usize;
                }
            }
        }
    }
    println!(
        "coincident/concentric: {cases} pairs, {capped} ended OutOfIterations, worst |depth − reference|/size {worst:.1e}"
    );
}

/// Shapes touching exactly at t0 (two discs, and an ellipse's circle against a disc, at a centre
/// distance of exactly r1 + r2 along an axis).
#[test]
fn shapes_touching_exactly_at_t0() {
    let mut counts: BTreeMap<String, usize> = BTreeMap::new();
    for s in [1e-6, 1.0, 1e6] {
        let (r1, r2) = (0.5 * s, 0.25 * s);
        let shapes: [Box<dyn ConvexCurve>; 2] = [Box::new(BallCurve { radius: r1 }), Box::new(Ellipse::new(r1, r1))];
        for a in &shapes {
            let b = BallCurve { radius: r2 };
            let pos12 = Pose::new(Vector::new(r1 + r2, 0.0), 0.7);
            let d = stationary_distance(&**a, &b, &pos12, &DistanceOptions::default()).unwrap();
            assert!(d.distance.abs() <= 1e-15 * s, "s {s}: {}", d.distance);
            // Velocity of disc 2: approaching, separating, sliding, and with spins.
            for (v, w) in [
                (Vector::new(-1.0, 0.3), 0.0),
                (Vector::new(1.0, 0.3), 0.0),
                (Vector::new(0.0, 1.0), 0.0),
                (Vector::new(0.0, 0.0), 5.0),
                (Vector::new(-1.0, 0.0), -5.0),
            ] {
                for stop in [true, false] {
                    let m1 = NonlinearRigidMotion::new(Pose::new(Vector::ZERO, 0.0), Vector::ZERO, Vector::ZERO, w);
                    let m2 = NonlinearRigidMotion::new(pos12, Vector::ZERO, v * s, 0.0);
                    let o = ToiOptions::default().with_stop_at_penetration(stop);
                    let r = time_of_impact(&**a, &m1, &b, &m2, 0.0, 1.0, &o).unwrap();
                    if stop || v.x < 0.0 {
                        // Stopping at contacts, or approaching: the start.
                        assert_eq!(r.status, ToiStatus::PenetratingAtStart, "s {s} v {v} stop {stop}");
                        assert_eq!(r.time, 0.0);
                    } else if v.x > 0.0 {
                        // Separating: the contact is ignored; discs moving apart never meet again.
                        assert_eq!(r.status, ToiStatus::NoHit, "s {s} v {v}");
                    } else {
                        // D' = 0 at the start (sliding, spinning): rounding decides whether the
                        // contact is approaching (the start) or separating (followed until the
                        // discs part, or a Hit still in contact where the approach resumes).
                        match r.status {
                            ToiStatus::PenetratingAtStart => assert_eq!(r.time, 0.0),
                            ToiStatus::Hit => assert!(r.distance <= 1e-10 * r1, "{r:?}"),
                            ToiStatus::NoHit => {}
                            other => panic!("s {s} v {v}: {other:?}"),
                        }
                    }
                    *counts.entry(format!("{:?}", r.status)).or_default() += 1;
                }
            }
        }
    }
    println!("touching at t0: {counts:?}");
}

/// A disc slides past another (or past an ellipse's circle) along the common tangent: the
/// smallest distance over the window is exactly `gap`, reached at tc inside the window.
#[test]
fn grazing_passes_within_1e_12() {
    let mut rows = Vec::new();
    for s in [1e-6f64, 1.0, 1e6] {
        let (r1, r2) = (0.5 * s, 0.5 * s);
        let size = r1.max(r2);
        for rel in [-1e-9, -1e-11, -1e-12, 0.0, 1e-12, 1e-11, 1e-9, 1e-6] {
            let gap = rel * size;
            let mut hits = 0;
            for (k, dir) in [0.3f64, 1.9, -2.4].into_iter().enumerate() {
                let n = Vector::new(dir.cos(), dir.sin());
                let tan = Vector::new(-n.y, n.x);
                let (t0, t1) = (-1.0 + k as f64, 0.5 + k as f64);
                let tc = t0 + 0.6 * (t1 - t0);
                let speed = 2.0 * s;
                let dist = r1 + r2 + gap;
                // Disc 2's centre: n·dist + tan·speed·(t − tc).
                let m2 = NonlinearRigidMotion::new(
                    Pose::new(n * dist - tan * (speed * tc), 0.0),
                    Vector::ZERO,
                    tan * speed,
                    0.0,
                );
                let shapes: [Box<dyn ConvexCurve>; 2] =
                    [Box::new(BallCurve { radius: r1 }), Box::new(Ellipse::new(r1, r1))];
                for a in &shapes {
                    let m1 = still(0.0, 0.0, 0.4);
                    let r = time_of_impact(
                        &**a,
                        &m1,
                        &BallCurve { radius: r2 },
                        &m2,
                        t0,
                        t1,
                        &ToiOptions::default(),
                    )
                    .unwrap();
                    // The exact distance at t: |centre(t)| − r1 − r2.
                    let exact = |t: f64| m2.position_at_time(t).translation.length() - r1 - r2;
                    match r.status {
                        ToiStatus::Hit => {
                            hits += 1;
                            let d = exact(r.time);
                            assert!(
                                d >= -1e-12 * size && d <= 1e-10 * size + 1e-12 * size,
                                "s {s} gap {rel}: hit at {} with distance {d}",
                                r.time
                            );
                            assert!(
                                rel <= 1e-10,
                                "s {s} gap {rel}: a hit though the gap exceeds the tolerance"
                            );
                        }
                        ToiStatus::NoHit => {
                            assert!(rel >= -1e-12, "s {s} gap {rel}: the graze below the target was missed");
                        }
                        other => panic!("s {s} gap {rel}: {other:?}"),
                    }
                }
            }
            rows.push(format!("s {s:e} gap {rel:+e}·size: {hits}/6 hits"));
        }
    }
    println!("grazing passes:\n  {}", rows.join("\n  "));
}
