//! The CCD scene suite (`tests/common/ccd_scenes.rs`, judged by `tests/common/ccd_judge.rs`):
//! game-like continuous-collision scenes — segment and chain walls, thin posts and planks,
//! funnels and an acute wedge, a slide into a corner, bullets into a stack, a flipper, bouncing
//! boxes — with every shape family of the crate as the moving body, 10 to 3000 m/s and spins to
//! 600 rad/s (rapier's caps lifted where a case is above them), in rapier2d-f64 with
//! `SmoothDispatcher`, side by side with rapier's default narrow phase on parry's closest
//! shapes. `cargo run --release --example ccd_scenes` prints the same table.
//!
//! What it pins for `SmoothDispatcher`: no body through a wall, no NaN, no panic in any case;
//! with rapier's contact recycling off (every manifold recomputed every step), no body frozen
//! in any case; with it on (rapier's default), no body frozen but at most [`MAX_FROZEN`] cases
//! of the one class [`may_freeze`] names (docs/rapier.md, "What is left", says why); with it on
//! and the CCD bodies' colliders given active hooks (the remedy docs/rapier.md gives, which
//! exempts their pairs from recycling), no body frozen in any case; with rapier's rotation cap
//! kept on the bodies launched spinning below it, no body frozen in any case. In every setting,
//! after every step in which rapier's CCD swept a body: its centre of mass at least an eighth of
//! its `ccd_thickness` from every fixed target (the start-contact rule's core), and no case in
//! which it ended deeper than [`APART_TOLERANCE`] in a fixed target it was apart from at the
//! step's start *and which rapier asked the dispatcher to cast it against* in that step (the
//! judge records the casts); the cases deep in a target rapier never asked about (its
//! candidate search misses a target a body turning fast reaches mid-step) are printed. With
//! the pass `MovingPairs` around the steps: no case at all deeper than [`APART_TOLERANCE`] from
//! apart, asked or not, and at most one more frozen case (a bullet lodged in the stack). The table it prints has
//! those two figures and the deepest penetration after a swept step. The chain families built as
//! oriented (one-sided) polylines: no body through nor frozen, and none deeper from apart than
//! the one-sided early-out's bound. Without rapier's CCD, this crate's disc follows parry's
//! `Ball` in every scene to 1e-6 m (the manifolds alone compared).

mod common;

use common::ccd_judge::{run_all, run_case, table};
use common::ccd_scenes::{all_cases, Body, Case, Family, Method};

/// The one class of cases in which a body may stay frozen for `FROZEN_STEPS` steps, with
/// rapier's contact recycling on: the sliver at 1000 m/s or more shot into the acute wedge.
/// rapier selects a pair's speculative contacts (the core contact of the wall it is about to
/// be thrown against) by the velocities before its solver runs, and keeps that selection while
/// the pair's relative pose stays within 0.05 of its last full update; the CCD's clamp keeps
/// the sliver (inradius 0.01 about its centroid) within a quarter of that inradius a step, and
/// the pair is recomputed only after about ten steps (docs/rapier.md, "What is left"). At most
/// [`MAX_FROZEN`] such cases; none of any other body, family or speed, and none with contact
/// recycling off.
///
/// With the pass `MovingPairs` around the steps ([`Case::moving_pairs`]), one more class: a
/// bullet at 1000 m/s or more shot into the stack, lodged between moving boxes. The pass
/// measures a contact of two moving bodies at the step's start on their whole motions
/// (`CastPolicy::RapierConstantSpin`), and stops both at the step's start when those take the
/// contact deeper by the allowance or the bullet's core deeper than its depth limit (already
/// past it there); where the solver leaves that approach in place, the two stay there
/// (docs/rapier.md, "Two moving bodies", where it is not exact).
fn may_freeze(c: &Case) -> bool {
    (c.recycling && c.family == Family::Wedge && c.body == Body::Sliver && c.speed >= 1000.0)
        || (c.moving_pairs && c.family == Family::BulletsStack && c.speed >= 1000.0)
}

/// The most cases of the [`may_freeze`] class that may freeze.
const MAX_FROZEN: usize = 1;

