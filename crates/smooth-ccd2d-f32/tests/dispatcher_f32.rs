//! The f32 dispatcher's routes: this package's pairs answer as the f64 dispatcher on the widened
//! inputs, rounded once; parry's own pairs are parry2d's untouched; composites decompose with
//! the f32 dispatcher inside; contact manifolds keep rapier's per-contact data by feature id;
//! bad input is an error, never a NaN.

#[path = "../../../tests/common/mod.rs"]
mod common;
mod common32;

use common32::{pose64, v64};
use parry2d::math::{Pose, Vector};
use parry2d::query::{
    ClosestPoints, ContactManifold, DefaultQueryDispatcher, PersistentQueryDispatcher, QueryDispatcher,
    ShapeCastOptions,
};
use parry2d::shape::{Ball, Compound, ConvexPolygon, Cuboid, HeightField, Shape, SharedShape};
use parry2d_f64::query::{PersistentQueryDispatcher as _, QueryDispatcher as _};
use smooth_ccd2d_f32::{CapsuleEllipse, Ellipse, RoundedPolygon, SmoothDispatcher};

/// A pair: (shape 1 in f32, the same in f64, shape 2 in f32, the same in f64).
type Pair = (
    Box<dyn Shape>,
    Box<dyn parry2d_f64::shape::Shape>,
    Box<dyn Shape>,
    Box<dyn parry2d_f64::shape::Shape>,
);

/// The pairs checked.
fn pairs() -> Vec<Pair> {
    let e = Ellipse::new(0.5, 0.2);
    let h = RoundedPolygon::regular(7, 0.6, 0.05);
    let c = CapsuleEllipse::new(0.3, 0.4, 0.5);
    let tri = [Vector::new(-0.4, -0.3), Vector::new(0.5, -0.2), Vector::new(0.0, 0.6)];
    let poly = ConvexPolygon::from_convex_polyline(tri.to_vec()).expect("a triangle");
    let poly64 = parry2d_f64::shape::ConvexPolygon::from_convex_polyline(tri.iter().map(|&v| v64(v)).collect())
        .expect("a triangle");
    vec![
        (
            Box::new(e),
            Box::new(*e.as_f64()),
            Box::new(Cuboid::new(Vector::new(0.4, 0.3))),
            Box::new(parry2d_f64::shape::Cuboid::new(v64(Vector::new(0.4, 0.3)))),
        ),
        (
            Box::new(h.clone()),
            Box::new(h.as_f64().clone()),
            Box::new(Ball::new(0.25)),
            Box::new(parry2d_f64::shape::Ball::new(0.25)),
        ),
        (
            Box::new(c.clone()),
            Box::new(c.as_f64().clone()),
            Box::new(poly),
            Box::new(poly64),
        ),
        (
            Box::new(h.clone()),
            Box::new(h.as_f64().clone()),
            Box::new(e),
            Box::new(*e.as_f64()),
        ),
    ]
}

fn poses() -> Vec<Pose> {
    (0..24)
        .map(|k| {
            let a = k as f32 * 0.61;
            Pose::new(Vector::new(a.cos(), a.sin()) * (0.4 + 0.05 * k as f32), 0.37 * k as f32)
        })
        .collect()
}

