//! Poses far from the origin, speeds near zero or near the largest float, windows ending far
//! from their start: every answer finite, inside its window, and as on an ordinary scale.

use super::*;

/// Item 4: shapes with flat pieces (a `CapsuleEllipse`, a user curve with a flat piece) 1e155
/// or more apart were `intersecting`, at distance 0, `PenetratingAtStart`: the axis the exact
/// distance starts from, the offset normalised, was 0 when its squared length overflowed. Now
/// a unit axis from any offset: the answer is the distance (or, where it overflows, the
/// documented `Unsupported` / `Degenerate`), never a contact.
#[test]
fn shapes_1e155_and_more_apart_are_never_touching() {
    let ce = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let flat_curve = CustomCurve::new(CapsuleEllipse::new(0.3, 0.6, 0.5));
    let others: Vec<SharedShape> = vec![
        SharedShape::new(RoundedPolygon::regular(6, 1.0, 0.1)),
        SharedShape::new(Cuboid::new(Vector::new(0.5, 0.2))),
        SharedShape::new(Capsule::new_y(0.5, 0.2)),
        SharedShape::new(Triangle::new(Vector::ZERO, Vector::X, Vector::Y)),
        SharedShape::new(CapsuleEllipse::new(0.2, 0.4, 0.3)),
    ];
    let d = SmoothDispatcher::default();
    let mut answered = 0;
    for g1 in [SharedShape::new(ce), SharedShape::new(flat_curve)] {
        for g2 in &others {
            for x in [1e150, 1e155, 1e200, 1e300] {
                let pose = Pose::new(Vector::new(x, -0.3 * x), 0.3);
                if let Ok(i) = d.intersection_test(&pose, &*g1, &**g2) {
                    assert!(!i.intersecting, "{x}: intersecting");
                    answered += 1;
                }
                if let Ok(r) = d.distance(&pose, &*g1, &**g2) {
                    assert!(r.distance > 0.9 * x, "{x}: distance {}", r.distance);
                }
                assert!(
                    !matches!(d.contact(&pose, &*g1, &**g2, 0.1), Ok(Some(_))),
                    "{x}: contact"
                );
                assert!(
                    !matches!(
                        d.closest_points(&pose, &*g1, &**g2, 0.1),
                        Ok(ClosestPoints::Intersecting | ClosestPoints::WithinMargin(..))
                    ),
                    "{x}: closest points"
                );
                let m1 = NonlinearRigidMotion::identity();
                let m2 = NonlinearRigidMotion::constant_position(pose);
                let r = shape_time_of_impact(&*g1, &m1, &**g2, &m2, 0.0, 1.0, &ToiOptions::default());
                assert!(
                    !matches!(r, Ok(ref r) if r.status != ToiStatus::NoHit),
                    "{x}: time of impact {r:?}"
                );
            }
        }
    }
    // Up to 1e300 the distance itself is answered (no square of the offset is taken).
    assert!(answered >= 30, "{answered}");
}

