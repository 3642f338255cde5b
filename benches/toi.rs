//! Criterion benchmarks: this crate's `SmoothDispatcher::cast_shapes_nonlinear` against parry's
//! `DefaultQueryDispatcher::cast_shapes_nonlinear` on the same shapes, one group per scenario
//! class of `tests/common/scenarios.rs`, hits and misses separately (a fixed batch of
//! `support::BATCH` scenarios per class split by this crate's outcome; one iteration runs the
//! whole batch). A last group compares the stationary distance on ellipse pairs (with this
//! crate's curve API, which also computes the penetration depth, as a third function).
//!
//! Run with `cargo bench --bench toi`.

#[path = "../tests/common/mod.rs"]
#[allow(unused_imports)]
mod common;
mod support;

use common::{generate, ScenarioClass, TestShape};
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use parry2d_f64::math::Pose;
use parry2d_f64::query::{DefaultQueryDispatcher, QueryDispatcher};
use parry2d_f64::shape::Shape;
use smooth_ccd2d::{stationary_distance, DistanceOptions, Ellipse, SmoothDispatcher};
use std::time::Duration;
use support::{split_batch, Case, BATCH};

fn bench_toi(c: &mut Criterion) {
    let d = SmoothDispatcher::default();
    for class in ScenarioClass::ALL {
        let (hits, misses) = split_batch(class);
        let mut g = c.benchmark_group(format!("toi/{}", class.name()));
        g.sample_size(10)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
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

/// Ellipse pairs of the `EllipseEllipse` batch: the pose of shape 2 in shape 1's frame at the
/// window start (separated), and the same pose with the centres brought to a quarter of their
/// distance, kept where that overlaps (penetrating).
type PosePair = (Pose, Box<dyn Shape>, Box<dyn Shape>);

fn ellipse_pairs() -> (Vec<PosePair>, Vec<PosePair>) {
    let d = SmoothDispatcher::default();
    let (mut apart, mut overlapping) = (Vec::new(), Vec::new());
    for seed in 0..BATCH as u64 {
        let s = generate(ScenarioClass::EllipseEllipse, seed);
        let (TestShape::Ellipse(e1), TestShape::Ellipse(e2)) = (&s.shape1, &s.shape2) else {
            continue;
        };
        let pos12 = s.motion1.position_at_time(s.t0).inverse() * s.motion2.position_at_time(s.t0);
        apart.push((pos12, Box::new(*e1) as Box<dyn Shape>, Box::new(*e2) as Box<dyn Shape>));
        let mut close = pos12;
        close.translation *= 0.25;
        if let Some(Ok(r)) = d.signed_distance(&close, e1, e2) {
            if r.distance < 0.0 {
                overlapping.push((close, Box::new(*e1) as Box<dyn Shape>, Box::new(*e2) as Box<dyn Shape>));
            }
        }
    }
    (apart, overlapping)
}

fn bench_distance(c: &mut Criterion) {
    let d = SmoothDispatcher::default();
    let (apart, overlapping) = ellipse_pairs();
    let mut g = c.benchmark_group("distance/ellipse-ellipse");
    g.sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for (label, batch) in [("separated", &apart), ("penetrating", &overlapping)] {
        if batch.is_empty() {
            continue;
        }
        let param = format!("{label} ({})", batch.len());
        g.bench_with_input(BenchmarkId::new("ours", &param), batch, |b, batch: &Vec<PosePair>| {
            b.iter(|| {
                for (p, g1, g2) in batch {
                    black_box(d.distance(p, &**g1, &**g2).ok());
                }
            })
        });
        g.bench_with_input(BenchmarkId::new("parry", &param), batch, |b, batch: &Vec<PosePair>| {
            b.iter(|| {
                for (p, g1, g2) in batch {
                    black_box(DefaultQueryDispatcher.distance(p, &**g1, &**g2).ok());
                }
            })
        });
        // The signed distance through the curve API (no dispatch; penetration depth included).
        let curves: Vec<(Pose, Ellipse, Ellipse)> = batch
            .iter()
            .filter_map(|(p, g1, g2)| Some((*p, *g1.as_shape::<Ellipse>()?, *g2.as_shape::<Ellipse>()?)))
            .collect();
        let opts = DistanceOptions::default();
        g.bench_with_input(BenchmarkId::new("ours-curve-api", &param), &curves, |b, curves| {
            b.iter(|| {
                for (p, e1, e2) in curves {
                    black_box(stationary_distance(e1, e2, p, &opts).ok());
                }
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default();
    targets = bench_toi, bench_distance
}
criterion_main!(benches);
