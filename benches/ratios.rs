//! Speed ratios parry / ours per scenario class and outcome, with the accuracy beside them, and
//! how the cost grows with turns before impact, axis ratio and angular velocity. Prints markdown
//! tables.
//!
//! Run with `cargo bench --bench ratios`.
//!
//! Method: every scenario is timed on its own, for ours and for parry alternately, in several
//! rounds. Each timing repeats the query enough times to last at least `MIN_TIMING` (far above
//! the timer's resolution), and a scenario's time is the minimum over the rounds (robust
//! against interference from other processes). Both casts run through the dispatchers with
//! `stop_at_penetration = true` and parry's target distance 0.

#[path = "../tests/common/mod.rs"]
#[allow(unused_imports)]
mod common;
mod support;

use common::{ScenarioClass, ScenarioKind};
use core::f64::consts::TAU;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{
    DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit, ShapeCastStatus,
};
use parry2d_f64::shape::{Ball, Shape};
use smooth_ccd2d::{time_of_impact, BallCurve, ConvexCurve, Ellipse, SmoothDispatcher, ToiOptions};
use std::hint::black_box;
use std::time::{Duration, Instant};
use support::{split_batch, Case};

const MIN_TIMING: Duration = Duration::from_micros(200);
const ROUNDS: usize = 5;

/// Repetitions of `f` that take at least `MIN_TIMING`.
fn calibrate(f: &mut dyn FnMut()) -> u32 {
    let mut reps = 1u32;
    loop {
        let start = Instant::now();
        for _ in 0..reps {
            f();
        }
        let el = start.elapsed();
        if el >= MIN_TIMING {
            return reps;
        }
        let want = (MIN_TIMING.as_secs_f64() / el.as_secs_f64().max(1e-9) * 1.2).ceil();
        reps = (want as u32).clamp(reps.saturating_mul(2), reps.saturating_mul(100).max(2));
    }
}

/// Seconds per call of `f`, repeated `reps` times.
fn time_once(f: &mut dyn FnMut(), reps: u32) -> f64 {
    let start = Instant::now();
    for _ in 0..reps {
        f();
    }
    start.elapsed().as_secs_f64() / reps as f64
}

/// Per-query seconds of `a` and `b` (minimum over `ROUNDS` alternating rounds).
fn time_pair(a: &mut dyn FnMut(), b: &mut dyn FnMut()) -> (f64, f64) {
    let (ra, rb) = (calibrate(a), calibrate(b));
    let (mut ta, mut tb) = (f64::INFINITY, f64::INFINITY);
    for round in 0..ROUNDS {
        if round % 2 == 0 {
            ta = ta.min(time_once(a, ra));
            tb = tb.min(time_once(b, rb));
        } else {
            tb = tb.min(time_once(b, rb));
            ta = ta.min(time_once(a, ra));
        }
    }
    (ta, tb)
}

/// The q-quantile (nearest rank) of `v`; NaN for an empty slice.
fn quantile(v: &[f64], q: f64) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let i = ((q * s.len() as f64).ceil() as usize).clamp(1, s.len()) - 1;
    s[i]
}

fn us(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else {
        format!("{:.2}", x * 1e6)
    }
}

fn fx2(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else {
        format!("{x:.2}")
    }
}

fn sci(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else {
        format!("{x:.1e}")
    }
}

/// One timed scenario.
struct Timed {
    kind: ScenarioKind,
    /// Ours right / parry right against the reference (`None`: reference capped).
    ours_right: Option<bool>,
    parry_right: Option<bool>,
    /// |t − t_ref| of ours / parry where both it and the reference hit.
    ours_err: Option<f64>,
    parry_err: Option<f64>,
    /// (t_parry − t_ref) / window where both hit.
    parry_signed_err: Option<f64>,
    ours: f64,
    parry: f64,
    ours_hit: Option<ShapeCastHit>,
    parry_hit: Option<ShapeCastHit>,
}

