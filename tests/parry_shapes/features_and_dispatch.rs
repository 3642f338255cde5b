//! Polygonal features, parry's default dispatcher and rapier's default narrow phase on the
//! crate's shapes, bad input, scaling, and the shapes' parry traits.

use super::*;

fn feature_of(shape: &dyn Shape, dir: Vector) -> PolygonalFeature {
    let (pfm, radius) = shape.as_polygonal_feature_map().unwrap();
    assert_eq!(radius, 0.0);
    let mut f = PolygonalFeature::default();
    pfm.local_support_feature(dir, &mut f);
    f
}

#[test]
fn polygonal_features_are_segments_touching_the_support_level() {
    let mut rng = Rng::new(13);
    for c in cases() {
        let sm = c.shape.as_support_map().unwrap();
        let mut dirs: Vec<Vector> = (0..300).map(|_| rng.direction()).collect();
        dirs.extend([
            Vector::X,
            -Vector::X,
            Vector::Y,
            -Vector::Y,
            Vector::new(1.0, 1e-3).normalize(),
        ]);
        for n in dirs {
            let f = feature_of(&*c.shape, n * 2.5);
            assert_eq!(f.num_vertices, 2, "{}", c.name);
            let [v0, v1] = f.vertices;
            assert!(v0.is_finite() && v1.is_finite());
            assert!((v1 - v0).length() > 0.0, "{}: degenerate feature", c.name);
            assert_ne!(f.vids[0], f.vids[1]);
            // Counter-clockwise seen from outside: v1 − v0 turns with the tangent perp(n).
            assert!(
                (v1 - v0).dot(Vector::new(-n.y, n.x)) > 0.0,
                "{}: feature orientation",
                c.name
            );
            // Its highest vertex is at the support level: parry reads contact distances off it.
            let h = sm.local_support_point(n).dot(n);
            let top = v0.dot(n).max(v1.dot(n));
            assert!(
                (top - h).abs() <= 1e-12 * c.size,
                "{}: feature at {top}, support at {h}",
                c.name
            );
            // Both vertices lie in the shape (up to rounding) or on its tangent line.
            for v in [v0, v1] {
                assert!(v.dot(n) <= h + 1e-12 * c.size);
            }
        }
    }
    // Smooth points give a short tangent segment; flat sides give the whole side.
    let e = Ellipse::new(1.0, 0.001);
    let f = feature_of(&e, Vector::X);
    assert!((f.vertices[1] - f.vertices[0]).length() <= 1e-6);
    let cap = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let f = feature_of(&cap, Vector::new(1.0, 0.01));
    assert!((f.vertices[0] - Vector::new(0.5, -1.0)).length() < 1e-12);
    assert!((f.vertices[1] - ConvexCurve::support_point(&cap, Vector::new(1.0, 0.01).normalize())).length() < 1e-12);
    let sq = RoundedPolygon::regular(4, 1.0, 0.1);
    let f = feature_of(&sq, Vector::new(1.0, 1.0));
    assert!(((f.vertices[1] - f.vertices[0]).length() - 2f64.sqrt()).abs() < 1e-12);
}

fn manifolds(pos12: &Pose, s1: &dyn Shape, s2: &dyn Shape, prediction: f64) -> Vec<ContactManifold<(), ()>> {
    let mut out: Vec<ContactManifold<(), ()>> = Vec::new();
    let mut ws = None;
    DefaultQueryDispatcher
        .contact_manifolds(pos12, s1, s2, prediction, &mut out, &mut ws)
        .expect("supported");
    out
}

