//! What the f32 boundary costs: the f32 package's dispatcher against the f64 crate's on the same
//! queries (the f32 inputs widened), and parry2d's own f32 `DefaultQueryDispatcher` on the same
//! f32 shapes (through their support maps), side by side in one criterion group per pair class.
//! Each iteration answers a batch of scenarios of the workspace's f64 tests rounded to f32.
//!
//! Run: `cargo bench -p smooth-ccd2d-f32 --bench f32`. Quote ratios, not times.

#[path = "../../../tests/common/mod.rs"]
mod common;
#[path = "../tests/common32/mod.rs"]
mod common32;

use common::{generate, ScenarioClass};
use common32::{pose64, rounded, Rounded};
use criterion::{criterion_group, criterion_main, Criterion};
use parry2d::math::{Pose, Vector};
use parry2d::query::{ContactManifold, DefaultQueryDispatcher, PersistentQueryDispatcher, QueryDispatcher};
use parry2d::shape::Cuboid;
use parry2d_f64::query::{PersistentQueryDispatcher as _, QueryDispatcher as _};
use smooth_ccd2d_f32::{Ellipse, RoundedPolygon, SmoothDispatcher};
use std::hint::black_box;
use std::time::Duration;

/// A scenario rounded to f32, with the f64 shapes it stands for.
type Case = (
    Rounded,
    Box<dyn parry2d_f64::shape::Shape>,
    Box<dyn parry2d_f64::shape::Shape>,
);

/// The scenarios of a class, rounded to f32, with their f64 shapes.
fn batch(class: ScenarioClass, n: u64) -> Vec<Case> {
    (0..n)
        .filter_map(|seed| rounded(&generate(class, seed)))
        .map(|r| {
            let (w1, w2) = (r.wide.shape1.parry_shape(), r.wide.shape2.parry_shape());
            (r, w1, w2)
        })
        .collect()
}

fn casts(c: &mut Criterion) {
    let (d32, d64) = (SmoothDispatcher::default(), smooth_ccd2d::SmoothDispatcher::default());
    for class in [
        ScenarioClass::EllipseEllipse,
        ScenarioClass::EllipseRoundedPolygon,
        ScenarioClass::PolygonCuboid,
    ] {
        let cases = batch(class, 100);
        let mut g = c.benchmark_group(format!("f32/toi/{}", class.name()));
        g.sample_size(20)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        g.bench_function("f64 crate (widened inputs)", |b| {
            b.iter(|| {
                for (r, w1, w2) in &cases {
                    let (m1, m2) = (&r.wide.motion1, &r.wide.motion2);
                    black_box(d64.cast_shapes_nonlinear(m1, &**w1, m2, &**w2, 0.0, 1.0, true).ok());
                }
            })
        });
        g.bench_function("f32 package", |b| {
            b.iter(|| {
                for (r, _, _) in &cases {
                    black_box(
                        d32.cast_shapes_nonlinear(&r.m1, &*r.g1, &r.m2, &*r.g2, 0.0, 1.0, true)
                            .ok(),
                    );
                }
            })
        });
        g.bench_function("parry2d f32 (same shapes)", |b| {
            b.iter(|| {
                for (r, _, _) in &cases {
                    let hit =
                        DefaultQueryDispatcher.cast_shapes_nonlinear(&r.m1, &*r.g1, &r.m2, &*r.g2, 0.0, 1.0, true);
                    black_box(hit.ok());
                }
            })
        });
        g.finish();
    }
}

fn manifolds(c: &mut Criterion) {
    let (d32, d64) = (SmoothDispatcher::default(), smooth_ccd2d::SmoothDispatcher::default());
    let ground = Cuboid::new(Vector::new(5.0, 0.5));
    let ground64 = parry2d_f64::shape::Cuboid::new(parry2d_f64::math::Vector::new(5.0, 0.5));
    let ellipse = Ellipse::new(0.5, 0.2);
    let heptagon = RoundedPolygon::regular(7, 0.5, 0.05);
    let poses: Vec<Pose> = (0..64)
        .map(|k| {
            Pose::new(
                Vector::new(0.1 * k as f32 - 3.0, 0.69 - 1e-3 * (k % 7) as f32),
                0.1 * k as f32,
            )
        })
        .collect();
    type Pair<'a> = (
        &'a str,
        &'a dyn parry2d::shape::Shape,
        &'a dyn parry2d_f64::shape::Shape,
    );
    let pairs: [Pair; 2] = [
        ("ellipse", &ellipse, ellipse.as_f64()),
        ("rounded heptagon", &heptagon, heptagon.as_f64()),
    ];
    for (name, g2, w2) in pairs {
        let mut g = c.benchmark_group(format!("f32/manifold/{name} on a box"));
        g.sample_size(20)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        g.bench_function("f64 crate (widened inputs)", |b| {
            let mut m: Vec<parry2d_f64::query::ContactManifold<(), ()>> = Vec::new();
            b.iter(|| {
                for p in &poses {
                    m.clear();
                    black_box(
                        d64.contact_manifolds(&pose64(p), &ground64, w2, 0.01, &mut m, &mut None)
                            .ok(),
                    );
                }
            })
        });
        g.bench_function("f32 package", |b| {
            let mut m: Vec<ContactManifold<(), ()>> = Vec::new();
            b.iter(|| {
                for p in &poses {
                    m.clear();
                    black_box(d32.contact_manifolds(p, &ground, g2, 0.01, &mut m, &mut None).ok());
                }
            })
        });
        g.finish();
    }
}

criterion_group!(benches, casts, manifolds);
criterion_main!(benches);
