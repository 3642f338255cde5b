//! The contact-manifold comparison of both benches: every pair kind (the scenario classes, plus a
//! rounded polygon against a disc and against a box, thin 1:100 ellipses against each other and
//! against a rounded polygon, and the Appendix D heptagon against its ellipse), each pair at a
//! resting overlap (signed distance −1 % of the size) and a deep one (−10 %), prediction 1 % of
//! the size; this crate's `contact_manifolds` on the exact shapes against parry's on its polygonal
//! stand-ins ([`super::parry_polygonal`]). `MANIFOLD_KIND=<part of a name>` in the environment
//! restricts the ratio table to the kinds whose name contains it.

use super::reference::reference_distance;
use super::rng::Rng;
use super::scenarios::{ScenarioClass, TestShape};
use super::timing::{quantile, time_pair};
use super::{parry_polygonal, pose_at_depth, sci, us, Case, BATCH};
use core::f64::consts::{PI, TAU};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{ContactManifold, DefaultQueryDispatcher, PersistentQueryDispatcher};
use parry2d_f64::shape::Shape;
use smooth_ccd2d::{BallCurve, CapsuleEllipse, ConvexCurve, Ellipse, RoundedPolygon, SmoothDispatcher};
use std::hint::black_box;

/// The overlaps compared: (label, signed distance as a fraction of the size).
pub const OVERLAPS: [(&str, f64); 2] = [("resting 1 %", -0.01), ("deep 10 %", -0.10)];

/// Contact manifolds as both dispatchers fill them.
pub type Manifolds = Vec<ContactManifold<(), ()>>;

/// A pair at one pose: the shapes as this crate answers them and as parry's stand-ins.
pub struct ManifoldPair {
    pub g1: Box<dyn Shape>,
    pub g2: Box<dyn Shape>,
    pub a1: Box<dyn Shape>,
    pub a2: Box<dyn Shape>,
    pub pos12: Pose,
    /// The larger bounding radius.
    pub size: f64,
    /// The reference signed distance at `pos12`.
    pub reference: f64,
}

impl ManifoldPair {
    /// The prediction distance of the comparison: 1 % of the size.
    pub fn prediction(&self) -> f64 {
        0.01 * self.size
    }
}

/// A pair kind: its name and its shape pairs with a starting pose (apart), from which
/// [`pairs_at`] brings the centres together.
pub struct Kind {
    pub name: String,
    pub shapes: Vec<(TestShape, TestShape, Pose)>,
}

/// A random pose at `reach` from the origin with a random angle.
fn random_pose(rng: &mut Rng, reach: f64) -> Pose {
    let dir = rng.uniform(0.0, TAU);
    Pose::new(Vector::new(dir.cos(), dir.sin()) * reach, rng.uniform(-PI, PI))
}

fn radius(t: &TestShape) -> f64 {
    t.curve().bounding_radius()
}