/// The most cases of [`may_freeze`]'s class with the pass `MovingPairs` (a bullet lodged in the
/// stack) that may freeze, besides [`MAX_FROZEN`] of the wedge's.
const MAX_FROZEN_WITH_PASS: usize = 1;

/// The deepest a CCD-swept body may be, at a step's end, in a fixed target it was apart from
/// at the step's start (m): rapier's CCD stops it where it touches, which the dispatcher's
/// cast finds exactly (about 10⁻¹⁴ m measured at these scenes' scales).
const APART_TOLERANCE: f64 = 1e-9;

// The targets rapier's CCD never asks the dispatcher about, in which a swept body may end a
// step deeper than [`APART_TOLERANCE`] although it was apart at the step's start: rapier takes
// as candidates the fixed colliders whose box meets the union of the body's boxes at the
// step's two end poses, which a long body turning fast pokes out of in mid-step
// (docs/rapier.md, "A target rapier's CCD does not cast"). Printed, not bounded: no answer of
// the dispatcher is involved. Traced cast by cast on 2026-11-29: the sliver at 3000 m/s, 20 rad/s
// into the stack, cast only against a box of the stack in a step it turns 1.86 rad, its tip
// 0.114 m into the ground; with the CCD bodies' hooks or recycling off, the thin ellipse at
// 100 m/s, −100 rad/s in the bouncing box, cast only against the side wall while it turns
// 2.74 rad, 0.055 m into the floor. `MovingPairs` sweeps such bodies against every fixed
// collider their swept box meets: with it, none.

/// The least distance from a swept body's centre of mass to a fixed target at a step's end, as
/// a fraction of its `ccd_thickness` r: `CastPolicy::Rapier` keeps the core (r/4 about the
/// centre) off every target, and one that starts touching within half its radius of it, so
/// the centre stays r/8 away (less a rounding allowance).
const CENTRE_CLEARANCE: f64 = 0.125 - 1e-9;

/// What went wrong in a case under `SmoothDispatcher` and is never allowed: a body through a
/// wall, a NaN, a panic, a frozen body outside [`may_freeze`], a swept body's centre within
/// [`CENTRE_CLEARANCE`] of a fixed target.
fn failures_of(c: &Case, o: &common::ccd_judge::Outcome) -> Vec<String> {
    let what = c.describe();
    let mut failures = Vec::new();
    if o.centre_clearance < CENTRE_CLEARANCE {
        failures.push(format!(
            "{what}: a swept body's centre {} of its thickness from a wall",
            o.centre_clearance
        ));
    }
    if let Some(t) = &o.through {
        failures.push(format!("{what}: through at step {} ({})", t.0, t.1));
    }
    if let Some(step) = o.nan {
        failures.push(format!("{what}: NaN at step {step}"));
    }
    if let Some(p) = &o.panicked {
        failures.push(format!("{what}: panicked ({p})"));
    }
    if o.frozen.is_some() && !may_freeze(c) {
        failures.push(format!("{what}: frozen at step {:?}", o.frozen));
    }
    failures
}

