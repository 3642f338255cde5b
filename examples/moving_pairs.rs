//! Issue 30's scenes, headless: two bodies that both move fast, with the moving-pairs pass
//! (`MovingPairs` around `PhysicsPipeline::step`) and with rapier alone (the same world and
//! dispatcher, the pass left out). rapier's CCD never sweeps a bullet against another bullet,
//! and sweeps a bullet against a moving body held at its end-of-step pose.
//!
//! Prints the head-on table (two bullets at 100–3000 m/s each, spins to 600 rad/s, equal and
//! unequal sizes, every shape family of the crate and parry's own shapes; momentum and energy
//! before and after, without hooks, with `CoreContactHooks` and with `OneBounceHooks`), the crossing and plank tables, the closed box of 50 fast bouncing bodies
//! over 10 s (pairs through each other, bodies out, NaN, panics, the pass's share of the step),
//! and two summary lines, `head-on: …` and `box: …`, the pass's figure first.
//!
//! `cargo run --release --example moving_pairs` (a few minutes: the box runs five times); `-- --shots` prints
//! every head-on shot; `-- --seed=N` launches the box's bodies from the random sequence of N (the
//! default: `BOX_SEED`); `-- --box` runs only the box (its table and its summary line).

#[path = "common/mod.rs"]
mod common;

use common::moving_pairs::{Hooks, Launch, Verdicts};
use common::moving_scenes::{
    crossing_shots, head_on_pairs, head_on_shots, pass_options, pile_cost, plank_shots, run_box_seeded, run_shot,
    run_shot_with, wall_bounce_energy, BoxResult, PlankWay, ShotResult, BOX_BODIES, BOX_SEED, BOX_STEPS, HEAD_ON_STEPS,
    SLOW_SPEED, SLOW_STEPS,
};
use std::time::Instant;

/// Steps of the pile's cost measurement.
const PILE_STEPS: usize = 600;

/// A shot with the pass and with rapier alone.
struct Both {
    pass: ShotResult,
    alone: ShotResult,
}

fn both(launches: &[Launch], steps: usize, friction: f64) -> Both {
    Both {
        pass: run_shot(launches, steps, friction, Some(pass_options())),
        alone: run_shot(launches, steps, friction, None),
    }
}

/// E after over E before, and |Δp| over Σ m|v| before.
fn conservation(r: &ShotResult, launches: &[Launch]) -> (f64, f64) {
    let _ = launches;
    let scale = r.e0.max(f64::MIN_POSITIVE);
    (r.e1 / scale, (r.p1 - r.p0).length())
}

fn main() {
    let every_shot = std::env::args().any(|a| a == "--shots");
    let box_only = std::env::args().any(|a| a == "--box");
    let seed = std::env::args()
        .find_map(|a| {
            a.strip_prefix("--seed=")
                .map(|n| n.parse::<u64>().expect("--seed=N: N a number"))
        })
        .unwrap_or(BOX_SEED);
    let t = Instant::now();
    let head = (!box_only).then(|| {
        let head = head_on(every_shot);
        other_scenes();
        head
    });
    let boxes = the_box(seed);
    if !box_only {
        pile_table(&boxes[0]);
    }
    println!();
    println!("(ran in {:.1} s)", t.elapsed().as_secs_f64());
    if let Some(head) = head {
        println!("{head}");
    }
    box_summary(&boxes);
}

/// The largest energy ratio, the shots that gained, passed through or went NaN of one column.
#[derive(Clone, Copy, Debug, Default)]
struct Column {
    worst: f64,
    gained: usize,
    through: usize,
    nan: usize,
}

impl Column {
    fn add(&mut self, r: &ShotResult) {
        self.worst = self.worst.max(r.e1 / r.e0.max(f64::MIN_POSITIVE));
        self.gained += usize::from(gains(r));
        self.through += usize::from(r.through());
        self.nan += usize::from(!r.finite);
    }
}

/// The head-on table's columns over every shot: the pass, with each hooks, slowed; and the
/// shots where the pass gained while the slowed shot did not.
#[derive(Clone, Copy, Debug, Default)]
struct Tally {
    pass: Column,
    alone: Column,
    core: Column,
    one: Column,
    slowed: Column,
    pass_only: usize,
}

