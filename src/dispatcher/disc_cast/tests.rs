//! The closed form of `disc_cast` against the general path, and the cases it leaves to it.

use super::*;
use crate::dispatcher::SmoothDispatcher;
use crate::numerics::math::Pose;
use crate::RoundedPolygon;
use parry2d_f64::shape::{
    Ball, Capsule, ConvexPolygon, Cuboid, RoundConvexPolygon, RoundCuboid, Segment, Shape, Triangle,
};

/// A seeded uniform generator (xorshift64).
struct Rng(u64);

impl Rng {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        lo + (hi - lo) * (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn chance(&mut self, p: f64) -> bool {
        self.uniform(0.0, 1.0) < p
    }
    fn direction(&mut self) -> Vector {
        let a = self.uniform(-3.2, 3.2);
        Vector::new(a.cos(), a.sin())
    }
}

/// Every kind of target the closed form reads.
fn targets() -> Vec<Box<dyn Shape>> {
    let hull = |pts: &[Vector]| ConvexPolygon::from_convex_hull(pts).unwrap();
    let pent: Vec<Vector> = (0..5)
        .map(|i| {
            let a = 1.3 * i as f64;
            Vector::new(0.7 * a.cos(), 0.4 * a.sin())
        })
        .collect();
    vec![
        Box::new(Ball::new(0.4)),
        Box::new(Cuboid::new(Vector::new(0.8, 0.05))),
        Box::new(Cuboid::new(Vector::new(0.5, 0.3))),
        Box::new(RoundCuboid {
            inner_shape: Cuboid::new(Vector::new(0.4, 0.2)),
            border_radius: 0.1,
        }),
        Box::new(Segment::new(Vector::new(-0.6, 0.1), Vector::new(0.5, -0.2))),
        Box::new(Capsule::new(Vector::new(-0.3, 0.0), Vector::new(0.4, 0.2), 0.15)),
        Box::new(Triangle::new(
            Vector::new(0.0, 0.0),
            Vector::new(0.9, 0.1),
            Vector::new(0.2, 0.7),
        )),
        Box::new(hull(&pent)),
        Box::new(RoundConvexPolygon {
            inner_shape: hull(&pent),
            border_radius: 0.05,
        }),
        Box::new(RoundedPolygon::regular(6, 0.5, 0.08)),
        Box::new(RoundedPolygon::regular(3, 0.6, 0.0)),
        Box::new(Ellipse::new(0.3, 0.3)),
    ]
}

/// One random cast of a disc at a target: apart (aimed near the target, hits and misses) or
/// in contact (touching or up to a tenth of the radius deep), any spin, the target at rest
/// or translating, either rapier policy, either `stop_at_penetration`.
struct Case {
    disc: Ellipse,
    m1: NonlinearRigidMotion,
    m2: NonlinearRigidMotion,
    window: (Real, Real),
    stop: bool,
    policy: CastPolicy,
}

fn case(rng: &mut Rng, target: &dyn Shape, contact: bool) -> Case {
    let rho = rng.uniform(0.05, 1.0);
    let disc = Ellipse::new(rho, rho);
    let reach = target.compute_local_bounding_sphere().radius + rho;
    let pose2 = Pose::new(
        Vector::new(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)),
        rng.uniform(-3.2, 3.2),
    );
    let span = if rng.chance(0.5) { 1.0 / 60.0 } else { 1.0 };
    let t0 = if rng.chance(0.5) { 0.0 } else { rng.uniform(0.0, 0.5) };
    let u = rng.direction();
    let (centre, velocity) = if contact {
        // On the target's boundary (its exact contact along u), pushed in by a depth.
        let mut centre = pose2.translation + u * (reach + 0.5);
        for _ in 0..4 {
            let pos12 = Pose::from_translation(centre).inv_mul(&pose2);
            let k = exact_contact(&pos12, &disc, target, None).unwrap();
            centre += k.normal * k.dist;
        }
        // Down past the core (0.75 of the radius) now and then: the core's own start contact.
        let depth = if rng.chance(0.3) {
            0.0
        } else if rng.chance(0.2) {
            rng.uniform(0.6 * rho, 1.0 * rho)
        } else {
            rng.uniform(0.0, 0.1 * rho)
        };
        let pos12 = Pose::from_translation(centre).inv_mul(&pose2);
        let k = exact_contact(&pos12, &disc, target, None).unwrap();
        (
            centre + k.normal * (k.dist + depth),
            rng.direction() * rng.uniform(0.1, 3.0) * reach / span,
        )
    } else {
        let centre = pose2.translation + u * reach * rng.uniform(1.05, 3.0);
        let aim = pose2.translation + rng.direction() * rng.uniform(0.0, 1.5) * reach;
        let travel = rng.uniform(0.2, 2.0) * (aim - centre).length();
        (centre, (aim - centre).normalize() * travel / span)
    };
    let angvel = if rng.chance(0.3) {
        0.0
    } else {
        rng.uniform(-4.0, 4.0) * core::f64::consts::PI / span
    };
    // The general path's start-contact rule takes the start contact in the frame of the
    // spin at t₀ and the translation in the frame of parry's start pose (t = 0): the same
    // frame only when t₀ = 0 or the body does not turn (rapier's casts start at 0).
    let t0 = if contact && angvel != 0.0 { 0.0 } else { t0 };
    // parry's motions turn from t = 0: the start pose is the pose at t = 0.
    let start = Pose::new(centre - velocity * t0, rng.uniform(-3.2, 3.2));
    let v2 = if rng.chance(0.3) {
        rng.direction() * rng.uniform(0.0, 0.5) * reach / span
    } else {
        Vector::ZERO
    };
    let m2 = NonlinearRigidMotion::new(
        Pose::from_parts(pose2.translation - v2 * t0, pose2.rotation),
        Vector::ZERO,
        v2,
        0.0,
    );
    Case {
        disc,
        m1: NonlinearRigidMotion::new(start, Vector::ZERO, velocity, angvel),
        m2,
        window: (t0, t0 + span),
        stop: rng.chance(0.2),
        policy: if rng.chance(0.7) {
            CastPolicy::Rapier
        } else {
            CastPolicy::RapierConstantSpin
        },
    }
}

