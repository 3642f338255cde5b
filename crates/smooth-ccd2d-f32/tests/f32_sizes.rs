//! Issue 32, item 8 and its fuzz: the f32 shapes at every size from 1e-30 to 1e30.
//!
//! * `f32_mass_properties_are_finite_at_every_size`: f32 shapes of 1e-10 and below reported
//!   `inv_principal_inertia = ∞` (below about 1e-19 `inv_mass = ∞` too), the f64 inverse rounded
//!   to f32; now an inverse that leaves f32's range is 0, as parry2d reports for its own shapes
//!   whose mass or inertia rounds to 0. (parry2d's own ball is not finite everywhere: between
//!   the sizes where its inertia or mass is subnormal in f32 and where it is 0 it reports ∞ —
//!   printed, not this package's.)
//! * `rapier2d_bodies_of_every_size_stay_finite`: the body whose angular velocity was NaN at
//!   the first step.
//! * `every_f32_query_at_sizes_1e_minus_30_to_1e30_is_finite`: every query of the f32
//!   dispatcher on every pair with one of the package's shapes (the other one of them or
//!   parry2d's ball or box) and every query of the package's shapes, at each size: no panic, no
//!   NaN or infinity in an answer (an `Unsupported` is an answer); counts printed. Pairs of
//!   parry2d's own shapes are parry2d's.

use parry2d::math::{Pose, Vector};
use parry2d::query::details::ShapeCastOptions;
use parry2d::query::{
    ClosestPoints, ContactManifold, NonlinearRigidMotion, PersistentQueryDispatcher, QueryDispatcher, Ray,
};
use parry2d::shape::{Ball, Cuboid, Shape, SharedShape};
use smooth_ccd2d_f32::{CapsuleEllipse, CustomCurve, Ellipse, RoundedPolygon, SmoothDispatcher};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The sizes: 10^k for k in −30 … 30.
fn sizes() -> impl Iterator<Item = f32> {
    (-30..=30).map(|k| 10f32.powi(k))
}

/// Whether a shape of [`shapes`] is this package's (not parry2d's).
fn ours(name: &str) -> bool {
    !name.starts_with("parry2d")
}

/// The package's four shapes (and parry2d's ball and box) at size `s`.
fn shapes(s: f32) -> Vec<(&'static str, SharedShape)> {
    vec![
        ("ellipse", SharedShape::new(Ellipse::new(s, 0.4 * s))),
        (
            "rounded polygon",
            SharedShape::new(RoundedPolygon::regular(6, s, 0.1 * s)),
        ),
        (
            "capsule-ellipse",
            SharedShape::new(CapsuleEllipse::new(0.4 * s, 0.3 * s, 0.5 * s)),
        ),
        (
            "custom curve",
            SharedShape::new(CustomCurve::new(smooth_ccd2d::Ellipse::new(s as f64, 0.6 * s as f64))),
        ),
        ("parry2d ball", SharedShape::new(Ball::new(s))),
        ("parry2d box", SharedShape::new(Cuboid::new(Vector::new(s, 0.5 * s)))),
    ]
}

