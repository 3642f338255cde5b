//! rapier's CCD casts, this crate against parry's Box2D-style `sweep_time_of_impact`, on every
//! pair kind the sweep accepts where this crate has a counterpart (section `rapier-casts` of
//! `cargo bench --bench ratios`).
//!
//! What rapier 0.36 asks (`dynamics/ccd/sweeps.rs`), one step of `DT`, the target held at its
//! pose:
//!
//! * for its own shapes (parry's `Ball`, `ConvexPolygon`, `RoundConvexPolygon`, …):
//!   `sweep_time_of_impact(target_proxy, Sweep::constant(target_pose), body_proxy,
//!   Sweep::from_poses(start, end, local_com), 1, linear_slop)`, a fraction in (0, 1) kept, and at
//!   a fraction of exactly 0 the same sweep again with the body's core circle
//!   (`ToiProxy::point(centroid, CORE_FRACTION · ccd_thickness)`) — [`parry_cast`];
//! * for this crate's shapes: `SmoothDispatcher::cast_shapes_nonlinear(body motion, body,
//!   constant target motion, target, 0, DT, false)`, `time_of_impact / DT` kept when in (0, 1) —
//!   [`ours_cast`].
//!
//! The body moves from its pose at 0 to its pose at `DT` (constant velocity and spin); rapier
//! clamps it on the nlerp path between them (`Sweep::transform_at`), which both follow.
//!
//! The references (`tests/common/reference.rs`, conservative advancement on support functions,
//! on the nlerp path) judge each answer:
//!
//! * starting apart: the first touching time; this crate must find it (a miss, a false impact,
//!   or a time off by more than 1e-6 of the step, `support::judge`). parry's sweep stops where
//!   the cores are `max(slop, R − slop) ± slop/4` apart (R the sum of the proxies' radii): a
//!   *miss* of parry's is a touching impact it does not report although the pair goes past the
//!   deep end of that band; a *false* impact one it reports where the shapes never touch and
//!   never come within the band's shallow end; *off* a hit outside the band's times;
//! * starting in contact, each against its own rule: this crate's (`CastPolicy::Rapier`: the
//!   earlier of the body's core disc, a quarter of its inradius about its rotation centre,
//!   touching the target, and its translation without spin taking the contact a quarter of that
//!   inradius deeper) and rapier's for parry (the sweep's band, or at a fraction 0 the core
//!   circle's band).
#![allow(clippy::too_many_arguments)]

use super::reference::{reference_distance, reference_toi_with, RefOutcome, RefToi, RefToiOptions};
use super::rng::Rng;
use super::scenarios::par_map;
use super::timing::{quantile, time_contenders};
use super::{judge, polygon_approximation, POLYGON_VERTICES};
use core::f64::consts::{FRAC_PI_4, PI, TAU};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::sweep_toi::CORE_FRACTION;
use parry2d_f64::query::{
    sweep_time_of_impact, NonlinearRigidMotion, QueryDispatcher, Sweep, SweepToiStatus, ToiProxy,
};
use parry2d_f64::shape::{Ball, Capsule, ConvexPolygon, Cuboid, Segment, Shape, Triangle};
use smooth_ccd2d::{BallCurve, ConvexCurve, CurvePoint, Ellipse, RoundedPolygon, SmoothDispatcher};
use std::sync::Arc;

mod judging;
mod making;

pub use judging::*;
pub use making::*;

/// One step (rapier's default).
pub const DT: f64 = 1.0 / 60.0;
/// rapier's `linear_slop` (`IntegrationParameters::allowed_linear_error()`, 0.005 × length unit 1).
pub const SLOP: f64 = 0.005;
/// Cases per pair kind and set (`RAPIER_CASTS_CASES` overrides it).
pub const CASES: usize = 80;