use crate::dispatcher::support_shape::exact_contact;

/// What a comparison saw.
#[derive(Default, Debug)]
struct Tally {
    apart_hits: usize,
    apart_misses: usize,
    contact_hits: usize,
    contact_misses: usize,
    general: usize,
    within_window_1e12: usize,
}

/// The closed form against the general path on thousands of random casts: the same hit or
/// miss and status, the same time (within 1e-12 of the window, or within the distance
/// tolerance the general path accepts, τ/|D′|, where it finds the time to that tolerance),
/// normals and witnesses of that time.
#[test]
fn disc_casts_answer_as_the_general_path() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut tally = Tally::default();
    for target in targets() {
        for i in 0..700 {
            let k = case(&mut rng, &*target, i % 3 == 0);
            let d = SmoothDispatcher::default().with_cast_policy(k.policy);
            let mut c = NonlinearCast::new(&k.m1, &k.disc, &k.m2, &*target, k.window, k.stop);
            // As `cast_shapes_nonlinear` sets it.
            c.spin_at_start = crate::dispatcher::rapier_rule::spin_at_start(k.policy, &k.m1, &k.m2);
            let (opts, rule) = d.cast_setup(&c);
            let Some(fast) = disc_cast(&c, &opts, rule.start_contact) else {
                tally.general += 1;
                continue;
            };
            let general = d.general_cast(&c, &opts, rule);
            compare(&c, &opts, fast, general, &mut tally, &*target);
        }
    }
    println!("{tally:?}");
    assert!(tally.apart_hits > 1500 && tally.apart_misses > 1500, "{tally:?}");
    assert!(tally.contact_hits > 300 && tally.contact_misses > 300, "{tally:?}");
}