fn time_batch(batch: &[Case], d: &SmoothDispatcher) -> Vec<Timed> {
    // The reference for parry's target distance 0 (all cores; before any timing).
    let refs = common::par_map(batch, |c| c.s.reference_with_target(0.0));
    batch
        .iter()
        .zip(&refs)
        .map(|(c, rf)| {
            let (ours, parry) = time_pair(
                &mut || {
                    black_box(c.ours(d));
                },
                &mut || {
                    black_box(c.parry());
                },
            );
            let (ours_hit, parry_hit) = (c.ours(d), c.parry());
            let (size, window) = (c.s.size(), c.s.t1 - c.s.t0);
            let err = |h: Option<ShapeCastHit>| Some((h?.time_of_impact - rf.hit_time()?).abs());
            Timed {
                kind: c.s.kind,
                ours_right: support::judge(ours_hit.map(|h| h.time_of_impact), rf, size, window),
                parry_right: support::judge(parry_hit.map(|h| h.time_of_impact), rf, size, window),
                ours_err: err(ours_hit),
                parry_err: err(parry_hit),
                parry_signed_err: parry_hit
                    .zip(rf.hit_time())
                    .map(|(h, t)| (h.time_of_impact - t) / window),
                ours,
                parry,
                ours_hit,
                parry_hit,
            }
        })
        .collect()
}

/// (ours wrong, parry wrong, undecided) against the reference.
fn wrong_counts<'a>(t: impl Iterator<Item = &'a Timed>) -> (usize, usize, usize) {
    t.fold((0, 0, 0), |(o, p, u), x| match (x.ours_right, x.parry_right) {
        (Some(a), Some(b)) => (o + usize::from(!a), p + usize::from(!b), u),
        _ => (o, p, u + 1),
    })
}

