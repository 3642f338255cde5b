//! proptest: the fuzz's checks over strategies of random and adversarial numbers.

use super::*;

const PROP_CASES: u32 = 300;
static PROP_WILD: AtomicUsize = AtomicUsize::new(0);
static PROP_VALID: AtomicUsize = AtomicUsize::new(0);

/// A number in `lo..hi`, or (one time in five) one of [`WILD`].
fn num(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    prop_oneof![4 => lo..hi, 1 => prop::sample::select(WILD.to_vec())]
}

fn vec2(lo: f64, hi: f64) -> impl Strategy<Value = Vector> {
    (num(lo, hi), num(lo, hi)).prop_map(|(x, y)| Vector::new(x, y))
}

fn pose_s() -> impl Strategy<Value = Pose> {
    (vec2(-3.0, 3.0), num(-4.0, 4.0)).prop_map(|(t, a)| Pose::new(t, a))
}

fn motion_s() -> impl Strategy<Value = NonlinearRigidMotion> {
    (pose_s(), vec2(-0.3, 0.3), vec2(-5.0, 5.0), num(-60.0, 60.0))
        .prop_map(|(p, c, v, w)| NonlinearRigidMotion::new(p, c, v, w))
}

/// One of the crate's shapes (or a ball) with numbers that may be wild.
fn spec_s() -> impl Strategy<Value = ShapeSpec> {
    prop_oneof![
        (num(0.05, 1.5), num(1e-6, 1.5)).prop_map(|(a, b)| ShapeSpec::Ellipse(a, b)),
        (0usize..10, num(0.1, 1.5), num(0.0, 0.4)).prop_map(|(n, c, r)| ShapeSpec::Regular(n, c, r)),
        (num(0.05, 0.8), num(0.05, 0.8), num(0.05, 0.8)).prop_map(|(a, b, c)| ShapeSpec::CapsuleEllipse(a, b, c)),
        num(0.05, 1.0).prop_map(ShapeSpec::Ball),
        (num(0.05, 1.0), num(0.05, 1.0)).prop_map(|(a, b)| ShapeSpec::Custom(Box::new(ShapeSpec::Ellipse(a, b)))),
        (num(0.05, 1.0), num(0.05, 1.0)).prop_map(|(a, b)| ShapeSpec::Cuboid(a, b)),
        num(-4.0, 4.0).prop_map(ShapeSpec::HalfSpace),
    ]
}

/// A case with every number drawn from [`num`]: only the no-panic, no-NaN and documented-status
/// checks apply (`supported = false`).
pub(crate) fn wild_case() -> impl Strategy<Value = Case> {
    (
        (spec_s(), spec_s(), pose_s(), motion_s(), motion_s()),
        (
            num(-2.0, 2.0),
            num(-2.0, 3.0),
            num(0.0, 0.1),
            any::<bool>(),
            num(0.0, 0.5),
            vec2(-5.0, 5.0),
        ),
        (
            vec2(-3.0, 3.0),
            vec2(-1.0, 1.0),
            num(0.0, 10.0),
            any::<bool>(),
            vec2(-3.0, 3.0),
            vec2(-1.0, 1.0),
        ),
        (num(1e-3, 1e3), vec2(0.1, 10.0)),
    )
        .prop_map(
            |(
                (s1, s2, pos12, m1, m2),
                (t0, t1, target, stop, prediction, local_vel12),
                (ro, rd, max_toi, solid, point, dir),
                (density, rescale),
            )| Case {
                seed: 0,
                index: 0,
                class: "proptest-wild",
                supported: false,
                scale: 1.0,
                s1,
                s2,
                pos12,
                m1,
                m2,
                t0,
                t1,
                target,
                stop,
                prediction,
                local_vel12,
                ray: parry2d_f64::query::Ray::new(ro, rd),
                max_toi,
                solid,
                point,
                dir,
                density,
                rescale,
                min_gap: None,
            },
        )
}

