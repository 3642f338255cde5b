//! Speed ratios parry / ours with the accuracy beside them, as markdown tables: the time of
//! impact per scenario class and outcome (and per scenario kind; the classes with no strictly
//! convex side also against parry's own shapes, section `classes-native`), the stationary
//! distance, the
//! contact manifolds (also on parry's own pairs through the dispatcher), parry's Box2D-style `sweep_time_of_impact` where it applies, how the time
//! of impact's cost grows with turns before impact, axis ratio and angular velocity (also drawn
//! to `docs/figures/toi_growth.png`), and a rapier step of the pile (with where it goes: the
//! dispatcher's calls by pair kind, and rapier's stage timers in a build with rapier's
//! `profiler` feature, `cargo bench --bench ratios --features rapier2d-f64/profiler -- pile`),
//! and rapier's CCD casts, this crate's shapes through `SmoothDispatcher` against the same bodies
//! as parry's shapes through `sweep_time_of_impact`, on every pair kind that function accepts
//! (section `rapier-casts`, `support/rapier_casts.rs`: starting apart with spins up to π/4 a step
//! and beyond, and in contact, each answer judged against the reference on the nlerp path).
//!
//! Run with `cargo bench --bench ratios` (all sections, a few minutes on two cores), or name
//! sections: `cargo bench --bench ratios -- classes distance manifolds parry-pairs sweep growth
//! pile rapier-casts cast-calls corner` (`cast-calls`: this crate's casts of `rapier-casts` alone, for
//! an instruction counter; `corner`: the degenerate starts of `tests/degenerate_starts.rs`, a
//! disc centred on a box's corner and its neighbours, with their evaluation counts)
//! (`classes` runs `classes-native` too; `native` alone runs only it).
//!
//! Method: every scenario is timed on its own, for ours and for parry alternately, in several
//! rounds. Each timing repeats the query enough times to last at least 200 µs (far above the
//! timer's resolution), and a scenario's time is the minimum over the rounds (robust against
//! interference from other processes). Ratios are parry's time over ours: above 1, ours is
//! faster. The casts run through the dispatchers with `stop_at_penetration = true` and target
//! distance 0 (but in `rapier-casts`, which makes rapier's own calls: `false` for ours, parry's
//! sweep with rapier's `linear_slop`).

mod support;

use core::f64::consts::TAU;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{
    DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit, ShapeCastStatus,
};
use parry2d_f64::shape::{Ball, Shape};
use smooth_ccd2d::{time_of_impact, BallCurve, ConvexCurve, Ellipse, SmoothDispatcher, ToiOptions};
use std::hint::black_box;
use std::time::Duration;
use support::scenarios::{par_map, ScenarioClass, ScenarioKind};
use support::{sci, split_batch, sweep_of, us, Case, PolygonDisc};

use support::timing::{calibrate, quantile, time_contenders, time_once, ROUNDS};

