//! parry's own pairs through [`SmoothDispatcher`] (`cargo bench --bench ratios -- parry-pairs`):
//! what a rapier scene that swaps in the dispatcher pays on the pairs it hands to parry. Both
//! sides run on the same shapes, so the answers must be the same; the table says whether they
//! are, to the bit.

use super::rng::Rng;
use super::timing::{quantile, time_pair};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{ContactManifold, DefaultQueryDispatcher, PersistentQueryDispatcher, QueryDispatcher};
use parry2d_f64::shape::{Ball, Capsule, ConvexPolygon, Cuboid, RoundConvexPolygon, Segment, Shape, Triangle};
use smooth_ccd2d::SmoothDispatcher;
use std::hint::black_box;

/// Poses per pair kind.
const POSES: usize = 100;

type Manifolds = Vec<ContactManifold<(), u32>>;

/// A pair kind: its name and its two shapes.
struct Kind {
    name: &'static str,
    g1: Box<dyn Shape>,
    g2: Box<dyn Shape>,
}

fn kinds() -> Vec<Kind> {
    let hexagon: Vec<Vector> = (0..6)
        .map(|k| {
            let a = k as f64 * core::f64::consts::TAU / 6.0;
            Vector::new(0.6 * a.cos(), 0.6 * a.sin())
        })
        .collect();
    let hex = ConvexPolygon::from_convex_hull(&hexagon).expect("a hexagon");
    let round_hex = RoundConvexPolygon {
        inner_shape: hex.clone(),
        border_radius: 0.05,
    };
    let tri = Triangle::new(Vector::new(-0.8, -0.3), Vector::new(0.8, -0.3), Vector::new(0.0, 0.6));
    let cuboid = || Box::new(Cuboid::new(Vector::new(0.7, 0.3)));
    let kind = |name, g1: Box<dyn Shape>, g2: Box<dyn Shape>| Kind { name, g1, g2 };
    vec![
        kind("disc – disc", Box::new(Ball::new(0.6)), Box::new(Ball::new(0.5))),
        kind("disc – box", Box::new(Ball::new(0.6)), cuboid()),
        kind("box – box", cuboid(), Box::new(Cuboid::new(Vector::new(0.5, 0.4)))),
        kind(
            "capsule – disc",
            Box::new(Capsule::new_x(0.5, 0.2)),
            Box::new(Ball::new(0.5)),
        ),
        kind(
            "capsule – capsule",
            Box::new(Capsule::new_x(0.5, 0.2)),
            Box::new(Capsule::new_y(0.4, 0.3)),
        ),
        kind("capsule – box", Box::new(Capsule::new_x(0.5, 0.2)), cuboid()),
        kind(
            "segment – disc",
            Box::new(Segment::new(Vector::new(-1.0, 0.0), Vector::new(1.0, 0.2))),
            Box::new(Ball::new(0.5)),
        ),
        kind("triangle – disc", Box::new(tri), Box::new(Ball::new(0.5))),
        kind("triangle – box", Box::new(tri), cuboid()),
        kind("polygon – polygon", Box::new(hex.clone()), Box::new(hex)),
        kind("round polygon – disc", Box::new(round_hex), Box::new(Ball::new(0.4))),
    ]
}