#[test]
fn default_dispatcher_contact_manifolds_on_ellipse_pairs_do_not_panic() {
    let e1 = Ellipse::new(1.0, 0.5);
    let e2 = Ellipse::new(0.7, 0.2);
    let cuboid = Cuboid::new(Vector::new(2.0, 0.3));
    let mut rng = Rng::new(17);
    let others: Vec<(&str, Box<dyn Shape>)> = vec![
        ("ellipse", Box::new(e2)),
        ("cuboid", Box::new(cuboid)),
        ("ball", Box::new(Ball::new(0.4))),
        ("rounded polygon", Box::new(RoundedPolygon::regular(5, 0.6, 0.1))),
        ("sharp polygon", Box::new(RoundedPolygon::regular(3, 0.6, 0.0))),
        ("capsule ellipse", Box::new(CapsuleEllipse::new(0.3, 0.4, 0.5))),
        ("custom", Box::new(custom_ellipse())),
        (
            "parry round polygon",
            Box::new(RoundedPolygon::regular(6, 0.5, 0.1).to_parry().unwrap()),
        ),
    ];
    for (name, other) in &others {
        let mut found = 0;
        for _ in 0..200 {
            let dir = rng.direction();
            let gap = rng.uniform(-0.2, 0.3);
            let angle = rng.uniform(-PI, PI);
            // Place shape 2 along dir at roughly the gap.
            let mut pos12 = Pose::new(dir * 6.0, angle);
            let d = query::distance(&Pose::IDENTITY, &e1, &pos12, &**other)
                .unwrap()
                .distance;
            pos12 = Pose::new(dir * (6.0 - d + gap), angle);
            let ms = manifolds(&pos12, &e1, &**other, 0.1);
            let contact = query::contact(&Pose::IDENTITY, &e1, &pos12, &**other, 0.1).unwrap();
            let points: Vec<f64> = ms.iter().flat_map(|m| m.points.iter().map(|p| p.dist)).collect();
            if let Some(contact) = contact {
                assert!(!points.is_empty(), "{name}: contact {contact:?} but no manifold point");
                found += 1;
                let dmin = points.iter().copied().fold(f64::INFINITY, f64::min);
                assert!(
                    (dmin - contact.dist).abs() < 1e-3,
                    "{name}: manifold {dmin} vs contact {}",
                    contact.dist
                );
                for m in &ms {
                    assert!(m.local_n1.is_finite() && (m.local_n1.length() - 1.0).abs() < 1e-9);
                    for p in &m.points {
                        assert!(p.local_p1.is_finite() && p.local_p2.is_finite() && p.dist.is_finite());
                    }
                }
            }
            // Swapped roles too.
            let _ = manifolds(&pos12.inverse(), &**other, &e1, 0.1);
        }
        assert!(found > 20, "{name}: only {found} contacts");
    }
    // Ellipse on a half-space (parry's half-space × feature-map path).
    let ground = HalfSpace::new(Vector::Y);
    let ms = manifolds(&Pose::new(Vector::new(0.0, 0.49), 0.0), &ground, &e1, 0.1);
    assert_eq!(ms.len(), 1);
    assert!(ms[0].points.iter().all(|p| (p.dist + 0.01).abs() < 1e-12));
}

#[test]
fn resting_flat_sides_give_two_point_manifolds() {
    let ground = Cuboid::new(Vector::new(5.0, 0.5));
    // A rounded square lying on its side, and the capsule-ellipse on its segment.
    let sq = RoundedPolygon::regular(4, 1.0, 0.1);
    let h = (PI / 4.0).cos() + 0.1;
    let pos = Pose::new(Vector::new(0.3, 0.5 + h - 1e-3), PI / 4.0);
    let ms = manifolds(&pos, &ground, &sq, 0.05);
    assert_eq!(ms[0].points.len(), 2, "{ms:?}");
    for p in &ms[0].points {
        assert!((p.dist + 1e-3).abs() < 1e-9, "{}", p.dist);
    }
    let cap = CapsuleEllipse::new(0.5, 1.0, 0.8);
    // Segment x = r1 facing down: rotate by −π/2.
    let pos = Pose::new(Vector::new(0.0, 0.5 + 0.5 - 2e-3), -PI / 2.0);
    let ms = manifolds(&pos, &ground, &cap, 0.05);
    assert_eq!(ms[0].points.len(), 2, "{ms:?}");
    for p in &ms[0].points {
        assert!((p.dist + 2e-3).abs() < 1e-9, "{}", p.dist);
    }
}