fn fx2(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else {
        format!("{x:.2}")
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
    let refs = par_map(batch, |c| c.s.reference_with_target(0.0));
    batch
        .iter()
        .zip(&refs)
        .map(|(c, rf)| {
            let (ours, parry) = time_contenders(|| c.ours(d), || c.parry());
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
    let mut compact = vec![
        "| class | outcome (ours) | n | ratio of medians | ratio of p90s | per-scenario ratio median / p10 | wrong vs reference: ours / parry | median \\|t − t_ref\\|/window ours / parry |".to_string(),
        "|---|---|---:|---:|---:|---:|---:|---:|".to_string(),
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
            compact.push(format!(
                "| {} | {label} | {} | {:.2} | {:.2} | {:.2} / {:.2} | {ow} / {pw}{} | {} / {} |",
                class.name(),
                t.len(),
                quantile(&parry, 0.5) / quantile(&ours, 0.5),
                quantile(&parry, 0.9) / quantile(&ours, 0.9),
                quantile(&ratio, 0.5),
                quantile(&ratio, 0.1),
                if und > 0 {
                    format!(" ({und} undecided)")
                } else {
                    String::new()
                },
                sci(quantile(&ours_err, 0.5)),
                sci(quantile(&parry_err, 0.5)),
            ));
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
    println!("## Time of impact: speed ratio parry / ours per class and outcome\n");
    println!(
        "{} scenarios per class (seeds 0..{}), split by our outcome. Ratios are parry's time over ours (above 1: ours is faster); \"wrong\" counts answers the reference contradicts (a missed or false impact, or a time off by more than 1e-6 of the window).\n",
        support::BATCH,
        support::BATCH
    );
    for l in compact {
        println!("{l}");
    }
    println!("\n### Details\n");
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
fn growth_row(label: String, configs: &[Growth], d: &SmoothDispatcher) -> (String, f64, f64, bool) {
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
            let (a, b) = time_contenders(ours, parry);
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
        let rf = support::reference::reference_toi(&g.ellipse, &g.m1, &disc, &g.m2, 0.0, g.t1, 0.0);
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
    let row = format!(
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
    );
    (row, quantile(&to, 0.5), quantile(&tp, 0.5), parry_wrong > 0)
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
    let mut panels = Vec::new();
    let mut points = Vec::new();
    for k in [1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0] {
        let cfg: Vec<Growth> = phases().map(|p| growth(1.0, 1.0 / k, 5.0, 1.0, 0.5, 1.0, p)).collect();
        let (row, o, p, w) = growth_row(format!("{k}"), &cfg, &d);
        println!("{row}");
        points.push((k, o, p, w));
    }
    panels.push(("axis ratio (5 rad/s)", "axis ratio k of the ellipse 1 × 1/k", points));

    println!("\n## Growth: angular velocity\n");
    println!("Ellipse 1 × 0.25 spinning at ω, disc of radius 0.5 closing a gap of 1 along x at speed 2 (t_c = 0.5); window [0, 1]; {PHASES} initial angles.\n");
    header("ω rad/s");
    let mut points = Vec::new();
    for w in [0.0, 1.0, 3.0, 10.0, 30.0, 60.0, 100.0, 300.0] {
        let cfg: Vec<Growth> = phases().map(|p| growth(1.0, 0.25, w, 1.0, 0.5, 1.0, p)).collect();
        let (row, o, p, wrong) = growth_row(format!("{w}"), &cfg, &d);
        println!("{row}");
        if w > 0.0 {
            points.push((w, o, p, wrong));
        }
    }
    panels.push(("angular velocity (window 1 s)", "ω (rad/s)", points));

    println!("\n## Growth: turns before impact\n");
    println!("Ellipse 1 × 0.25 spinning at 20 rad/s, disc of radius 0.5 closing a gap of 0.5 along x slowly enough that the ellipse turns N times before the gap closes (t_c = 2πN/ω); window [0, t_c + 2π/ω]; {PHASES} initial angles.\n");
    header("turns N");
    let omega = 20.0;
    let mut points = Vec::new();
    for n in [1u32, 2, 4, 8, 16, 32, 64] {
        let tc = TAU * n as f64 / omega;
        let t1 = tc + TAU / omega;
        let cfg: Vec<Growth> = phases().map(|p| growth(1.0, 0.25, omega, 0.5, tc, t1, p)).collect();
        let (row, o, p, w) = growth_row(n.to_string(), &cfg, &d);
        println!("{row}");
        points.push((n as f64, o, p, w));
    }
    panels.push(("turns before impact (20 rad/s)", "turns N before impact", points));
    // The bench belongs to the member `crates/dev`: the repository's root is two folders up.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let path = root.join("docs/figures/toi_growth.png");
    match plot_growth(&path, &panels) {
        Ok(()) => println!("\nPlot: `{}`.", path.strip_prefix(&root).unwrap_or(&path).display()),
        Err(e) => println!("\n(plot not written: {e})"),
    }
}

/// One panel of the growth plot: title, x label, (x, ours s, parry s or NaN, parry wrong in some
/// of the configurations).
type Panel = (&'static str, &'static str, Vec<(f64, f64, f64, bool)>);

/// Draws the growth panels side by side (log–log, median µs per query of ours and parry).
fn plot_growth(path: &std::path::Path, panels: &[Panel]) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    use plotters::style::FontStyle;
    const FONT: &str = "sans-serif";
    plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| "could not load the embedded DejaVu Sans font")?;
    let root = BitMapBackend::new(path, (1500, 500)).into_drawing_area();
    root.fill(&WHITE)?;
    let (title, body) = root.split_vertically(40);
    title.titled(
        "Time of impact, ellipse against a disc: median µs per query, this crate vs parry's cast_shapes_nonlinear (hollow: parry wrong in some)",
        (FONT, 20),
    )?;
    let areas = body.split_evenly((1, panels.len()));
    let (y_lo, y_hi) = panels
        .iter()
        .flat_map(|p| p.2.iter().flat_map(|&(_, o, q, _)| [o, q]))
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v * 1e6), hi.max(v * 1e6))
        });
    let blue = RGBColor(31, 119, 180);
    let orange = RGBColor(255, 127, 14);
    for (area, (name, xlabel, pts)) in areas.iter().zip(panels) {
        let (x_lo, x_hi) = pts
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), p| (lo.min(p.0), hi.max(p.0)));
        let mut chart = ChartBuilder::on(area)
            .caption(*name, (FONT, 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(
                (x_lo * 0.8..x_hi * 1.25).log_scale(),
                (y_lo * 0.5..y_hi * 2.0).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc(*xlabel)
            .y_desc("µs per query")
            .label_style((FONT, 13))
            .axis_desc_style((FONT, 14))
            .draw()?;
        let ours: Vec<(f64, f64)> = pts.iter().map(|p| (p.0, p.1 * 1e6)).collect();
        let parry: Vec<(f64, f64, bool)> = pts
            .iter()
            .filter(|p| p.2.is_finite())
            .map(|p| (p.0, p.2 * 1e6, p.3))
            .collect();
        chart
            .draw_series(LineSeries::new(ours.clone(), blue.stroke_width(2)))?
            .label("this crate")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], blue.stroke_width(2)));
        chart.draw_series(ours.iter().map(|&p| Circle::new(p, 4, blue.filled())))?;
        chart
            .draw_series(LineSeries::new(
                parry.iter().map(|p| (p.0, p.1)),
                orange.stroke_width(2),
            ))?
            .label("parry")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], orange.stroke_width(2)));
        chart.draw_series(parry.iter().map(|&(x, y, wrong)| {
            let style = if wrong {
                ShapeStyle::from(&WHITE).filled()
            } else {
                orange.filled()
            };
            TriangleMarker::new((x, y), 5, style)
        }))?;
        chart.draw_series(
            parry
                .iter()
                .filter(|p| p.2)
                .map(|&(x, y, _)| TriangleMarker::new((x, y), 5, orange.stroke_width(2))),
        )?;
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .label_font((FONT, 13))
            .draw()?;
    }
    root.present()?;
    Ok(())
}

