//! Warm-started contact manifolds equal cold ones: rapier hands the previous step's manifold
//! back to the dispatcher, whose computation then starts from its normal; the answer must not
//! depend on it. Random pairs of every kind the exact contact query takes (ellipses, thin ones,
//! rounded and sharp polygons, capsule-ellipses, parry's boxes and discs), at resting and deep
//! overlaps, each followed through small pose changes.

mod common;

use common::rng::Rng;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
use parry2d_f64::shape::{Ball, Cuboid, Shape};
use smooth_ccd2d::{CapsuleEllipse, Ellipse, RoundedPolygon, SmoothDispatcher};

type Manifolds = Vec<ContactManifold<(), ()>>;

/// A random shape of kind `k` and its size (bounding radius).
fn shape(rng: &mut Rng, k: usize) -> (Box<dyn Shape>, f64) {
    let s = rng.log_uniform(0.1, 10.0);
    match k {
        0 => (Box::new(Ellipse::new(s, s * rng.uniform(0.2, 1.0))), s),
        1 => (Box::new(Ellipse::new(s, s / 100.0)), s),
        2 => {
            let n = rng.int(3, 9);
            let r = if rng.chance(0.3) {
                0.0
            } else {
                s * rng.uniform(0.02, 0.3)
            };
            (Box::new(RoundedPolygon::regular(n, s, r)), s + r)
        }
        3 => {
            let (r1, r2, r3) = (
                s * rng.uniform(0.2, 0.5),
                s * rng.uniform(0.1, 0.5),
                s * rng.uniform(0.2, 1.0),
            );
            (Box::new(CapsuleEllipse::new(r1, r2, r3)), (r1 + r2).max(r3) + r1)
        }
        4 => {
            let h = Vector::new(s, s * rng.uniform(0.2, 1.0));
            (Box::new(Cuboid::new(h)), h.length())
        }
        _ => (Box::new(Ball::new(s)), s),
    }
}

fn manifolds(d: &SmoothDispatcher, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, pred: f64, m: &mut Manifolds) {
    let mut ws = None;
    d.contact_manifolds(pos12, g1, g2, pred, m, &mut ws)
        .expect("a manifold");
}

#[test]
fn warm_started_manifolds_equal_cold_ones_over_small_pose_changes() {
    let warm = SmoothDispatcher::default();
    let cold = SmoothDispatcher::default().with_warm_start(false);
    let mut rng = Rng::new(0x3A2A);
    let (mut changes, mut points) = (0usize, 0usize);
    // Pairs with at least one of this crate's shapes (kinds 0–3).
    let pairs = [
        (0, 0),
        (1, 1),
        (0, 1),
        (0, 2),
        (1, 2),
        (2, 2),
        (3, 0),
        (3, 2),
        (2, 4),
        (3, 4),
        (0, 5),
        (2, 5),
    ];
    while changes < 10_000 {
        let (k1, k2) = pairs[rng.int(0, pairs.len() - 1)];
        let (g1, r1) = shape(&mut rng, k1);
        let (g2, r2) = shape(&mut rng, k2);
        let size = r1.max(r2);
        let dir = rng.uniform(0.0, std::f64::consts::TAU);
        let mut pose = Pose::new(
            Vector::new(dir.cos(), dir.sin()) * (r1 + r2) * rng.uniform(0.1, 1.0),
            rng.uniform(-3.2, 3.2),
        );
        let pred = 0.01 * size;
        let mut chain: Manifolds = Vec::new();
        manifolds(&warm, &pose, &*g1, &*g2, pred, &mut chain);
        for _ in 0..10 {
            pose = Pose::new(
                pose.translation + Vector::new(rng.uniform(-1e-3, 1e-3), rng.uniform(-1e-3, 1e-3)) * size,
                pose.rotation.angle() + rng.uniform(-1e-2, 1e-2),
            );
            // The warm manifold is the previous one, updated; the cold one is computed afresh.
            manifolds(&warm, &pose, &*g1, &*g2, pred, &mut chain);
            let mut fresh: Manifolds = Vec::new();
            manifolds(&cold, &pose, &*g1, &*g2, pred, &mut fresh);
            assert_eq!(chain.len(), fresh.len());
            for (a, b) in chain.iter().zip(&fresh) {
                assert_eq!(a.points.len(), b.points.len(), "{k1}-{k2} at {pose:?}");
                // (Without points the normal is not part of the answer.)
                let normals_agree = (a.local_n1 - b.local_n1).length() <= 1e-12;
                assert!(a.points.is_empty() || normals_agree, "{k1}-{k2} at {pose:?}");
                for (p, q) in a.points.iter().zip(&b.points) {
                    assert_eq!((p.fid1, p.fid2), (q.fid1, q.fid2), "{k1}-{k2} at {pose:?}");
                    assert!(
                        (p.local_p1 - q.local_p1).length() <= 1e-12 * size,
                        "{k1}-{k2} at {pose:?}"
                    );
                    assert!(
                        (p.local_p2 - q.local_p2).length() <= 1e-12 * size,
                        "{k1}-{k2} at {pose:?}"
                    );
                    assert!((p.dist - q.dist).abs() <= 1e-12 * size, "{k1}-{k2} at {pose:?}");
                    points += 1;
                }
            }
            changes += 1;
        }
    }
    println!("warm_started_manifolds_equal_cold_ones_over_small_pose_changes: {changes} pose changes, {points} points compared");
}
