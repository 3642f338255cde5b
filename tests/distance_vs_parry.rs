//! SmoothDispatcher's stationary queries against parry's own (GJK/EPA through the shapes'
//! support maps) over random configurations, penetration included, and against closed forms.

mod common;

use common::rng::Rng;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{self, DefaultQueryDispatcher, QueryDispatcher};
use parry2d_f64::shape::{Ball, Capsule, Cuboid, HalfSpace, Shape};
use smooth_ccd2d::{CapsuleEllipse, DistanceStatus, Ellipse, RoundedPolygon, SmoothDispatcher};

fn random_shape(kind: &str, rng: &mut Rng) -> Box<dyn Shape> {
    let s = rng.uniform(0.3, 1.5);
    match kind {
        "ellipse" => Box::new(Ellipse::new(s, s * rng.uniform(0.1, 1.0))),
        "ball" => Box::new(Ball::new(s)),
        "rounded" => Box::new(RoundedPolygon::regular(
            (rng.next_u64() % 6 + 3) as usize,
            s,
            s * rng.uniform(0.02, 0.4),
        )),
        "sharp" => Box::new(RoundedPolygon::regular((rng.next_u64() % 6 + 3) as usize, s, 0.0)),
        "capsule_ellipse" => Box::new(CapsuleEllipse::new(
            s * 0.5,
            s * rng.uniform(0.2, 1.0),
            s * rng.uniform(0.3, 1.0),
        )),
        "cuboid" => Box::new(Cuboid::new(Vector::new(s, s * rng.uniform(0.2, 1.0)))),
        "capsule" => Box::new(Capsule::new_y(s * rng.uniform(0.2, 1.0), s * 0.4)),
        _ => unreachable!(),
    }
}

fn size_of(g: &dyn Shape) -> f64 {
    g.compute_local_bounding_sphere().radius
}

/// Shapes of kinds `k1` and `k2`, and shape 2's pose in shape 1's frame: centres `reach` times
/// the sum of the bounding radii apart, `reach` uniform in `reach_range`, any direction and
/// rotation. Also the pair's size (the larger bounding radius).
fn random_pair(
    k1: &str,
    k2: &str,
    rng: &mut Rng,
    reach_range: (f64, f64),
) -> (Box<dyn Shape>, Box<dyn Shape>, Pose, f64) {
    let g1 = random_shape(k1, rng);
    let g2 = random_shape(k2, rng);
    let size = size_of(&*g1).max(size_of(&*g2));
    let reach = size_of(&*g1) + size_of(&*g2);
    let dir = rng.uniform(-3.2, 3.2);
    let r = reach * rng.uniform(reach_range.0, reach_range.1);
    let pos12 = Pose::new(Vector::new(r * dir.cos(), r * dir.sin()), rng.uniform(-3.2, 3.2));
    (g1, g2, pos12, size)
}