/// Item 5: the half-space cast took its distances between world points: the plane 1e4 from the
/// origin put the hit 2.4e-12·s inside it, 1e8 9.9e-9·s, 1e15 0.17·s (t = 1.75 for 1.8). Now in
/// the half-space's frame from the pair's relative motion: exact at every offset, also through
/// the dispatcher.
#[test]
fn halfspace_cast_far_from_the_origin_is_as_exact_as_at_it() {
    let e = Ellipse::new(0.5, 0.2);
    let hs = HalfSpace::new(Vector::Y);
    let d = SmoothDispatcher::default();
    for off in [0.0, 1e4, 1e8, 1e12, 1e15] {
        // The ellipse's centre 2 above the plane, falling at 1 m/s: its bottom (0.2 below the
        // centre) reaches the plane at t = 1.8. Both positions are exact in f64.
        let mc = NonlinearRigidMotion::new(
            Pose::translation(off, off + 2.0),
            Vector::ZERO,
            Vector::new(0.0, -1.0),
            0.0,
        );
        let mh = NonlinearRigidMotion::constant_position(Pose::translation(off, off));
        let r = time_of_impact_halfspace(&e, &mc, &hs, &mh, 0.0, 5.0, &ToiOptions::default()).expect("answered");
        assert_eq!(r.status, ToiStatus::Hit);
        assert!((r.time - 1.8).abs() <= 1e-12, "offset {off}: t = {}", r.time);
        let hit = d
            .cast_shapes_nonlinear(&mc, &e, &mh, &hs, 0.0, 5.0, true)
            .expect("answered")
            .expect("a hit");
        assert!(
            (hit.time_of_impact - 1.8).abs() <= 1e-12,
            "dispatcher, offset {off}: t = {}",
            hit.time_of_impact
        );
        // A spinning one: the same answer as at the origin.
        let spin = |o: f64| {
            let mc = NonlinearRigidMotion::new(
                Pose::new(Vector::new(o, o + 2.0), 0.3),
                Vector::ZERO,
                Vector::new(0.3, -1.0),
                7.0,
            );
            let mh = NonlinearRigidMotion::constant_position(Pose::translation(o, o));
            time_of_impact_halfspace(&e, &mc, &hs, &mh, 0.0, 5.0, &ToiOptions::default()).expect("answered")
        };
        let (far, near) = (spin(off), spin(0.0));
        assert_eq!(far.status, near.status);
        assert!(
            (far.time - near.time).abs() <= 1e-12,
            "offset {off}: {} vs {}",
            far.time,
            near.time
        );
    }
}

/// Item 6: the bounding-circle test took the time of closest approach −Δ·v/|v|², and |v|²
/// underflowed to 0 below about 1e-162 m/s (overflowed above 1e154): an approach at 1e-200 m/s
/// over a window of 1e201 s answered `NoHit` at t = 0 (contact at 1.2e200 s) in the φ–t
/// tracker, the gap tracker and the dispatcher. With v scaled by its largest component when |v|²
/// leaves the normal range, all three find the hit at the speed's own scale, at 1e-300 too.
#[test]
fn approach_at_1e_minus_200_meters_per_second_is_a_hit() {
    let (a, b) = (Ellipse::new(0.5, 0.2), Ellipse::new(0.3, 0.3));
    let (p, c) = (RoundedPolygon::regular(5, 0.5, 0.0), Cuboid::new(Vector::new(0.3, 0.3)));
    let d = SmoothDispatcher::default();
    for v in [1.0, 1e-160, 1e-200, 1e-300] {
        let m1 = NonlinearRigidMotion::new(Pose::translation(-2.0, 0.0), Vector::ZERO, Vector::new(v, 0.0), 0.0);
        let m2 = NonlinearRigidMotion::identity();
        let t1 = 10.0 / v;
        // The ellipse's +x tip reaches the disc at x = −0.3: the centre travels 1.2.
        let r = time_of_impact(&a, &m1, &b, &m2, 0.0, t1, &ToiOptions::default()).expect("answered");
        assert_eq!(r.status, ToiStatus::Hit, "{v}");
        assert!((r.time * v - 1.2).abs() < 1e-9, "φ–t tracker at {v}: {}", r.time * v);
        // The pentagon's vertex at +x (circumradius 0.5) reaches the box at x = −0.3: 1.2 too.
        let r = shape_time_of_impact(&p, &m1, &c, &m2, 0.0, t1, &ToiOptions::default()).expect("answered");
        assert_eq!(r.status, ToiStatus::Hit, "{v}");
        assert!((r.time * v - 1.2).abs() < 1e-9, "gap tracker at {v}: {}", r.time * v);
        let hit = d
            .cast_shapes_nonlinear(&m1, &a, &m2, &b, 0.0, t1, true)
            .expect("answered")
            .expect("a hit");
        assert!((hit.time_of_impact * v - 1.2).abs() < 1e-9, "dispatcher at {v}");
    }
}