#[test]
fn distance_and_contact_work_through_support_maps() {
    let e = Ellipse::new(2.0, 0.3);
    let ball = Ball::new(0.25);
    let mut rng = Rng::new(21);
    for _ in 0..100 {
        let c = rng.direction() * rng.uniform(2.5, 4.0);
        let pos2 = Pose::new(c, 0.0);
        let d = query::distance(&Pose::IDENTITY, &e, &pos2, &ball).unwrap().distance;
        let exact = (e.project_local_point(c, true).point - c).length() - 0.25;
        assert!((d - exact).abs() < 1e-6, "{d} vs {exact}");
    }
    // Penetrating ellipses: contact reports a negative distance, close to our projection-based
    // bound along the axis.
    let e2 = Ellipse::new(0.5, 0.5);
    let pos2 = Pose::new(Vector::new(2.3, 0.0), 0.3);
    let c = query::contact(&Pose::IDENTITY, &e, &pos2, &e2, 0.0).unwrap().unwrap();
    assert!((c.dist - (-0.2)).abs() < 1e-6, "{}", c.dist);
    // Custom, capsule-ellipse and rounded polygons against parry's own shapes.
    let shapes: Vec<Box<dyn Shape>> = vec![
        Box::new(custom_ellipse()),
        Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8)),
        Box::new(RoundedPolygon::regular(6, 1.0, 0.2)),
    ];
    for s in &shapes {
        let d = query::distance(&Pose::IDENTITY, &**s, &Pose::new(Vector::new(5.0, 0.0), 0.0), &ball)
            .unwrap()
            .distance;
        let exact = (s.project_local_point(Vector::new(5.0, 0.0), true).point - Vector::new(5.0, 0.0)).length() - 0.25;
        assert!((d - exact).abs() < 1e-6, "{d} vs {exact}");
    }
    // The rounded polygon agrees with parry's RoundConvexPolygon.
    let p = RoundedPolygon::regular(5, 1.0, 0.3);
    let parry_p = p.to_parry().unwrap();
    let cub = Cuboid::new(Vector::new(0.4, 0.2));
    for _ in 0..50 {
        let pos2 = Pose::new(rng.direction() * rng.uniform(1.0, 3.0), rng.uniform(-PI, PI));
        let ours = query::contact(&Pose::IDENTITY, &p, &pos2, &cub, 1.0).unwrap();
        let theirs = query::contact(&Pose::IDENTITY, &parry_p, &pos2, &cub, 1.0).unwrap();
        assert_eq!(ours.is_some(), theirs.is_some());
        if let (Some(a), Some(b)) = (ours, theirs) {
            assert!((a.dist - b.dist).abs() < 1e-6, "{} vs {}", a.dist, b.dist);
        }
    }
}

#[test]
fn queries_on_bad_input_do_not_panic_or_return_nan() {
    for c in cases() {
        let s = &*c.shape;
        let bad = [
            Vector::new(f64::NAN, 0.0),
            Vector::new(f64::INFINITY, 1.0),
            Vector::ZERO,
        ];
        for v in bad {
            let pr = s.project_local_point(v, false);
            assert!(pr.point.is_finite(), "{}", c.name);
            let (fp, _) = s.project_local_point_and_get_feature(v);
            assert!(fp.point.is_finite());
            assert!(s.as_support_map().unwrap().local_support_point(v).is_finite());
            let f = feature_of(s, v);
            assert!(f.vertices[0].is_finite() && f.vertices[1].is_finite());
            for o in [
                Vector::ZERO,
                Vector::new(10.0 * c.size, 0.0),
                Vector::new(f64::NAN, 0.0),
            ] {
                for solid in [true, false] {
                    if let Some(hit) = s.cast_local_ray_and_get_normal(&Ray::new(o, v), f64::MAX, solid) {
                        assert!(hit.time_of_impact.is_finite() && hit.normal.is_finite(), "{}", c.name);
                    }
                    let _ = s.cast_local_ray_and_get_normal(&Ray::new(v, Vector::X), f64::NAN, solid);
                }
            }
        }
        // A zero-length ray from inside hits at 0; from outside it misses.
        let inside = c.boundary[0].lerp(c.boundary[c.boundary.len() / 2], 0.5);
        let hit = s
            .cast_local_ray_and_get_normal(&Ray::new(inside, Vector::ZERO), 1.0, false)
            .unwrap();
        assert_eq!(hit.time_of_impact, 0.0);
        assert!(hit.normal.is_finite());
        assert!(s
            .cast_local_ray_and_get_normal(&Ray::new(Vector::splat(10.0 * c.size), Vector::ZERO), 1.0, true)
            .is_none());
    }
}