/// The head-on table, its notes and the wall reference; returns the summary line.
fn head_on(every_shot: bool) -> String {
    let shots = head_on_shots();
    let results: Vec<Both> = shots.iter().map(|s| both(&s.launches(), HEAD_ON_STEPS, 0.5)).collect();
    // The same shots with `CoreContactHooks` (no bounce on the core contacts), and with
    // `OneBounceHooks` (and one bouncing row per impact).
    let with_hooks = |hooks: Hooks| -> Vec<ShotResult> {
        shots
            .iter()
            .map(|s| run_shot_with(&s.launches(), HEAD_ON_STEPS, 0.5, Some(pass_options()), hooks))
            .collect()
    };
    let (core, one) = (with_hooks(Hooks::Core), with_hooks(Hooks::OneBounce));
    // The same shots slowed to 1 m/s in rapier alone: the collision as rapier's solver resolves
    // it without any CCD (the reference for the energy).
    let slowed: Vec<ShotResult> = shots
        .iter()
        .map(|s| run_shot(&s.slowed().launches(), SLOW_STEPS, 0.5, None))
        .collect();
    println!(
        "Head-on: two bullets (CCD on) shot at each other from 6 m apart, {HEAD_ON_STEPS} steps of 1/60 s, \
         restitution 1, friction 0.5, rapier's caps lifted; speeds 100/300/1000/3000 m/s each, spins \
         0/0, 150/-90, -600/600 rad/s, the second body at scale 1 and 0.4 ({} shots)",
        shots.len()
    );
    println!(
        "{:<34} {:>5} {:>12} {:>12} {:>14} {:>12} {:>12} {:>14} {:>12}",
        "pair",
        "shots",
        "through/pass",
        "through/alone",
        "max E1/E0 pass",
        "core hooks",
        "one bounce",
        "E1/E0 slowed",
        "max |Δp| pass"
    );
    let mut all = Tally::default();
    for (a, b) in head_on_pairs() {
        let mut row = Tally::default();
        let mut p = 0.0f64;
        for i in (0..shots.len()).filter(|i| shots[*i].a == a && shots[*i].b == b) {
            let r = &results[i];
            p = p.max(conservation(&r.pass, &shots[i].launches()).1);
            for t in [&mut row, &mut all] {
                t.pass.add(&r.pass);
                t.alone.add(&r.alone);
                t.core.add(&core[i]);
                t.one.add(&one[i]);
                t.slowed.add(&slowed[i]);
                t.pass_only += usize::from(gains(&r.pass) && !gains(&slowed[i]));
            }
        }
        println!(
            "{:<34} {:>5} {:>12} {:>12} {:>14.9} {:>12.9} {:>12.9} {:>14.9} {:>12.2e}",
            format!("{} / {}", a.name(), b.name()),
            shots.iter().filter(|s| s.a == a && s.b == b).count(),
            row.pass.through,
            row.alone.through,
            row.pass.worst,
            row.core.worst,
            row.one.worst,
            row.slowed.worst,
            p
        );
    }
    if every_shot {
        for (s, r) in shots.iter().zip(&results) {
            println!(
                "  {:?}: pass {} (E {:.6e} -> {:.6e}, p ({:.3e}, {:.3e}) -> ({:.3e}, {:.3e})), alone {}",
                s,
                r.pass.through(),
                r.pass.e0,
                r.pass.e1,
                r.pass.p0.x,
                r.pass.p0.y,
                r.pass.p1.x,
                r.pass.p1.y,
                r.alone.through()
            );
        }
    }
    head_on_notes(&all, shots.len());
    let Tally {
        pass,
        alone,
        core,
        one,
        slowed,
        pass_only,
    } = all;
    format!(
        "head-on: {} through of {} shots with the pass (energy gained in {}, largest E after/before {:.6}, in \
         {pass_only} where the slowed shot gained none; with CoreContactHooks in {}, largest {:.6}; with \
         OneBounceHooks in {}, largest {:.9}, through {}; NaN in {}); rapier alone: {} through of {} (slowed to \
         {SLOW_SPEED} m/s: energy gained in {}, largest {:.6})",
        pass.through,
        shots.len(),
        pass.gained,
        pass.worst,
        core.gained,
        core.worst,
        one.gained,
        one.worst,
        one.through,
        pass.nan,
        alone.through,
        shots.len(),
        slowed.gained,
        slowed.worst
    )
}