/// Found by the fuzz with another seed (`FUZZ_SEED=777`, case 6968): a window from −1e300 s to
/// −1 s, two bodies 1e-4 in size meeting near its end. The tracker halved its way from the start
/// to t ≈ −1.1e287 and then recovered with the global distance at t + h, which rounded to 0 (the
/// window's end, −1, is lost against 1e287): a hit at 0, after the window. Every tracker's next
/// time is now kept within the window; the hit is at its end, where the pair touches.
#[test]
fn a_window_ending_far_from_its_start_keeps_every_answer_inside_it() {
    let p = RoundedPolygon::try_regular(10, 6.583887209729579e-5, 2.5898850691172458e-5).expect("valid");
    let b = Ellipse::new(0.00013066506841059132, 0.00013066506841059132);
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::new(-0.0, -9.960467120501367e-6),
        Vector::new(-7.045141471315296e-5, 7.145894484436469e-5),
        5e-324,
    );
    let start2 = Pose::from_parts(
        Vector::new(1.3427850226082439e-5, 5.86613868106411e-5),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(0.9505975648210587, 0.31042594890935427),
    );
    let m2 = NonlinearRigidMotion::new(
        start2,
        Vector::new(-5.6161949771065445e-6, 1e20),
        Vector::new(7.156175118024756e-5, 2.5148291494086983e-5),
        0.0,
    );
    let (t0, t1) = (-1e300, -1.0);
    let o = ToiOptions::default().with_stop_at_penetration(true);
    let r = within("time_of_impact", move || time_of_impact(&p, &m1, &b, &m2, t0, t1, &o)).expect("answered");
    assert!(
        (t0..=t1).contains(&r.time),
        "{:?} at {} outside [{t0}, {t1}]",
        r.status,
        r.time
    );
    assert_eq!(r.status, ToiStatus::Hit);
}

/// Found by the fuzz with another seed (`FUZZ_SEED=2004`, case 122492), in rapier's cast of a
/// polygon that does not turn (in closed form, as a disc's): a window from −1.8e308 s to
/// −1.38 s, where the start plus the entry's offset rounds past the window's end. The closed
/// forms' times are kept within the window.
#[test]
fn a_closed_form_cast_over_a_window_ending_far_from_its_start_stays_inside_it() {
    let p = RoundedPolygon::try_regular(10, 2.509739471376431e-6, 3.0752608652163396e-7).expect("valid");
    let q = RoundedPolygon::try_new(
        &[
            Vector::new(-6.07458065535825e-6, -2.528236234554779e-6),
            Vector::new(6.562311006503291e-6, -1.668740082707563e-6),
            Vector::new(5.7054280188391075e-6, 2.989501685379284e-6),
            Vector::new(5.638999177641803e-6, 3.062381809026463e-6),
            Vector::new(5.0240907127375235e-6, 3.63534475810723e-6),
            Vector::new(-6.9112637153172104e-6, 1.814885990066977e-7),
        ],
        1.9223336181371837e-6,
    )
    .expect("valid");
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::new(-5.581405653857503e-7, 3.133657443641483e-7),
        Vector::new(-5.3416986518452875e-6, -9.591119592255376e-6),
        0.0,
    );
    let start2 = Pose::from_parts(
        Vector::new(6.3298184099516535e-6, 9.614719329102188e-6),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.9952068144095766, 0.09779262013435641),
    );
    let m2 = NonlinearRigidMotion::new(
        start2,
        Vector::ZERO,
        Vector::new(-4.097794192889215e-6, 4.522391117438657e-6),
        0.0,
    );
    let (t0, t1) = (-f64::MAX, -1.379789359758342);
    for (g1, g2, a, b) in [(&p, &q, &m1, &m2), (&q, &p, &m2, &m1)] {
        let (g1, g2, a, b) = (g1.clone(), g2.clone(), *a, *b);
        let hit = within("cast_shapes_nonlinear", move || {
            SmoothDispatcher::default().cast_shapes_nonlinear(&a, &g1, &b, &g2, t0, t1, true)
        })
        .expect("answered");
        if let Some(h) = hit {
            assert!(
                (t0..=t1).contains(&h.time_of_impact),
                "a hit at {} outside [{t0}, {t1}]",
                h.time_of_impact
            );
        }
    }
}

