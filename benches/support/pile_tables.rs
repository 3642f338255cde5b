//! The pile's tables of `cargo bench --bench ratios -- pile`: the step against parry's
//! stand-ins ([`pile_table`]), where a step goes (the dispatcher's calls and rapier's CCD casts
//! timed in the simulation, [`pile_call_table`]; rapier's stage timers, [`pile_stage_table`]) and
//! the step with a free dispatcher ([`pile_bound_table`], `-- pile-bound`).

pub fn pile_table() {
    use super::pile::{Pile, BODIES};
    use std::time::Instant;
    const STEPS: usize = 400;
    const EARLY: usize = 200;
    println!("\n## rapier: one step of the pile\n");
    println!(
        "`examples/pile.rs`'s {BODIES} bodies (ellipses, rounded polygons, `CapsuleEllipse`s) dropped into a box, {STEPS} steps of 1/60 s from the start (falling, then piling up; the exact pile falls asleep after about 330 steps, parry's does not, so the first {EARLY} steps are also shown). Ours: the exact shapes with `SmoothDispatcher` (warm start on or off); parry: ellipses and `CapsuleEllipse`s as inscribed {}-gons, rounded polygons as `RoundConvexPolygon`, parry's default dispatcher. rapier's contact recycling (`IntegrationParameters::contact_recycling`) on and off. The best of 3 runs.\n",
        super::POLYGON_VERTICES
    );
    println!("| contact recycling | narrow phase | mean step ms | mean of the first {EARLY} steps ms | max step ms | touching pairs at the end |");
    println!("|---|---|---:|---:|---:|---:|");
    for recycling in [true, false] {
        let mut means = [0.0; 3];
        let mut early = [0.0; 3];
        for (i, (label, exact, warm)) in [
            ("SmoothDispatcher, exact shapes", true, true),
            ("SmoothDispatcher, exact shapes, no warm start", true, false),
            ("parry, polygon approximations", false, false),
        ]
        .into_iter()
        .enumerate()
        {
            let (mut best_mean, mut best_early, mut best_max, mut touching) = (f64::INFINITY, f64::INFINITY, 0.0, 0);
            for _ in 0..3 {
                let mut pile = Pile::with(exact, recycling, warm);
                let (mut total, mut first, mut worst) = (0.0f64, 0.0f64, 0.0f64);
                for k in 0..STEPS {
                    let st = Instant::now();
                    pile.step();
                    let el = st.elapsed().as_secs_f64();
                    total += el;
                    if k < EARLY {
                        first += el;
                    }
                    worst = worst.max(el);
                }
                best_early = best_early.min(first / EARLY as f64);
                if total / (STEPS as f64) < best_mean {
                    best_mean = total / STEPS as f64;
                    best_max = worst;
                    touching = pile.touching_pairs();
                }
            }
            means[i] = best_mean;
            early[i] = best_early;
            println!(
                "| {} | {label} | {:.3} | {:.3} | {:.3} | {touching} |",
                if recycling { "on" } else { "off" },
                best_mean * 1e3,
                best_early * 1e3,
                best_max * 1e3
            );
        }
        println!(
            "\nRecycling {}: ratio parry / ours of the mean step {:.2} (first {EARLY} steps {:.2}); warm start off / on {:.2}.\n",
            if recycling { "on" } else { "off" },
            means[2] / means[0],
            early[2] / early[0],
            means[1] / means[0]
        );
    }
}

/// The pile's step with the narrow phase's answers handed back from a recording (see
/// `super::replay`): what the step would cost were this crate's dispatcher free, against
/// parry's pile as in [`pile_table`].
pub fn pile_bound_table() {
    use super::pile::Pile;
    use super::replay::replayed_pile;
    use std::time::Instant;
    const STEPS: usize = 400;
    const RUNS: usize = 3;
    println!("\n## rapier: the pile's step with a free narrow phase\n");
    println!(
        "The exact pile's first {STEPS} steps run with `SmoothDispatcher` (the best of {RUNS} runs), once more with its answers recorded (`contact_manifolds`, and `cast_shapes_nonlinear` for rapier's CCD), and then {RUNS} times with the recorded answers handed back in call order (the run is deterministic: the recording and every replay must end in the plain run's state, bit for bit); parry's pile as in the table above, the best of {RUNS} runs. The replayed step is what rapier spends on this pile besides the dispatcher, the bound on the step of any dispatcher giving these answers.\n"
    );
    println!("| contact recycling | exact pile, mean step ms | exact pile replayed, mean step ms | replays end in the plain run's state | parry's pile, mean step ms | ratio parry / exact | ratio parry / replayed (the bound) |");
    println!("|---|---:|---:|---|---:|---:|---:|");
    for recycling in [true, false] {
        let (replayed, same) = replayed_pile(recycling, STEPS, RUNS);
        let mean_step = |exact: bool| {
            let mut best = f64::INFINITY;
            for _ in 0..RUNS {
                let mut pile = Pile::with(exact, recycling, true);
                let start = Instant::now();
                for _ in 0..STEPS {
                    pile.step();
                }
                best = best.min(start.elapsed().as_secs_f64() / STEPS as f64);
            }
            best
        };
        let (ours, parry) = (mean_step(true), mean_step(false));
        println!(
            "| {} | {:.3} | {:.3} | {} | {:.3} | {:.2} | {:.2} |",
            if recycling { "on" } else { "off" },
            ours * 1e3,
            replayed * 1e3,
            if same { "yes" } else { "**no**" },
            parry * 1e3,
            parry / ours,
            parry / replayed
        );
    }
}