#[test]
fn no_body_goes_through_a_wall_nor_freezes_in_the_ccd_scene_suite() {
    let cases = all_cases();
    let outcomes = run_all(&cases);
    println!("CCD scene suite: {} cases", cases.len());
    print!("{}", table(&cases, &outcomes));
    let mut failures: Vec<String> = cases
        .iter()
        .zip(&outcomes)
        .flat_map(|(c, o)| failures_of(c, &o[0]))
        .collect();
    let frozen: Vec<String> = cases
        .iter()
        .zip(&outcomes)
        .filter(|(_, o)| o[0].frozen.is_some())
        .map(|(c, _)| c.describe())
        .collect();
    println!(
        "SmoothDispatcher: {} frozen (at most {MAX_FROZEN}): {frozen:?}",
        frozen.len()
    );
    if frozen.len() > MAX_FROZEN {
        failures.push(format!("{} frozen cases, more than {MAX_FROZEN}", frozen.len()));
    }
    failures.extend(asked_failures(&cases, outcomes.iter().map(|o| &o[0])));
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// With rapier's contact recycling off, every manifold is recomputed every step from the poses
/// and velocities of that step: no body of any case goes through a wall or freezes, no NaN, no
/// panic (`SmoothDispatcher` only; `cargo run --release --example ccd_scenes -- --no-recycling`
/// prints the table of both methods).
#[test]
fn no_body_goes_through_a_wall_nor_freezes_with_contact_recycling_off() {
    let cases = all_cases().into_iter().map(|c| Case { recycling: false, ..c });
    no_body_through_nor_frozen(cases.collect(), "contact recycling off");
}

/// The remedy docs/rapier.md ("What is left") gives a user whose thin CCD body freezes with
/// contact recycling on, scoped to those bodies: their colliders with
/// `ActiveHooks::MODIFY_SOLVER_CONTACTS` and no-op hooks (`()`), so that rapier never recycles
/// their pairs (every other pair is recycled as usual, the recycle distance left at 0.05). No
/// body of any case goes through a wall or freezes, no NaN, no panic (`SmoothDispatcher` only;
/// `cargo run --release --example ccd_scenes -- --ccd-hooks` prints the table of both methods).
#[test]
fn no_body_freezes_when_the_ccd_bodies_have_active_hooks() {
    let cases = all_cases().into_iter().map(|c| Case { ccd_hooks: true, ..c });
    no_body_through_nor_frozen(cases.collect(), "CCD bodies with active hooks");
}

/// rapier's rotation cap (π/4 a step) kept on the bodies launched spinning below it, the linear
/// cap lifted as in every case above it: the frozen class of [`may_freeze`] (a sliver launched
/// without spin, which the wedge's walls spin past half a turn a step, where rapier's clamp path
/// turns the other way from its solver's spin) does not arise, and no body of any case goes
/// through a wall or freezes, with contact recycling on (`cargo run --release --example
/// ccd_scenes --rotation-cap-kept` prints the table of both methods).
#[test]
fn no_body_freezes_when_only_the_spinning_bodies_lift_the_rotation_cap() {
    let cases = all_cases().into_iter().map(|c| Case {
        rotation_cap_kept: true,
        ..c
    });
    no_body_through_nor_frozen(cases.collect(), "rotation cap kept below it");
}

/// This crate's pass for two moving bodies, `MovingPairs` with its default options, around
/// every step of `SmoothDispatcher`'s run, rapier's contact recycling on: no body through a wall,
/// no NaN, no panic, every swept body's centre at least an eighth of its thickness off every
/// fixed target, and **no** case in which a swept body ended a step deeper than
/// [`APART_TOLERANCE`] in a fixed target it was apart from at the step's start — the pass sweeps
/// a body turning past rapier's regime (π/4 a step) against every fixed collider its swept box
/// meets, the targets rapier's candidate search misses among them. Frozen: at
/// most [`MAX_FROZEN`] cases in the wedge and [`MAX_FROZEN_WITH_PASS`] in the stack, the classes
/// [`may_freeze`] names (`cargo run --release
/// --example ccd_scenes -- --moving-pairs` prints the table of both methods, rapier's default
/// without the pass).
#[test]
fn with_the_moving_pairs_pass_no_swept_body_ends_deep_in_a_target_it_was_apart_from() {
    let cases: Vec<Case> = all_cases()
        .into_iter()
        .map(|c| Case {
            moving_pairs: true,
            ..c
        })
        .collect();
    let outcomes: Vec<_> = cases.iter().map(|c| run_case(c, Method::Smooth)).collect();
    let mut failures: Vec<String> = cases
        .iter()
        .zip(&outcomes)
        .flat_map(|(c, o)| failures_of(c, o))
        .collect();
    let frozen: Vec<&Case> = cases
        .iter()
        .zip(&outcomes)
        .filter(|(_, o)| o.frozen.is_some())
        .map(|(c, _)| c)
        .collect();
    let stack = frozen.iter().filter(|c| c.family == Family::BulletsStack).count();
    println!(
        "with MovingPairs: {} cases, {} frozen (at most {MAX_FROZEN} in the wedge, {MAX_FROZEN_WITH_PASS} in the stack): {:?}",
        cases.len(),
        frozen.len(),
        frozen.iter().map(|c| c.describe()).collect::<Vec<_>>()
    );
    if stack > MAX_FROZEN_WITH_PASS || frozen.len() - stack > MAX_FROZEN {
        failures.push(format!("{} frozen cases, {stack} of them in the stack", frozen.len()));
    }
    failures.extend(deep_from_apart(&cases, outcomes.iter(), 0));
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The chain box and the chain terrain built as oriented (one-sided) polylines, as a game builds
/// its level (`cargo run --release --example ccd_scenes -- chain-box --oriented-chains` prints the
/// table of both methods): no body through a wall, none frozen, no NaN, no panic, every swept
/// body's centre at least an eighth of its thickness off every fixed target; and a swept body
/// apart from a segment at the step's start less than a quarter of its `ccd_thickness` inside it
/// at the step's end — the bound of rapier's one-sided early-out with the turn counted
/// (docs/rapier.md, rule 4 of `CastPolicy::Rapier`), the segments cast exactly otherwise.
#[test]
fn no_body_goes_through_nor_freezes_on_oriented_chains() {
    let cases: Vec<Case> = all_cases()
        .into_iter()
        .filter(|c| matches!(c.family, Family::ChainBox | Family::ChainTerrain))
        .map(|c| Case {
            oriented_chains: true,
            ..c
        })
        .collect();
    let (frozen, failures, outcomes) = run_smooth(&cases, |c, o| {
        let margin = 0.25 * c.body.shape(Method::Smooth).ccd_thickness();
        (o.asked_apart_deepest >= margin).then(|| {
            format!(
                "{}: {} m deep from apart, the margin {margin} m",
                c.describe(),
                o.asked_apart_deepest
            )
        })
    });
    let deepest = outcomes.iter().map(|o| o.asked_apart_deepest).fold(0.0f64, f64::max);
    println!(
        "oriented chains: {} cases, {frozen} frozen, deepest from apart in a target rapier asked about {deepest:.3e} m",
        cases.len()
    );
    assert_eq!(frozen, 0, "frozen on oriented chains:\n{}", failures.join("\n"));
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The cases for which `depth` gives a depth, each described with it.
fn listed<'a>(
    cases: &[Case],
    outcomes: impl Iterator<Item = &'a common::ccd_judge::Outcome>,
    depth: impl Fn(&common::ccd_judge::Outcome) -> Option<f64>,
) -> Vec<String> {
    cases
        .iter()
        .zip(outcomes)
        .filter_map(|(c, o)| depth(o).map(|d| format!("{}: {d:.3e} m", c.describe())))
        .collect()
}

/// The cases whose swept bodies ended a step deeper than [`APART_TOLERANCE`] in a fixed target
/// they started the step apart from: as a failure where rapier asked the dispatcher to cast that
/// pair (its answer put the body there); the others, targets rapier never asked about, printed.
fn asked_failures<'a>(
    cases: &[Case],
    outcomes: impl Iterator<Item = &'a common::ccd_judge::Outcome> + Clone,
) -> Vec<String> {
    let unasked = listed(cases, outcomes.clone(), |o| {
        (o.apart_deepest > APART_TOLERANCE && o.asked_apart_deepest <= APART_TOLERANCE).then_some(o.apart_deepest)
    });
    println!("deeper than {APART_TOLERANCE:e} m from apart in a target rapier never asked about: {unasked:?}");
    let asked = listed(cases, outcomes, |o| {
        (o.asked_apart_deepest > APART_TOLERANCE).then_some(o.asked_apart_deepest)
    });
    println!("deeper than {APART_TOLERANCE:e} m from apart in a target rapier asked about (none allowed): {asked:?}");
    if asked.is_empty() {
        Vec::new()
    } else {
        vec![format!(
            "{} cases deeper than {APART_TOLERANCE:e} m from apart in a target the dispatcher was asked about: {asked:?}",
            asked.len()
        )]
    }
}

/// The cases whose swept bodies ended a step deeper than [`APART_TOLERANCE`] in a fixed target
/// they started the step apart from (printed), as a failure when there are more than `most`.
fn deep_from_apart<'a>(
    cases: &[Case],
    outcomes: impl Iterator<Item = &'a common::ccd_judge::Outcome>,
    most: usize,
) -> Vec<String> {
    let deep = listed(cases, outcomes, |o| {
        (o.apart_deepest > APART_TOLERANCE).then_some(o.apart_deepest)
    });
    println!("deeper than {APART_TOLERANCE:e} m after a swept step, apart at its start (at most {most}): {deep:?}");
    if deep.len() > most {
        vec![format!(
            "{} cases deeper than {APART_TOLERANCE:e} m from apart: {deep:?}",
            deep.len()
        )]
    } else {
        Vec::new()
    }
}