fn compare(
    c: &NonlinearCast,
    opts: &ToiOptions,
    fast: Result<Option<ShapeCastHit>, Unsupported>,
    general: Result<Option<ShapeCastHit>, Unsupported>,
    tally: &mut Tally,
    target: &dyn Shape,
) {
    let at_start = in_contact(c, start_distance(c, target));
    let (fast, general) = (fast.unwrap(), general.unwrap());
    let what = format!(
        "{:?} {:?} {:?} {:?} stop {}",
        target.shape_type(),
        c.m1,
        c.m2,
        (c.t0, c.t1),
        c.stop
    );
    assert_eq!(fast.is_some(), general.is_some(), "{what}: {fast:?} / {general:?}");
    let (Some(f), Some(g)) = (fast, general) else {
        if at_start {
            tally.contact_misses += 1
        } else {
            tally.apart_misses += 1
        }
        return;
    };
    if at_start {
        tally.contact_hits += 1
    } else {
        tally.apart_hits += 1
    }
    assert_eq!(f.status, g.status, "{what}");
    let span = c.t1 - c.t0;
    let dt = (f.time_of_impact - g.time_of_impact).abs();
    // The rate of the signed distance along the contact normal at the hit (target's frame).
    let rotation2 = c.m2.start.rotation;
    let w = rotation2.inverse() * (c.m1.linvel - c.m2.linvel);
    let rate = f.normal2.dot(w).abs();
    let size = c.size();
    let tol = opts.distance_tolerance * size;
    if dt <= 1e-12 * span {
        tally.within_window_1e12 += 1;
    }
    assert!(dt <= 1e-12 * span + tol / rate, "{what}: {f:?} / {g:?}");
    // The normals and witnesses of the two times. The general path's normal is the
    // separating axis of its last step where a crossing's certificate accepts it, which
    // leaves the level of radius ≥ ρ by at most the tolerance τ: within √(2τ/ρ) of the
    // exact normal; between the two times the normal turns by at most |w|·Δt/ρ.
    let rho = c.g1.as_shape::<Ellipse>().unwrap().half_x();
    let angle = 1e-12 + (2.0 * tol / rho).sqrt() + dt * w.length() / rho;
    let off = 1e-12 * size + rho.max(size) * angle + dt * w.length();
    assert!((f.normal2 - g.normal2).length() <= angle, "{what}: {f:?} / {g:?}");
    assert!((f.normal1 - g.normal1).length() <= angle, "{what}: {f:?} / {g:?}");
    assert!((f.witness2 - g.witness2).length() <= off, "{what}: {f:?} / {g:?}");
    assert!((f.witness1 - g.witness1).length() <= off, "{what}: {f:?} / {g:?}");
}

/// A disc shot at a ball through the dispatcher (3000 m/s, one step): the time of the
/// centres' quadratic, to rounding, on both rapier policies, whatever the spin.
#[test]
fn disc_hits_a_ball_at_the_quadratics_time() {
    use parry2d_f64::query::QueryDispatcher as _;
    let (disc, ball) = (Ellipse::new(0.1, 0.1), Ball::new(0.4));
    let m2 = NonlinearRigidMotion::constant_position(Pose::new(Vector::new(3.0, 0.3), 0.4));
    // The centre from (−1, 0) along x: |c(t) − (3, 0.3)| = 0.5 at 4 − 3000 t = √(0.25 − 0.09).
    let expected = (4.0 - 0.16f64.sqrt()) / 3000.0;
    for (policy, angvel) in [
        (CastPolicy::Rapier, 0.0),
        (CastPolicy::Rapier, 300.0),
        (CastPolicy::RapierConstantSpin, -40.0),
    ] {
        let d = SmoothDispatcher::default().with_cast_policy(policy);
        let m1 = NonlinearRigidMotion::new(
            Pose::new(Vector::new(-1.0, 0.0), 1.0),
            Vector::ZERO,
            Vector::new(3000.0, 0.0),
            angvel,
        );
        let hit = d
            .cast_shapes_nonlinear(&m1, &disc, &m2, &ball, 0.0, 1.0 / 60.0, false)
            .unwrap()
            .unwrap();
        assert!(
            (hit.time_of_impact - expected).abs() <= 1e-15,
            "{policy:?} {angvel}: {hit:?}"
        );
        // The witnesses face each other along the centres' line, the disc's in its frame at
        // the rotation of its path then: rapier's clamp (parry's `Sweep`) on the nlerp path.
        let (t, span) = (hit.time_of_impact, 1.0 / 60.0);
        let pose1 = if policy == CastPolicy::Rapier {
            let end = m1.position_at_time(span);
            parry2d_f64::query::Sweep::from_poses(&m1.start, &end, m1.local_center).transform_at(t / span)
        } else {
            m1.position_at_time(t)
        };
        let pose2 = m2.start;
        assert!(
            (pose1 * hit.witness1 - pose2 * hit.witness2).length() <= 1e-12,
            "{policy:?}: {hit:?}"
        );
        assert!(
            (pose1.rotation * hit.normal1 + pose2.rotation * hit.normal2).length() <= 1e-12,
            "{hit:?}"
        );
        let centre = m1.start.translation + m1.linvel * t;
        let towards = (centre - pose2.translation).normalize();
        assert!(
            (pose2.rotation * hit.normal2 - towards).length() <= 1e-12,
            "{hit:?} {towards:?} {:?}",
            pose2.rotation * hit.normal2
        );
    }
}