/// Every query of every pair: the f64 answer for the widened inputs, rounded.
#[test]
fn our_pairs_answer_as_the_f64_dispatcher_rounded() {
    let (d32, d64) = (SmoothDispatcher::default(), smooth_ccd2d::SmoothDispatcher::default());
    let mut n = 0;
    for (g1, w1, g2, w2) in pairs() {
        for pos in poses() {
            let p = pose64(&pos);
            n += 1;
            let i32 = d32.intersection_test(&pos, &*g1, &*g2).expect("intersection");
            let i64 = d64.intersection_test(&p, &*w1, &*w2).expect("intersection");
            assert_eq!(i32.intersecting, i64.intersecting);
            let dist32 = d32.distance(&pos, &*g1, &*g2).expect("distance").distance;
            let dist64 = d64.distance(&p, &*w1, &*w2).expect("distance").distance;
            assert_eq!(dist32, dist64 as f32);
            let c32 = d32.contact(&pos, &*g1, &*g2, 1.0).expect("contact");
            let c64 = d64.contact(&p, &*w1, &*w2, 1.0).expect("contact");
            assert_eq!(c32.map(|c| c.dist), c64.map(|c| c.dist as f32));
            assert_eq!(c32.map(|c| c.point1.x), c64.map(|c| c.point1.x as f32));
            match (
                d32.closest_points(&pos, &*g1, &*g2, 1.0).expect("closest"),
                d64.closest_points(&p, &*w1, &*w2, 1.0).expect("closest"),
            ) {
                (ClosestPoints::WithinMargin(a, _), parry2d_f64::query::ClosestPoints::WithinMargin(b, _)) => {
                    assert_eq!(a.x, b.x as f32)
                }
                (ClosestPoints::Intersecting, parry2d_f64::query::ClosestPoints::Intersecting)
                | (ClosestPoints::Disjoint, parry2d_f64::query::ClosestPoints::Disjoint) => {}
                (a, b) => panic!("closest points differ: {a:?} / {b:?}"),
            }
            let vel = Vector::new(-pos.translation.x, -pos.translation.y) * 2.0;
            let opts = ShapeCastOptions::with_max_time_of_impact(1.0);
            let h32 = d32.cast_shapes(&pos, vel, &*g1, &*g2, opts).expect("cast");
            let opts64 = parry2d_f64::query::ShapeCastOptions::with_max_time_of_impact(1.0);
            let h64 = d64.cast_shapes(&p, v64(vel), &*w1, &*w2, opts64).expect("cast");
            assert_eq!(h32.is_some(), h64.is_some());
            if let (Some(a), Some(b)) = (h32, h64) {
                assert!(
                    a.time_of_impact as f64 <= b.time_of_impact,
                    "{} {} {:?}",
                    a.time_of_impact,
                    b.time_of_impact,
                    b.status
                );
                assert!(
                    b.time_of_impact - (a.time_of_impact as f64) <= f32::EPSILON as f64 * b.time_of_impact,
                    "{} {} {:?}",
                    a.time_of_impact,
                    b.time_of_impact,
                    b.status
                );
            }
        }
    }
    println!("f32 dispatcher = f64 dispatcher rounded: {n} pair poses, every query");
}

/// A pair with none of this package's shapes is parry2d's, answer for answer.
#[test]
fn parry_pairs_are_parrys_own() {
    let (a, b) = (Cuboid::new(Vector::new(0.5, 0.2)), Ball::new(0.3));
    for pos in poses() {
        let ours = SmoothDispatcher::default().contact(&pos, &a, &b, 0.5).expect("contact");
        let parry = DefaultQueryDispatcher.contact(&pos, &a, &b, 0.5).expect("contact");
        assert_eq!(ours.map(|c| (c.dist, c.point1)), parry.map(|c| (c.dist, c.point1)));
    }
}