/// Runs every case with `SmoothDispatcher`: the frozen cases' count, the failures of each case
/// ([`failures_of`], and `extra`'s), and the outcomes.
fn run_smooth(
    cases: &[Case],
    extra: impl Fn(&Case, &common::ccd_judge::Outcome) -> Option<String>,
) -> (usize, Vec<String>, Vec<common::ccd_judge::Outcome>) {
    let (mut frozen, mut failures, mut outcomes) = (0, Vec::new(), Vec::new());
    for c in cases {
        let o = run_case(c, Method::Smooth);
        frozen += o.frozen.is_some() as usize;
        failures.extend(failures_of(c, &o));
        failures.extend(extra(c, &o));
        outcomes.push(o);
    }
    (frozen, failures, outcomes)
}

/// Runs every case with `SmoothDispatcher`, prints the count, and asserts no case froze and no
/// case failed otherwise (through, NaN, panic, a centre near a wall, a case deep from apart in a
/// target rapier asked the dispatcher about).
fn no_body_through_nor_frozen(cases: Vec<Case>, setting: &str) {
    let (frozen, mut failures, outcomes) = run_smooth(&cases, |_, _| None);
    failures.extend(asked_failures(&cases, outcomes.iter()));
    println!("{setting}: {} cases, {frozen} frozen", cases.len());
    assert_eq!(frozen, 0, "frozen with {setting}:\n{}", failures.join("\n"));
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Without rapier's CCD (`max_ccd_substeps` 0, no bullet), at 3 m/s with and without spin, this
/// crate's disc (`Ellipse::new(0.2, 0.2)` with `SmoothDispatcher`) follows parry's `Ball` on
/// rapier's default narrow phase to 1e-6 m over every step of every scene of the suite: its
/// manifolds — exact points, core contacts, the composite parts of chains (two-sided and
/// oriented), posts and the stack, the flipper's joint — leave rapier's solver the same work a
/// ball's do. (With the CCD on they
/// part where rapier's sweep stops within its slop, and this crate's cast at the touching time.)
#[test]
fn without_ccd_this_crate_s_disc_follows_parry_s_ball_in_every_scene() {
    let path = |case: &Case, method: Method| {
        let mut scene = common::ccd_scenes::build(case, method);
        for (_, rb) in scene.world.bodies.iter_mut() {
            rb.enable_ccd(false);
        }
        scene.world.params.max_ccd_substeps = 0;
        let body = scene.dynamic[0];
        (0..scene.steps)
            .map(|step| {
                common::ccd_scenes::drive(&mut scene, step);
                scene.world.step(scene.gravity, &());
                scene.world.bodies[body].translation()
            })
            .collect::<Vec<_>>()
    };
    let mut runs = 0;
    for family in Family::ALL {
        // The chain families also with their chains oriented (one-sided, pseudo-normals).
        let chains = matches!(family, Family::ChainBox | Family::ChainTerrain);
        for (spin, oriented_chains) in [(0.0, false), (5.0, false), (0.0, true), (5.0, true)] {
            if oriented_chains && !chains {
                continue;
            }
            let case = Case {
                speed: 3.0,
                spin,
                oriented_chains,
                ..all_cases()
                    .into_iter()
                    .find(|c| c.family == family && c.body == Body::Disc)
                    .expect("a disc case")
            };
            let (ours, parry) = (path(&case, Method::Smooth), path(&case, Method::Rapier));
            let worst = ours
                .iter()
                .zip(&parry)
                .map(|(a, b)| (*a - *b).length())
                .fold(0.0, f64::max);
            let chain = if oriented_chains { ", oriented chains" } else { "" };
            assert!(worst < 1e-6, "{}{chain}: {worst} m from parry's Ball", case.describe());
            runs += 1;
        }
    }
    println!("{runs} scene runs: this crate's disc within 1e-6 m of parry's Ball at every step");
}