/// The casts the closed form does not take go to the general path: a disc turning about
/// another point, an ellipse, the disc as the target, a turning target, non-finite input,
/// a start in contact with `stop_at_penetration`.
#[test]
fn casts_other_than_a_disc_about_its_centre_are_left_to_the_general_path() {
    let (disc, ball) = (Ellipse::new(0.2, 0.2), Ball::new(0.3));
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let shot = |lc: Vector, angvel: f64| {
        NonlinearRigidMotion::new(
            Pose::from_translation(Vector::new(-2.0, 0.0)),
            lc,
            Vector::new(100.0, 0.0),
            angvel,
        )
    };
    let opts = ToiOptions::default();
    let declined = |m1: &NonlinearRigidMotion, g1: &dyn Shape, m2: &NonlinearRigidMotion, g2: &dyn Shape, stop| {
        disc_cast(&NonlinearCast::new(m1, g1, m2, g2, (0.0, 0.1), stop), &opts, !stop).is_none()
    };
    assert!(!declined(&shot(Vector::ZERO, 50.0), &disc, &still, &ball, false));
    // A disc off its rotation centre sweeps a curve; without a spin it translates.
    assert!(declined(
        &shot(Vector::new(0.05, 0.0), 50.0),
        &disc,
        &still,
        &ball,
        false
    ));
    assert!(!declined(
        &shot(Vector::new(0.05, 0.0), 0.0),
        &disc,
        &still,
        &ball,
        false
    ));
    assert!(declined(
        &shot(Vector::ZERO, 50.0),
        &Ellipse::new(0.2, 0.1),
        &still,
        &ball,
        false
    ));
    assert!(declined(&shot(Vector::ZERO, 50.0), &ball, &still, &disc, false));
    let turning = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::ZERO, 1.0);
    assert!(declined(&shot(Vector::ZERO, 0.0), &disc, &turning, &ball, false));
    assert!(declined(&shot(Vector::ZERO, f64::NAN), &disc, &still, &ball, false));
    let touching = NonlinearRigidMotion::new(
        Pose::from_translation(Vector::new(-0.5, 0.0)),
        Vector::ZERO,
        Vector::new(1.0, 0.0),
        3.0,
    );
    assert!(declined(&touching, &disc, &still, &ball, true));
    assert!(!declined(&touching, &disc, &still, &ball, false));
}

/// Degenerate motions answer as the general path does: no motion at all, apart or in
/// contact (no hit), and a contact at the start deeper than the core (the core's start
/// contact, coming closer: at the nudge).
#[test]
fn zero_and_deep_motions_answer_as_the_general_path() {
    let (disc, boxed) = (Ellipse::new(0.3, 0.3), Cuboid::new(Vector::new(1.0, 0.5)));
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let d = SmoothDispatcher::default();
    let at = |x: f64, y: f64, v: Vector| {
        NonlinearRigidMotion::new(Pose::from_translation(Vector::new(x, y)), Vector::ZERO, v, 2.0)
    };
    let cases = [
        at(0.0, 2.0, Vector::ZERO),
        at(0.0, 0.8, Vector::ZERO),
        at(0.0, 0.7, Vector::ZERO),
        at(0.0, 0.3, Vector::new(0.0, -5.0)),
        at(0.0, 0.3, Vector::new(0.0, 5.0)),
        at(1.2, 0.0, Vector::new(-50.0, 1.0)),
    ];
    for m1 in cases {
        let c = NonlinearCast::new(&m1, &disc, &still, &boxed, (0.0, 1.0 / 60.0), false);
        let (opts, rule) = d.cast_setup(&c);
        let fast = disc_cast(&c, &opts, rule.start_contact).expect("a disc's cast");
        let general = d.general_cast(&c, &opts, rule);
        let time = |r: &Result<Option<ShapeCastHit>, Unsupported>| r.unwrap().map(|h| (h.time_of_impact, h.status));
        let (f, g) = (time(&fast), time(&general));
        assert_eq!(f.is_some(), g.is_some(), "{m1:?}: {f:?} / {g:?}");
        if let (Some(f), Some(g)) = (f, g) {
            assert_eq!(f.1, g.1);
            assert!((f.0 - g.0).abs() <= 1e-12 / 60.0 + 1e-10, "{m1:?}: {f:?} / {g:?}");
        }
    }
}