fn class_tables() {
    let d = SmoothDispatcher::default();
    let mut main = vec![
        "| class | outcome (ours) | n | ours median µs | parry median µs | ratio of medians | ours p90 µs | parry p90 µs | ratio of p90s | per-scenario ratio median | per-scenario ratio p10 | per-scenario ratio min | hit/miss agree | median \\|Δt\\| both hit | max \\|Δt\\| both hit | wrong vs reference: ours / parry (undecided) | median \\|t − t_ref\\| ours / parry | parry hits with status Failed | parry hits early / late vs reference |".to_string(),
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|".to_string(),
    ];
    let mut kinds = vec![
        "| class | kind | n | per-scenario ratio median | p10 | min | ours median µs | parry median µs | wrong vs reference: ours / parry (undecided) |".to_string(),
        "|---|---|---:|---:|---:|---:|---:|---:|---:|".to_string(),
    ];
    for class in ScenarioClass::ALL {
        let (hits, misses) = split_batch(class);
        let mut all = Vec::new();
        for (label, batch) in [("hit", &hits), ("miss", &misses)] {
            let t = time_batch(batch, &d);
            let ours: Vec<f64> = t.iter().map(|x| x.ours).collect();
            let parry: Vec<f64> = t.iter().map(|x| x.parry).collect();
            let ratio: Vec<f64> = t.iter().map(|x| x.parry / x.ours).collect();
            let agree = t
                .iter()
                .filter(|x| x.ours_hit.is_some() == x.parry_hit.is_some())
                .count();
            let dts: Vec<f64> = t
                .iter()
                .filter_map(|x| match (x.ours_hit, x.parry_hit) {
                    (Some(a), Some(b)) => Some((a.time_of_impact - b.time_of_impact).abs()),
                    _ => None,
                })
                .collect();
            let (ow, pw, und) = wrong_counts(t.iter());
            let failed = t
                .iter()
                .filter(|x| x.parry_hit.is_some_and(|h| h.status == ShapeCastStatus::Failed))
                .count();
            let early = t
                .iter()
                .filter(|x| x.parry_signed_err.is_some_and(|e| e < -1e-6))
                .count();
            let late = t
                .iter()
                .filter(|x| x.parry_signed_err.is_some_and(|e| e > 1e-6))
                .count();
            let ours_err: Vec<f64> = t.iter().filter_map(|x| x.ours_err).collect();
            let parry_err: Vec<f64> = t.iter().filter_map(|x| x.parry_err).collect();
            main.push(format!(
                "| {} | {label} | {} | {} | {} | {:.2} | {} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {}/{} | {} | {} | {ow} / {pw} ({und}) | {} / {} | {failed} | {early} / {late} |",
                class.name(),
                t.len(),
                us(quantile(&ours, 0.5)),
                us(quantile(&parry, 0.5)),
                quantile(&parry, 0.5) / quantile(&ours, 0.5),
                us(quantile(&ours, 0.9)),
                us(quantile(&parry, 0.9)),
                quantile(&parry, 0.9) / quantile(&ours, 0.9),
                quantile(&ratio, 0.5),
                quantile(&ratio, 0.1),
                quantile(&ratio, 0.0),
                agree,
                t.len(),
                sci(quantile(&dts, 0.5)),
                sci(quantile(&dts, 1.0)),
                sci(quantile(&ours_err, 0.5)),
                sci(quantile(&parry_err, 0.5)),
            ));
            all.extend(t);
        }
        for kind in ScenarioKind::ALL {
            let t: Vec<&Timed> = all.iter().filter(|x| x.kind == kind).collect();
            if t.is_empty() {
                continue;
            }
            let ratio: Vec<f64> = t.iter().map(|x| x.parry / x.ours).collect();
            let ours: Vec<f64> = t.iter().map(|x| x.ours).collect();
            let parry: Vec<f64> = t.iter().map(|x| x.parry).collect();
            let (ow, pw, und) = wrong_counts(t.iter().copied());
            kinds.push(format!(
                "| {} | {kind:?} | {} | {:.2} | {:.2} | {:.2} | {} | {} | {ow} / {pw} ({und}) |",
                class.name(),
                t.len(),
                quantile(&ratio, 0.5),
                quantile(&ratio, 0.1),
                quantile(&ratio, 0.0),
                us(quantile(&ours, 0.5)),
                us(quantile(&parry, 0.5)),
            ));
        }
    }
    println!("## Speed ratio parry / ours per class and outcome\n");
    println!(
        "{} scenarios per class (seeds 0..{}), split by our outcome; times per query, minimum of {ROUNDS} alternating rounds.\n",
        support::BATCH,
        support::BATCH
    );
    for l in main {
        println!("{l}");
    }
    println!("\n## Speed ratio parry / ours per class and scenario kind (hits and misses together)\n");
    for l in kinds {
        println!("{l}");
    }
}

/// One growth configuration: an ellipse at the origin spinning at `omega` about its centre and a
/// disc of radius 0.5 approaching it along x from `gap0` beyond the ellipse's long reach, so that
/// the gap along x would close at `tc`; window `[0, t1]`. `phase` is the ellipse's initial angle.
struct Growth {
    ellipse: Ellipse,
    m1: NonlinearRigidMotion,
    m2: NonlinearRigidMotion,
    t1: f64,
}

const DISC: f64 = 0.5;

fn growth(half_x: f64, half_y: f64, omega: f64, gap0: f64, tc: f64, t1: f64, phase: f64) -> Growth {
    let m1 = NonlinearRigidMotion::new(Pose::rotation(phase), Vector::ZERO, Vector::ZERO, omega);
    let x0 = half_x.max(half_y) + DISC + gap0;
    let m2 = NonlinearRigidMotion::new(
        Pose::translation(x0, 0.0),
        Vector::ZERO,
        Vector::new(-gap0 / tc, 0.0),
        0.0,
    );
    Growth {
        ellipse: Ellipse::new(half_x, half_y),
        m1,
        m2,
        t1,
    }
}

const PHASES: usize = 8;