/// A valid case at a random scale 1e-6..1e6 and axis ratio to 1:1e6: the accuracy checks apply
/// too (`supported = true`).
fn valid_case() -> impl Strategy<Value = Case> {
    (
        (
            -6.0f64..6.0,
            0usize..3,
            -6.0f64..0.0,
            3usize..9,
            0.0f64..0.3,
            0.3f64..3.0,
        ),
        (
            -3.2f64..3.2,
            0.0f64..1.6,
            -3.2f64..3.2,
            -60.0f64..60.0,
            -10.0f64..10.0,
            0.0f64..6.0,
        ),
        (-3.2f64..3.2, any::<bool>(), 0u8..3, -3.0f64..3.0, 1e-3f64..10.0),
    )
        .prop_map(
            |((log_s, kind, log_ratio, sides, r, s2_rel), (dir, dist, a1, w1, w2, speed), (vdir, stop, win, t0, w))| {
                let s = 10f64.powf(log_s);
                let ratio = 10f64.powf(log_ratio);
                let s1 = match kind {
                    0 => ShapeSpec::Ellipse(s, s * ratio),
                    1 => ShapeSpec::Regular(sides, s, s * r),
                    _ => ShapeSpec::CapsuleEllipse(s * 0.4, s * 0.5, s * 0.6),
                };
                let s2 = ShapeSpec::Ellipse(s * s2_rel, s * s2_rel * ratio.sqrt());
                let reach = 3.0 * s * s2_rel.max(1.0);
                let pos12 = Pose::new(Vector::new(dir.cos(), dir.sin()) * (dist * reach), a1);
                let (t0, t1) = match win {
                    0 => (t0, t0),
                    1 => (t0, t0 - w),
                    _ => (t0, t0 + w),
                };
                let v = Vector::new(vdir.cos(), vdir.sin()) * (speed * s / w);
                let m1 = NonlinearRigidMotion::new(Pose::new(Vector::ZERO, 0.0), Vector::ZERO, v, w1);
                let m2 = NonlinearRigidMotion::new(pos12, Vector::ZERO, Vector::ZERO, w2);
                Case {
                    seed: 0,
                    index: 0,
                    class: "proptest-valid",
                    supported: true,
                    scale: s,
                    s1,
                    s2,
                    pos12,
                    m1,
                    m2,
                    t0,
                    t1,
                    target: 0.0,
                    stop,
                    prediction: 0.1 * s,
                    local_vel12: -v,
                    ray: parry2d_f64::query::Ray::new(Vector::new(-3.0 * s, 0.1 * s), Vector::X),
                    max_toi: 10.0,
                    solid: stop,
                    point: Vector::new(0.3 * s, -2.0 * s),
                    dir: Vector::new(dir.sin(), dir.cos()),
                    density: 1.0,
                    rescale: Vector::new(2.0, 0.5),
                    min_gap: None,
                }
            },
        )
}

proptest! {
    // A fixed seed: the same cases on every run (deterministic, as the fuzz batch).
    #![proptest_config(ProptestConfig {
        cases: PROP_CASES,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x0007_0007),
        ..ProptestConfig::default()
    })]

    /// Every query on every kind of bad number: no panic, no NaN, the documented error or status.
    #[test]
    fn prop_every_query_on_adversarial_numbers_keeps_its_promises(case in wild_case()) {
        let out = guarded(&case);
        prop_assert!(out.violations.is_empty(), "{}\n{}", describe(&case), out.violations.join("\n"));
        PROP_WILD.fetch_add(1, Ordering::Relaxed);
    }

    /// Valid inputs at scales 1e-6..1e6 and axis ratios to 1:1e6: also accurate.
    #[test]
    fn prop_every_query_on_valid_inputs_across_scales_is_answered_and_accurate(case in valid_case()) {
        let out = guarded(&case);
        prop_assert!(out.violations.is_empty(), "{}\n{}", describe(&case), out.violations.join("\n"));
        PROP_VALID.fetch_add(1, Ordering::Relaxed);
    }
}

#[test]
fn proptest_case_counts_are_printed() {
    // proptest runs exactly PROP_CASES cases of each property above unless one fails (then that
    // test fails with its minimal input); the counters show how many had finished when this ran.
    println!(
        "adversarial proptest: {PROP_CASES} cases each (finished so far: adversarial numbers {}, valid inputs {})",
        PROP_WILD.load(Ordering::Relaxed),
        PROP_VALID.load(Ordering::Relaxed)
    );
}