/// Where a step of the pile goes, from rapier's stage timers (a build with rapier's `profiler`
/// feature: `cargo bench --bench ratios --features rapier2d-f64/profiler -- pile`): the mean
/// over the first `STEPS` steps of the step, the narrow phase, the solver, the update of the
/// colliders and the rest, for each narrow phase, with rapier's contact recycling on and off.
pub fn pile_stage_table() {
    use super::pile::Pile;
    const STEPS: usize = 400;
    println!("\n### Where a step of the pile goes\n");
    pile_call_table(STEPS);
    // rapier's timers read zero without its `profiler` feature.
    let mut probe = Pile::with(true, true, true).with_counters();
    probe.step();
    if probe.stage_ms()[0] == 0.0 {
        println!("\n(rapier's stage timers are off: run `cargo bench --bench ratios --features rapier2d-f64/profiler -- pile` to see them.)");
        return;
    }
    let mut rows = vec![];
    for recycling in [true, false] {
        for exact in [true, false] {
            let mut best = [f64::INFINITY; 4];
            for _ in 0..3 {
                let mut pile = Pile::with(exact, recycling, true).with_counters();
                let mut sum = [0.0f64; 4];
                for _ in 0..STEPS {
                    pile.step();
                    sum.iter_mut()
                        .zip(pile.stage_ms())
                        .for_each(|(s, t)| *s += t / STEPS as f64);
                }
                if sum[0] < best[0] {
                    best = sum;
                }
            }
            rows.push((recycling, exact, best));
        }
    }
    println!(
        "\nrapier's stage timers (`PhysicsPipeline::counters`, rapier's `profiler` feature), mean over the first {STEPS} steps, the best of 3 runs; these runs have the counters on (a statistics pass per step), so their step times are not the table above's.\n"
    );
    println!(
        "| contact recycling | narrow phase | step ms | narrow phase ms | solver ms | collider update ms | rest ms |"
    );
    println!("|---|---|---:|---:|---:|---:|---:|");
    for (recycling, exact, t) in &rows {
        println!(
            "| {} | {} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} |",
            if *recycling { "on" } else { "off" },
            if *exact {
                "SmoothDispatcher, exact shapes"
            } else {
                "parry, polygon approximations"
            },
            t[0],
            t[1],
            t[2],
            t[3],
            t[0] - t[1] - t[2] - t[3]
        );
    }
    for pair in rows.chunks(2) {
        let (ours, parry) = (pair[0].2, pair[1].2);
        println!(
            "\nRecycling {}: ratio parry / ours of the step {:.2}, of the narrow phase {:.2}, of the solver {:.2}.",
            if pair[0].0 { "on" } else { "off" },
            parry[0] / ours[0],
            parry[1] / ours[1],
            parry[2] / ours[2]
        );
    }
}

/// The dispatcher's `contact_manifolds` calls in the pile over its first `steps` steps, by pair
/// kind: calls per step, time per call inside the simulation (the shapes and manifolds of many
/// pairs in turn, not one pair's in a loop) and per step, points per call; then rapier's CCD
/// casts (`cast_shapes_nonlinear`), their number, mean and longest time.
pub fn pile_call_table(steps: usize) {
    use super::pile::{CallStats, Pile};
    use std::sync::{Arc, Mutex};
    println!(
        "The dispatcher's `contact_manifolds` calls over the first {steps} steps, by pair kind (one run; each call's time includes a pair of clock readings, about 50 ns here, and follows the timer's own bookkeeping: `-- pile-calls` times the same calls without either):\n"
    );
    println!("| contact recycling | narrow phase | pair kind | calls per step | µs per call | ms per step | points per call |");
    println!("|---|---|---|---:|---:|---:|---:|");
    let mut runs: Vec<(String, CallStats)> = Vec::new();
    for recycling in [true, false] {
        for exact in [true, false] {
            let stats = Arc::new(Mutex::new(CallStats::default()));
            let mut pile = Pile::timed(exact, recycling, &stats);
            for _ in 0..steps {
                pile.step();
            }
            let stats = std::mem::take(&mut *stats.lock().unwrap_or_else(|e| e.into_inner()));
            let mut total = (0u64, 0.0f64);
            let label = if exact {
                "SmoothDispatcher, exact shapes"
            } else {
                "parry, polygon approximations"
            };
            let on = if recycling { "on" } else { "off" };
            for (kind, &(calls, seconds, points)) in stats.manifolds.iter() {
                total = (total.0 + calls, total.1 + seconds);
                println!(
                    "| {on} | {label} | {kind} | {:.1} | {:.2} | {:.4} | {:.2} |",
                    calls as f64 / steps as f64,
                    seconds / calls as f64 * 1e6,
                    seconds / steps as f64 * 1e3,
                    points as f64 / calls as f64
                );
            }
            println!(
                "| {on} | {label} | **all** | {:.1} | {:.2} | {:.4} | |",
                total.0 as f64 / steps as f64,
                total.1 / total.0.max(1) as f64 * 1e6,
                total.1 / steps as f64 * 1e3
            );
            runs.push((format!("| {on} | {label} |"), stats));
        }
    }
    println!(
        "\nrapier's CCD casts (`cast_shapes_nonlinear`: rapier sweeps the pile's fast bodies whether or not their CCD flag is set) in the same runs:\n"
    );
    println!("| contact recycling | narrow phase | pair kind | casts | mean µs | longest µs | ms per step |");
    println!("|---|---|---|---:|---:|---:|---:|");
    for (row, stats) in &runs {
        for (kind, &(casts, seconds, longest)) in stats.casts.iter() {
            println!(
                "{row} {kind} | {casts} | {:.2} | {:.2} | {:.4} |",
                seconds / casts as f64 * 1e6,
                longest * 1e6,
                seconds / steps as f64 * 1e3
            );
        }
    }
}