/// parry's cast of a growth configuration on a thread of its own: `None` when it has not
/// returned within `PARRY_LIMIT` (the thread is left running; `main` ends the process).
fn parry_probe(g: &Growth) -> Option<Option<ShapeCastHit>> {
    // After one cast that never returned, parry is not tried again (its thread keeps a core).
    if PARRY_HUNG.load(std::sync::atomic::Ordering::Relaxed) {
        return None;
    }
    let (tx, rx) = std::sync::mpsc::channel();
    let (e, m1, m2, t1) = (g.ellipse, g.m1, g.m2, g.t1);
    std::thread::spawn(move || {
        let r = DefaultQueryDispatcher
            .cast_shapes_nonlinear(&m1, &e, &m2, &Ball::new(DISC), 0.0, t1, true)
            .ok()
            .flatten();
        let _ = tx.send(r);
    });
    let r = rx.recv_timeout(PARRY_LIMIT).ok();
    if r.is_none() {
        PARRY_HUNG.store(true, std::sync::atomic::Ordering::Relaxed);
    }
    r
}

static PARRY_HUNG: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

const PARRY_LIMIT: Duration = Duration::from_secs(10);

/// Median over the phases of: ours µs, ours predictor steps, parry µs, ratio; answers wrong
/// against the reference; parry's hits with status `Failed`, and configurations where parry did
/// not return within `PARRY_LIMIT` (not timed); largest |t − t_ref| of each where both it and
/// the reference hit; median reference time of impact.
fn growth_row(label: String, configs: &[Growth], d: &SmoothDispatcher) -> String {
    let ball = Ball::new(DISC);
    let disc = BallCurve { radius: DISC };
    let (mut to, mut tp, mut steps, mut ratio, mut tref) = (vec![], vec![], vec![], vec![], vec![]);
    let (mut ours_err, mut parry_err) = (vec![], vec![]);
    let (mut ours_wrong, mut parry_wrong, mut undecided, mut failed, mut hung) = (0, 0, 0, 0, 0);
    let (mut early, mut late) = (0, 0);
    for g in configs {
        let e: &dyn Shape = &g.ellipse;
        let ours = || {
            d.cast_shapes_nonlinear(&g.m1, e, &g.m2, &ball, 0.0, g.t1, true)
                .ok()
                .flatten()
        };
        let parry = || {
            DefaultQueryDispatcher
                .cast_shapes_nonlinear(&g.m1, e, &g.m2, &ball, 0.0, g.t1, true)
                .ok()
                .flatten()
        };
        let probe = parry_probe(g);
        if probe.is_some() {
            let (a, b) = time_pair(
                &mut || {
                    black_box(ours());
                },
                &mut || {
                    black_box(parry());
                },
            );
            to.push(a);
            tp.push(b);
            ratio.push(b / a);
        } else {
            hung += 1;
            let mut f = || {
                black_box(ours());
            };
            let reps = calibrate(&mut f);
            to.push(
                (0..ROUNDS)
                    .map(|_| time_once(&mut f, reps))
                    .fold(f64::INFINITY, f64::min),
            );
        }
        let r = time_of_impact(&g.ellipse, &g.m1, &disc, &g.m2, 0.0, g.t1, &ToiOptions::default());
        if let Ok(r) = r {
            steps.push(r.cost.predictor_steps as f64);
        }
        let rf = common::reference_toi(&g.ellipse, &g.m1, &disc, &g.m2, 0.0, g.t1, 0.0);
        let size = g.ellipse.bounding_radius().max(DISC);
        let ho = ours().map(|h| h.time_of_impact);
        let hp = probe.flatten();
        failed += usize::from(hp.is_some_and(|h| h.status == ShapeCastStatus::Failed));
        let hp = hp.map(|h| h.time_of_impact);
        let judge_o = support::judge(ho, &rf, size, g.t1);
        let judge_p = probe.and_then(|_| support::judge(hp, &rf, size, g.t1));
        match (judge_o, judge_p) {
            (Some(a), Some(b)) => {
                ours_wrong += usize::from(!a);
                parry_wrong += usize::from(!b);
            }
            _ => undecided += 1,
        }
        if let Some(t) = rf.hit_time() {
            tref.push(t);
            if let Some(x) = ho {
                ours_err.push((x - t).abs());
            }
            if let Some(x) = hp {
                parry_err.push((x - t).abs());
                early += usize::from(x < t - 1e-6 * g.t1);
                late += usize::from(x > t + 1e-6 * g.t1);
            }
        }
    }
    format!(
        "| {label} | {} | {:.0} | {} | {} | {} | {ours_wrong} / {parry_wrong} of {} ({undecided}) | {early} / {late} | {failed} | {hung} | {} / {} | {} |",
        us(quantile(&to, 0.5)),
        quantile(&steps, 0.5),
        us(quantile(&tp, 0.5)),
        fx2(quantile(&ratio, 0.5)),
        fx2(quantile(&ratio, 0.0)),
        configs.len(),
        sci(quantile(&ours_err, 1.0)),
        sci(quantile(&parry_err, 1.0)),
        sci(quantile(&tref, 0.5)),
    )
}

