//! The f32 package against the f64 crate and the independent reference, on the f64 tests'
//! random scenarios (`tests/common` of the workspace root, shared by path) rounded to f32:
//!
//! * the f32 dispatcher's time of impact is the f64 dispatcher's for the same (f32) inputs,
//!   rounded down to f32;
//! * against the f64 answer for the original (unrounded) inputs, it agrees to the f32 rounding
//!   of the inputs: at the f32 time, the original pair's distance is within a few input
//!   roundings of the target (worst |Δt|/window printed);
//! * a reported hit is never inside penetration (for the f32 inputs) beyond the core's tolerance;
//! * a sample checked against the reference (conservative advancement) as in
//!   `tests/toi_vs_reference.rs`: no missed and no false impact;
//! * the Appendix D scene within 1e-5 s of the f64 answer.
//!
//! Parry's own pairs (box against box) are parry2d's in f32 and are left out.

#[path = "../../../tests/common/mod.rs"]
mod common;
mod common32;

use common::{generate, RefOutcome, Scenario, ScenarioClass, ScenarioKind};
use common32::{rounded, v32, Rounded, U32};
use parry2d::math::{Pose as Pose32, Vector as V32};
use parry2d::query::{NonlinearRigidMotion as Motion32, QueryDispatcher as _};
use parry2d_f64::query::{NonlinearRigidMotion, QueryDispatcher as _};
use smooth_ccd2d::ToiOptions;
use smooth_ccd2d_f32::{CastPolicy, Ellipse, RoundedPolygon, SmoothDispatcher};

/// The f32 dispatcher's cast (`stop_at_penetration`, the scenario's target distance).
fn cast32(r: &Rounded, s: &Scenario) -> Option<f32> {
    cast32_with(r, s, true)
}

/// The f32 dispatcher's cast, with `stop_at_penetration` = `stop` (false: rapier's rule).
fn cast32_with(r: &Rounded, s: &Scenario, stop: bool) -> Option<f32> {
    let d = SmoothDispatcher::default().with_toi_options(ToiOptions::default().with_target_distance(r.target as f64));
    d.cast_shapes_nonlinear(&r.m1, &*r.g1, &r.m2, &*r.g2, s.t0 as f32, s.t1 as f32, stop)
        .expect("the f32 dispatcher answers")
        .map(|h| h.time_of_impact)
}

/// The f64 dispatcher's cast of a scenario.
fn cast64(s: &Scenario) -> Option<f64> {
    cast64_with(s, true)
}

/// The f64 dispatcher's cast of a scenario, with `stop_at_penetration` = `stop`.
fn cast64_with(s: &Scenario, stop: bool) -> Option<f64> {
    let d = smooth_ccd2d::SmoothDispatcher::default()
        .with_toi_options(ToiOptions::default().with_target_distance(s.target));
    let (g1, g2) = (s.shape1.parry_shape(), s.shape2.parry_shape());
    d.cast_shapes_nonlinear(&s.motion1, &*g1, &s.motion2, &*g2, s.t0, s.t1, stop)
        .expect("the f64 dispatcher answers")
        .map(|h| h.time_of_impact)
}

/// How far rounding a scenario's inputs to f32 can move its shapes' points over the window:
/// u·(|centres| + |centre offsets| + 4·size + travel + turn·size), u the f32 unit roundoff.
fn rounding_scale(s: &Scenario) -> f64 {
    let t = s.t1 - s.t0;
    let size = s.size();
    let m = |m: &NonlinearRigidMotion| {
        m.start.translation.length() + m.local_center.length() + m.linvel.length() * t + m.angvel.abs() * t * size
    };
    U32 * (m(&s.motion1) + m(&s.motion2) + 4.0 * size)
}

fn classes() -> impl Iterator<Item = ScenarioClass> {
    ScenarioClass::ALL
        .into_iter()
        .filter(|&c| c != ScenarioClass::CuboidCuboid)
}