fn cases() -> usize {
    std::env::var("RAPIER_CASTS_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(CASES)
}

/// Whether `name` is selected by the environment variable `var`: unset, or `name` starts with
/// its value (`RAPIER_CASTS_BODY=disc`, `RAPIER_CASTS_SET=contact`, `RAPIER_CASTS_TARGET=Cuboid`;
/// a target's name without its backquotes).
fn selected(var: &str, name: &str) -> bool {
    std::env::var(var).map_or(true, |v| name.trim_start_matches('`').starts_with(v.as_str()))
}

/// With `RAPIER_CASTS_PROFILE` set, the section makes each selected cast once, ours then
/// parry's, and prints no table, only each row's hits and the digest of this crate's answers:
/// a run for instruction counts (`valgrind --tool=callgrind
/// --toggle-collect='*cast_shapes_nonlinear*'`) and for a change that keeps every answer.
fn profile_only() -> bool {
    std::env::var_os("RAPIER_CASTS_PROFILE").is_some()
}
/// The smallest start gap of the sets starting apart: two slops, so that parry's sweep starts
/// apart too.
const MIN_START_GAP: f64 = 2.0 * SLOP;
/// This crate's core and allowance, as fractions of the body's inradius (`CastPolicy::CORE`,
/// `CastPolicy::ALLOWANCE`).
const OUR_CORE: f64 = 0.25;
const OUR_ALLOWANCE: f64 = 0.25;

/// The moving body's kind.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Body {
    /// A disc: this crate's `Ellipse::new(r, r)`, parry's `Ball`.
    Disc,
    /// A random convex polygon of 3–8 vertices: `RoundedPolygon` of radius 0, parry's `ConvexPolygon`.
    Polygon,
    /// The same rounded (0.02–0.3 of its size): `RoundedPolygon`, parry's `RoundConvexPolygon`.
    Rounded,
    /// A sliver polygon (3–4 vertices, 1:10–1:50), sharp.
    Sliver,
    /// An ellipse (1:1.5–1:10): parry casts its inscribed 64-gon.
    Ellipse,
}

impl Body {
    /// Every kind.
    pub const ALL: [Body; 5] = [Body::Disc, Body::Polygon, Body::Rounded, Body::Sliver, Body::Ellipse];

    fn name(self) -> &'static str {
        match self {
            Body::Disc => "disc",
            Body::Polygon => "polygon",
            Body::Rounded => "rounded polygon",
            Body::Sliver => "sliver polygon",
            Body::Ellipse => "ellipse (parry: 64-gon)",
        }
    }
}

/// The target's kind (parry's shapes, for both).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Target {
    Ball,
    Cuboid,
    Segment,
    Capsule,
    Triangle,
    Polygon,
}

impl Target {
    /// Every kind.
    pub const ALL: [Target; 6] = [
        Target::Ball,
        Target::Cuboid,
        Target::Segment,
        Target::Capsule,
        Target::Triangle,
        Target::Polygon,
    ];

    fn name(self) -> &'static str {
        match self {
            Target::Ball => "`Ball`",
            Target::Cuboid => "`Cuboid`",
            Target::Segment => "`Segment`",
            Target::Capsule => "`Capsule`",
            Target::Triangle => "`Triangle`",
            Target::Polygon => "`ConvexPolygon`",
        }
    }
}

/// The set a case belongs to.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Set {
    /// Apart at the start, |ω|·DT ≤ π/4 (rapier's regime).
    Apart,
    /// Apart at the start, |ω|·DT in [π/4, 4π] (up to two turns a step).
    Beyond,
    /// In contact at the start (touching or up to a tenth of the inradius deep), |ω|·DT ≤ π/4.
    Contact,
    /// Apart at the start, no spin at all (a body with its rotation locked, a bullet fired
    /// without spin): rapier's cast of a body that does not turn.
    Still,
}

impl Set {
    /// Every set.
    pub const ALL: [Set; 4] = [Set::Apart, Set::Beyond, Set::Contact, Set::Still];

    fn name(self) -> &'static str {
        match self {
            Set::Apart => "apart, ≤ π/4",
            Set::Beyond => "apart, π/4–4π",
            Set::Contact => "contact, ≤ π/4",
            Set::Still => "apart, no spin",
        }
    }
}