/// Every pair kind of the comparison, `BATCH` pairs each.
pub fn kinds() -> Vec<Kind> {
    let mut out: Vec<Kind> = ScenarioClass::ALL
        .iter()
        .map(|&class| Kind {
            name: class.name().to_string(),
            shapes: (0..BATCH as u64)
                .map(|seed| {
                    let c = Case::new(class, seed);
                    let pose = c.start_pose();
                    (c.s.shape1, c.s.shape2, pose)
                })
                .collect(),
        })
        .collect();
    let mut rng = Rng::new(0x005E_ED18);
    let mut extra = |name: &str, make: &mut dyn FnMut(&mut Rng, u64) -> (TestShape, TestShape)| {
        let shapes = (0..BATCH as u64)
            .map(|seed| {
                let (a, b) = make(&mut rng, seed);
                let reach = 2.0 * (radius(&a) + radius(&b));
                let pose = random_pose(&mut rng, reach);
                (a, b, pose)
            })
            .collect();
        out.push(Kind {
            name: name.to_string(),
            shapes,
        });
    };
    let rounded = |seed: u64| loop {
        // The rounded polygons of the rounded polygon – ellipse class.
        let c = Case::new(ScenarioClass::RoundedPolygonEllipse, seed);
        if let TestShape::RoundedPolygon(p) = c.s.shape1 {
            return p;
        }
    };
    extra("rounded_polygon-ball", &mut |rng, seed| {
        let p = rounded(seed);
        let r = rng.uniform(0.2, 1.0) * p.bounding_radius();
        (TestShape::RoundedPolygon(p), TestShape::Ball(BallCurve { radius: r }))
    });
    extra("rounded_polygon-cuboid", &mut |rng, seed| {
        let p = rounded(seed);
        let s = p.bounding_radius();
        let h = Vector::new(rng.uniform(0.3, 2.0) * s, rng.uniform(0.1, 1.0) * s);
        let core = [
            Vector::new(-h.x, -h.y),
            Vector::new(h.x, -h.y),
            h,
            Vector::new(-h.x, h.y),
        ];
        let curve = RoundedPolygon::new(&core, 0.0);
        (TestShape::RoundedPolygon(p), TestShape::Cuboid(h, curve))
    });
    let thin = |rng: &mut Rng| {
        let a = rng.log_uniform(0.1, 10.0);
        Ellipse::new(a, a / 100.0)
    };
    extra("thin_ellipse-thin_ellipse (1:100)", &mut |rng, _| {
        (TestShape::Ellipse(thin(rng)), TestShape::Ellipse(thin(rng)))
    });
    extra("thin_ellipse-rounded_polygon (1:100)", &mut |rng, seed| {
        let p = rounded(seed);
        let a = p.bounding_radius() * rng.uniform(0.5, 2.0);
        let e = Ellipse::new(a, a / 100.0);
        (TestShape::Ellipse(e), TestShape::RoundedPolygon(p))
    });
    extra("appendix_d heptagon-ellipse", &mut |_, _| {
        (
            TestShape::RoundedPolygon(RoundedPolygon::regular(7, 1.0, 0.15)),
            TestShape::Ellipse(Ellipse::new(0.5, 1.5)),
        )
    });
    // Appended, so that the kinds above keep their random draws: the pairs of the pile
    // (`examples/pile.rs`) not above — its `CapsuleEllipse`s against each other and against
    // rounded polygons, two rounded polygons, ellipses on its box walls.
    let capsule = |rng: &mut Rng, s: f64| {
        CapsuleEllipse::new(
            s * rng.uniform(0.2, 0.8),
            s * rng.uniform(0.1, 0.8),
            s * rng.uniform(0.1, 1.5),
        )
    };
    extra("capsule_ellipse-capsule_ellipse", &mut |rng, _| {
        let s2 = rng.uniform(0.3, 1.0);
        (
            TestShape::CapsuleEllipse(capsule(rng, 1.0)),
            TestShape::CapsuleEllipse(capsule(rng, s2)),
        )
    });
    extra("capsule_ellipse-rounded_polygon", &mut |rng, seed| {
        let p = rounded(seed);
        let s = p.bounding_radius() * rng.uniform(0.3, 1.0);
        (TestShape::CapsuleEllipse(capsule(rng, s)), TestShape::RoundedPolygon(p))
    });
    extra("rounded_polygon-rounded_polygon", &mut |_, seed| {
        (
            TestShape::RoundedPolygon(rounded(seed)),
            TestShape::RoundedPolygon(rounded(seed + 1000)),
        )
    });
    extra("ellipse-cuboid", &mut |rng, _| {
        let a = rng.uniform(0.2, 1.0);
        let e = Ellipse::new(a, a * rng.log_uniform(0.05, 1.0));
        let h = Vector::new(rng.uniform(0.3, 2.0), rng.uniform(0.1, 1.0));
        let core = [
            Vector::new(-h.x, -h.y),
            Vector::new(h.x, -h.y),
            h,
            Vector::new(-h.x, h.y),
        ];
        (
            TestShape::Ellipse(e),
            TestShape::Cuboid(h, RoundedPolygon::new(&core, 0.0)),
        )
    });
    out
}

/// The pairs of `kind` brought together along their starting direction until this crate's
/// signed distance is `depth` of the size (bisection on the translation's scale; pairs that
/// cannot reach it are left out).
pub fn pairs_at(kind: &Kind, depth: f64, d: &SmoothDispatcher) -> Vec<ManifoldPair> {
    kind.shapes
        .iter()
        .filter_map(|(t1, t2, p0)| {
            let (g1, g2) = (t1.parry_shape(), t2.parry_shape());
            let size = radius(t1).max(radius(t2));
            let pos12 = pose_at_depth(p0, &*g1, &*g2, depth * size, d)?;
            let reference = reference_distance(t1.curve(), &Pose::IDENTITY, t2.curve(), &pos12).distance;
            Some(ManifoldPair {
                a1: parry_polygonal(t1),
                a2: parry_polygonal(t2),
                g1,
                g2,
                pos12,
                size,
                reference,
            })
        })
        .collect()
}

/// The deepest point's distance of `m` (+∞ without points).
pub fn deepest(m: &Manifolds) -> f64 {
    m.iter()
        .flat_map(|m| m.points.iter().map(|c| c.dist))
        .fold(f64::INFINITY, f64::min)
}