/// One pose of a pair for the stationary queries: shape 2 at `pos12` in shape 1's frame, the
/// reference signed distance there, and the size of the pair.
struct PosedPair {
    case: Case,
    pos12: Pose,
    reference: f64,
    size: f64,
}

impl PosedPair {
    fn new(case: Case, pos12: Pose) -> Self {
        let reference =
            support::reference::reference_distance(case.s.curve1(), &Pose::IDENTITY, case.s.curve2(), &pos12).distance;
        let size = case.s.size();
        Self {
            case,
            pos12,
            reference,
            size,
        }
    }
}

/// (median ours µs, median parry µs, ratio of medians, ratio of p90s, per-scenario ratio median).
fn ratios(ours: &[f64], parry: &[f64]) -> (f64, f64, f64, f64, f64) {
    let r: Vec<f64> = ours.iter().zip(parry).map(|(o, p)| p / o).collect();
    (
        quantile(ours, 0.5),
        quantile(parry, 0.5),
        quantile(parry, 0.5) / quantile(ours, 0.5),
        quantile(parry, 0.9) / quantile(ours, 0.9),
        quantile(&r, 0.5),
    )
}

fn distance_tables() {
    let d = SmoothDispatcher::default();
    println!("\n## Stationary distance: speed ratio parry / ours\n");
    println!(
        "Per class, the pair at the window start of the {} scenarios (separated: `distance`, parry's GJK) and the same poses with the centres brought to a quarter of their distance where that overlaps (penetrating: `contact`, parry's EPA), both through the shapes' support maps. Errors are against the dense-search reference of `tests/common`, relative to the size.\n",
        support::BATCH
    );
    println!("| class | set | n | ours median µs | parry median µs | ratio of medians | ratio of p90s | per-scenario ratio median | worst \\|error\\|/size ours | parry | parry off by > 1e-6·size |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for class in ScenarioClass::ALL {
        let cases: Vec<Case> = (0..support::BATCH as u64).map(|s| Case::new(class, s)).collect();
        let (mut apart, mut overlapping) = (Vec::new(), Vec::new());
        for c in cases {
            let p = c.start_pose();
            let mut close = p;
            close.translation *= 0.25;
            let c2 = Case::new(class, c.s.seed);
            apart.push(PosedPair::new(c, p));
            overlapping.push(PosedPair::new(c2, close));
        }
        let apart: Vec<PosedPair> = apart.into_iter().filter(|p| p.reference > 0.0).collect();
        let overlapping: Vec<PosedPair> = overlapping.into_iter().filter(|p| p.reference < 0.0).collect();
        for (label, set, penetrating) in [("separated", &apart, false), ("penetrating", &overlapping, true)] {
            let (mut to, mut tp, mut eo, mut ep, mut off) = (vec![], vec![], 0.0f64, 0.0f64, 0);
            for p in set.iter() {
                let (g1, g2) = (&*p.case.g1, &*p.case.g2);
                let ours = || -> Option<f64> {
                    if penetrating {
                        Some(d.contact(&p.pos12, g1, g2, 0.0).ok()??.dist)
                    } else {
                        d.distance(&p.pos12, g1, g2).ok().map(|x| x.distance)
                    }
                };
                let parry = || -> Option<f64> {
                    if penetrating {
                        Some(DefaultQueryDispatcher.contact(&p.pos12, g1, g2, 0.0).ok()??.dist)
                    } else {
                        DefaultQueryDispatcher
                            .distance(&p.pos12, g1, g2)
                            .ok()
                            .map(|x| x.distance)
                    }
                };
                let (a, b) = time_contenders(ours, parry);
                to.push(a);
                tp.push(b);
                let err = |x: Option<f64>| x.map_or(f64::INFINITY, |x| (x - p.reference).abs() / p.size);
                eo = eo.max(err(ours()));
                let e = err(parry());
                ep = ep.max(e);
                off += usize::from(e > 1e-6);
            }
            let (mo, mp, rm, r9, rs) = ratios(&to, &tp);
            println!(
                "| {} | {label} | {} | {} | {} | {rm:.2} | {r9:.2} | {rs:.2} | {} | {} | {off} |",
                class.name(),
                set.len(),
                us(mo),
                us(mp),
                sci(eo),
                sci(ep)
            );
        }
    }
}