/// A parry shape as a curve for the reference: its support points shifted by `shift` and pushed
/// out along the direction by `offset` (negative: eroded), so that the reference's signed
/// distance is the pair's minus the offset. Only `support_point` and `bounding_radius` are read
/// by the reference.
#[derive(Clone)]
pub struct ParryCurve {
    shape: Arc<dyn Shape>,
    shift: Vector,
    offset: f64,
}

impl core::fmt::Debug for ParryCurve {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "ParryCurve({:?}, shift {:?}, offset {})",
            self.shape.shape_type(),
            self.shift,
            self.offset
        )
    }
}

impl ConvexCurve for ParryCurve {
    fn eval(&self, _phi: f64) -> CurvePoint {
        unreachable!("the reference reads support points only")
    }
    fn bounding_radius(&self) -> f64 {
        let s = self.shape.compute_local_bounding_sphere();
        s.center.length() + s.radius + self.shift.length() + self.offset.max(0.0)
    }
    fn support_point(&self, n: Vector) -> Vector {
        let m = self.shape.as_support_map().expect("a support-map shape");
        self.shift + m.local_support_point_toward(n) + n * self.offset
    }
}

/// One rapier cast.
pub struct RCase {
    pub body: Body,
    pub target: Target,
    pub set: Set,
    pub seed: u64,
    /// The body as this crate's shape, as a parry shape and as a curve.
    pub ours: Arc<dyn Shape>,
    pub ours_curve: Arc<dyn ConvexCurve>,
    /// The body as parry's shape (for the ellipse, its inscribed 64-gon).
    pub parry: Arc<dyn Shape>,
    /// The target (a parry shape, for both).
    pub target_shape: Arc<dyn Shape>,
    pub target_pose: Pose,
    /// The body's motion (rotation about its centre of mass), from its pose at 0 to its pose at `DT`.
    pub motion: NonlinearRigidMotion,
    /// rapier's sweep of the body (`Sweep::from_poses(start, end, local_com)`).
    pub sweep: Sweep,
    /// parry's centroid and `ccd_thickness` of its body shape (its core circle).
    pub parry_centroid: Vector,
    pub parry_thickness: f64,
    /// The body's inradius about its centre of mass (this crate's rule).
    pub inradius: f64,
    /// The reference signed distance at the start.
    pub d0: f64,
}

/// What parry's sweep and rapier's use of it answer: the fraction kept (rapier's
/// `cast_sub_shape` for a solid pair and a point-cloud target).
#[inline]
pub fn parry_cast(c: &RCase) -> Option<f64> {
    let target = ToiProxy::from_shape(&*c.target_shape)?;
    let body = ToiProxy::from_shape(&*c.parry)?;
    let target_sweep = Sweep::constant(&c.target_pose, Vector::ZERO);
    let out = sweep_time_of_impact(&target, &target_sweep, &body, &c.sweep, 1.0, SLOP);
    if 0.0 < out.fraction && out.fraction < 1.0 {
        return Some(out.fraction);
    }
    if out.fraction == 0.0 {
        let core = ToiProxy::point(c.parry_centroid, CORE_FRACTION * c.parry_thickness);
        let out = sweep_time_of_impact(&target, &target_sweep, &core, &c.sweep, 1.0, SLOP);
        if 0.0 < out.fraction && out.fraction < 1.0 {
            return Some(out.fraction);
        }
    }
    None
}

/// The status of parry's first sweep of `c`.
pub fn parry_status(c: &RCase) -> Option<SweepToiStatus> {
    let target = ToiProxy::from_shape(&*c.target_shape)?;
    let body = ToiProxy::from_shape(&*c.parry)?;
    let target_sweep = Sweep::constant(&c.target_pose, Vector::ZERO);
    Some(sweep_time_of_impact(&target, &target_sweep, &body, &c.sweep, 1.0, SLOP).status)
}

