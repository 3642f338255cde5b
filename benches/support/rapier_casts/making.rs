//! The random casts of each pair kind and set: the shapes (ours and parry's closest), poses
//! and motions, built from a seed.

use super::*;

/// Points on the ellipse of semi-axes `a`, `b` at `n` sorted random angles at least `gap` apart
/// (in convex position, counter-clockwise), shifted by `shift`.
fn ellipse_points(rng: &mut Rng, n: usize, a: f64, b: f64, gap: f64, shift: Vector) -> Vec<Vector> {
    loop {
        let mut t: Vec<f64> = (0..n).map(|_| rng.uniform(0.0, TAU)).collect();
        t.sort_by(f64::total_cmp);
        let ok = (0..n).all(|i| {
            let next = if i + 1 < n { t[i + 1] } else { t[0] + TAU };
            next - t[i] >= gap && next - t[i] <= PI - gap
        });
        if ok {
            return t
                .iter()
                .map(|&t| Vector::new(a * t.cos(), b * t.sin()) + shift)
                .collect();
        }
    }
}

/// The body shapes of `kind`: this crate's, parry's.
fn body_shapes(rng: &mut Rng, kind: Body) -> (Arc<dyn Shape>, Arc<dyn ConvexCurve>, Arc<dyn Shape>) {
    let s = rng.log_uniform(0.1, 1.0);
    let shift = rng.in_disc(0.2 * s);
    let polygon = |pts: Vec<Vector>, radius: f64| {
        let p = RoundedPolygon::new(&pts, radius);
        let parry: Arc<dyn Shape> = if radius > 0.0 {
            Arc::new(p.to_parry().expect("a polygon"))
        } else {
            Arc::new(p.to_parry().expect("a polygon").inner_shape)
        };
        (
            Arc::new(p.clone()) as Arc<dyn Shape>,
            Arc::new(p) as Arc<dyn ConvexCurve>,
            parry,
        )
    };
    match kind {
        Body::Disc => {
            let e = Ellipse::new(s, s);
            (Arc::new(e), Arc::new(e), Arc::new(Ball::new(s)))
        }
        Body::Polygon => {
            let n = rng.int(3, 8);
            let (a, b) = (s, s * rng.uniform(0.5, 1.0));
            let pts = ellipse_points(rng, n, a, b, 0.2, shift);
            polygon(pts, 0.0)
        }
        Body::Rounded => {
            let n = rng.int(3, 8);
            let (a, b) = (s, s * rng.uniform(0.5, 1.0));
            let pts = ellipse_points(rng, n, a, b, 0.2, shift);
            let r = s * rng.uniform(0.02, 0.3);
            polygon(pts, r)
        }
        Body::Sliver => {
            let n = rng.int(3, 4);
            let (a, b) = (s, s / rng.uniform(10.0, 50.0));
            let pts = ellipse_points(rng, n, a, b, 0.5, shift);
            polygon(pts, 0.0)
        }
        Body::Ellipse => {
            let e = Ellipse::new(s, s / rng.uniform(1.5, 10.0));
            let poly = polygon_approximation(&e, POLYGON_VERTICES);
            (Arc::new(e), Arc::new(e), Arc::new(poly))
        }
    }
}

/// The target shape of `kind`.
fn target_shape(rng: &mut Rng, kind: Target) -> Arc<dyn Shape> {
    match kind {
        Target::Ball => Arc::new(Ball::new(rng.log_uniform(0.1, 2.0))),
        Target::Cuboid => Arc::new(Cuboid::new(Vector::new(
            rng.log_uniform(0.02, 2.0),
            rng.log_uniform(0.02, 2.0),
        ))),
        Target::Segment => {
            let h = rng.log_uniform(0.2, 4.0);
            Arc::new(Segment::new(Vector::new(-h, 0.0), Vector::new(h, 0.0)))
        }
        Target::Capsule => {
            let h = rng.log_uniform(0.1, 2.0);
            Arc::new(Capsule::new(
                Vector::new(-h, 0.0),
                Vector::new(h, 0.0),
                rng.log_uniform(0.05, 0.5),
            ))
        }
        Target::Triangle => {
            let r = rng.log_uniform(0.2, 2.0);
            let p = ellipse_points(rng, 3, r, r, 0.3, Vector::ZERO);
            Arc::new(Triangle::new(p[0], p[1], p[2]))
        }
        Target::Polygon => {
            let n = rng.int(3, 8);
            let r = rng.log_uniform(0.2, 2.0);
            let b = r * rng.uniform(0.3, 1.0);
            let p = ellipse_points(rng, n, r, b, 0.2, Vector::ZERO);
            Arc::new(ConvexPolygon::from_convex_polyline(p).expect("a polygon"))
        }
    }
}

