//! The CCD scene suite: game-like continuous-collision scenes (segment and chain walls, thin
//! posts, funnels and wedges, slides into a corner, bullets into a stack, a flipper, bouncing
//! boxes, thin walls, plank drops), every shape family of the crate as the moving body, speeds
//! from 10 to 3000 m/s and spins to 600 rad/s (rapier's caps lifted where a case is above them),
//! run headless in rapier2d-f64 with `SmoothDispatcher` and, side by side, with rapier's default
//! narrow phase on parry's closest shapes. Prints one table by family: cases, bodies through a
//! wall, frozen bodies, NaN, panics, the deepest penetration after a CCD-swept step, the deepest
//! after such a step into a fixed target the body was apart from at its start ("apart m"), the
//! least distance from a swept body's centre to a fixed target over its `ccd_thickness`
//! ("centre") and the mean step time (with the ratio, this crate's over rapier's), with the suite's totals over all cases
//! and over the cases neither method fails, then the cases that failed.
//!
//! Run: `cargo run --release --example ccd_scenes` (optionally a family name, dashes for spaces,
//! to run only it, `--no-recycling` to run with rapier's contact recycling off, and
//! `--recycle-distance=D` to set rapier's `normalized_contact_recycle_distance`, 0.05 by default,
//! and `--ccd-hooks` to give the launched CCD bodies' colliders
//! `ActiveHooks::MODIFY_SOLVER_CONTACTS` with no-op hooks, so that rapier never recycles their
//! pairs, and `--rotation-cap-kept` to give `allow_fast_rotation` only to the cases whose spin is
//! above rapier's rotation cap, π/4 a step, not to every case above one of its caps, and
//! `--moving-pairs` to run `SmoothDispatcher`'s steps with this crate's pass for two moving
//! bodies, `MovingPairs`, with its default options, and `--oriented-chains` to build the chain box
//! and the chain terrain as oriented, one-sided polylines).

#[path = "common/mod.rs"]
mod common;

use common::ccd_judge::{run_all, table};
use common::ccd_scenes::{all_cases, Method};

/// The flags the example takes (module docs).
const FLAGS: [&str; 6] = [
    "--no-recycling",
    "--ccd-hooks",
    "--rotation-cap-kept",
    "--moving-pairs",
    "--oriented-chains",
    "--recycle-distance=D",
];