/// What `SmoothDispatcher` answers rapier for the same cast (`fallback_nonlinear_fraction`).
#[inline]
pub fn ours_cast(c: &RCase, d: &SmoothDispatcher) -> Option<f64> {
    let target = NonlinearRigidMotion::constant_position(c.target_pose);
    let hit = d
        .cast_shapes_nonlinear(&c.motion, &*c.ours, &target, &*c.target_shape, 0.0, DT, false)
        .ok()??;
    let f = hit.time_of_impact / DT;
    (0.0 < f && f < 1.0).then_some(f)
}

/// One timed, judged case.
struct Row {
    ours_s: f64,
    parry_s: f64,
    j: Judged,
}

/// The seed of case `i` of a pair kind and set.
fn seed(body: Body, target: Target, set: Set, i: usize) -> u64 {
    let b = Body::ALL.iter().position(|&x| x == body).unwrap() as u64;
    let t = Target::ALL.iter().position(|&x| x == target).unwrap() as u64;
    let s = Set::ALL.iter().position(|&x| x == set).unwrap() as u64;
    0x7A91_0000_0000 + ((s * 8 + b) * 8 + t) * 10_000 + i as u64
}

fn fx(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else {
        format!("{x:.2}")
    }
}

fn sci(x: Option<f64>) -> String {
    x.map_or("–".into(), |x| format!("{x:.1e}"))
}

/// miss / false, with the off and undecided counts when not 0.
fn counts(v: &[&Verdict]) -> String {
    let n = |f: fn(&Verdict) -> bool| v.iter().filter(|x| f(x)).count();
    let mut s = format!("{} / {}", n(|x| x.miss), n(|x| x.false_hit));
    let off = n(|x| x.off);
    if off > 0 {
        s += &format!(" ({off} off)");
    }
    let und = n(|x| x.undecided);
    if und > 0 {
        s += &format!(" [{und} undecided]");
    }
    s
}

fn worst(v: &[&Verdict]) -> Option<f64> {
    v.iter()
        .filter_map(|x| x.err)
        .fold(None, |m, e| Some(m.map_or(e, |m: f64| m.max(e))))
}