#[test]
fn f32_mass_properties_are_finite_at_every_size() {
    // Per shape: the largest small size (< 1) and the smallest large size (> 1) at which an
    // inverse is 0 (the mass or inertia out of f32's range: parry2d's convention).
    let mut ranges: Vec<(&str, [f32; 4])> = Vec::new();
    let mut parry_infinite = Vec::new();
    for s in sizes() {
        for (name, g) in shapes(s) {
            if !ours(name) {
                let m = g.mass_properties(1.0);
                if !(m.inv_mass.is_finite() && m.inv_principal_inertia.is_finite()) {
                    parry_infinite.push(format!("{name} {s:e}"));
                }
                continue;
            }
            for density in [1.0f32, 1e-3, 1e3] {
                let m = g.mass_properties(density);
                assert!(
                    m.inv_mass.is_finite() && m.inv_principal_inertia.is_finite() && m.local_com.is_finite(),
                    "{name} of size {s:e}, density {density}: {m:?}"
                );
                assert!(
                    m.inv_mass >= 0.0 && m.inv_principal_inertia >= 0.0,
                    "{name} {s:e}: {m:?}"
                );
            }
            let m = g.mass_properties(1.0);
            let i = match ranges.iter().position(|(n, _)| *n == name) {
                Some(i) => i,
                None => {
                    ranges.push((name, [0.0, f32::INFINITY, 0.0, f32::INFINITY]));
                    ranges.len() - 1
                }
            };
            let r = &mut ranges[i].1;
            for (k, inv) in [m.inv_principal_inertia, m.inv_mass].into_iter().enumerate() {
                if inv == 0.0 && s < 1.0 {
                    r[2 * k] = r[2 * k].max(s);
                }
                if inv == 0.0 && s > 1.0 {
                    r[2 * k + 1] = r[2 * k + 1].min(s);
                }
            }
        }
    }
    for (name, [i_lo, i_hi, m_lo, m_hi]) in &ranges {
        println!(
            "{name}: inverse inertia 0 at sizes ≤ {i_lo:e} and ≥ {i_hi:e}, inverse mass 0 at ≤ {m_lo:e} and ≥ {m_hi:e}"
        );
    }
    println!(
        "parry2d's own shapes (not this package's), an inverse mass or inertia ∞: {}",
        parry_infinite.join(", ")
    );
    // At the ordinary sizes, the f64 answer rounded.
    let e = Ellipse::new(0.5, 0.2);
    let (m32, m64) = (
        e.mass_properties(2.0),
        parry2d_f64::shape::Shape::mass_properties(e.as_f64(), 2.0),
    );
    assert_eq!(m32.inv_mass, m64.inv_mass as f32);
    assert_eq!(m32.inv_principal_inertia, m64.inv_principal_inertia as f32);
}

#[test]
fn rapier2d_bodies_of_every_size_stay_finite() {
    use rapier2d::prelude::*;
    for s in [1e-30f32, 1e-19, 1e-12, 1e-10, 1.0, 1e10, 1e19, 1e30] {
        for (name, shape) in shapes(s).into_iter().filter(|(n, _)| ours(n)) {
            let mut w = PhysicsWorld {
                narrow_phase: NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
                ..PhysicsWorld::default()
            };
            let body = RigidBodyBuilder::dynamic().angvel(3.0).linvel(Vector::new(s, 0.0));
            let (h, _) = w.insert(body, ColliderBuilder::new(shape));
            for _ in 0..5 {
                w.step();
            }
            let b = &w.bodies[h];
            assert!(
                b.angvel().is_finite() && b.linvel().is_finite() && b.translation().is_finite(),
                "{name} of size {s:e}: angvel {}, linvel {:?}, at {:?}",
                b.angvel(),
                b.linvel(),
                b.translation()
            );
        }
    }
}

/// Every number of a query's answer, to check them all finite.
fn numbers_of_contact(c: &parry2d::query::Contact) -> Vec<f32> {
    vec![
        c.dist,
        c.point1.x,
        c.point1.y,
        c.point2.x,
        c.point2.y,
        c.normal1.x,
        c.normal1.y,
        c.normal2.x,
        c.normal2.y,
    ]
}