/// Exits with the example's usage: status 0 for `--help`, 2 for a mistake (`why`).
fn usage(why: Option<String>) -> ! {
    let families: Vec<String> = all_cases().iter().map(|c| c.family.name().replace(' ', "-")).collect();
    let mut families = families;
    families.dedup();
    if let Some(why) = &why {
        eprintln!("{why}");
    }
    eprintln!(
        "usage: cargo run --release --example ccd_scenes -- [FAMILY] [{}]\nfamilies: {}",
        FLAGS.join("] ["),
        families.join(", ")
    );
    std::process::exit(if why.is_some() { 2 } else { 0 });
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "--help" || a == "-h") {
        usage(None);
    }
    for a in args.iter().filter(|a| a.starts_with('-')) {
        let known = FLAGS.iter().any(|f| match f.strip_suffix('D') {
            Some(prefix) => a.starts_with(prefix),
            None => a == f,
        });
        if !known {
            usage(Some(format!("unknown option `{a}`")));
        }
    }
    if let Some(f) = args.iter().find(|a| !a.starts_with('-')) {
        if !all_cases().iter().any(|c| c.family.name().replace(' ', "-") == *f) {
            usage(Some(format!("unknown family `{f}`")));
        }
    }
    // `--no-recycling`: rapier's contact recycling off (`IntegrationParameters::contact_recycling`).
    let recycling = !args.iter().any(|a| a == "--no-recycling");
    // `--recycle-distance=D`: rapier's `normalized_contact_recycle_distance` (0.05 by default).
    let recycle_distance = args
        .iter()
        .find_map(|a| a.strip_prefix("--recycle-distance="))
        .map(|d| d.parse::<f64>().expect("--recycle-distance=D, D a number"));
    // `--ccd-hooks`: the CCD bodies' colliders with active (no-op) hooks, never recycled.
    let ccd_hooks = args.iter().any(|a| a == "--ccd-hooks");
    // `--rotation-cap-kept`: `allow_fast_rotation` only on the cases whose spin is above π/4 a step.
    let rotation_cap_kept = args.iter().any(|a| a == "--rotation-cap-kept");
    // `--moving-pairs`: this crate's pass `MovingPairs` around `SmoothDispatcher`'s steps.
    let moving_pairs = args.iter().any(|a| a == "--moving-pairs");
    // `--oriented-chains`: the chain box and the chain terrain as oriented (one-sided) polylines.
    let oriented_chains = args.iter().any(|a| a == "--oriented-chains");
    let filter = args.iter().find(|a| !a.starts_with("--"));
    let cases: Vec<_> = all_cases()
        .into_iter()
        .filter(|c| filter.is_none_or(|f| c.family.name().replace(' ', "-") == *f))
        .map(|c| common::ccd_scenes::Case {
            recycling,
            recycle_distance,
            ccd_hooks,
            rotation_cap_kept,
            moving_pairs,
            oriented_chains,
            ..c
        })
        .collect();
    let t = std::time::Instant::now();
    let outcomes = run_all(&cases);
    println!(
        "CCD scene suite: {} cases, dt = 1/60 s; rapier's caps lifted in {} of them (speed > 400 m/s or spin > 47 rad/s){}; contact recycling {}{}{}",
        cases.len(),
        cases.iter().filter(|c| c.lifted()).count(),
        if rotation_cap_kept {
            ", its rotation cap only in the cases spinning above it"
        } else {
            ""
        },
        match (recycling, recycle_distance) {
            (false, _) => "off".to_string(),
            (true, None) => "on (rapier's default)".to_string(),
            (true, Some(d)) => format!("on, recycle distance {d}"),
        },
        if ccd_hooks {
            "; the CCD bodies' colliders with active hooks (their pairs never recycled)"
        } else {
            ""
        },
        if moving_pairs {
            "; SmoothDispatcher's steps with the pass MovingPairs (default options)"
        } else {
            ""
        }
    );
    print!("{}", table(&cases, &outcomes));
    // The *apart* column split: targets rapier asked the dispatcher to cast (its answers) and
    // targets rapier never asked about (its candidate search), for `SmoothDispatcher`.
    let asked = outcomes.iter().map(|o| o[0].asked_apart_deepest).fold(0.0, f64::max);
    let unasked: Vec<String> = cases
        .iter()
        .zip(&outcomes)
        .filter(|(_, o)| o[0].apart_deepest > 1e-9 && o[0].asked_apart_deepest <= 1e-9)
        .map(|(c, o)| format!("{}: {:.3e} m", c.describe(), o[0].apart_deepest))
        .collect();
    println!(
        "SmoothDispatcher, apart at a step's start: deepest after it {asked:.3e} m in a target rapier asked the dispatcher \
         about; deeper than 1e-9 m in a target rapier never asked about: {unasked:?}"
    );
    for (k, m) in Method::BOTH.iter().enumerate() {
        let only = std::env::var("ONLY").ok();
        let failed: Vec<_> = cases
            .iter()
            .zip(&outcomes)
            .filter(|(c, o)| o[k].failed() && only.as_deref().is_none_or(|s| format!("{} {}", c.spin, c.speed) == s))
            .collect();
        println!("{}: {} cases failed", m.name(), failed.len());
        let limit: usize = std::env::var("LIMIT").ok().and_then(|s| s.parse().ok()).unwrap_or(40);
        for (c, o) in failed.iter().take(if k == 0 { limit } else { 8 }) {
            let o = &o[k];
            println!(
                "  {:<18} {:<16} {:>6} m/s {:>5} rad/s: through {:?} frozen {:?} nan {:?} panic {:?}",
                c.family.name(),
                c.body.name(),
                c.speed,
                c.spin,
                o.through,
                o.frozen,
                o.nan,
                o.panicked
            );
        }
    }
    if std::env::var("BREAKDOWN").is_ok() {
        for spin in common::ccd_scenes::SPINS {
            for speed in common::ccd_scenes::SPEEDS {
                let sel: Vec<_> = cases
                    .iter()
                    .zip(&outcomes)
                    .filter(|(c, _)| c.spin == spin && c.speed == speed)
                    .collect();
                let th = sel.iter().filter(|(_, o)| o[0].through.is_some()).count();
                let fr = sel.iter().filter(|(_, o)| o[0].frozen.is_some()).count();
                let thr = sel.iter().filter(|(_, o)| o[1].through.is_some()).count();
                println!("spin {spin:6} speed {speed:6}: smooth through {th:3} frozen {fr:3} | rapier through {thr:3}");
            }
        }
        for body in common::ccd_scenes::Body::ALL {
            let sel: Vec<_> = cases.iter().zip(&outcomes).filter(|(c, _)| c.body == body).collect();
            let th = sel.iter().filter(|(_, o)| o[0].through.is_some()).count();
            let fr = sel.iter().filter(|(_, o)| o[0].frozen.is_some()).count();
            let thr = sel.iter().filter(|(_, o)| o[1].through.is_some()).count();
            println!(
                "{:16}: smooth through {th:3} frozen {fr:3} | rapier through {thr:3}",
                body.name()
            );
        }
    }
    println!("({:.1} s)", t.elapsed().as_secs_f64());
}