#[test]
fn scale_dyn_follows_the_shapes_rules() {
    let e = Ellipse::new(2.0, 0.5);
    let s = e.scale_dyn(Vector::new(-0.5, 3.0), 8).unwrap();
    let s = s.as_shape::<Ellipse>().unwrap();
    assert_eq!((s.half_x(), s.half_y()), (1.0, 1.5));
    assert!(e.scale_dyn(Vector::new(0.0, 1.0), 8).is_none());

    let p = RoundedPolygon::regular(5, 1.0, 0.2);
    let s = p.scale_dyn(Vector::new(2.0, -2.0), 8).unwrap();
    let s = s.as_shape::<RoundedPolygon>().unwrap();
    assert!((s.corner_radius() - 0.4).abs() < 1e-15);
    assert!((s.compute_local_aabb().maxs.x - 2.4).abs() < 1e-12);
    assert!(p.scale_dyn(Vector::new(2.0, 1.0), 8).is_none());
    let sharp = RoundedPolygon::regular(5, 1.0, 0.0);
    let s = sharp.scale_dyn(Vector::new(2.0, 1.0), 8).unwrap();
    assert!((s.compute_local_aabb().maxs.x - 2.0).abs() < 1e-12);

    let c = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let s = c.scale_dyn(Vector::new(2.0, -2.0), 8).unwrap();
    assert_eq!(s.as_shape::<CapsuleEllipse>().unwrap().params(), (1.0, 2.0, 1.6));
    assert!(c.scale_dyn(Vector::new(-2.0, 2.0), 8).is_none());
    assert!(c.scale_dyn(Vector::new(2.0, 1.0), 8).is_none());
    assert!(custom_ellipse().scale_dyn(Vector::splat(2.0), 8).is_none());
}

#[test]
fn shapes_are_custom_convex_with_support_and_feature_maps() {
    for c in cases() {
        let s = &*c.shape;
        assert_eq!(s.shape_type(), ShapeType::Custom);
        assert!(matches!(s.as_typed_shape(), TypedShape::Custom(_)));
        assert!(s.is_convex());
        assert!(s.as_support_map().is_some());
        assert!(s.as_polygonal_feature_map().is_some());
        let b = s.clone_dyn();
        assert_eq!(b.compute_local_aabb(), s.compute_local_aabb());
        assert!(s.ccd_thickness() > 0.0 && s.ccd_angular_thickness() > 0.0);
    }
}