/// Random poses of shape 2 (random direction and turn) with the centres brought together until
/// parry's signed distance is −1 % of the pair's size.
fn poses(k: &Kind, rng: &mut Rng) -> Vec<Pose> {
    let size = k.g1.compute_local_bounding_sphere().radius + k.g2.compute_local_bounding_sphere().radius;
    (0..POSES)
        .filter_map(|_| {
            let a = rng.uniform(0.0, core::f64::consts::TAU);
            let dir = Vector::new(a.cos(), a.sin());
            let turn = rng.uniform(-3.2, 3.2);
            let dist = |s: f64| {
                let pose = Pose::new(dir * s, turn);
                DefaultQueryDispatcher
                    .contact(&pose, &*k.g1, &*k.g2, 10.0 * size)
                    .ok()
                    .flatten()
                    .map(|c| c.dist)
            };
            let (mut lo, mut hi) = (0.0, 2.0 * size);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if dist(mid)? < -0.01 * size {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            Some(Pose::new(dir * lo, turn))
        })
        .collect()
}

/// Every number of the manifolds as bits (points, ids, normals).
fn bits(ms: &Manifolds) -> Vec<u64> {
    let mut v = vec![];
    for m in ms {
        v.extend([m.local_n1.x, m.local_n1.y, m.local_n2.x, m.local_n2.y].map(f64::to_bits));
        for p in &m.points {
            v.extend([p.local_p1.x, p.local_p1.y, p.local_p2.x, p.local_p2.y, p.dist].map(f64::to_bits));
            v.extend([u64::from(p.fid1.0), u64::from(p.fid2.0)]);
        }
    }
    v
}

/// Nanoseconds with one decimal.
fn ns(x: f64) -> String {
    format!("{:.1}", x * 1e9)
}

/// Prints the table (`cargo bench --bench ratios -- parry-pairs`).
pub fn table() {
    let d = SmoothDispatcher::default();
    println!("\n## parry's own pairs through the dispatcher: speed ratio parry / ours\n");
    println!(
        "Per pair kind, {POSES} random poses with parry's signed distance at −1 % of the size, prediction 1 % of it; each call recomputes (the points are cleared first). Ours: `SmoothDispatcher::contact_manifolds`, which hands these pairs to parry behind its input guards (and answers box – box, disc – disc and box – disc itself, without parry's dispatch); parry: `DefaultQueryDispatcher::contact_manifolds` on the same shapes. Same answers: every number and feature id equal to the bit.\n"
    );
    println!("| pair kind | n | ours median ns | parry median ns | ratio of medians | same answers |");
    println!("|---|---:|---:|---:|---:|---|");
    let mut rng = Rng::new(0x09A2_27E5);
    for k in kinds() {
        let set = poses(&k, &mut rng);
        let size = k.g1.compute_local_bounding_sphere().radius + k.g2.compute_local_bounding_sphere().radius;
        let prediction = 0.01 * size;
        let (mut ours, mut theirs, mut same) = (vec![], vec![], true);
        for pose in &set {
            let (mut mo, mut mp): (Manifolds, Manifolds) = (vec![], vec![]);
            let (mut wo, mut wp) = (None, None);
            let a = d.contact_manifolds(pose, &*k.g1, &*k.g2, prediction, &mut mo, &mut wo);
            let b = DefaultQueryDispatcher.contact_manifolds(pose, &*k.g1, &*k.g2, prediction, &mut mp, &mut wp);
            same &= a.is_ok() == b.is_ok() && bits(&mo) == bits(&mp);
            let (o, p) = time_pair(
                &mut || {
                    mo.iter_mut().for_each(|m| m.clear());
                    let _ =
                        black_box(d.contact_manifolds(black_box(pose), &*k.g1, &*k.g2, prediction, &mut mo, &mut wo));
                },
                &mut || {
                    mp.iter_mut().for_each(|m| m.clear());
                    let _ = black_box(DefaultQueryDispatcher.contact_manifolds(
                        black_box(pose),
                        &*k.g1,
                        &*k.g2,
                        prediction,
                        &mut mp,
                        &mut wp,
                    ));
                },
            );
            ours.push(o);
            theirs.push(p);
        }
        println!(
            "| {} | {} | {} | {} | {:.2} | {} |",
            k.name,
            set.len(),
            ns(quantile(&ours, 0.5)),
            ns(quantile(&theirs, 0.5)),
            quantile(&theirs, 0.5) / quantile(&ours, 0.5),
            if same { "yes" } else { "no" }
        );
    }
}