/// The closed form's answer to a start contact is the same when the window starts later
/// (the motion's start pose moved back along its spin and translation): only the elapsed
/// time counts.
#[test]
fn start_contact_answer_does_not_depend_on_the_windows_start() {
    let (disc, wall) = (
        Ellipse::new(0.25, 0.25),
        Segment::new(Vector::new(0.0, -1.0), Vector::new(0.0, 1.0)),
    );
    let still = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let d = SmoothDispatcher::default();
    let (v, w, span) = (Vector::new(40.0, 5.0), 90.0, 1.0 / 60.0);
    let mut answers = vec![];
    for t0 in [0.0, 0.37, 12.5] {
        let start = Pose::new(Vector::new(-0.25, 0.0) - v * t0, 0.3 - w * t0);
        let m1 = NonlinearRigidMotion::new(start, Vector::ZERO, v, w);
        let c = NonlinearCast::new(&m1, &disc, &still, &wall, (t0, t0 + span), false);
        let (opts, rule) = d.cast_setup(&c);
        let hit = disc_cast(&c, &opts, rule.start_contact).unwrap().unwrap().unwrap();
        answers.push(hit.time_of_impact - t0);
    }
    // The translation takes the contact a quarter of the radius deeper at 0.0625/40 s.
    assert!((answers[0] - 0.0625 / 40.0).abs() <= 1e-15, "{answers:?}");
    for a in &answers[1..] {
        assert!((a - answers[0]).abs() <= 1e-12 * span, "{answers:?}");
    }
}

/// The exact signed distance of the cast's pair at its start.
fn start_distance(c: &NonlinearCast, target: &dyn Shape) -> Real {
    let pos12 = crate::dispatcher::cast::pos12_at(c.m1, c.m2, c.t0);
    exact_contact(&pos12, c.g1, target, None).unwrap().dist
}

/// Issue 29's degenerate starts through rapier's call: a unit disc centred on a corner of the
/// unit box [0, 1]², and within 1e-6 of it, of an edge, of the centre (`tests/degenerate_starts.rs`),
/// still, translating or spinning, against the box as this crate's sharp polygon and as parry's
/// `Cuboid`: the closed form takes every one and answers as the general path.
#[test]
fn a_disc_centred_on_a_boxs_corner_edge_or_centre_answers_as_the_general_path() {
    let e = 1e-6;
    let (v, m, centre) = (Vector::new(1.0, 1.0), Vector::new(1.0, 0.5), Vector::new(0.5, 0.5));
    let places = [
        v,
        Vector::ZERO,
        v + Vector::new(e, e),
        v - Vector::new(e, e),
        v - Vector::new(e, 0.0),
        v + Vector::new(0.0, e),
        m,
        m - Vector::new(e, 0.0),
        m + Vector::new(e, 0.0),
        m + Vector::new(0.0, e),
        centre,
        centre + Vector::new(e, -e),
    ];
    let unit_box = RoundedPolygon::new(
        &[
            Vector::new(0.0, 0.0),
            Vector::new(1.0, 0.0),
            Vector::new(1.0, 1.0),
            Vector::new(0.0, 1.0),
        ],
        0.0,
    );
    let cuboid = Cuboid::new(Vector::new(0.5, 0.5));
    // Each box with the pose that puts its core on [0, 1]².
    let boxes: [(&dyn Shape, Pose); 2] = [
        (&unit_box, Pose::IDENTITY),
        (&cuboid, Pose::from_translation(Vector::new(0.5, 0.5))),
    ];
    let disc = Ellipse::new(1.0, 1.0);
    let mut tally = Tally::default();
    for (target, pose2) in boxes {
        let m2 = NonlinearRigidMotion::constant_position(pose2);
        for at in places {
            for (v, w) in [
                (Vector::ZERO, 0.0),
                (Vector::new(3.0, 1.0), 0.0),
                (Vector::new(-2.0, 5.0), 4.0),
            ] {
                let m1 = NonlinearRigidMotion::new(Pose::new(at, 0.3), Vector::ZERO, v, w);
                for policy in [CastPolicy::Rapier, CastPolicy::RapierConstantSpin] {
                    let d = SmoothDispatcher::default().with_cast_policy(policy);
                    let mut c = NonlinearCast::new(&m1, &disc, &m2, target, (0.0, 1.0), false);
                    // Forced for both policies' branches (the dispatcher sets it only for two
                    // moving bodies; the target here stands still): the closed form and the
                    // general path must agree on the whole-motion rule too.
                    c.spin_at_start = policy == CastPolicy::RapierConstantSpin;
                    let (opts, rule) = d.cast_setup(&c);
                    let fast = disc_cast(&c, &opts, rule.start_contact).expect("the closed form takes it");
                    let general = d.general_cast(&c, &opts, rule);
                    compare(&c, &opts, fast, general, &mut tally, target);
                }
            }
        }
    }
    // Every start is in contact; the still disc never deepens it, the moving ones do.
    assert_eq!(tally.apart_hits + tally.apart_misses, 0, "{tally:?}");
    assert!(tally.contact_hits > 0 && tally.contact_misses > 0, "{tally:?}");
}