/// The distance from `c` to the boundary of the body (inside it): the inradius about `c`.
fn inradius(kind: Body, ours: &dyn Shape, c: Vector) -> f64 {
    match kind {
        Body::Disc | Body::Ellipse => {
            let b = ours.compute_local_aabb();
            0.5 * (b.maxs - b.mins).min_element()
        }
        _ => {
            // The least distance from `c` to the core polygon's edge lines, plus the corner radius.
            let p = ours.as_shape::<RoundedPolygon>().expect("a rounded polygon");
            let v = p.vertices();
            let n = v.len();
            (0..n)
                .map(|i| {
                    let e = v[(i + 1) % n] - v[i];
                    let out = Vector::new(e.y, -e.x).normalize();
                    out.dot(v[i] - c)
                })
                .fold(f64::INFINITY, f64::min)
                + p.corner_radius()
        }
    }
}

/// A pose whose `local_center` point is at `centre`, turned by `angle`.
fn pose_with_centre(angle: f64, local_center: Vector, centre: Vector) -> Pose {
    let r = Pose::rotation(angle);
    Pose::from_parts(centre - r * local_center, r.rotation)
}

/// The reference signed distance of the body at `pose` and the target.
pub(super) fn distance(body: &dyn ConvexCurve, pose: &Pose, target: &dyn ConvexCurve, target_pose: &Pose) -> f64 {
    reference_distance(body, pose, target, target_pose).distance
}

/// The first distance along `u` from `from` at which the body (turned by `angle`, its centre at
/// the point) touches the target, by conservative advancement on the reference distance
/// (1-Lipschitz in the translation); `None` when it passes.
fn translation_contact(
    body: &dyn ConvexCurve,
    com: Vector,
    angle: f64,
    target: &dyn ConvexCurve,
    target_pose: &Pose,
    from: Vector,
    u: Vector,
    reach: f64,
) -> Option<f64> {
    let mut s = 0.0;
    for _ in 0..10_000 {
        let d = distance(body, &pose_with_centre(angle, com, from + u * s), target, target_pose);
        if d < 1e-13 * reach {
            return Some(s);
        }
        s += d;
        if s > reach {
            return None;
        }
    }
    None
}