fn sweep_tables() {
    use parry2d_f64::query::{sweep_time_of_impact, SweepToiStatus, ToiProxy};
    let d = SmoothDispatcher::default();
    println!("\n## parry's Box2D-style `sweep_time_of_impact`\n");
    println!(
        "It takes point clouds with a radius (balls, capsules, polygons and their rounded versions), so of this crate's pairs it applies to rounded polygon – disc. The {} `rounded_polygon-ellipse` scenarios with the ellipse replaced by the disc of the same area (this crate: `RoundedPolygon` and parry's `Ball` through `SmoothDispatcher`; the sweep: parry's `RoundConvexPolygon` and `Ball`, `linear_slop` 1e-9 of the size so that it stops within 1e-9·size of touching). The sweep interpolates the rotation between the end poses (nlerp) instead of spinning at constant speed, so its path is this crate's only without spin: the first set has the spins set to 0, the second keeps spins of at most 45° over the window (rapier's regime), where the two paths differ slightly and the reference follows this crate's.\n",
        support::BATCH
    );
    println!("| set | n | ours median µs | sweep median µs | ratio of medians | ratio of p90s | per-scenario ratio median | wrong vs reference: ours / sweep | sweep status Failed | median \\|t − t_ref\\| ours / sweep |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (label, spin) in [("no spin", false), ("spin ≤ 45° over the window", true)] {
        let mut rows = Vec::new();
        for seed in 0..support::BATCH as u64 {
            if let Some(pd) = PolygonDisc::new(seed, spin) {
                rows.push((pd.s, pd.poly, pd.parry_poly, pd.radius));
            }
        }
        let refs = par_map(&rows, |(s, ..)| s.reference_with_target(0.0));
        let (mut to, mut tp, mut wo, mut wp, mut failed, mut eo, mut ep) = (vec![], vec![], 0, 0, 0, vec![], vec![]);
        for ((s, poly, parry_poly, r), rf) in rows.iter().zip(&refs) {
            let ball = Ball::new(*r);
            let window = s.t1 - s.t0;
            let size = s.size();
            let slop = 1e-9 * size;
            let ours = || {
                d.cast_shapes_nonlinear(&s.motion1, poly, &s.motion2, &ball, s.t0, s.t1, true)
                    .ok()
                    .flatten()
                    .map(|h| h.time_of_impact)
            };
            let sweep = || {
                let (pa, pb) = (
                    ToiProxy::from_shape(parry_poly).unwrap(),
                    ToiProxy::from_shape(&ball).unwrap(),
                );
                let (sa, sb) = (sweep_of(&s.motion1, s.t0, s.t1), sweep_of(&s.motion2, s.t0, s.t1));
                sweep_time_of_impact(&pa, &sa, &pb, &sb, 1.0, slop)
            };
            let (a, b) = time_contenders(ours, sweep);
            to.push(a);
            tp.push(b);
            let so = sweep();
            failed += usize::from(so.status == SweepToiStatus::Failed);
            let sweep_answer = match so.status {
                SweepToiStatus::Separated => None,
                _ => Some(s.t0 + so.fraction * window),
            };
            let ho = ours();
            if let (Some(a), Some(b)) = (
                support::judge(ho, rf, size, window),
                support::judge(sweep_answer, rf, size, window),
            ) {
                wo += usize::from(!a);
                wp += usize::from(!b);
            }
            if let Some(t) = rf.hit_time() {
                if let Some(x) = ho {
                    eo.push((x - t).abs() / window);
                }
                if let Some(x) = sweep_answer {
                    ep.push((x - t).abs() / window);
                }
            }
        }
        let (mo, mp, rm, r9, rs) = ratios(&to, &tp);
        println!(
            "| {label} | {} | {} | {} | {rm:.2} | {r9:.2} | {rs:.2} | {wo} / {wp} | {failed} | {} / {} |",
            rows.len(),
            us(mo),
            us(mp),
            sci(quantile(&eo, 0.5)),
            sci(quantile(&ep, 0.5))
        );
    }
}