fn cases_per_class(total: usize) -> usize {
    let n = std::env::var("SMOOTH_CCD_F32_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(total);
    n.div_ceil(classes().count())
}

/// 10,000 random queries (every class with one of this package's shapes): the f32 answer is the
/// f64 answer of the f32 inputs rounded down, and agrees with the f64 answer of the original
/// inputs to the rounding of the inputs.
#[test]
fn f32_and_f64_times_of_impact_agree_to_the_rounding_of_the_inputs() {
    let per_class = cases_per_class(10_000);
    let (mut total, mut refused, mut both_hit, mut disagree) = (0, 0, 0, 0);
    let (mut worst_dt, mut worst_ulps, mut worst_gap) = (0.0f64, 0.0f64, 0.0f64);
    let (mut conditioned, mut worst_dt_conditioned, mut rapier_hits) = (0, 0.0f64, 0);
    for class in classes() {
        for seed in 0..per_class as u64 {
            let s = generate(class, seed);
            let Some(r) = rounded(&s) else {
                refused += 1;
                continue;
            };
            total += 1;
            let (t32, same, orig) = (cast32(&r, &s), cast64(&r.wide), cast64(&s));
            let ctx = || {
                format!(
                    "{} seed {seed}: f32 {t32:?}, f64 same inputs {same:?}, original {orig:?}",
                    class.name()
                )
            };
            // Same inputs: the f64 answer rounded down.
            match (t32, same) {
                (Some(a), Some(b)) => {
                    assert!(a as f64 <= b && b - a as f64 <= ulp(a), "{}", ctx());
                    worst_ulps = worst_ulps.max((b - a as f64) / ulp(a));
                }
                (None, None) => {}
                _ => panic!("hit and miss differ on the same inputs: {}", ctx()),
            }
            // rapier's rule (`stop_at_penetration = false`), same inputs: the f64 answer rounded
            // down, or one ulp after the start for an answer within one ulp of it.
            let (rapier32, rapier64) = (cast32_with(&r, &s, false), cast64_with(&r.wide, false));
            match (rapier32, rapier64) {
                (Some(a), Some(b)) => {
                    let start = s.t0 as f32;
                    let bumped = a == start.next_up() && b > start as f64 && b < a as f64;
                    assert!(
                        bumped || (a as f64 <= b && b - a as f64 <= ulp(a)),
                        "rapier rule: {a} / {b}: {}",
                        ctx()
                    );
                    rapier_hits += 1;
                }
                (None, None) => {}
                _ => panic!(
                    "rapier rule: hit and miss differ on the same inputs ({rapier32:?} / {rapier64:?}): {}",
                    ctx()
                ),
            }
            let (size, delta) = (s.size(), rounding_scale(&s));
            let window = s.t1 - s.t0;
            if let Some(a) = t32 {
                // Never inside penetration for the f32 inputs (beyond the core's tolerance).
                let d = r.wide.distance_at(a as f64) - r.wide.target;
                assert!(d >= -1e-10 * size, "f32 hit inside penetration by {d:e}: {}", ctx());
            }
            // The original inputs: each answer is a near-contact of the other's pair.
            match (t32, orig) {
                (Some(a), Some(b)) => {
                    both_hit += 1;
                    let dt = (a as f64 - b).abs() / window;
                    worst_dt = worst_dt.max(dt);
                    // Well conditioned: not a scenario built to graze, and the original's
                    // distance falls through the target at a rate of at least 1e-3 of the size
                    // per window (finite difference). Near a graze the rounding of the inputs
                    // can make or unmake an earlier touch, which moves the first contact.
                    let h = 1e-7 * window;
                    let falling = b - h > s.t0 && (s.distance_at(b - h) - s.distance_at(b)) / h * window > 1e-3 * size;
                    if s.kind != ScenarioKind::Grazing && falling {
                        conditioned += 1;
                        worst_dt_conditioned = worst_dt_conditioned.max(dt);
                    }
                    if s.t0 < a as f64 {
                        let gap = (s.distance_at(a as f64) - s.target).abs();
                        worst_gap = worst_gap.max(gap / delta);
                        assert!(gap <= 8.0 * delta + 1e-10 * size, "gap {gap:e} vs {delta:e}: {}", ctx());
                    }
                }
                (None, None) => {}
                (Some(a), None) => {
                    disagree += 1;
                    let gap = s.distance_at(a as f64) - s.target;
                    assert!(
                        gap <= 8.0 * delta + 1e-10 * size,
                        "f32-only hit, gap {gap:e}: {}",
                        ctx()
                    );
                }
                (None, Some(b)) => {
                    disagree += 1;
                    let gap = r.wide.distance_at(b) - r.wide.target;
                    assert!(
                        gap <= 8.0 * delta + 1e-10 * size,
                        "f64-only hit, f32 gap {gap:e}: {}",
                        ctx()
                    );
                }
            }
        }
    }
    println!(
        "f32 vs f64: {total} cases ({refused} shapes refused after rounding), {both_hit} hits in both; \
         same inputs: f32 = f64 rounded down (worst {worst_ulps:.2} ulp; with rapier's start-contact rule too, \
         {rapier_hits} hits); original inputs: worst |Δt|/window \
         {worst_dt_conditioned:.3e} over the {conditioned} well-conditioned hits ({worst_dt:.3e} over all, where \
         grazes move the first contact), worst |gap at the f32 time| {worst_gap:.2} input roundings, \
         {disagree} hit/miss differences, each a near-contact within 8 input roundings"
    );
    assert!(total >= 9_000 || std::env::var("SMOOTH_CCD_F32_CASES").is_ok());
}

/// One ulp of f32 at `t`, in f64.
fn ulp(t: f32) -> f64 {
    (t.abs().next_up() - t.abs()) as f64
}

/// A sample of scenarios against the reference, in f32: no missed and no false impact, the time
/// within the reference's conditioning of the f32 inputs' impact plus one ulp.
#[test]
fn f32_time_of_impact_matches_the_reference_on_a_sample() {
    let per_class = cases_per_class(900);
    let (mut total, mut hits, mut grazes) = (0, 0, 0);
    for class in classes() {
        for seed in 0..per_class as u64 {
            let s = generate(class, 1_000_000 + seed);
            let Some(r) = rounded(&s) else { continue };
            total += 1;
            let t32 = cast32(&r, &s);
            let rf = r.wide.reference();
            let size = r.wide.size();
            let tol = 1e-10 * size;
            let ctx = || {
                format!(
                    "{} seed {}: f32 {t32:?}, reference {:?}",
                    class.name(),
                    1_000_000 + seed,
                    rf.outcome
                )
            };
            if rf.initially_within_target {
                assert_eq!(t32, Some(s.t0 as f32), "{}", ctx());
                continue;
            }
            match rf.outcome {
                RefOutcome::Capped { reached } => {
                    if let Some(t) = t32 {
                        assert!(t as f64 >= reached - 1e-9 - ulp(t), "{}", ctx());
                    }
                }
                RefOutcome::Miss => {
                    if t32.is_some() {
                        assert!(rf.min_gap <= tol + 1e-12 * size, "false impact: {}", ctx());
                        grazes += 1;
                    }
                }
                RefOutcome::Hit { time, crossed } => match t32 {
                    None => {
                        assert!(!crossed && rf.min_gap >= -1e-12 * size, "missed impact: {}", ctx());
                        grazes += 1;
                    }
                    Some(t) => {
                        hits += 1;
                        let slope = rf.slope.abs();
                        let window = s.t1 - s.t0;
                        let allowed = 1e-9 + (tol + 1e-11 * size) / (slope * window).max(1e-300);
                        let dt = ((t as f64 - time).abs() - ulp(t)).max(0.0) / window;
                        assert!(dt <= allowed.max(1e-9) || !crossed, "time off by {dt:e}: {}", ctx());
                    }
                },
            }
        }
    }
    println!("f32 vs reference: {total} cases, {hits} hits, {grazes} grazes (no missed, no false impact)");
}

/// The specification's Appendix D scene in f32: the heptagon and the ellipse built from f32
/// parameters, the motion in f32; the time of impact within 1e-5 s of the f64 answer. The
/// dispatcher casts parry's constant-spin motion ([`CastPolicy::Plain`]: the default follows
/// rapier's clamp path).
#[test]
fn appendix_d_in_f32_is_within_1e_5_s_of_f64() {
    use common::appendix_d::{impact, ANGVEL, LINVEL, START, WINDOW};
    let hept = RoundedPolygon::regular(7, 1.0, 0.15);
    let ell = Ellipse::new(0.5, 1.5);
    let m1 = Motion32::new(Pose32::new(v32(START), 0.0), V32::ZERO, v32(LINVEL), ANGVEL as f32);
    let m2 = Motion32::identity();
    let hit = SmoothDispatcher::default()
        .with_cast_policy(CastPolicy::Plain)
        .cast_shapes_nonlinear(&m1, &hept, &m2, &ell, WINDOW.0 as f32, WINDOW.1 as f32, true)
        .expect("the dispatcher answers")
        .expect("a hit");
    let t64 = impact().time;
    let dt = (hit.time_of_impact as f64 - t64).abs();
    println!(
        "Appendix D: f32 {:.9} s, f64 {t64:.9} s, |Δt| = {dt:.2e} s",
        hit.time_of_impact
    );
    assert!(dt <= 1e-5, "{dt:e}");
}