/// The case of `seed` for a body of `body` kind against a `target` in `set`.
pub fn make_case(body: Body, target: Target, set: Set, seed: u64) -> RCase {
    let mut rng = Rng::mixed(seed);
    loop {
        let (ours, ours_curve, parry) = body_shapes(&mut rng, body);
        let target_shape = target_shape(&mut rng, target);
        let target_curve = ParryCurve {
            shape: target_shape.clone(),
            shift: Vector::ZERO,
            offset: 0.0,
        };
        let target_pose = Pose::new(
            Vector::new(rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0)),
            rng.angle(),
        );
        let com = ours.mass_properties(1.0).local_com;
        let rb = ours_curve.bounding_radius() + com.length();
        let rt = target_curve.bounding_radius();
        let speed = rng.log_uniform(1.0, 3000.0);
        let turn = match set {
            Set::Apart | Set::Contact => rng.uniform(-FRAC_PI_4, FRAC_PI_4),
            Set::Beyond => rng.sign() * rng.uniform(FRAC_PI_4, 4.0 * PI),
            Set::Still => 0.0,
        };
        let angle = rng.angle();
        let u = rng.direction();
        let side = Vector::new(-u.y, u.x);
        let aimed = rng.chance(0.6);
        let reach = rb + rt;
        let lateral = if aimed {
            rng.uniform(-0.5, 0.5) * reach
        } else {
            rng.sign() * rng.uniform(0.5, 1.3) * reach
        };
        let far = reach + 1.0;
        let from = target_pose.translation + side * lateral - u * far;
        let travel = speed * DT;
        let contact = translation_contact(
            &*ours_curve,
            com,
            angle,
            &target_curve,
            &target_pose,
            from,
            u,
            2.0 * far,
        );
        let (centre, velocity) = match set {
            Set::Apart | Set::Beyond | Set::Still => {
                // Touching (without spin) at fraction f of the step, or stopping short, or
                // passing by.
                let f = if contact.is_some() && rng.chance(0.3) {
                    rng.uniform(1.02, 2.0)
                } else {
                    rng.uniform(0.02, 0.98)
                };
                let s = match contact {
                    Some(s) => s - f * travel,
                    None => far - f * travel,
                };
                (from + u * s, u * speed)
            }
            Set::Contact => {
                let Some(s) = contact else { continue };
                let depth = if rng.chance(0.3) { 0.0 } else { rng.uniform(0.0, 0.1) };
                // Pushed in along u by up to a tenth of the inradius, then any direction.
                let r = inradius(body, &*ours, com);
                (from + u * (s + depth * r), rng.direction() * speed)
            }
        };
        let start = pose_with_centre(angle, com, centre);
        let d0 = distance(&*ours_curve, &start, &target_curve, &target_pose);
        let ok = match set {
            Set::Apart | Set::Beyond | Set::Still => d0 >= MIN_START_GAP,
            Set::Contact => d0 <= 1e-9 * reach,
        };
        if !ok {
            continue;
        }
        let motion = NonlinearRigidMotion::new(start, com, velocity, turn / DT);
        let sweep = Sweep::from_poses(&start, &motion.position_at_time(DT), com);
        let inradius = inradius(body, &*ours, com);
        let parry_centroid = parry.mass_properties(1.0).local_com;
        let parry_thickness = parry.ccd_thickness();
        return RCase {
            body,
            target,
            set,
            seed,
            ours,
            ours_curve,
            parry,
            target_shape,
            target_pose,
            motion,
            sweep,
            parry_centroid,
            parry_thickness,
            inradius,
            d0,
        };
    }
}

/// A case's inputs, exactly (f64 `Debug` round-trips).
pub fn describe(c: &RCase) -> String {
    let body = if let Some(p) = c.ours.as_shape::<RoundedPolygon>() {
        format!("RoundedPolygon::new(&{:?}, {:?})", p.vertices(), p.corner_radius())
    } else if let Some(e) = c.ours.as_shape::<Ellipse>() {
        format!("Ellipse::new({:?}, {:?})", e.half_x(), e.half_y())
    } else {
        "?".into()
    };
    let t = &c.target_shape;
    let target = if let Some(b) = t.as_ball() {
        format!("Ball::new({:?})", b.radius)
    } else if let Some(b) = t.as_cuboid() {
        format!("Cuboid::new({:?})", b.half_extents)
    } else if let Some(s) = t.as_segment() {
        format!("Segment::new({:?}, {:?})", s.a, s.b)
    } else if let Some(s) = t.as_capsule() {
        format!("Capsule::new({:?}, {:?}, {:?})", s.segment.a, s.segment.b, s.radius)
    } else if let Some(s) = t.as_triangle() {
        format!("Triangle::new({:?}, {:?}, {:?})", s.a, s.b, s.c)
    } else if let Some(p) = t.as_convex_polygon() {
        format!("ConvexPolygon::from_convex_polyline({:?})", p.points())
    } else {
        "?".into()
    };
    let m = &c.motion;
    format!(
        "seed {} ({:?} – {:?}, {:?}): body {body}, motion NonlinearRigidMotion::new({:?}, {:?}, {:?}, {:?}) over [0, 1/60]; target {target} at {:?}",
        c.seed, c.body, c.target, c.set, m.start, m.local_center, m.linvel, m.angvel, c.target_pose
    )
}