/// The notes under the head-on table, and the wall reference.
fn head_on_notes(all: &Tally, shots: usize) {
    println!(
        "(E1/E0: kinetic energy after over before; slowed: the same shots at {SLOW_SPEED} m/s, spins scaled alike, \
         in rapier alone, which needs no CCD there — rapier's solver on the same collision. A gain is rapier's \
         restitution on a contact of two rows (Box2D's: each point that pushed gets the bounce of its own \
         approach velocity): two points where flat sides meet, or the exact point and a core contact \
         (docs/rapier.md); the pass keeps every velocity)"
    );
    let (core, one) = (all.core, all.one);
    println!(
        "(core hooks: the pass with `CoreContactHooks` installed, restitution 0 on the core contacts' manifolds: \
         energy gained in {} of {shots} shots, largest {:.6}, through {}; one bounce: the pass with \
         `OneBounceHooks`, also the two points of an impact merged into one row: energy gained in {}, largest \
         {:.9}, through {}, NaN in {}; a gain is E1 > E0 (1 + 1e-9))",
        core.gained, core.worst, core.through, one.gained, one.worst, one.through, one.nan
    );
    let (wall_gained, wall_shots, wall_worst) = wall_bounce_energy(Hooks::None);
    let (wall_gained_one, _, wall_worst_one) = wall_bounce_energy(Hooks::OneBounce);
    println!(
        "(rapier's own CCD, a bullet of every family at a fixed wall, the same speeds and spins, restitution 1: \
         energy gained in {wall_gained} of {wall_shots} shots, largest {wall_worst:.6}; with `OneBounceHooks` in \
         {wall_gained_one}, largest {wall_worst_one:.9})"
    );
}

/// The crossing and plank table.
fn other_scenes() {
    let crossings = crossing_shots();
    let crossing: Vec<Both> = crossings.iter().map(|s| both(&s.launches(), 20, 0.5)).collect();
    let planks = plank_shots();
    let plank: Vec<Both> = planks.iter().map(|s| both(&s.launches(), 20, 0.5)).collect();
    println!();
    println!(
        "{:<52} {:>5} {:>12} {:>12}",
        "other scenes (20 steps each)", "shots", "through/pass", "through/alone"
    );
    let count = |v: &[Both], f: &dyn Fn(usize) -> bool| {
        let rows: Vec<&Both> = v.iter().enumerate().filter(|(i, _)| f(*i)).map(|(_, r)| r).collect();
        (
            rows.len(),
            rows.iter().filter(|r| r.pass.through()).count(),
            rows.iter().filter(|r| r.alone.through()).count(),
        )
    };
    for &angle in &common::moving_scenes::CROSSING_ANGLES {
        let (n, p, a) = count(&crossing, &|i| crossings[i].angle == angle);
        println!(
            "{:<52} {n:>5} {p:>12} {a:>12}",
            format!("a bullet crossing another's path at {angle}°")
        );
    }
    for way in [PlankWay::EdgeOn, PlankWay::Broadside] {
        let (n, p, a) = count(&plank, &|i| planks[i].way == way);
        let what = match way {
            PlankWay::EdgeOn => "a bullet at a fast dynamic plank, edge-on",
            PlankWay::Broadside => "a bullet at a fast dynamic plank, broadside",
        };
        println!("{what:<52} {n:>5} {p:>12} {a:>12}");
    }
}

/// The box's table: with the pass and rapier alone, with `CoreContactHooks`, without hooks, and
/// with the pass and `OneBounceHooks` (in that order); the bodies launched from `seed`.
fn the_box(seed: u64) -> [BoxResult; 5] {
    let run = |options, hooks| run_box_seeded(seed, BOX_STEPS, options, hooks, &|_| {});
    let boxes = [
        run(Some(pass_options()), Hooks::Core),
        run(None, Hooks::Core),
        run(Some(pass_options()), Hooks::None),
        run(None, Hooks::None),
        run(Some(pass_options()), Hooks::OneBounce),
    ];
    println!();
    println!(
        "The closed box: {BOX_BODIES} bullets of every family (50–250 m/s, spins to ±300 rad/s), restitution 1, \
         no friction, {BOX_STEPS} steps (10 s), seed {seed}; with CoreContactHooks (as docs/rapier.md advises for \
         bouncing bodies), without them, and with OneBounceHooks"
    );
    println!(
        "{:<27} {:>8} {:>10} {:>8} {:>4} {:>4} {:>4} {:>6} {:>9} {:>10} {:>10} {:>7} {:>7} {:>6}",
        "",
        "through",
        "in contact",
        "grazing",
        "out",
        "wall",
        "NaN",
        "panic",
        "E1/E0",
        "step ms",
        "pass ms",
        "share",
        "stops",
        "casts"
    );
    let names = [
        "with the pass",
        "rapier alone",
        "with the pass, no hooks",
        "rapier alone, no hooks",
        "with the pass, one bounce",
    ];
    for (name, r) in names.iter().zip(&boxes) {
        box_row(name, r);
    }
    println!(
        "(through: centre vector reversed within a step, d(k+1)·d(k) < 0, apart at both ends, the centres' \
         path within the sum of the inradii; grazing: within the bounding radii only, near misses included; out: a \
         centre beyond a wall's outer face; wall: a centre past a wall's inner face)"
    );
    boxes
}