/// Prints the section.
pub fn table() {
    let d = SmoothDispatcher::default();
    println!("\n## rapier's CCD casts: `SmoothDispatcher` against parry's `sweep_time_of_impact`\n");
    println!(
        "Per pair kind (body – target) and set, {} random casts of one step of 1/60 s (speeds 1–3000 m/s log-uniform, fixed seeds), the target at rest. Ours: rapier's call for this crate's shapes, `cast_shapes_nonlinear(body, constant target, 0, 1/60, stop_at_penetration = false)`, time/dt kept in (0, 1). parry: rapier's call for its own shapes, `sweep_time_of_impact(target, body, 1, linear_slop = {SLOP})` (with rapier's core-circle retry at a fraction 0), on the same body as parry's shape (disc: `Ball`; polygons: `ConvexPolygon` / `RoundConvexPolygon`; ellipse: its inscribed {POLYGON_VERTICES}-gon, against whose own reference parry's columns are judged). Times: mean µs per cast (each case the minimum of alternating rounds); ratio = parry / ours (≥ 1: ours at least as fast), of the means, then the per-case ratio's median and minimum. Apart sets: miss / false against the touching reference on the nlerp path (for parry, beyond its slop band; \"off\": a hit outside the tolerance, 1e-6 of the step for ours, parry's band for parry); worst |Δf|: |fraction − reference| where both hit (parry's includes its slop). Contact set: each against its own rule (ours: core or allowance; parry: band or core circle); parry's |Δf| is its distance outside its band.\n",
        cases()
    );
    println!("| pair kind | set | cases | hits (ref) | ours µs/cast | parry µs/cast | ratio (means) | per-case ratio median / min | ours miss / false | parry miss / false | worst \\|Δf\\| ours | worst \\|Δf\\| parry |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut all: Vec<(Body, Set, Row)> = Vec::new();
    let mut slow: Vec<(f64, f64, String)> = Vec::new();
    let mut wrong: Vec<String> = Vec::new();
    let mut parry_wrong: Vec<(Set, String)> = Vec::new();
    let sets = Set::ALL.into_iter().filter(|s| selected("RAPIER_CASTS_SET", s.name()));
    for set in sets {
        for body in Body::ALL
            .into_iter()
            .filter(|b| selected("RAPIER_CASTS_BODY", b.name()))
        {
            for target in Target::ALL
                .into_iter()
                .filter(|t| selected("RAPIER_CASTS_TARGET", t.name()))
            {
                let seeds: Vec<u64> = (0..cases()).map(|i| seed(body, target, set, i)).collect();
                let cases = par_map(&seeds, |&s| make_case(body, target, set, s));
                let answers: Vec<(Option<f64>, Option<f64>)> =
                    cases.iter().map(|c| (ours_cast(c, &d), parry_cast(c))).collect();
                if profile_only() {
                    let hits = answers.iter().filter(|a| a.0.is_some()).count();
                    // FNV-1a of this crate's fractions' bits (a miss as all ones): a change
                    // meant to keep every answer shows the same digests before and after.
                    let digest = answers.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, a| {
                        (h ^ a.0.map_or(u64::MAX, f64::to_bits)).wrapping_mul(0x0000_0100_0000_01b3)
                    });
                    println!(
                        "{} – {}, {}: {hits} hits, answers {digest:#018x}",
                        body.name(),
                        target.name(),
                        set.name()
                    );
                    continue;
                }
                let idx: Vec<usize> = (0..cases.len()).collect();
                let judged = par_map(&idx, |&i| judge_case(&cases[i], answers[i].0, answers[i].1));
                let mut rows = Vec::new();
                for (c, j) in cases.iter().zip(judged) {
                    let (o, p) = time_contenders(|| ours_cast(c, &d), || parry_cast(c));
                    if j.ours_v.miss || j.ours_v.false_hit || j.ours_v.off {
                        wrong.push(format!(
                            "ours {} (answer {:?}, reference {:?}): {}",
                            if j.ours_v.miss {
                                "miss"
                            } else if j.ours_v.false_hit {
                                "false"
                            } else {
                                "off"
                            },
                            j.ours,
                            j.ref_hit,
                            describe(c)
                        ));
                    }
                    if j.parry_v.miss || j.parry_v.false_hit {
                        parry_wrong.push((
                            set,
                            format!(
                                "parry {} (answer {:?}, sweep status {:?}, reference of this crate's event {:?}): {}",
                                if j.parry_v.miss { "miss" } else { "false" },
                                j.parry,
                                parry_status(c),
                                j.ref_hit,
                                describe(c)
                            ),
                        ));
                    }
                    slow.push((o, p, describe(c)));
                    rows.push(Row {
                        ours_s: o,
                        parry_s: p,
                        j,
                    });
                }
                print_row(
                    &format!("{} – {}", body.name(), target.name()),
                    set,
                    &rows.iter().collect::<Vec<_>>(),
                );
                all.extend(rows.into_iter().map(|r| (body, set, r)));
            }
        }
    }
    if profile_only() {
        return;
    }
    println!("\n### All pair kinds together\n");
    println!("| pair kind | set | cases | hits (ref) | ours µs/cast | parry µs/cast | ratio (means) | per-case ratio median / min | ours miss / false | parry miss / false | worst \\|Δf\\| ours | worst \\|Δf\\| parry |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for set in Set::ALL {
        for body in Body::ALL {
            let rows: Vec<&Row> = all.iter().filter(|x| x.0 == body && x.1 == set).map(|x| &x.2).collect();
            print_row(&format!("{} – all targets", body.name()), set, &rows);
        }
        let rows: Vec<&Row> = all.iter().filter(|x| x.1 == set).map(|x| &x.2).collect();
        print_row("all", set, &rows);
        for (label, hit) in [("all, reference hits", true), ("all, reference misses", false)] {
            let part: Vec<&Row> = rows.iter().copied().filter(|r| r.j.ref_hit.is_some() == hit).collect();
            print_row(label, set, &part);
        }
    }
    slow.sort_by(|a, b| b.0.total_cmp(&a.0));
    println!("\n### Slowest casts of ours\n");
    for (o, p, s) in slow.iter().take(8) {
        println!("- ours {:.2} µs, parry {:.2} µs: {s}", o * 1e6, p * 1e6);
    }
    println!("\n### parry's misses and false impacts\n");
    for set in Set::ALL {
        let w: Vec<&String> = parry_wrong.iter().filter(|x| x.0 == set).map(|x| &x.1).collect();
        println!("{} ({}; the first {}):\n", set.name(), w.len(), w.len().min(4));
        for w in w.iter().take(4) {
            println!("- {w}");
        }
        println!();
    }
    if wrong.is_empty() {
        println!("\nNo answer of ours was wrong against the reference.");
    } else {
        println!("\n### Answers of ours the reference contradicts\n");
        for w in &wrong {
            println!("- {w}");
        }
    }
}

