//! Criterion benchmarks, this crate against parry as two functions of one group:
//!
//! * `toi/<class>`: `SmoothDispatcher::cast_shapes_nonlinear` against parry's
//!   `DefaultQueryDispatcher::cast_shapes_nonlinear` on the same shapes, one group per scenario
//!   class of `tests/common/scenarios.rs`, hits and misses separately (a fixed batch of
//!   `support::BATCH` scenarios per class split by this crate's outcome; one iteration runs the
//!   whole batch);
//! * `distance/<class>`: the stationary distance (`distance` when separated, `contact` when
//!   penetrating) against parry's GJK and EPA through the shapes' support maps;
//! * `manifolds/<kind>`: `contact_manifolds` on the exact shapes against parry's manifolds on
//!   its polygonal stand-ins, every pair kind of `support/manifolds.rs` at a resting and a deep
//!   overlap;
//! * `sweep/rounded_polygon-disc`: against parry's Box2D-style `sweep_time_of_impact`, without
//!   spin (where both follow the same path);
//! * `pile/step`: one rapier step of `examples/pile.rs`'s pile, exact shapes with
//!   `SmoothDispatcher` against parry's polygon approximations;
//! * `ccd/resting-sweep`: rapier's CCD sweep (`stop_at_penetration = false`) of three bodies
//!   already in the pile's floor (`scenes::resting_sweeps`, recorded in the pile), the exact
//!   shapes against parry's on its stand-ins;
//! * `rapier-casts/<set>`: rapier's CCD casts of `support/rapier_casts.rs` (this crate's shapes
//!   through `SmoothDispatcher` against the same bodies as parry's shapes through
//!   `sweep_time_of_impact`), starting apart with spins up to π/4 a step and beyond, and in
//!   contact.
//! * `corner/<case>`: the degenerate starts of `support/corner.rs` (a disc centred on a box's
//!   corner and its neighbours), one case per function, parry's own cast beside where it has
//!   the pair.
//!
//! Run with `cargo bench --bench toi` (add a filter such as `-- distance` for one kind). The
//! ratios with the accuracy beside them are printed by `cargo bench --bench ratios`.

mod support;

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use parry2d_f64::math::Pose;
use parry2d_f64::query::{
    sweep_time_of_impact, DefaultQueryDispatcher, PersistentQueryDispatcher, QueryDispatcher, ToiProxy,
};
use parry2d_f64::shape::Ball;
use smooth_ccd2d::SmoothDispatcher;
use std::time::Duration;
use support::scenarios::ScenarioClass;
use support::{split_batch, sweep_of, Case, PolygonDisc, BATCH};

fn short(g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>) {
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
}

fn bench_toi(c: &mut Criterion) {
    let d = SmoothDispatcher::default();
    for class in ScenarioClass::ALL {
        let (hits, misses) = split_batch(class);
        let mut g = c.benchmark_group(format!("toi/{}", class.name()));
        short(&mut g);
        for (label, batch) in [("hits", &hits), ("misses", &misses)] {
            if batch.is_empty() {
                continue;
            }
            let param = format!("{label} ({})", batch.len());
            g.bench_with_input(BenchmarkId::new("ours", &param), batch, |b, batch: &Vec<Case>| {
                b.iter(|| {
                    for case in batch {
                        black_box(case.ours(&d));
                    }
                })
            });
            g.bench_with_input(BenchmarkId::new("parry", &param), batch, |b, batch: &Vec<Case>| {
                b.iter(|| {
                    for case in batch {
                        black_box(case.parry());
                    }
                })
            });
        }
        g.finish();
    }
}

fn bench_distance(c: &mut Criterion) {
    let d = SmoothDispatcher::default();
    for class in ScenarioClass::ALL {
        let cases: Vec<Case> = (0..BATCH as u64).map(|s| Case::new(class, s)).collect();
        let apart: Vec<(&Case, Pose)> = cases.iter().map(|c| (c, c.start_pose())).collect();
        let overlapping: Vec<(&Case, Pose)> = cases
            .iter()
            .filter_map(|c| {
                let mut p = c.start_pose();
                p.translation *= 0.25;
                let r = d.signed_distance(&p, &*c.g1, &*c.g2)?.ok()?;
                (r.distance < 0.0).then_some((c, p))
            })
            .collect();
        let mut g = c.benchmark_group(format!("distance/{}", class.name()));
        short(&mut g);
        for (label, set, penetrating) in [("separated", &apart, false), ("penetrating", &overlapping, true)] {
            let param = format!("{label} ({})", set.len());
            g.bench_function(BenchmarkId::new("ours", &param), |b| {
                b.iter(|| {
                    for (c, p) in set {
                        if penetrating {
                            black_box(d.contact(p, &*c.g1, &*c.g2, 0.0).ok());
                        } else {
                            black_box(d.distance(p, &*c.g1, &*c.g2).ok());
                        }
                    }
                })
            });
            g.bench_function(BenchmarkId::new("parry", &param), |b| {
                b.iter(|| {
                    for (c, p) in set {
                        if penetrating {
                            black_box(DefaultQueryDispatcher.contact(p, &*c.g1, &*c.g2, 0.0).ok());
                        } else {
                            black_box(DefaultQueryDispatcher.distance(p, &*c.g1, &*c.g2).ok());
                        }
                    }
                })
            });
        }
        g.finish();
    }
}