fn phases() -> impl Iterator<Item = f64> {
    (0..PHASES).map(|i| TAU * i as f64 / PHASES as f64 + 0.1)
}

fn growth_tables() {
    let d = SmoothDispatcher::default();
    let header = |p: &str| {
        println!("| {p} | ours median µs | ours predictor steps | parry median µs | ratio parry/ours median | ratio min | wrong vs reference: ours / parry (undecided) | parry hits early / late (> 1e-6 of the window) | parry hits with status Failed | parry: no answer in 10 s (not tried after one) | max \\|t − t_ref\\| ours / parry | median t_ref |");
        println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    };

    println!("\n## Growth: axis ratio\n");
    println!("Ellipse 1 × 1/k spinning at 5 rad/s, disc of radius 0.5 closing a gap of 1 along x at speed 2 (t_c = 0.5); window [0, 1]; {PHASES} initial angles.\n");
    header("axis ratio k");
    for k in [1.0, 10.0, 100.0, 1000.0] {
        let cfg: Vec<Growth> = phases().map(|p| growth(1.0, 1.0 / k, 5.0, 1.0, 0.5, 1.0, p)).collect();
        println!("{}", growth_row(format!("{k}"), &cfg, &d));
    }

    println!("\n## Growth: angular velocity\n");
    println!("Ellipse 1 × 0.25 spinning at ω, disc of radius 0.5 closing a gap of 1 along x at speed 2 (t_c = 0.5); window [0, 1]; {PHASES} initial angles.\n");
    header("ω rad/s");
    for w in [0.0, 1.0, 3.0, 10.0, 30.0, 60.0, 100.0, 300.0] {
        let cfg: Vec<Growth> = phases().map(|p| growth(1.0, 0.25, w, 1.0, 0.5, 1.0, p)).collect();
        println!("{}", growth_row(format!("{w}"), &cfg, &d));
    }

    println!("\n## Growth: turns before impact\n");
    println!("Ellipse 1 × 0.25 spinning at 20 rad/s, disc of radius 0.5 closing a gap of 0.5 along x slowly enough that the ellipse turns N times before the gap closes (t_c = 2πN/ω); window [0, t_c + 2π/ω]; {PHASES} initial angles.\n");
    header("turns N");
    let omega = 20.0;
    for n in [1u32, 2, 4, 8, 16, 32, 64] {
        let tc = TAU * n as f64 / omega;
        let t1 = tc + TAU / omega;
        let cfg: Vec<Growth> = phases().map(|p| growth(1.0, 0.25, omega, 0.5, tc, t1, p)).collect();
        println!("{}", growth_row(n.to_string(), &cfg, &d));
    }
}

fn main() {
    // `cargo bench` passes `--bench`; a filter argument selects "classes" or "growth".
    let args: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    let want = |name: &str| args.is_empty() || args.iter().any(|a| name.contains(a.as_str()));
    if want("classes") {
        class_tables();
    }
    if want("growth") {
        growth_tables();
    }
    // A parry cast that never returned may still be spinning on its thread.
    use std::io::Write;
    let _ = std::io::stdout().flush();
    std::process::exit(0);
}
