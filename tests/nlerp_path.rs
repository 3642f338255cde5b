//! The time of impact on the nlerp path (`MotionPath::Nlerp`: parry's `Sweep` interpolation
//! between the window's end poses, rapier's clamp) against the independent reference run on the
//! same path (`tests/common/reference.rs` with `nlerp`), over the random scenarios of every class
//! with one body turning — by up to several turns over the window, so that nlerp takes the short
//! way — and the other translating: no missed impact, no false impact, times to 1e-9 of the
//! window where the contact is well conditioned.

mod common;

use common::{generate, reference_toi_with, RefOutcome, RefToiOptions, Scenario, ScenarioClass};
use parry2d_f64::math::Pose;
use parry2d_f64::query::sweep_toi::Sweep;
use parry2d_f64::query::NonlinearRigidMotion;
use smooth_ccd2d::{shape_time_of_impact, MotionPath, QueryError, TimeOfImpact, ToiOptions, ToiStatus};

/// Scenarios per class.
const CASES: u64 = 300;

/// The scenario with only one body turning: body 1 turns (its spin scaled up to reach several
/// turns for one scenario in three, down to a residual 10⁻⁷ of it for one in five: a body
/// that hardly turns while it flies), body 2 only translates; for one scenario in four the same
/// motions run later, over a window that does not start at time 0 (parry's motions turn from
/// time 0, the nlerp path from the window's start).
fn one_turning(seed: u64, class: ScenarioClass) -> Scenario {
    let mut s = generate(class, seed);
    s.motion2.angvel = 0.0;
    if seed.is_multiple_of(3) {
        s.motion1.angvel *= 4.0;
    } else if seed % 5 == 2 {
        s.motion1.angvel *= 1e-7;
    }
    if seed % 4 == 1 {
        let tau = 0.7 * (s.t1 - s.t0) + 0.25;
        for m in [&mut s.motion1, &mut s.motion2] {
            m.start = m.position_at_time(-tau);
        }
        s.t0 += tau;
        s.t1 += tau;
    }
    s
}

/// The pose of a body of `s` at time `t` on the nlerp path.
fn nlerp_pose(m: &NonlinearRigidMotion, s: &Scenario, t: f64) -> Pose {
    let sweep = Sweep::from_poses(&m.position_at_time(s.t0), &m.position_at_time(s.t1), m.local_center);
    sweep.transform_at((t - s.t0) / (s.t1 - s.t0))
}

/// The reference signed distance of `s` at time `t` on the nlerp path.
fn nlerp_distance(s: &Scenario, t: f64) -> f64 {
    let (p1, p2) = (nlerp_pose(&s.motion1, s, t), nlerp_pose(&s.motion2, s, t));
    common::reference_distance(s.curve1(), &p1, s.curve2(), &p2).distance
}

fn ours(s: &Scenario) -> Result<TimeOfImpact, QueryError> {
    let opts = ToiOptions::default()
        .with_target_distance(s.target)
        .with_path(MotionPath::Nlerp);
    let (g1, g2) = (s.shape1.parry_shape(), s.shape2.parry_shape());
    shape_time_of_impact(&*g1, &s.motion1, &*g2, &s.motion2, s.t0, s.t1, &opts)
}

/// The dispatcher's cast for rapier (`CastPolicy::Rapier`: the nlerp path; its separating-axis
/// advancement where it takes the pair, the trackers elsewhere), stopping at penetration (no
/// start-contact rule), at target distance 0: its status and time.
fn dispatcher(s: &Scenario) -> Result<TimeOfImpact, QueryError> {
    use parry2d_f64::query::{QueryDispatcher, ShapeCastStatus};
    let (g1, g2) = (s.shape1.parry_shape(), s.shape2.parry_shape());
    let hit = smooth_ccd2d::SmoothDispatcher::default()
        .cast_shapes_nonlinear(&s.motion1, &*g1, &s.motion2, &*g2, s.t0, s.t1, true)
        .map_err(|_| QueryError::UnsupportedShape)?;
    let (status, time) = match hit {
        None => (ToiStatus::NoHit, s.t1),
        Some(h) => (
            match h.status {
                ShapeCastStatus::Converged => ToiStatus::Hit,
                ShapeCastStatus::PenetratingOrWithinTargetDist => ToiStatus::PenetratingAtStart,
                _ => ToiStatus::OutOfIterations,
            },
            h.time_of_impact,
        ),
    };
    let mut r = ours(s)?;
    r.status = status;
    r.time = time;
    Ok(r)
}

#[test]
fn the_nlerp_path_time_of_impact_matches_the_reference_on_the_same_path() {
    matches_the_reference_on_the_nlerp_path("shape_time_of_impact", |s| s, ours);
}

#[test]
fn the_dispatchers_rapier_cast_matches_the_reference_on_the_nlerp_path() {
    let at_contact = |mut s: Scenario| {
        s.target = 0.0;
        s
    };
    matches_the_reference_on_the_nlerp_path("SmoothDispatcher (rapier's casts)", at_contact, dispatcher);
}