/// Rule 3's core time in closed form (`core_entry`) is the time the level search of the
/// translating core answered before it (`translation_time_to_level` on a `Ball` of the core's
/// radius, its level from the exact contact at the window's start): the same hits to the
/// search's distance tolerance, the same misses, on random cores (apart, touching, inside)
/// against every target the closed form reads, the target translating without a turn, windows
/// starting anywhere (a disc given as an `Ellipse` with equal semi-axes among them).
#[test]
fn the_cores_closed_form_time_is_the_level_searchs() {
    use crate::dispatcher::rapier_rule::core_level;
    use crate::dispatcher::support_shape::exact_contact;
    use crate::dispatcher::translation_level::{translation_time_to_level, LevelTime, Translating};
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut cases, mut hits, mut worst) = (0, 0, 0.0f64);
    for target in targets() {
        let sphere = target.compute_local_bounding_sphere();
        for _ in 0..1500 {
            let radius = rng.uniform(0.01, 0.3);
            // The core's centre near the target, touching it or in it one time in three.
            let dir = rng.direction();
            let along = sphere.radius * rng.uniform(0.0, 1.2) + radius * rng.uniform(-1.0, 1.5);
            let centre0 = sphere.center + dir * along;
            let speed = rng.uniform(0.0, 8.0);
            let centre = NonlinearRigidMotion::new(
                Pose::from_translation(centre0),
                Vector::ZERO,
                rng.direction() * speed,
                0.0,
            );
            let pose2 = Pose::new(
                Vector::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)),
                rng.uniform(-3.2, 3.2),
            );
            let target_m = NonlinearRigidMotion::new(pose2, Vector::ZERO, rng.direction() * rng.uniform(0.0, 2.0), 0.0);
            // The centre given in the world: place it relative to the target's pose.
            let centre = NonlinearRigidMotion {
                start: Pose::from_translation(pose2 * centre.start.translation),
                ..centre
            };
            let t0 = rng.uniform(-0.5, 0.5);
            let t1 = t0 + rng.uniform(0.01, 1.0);
            let tol = 1e-9 * (sphere.radius + radius);
            let closed = core_entry(&centre, target.as_ref(), &target_m, radius, (t0, t1), tol);
            let core = Ball::new(radius);
            let pos12 = crate::dispatcher::cast::pos12_at(&centre, &target_m, t0);
            let k = exact_contact(&pos12, &core, target.as_ref(), None);
            let level = core_level(k.map(|k| k.dist), radius, tol);
            let p = Translating {
                g1: &core,
                m1: &centre,
                g2: target.as_ref(),
                m2: &target_m,
            };
            let searched = match translation_time_to_level(&p, t0, t1, level, tol, k) {
                LevelTime::Reached(t) | LevelTime::Capped(t) => Some(t),
                LevelTime::Never => None,
                LevelTime::Unread => panic!("the search reads every target here"),
            };
            let closed = closed.expect("the closed form reads this target");
            cases += 1;
            match (closed, searched) {
                (Some(a), Some(b)) => {
                    hits += 1;
                    // The search stops within the tolerance above the level, coming from the
                    // left; the closed form is the crossing itself (or the start).
                    let d = |t: Real| {
                        let pos12 = crate::dispatcher::cast::pos12_at(&centre, &target_m, t);
                        exact_contact(&pos12, &core, target.as_ref(), None).unwrap().dist - level
                    };
                    let (da, db) = (d(a), d(b));
                    if a == t0 && b == t0 {
                        // Both at the start: at or below the level there, coming closer.
                        assert!(da <= tol);
                        continue;
                    }
                    worst = worst.max(db.abs() / tol);
                    assert!(da.abs() <= 1e-3 * tol, "closed {a}: {da} off the level");
                    assert!(
                        b <= a + 1e-12 && db.abs() <= 2.0 * tol,
                        "closed {a}, searched {b} ({db} off the level)"
                    );
                }
                (None, None) => {}
                (a, b) => panic!("closed form {a:?}, level search {b:?}"),
            }
        }
    }
    println!("{cases} core times, {hits} hits, the search at most {worst:.3} of its tolerance off the level");
    assert!(hits * 5 > cases, "{hits} hits of {cases}");
}