/// Found by the adversarial fuzz with seed 20261127 (case 75845): under rapier's policies a pair
/// in contact at the start is answered at a nudge of the window past its start, with the pair's
/// contact there for witnesses; a spin of 1e160 rad/s over a window of 1e300 s reaches that
/// time only by overflowing, and the hit came out with zero witnesses and a NaN normal. Every
/// cast of a pair touching at the start, every pair kind and policy, spins and windows whose
/// product overflows: `Err(Unsupported)` or a hit whose every number is finite.
#[test]
fn start_contact_at_a_time_the_motions_overflow_to_is_unsupported_never_nan() {
    use smooth_ccd2d::CastPolicy;
    let shapes: Vec<SharedShape> = vec![
        SharedShape::new(RoundedPolygon::regular(12, 0.0052, 0.0013)),
        SharedShape::new(RoundedPolygon::regular(4, 0.006, 0.0)),
        SharedShape::new(Ellipse::new(0.0011, 0.0118)),
        SharedShape::new(Ellipse::new(0.005, 0.005)),
        SharedShape::new(CapsuleEllipse::new(0.003, 0.004, 0.006)),
        SharedShape::new(Ball::new(0.005)),
        SharedShape::new(Cuboid::new(Vector::new(0.004, 0.006))),
        SharedShape::new(parry2d_f64::shape::Segment::new(
            Vector::new(-0.01, 0.0),
            Vector::new(0.01, 0.0),
        )),
        SharedShape::new(Capsule::new_y(0.003, 0.002)),
    ];
    let pose2 = Pose::from_parts(
        Vector::new(-0.0012, -0.0021),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.003136167043825366, -0.9999950822160443),
    );
    let (mut casts, mut refused) = (0, 0);
    for policy in [CastPolicy::Rapier, CastPolicy::RapierConstantSpin, CastPolicy::Plain] {
        let d = SmoothDispatcher::default().with_cast_policy(policy);
        for g1 in &shapes {
            for g2 in &shapes {
                for (w1, w2, t1) in [(1e160, -19.9, 1e300), (0.0, 1e160, 1e200), (1e160, 0.0, 1e200)] {
                    let m1 = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::new(-0.011, 0.005), w1);
                    let m2 = NonlinearRigidMotion::new(pose2, Vector::ZERO, Vector::new(0.0034, 0.0007), w2);
                    for stop in [false, true] {
                        let r = d.cast_shapes_nonlinear(&m1, &**g1, &m2, &**g2, 0.0, t1, stop);
                        casts += 1;
                        match r {
                            Err(_) => refused += 1,
                            Ok(None) => {}
                            Ok(Some(h)) => assert!(
                                h.time_of_impact.is_finite()
                                    && h.witness1.is_finite()
                                    && h.witness2.is_finite()
                                    && h.normal1.is_finite()
                                    && h.normal2.is_finite(),
                                "{policy:?} {:?} against {:?}, spins {w1:e} and {w2:e} over [0, {t1:e}]: {h:?}",
                                g1.shape_type(),
                                g2.shape_type(),
                            ),
                        }
                    }
                }
            }
        }
    }
    println!("casts at overflowing times: {casts}, Err(Unsupported) {refused}, the rest finite");
    // The policies' start-contact answers are the ones refused; the pairs are in contact.
    assert!(refused > casts / 4, "{refused} of {casts} refused");
}