/// Every class's scenarios (one body turning, `one_turning`) after `prepare`, answered by
/// `answer`, against the reference on the nlerp path: no missed impact, no false one, the time
/// within the tolerance's share of the window.
fn matches_the_reference_on_the_nlerp_path(
    name: &str,
    prepare: impl Fn(Scenario) -> Scenario,
    answer: impl Fn(&Scenario) -> Result<TimeOfImpact, QueryError>,
) {
    let mut lines = Vec::new();
    let mut total = 0;
    for class in ScenarioClass::ALL {
        let (mut hits, mut misses, mut grazes, mut worst) = (0, 0, 0, 0.0f64);
        for seed in 0..CASES {
            let s = prepare(one_turning(seed, class));
            let r = answer(&s).expect("one turning body");
            let size = s.size();
            let window = s.t1 - s.t0;
            let tol = 1e-10 * size;
            let opts = RefToiOptions {
                nlerp: true,
                ..Default::default()
            };
            let rf = reference_toi_with(
                s.curve1(),
                &s.motion1,
                s.curve2(),
                &s.motion2,
                s.t0,
                s.t1,
                s.target,
                &opts,
            );
            let ctx = || {
                format!(
                    "{} seed {seed}: ours {:?} at {}; reference {:?}",
                    class.name(),
                    r.status,
                    r.time,
                    rf.outcome
                )
            };
            total += 1;
            if rf.initially_within_target {
                assert_eq!(r.status, ToiStatus::PenetratingAtStart, "{}", ctx());
                continue;
            }
            match rf.outcome {
                RefOutcome::Capped { reached } => {
                    if r.status == ToiStatus::Hit {
                        assert!(r.time >= reached - 1e-9 * window, "{}", ctx());
                    }
                }
                RefOutcome::Miss => {
                    if r.status == ToiStatus::Hit {
                        assert!(rf.min_gap <= tol + 1e-12 * size, "false impact: {}", ctx());
                        grazes += 1;
                    } else {
                        assert_eq!(r.status, ToiStatus::NoHit, "{}", ctx());
                        misses += 1;
                    }
                }
                RefOutcome::Hit { time, crossed } => {
                    if r.status != ToiStatus::Hit {
                        assert!(!crossed && rf.min_gap >= -1e-12 * size, "missed impact: {}", ctx());
                        grazes += 1;
                        continue;
                    }
                    hits += 1;
                    // At our time, on the nlerp path, the distance is the target's (independently).
                    let d = nlerp_distance(&s, r.time) - s.target;
                    assert!(
                        d >= -1e-11 * size && d <= tol + 1e-11 * size,
                        "distance on the path at our time {d:e}: {}",
                        ctx()
                    );
                    let dt = (r.time - time).abs() / window;
                    let slope = rf.slope.abs();
                    let allowed = 1e-9 + (tol + 1e-11 * size) / (slope * window).max(1e-300);
                    assert!(dt <= allowed.max(1e-9) || !crossed, "time off by {dt:e}: {}", ctx());
                    if crossed && slope * window > 1e-3 * size {
                        worst = worst.max(dt);
                    }
                }
            }
        }
        lines.push(format!(
            "{:<28} hits {hits:4}  misses {misses:4}  grazes {grazes:3}  worst |t - t_ref|/window {worst:.1e}",
            class.name()
        ));
    }
    println!("{name}: {total} scenarios on the nlerp path:");
    for l in lines {
        println!("  {l}");
    }
}

#[test]
fn both_bodies_turning_is_refused_on_the_nlerp_path() {
    let s = generate(ScenarioClass::ALL[0], 3);
    let mut m2 = s.motion2;
    m2.angvel = 1.0;
    let mut m1 = s.motion1;
    m1.angvel = 2.0;
    let opts = ToiOptions::default().with_path(MotionPath::Nlerp);
    let r = smooth_ccd2d::time_of_impact(s.curve1(), &m1, s.curve2(), &m2, 0.0, 1.0, &opts);
    assert_eq!(r.unwrap_err(), QueryError::UnsupportedMotion);
}

#[test]
fn without_a_turn_the_nlerp_path_is_the_motion_itself() {
    for seed in 0..50 {
        let mut s = generate(ScenarioClass::ALL[1], seed);
        s.motion1.angvel = 0.0;
        s.motion2.angvel = 0.0;
        let plain = ToiOptions::default().with_target_distance(s.target);
        let nlerp = plain.with_path(MotionPath::Nlerp);
        let a = smooth_ccd2d::time_of_impact(s.curve1(), &s.motion1, s.curve2(), &s.motion2, s.t0, s.t1, &plain);
        let b = smooth_ccd2d::time_of_impact(s.curve1(), &s.motion1, s.curve2(), &s.motion2, s.t0, s.t1, &nlerp);
        assert_eq!(a, b, "seed {seed}");
    }
}