/// A path that passes a sharp corner (a vertex circle of radius 0, as the Minkowski difference
/// of two sharp polygons has them) does not enter it, however close it passes: random
/// directions and distances from 1e-14 to 1e-6 of the path's distance from the vertex (the
/// difference of squares of the quadratic made those within about 1e-8 touch it), and one
/// twice as large about it is entered where the path's line meets it.
#[test]
fn a_path_passing_a_sharp_corner_does_not_enter_it() {
    let mut rng = Rng(0x51DE_C0DE);
    let core = Core {
        vertices: &CENTRE,
        normals: &[],
        radius: 0.0,
    };
    let mut cases = 0;
    for _ in 0..20_000 {
        let u = rng.direction();
        let n = Vector::new(-u.y, u.x);
        let (far, speed) = (rng.uniform(0.1, 10.0), rng.uniform(0.1, 100.0));
        let gap = far * 10f64.powf(rng.uniform(-14.0, -6.0));
        let p0 = -u * far + n * gap;
        let w = u * speed;
        assert_eq!(
            first_entry(&core, p0, w, 2.0 * far / speed, 0.0),
            None,
            "gap {gap:e} at {far}"
        );
        // Within a circle of radius 2·gap about the corner: entered where the line meets it.
        let r = 2.0 * gap;
        let s = first_entry(&core, p0, w, 2.0 * far / speed, r).expect("within the circle");
        let want = (far - (r * r - gap * gap).sqrt()) / speed;
        assert!((s - want).abs() <= 1e-12 * far / speed, "{s} vs {want}");
        cases += 1;
    }
    println!("a_path_passing_a_sharp_corner_does_not_enter_it: {cases} paths");
}

/// A start pose parry could not use — a rotation that is not unit — is left to the general
/// path, on either side, as the non-turning polygon's closed form leaves it: the closed form
/// would read the target's frame from it.
#[test]
fn a_start_pose_parry_cannot_use_is_left_to_the_general_path() {
    let disc = Ellipse::new(0.3, 0.3);
    let target = Cuboid::new(Vector::new(0.5, 0.2));
    let bent = Pose::from_parts(Vector::new(2.0, 0.0), Rotation::from_cos_sin_unchecked(1e-160, -0.886));
    let fine = Pose::from_parts(Vector::new(2.0, 0.0), Rotation::IDENTITY);
    let opts = ToiOptions::default();
    for (p1, p2) in [(bent, Pose::IDENTITY), (Pose::IDENTITY, bent), (fine, Pose::IDENTITY)] {
        let m1 = NonlinearRigidMotion::new(p1, Vector::ZERO, Vector::new(-120.0, 0.0), 0.0);
        let m2 = NonlinearRigidMotion::new(p2, Vector::ZERO, Vector::ZERO, 0.0);
        let c = NonlinearCast::new(&m1, &disc, &m2, &target, (0.0, 1.0 / 60.0), false);
        let answered = disc_cast(&c, &opts, true).is_some();
        assert_eq!(answered, p1 == fine, "{p1:?} / {p2:?}");
    }
}