/// The degenerate starts (`support::corner`): status, evaluations and time of each, parry's own
/// cast beside where parry has the pair.
fn corner_table() {
    println!("\n## Degenerate starts: a shape centred on a polygon's corner, edge or centre\n");
    println!(
        "The issue's pathological cast (a unit disc centred on the corner of the unit box, `stop_at_penetration`: 4,002 evaluations, 1.7 ms before the stationary distance's sinusoid bound) and its neighbours, through `shape_time_of_impact` (`time_of_impact` for the curves), window [0, 1]; parry: its `DefaultQueryDispatcher` cast of its `Ball` and `Cuboid`s where it has the pair. Evaluations: pair evaluations of the φ–t tracker, exact distances of the gap tracker.\n"
    );
    println!("| case | status | evaluations | ours µs | parry µs | ratio |");
    println!("|---|---|---:|---:|---:|---:|");
    for c in support::corner::cases() {
        let r = c.ours();
        let (status, evals) = match &r {
            Ok(r) => (format!("{:?}", r.status), r.cost.evaluations.to_string()),
            Err(e) => (format!("{e:?}"), "–".into()),
        };
        let (ours, parry) = if c.has_parry() {
            time_contenders(|| c.ours(), || c.parry())
        } else {
            (
                support::timing::time_one(&mut || {
                    black_box(c.ours()).ok();
                }),
                f64::NAN,
            )
        };
        println!(
            "| {} | {status} | {evals} | {} | {} | {} |",
            c.name,
            us(ours),
            us(parry),
            fx2(parry / ours)
        );
    }
}

fn main() {
    // `cargo bench` passes `--bench`; arguments select sections.
    let args: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    let want = |name: &str| args.is_empty() || args.iter().any(|a| name.contains(a.as_str()));
    if want("classes") {
        class_tables();
    }
    if want("classes-native") {
        support::native::native_table();
    }
    if want("distance") {
        distance_tables();
    }
    if want("manifolds") {
        support::manifolds::table();
    }
    if want("parry-pairs") {
        support::parry_pairs::table();
    }
    if want("sweep") {
        sweep_tables();
    }
    if want("growth") {
        growth_tables();
    }
    if want("rapier-casts") {
        support::rapier_casts::table();
    }
    if want("cast-calls") {
        support::rapier_casts::calls();
    }
    if want("pile") {
        support::pile_tables::pile_table();
        support::pile_tables::pile_stage_table();
    }
    if want("pile-bound") {
        support::pile_tables::pile_bound_table();
    }
    if want("pile-calls") {
        support::replay::pile_calls_table(400);
    }
    if want("corner") {
        corner_table();
    }
    // A parry cast that never returned may still be spinning on its thread.
    use std::io::Write;
    let _ = std::io::stdout().flush();
    std::process::exit(0);
}