/// Signed distance by dense sampling of the separating-axis gap (independent of both).
fn dense_gap(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> f64 {
    let (s1, s2) = (g1.as_support_map().unwrap(), g2.as_support_map().unwrap());
    let gap = |th: f64| {
        let n = Vector::new(th.cos(), th.sin());
        let p1 = s1.local_support_point(n);
        let n2 = pos12.rotation.inverse_transform_vector(-n);
        let p2 = *pos12 * s2.local_support_point(n2);
        (p2 - p1).dot(n)
    };
    let m = 20_000;
    let (mut best, mut bt) = (f64::NEG_INFINITY, 0.0);
    for k in 0..m {
        let th = std::f64::consts::TAU * k as f64 / m as f64;
        let g = gap(th);
        if g > best {
            best = g;
            bt = th;
        }
    }
    // Golden-section refinement around the best sample.
    let (mut a, mut b) = (
        bt - std::f64::consts::TAU / m as f64,
        bt + std::f64::consts::TAU / m as f64,
    );
    for _ in 0..100 {
        let (x1, x2) = (b - 0.618_033_988_75 * (b - a), a + 0.618_033_988_75 * (b - a));
        if gap(x1) > gap(x2) {
            b = x2;
        } else {
            a = x1;
        }
    }
    best.max(gap(0.5 * (a + b)))
}

fn median(v: &mut [usize]) -> usize {
    v.sort_unstable();
    v[v.len() / 2]
}

const KINDS: [(&str, &str); 8] = [
    ("ellipse", "ellipse"),
    ("ellipse", "ball"),
    ("rounded", "ellipse"),
    ("ellipse", "rounded"),
    ("capsule_ellipse", "ellipse"),
    ("sharp", "ellipse"),
    ("cuboid", "ellipse"),
    ("ellipse", "capsule"),
];

#[test]
fn distance_and_contact_agree_with_parry_over_random_configurations() {
    let d = SmoothDispatcher::default();
    let n = 10_000;
    let mut rng = Rng::new(7);
    for (k1, k2) in KINDS {
        let mut iters = Vec::with_capacity(n);
        let (mut worst_sep, mut worst_pen, mut penetrating, mut parry_off) = (0.0f64, 0.0f64, 0usize, 0usize);
        for case in 0..n {
            let (g1, g2, pos12, size) = random_pair(k1, k2, &mut rng, (0.2, 1.4));
            let ours = d
                .signed_distance(&pos12, &*g1, &*g2)
                .expect("pair handled")
                .expect("query ok");
            iters.push(ours.newton_iterations);
            let parry_d = DefaultQueryDispatcher.distance(&pos12, &*g1, &*g2).unwrap().distance;
            let mine_d = d.distance(&pos12, &*g1, &*g2).unwrap().distance;
            assert!(mine_d.is_finite() && ours.distance.is_finite());
            if parry_d > 1e-6 * size {
                if (mine_d - parry_d).abs() > 1e-6 * size {
                    // Disagreement: the dense reference decides, and ours must match it.
                    let dense = dense_gap(&pos12, &*g1, &*g2);
                    assert!(
                        (mine_d - dense).abs() <= 1e-9 * size,
                        "{k1}-{k2} case {case}: ours {mine_d} parry {parry_d} dense {dense}"
                    );
                    parry_off += 1;
                } else {
                    worst_sep = worst_sep.max((mine_d - parry_d).abs() / size);
                }
            } else {
                penetrating += 1;
                // Penetration depth: parry's contact (EPA) against ours.
                let pc = DefaultQueryDispatcher.contact(&pos12, &*g1, &*g2, 0.0).unwrap();
                let mc = d.contact(&pos12, &*g1, &*g2, 0.0).unwrap().expect("contact");
                if let Some(pc) = pc {
                    if (mc.dist - pc.dist).abs() > 1e-6 * size {
                        let dense = dense_gap(&pos12, &*g1, &*g2);
                        assert!(
                            (mc.dist - dense).abs() <= 1e-9 * size,
                            "{k1}-{k2} case {case}: ours {} parry {} dense {dense}",
                            mc.dist,
                            pc.dist
                        );
                        parry_off += 1;
                        continue;
                    }
                    worst_pen = worst_pen.max((mc.dist - pc.dist).abs() / size);
                    assert!(
                        (mc.dist - pc.dist).abs() <= 1e-6 * size,
                        "{k1}-{k2} case {case}: ours {} parry {} dense {} status {:?} evals {}",
                        mc.dist,
                        pc.dist,
                        dense_gap(&pos12, &*g1, &*g2),
                        ours.status,
                        ours.evaluations
                    );
                    assert!((mc.normal1 - pc.normal1).length() < 1e-3 || pc.dist > -1e-9 * size);
                }
                assert!(mc.dist <= 1e-6 * size);
                assert_ne!(ours.status, DistanceStatus::OutOfIterations);
            }
        }
        println!(
            "{k1}-{k2}: {n} cases ({penetrating} penetrating), median Newton iterations {}, worst |ours − parry|/size separated {worst_sep:.2e}, penetrating {worst_pen:.2e}; parry off by > 1e-6·size (dense sampling sides with ours) in {parry_off}",
            median(&mut iters)
        );
    }
}

#[test]
fn closed_forms_through_the_dispatcher_hold_to_1e_12() {
    let d = SmoothDispatcher::default();
    // Two discs (parry balls: handled through an ellipse on the other side).
    let e = Ellipse::new(0.7, 0.7);
    let b = Ball::new(0.4);
    for (x, y) in [(2.0, 0.3), (0.5, -0.2), (-1.0, 0.05)] {
        let r = d
            .signed_distance(&Pose::new(Vector::new(x, y), 0.4), &e, &b)
            .unwrap()
            .unwrap();
        let exact = (x * x + y * y).sqrt() - 1.1;
        assert!((r.distance - exact).abs() < 1e-12);
    }
    // Axis-aligned ellipses on a common axis.
    let (e1, e2) = (Ellipse::new(0.5, 0.8), Ellipse::new(0.3, 2.0));
    let r = d
        .signed_distance(&Pose::new(Vector::new(1.9, 0.0), 0.0), &e1, &e2)
        .unwrap()
        .unwrap();
    assert!((r.distance - 1.1).abs() < 1e-12);
    // A disc against a box face.
    let bx = Cuboid::new(Vector::new(1.0, 0.5));
    let disc = Ellipse::new(0.25, 0.25);
    let r = d
        .signed_distance(&Pose::new(Vector::new(0.3, 1.5), 0.0), &bx, &disc)
        .unwrap()
        .unwrap();
    assert!((r.distance - 0.75).abs() < 1e-12, "{}", r.distance);
    // An ellipse above a half-space.
    let hs = HalfSpace::new(Vector::Y);
    let r = d
        .signed_distance(&Pose::new(Vector::new(0.0, -2.0), 0.0), &e1, &hs)
        .unwrap()
        .unwrap();
    assert!((r.distance - 1.2).abs() < 1e-12, "{}", r.distance);
}

#[test]
fn contact_manifolds_of_parrys_default_dispatcher_work_on_smooth_shapes() {
    use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
    let e1 = Ellipse::new(1.0, 0.5);
    let e2 = Ellipse::new(0.6, 0.3);
    let bx = Cuboid::new(Vector::new(1.0, 0.2));
    for (g2, pos) in [
        (&e2 as &dyn Shape, Vector::new(1.4, 0.2)),
        (&bx as &dyn Shape, Vector::new(0.0, 0.65)),
    ] {
        let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
        let mut ws = None;
        DefaultQueryDispatcher
            .contact_manifolds(&Pose::new(pos, 0.1), &e1, g2, 0.1, &mut manifolds, &mut ws)
            .unwrap();
        assert!(manifolds.iter().any(|m| !m.points.is_empty()), "no contact points");
    }
    let _ = query::distance;
}

/// Pairs with no strictly convex side (the gap tracker's exact distance, `query::gap`).
const FACETED_KINDS: [(&str, &str); 7] = [
    ("rounded", "rounded"),
    ("sharp", "rounded"),
    ("sharp", "sharp"),
    ("rounded", "cuboid"),
    ("capsule_ellipse", "sharp"),
    ("capsule_ellipse", "cuboid"),
    ("capsule", "rounded"),
];

/// Distance and contact of pairs with no strictly convex side, apart and penetrating: against
/// parry's GJK/EPA on every case, and against dense sampling of the separating-axis gap on every
/// tenth case and wherever the two disagree by more than 1e-9·size (the dense reference must
/// side with this crate to 1e-9·size).
#[test]
fn faceted_pairs_distance_and_contact_agree_with_parry_and_dense_sampling() {
    let d = SmoothDispatcher::default();
    let n = 4_000;
    let mut rng = Rng::new(17);
    for (k1, k2) in FACETED_KINDS {
        let (mut worst_parry, mut worst_dense, mut penetrating, mut parry_off, mut dense_checked) =
            (0.0f64, 0.0f64, 0usize, 0usize, 0usize);
        for case in 0..n {
            let (g1, g2, pos12, size) = random_pair(k1, k2, &mut rng, (0.1, 1.3));
            let mine = d.distance(&pos12, &*g1, &*g2).expect("distance").distance;
            let contact = d
                .contact(&pos12, &*g1, &*g2, f64::MAX)
                .expect("contact")
                .expect("within prediction");
            assert!(mine.is_finite() && contact.dist.is_finite());
            // The distance query reports 0 for overlapping shapes; the contact gives the depth.
            assert!(
                (mine - contact.dist.max(0.0)).abs() <= 1e-12 * size,
                "{k1}-{k2} case {case}"
            );
            let parry = if contact.dist > 0.0 {
                DefaultQueryDispatcher.distance(&pos12, &*g1, &*g2).unwrap().distance
            } else {
                penetrating += 1;
                match DefaultQueryDispatcher.contact(&pos12, &*g1, &*g2, 0.0).unwrap() {
                    Some(c) => c.dist,
                    None => f64::NAN,
                }
            };
            let off = (contact.dist - parry).abs();
            // False also when parry gave no answer (NaN).
            let parry_agrees = off <= 1e-9 * size;
            if !parry_agrees || case % 10 == 0 {
                let dense = dense_gap(&pos12, &*g1, &*g2);
                dense_checked += 1;
                let e = (contact.dist - dense).abs();
                assert!(
                    e <= 1e-9 * size,
                    "{k1}-{k2} case {case}: ours {} parry {parry} dense {dense}",
                    contact.dist
                );
                worst_dense = worst_dense.max(e / size);
                if !parry_agrees {
                    parry_off += 1;
                    continue;
                }
            }
            worst_parry = worst_parry.max(off / size);
            // Witnesses: D apart along the normal, in shape 1's frame.
            let p2 = pos12 * contact.point2;
            let along = (p2 - contact.point1).dot(contact.normal1);
            assert!(
                (along - contact.dist).abs() <= 1e-9 * size,
                "{k1}-{k2} case {case}: witnesses"
            );
        }
        println!(
            "{k1}-{k2}: {n} cases ({penetrating} penetrating), worst |ours − parry|/size {worst_parry:.1e}; \
             against dense sampling ({dense_checked} cases) {worst_dense:.1e}; parry off by > 1e-9·size \
             (dense sampling sides with ours) in {parry_off}"
        );
        assert!(penetrating > n / 10 && penetrating < n * 9 / 10);
    }
}