/// The promise the hostile fuzz with seed 99 (case 531) found stated too widely: a cast on a
/// time scale of 2^k answers as on the ordinary scale, with its time scaled, unless the
/// answer's own rate of distance is beyond f64's range — a spinning half-space's turn times the
/// lever arm to the far contact, at 2^1000 — where the answer is `Degenerate`
/// (`QueryError::Degenerate`; the fuzz had expected the ordinary answer). That case's
/// capsule-ellipse (17 596, 3 859, 9 693) and half-space (moving at 5e5 m/s and spinning at
/// 4.8 rad/s, the contact 5e6 m from its centre), its time scaled by 2^k for k = −1000 … 1000
/// (every 50, and every 1 from −1000 to −990, where the rates reach 1e307).
#[test]
fn halfspace_cast_answers_alike_on_every_time_scale() {
    let shape = CapsuleEllipse::new(17596.32492950854, 3858.834104952514, 9692.58743683483);
    let plane = HalfSpace::new(Vector::new(
        (-1.5003572930047504f64).cos(),
        (-1.5003572930047504f64).sin(),
    ));
    let hs_pose = Pose::from_parts(
        Vector::new(-84202.76467746461, -127987.46116208693),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(0.04961528762791126, 0.9987684032014628),
    );
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(1346403.6867640833, -461346.6492651799),
        55.19429736439399,
    );
    let m2 = NonlinearRigidMotion::new(
        hs_pose,
        Vector::ZERO,
        Vector::new(-185546.482384213, 493626.5746941382),
        -4.788139072837382,
    );
    let (mut checked, mut unrepresentable) = (0, 0);
    for (t0, t1, stop) in [
        (2.9579598316465, 3.0419384651048547, true),
        (2.0, 3.2, false),
        (0.0, 0.5, false),
    ] {
        let o = ToiOptions::default().with_stop_at_penetration(stop);
        let base = time_of_impact_halfspace(&shape, &m1, &plane, &m2, t0, t1, &o).unwrap();
        for k in (-20..=20).map(|i| 50 * i).chain(-1000..-990) {
            let s = 2f64.powi(k);
            let fast = |m: &NonlinearRigidMotion| {
                NonlinearRigidMotion::new(m.start, m.local_center, m.linvel / s, m.angvel / s)
            };
            let r = time_of_impact_halfspace(&shape, &fast(&m1), &plane, &fast(&m2), t0 * s, t1 * s, &o);
            checked += 1;
            match r {
                Err(e) => {
                    assert!(
                        e == smooth_ccd2d::QueryError::Degenerate && !(base.distance_rate / s).is_finite(),
                        "2^{k}: {e:?}, unscaled {base:?}"
                    );
                    unrepresentable += 1;
                }
                Ok(r) => {
                    assert_eq!(r.status, base.status, "2^{k}");
                    assert!(
                        (r.time / s - base.time).abs() <= 1e-12 * (t1 - t0),
                        "2^{k}: {} vs {}",
                        r.time / s,
                        base.time
                    );
                }
            }
        }
    }
    println!("half-space casts on 51 time scales: {checked}, {unrepresentable} Degenerate (a rate of distance beyond f64), the rest as on the ordinary scale");
}

/// Fuzz seed 5032, case 79067 (`crates/dev/tests/adversarial.rs`): a thin ellipse and a
/// compound of one ellipse, 0.1 m apart and moving side by side at 1e20 m/s, cast over half a
/// second. The pair goes to parry's composite cast, which saw positions of 1e19 m — rounded by
/// 1e3 m, ten thousand times the bodies — and its advancement, moved by that rounding at every
/// step, ran for ever (more than 20 s); with the compound first, on the time scale the
/// dispatcher takes for rates beyond 2^64 (a window of 5.7e20 s), parry's absolute time
/// tolerances did the same. Parry's casts now get the motions seen from the body that does not
/// turn (`input_guard::resolved_motions`) and the caller's time scale: the answer at once, the
/// same as for the same relative motion near the origin.
#[test]
fn a_composite_cast_of_bodies_side_by_side_at_1e20_m_per_s_answers_at_once() {
    // The pair's casts in both orders (the compound first: a window rescaled for the rates of
    // 1e20 m/s, which parry's composite helper must not get), both motions shifted by −shift and
    // moving by `common` besides their own.
    fn cast(shift: Vector, common: Vector) -> [Result<Option<ShapeCastHit>, Unsupported>; 2] {
        let ellipse = Ellipse::new(0.00043654616129277564, 0.06672093399598593);
        let part = Pose::new(
            Vector::new(0.033360466997992964, 0.0),
            (-0.9165356509417905f64).atan2(0.39995299792939215),
        );
        let compound = Compound::new(vec![(
            part,
            SharedShape::new(Ellipse::new(0.04003256039759156, 0.02001628019879578)),
        )]);
        let turned = (0.9869190977011687f64).atan2(0.1612162975406362);
        let m1 = NonlinearRigidMotion::new(
            Pose::translation(-shift.x, -shift.y),
            Vector::new(-0.009055778579886117, -0.008097205025047445),
            common + Vector::new(0.0, 0.5609752929646611),
            0.0,
        );
        let m2 = NonlinearRigidMotion::new(
            Pose::new(Vector::new(0.01346469952869244, -0.10048141844158512) - shift, turned),
            Vector::ZERO,
            common + Vector::new(0.0, 0.3623689006538127),
            -0.0,
        );
        let d = SmoothDispatcher::default();
        [
            d.cast_shapes_nonlinear(&m1, &ellipse, &m2, &compound, 0.0, 0.4831652517656168, false),
            d.cast_shapes_nonlinear(&m1, &compound, &m2, &ellipse, 0.0, 0.4831652517656168, false),
        ]
    }
    // On a thread of its own: a cast that runs for ever fails the test instead of stalling it.
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(cast(Vector::ZERO, Vector::new(1e20, 0.0)));
    });
    let limit = reliability::CALL_LIMIT / 4;
    let fast = rx
        .recv_timeout(limit)
        .unwrap_or_else(|_| panic!("the casts still run after {limit:?}"));
    // The same relative motion near the origin (the compound at rest there): overlapping at the
    // start and parting, no hit with `stop_at_penetration = false`.
    let slow = cast(
        Vector::new(0.01346469952869244, -0.10048141844158512),
        Vector::new(0.0, -0.3623689006538127),
    );
    for hit in fast.iter().chain(&slow) {
        assert_eq!(hit.as_ref().map(|h| h.is_none()), Ok(true), "{fast:?} {slow:?}");
    }
}