fn bench_manifolds(c: &mut Criterion) {
    use support::manifolds::{kinds, pairs_at, Manifolds, OVERLAPS};
    let d = SmoothDispatcher::default();
    for kind in kinds() {
        let mut g = c.benchmark_group(format!("manifolds/{}", kind.name));
        short(&mut g);
        for (label, depth) in OVERLAPS {
            let set = pairs_at(&kind, depth, &d);
            let param = format!("{label} ({})", set.len());
            // The manifolds are kept between iterations (no allocation). This crate's points
            // are kept too, as rapier keeps a pair's in contact: the dispatcher recomputes every
            // call (`support::manifolds::time_pairs`); parry's are cleared before each call, so
            // that it recomputes them rather than reuse them for an unchanged pose.
            let mut mo: Vec<(Manifolds, _)> = set.iter().map(|_| (Vec::new(), None)).collect();
            g.bench_function(BenchmarkId::new("ours", &param), |b| {
                b.iter(|| {
                    for (p, (m, w)) in set.iter().zip(mo.iter_mut()) {
                        let _ = black_box(d.contact_manifolds(&p.pos12, &*p.g1, &*p.g2, p.prediction(), m, w));
                    }
                })
            });
            let mut mp: Vec<(Manifolds, _)> = set.iter().map(|_| (Vec::new(), None)).collect();
            g.bench_function(BenchmarkId::new("parry-polygons", &param), |b| {
                b.iter(|| {
                    for (p, (m, w)) in set.iter().zip(mp.iter_mut()) {
                        m.iter_mut().for_each(|m| m.clear());
                        let _ = black_box(DefaultQueryDispatcher.contact_manifolds(
                            &p.pos12,
                            &*p.a1,
                            &*p.a2,
                            p.prediction(),
                            m,
                            w,
                        ));
                    }
                })
            });
        }
        g.finish();
    }
}

fn bench_sweep(c: &mut Criterion) {
    let d = SmoothDispatcher::default();
    // The rounded_polygon-ellipse scenarios with the ellipse replaced by the disc of the same
    // area and the spins set to 0 (the sweep interpolates rotations differently).
    let set: Vec<_> = (0..BATCH as u64)
        .filter_map(|seed| {
            let PolygonDisc {
                s,
                poly,
                parry_poly,
                radius: r,
            } = PolygonDisc::new(seed, false)?;
            let (sa, sb) = (sweep_of(&s.motion1, s.t0, s.t1), sweep_of(&s.motion2, s.t0, s.t1));
            let slop = 1e-9 * s.size();
            Some((s, poly, parry_poly, Ball::new(r), sa, sb, slop))
        })
        .collect();
    let mut g = c.benchmark_group("sweep/rounded_polygon-disc");
    short(&mut g);
    let param = format!("no spin ({})", set.len());
    g.bench_function(BenchmarkId::new("ours", &param), |b| {
        b.iter(|| {
            for (s, poly, _, ball, ..) in &set {
                black_box(
                    d.cast_shapes_nonlinear(&s.motion1, poly, &s.motion2, ball, s.t0, s.t1, true)
                        .ok(),
                );
            }
        })
    });
    g.bench_function(BenchmarkId::new("parry-sweep", &param), |b| {
        b.iter(|| {
            for (_, _, parry_poly, ball, sa, sb, slop) in &set {
                let (pa, pb) = (
                    ToiProxy::from_shape(parry_poly).unwrap(),
                    ToiProxy::from_shape(ball).unwrap(),
                );
                black_box(sweep_time_of_impact(&pa, sa, &pb, sb, 1.0, *slop));
            }
        })
    });
    g.finish();
}