#[test]
fn ccd_thickness_is_the_inradius_about_the_centroid() {
    // The distance from the centroid (rapier's rotation centre) to the boundary: rapier sweeps a
    // body that moves more than a fraction of it in a step.
    assert_eq!(Ellipse::new(2.0, 0.3).ccd_thickness(), 0.3);
    for (n, r) in [(3, 0.0), (5, 0.2), (8, 1.0)] {
        let p = RoundedPolygon::regular(n, 1.0, r);
        let inradius = (std::f64::consts::PI / n as f64).cos() + r;
        assert!((p.ccd_thickness() - inradius).abs() < 1e-14, "{n} {r}");
        let parry: RoundShape<ConvexPolygon> = p.to_parry().unwrap();
        assert_eq!(p.ccd_angular_thickness(), parry.ccd_angular_thickness());
    }
    // A thin sliver turned off its axes: its box is wide, the body is not.
    let sliver = RoundedPolygon::new(
        &[Vector::new(-0.5, -0.5), Vector::new(0.5, 0.4), Vector::new(0.4, 0.5)],
        0.0,
    );
    let c = sliver.mass_properties(1.0).local_com;
    let by_projection = (sliver.project_local_point(c, false).point - c).length();
    assert!((sliver.ccd_thickness() - by_projection).abs() < 1e-12);
    assert!(sliver.ccd_thickness() < 0.05, "{}", sliver.ccd_thickness());
    // CapsuleEllipse (r1 = 0.5, r2 = 1.0, r3 = 0.8): its centroid and the nearest boundary point,
    // against point projection.
    let cap = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let c = cap.mass_properties(1.0).local_com;
    let by_projection = (cap.project_local_point(c, false).point - c).length();
    assert!(
        (cap.ccd_thickness() - by_projection).abs() < 1e-9,
        "{} {by_projection}",
        cap.ccd_thickness()
    );
    // A custom curve (an ellipse 1.3 × 0.4 off its origin): its semi-minor axis.
    assert!(
        (custom_ellipse().ccd_thickness() - 0.4).abs() < 1e-9,
        "{}",
        custom_ellipse().ccd_thickness()
    );
}

#[test]
fn rapier_default_narrow_phase_keeps_every_shape_on_the_ground() {
    use rapier2d_f64::prelude::*;
    // (name, shape, smallest distance from the body origin to its boundary, comes to rest):
    // smooth shapes rock for a long time (rolling without slipping dissipates little).
    let shapes: Vec<(&str, SharedShape, f64, bool)> = vec![
        ("ellipse", SharedShape::new(Ellipse::new(0.6, 0.25)), 0.25, false),
        ("thin ellipse", SharedShape::new(Ellipse::new(1.0, 0.05)), 0.05, false),
        (
            "rounded square",
            SharedShape::new(RoundedPolygon::regular(4, 0.5, 0.05)),
            0.4,
            true,
        ),
        (
            "sharp pentagon",
            SharedShape::new(RoundedPolygon::regular(5, 0.5, 0.0)),
            0.4,
            true,
        ),
        (
            "capsule ellipse",
            SharedShape::new(CapsuleEllipse::new(0.3, 0.4, 0.5)),
            0.3,
            false,
        ),
        ("custom", SharedShape::new(custom_ellipse()), 0.2, false),
    ];
    for (name, shape, inner, rests) in shapes {
        let mut world = PhysicsWorld::default();
        world.insert(RigidBodyBuilder::fixed(), ColliderBuilder::cuboid(50.0, 0.5));
        let (body, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, 3.0))
                .rotation(0.7)
                .angvel(2.0),
            ColliderBuilder::new(shape),
        );
        let energy = |w: &PhysicsWorld| {
            let rb = &w.bodies[body];
            let m = rb.mass();
            let i = rb.mass_properties().local_mprops.principal_inertia();
            m * 9.81 * rb.center_of_mass().y
                + 0.5 * m * rb.linvel().length_squared()
                + 0.5 * i * rb.angvel() * rb.angvel()
        };
        let e0 = energy(&world);
        // Lowest centre over the whole run (impact included) and over the second half.
        let (mut min_all, mut min_late) = (f64::INFINITY, f64::INFINITY);
        for step in 0..1200 {
            world.step();
            let y = world.bodies[body].translation().y;
            min_all = min_all.min(y);
            if step >= 600 {
                min_late = min_late.min(y);
            }
        }
        let rb = &world.bodies[body];
        let y = rb.translation().y;
        assert!(
            min_all.is_finite() && min_all > 0.4,
            "{name}: went through the ground: {min_all}"
        );
        assert!(min_late > 0.5 + inner - 0.01, "{name}: sank to y = {min_late}");
        assert!(y < 2.0, "{name}: flew to y = {y}");
        assert!(energy(&world) < e0, "{name}: gained energy");
        if rests {
            assert!(
                rb.linvel().length() < 0.05 && rb.angvel().abs() < 0.1,
                "{name}: still moving {} {}",
                rb.linvel(),
                rb.angvel()
            );
        }
    }
}