/// The cost where no pair is fast (the mixed pile), and the box's (`with`: the box with the pass).
fn pile_table(with: &BoxResult) {
    let pile = pile_cost(PILE_STEPS);
    println!();
    println!(
        "The pass's cost: the mixed pile (150 bodies, half of them bullets, dropped on the ground), {} steps",
        pile.steps
    );
    println!(
        "{:<20} {:>6} {:>10} {:>10} {:>7} {:>8}",
        "steps of", "steps", "step ms", "pass ms", "share", "casts"
    );
    for (k, what) in ["pile, no fast body", "pile, fast bodies"].iter().enumerate() {
        let (step, pass) = (pile.step_time[k].as_secs_f64(), pile.pass_time[k].as_secs_f64());
        let steps = if k == 0 {
            pile.steps - pile.steps_with_fast
        } else {
            pile.steps_with_fast
        };
        println!(
            "{what:<20} {:>6} {:>10.1} {:>10.2} {:>6.2}% {:>8}",
            steps,
            step * 1e3,
            pass * 1e3,
            100.0 * pass / step.max(f64::MIN_POSITIVE),
            if k == 0 { 0 } else { pile.casts }
        );
    }
    println!(
        "{:<20} {:>6} {:>10.1} {:>10.2} {:>6.1}% {:>8}",
        "the closed box",
        BOX_STEPS,
        with.step_time.as_secs_f64() * 1e3,
        with.pass_time.as_secs_f64() * 1e3,
        share(with),
        with.totals.casts
    );
}

/// The `box: …` summary line (the boxes of [`the_box`]).
fn box_summary(boxes: &[BoxResult; 5]) {
    let [with, alone, with_plain, alone_plain, with_one] = boxes;
    println!(
        "box: {} pairs through with the pass ({} bodies out of the box, {} into a wall, NaN {}, panic {}; the pass \
         {:.1} % of the step); rapier alone: {} pairs through ({} out, {} into a wall, NaN {}, panic {}); without \
         CoreContactHooks: {} through and {} out with the pass, {} and {} alone; with OneBounceHooks: {} through, {} \
         out, {} into a wall, NaN {}, panic {}",
        with.verdicts.through,
        with.out_of_box,
        with.in_wall,
        yes(with.nan),
        yes(with.panicked),
        share(with),
        alone.verdicts.through,
        alone.out_of_box,
        alone.in_wall,
        yes(alone.nan),
        yes(alone.panicked),
        with_plain.verdicts.through,
        with_plain.out_of_box,
        alone_plain.verdicts.through,
        alone_plain.out_of_box,
        with_one.verdicts.through,
        with_one.out_of_box,
        with_one.in_wall,
        yes(with_one.nan),
        yes(with_one.panicked)
    );
}

/// Whether a shot ended with more kinetic energy than it started with (beyond rounding).
fn gains(r: &ShotResult) -> bool {
    r.e1 > r.e0 * (1.0 + 1e-9)
}

fn yes(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}

/// The pass's time over the step's (percent).
fn share(r: &BoxResult) -> f64 {
    100.0 * r.pass_time.as_secs_f64() / r.step_time.as_secs_f64().max(f64::MIN_POSITIVE)
}

fn box_row(name: &str, r: &BoxResult) {
    let Verdicts {
        through,
        crossed_in_contact,
        grazing,
    } = r.verdicts;
    println!(
        "{name:<27} {through:>8} {crossed_in_contact:>10} {grazing:>8} {:>4} {:>4} {:>4} {:>6} {:>9.3e} {:>10.1} {:>10.1} {:>6.1}% {:>7} {:>6}",
        r.out_of_box,
        r.in_wall,
        yes(r.nan),
        yes(r.panicked),
        r.energy_ratio,
        r.step_time.as_secs_f64() * 1e3,
        r.pass_time.as_secs_f64() * 1e3,
        share(r),
        r.totals.stopped_bodies,
        r.totals.casts
    );
}