/// An ellipse inside a compound and an ellipse on a heightfield: the composite helpers call the
/// f32 dispatcher for each part, so the contacts are the exact ones.
#[test]
fn composites_decompose_with_the_f32_dispatcher() {
    let e = Ellipse::new(0.5, 0.2);
    let compound = Compound::new(vec![
        (Pose::translation(-1.0, 0.0), SharedShape::new(e)),
        (Pose::translation(1.0, 0.0), SharedShape::cuboid(0.2, 0.2)),
    ]);
    let ball = Ball::new(0.25);
    // The ball 0.1 above the compound's ellipse (top at y = 0.2).
    let pos = Pose::translation(-1.0, 0.55);
    let c = SmoothDispatcher::default()
        .contact(&pos, &compound, &ball, 0.5)
        .expect("contact")
        .expect("within");
    assert!((c.dist - 0.1).abs() < 1e-6, "{}", c.dist);
    let heights = vec![0.0; 11];
    let ground = HeightField::new(heights, Vector::new(10.0, 1.0));
    // The ellipse lying on the flat heightfield, 0.01 into it.
    let pos = Pose::translation(0.3, 0.19);
    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
    SmoothDispatcher::default()
        .contact_manifolds(&pos, &ground, &e, 0.05, &mut manifolds, &mut None)
        .expect("manifolds");
    let deepest = manifolds
        .iter()
        .flat_map(|m| m.points.iter().map(move |p| (m.local_n1, p.dist)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("a contact");
    assert!((deepest.0 - Vector::Y).length() < 1e-6, "{:?}", deepest.0);
    assert!((deepest.1 + 0.01).abs() < 1e-6, "{}", deepest.1);
    // The same manifolds as the f64 dispatcher's on the f64 heightfield (the neighbouring
    // segment's end gives a predicted contact too, in f64 as in parry), to the f32 rounding of
    // the sub-shape poses that parry2d's composite helpers compose in f32.
    let ground64 = parry2d_f64::shape::HeightField::new(vec![0.0; 11], parry2d_f64::math::Vector::new(10.0, 1.0));
    let mut m64: Vec<parry2d_f64::query::ContactManifold<(), ()>> = Vec::new();
    smooth_ccd2d::SmoothDispatcher::default()
        .contact_manifolds(&pose64(&pos), &ground64, e.as_f64(), 0.05, &mut m64, &mut None)
        .expect("manifolds");
    let a: Vec<_> = manifolds
        .iter()
        .flat_map(|m| m.points.iter().map(|p| (m.subshape1, p.dist)))
        .collect();
    let b: Vec<_> = m64
        .iter()
        .flat_map(|m| m.points.iter().map(|p| (m.subshape1, p.dist)))
        .collect();
    assert_eq!(a.len(), b.len());
    for ((s1, d1), (s2, d2)) in a.into_iter().zip(b) {
        assert_eq!(s1, s2);
        assert!((d1 as f64 - d2).abs() <= 1e-6, "{d1} / {d2}");
    }
}

/// rapier's per-contact data survives a recomputation where the contact keeps its ids, as in
/// parry's own manifolds.
#[test]
fn contact_data_is_kept_by_feature_id() {
    let d = SmoothDispatcher::default();
    let h = RoundedPolygon::regular(4, 0.5, 0.05);
    let ground = Cuboid::new(Vector::new(5.0, 0.5));
    let mut manifolds: Vec<ContactManifold<(), u32>> = Vec::new();
    // A rounded square (core half-side 0.5/√2, turned by π/4 to sit on a face) resting on the
    // box top, 1e-3 into it: two points, one per end of the facing faces.
    let quarter = std::f32::consts::FRAC_PI_4;
    let pos = Pose::new(Vector::new(0.0, 0.5 + 0.5f32.sqrt() * 0.5 + 0.05 - 1e-3), quarter);
    d.contact_manifolds(&pos, &ground, &h, 0.05, &mut manifolds, &mut None)
        .expect("manifolds");
    // Three manifolds: the pair's points, then the bodies' core contacts (both have a core, both
    // along the pair's normal: the box's face under the square's centre, the square's face over
    // the box's: they share the first, the second is empty).
    assert_eq!(manifolds.len(), 3);
    assert_eq!(manifolds[0].points.len(), 2);
    assert_eq!(manifolds[1].points.len(), 2);
    assert!(manifolds[2].points.is_empty());
    for (k, p) in manifolds.iter_mut().flat_map(|m| m.points.iter_mut()).enumerate() {
        p.data = 7 + k as u32;
    }
    let ids = |ms: &[ContactManifold<(), u32>]| -> Vec<Vec<_>> {
        ms.iter()
            .map(|m| m.points.iter().map(|p| (p.fid1, p.fid2, p.data)).collect())
            .collect()
    };
    let before = ids(&manifolds);
    for m in before.iter().filter(|m| !m.is_empty()) {
        assert_ne!((m[0].0, m[0].1), (m[1].0, m[1].1), "distinct ids");
    }
    let moved = Pose::new(pos.translation + Vector::new(1e-4, -1e-4), quarter);
    d.contact_manifolds(&moved, &ground, &h, 0.05, &mut manifolds, &mut None)
        .expect("manifolds");
    assert_eq!(before, ids(&manifolds));
}

/// Non-finite poses and motions are refused (`Unsupported`), never answered with a NaN.
#[test]
fn bad_input_is_an_error_not_a_nan() {
    let d = SmoothDispatcher::default();
    let (e, b) = (Ellipse::new(0.5, 0.2), Ball::new(0.3));
    let bad = Pose::translation(f32::NAN, 0.0);
    assert!(d.distance(&bad, &e, &b).is_err());
    assert!(d.contact(&bad, &e, &b, 0.1).is_err());
    assert!(d.contact(&Pose::IDENTITY, &e, &b, -1.0).is_err());
    let m = parry2d::query::NonlinearRigidMotion::new(
        Pose::translation(-3.0, 0.0),
        Vector::ZERO,
        Vector::new(f32::INFINITY, 0.0),
        0.0,
    );
    let r = d.cast_shapes_nonlinear(
        &m,
        &e,
        &parry2d::query::NonlinearRigidMotion::identity(),
        &b,
        0.0,
        1.0,
        true,
    );
    assert!(r.is_err());
    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
    let r = d.contact_manifolds(&bad, &e, &b, 0.1, &mut manifolds, &mut None);
    assert!(r.is_err() && manifolds.iter().all(|m| m.points.is_empty()));
}

/// Bad input on a composite pair is refused as in f64, before parry2d's composite helpers
/// (which assert on a negative margin and pass NaN through).
#[test]
fn bad_input_on_composites_is_an_error_not_a_panic() {
    let d = SmoothDispatcher::default();
    let compound = Compound::new(vec![
        (Pose::translation(-1.0, 0.0), SharedShape::new(Ellipse::new(0.5, 0.2))),
        (Pose::translation(1.0, 0.0), SharedShape::ball(0.2)),
    ]);
    let b = Ball::new(0.3);
    let (ok, bad) = (Pose::translation(0.0, 3.0), Pose::translation(f32::NAN, 0.0));
    assert!(d.contact(&ok, &compound, &b, -1.0).is_err());
    assert!(d.contact(&ok, &compound, &b, f32::NAN).is_err());
    assert!(d.closest_points(&ok, &compound, &b, -1.0).is_err());
    assert!(d.distance(&bad, &compound, &b).is_err());
    assert!(d
        .distance(&Pose::translation(f32::INFINITY, 0.0), &b, &compound)
        .is_err());
    assert!(d.intersection_test(&bad, &compound, &b).is_err());
    assert!(d.contact(&bad, &compound, &b, 0.1).is_err());
    let m = parry2d::query::NonlinearRigidMotion::new(ok, Vector::ZERO, Vector::new(0.0, f32::NAN), 0.0);
    let still = parry2d::query::NonlinearRigidMotion::identity();
    assert!(d
        .cast_shapes_nonlinear(&still, &compound, &m, &b, 0.0, 1.0, true)
        .is_err());
    let m = parry2d::query::NonlinearRigidMotion::new(ok, Vector::ZERO, Vector::new(0.0, -1.0), 0.0);
    assert!(d
        .cast_shapes_nonlinear(&still, &compound, &m, &b, 0.0, f32::INFINITY, true)
        .is_err());
    assert!(d
        .cast_shapes_nonlinear(&still, &compound, &m, &b, 1.0, 0.0, true)
        .is_err());
    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
    assert!(d
        .contact_manifolds(&bad, &compound, &b, 0.1, &mut manifolds, &mut None)
        .is_err());
    assert!(d
        .contact_manifolds(&ok, &compound, &b, -0.1, &mut manifolds, &mut None)
        .is_err());
    // Good input still answers, as the f64 dispatcher on the same compound.
    let compound64 = parry2d_f64::shape::Compound::new(vec![
        (
            parry2d_f64::math::Pose::translation(-1.0, 0.0),
            parry2d_f64::shape::SharedShape::new(smooth_ccd2d::Ellipse::new(0.5, 0.2)),
        ),
        (
            parry2d_f64::math::Pose::translation(1.0, 0.0),
            parry2d_f64::shape::SharedShape::ball(0.2),
        ),
    ]);
    let c = d.distance(&ok, &compound, &b).expect("distance").distance;
    let c64 = smooth_ccd2d::SmoothDispatcher::default()
        .distance(&pose64(&ok), &compound64, &parry2d_f64::shape::Ball::new(0.3))
        .expect("distance")
        .distance;
    assert!((c as f64 - c64).abs() < 1e-6, "{c} / {c64}");
}

/// A constrained pair (a compound with internal edges fixed gives its parts pseudo-normals)
/// takes the f64 crate's constrained route: the same manifold as the f64 dispatcher's on the same
/// compound, ids included.
#[test]
fn constrained_pairs_take_the_f64_constrained_route() {
    use parry2d::shape::CompoundFlags;
    let box_at = |x: f32| (Pose::translation(x, 0.0), SharedShape::cuboid(0.5, 0.5));
    let ground = Compound::with_flags(vec![box_at(0.0), box_at(1.0)], CompoundFlags::FIX_INTERNAL_EDGES, None);
    let box64 = |x: f64| {
        (
            parry2d_f64::math::Pose::translation(x, 0.0),
            parry2d_f64::shape::SharedShape::cuboid(0.5, 0.5),
        )
    };
    let ground64 = parry2d_f64::shape::Compound::with_flags(
        vec![box64(0.0), box64(1.0)],
        parry2d_f64::shape::CompoundFlags::FIX_INTERNAL_EDGES,
        None,
    );
    let square = RoundedPolygon::regular(4, 0.4, 0.05);
    let (d32, d64) = (SmoothDispatcher::default(), smooth_ccd2d::SmoothDispatcher::default());
    let mut compared = 0;
    for k in 0..16 {
        // A rounded square on the compound's top (y = 0.5), across the internal edge at x = 0.5.
        let pos = Pose::new(
            Vector::new(0.1 + 0.05 * k as f32, 0.5 + 0.4 * 0.5f32.sqrt() + 0.05 - 2e-3),
            0.785 + 0.02 * k as f32,
        );
        let mut m32: Vec<ContactManifold<(), ()>> = Vec::new();
        let mut m64: Vec<parry2d_f64::query::ContactManifold<(), ()>> = Vec::new();
        d32.contact_manifolds(&pos, &ground, &square, 0.05, &mut m32, &mut None)
            .expect("manifolds");
        d64.contact_manifolds(&pose64(&pos), &ground64, square.as_f64(), 0.05, &mut m64, &mut None)
            .expect("manifolds");
        let a: Vec<_> = m32
            .iter()
            .flat_map(|m| m.points.iter().map(move |p| (m.subshape1, p.fid1.0, p.fid2.0, p.dist)))
            .collect();
        let b: Vec<_> = m64
            .iter()
            .flat_map(|m| m.points.iter().map(move |p| (m.subshape1, p.fid1.0, p.fid2.0, p.dist)))
            .collect();
        assert_eq!(a.len(), b.len(), "pose {k}: {a:?} / {b:?}");
        for (x, y) in a.iter().zip(&b) {
            assert_eq!((x.0, x.1, x.2), (y.0, y.1, y.2), "pose {k}");
            assert!((x.3 as f64 - y.3).abs() <= 1e-6, "pose {k}: {} / {}", x.3, y.3);
            compared += 1;
        }
    }
    assert!(compared > 16, "{compared}");
    println!("constrained pairs: {compared} points with the f64 ids");
}

/// The f32 dispatcher's manifold is the f64 one rounded (points, distances and ids).
#[test]
fn manifolds_are_the_f64_manifolds_rounded() {
    let (d32, d64) = (SmoothDispatcher::default(), smooth_ccd2d::SmoothDispatcher::default());
    let mut n = 0;
    for (g1, w1, g2, w2) in pairs() {
        for pos in poses() {
            let mut m32: Vec<ContactManifold<(), ()>> = Vec::new();
            let mut m64: Vec<parry2d_f64::query::ContactManifold<(), ()>> = Vec::new();
            d32.contact_manifolds(&pos, &*g1, &*g2, 1.0, &mut m32, &mut None)
                .expect("manifolds");
            d64.contact_manifolds(&pose64(&pos), &*w1, &*w2, 1.0, &mut m64, &mut None)
                .expect("manifolds");
            let a: Vec<_> = m32
                .iter()
                .flat_map(|m| m.points.iter().map(|p| (p.dist, p.fid1.0, p.fid2.0)))
                .collect();
            let b: Vec<_> = m64
                .iter()
                .flat_map(|m| m.points.iter().map(|p| (p.dist as f32, p.fid1.0, p.fid2.0)))
                .collect();
            assert_eq!(a, b);
            n += a.len();
        }
    }
    println!("manifolds: {n} points equal to the f64 ones rounded");
}

/// One of this package's shapes against a shape the f64 crate does not take (here a half-space
/// whose normal is not finite) goes to parry2d through the support map, under the same guards:
/// an error, never a NaN.
#[test]
fn our_shape_against_a_shape_the_core_refuses_is_guarded() {
    let d = SmoothDispatcher::default();
    let e = Ellipse::new(0.5, 0.2);
    let bad_plane = parry2d::shape::HalfSpace::new(Vector::new(f32::NAN, 1.0));
    let pos = Pose::translation(0.0, 1.0);
    assert!(d.intersection_test(&pos, &bad_plane, &e).is_err());
    assert!(d.distance(&pos, &bad_plane, &e).is_err());
    assert!(d.contact(&pos, &e, &bad_plane, 0.1).is_err());
    assert!(d.closest_points(&pos, &bad_plane, &e, 0.1).is_err());
    let opts = ShapeCastOptions::with_max_time_of_impact(1.0);
    assert!(d
        .cast_shapes(&pos, Vector::new(0.0, -1.0), &bad_plane, &e, opts)
        .is_err());
    let still = parry2d::query::NonlinearRigidMotion::identity();
    let falling = parry2d::query::NonlinearRigidMotion::new(pos, Vector::ZERO, Vector::new(0.0, -1.0), 0.0);
    assert!(d
        .cast_shapes_nonlinear(&still, &bad_plane, &falling, &e, 0.0, 1.0, true)
        .is_err());
    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
    assert!(d
        .contact_manifolds(&pos, &bad_plane, &e, 0.1, &mut manifolds, &mut None)
        .is_err());
    assert!(manifolds.iter().all(|m| m.points.is_empty()));
    // A good half-space is the f64 crate's: the ellipse 1 above the plane y = 0, 0.8 apart.
    let plane = parry2d::shape::HalfSpace::new(Vector::Y);
    let dist = d.distance(&pos, &plane, &e).expect("distance").distance;
    assert!((dist - 0.8).abs() < 1e-6, "{dist}");
}

/// A cast against a composite at rest (rapier's CCD against level geometry), which the f32
/// dispatcher answers part by part with the f64 dispatcher's culling (the shared composite
/// helpers, computed in f32 here): the earliest hit over every part cast on its own, to the bit.
#[test]
fn a_cast_against_a_composite_at_rest_is_the_earliest_hit_over_every_part_in_f32() {
    use parry2d::query::NonlinearRigidMotion;
    use parry2d::shape::{Polyline, Segment};
    let d = SmoothDispatcher::default();
    let mut rng = common::rng::Rng::new(0xF32C_0A57);
    let dt = 1.0 / 60.0;
    let bodies: Vec<Box<dyn Shape>> = vec![
        Box::new(Ellipse::new(0.5, 0.2)),
        Box::new(Ellipse::new(0.3, 0.3)),
        Box::new(RoundedPolygon::regular(6, 0.4, 0.05)),
        Box::new(CapsuleEllipse::new(0.2, 0.3, 0.4)),
    ];
    let (mut cases, mut hits) = (0usize, 0usize);
    for _ in 0..1000 {
        let n = rng.int(8, 40);
        let points: Vec<Vector> = (0..=n)
            .map(|i| Vector::new(-10.0 + 20.0 * i as f32 / n as f32, rng.uniform(-0.3, 0.3) as f32))
            .collect();
        let ground = Polyline::new(points.clone(), None);
        let pose = Pose::new(
            Vector::new(rng.uniform(-1.0, 1.0) as f32, rng.uniform(-1.0, 1.0) as f32),
            rng.uniform(-0.3, 0.3) as f32,
        );
        for body in &bodies {
            let start = pose
                * Pose::new(
                    Vector::new(rng.uniform(-9.0, 9.0) as f32, rng.uniform(0.0, 1.2) as f32),
                    rng.angle() as f32,
                );
            let dir = Vector::new(rng.uniform(-1.0, 1.0) as f32, rng.uniform(-1.0, 0.3) as f32).normalize();
            // None, within a step's quarter turn, up to about half a turn, far beyond.
            let spin = match rng.int(0, 3) {
                0 => 0.0,
                1 => rng.uniform(0.0, 3.0),
                2 => rng.uniform(3.0, 180.0),
                _ => 1e4,
            } as f32
                * rng.sign() as f32;
            let mb = NonlinearRigidMotion::new(start, Vector::ZERO, dir * rng.log_uniform(1.0, 3000.0) as f32, spin);
            let mc = NonlinearRigidMotion::constant_position(pose);
            let got = d
                .cast_shapes_nonlinear(&mb, body.as_ref(), &mc, &ground, 0.0, dt, false)
                .expect("a composite at rest is supported")
                .map(|h| h.time_of_impact);
            let mut want: Option<f32> = None;
            for w in points.windows(2) {
                let part = Segment::new(w[0], w[1]);
                if let Ok(Some(h)) = d.cast_shapes_nonlinear(&mb, body.as_ref(), &mc, &part, 0.0, dt, false) {
                    if want.is_none_or(|b| h.time_of_impact < b) {
                        want = Some(h.time_of_impact);
                    }
                }
            }
            assert_eq!(
                got.map(f32::to_bits),
                want.map(f32::to_bits),
                "{:?} ({mb:?}): {got:?} vs {want:?}",
                body.shape_type()
            );
            cases += 1;
            hits += usize::from(got.is_some());
        }
    }
    println!("{cases} f32 composite casts ({hits} hits)");
}

#[test]
fn an_oriented_chain_is_one_sided_to_rapier_s_casts_in_f32() {
    use parry2d::query::NonlinearRigidMotion;
    use parry2d::shape::{Polyline, PolylineFlags};
    use smooth_ccd2d_f32::CastPolicy;
    // A flat chain facing up (vertices from right to left), oriented or not; an ellipse coming
    // up through it from 0.2 m behind at 30 m/s, spinning.
    let chain = |flags| {
        let points = (0..=20)
            .rev()
            .map(|i| Vector::new(-1.5 + 0.15 * i as f32, 0.0))
            .collect();
        Polyline::with_flags(points, None, flags)
    };
    let body = Ellipse::new(0.5, 0.1);
    let mb = NonlinearRigidMotion::new(
        Pose::new(Vector::new(0.07, -0.3), 0.2),
        Vector::ZERO,
        Vector::new(1.0, 30.0),
        5.0,
    );
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let cast = |policy, ground: &Polyline| {
        SmoothDispatcher::default()
            .with_cast_policy(policy)
            .cast_shapes_nonlinear(&mb, &body, &still, ground, 0.0, 1.0 / 60.0, false)
            .expect("a composite at rest is supported")
    };
    let oriented = chain(PolylineFlags::ORIENTED);
    assert!(cast(CastPolicy::Rapier, &oriented).is_none());
    assert!(cast(CastPolicy::Plain, &oriented).is_some());
    assert!(cast(CastPolicy::Rapier, &chain(PolylineFlags::empty())).is_some());
}

#[test]
fn an_oriented_chain_holds_an_ellipse_near_its_inner_vertex_by_one_point_in_f32() {
    use parry2d::query::{ContactManifold, PersistentQueryDispatcher};
    use parry2d::shape::{Polyline, PolylineFlags};
    // A flat chain of 0.25 m segments facing up (vertices right to left), an inner vertex at the
    // origin; an ellipse 0.1 mm above it, its lowest point 2 cm left of the vertex. Two-sided,
    // the segment right of the vertex keeps a point at the vertex (rapier's ghost contact);
    // oriented, its pseudo-normals turn the normal up and the vertical line through the lowest
    // point misses it: only the segment under the ellipse holds it (tests/internal_vertices.rs
    // in f64).
    let chain = |flags| {
        let points = (-20..=20).rev().map(|i| Vector::new(0.25 * i as f32, 0.0)).collect();
        Polyline::with_flags(points, None, flags)
    };
    let ellipse = Ellipse::new(0.5, 0.2);
    let pos12 = Pose::translation(-0.02, 0.2 + 1e-4);
    let holding = |flags| {
        let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
        PersistentQueryDispatcher::<(), ()>::contact_manifolds(
            &SmoothDispatcher::default(),
            &pos12,
            &chain(flags),
            &ellipse,
            0.002,
            &mut manifolds,
            &mut None,
        )
        .expect("supported");
        let mut parts: Vec<u32> = manifolds
            .iter()
            .filter(|m| !m.points.is_empty())
            .map(|m| m.subshape1)
            .collect();
        parts.sort_unstable();
        parts
    };
    assert_eq!(holding(PolylineFlags::empty()), vec![19, 20]);
    assert_eq!(holding(PolylineFlags::ORIENTED), vec![20]);
}

/// A polyline's and a heightfield's part against this package's sliver in f32, its long side
/// tilted 0.3 rad off the wall with its tip on it: the part's points (the tip and the side's
/// far end, 0.3 away) and, in a manifold of its own after them, the sliver's core contact, both
/// with the part's sub-shape id (`tests/zero_thickness.rs` in f64).
#[test]
fn a_chain_part_keeps_the_far_point_and_its_core_contact_in_two_manifolds_in_f32() {
    use parry2d::query::{ContactManifold, PersistentQueryDispatcher};
    use parry2d::shape::Polyline;
    let sliver = RoundedPolygon::new(
        &[Vector::new(-0.5, 0.0), Vector::new(-0.25, 0.0), Vector::new(0.5, 0.125)],
        0.0,
    );
    let side = Vector::new(1.0, 0.125);
    let rot = parry2d::math::Rotation::new(core::f32::consts::PI - 0.3 - side.y.atan2(side.x));
    let pos12 = Pose::from_parts(Vector::new(2.0, 0.0) - rot * Vector::new(-0.5, 0.0), rot);
    let walls: [Box<dyn Shape>; 2] = [
        Box::new(Polyline::new(
            vec![Vector::new(-10.0, 0.0), Vector::new(0.0, 0.0), Vector::new(10.0, 0.0)],
            None,
        )),
        Box::new(HeightField::new(vec![0.0, 0.0, 0.0], Vector::new(20.0, 1.0))),
    ];
    for wall in &walls {
        let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
        PersistentQueryDispatcher::<(), ()>::contact_manifolds(
            &SmoothDispatcher::default(),
            &pos12,
            &**wall,
            &sliver,
            0.002,
            &mut manifolds,
            &mut None,
        )
        .expect("supported");
        let what = format!("{:?}: {manifolds:?}", wall.shape_type());
        let held: Vec<&ContactManifold<(), ()>> = manifolds.iter().filter(|m| !m.points.is_empty()).collect();
        assert_eq!(held.len(), 2, "{what}");
        assert_eq!(held[0].subshape1, held[1].subshape1, "{what}");
        assert_eq!(held[0].points.len(), 2, "{what}");
        assert!(
            held[0]
                .points
                .iter()
                .all(|p| !smooth_ccd2d::__is_core_feature(p.fid2.0)),
            "{what}"
        );
        assert!(held[0].points.iter().any(|p| p.dist > 0.2), "the far end: {what}");
        assert_eq!(held[1].points.len(), 1, "{what}");
        assert!(smooth_ccd2d::__is_core_feature(held[1].points[0].fid2.0), "{what}");
    }
}