/// Adversarial fuzz seed 5042, case 29513 (`wild`): a parry `Ball` of radius 1e160 against a
/// rounded hexagon at a pose whose rotation is not unit ((1e20, −0.36)). The pair's manifold
/// came from the stationary distance, and its new core contacts (a user's curve's, a polygon's
/// the exact contact query does not read) put a point at (−∞, −∞) in body 2's frame; such a
/// point is now left out, and every query of the case keeps its promises.
#[test]
fn a_core_contact_that_leaves_f64_in_the_other_bodys_frame_is_left_out() {
    let case = reliability::generate(5042, 29513);
    let out = within("seed 5042, case 29513", move || reliability::run_case(&case));
    assert!(out.violations.is_empty(), "{:?}", out.violations);
}

#[test]
fn halfspace_cast_at_speeds_near_the_largest_float_answers_as_on_an_ordinary_time_scale() {
    let shape = CapsuleEllipse::new(1153.3140806495276, 247.99646258840284, 1625.8808178461309);
    let plane = HalfSpace::new(Vector::new(2.50617742176697f64.cos(), 2.50617742176697f64.sin()));
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::new(-532.278763160718, 675.8979939503903),
        Vector::new(8.278734823079186e306, -2.2096967042384525e304),
        -1.8227849416608437e302,
    );
    let m2 = NonlinearRigidMotion::new(
        Pose::from_parts(
            Vector::new(159.61864580987213, -1662.173976309729),
            parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.8827046285351703, 0.46992822724602007),
        ),
        Vector::ZERO,
        Vector::new(4.122629139791279e306, 3.2764118478829426e306),
        -6.0386591952442085e302,
    );
    let (t0, t1) = (3.417310090086945e-301, 3.4256241776342636e-301);
    let o = ToiOptions::default().with_stop_at_penetration(true);
    let fast = time_of_impact_halfspace(&shape, &m1, &plane, &m2, t0, t1, &o).unwrap();
    let s = 2f64.powi(-1000);
    let slow =
        |m: &NonlinearRigidMotion| NonlinearRigidMotion::new(m.start, m.local_center, m.linvel * s, m.angvel * s);
    let base = time_of_impact_halfspace(&shape, &slow(&m1), &plane, &slow(&m2), t0 / s, t1 / s, &o).unwrap();
    assert_eq!(fast.status, base.status);
    assert_eq!(fast.status, smooth_ccd2d::ToiStatus::NoHit);
    assert!((fast.time / t1 - 1.0).abs() <= 1e-12, "{} vs {}", fast.time, t1);
}