fn bench_pile(c: &mut Criterion) {
    let mut g = c.benchmark_group("pile/step");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    for (name, exact) in [("ours", true), ("parry-polygons", false)] {
        // Steps of the first `CYCLE` (the bodies fall, then pile up), restarted every `CYCLE`
        // steps so that no run measures a pile asleep; the rebuilds are not timed.
        const CYCLE: u64 = 400;
        g.bench_function(BenchmarkId::new(name, support::pile::BODIES), |b| {
            b.iter_custom(|iters| {
                let mut total = Duration::ZERO;
                let mut pile = support::pile::Pile::new(exact);
                for i in 0..iters {
                    if i > 0 && i % CYCLE == 0 {
                        pile = support::pile::Pile::new(exact);
                    }
                    let start = std::time::Instant::now();
                    pile.step();
                    total += start.elapsed();
                }
                total
            })
        });
    }
    g.finish();
}

fn bench_resting_sweeps(c: &mut Criterion) {
    use support::resting::pile_polygonal;
    let sweeps = support::scenes::resting_sweeps();
    let exact: Vec<_> = sweeps.iter().map(|s| s.body.shared()).collect();
    let stand_ins: Vec<_> = sweeps.iter().map(|s| pile_polygonal(&s.body)).collect();
    let dt = 1.0 / 60.0;
    let mut g = c.benchmark_group("ccd/resting-sweep");
    short(&mut g);
    let d = SmoothDispatcher::default();
    g.bench_function(BenchmarkId::new("ours", sweeps.len()), |b| {
        b.iter(|| {
            for (s, body) in sweeps.iter().zip(&exact) {
                let _ =
                    black_box(d.cast_shapes_nonlinear(&s.motion, &**body, &s.floor_motion, &s.floor, 0.0, dt, false));
            }
        })
    });
    g.bench_function(BenchmarkId::new("parry-polygons", sweeps.len()), |b| {
        b.iter(|| {
            for (s, body) in sweeps.iter().zip(&stand_ins) {
                let _ = black_box(DefaultQueryDispatcher.cast_shapes_nonlinear(
                    &s.motion,
                    &**body,
                    &s.floor_motion,
                    &s.floor,
                    0.0,
                    dt,
                    false,
                ));
            }
        })
    });
    g.finish();
}

/// rapier's CCD casts (`support::rapier_casts`): per set, every body kind against every target
/// kind, `RAPIER_BATCH` cases each; ours (`SmoothDispatcher::cast_shapes_nonlinear`, rapier's call
/// for this crate's shapes) and parry (`sweep_time_of_impact` with rapier's core-circle retry,
/// rapier's call for parry's shapes) as two functions of one group.
fn bench_rapier_casts(c: &mut Criterion) {
    use support::rapier_casts::{make_case, ours_cast, parry_cast, Body, Set, Target};
    const RAPIER_BATCH: usize = 8;
    let d = SmoothDispatcher::default();
    for (set_index, set) in Set::ALL.into_iter().enumerate() {
        let mut cases = Vec::new();
        for body in Body::ALL {
            for target in Target::ALL {
                for _ in 0..RAPIER_BATCH {
                    // Seeds of their own (the ratios section draws its cases from others).
                    let seed = 0xC417_0000 + (set_index * 1000 + cases.len()) as u64;
                    cases.push(make_case(body, target, set, seed));
                }
            }
        }
        let mut g = c.benchmark_group(format!("rapier-casts/{set:?}"));
        short(&mut g);
        g.bench_function(BenchmarkId::new("ours", cases.len()), |b| {
            b.iter(|| {
                for case in &cases {
                    black_box(ours_cast(case, &d));
                }
            })
        });
        g.bench_function(BenchmarkId::new("parry-sweep", cases.len()), |b| {
            b.iter(|| {
                for case in &cases {
                    black_box(parry_cast(case));
                }
            })
        });
        g.finish();
    }
}

/// The degenerate starts (`support::corner`): one function per case, parry's own cast beside
/// where it has the pair.
fn bench_corner(c: &mut Criterion) {
    let mut g = c.benchmark_group("corner");
    short(&mut g);
    for case in support::corner::cases() {
        g.bench_function(BenchmarkId::new("ours", &case.name), |b| {
            b.iter(|| black_box(case.ours()))
        });
        if case.has_parry() {
            g.bench_function(BenchmarkId::new("parry", &case.name), |b| {
                b.iter(|| black_box(case.parry()))
            });
        }
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default();
    targets = bench_toi, bench_distance, bench_manifolds, bench_sweep, bench_pile, bench_resting_sweeps, bench_rapier_casts, bench_corner
}
criterion_main!(benches);