/// One row of the comparison: per-pair seconds of ours and parry, and the depth errors
/// relative to the size.
pub struct Row {
    pub ours: Vec<f64>,
    pub parry: Vec<f64>,
    pub ours_err: Vec<f64>,
    pub parry_err: Vec<f64>,
}

/// Times every pair, each call recomputing its manifold as for a pair in contact since the
/// last step: parry's points are cleared first (otherwise its manifold would be reused as it
/// stands for an unchanged pose); this crate's are kept, as rapier keeps them — the dispatcher
/// has no such shortcut and recomputes every call, and it tries the separating axes of
/// `dispatcher::apart` only for a pair whose last manifold had no point. The manifolds
/// themselves are kept, so nothing allocates and both keep their warm-start normal.
pub fn time_pairs(set: &[ManifoldPair], d: &SmoothDispatcher) -> Row {
    let mut row = Row {
        ours: vec![],
        parry: vec![],
        ours_err: vec![],
        parry_err: vec![],
    };
    for p in set {
        let prediction = p.prediction();
        let (mut mo, mut mp): (Manifolds, Manifolds) = (Vec::new(), Vec::new());
        let (mut wo, mut wp) = (None, None);
        let _ = d.contact_manifolds(&p.pos12, &*p.g1, &*p.g2, prediction, &mut mo, &mut wo);
        let _ = DefaultQueryDispatcher.contact_manifolds(&p.pos12, &*p.a1, &*p.a2, prediction, &mut mp, &mut wp);
        row.ours_err.push((deepest(&mo) - p.reference).abs() / p.size);
        row.parry_err.push((deepest(&mp) - p.reference).abs() / p.size);
        let (a, b) = time_pair(
            &mut || {
                let _ = black_box(d.contact_manifolds(&p.pos12, &*p.g1, &*p.g2, prediction, &mut mo, &mut wo));
            },
            &mut || {
                mp.iter_mut().for_each(|m| m.clear());
                let _ = black_box(
                    DefaultQueryDispatcher.contact_manifolds(&p.pos12, &*p.a1, &*p.a2, prediction, &mut mp, &mut wp),
                );
            },
        );
        row.ours.push(a);
        row.parry.push(b);
    }
    row
}

/// Prints the contact-manifold table (`cargo bench --bench ratios -- manifolds`).
pub fn table() {
    let d = SmoothDispatcher::default();
    println!("\n## Contact manifolds: speed ratio parry / ours\n");
    println!(
        "Per pair kind, {BATCH} pairs (the scenario classes at their window-start orientation; the other kinds at random poses) with the centres brought together until the exact signed distance is −1 % of the size (resting) or −10 % (deep; kinds that cannot reach it have fewer pairs), prediction 1 % of the size. Ours: `SmoothDispatcher`'s `contact_manifolds` on the exact shapes. Parry: `DefaultQueryDispatcher`'s manifolds on its stand-ins (ellipses and `CapsuleEllipse`s as inscribed {}-gons, rounded polygons as parry's exact `RoundConvexPolygon`, discs and boxes as themselves). Depth error: the deepest manifold point's distance against the dense-search reference signed distance, relative to the size. Each call recomputes the contact points (parry's cleared before each call, this crate's kept as rapier keeps a pair's in contact: the dispatcher recomputes them all the same).\n",
        super::POLYGON_VERTICES
    );
    println!("| pair kind | overlap | n | ours median µs | parry median µs | ratio of medians | ratio of p90s | per-pair ratio median | worst depth error/size ours | parry | median depth error/size parry |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let only = std::env::var("MANIFOLD_KIND").ok();
    for kind in kinds() {
        if only.as_ref().is_some_and(|o| !kind.name.contains(o.as_str())) {
            continue;
        }
        for (label, depth) in OVERLAPS {
            let set = pairs_at(&kind, depth, &d);
            let row = time_pairs(&set, &d);
            let r: Vec<f64> = row.ours.iter().zip(&row.parry).map(|(o, p)| p / o).collect();
            let worst = |v: &[f64]| v.iter().copied().fold(0.0f64, f64::max);
            println!(
                "| {} | {label} | {} | {} | {} | {:.2} | {:.2} | {:.2} | {} | {} | {} |",
                kind.name,
                set.len(),
                us(quantile(&row.ours, 0.5)),
                us(quantile(&row.parry, 0.5)),
                quantile(&row.parry, 0.5) / quantile(&row.ours, 0.5),
                quantile(&row.parry, 0.9) / quantile(&row.ours, 0.9),
                quantile(&r, 0.5),
                sci(worst(&row.ours_err)),
                sci(worst(&row.parry_err)),
                sci(quantile(&row.parry_err, 0.5))
            );
        }
    }
}
