//! The classes with no strictly convex side against parry's cast on parry's own shapes: the
//! same geometry as parry's `RoundConvexPolygon`, `ConvexPolygon` and `Cuboid` (a
//! `CapsuleEllipse`, which parry has no shape for, stays this crate's shape), so that parry's
//! support maps are not called through this crate's shapes.

use super::scenarios::{ScenarioClass, TestShape};
use super::timing::{quantile, time_contenders};
use super::{parry_polygonal, split_batch, Case};
use parry2d_f64::query::{DefaultQueryDispatcher, QueryDispatcher};
use parry2d_f64::shape::Shape;
use smooth_ccd2d::SmoothDispatcher;

/// The classes the table covers.
const CLASSES: [ScenarioClass; 4] = [
    ScenarioClass::PolygonPolygon,
    ScenarioClass::PolygonCuboid,
    ScenarioClass::CapsuleEllipsePolygon,
    ScenarioClass::CuboidCuboid,
];

/// `t` as parry's own shape where parry has one.
fn native(t: &TestShape) -> Box<dyn Shape> {
    match t {
        TestShape::RoundedPolygon(_) | TestShape::Cuboid(..) => parry_polygonal(t),
        other => other.parry_shape(),
    }
}

/// parry's nonlinear cast of `c`'s scenario on its own shapes (`stop_at_penetration`, target 0).
fn parry_native(c: &Case, g1: &dyn Shape, g2: &dyn Shape) -> bool {
    let s = &c.s;
    DefaultQueryDispatcher
        .cast_shapes_nonlinear(&s.motion1, g1, &s.motion2, g2, s.t0, s.t1, true)
        .ok()
        .flatten()
        .is_some()
}

/// Prints the table: per class and outcome, the median times and their ratio.
pub fn native_table() {
    let d = SmoothDispatcher::default();
    println!("\n## Pairs with no strictly convex side against parry's own shapes\n");
    println!(
        "The same 200 scenarios per class; parry casts the polygons as its `RoundConvexPolygon` (or `ConvexPolygon` for corner radius 0) and the boxes as `Cuboid`s (a `CapsuleEllipse` stays this crate's shape); this crate casts its own shapes through `SmoothDispatcher`. Ratio: parry's median over ours.\n"
    );
    println!("| class | outcome (ours) | n | ours median µs | parry median µs | ratio of medians | parry agrees on hit/miss |");
    println!("|---|---|---:|---:|---:|---:|---:|");
    for class in CLASSES {
        let (hits, misses) = split_batch(class);
        for (label, batch) in [("hit", &hits), ("miss", &misses)] {
            let (mut ours, mut parry, mut agree) = (Vec::new(), Vec::new(), 0);
            for c in batch.iter() {
                let (n1, n2) = (native(&c.s.shape1), native(&c.s.shape2));
                let (a, b) = time_contenders(|| c.ours(&d), || parry_native(c, &*n1, &*n2));
                ours.push(a * 1e6);
                parry.push(b * 1e6);
                agree += usize::from(parry_native(c, &*n1, &*n2) == c.ours(&d).is_some());
            }
            let (mo, mp) = (quantile(&ours, 0.5), quantile(&parry, 0.5));
            println!(
                "| {} | {label} | {} | {mo:.2} | {mp:.2} | {:.2} | {agree}/{} |",
                class.name(),
                batch.len(),
                mp / mo,
                batch.len()
            );
        }
    }
}