fn print_row(label: &str, set: Set, rows: &[&Row]) {
    let n = rows.len();
    if n == 0 {
        return;
    }
    let hits = rows.iter().filter(|r| r.j.ref_hit.is_some()).count();
    let mo = rows.iter().map(|r| r.ours_s).sum::<f64>() / n as f64;
    let mp = rows.iter().map(|r| r.parry_s).sum::<f64>() / n as f64;
    let ratio: Vec<f64> = rows.iter().map(|r| r.parry_s / r.ours_s).collect();
    let ov: Vec<&Verdict> = rows.iter().map(|r| &r.j.ours_v).collect();
    let pv: Vec<&Verdict> = rows.iter().map(|r| &r.j.parry_v).collect();
    println!(
        "| {label} | {} | {n} | {hits} | {:.2} | {:.2} | {} | {} / {} | {} | {} | {} | {} |",
        set.name(),
        mo * 1e6,
        mp * 1e6,
        fx(mp / mo),
        fx(quantile(&ratio, 0.5)),
        fx(quantile(&ratio, 0.0)),
        counts(&ov),
        counts(&pv),
        sci(worst(&ov)),
        sci(worst(&pv)),
    );
}

/// rapier's casts of this crate's shapes only, for an instruction counter
/// (`cargo bench --bench ratios -- cast-calls` under `valgrind --tool=callgrind
/// --toggle-collect='*cast_shapes_nonlinear*'`): every case of the sets and body kinds that
/// `RAPIER_CASTS_SET` (`apart`, `beyond`, `contact`) and `RAPIER_CASTS_BODY` (`disc`, `polygon`,
/// `rounded`, `sliver`, `ellipse`) name (all when unset), cast `RAPIER_CASTS_PASSES` times (4),
/// no timing and no reference; prints the casts made, the hits and a digest of the answers' bits.
pub fn calls() {
    let d = SmoothDispatcher::default();
    let pick = |var: &str, name: &str| std::env::var(var).map_or(true, |v| name.starts_with(v.as_str()));
    let passes: usize = std::env::var("RAPIER_CASTS_PASSES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(4);
    let mut all = Vec::new();
    for set in Set::ALL {
        let set_name = match set {
            Set::Apart => "apart",
            Set::Beyond => "beyond",
            Set::Contact => "contact",
            Set::Still => "still",
        };
        for body in Body::ALL {
            if !(pick("RAPIER_CASTS_SET", set_name) && pick("RAPIER_CASTS_BODY", body.name())) {
                continue;
            }
            for target in Target::ALL {
                let seeds: Vec<u64> = (0..cases()).map(|i| seed(body, target, set, i)).collect();
                all.extend(par_map(&seeds, |&s| make_case(body, target, set, s)));
            }
        }
    }
    let (mut hits, mut digest) = (0usize, 0xCBF2_9CE4_8422_2325u64);
    for _ in 0..passes {
        for c in &all {
            let a = std::hint::black_box(ours_cast(c, &d));
            hits += usize::from(a.is_some());
            digest = (digest ^ a.map_or(u64::MAX, f64::to_bits)).wrapping_mul(0x0100_0000_01B3);
        }
    }
    println!(
        "cast-calls: {} cases × {passes} passes, {} hits a pass, answers' digest {digest:016x}",
        all.len(),
        hits / passes.max(1)
    );
}