#[test]
fn every_f32_query_at_sizes_1e_minus_30_to_1e30_is_finite() {
    let d = SmoothDispatcher::default();
    let (mut queries, mut unsupported, mut bad) = (0usize, 0usize, Vec::new());
    for s in sizes() {
        let all = shapes(s);
        for (n1, g1) in &all {
            // The shape's own queries (this package's shapes).
            let r = (ours(n1)).then(|| {
                catch_unwind(AssertUnwindSafe(|| {
                    let mut v = Vec::new();
                    let a = g1.compute_local_aabb();
                    v.extend([
                        a.mins.x,
                        a.mins.y,
                        a.maxs.x,
                        a.maxs.y,
                        g1.compute_local_bounding_sphere().radius,
                    ]);
                    v.push(g1.ccd_thickness());
                    let hit = g1.cast_local_ray_and_get_normal(
                        &Ray::new(Vector::new(-3.0 * s, 0.1 * s), Vector::X),
                        10.0,
                        true,
                    );
                    if let Some(h) = hit {
                        v.extend([h.time_of_impact, h.normal.x, h.normal.y]);
                    }
                    let p = g1.project_local_point(Vector::new(0.3 * s, 2.0 * s), true);
                    v.extend([p.point.x, p.point.y]);
                    v
                }))
            });
            match r {
                None => {}
                Some(Ok(v)) if v.iter().all(|x| x.is_finite()) => queries += 4,
                Some(Ok(v)) => bad.push(format!("{n1} at {s:e}: shape queries {v:?}")),
                Some(Err(_)) => bad.push(format!("{n1} at {s:e}: shape queries panicked")),
            }
            for (n2, g2) in &all {
                if !(ours(n1) || ours(n2)) {
                    continue;
                }
                let pose = Pose::new(Vector::new(1.5 * s, 0.3 * s), 0.4);
                let m1 = NonlinearRigidMotion::new(
                    Pose::new(Vector::new(-3.0 * s, 0.0), 0.0),
                    Vector::ZERO,
                    Vector::new(4.0 * s, 0.0),
                    5.0,
                );
                let m2 = NonlinearRigidMotion::constant_position(Pose::new(Vector::ZERO, 0.3));
                let r = catch_unwind(AssertUnwindSafe(|| {
                    let mut v: Vec<f32> = Vec::new();
                    let mut errs = 0;
                    match d.intersection_test(&pose, &**g1, &**g2) {
                        Ok(_) => {}
                        Err(_) => errs += 1,
                    }
                    match d.distance(&pose, &**g1, &**g2) {
                        Ok(r) => v.push(r.distance),
                        Err(_) => errs += 1,
                    }
                    match d.contact(&pose, &**g1, &**g2, 0.1 * s) {
                        Ok(Some(c)) => v.extend(numbers_of_contact(&c)),
                        Ok(None) => {}
                        Err(_) => errs += 1,
                    }
                    match d.closest_points(&pose, &**g1, &**g2, 0.5 * s) {
                        Ok(ClosestPoints::WithinMargin(a, b)) => v.extend([a.x, a.y, b.x, b.y]),
                        Ok(_) => {}
                        Err(_) => errs += 1,
                    }
                    let opts = ShapeCastOptions::with_max_time_of_impact(2.0);
                    match d.cast_shapes(&pose, Vector::new(-s, 0.0), &**g1, &**g2, opts) {
                        Ok(Some(h)) => v.extend([h.time_of_impact, h.normal1.x, h.normal1.y, h.witness1.x]),
                        Ok(None) => {}
                        Err(_) => errs += 1,
                    }
                    for stop in [true, false] {
                        match d.cast_shapes_nonlinear(&m1, &**g1, &m2, &**g2, 0.0, 1.0, stop) {
                            Ok(Some(h)) => v.extend([h.time_of_impact, h.normal1.x, h.witness2.y]),
                            Ok(None) => {}
                            Err(_) => errs += 1,
                        }
                    }
                    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
                    match d.contact_manifolds(&pose, &**g1, &**g2, 0.1 * s, &mut manifolds, &mut None) {
                        Ok(()) => {
                            for m in &manifolds {
                                for p in &m.points {
                                    v.extend([p.dist, p.local_p1.x, p.local_p2.y]);
                                }
                            }
                        }
                        Err(_) => errs += 1,
                    }
                    (v, errs)
                }));
                queries += 8;
                match r {
                    Ok((v, errs)) => {
                        unsupported += errs;
                        if !v.iter().all(|x| x.is_finite()) {
                            bad.push(format!("{n1} / {n2} at {s:e}: {v:?}"));
                        }
                    }
                    Err(_) => bad.push(format!("{n1} / {n2} at {s:e}: a query panicked")),
                }
            }
        }
    }
    println!(
        "f32 sizes 1e-30 … 1e30: {queries} queries, {unsupported} answered Unsupported, {} with a non-finite number or a panic",
        bad.len()
    );
    for b in bad.iter().take(10) {
        println!("  {b}");
    }
    assert!(bad.is_empty(), "{} queries broke a promise", bad.len());
}
