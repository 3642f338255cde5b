//! Issue 32, "Hostile input": the nine broken promises a hostile-input pass found, each pinned
//! by the reproduction it was found with, run under a time limit of one second per call (a
//! regression that hangs fails instead of stalling the suite), and the checks of a user's
//! curve at [`CustomCurve::try_new`] (one broken part of the contract at a time, each refused
//! naming its method).
//!
//! And the fuzz over the same kinds of input, `hostile_fuzz_of_every_query_keeps_its_promises`
//! (the hostile batch of `tests/reliability/hostile.rs`: user curves breaking each part of the
//! contract, polygons of 10⁵ vertices, poses far from the origin, extreme motions), every query
//! through the fuzz's checks of `crates/dev/tests/adversarial.rs` (`reliability::run_case`, with its limit
//! per call). f32 sizes are in `crates/smooth-ccd2d-f32/tests/f32_sizes.rs`.
//!
//! Run with `cargo test --test hostile_input -- --nocapture` to see the counts.

mod common;
mod reliability;

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{
    ClosestPoints, ContactManifold, NonlinearRigidMotion, PersistentQueryDispatcher, QueryDispatcher, Ray, RayCast,
    ShapeCastHit, Unsupported,
};
use parry2d_f64::shape::{Ball, Capsule, Compound, Cuboid, HalfSpace, Shape, SharedShape, Triangle};
use smooth_ccd2d::{
    shape_time_of_impact, stationary_distance, time_of_impact, time_of_impact_halfspace, CapsuleEllipse, ConvexCurve,
    CurvePoint, CustomCurve, DistanceOptions, Ellipse, QuadratureStatus, RoundedPolygon, ShapeError, SmoothDispatcher,
    SupportJet, ToiOptions, ToiStatus, MAX_VERTICES,
};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// The time limit of one call.
const CALL_LIMIT: Duration = Duration::from_secs(1);

/// `f()` run on its own thread, or a failure naming `what` when it takes longer than
/// [`CALL_LIMIT`] (the thread is left behind: a hang fails the test instead of stalling it).
fn within<T: Send + 'static>(what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    let start = Instant::now();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    match rx.recv_timeout(CALL_LIMIT) {
        Ok(v) => v,
        Err(_) => panic!("{what}: no answer after {:?}", start.elapsed()),
    }
}

// ---------------------------------------------------------------------------------------------
// User curves: an ellipse (normal-angle parametrisation) with one method broken at a time
// ---------------------------------------------------------------------------------------------

/// What a [`Broken`] ellipse gets wrong.
#[derive(Copy, Clone, Debug, PartialEq)]
enum Break {
    /// Nothing: the ellipse's own methods.
    None,
    /// `bounding_radius` times this factor.
    Radius(f64),
    /// Every number of `eval` rounded to f32 (a curve computed in f32: relative noise 1e-7).
    F32Eval,
    /// `eval` with a relative noise of this size on its point.
    Noise(f64),
    /// `phi_range_of_normal` answers (p, p + this).
    HugeRange(f64),
    /// Inward normals.
    Inward,
    /// Traversed clockwise.
    Clockwise,
    /// `eval` is NaN at φ ∈ [1, 1.1].
    NanEval,
    /// Normals of length 1.01.
    LongNormal,
    /// Breakpoints out of order, or outside [−π, π).
    Breakpoints(&'static [f64]),
    /// `support_jet` returns `None`.
    NoSupportJet,
    /// `support_dd_bound` returns 0.
    ZeroDdBound,
    /// `max_radius_of_curvature` returns the smallest radius.
    SmallMaxRadius,
    /// `min_radius_of_curvature` returns the largest radius.
    LargeMinRadius,
    /// `eval` does not wrap φ outside [−π, π) (the ellipse's points are evaluated as given,
    /// with a drift of φ − wrap(φ)).
    Unwrapped,
    /// `d_point` = 0 (the area of Green's theorem is 0: a body with no mass).
    NoDerivative,
}

#[derive(Debug)]
struct Broken {
    e: Ellipse,
    how: Break,
}

fn broken(how: Break) -> Broken {
    Broken {
        e: Ellipse::new(0.6, 0.3),
        how,
    }
}

/// A deterministic relative noise in [−1, 1] from the bits of φ.
fn noise(phi: f64) -> f64 {
    let mut z = phi.to_bits().wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z ^= z >> 29;
    (z % 2001) as f64 / 1000.0 - 1.0
}

fn round32(v: Vector) -> Vector {
    Vector::new(v.x as f32 as f64, v.y as f32 as f64)
}

impl ConvexCurve for Broken {
    fn eval(&self, phi: f64) -> CurvePoint {
        let mut cp = self.e.eval(phi);
        match self.how {
            Break::F32Eval => {
                for v in [
                    &mut cp.point,
                    &mut cp.d_point,
                    &mut cp.dd_point,
                    &mut cp.normal,
                    &mut cp.d_normal,
                    &mut cp.dd_normal,
                ] {
                    *v = round32(*v);
                }
            }
            Break::Noise(eps) => cp.point *= 1.0 + eps * noise(phi),
            Break::Inward => {
                cp.normal = -cp.normal;
                cp.d_normal = -cp.d_normal;
                cp.dd_normal = -cp.dd_normal;
            }
            Break::Clockwise => {
                cp = self.e.eval(-phi);
                cp.d_point = -cp.d_point;
                cp.d_normal = -cp.d_normal;
            }
            Break::NanEval if (1.0..=1.1).contains(&phi) => cp.point.x = f64::NAN,
            Break::LongNormal => cp.normal *= 1.01,
            Break::Unwrapped if !(-PI..PI).contains(&phi) => {
                cp = self.e.eval(smooth_ccd2d::method::wrap_phi(phi) + 0.5)
            }
            Break::NoDerivative => cp.d_point = Vector::ZERO,
            _ => {}
        }
        cp
    }
    fn breakpoints(&self) -> &[f64] {
        match self.how {
            Break::Breakpoints(b) => b,
            _ => &[],
        }
    }
    fn bounding_radius(&self) -> f64 {
        match self.how {
            Break::Radius(f) => f * self.e.bounding_radius(),
            _ => self.e.bounding_radius(),
        }
    }
    fn phi_range_of_normal(&self, n: Vector) -> (f64, f64) {
        let (lo, hi) = self.e.phi_range_of_normal(n);
        match self.how {
            Break::HugeRange(w) => (lo, lo + w),
            _ => (lo, hi),
        }
    }
    fn support_jet(&self, m: Vector) -> Option<SupportJet> {
        match self.how {
            Break::NoSupportJet => None,
            _ => self.e.support_jet(m),
        }
    }
    fn is_strictly_convex(&self) -> bool {
        true
    }
    fn max_radius_of_curvature(&self) -> f64 {
        match self.how {
            Break::SmallMaxRadius => self.e.min_radius_of_curvature(),
            _ => self.e.max_radius_of_curvature(),
        }
    }
    fn min_radius_of_curvature(&self) -> f64 {
        match self.how {
            Break::LargeMinRadius => self.e.max_radius_of_curvature(),
            _ => self.e.min_radius_of_curvature(),
        }
    }
    fn support_dd_bound(&self) -> f64 {
        match self.how {
            Break::ZeroDdBound => 0.0,
            _ => self.e.support_dd_bound(),
        }
    }
    fn support_dd_bound_near(&self, m: Vector, half_angle: f64) -> f64 {
        match self.how {
            Break::ZeroDdBound => 0.0,
            _ => self.e.support_dd_bound_near(m, half_angle),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 1. mass_properties of a user curve
// ---------------------------------------------------------------------------------------------

/// Item 1: the adaptive integral had no budget and a tolerance from the user's bounding radius;
/// a radius of 0.2× the true one, 0, or an `eval` noisy to 1e-13 never finished (6e8
/// evaluations after 20 s). Now a radius below the curve's own points is refused at wrapping
/// (naming `bounding_radius`), and a noisy curve's quadrature stops at its budget, says so, and
/// is as accurate as the noise.
#[test]
fn user_curve_mass_properties_finish_under_a_wrong_radius_or_a_noisy_eval() {
    let e = Ellipse::new(0.6, 0.3);
    // The reproduction: the radius 0.2 × 0.6.
    let r = within("try_new, radius 0.2×", || {
        CustomCurve::try_new(broken(Break::Radius(0.2)))
    });
    assert!(
        matches!(
            r,
            Err(ShapeError::BrokenContract {
                method: "bounding_radius",
                ..
            })
        ),
        "{r:?}"
    );
    for (f, name) in [(0.0, "0"), (-1.0, "−1"), (f64::NAN, "NaN")] {
        let r = within("try_new, bad radius", move || {
            CustomCurve::try_new(broken(Break::Radius(f)))
        });
        assert!(
            matches!(
                r,
                Err(ShapeError::NotPositive {
                    name: "bounding_radius",
                    ..
                }) | Err(ShapeError::NotFinite {
                    name: "bounding_radius",
                    ..
                })
            ),
            "radius {name}: {r:?}"
        );
    }
    // Noisy curves are accepted; their mass finishes and is right to the noise.
    let exact = e.mass_properties(1.0);
    for how in [Break::Noise(1e-13), Break::Noise(1e-9), Break::F32Eval] {
        let (c, m) = within("wrap and mass of a noisy curve", move || {
            let c = CustomCurve::try_new(broken(how)).expect("a noisy curve passes the checks");
            let m = c.mass_properties(1.0);
            (c, m)
        });
        let q = c.mass_quadrature();
        let rel = (m.mass() - exact.mass()).abs() / exact.mass();
        let rel_i = (m.principal_inertia() - exact.principal_inertia()).abs() / exact.principal_inertia();
        println!(
            "{how:?}: mass off by {rel:.1e}, inertia by {rel_i:.1e}; {:?} after {} evaluations",
            q.status, q.evaluations
        );
        assert!(rel < 1e-6 && rel_i < 1e-6, "{how:?}: {rel} {rel_i}");
        assert!(q.evaluations <= (1 << 17) + 256 * 8, "{how:?}: {q:?}");
    }
    // The f32 curve's noise is above the tolerance: capped, and it says so.
    let c = CustomCurve::try_new(broken(Break::F32Eval)).expect("passes");
    assert_eq!(c.mass_quadrature().status, QuadratureStatus::OutOfEvaluations);
    assert_eq!(
        CustomCurve::new(e).mass_quadrature().status,
        QuadratureStatus::Converged
    );
    // And rapier's insert_with_parent (which asks for the mass) finishes.
    within("rapier insert of a noisy curve", || {
        use rapier2d_f64::prelude::*;
        let (mut bodies, mut colliders) = (RigidBodySet::new(), ColliderSet::new());
        let h = bodies.insert(RigidBodyBuilder::dynamic());
        let shape = SharedShape::new(CustomCurve::new(broken(Break::Noise(1e-13))));
        colliders.insert_with_parent(ColliderBuilder::new(shape).build(), h, &mut bodies);
        assert!(bodies[h].mass() > 0.0);
    });
}

// ---------------------------------------------------------------------------------------------
// 2. the ray cast of a user curve
// ---------------------------------------------------------------------------------------------

/// Item 2: `unwrap_after` added 2π until it passed its base, and from about 5.7e16 on
/// `base + 2π == base`: a `phi_range_of_normal` answering `(p, p + 1e17)` looped for ever in
/// the ray cast. Such a curve is now refused at wrapping; and the ray cast takes a user's range
/// only within one turn (`ray_cast_ends_when_phi_range_of_normal_answers_a_huge_interval` in
/// `src/parry_shape/ray.rs` casts on such a curve directly).
#[test]
fn ray_cast_of_a_user_curve_ends_whatever_its_phi_ranges() {
    for w in [1e17, 5.7e16, 1e300, f64::INFINITY] {
        let r = within("try_new of a curve with huge φ ranges", move || {
            CustomCurve::try_new(broken(Break::HugeRange(w)))
        });
        assert!(
            matches!(
                r,
                Err(ShapeError::BrokenContract {
                    method: "phi_range_of_normal",
                    ..
                })
            ),
            "width {w}: {r:?}"
        );
    }
    // A sound curve's rays, for comparison, in every direction.
    let c = CustomCurve::new(broken(Break::None));
    for k in 0..64 {
        let a = 2.0 * PI * k as f64 / 64.0;
        let dir = Vector::new(a.cos(), a.sin());
        let c = c.clone();
        let hit = within("ray", move || {
            c.cast_local_ray_and_get_normal(&Ray::new(-dir * 3.0, dir), 10.0, true)
        });
        let toi = hit.expect("a ray through the centre hits").time_of_impact;
        assert!(toi > 2.3 && toi < 2.71, "direction {a}: {toi}");
    }
}

// ---------------------------------------------------------------------------------------------
// 3. polygons of many vertices
// ---------------------------------------------------------------------------------------------

/// Item 3: the exact distance of a penetrating pair with no strictly convex side scanned the
/// other polygon once per face: 229 ms at 30,000 vertices, 2.5 s at 100,000, 245 s at 10⁶. The
/// faces and vertex pairs are now swept once (O(n + m)): every query of the pair at
/// 100,000 vertices, and of two such polygons overlapping, in well under a second each.
#[test]
fn queries_on_a_polygon_of_a_hundred_thousand_vertices_take_under_a_second() {
    let n = 100_000;
    let p = RoundedPolygon::regular(n, 1.0, 0.01);
    let q = RoundedPolygon::regular(n, 0.8, 0.0);
    let pose = Pose::new(Vector::new(1.3, 0.2), 0.3);
    let deep = Pose::new(Vector::new(0.3, 0.2), 0.3);
    let others: Vec<(&str, SharedShape, Pose)> = vec![
        ("box", SharedShape::new(Cuboid::new(Vector::new(0.5, 0.2))), pose),
        ("polygon", SharedShape::new(q), deep),
        ("ellipse", SharedShape::new(Ellipse::new(0.5, 0.2)), deep),
    ];
    let p = SharedShape::new(p);
    for (name, other, pose) in others {
        let (p, other) = (p.clone(), other.clone());
        let t = Instant::now();
        let (inter, dist, contact, closest, manifold) = within(name, move || {
            let d = SmoothDispatcher::default();
            let mut m: Vec<ContactManifold<(), ()>> = Vec::new();
            (
                d.intersection_test(&pose, &*p, &*other).expect("answered").intersecting,
                d.distance(&pose, &*p, &*other).expect("answered").distance,
                d.contact(&pose, &*p, &*other, 0.1).expect("answered"),
                d.closest_points(&pose, &*p, &*other, 0.1).expect("answered"),
                d.contact_manifolds(&pose, &*p, &*other, 0.1, &mut m, &mut None)
                    .map(|_| m),
            )
        });
        println!("{name}: five queries on 100,000 vertices in {:?}", t.elapsed());
        // The pairs overlap: the exact answers say so.
        assert!(inter && dist == 0.0, "{name}");
        assert!(contact.is_some_and(|c| c.dist < 0.0), "{name}");
        assert_eq!(closest, ClosestPoints::Intersecting, "{name}");
        assert!(manifold.is_ok(), "{name}");
    }
    // A time of impact: a spinning 100,000-gon against the box.
    let m1 = NonlinearRigidMotion::new(Pose::translation(-3.0, 0.0), Vector::ZERO, Vector::new(1.2, 0.0), 20.0);
    let m2 = NonlinearRigidMotion::identity();
    let r = within("time of impact", move || {
        let p = RoundedPolygon::regular(n, 1.0, 0.01);
        shape_time_of_impact(
            &p,
            &m1,
            &Cuboid::new(Vector::new(0.5, 0.2)),
            &m2,
            0.0,
            2.0,
            &ToiOptions::default(),
        )
    });
    assert_eq!(r.map(|r| r.status), Ok(ToiStatus::Hit));
}

// ---------------------------------------------------------------------------------------------
// 4. far apart, reported touching
// ---------------------------------------------------------------------------------------------

/// Item 4: shapes with flat pieces (a `CapsuleEllipse`, a user curve with a flat piece) 1e155
/// or more apart were `intersecting`, at distance 0, `PenetratingAtStart`: the axis the exact
/// distance starts from, the offset normalised, was 0 when its squared length overflowed. Now
/// a unit axis from any offset: the answer is the distance (or, where it overflows, the
/// documented `Unsupported` / `Degenerate`), never a contact.
#[test]
fn shapes_1e155_and_more_apart_are_never_touching() {
    let ce = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let flat_curve = CustomCurve::new(CapsuleEllipse::new(0.3, 0.6, 0.5));
    let others: Vec<SharedShape> = vec![
        SharedShape::new(RoundedPolygon::regular(6, 1.0, 0.1)),
        SharedShape::new(Cuboid::new(Vector::new(0.5, 0.2))),
        SharedShape::new(Capsule::new_y(0.5, 0.2)),
        SharedShape::new(Triangle::new(Vector::ZERO, Vector::X, Vector::Y)),
        SharedShape::new(CapsuleEllipse::new(0.2, 0.4, 0.3)),
    ];
    let d = SmoothDispatcher::default();
    let mut answered = 0;
    for g1 in [SharedShape::new(ce), SharedShape::new(flat_curve)] {
        for g2 in &others {
            for x in [1e150, 1e155, 1e200, 1e300] {
                let pose = Pose::new(Vector::new(x, -0.3 * x), 0.3);
                if let Ok(i) = d.intersection_test(&pose, &*g1, &**g2) {
                    assert!(!i.intersecting, "{x}: intersecting");
                    answered += 1;
                }
                if let Ok(r) = d.distance(&pose, &*g1, &**g2) {
                    assert!(r.distance > 0.9 * x, "{x}: distance {}", r.distance);
                }
                assert!(
                    !matches!(d.contact(&pose, &*g1, &**g2, 0.1), Ok(Some(_))),
                    "{x}: contact"
                );
                assert!(
                    !matches!(
                        d.closest_points(&pose, &*g1, &**g2, 0.1),
                        Ok(ClosestPoints::Intersecting | ClosestPoints::WithinMargin(..))
                    ),
                    "{x}: closest points"
                );
                let m1 = NonlinearRigidMotion::identity();
                let m2 = NonlinearRigidMotion::constant_position(pose);
                let r = shape_time_of_impact(&*g1, &m1, &**g2, &m2, 0.0, 1.0, &ToiOptions::default());
                assert!(
                    !matches!(r, Ok(ref r) if r.status != ToiStatus::NoHit),
                    "{x}: time of impact {r:?}"
                );
            }
        }
    }
    // Up to 1e300 the distance itself is answered (no square of the offset is taken).
    assert!(answered >= 30, "{answered}");
}

// ---------------------------------------------------------------------------------------------
// 5. the half-space cast far from the origin
// ---------------------------------------------------------------------------------------------

/// Item 5: the half-space cast took its distances between world points: the plane 1e4 from the
/// origin put the hit 2.4e-12·s inside it, 1e8 9.9e-9·s, 1e15 0.17·s (t = 1.75 for 1.8). Now in
/// the half-space's frame from the pair's relative motion: exact at every offset, also through
/// the dispatcher.
#[test]
fn halfspace_cast_far_from_the_origin_is_as_exact_as_at_it() {
    let e = Ellipse::new(0.5, 0.2);
    let hs = HalfSpace::new(Vector::Y);
    let d = SmoothDispatcher::default();
    for off in [0.0, 1e4, 1e8, 1e12, 1e15] {
        // The ellipse's centre 2 above the plane, falling at 1 m/s: its bottom (0.2 below the
        // centre) reaches the plane at t = 1.8. Both positions are exact in f64.
        let mc = NonlinearRigidMotion::new(
            Pose::translation(off, off + 2.0),
            Vector::ZERO,
            Vector::new(0.0, -1.0),
            0.0,
        );
        let mh = NonlinearRigidMotion::constant_position(Pose::translation(off, off));
        let r = time_of_impact_halfspace(&e, &mc, &hs, &mh, 0.0, 5.0, &ToiOptions::default()).expect("answered");
        assert_eq!(r.status, ToiStatus::Hit);
        assert!((r.time - 1.8).abs() <= 1e-12, "offset {off}: t = {}", r.time);
        let hit = d
            .cast_shapes_nonlinear(&mc, &e, &mh, &hs, 0.0, 5.0, true)
            .expect("answered")
            .expect("a hit");
        assert!(
            (hit.time_of_impact - 1.8).abs() <= 1e-12,
            "dispatcher, offset {off}: t = {}",
            hit.time_of_impact
        );
        // A spinning one: the same answer as at the origin.
        let spin = |o: f64| {
            let mc = NonlinearRigidMotion::new(
                Pose::new(Vector::new(o, o + 2.0), 0.3),
                Vector::ZERO,
                Vector::new(0.3, -1.0),
                7.0,
            );
            let mh = NonlinearRigidMotion::constant_position(Pose::translation(o, o));
            time_of_impact_halfspace(&e, &mc, &hs, &mh, 0.0, 5.0, &ToiOptions::default()).expect("answered")
        };
        let (far, near) = (spin(off), spin(0.0));
        assert_eq!(far.status, near.status);
        assert!(
            (far.time - near.time).abs() <= 1e-12,
            "offset {off}: {} vs {}",
            far.time,
            near.time
        );
    }
}

// ---------------------------------------------------------------------------------------------
// 6. underflow
// ---------------------------------------------------------------------------------------------

/// Item 6: the bounding-circle test took the time of closest approach −Δ·v/|v|², and |v|²
/// underflowed to 0 below about 1e-162 m/s (overflowed above 1e154): an approach at 1e-200 m/s
/// over a window of 1e201 s answered `NoHit` at t = 0 (contact at 1.2e200 s) in the φ–t
/// tracker, the gap tracker and the dispatcher. With v scaled by its largest component when |v|²
/// leaves the normal range, all three find the hit at the speed's own scale, at 1e-300 too.
#[test]
fn approach_at_1e_minus_200_meters_per_second_is_a_hit() {
    let (a, b) = (Ellipse::new(0.5, 0.2), Ellipse::new(0.3, 0.3));
    let (p, c) = (RoundedPolygon::regular(5, 0.5, 0.0), Cuboid::new(Vector::new(0.3, 0.3)));
    let d = SmoothDispatcher::default();
    for v in [1.0, 1e-160, 1e-200, 1e-300] {
        let m1 = NonlinearRigidMotion::new(Pose::translation(-2.0, 0.0), Vector::ZERO, Vector::new(v, 0.0), 0.0);
        let m2 = NonlinearRigidMotion::identity();
        let t1 = 10.0 / v;
        // The ellipse's +x tip reaches the disc at x = −0.3: the centre travels 1.2.
        let r = time_of_impact(&a, &m1, &b, &m2, 0.0, t1, &ToiOptions::default()).expect("answered");
        assert_eq!(r.status, ToiStatus::Hit, "{v}");
        assert!((r.time * v - 1.2).abs() < 1e-9, "φ–t tracker at {v}: {}", r.time * v);
        // The pentagon's vertex at +x (circumradius 0.5) reaches the box at x = −0.3: 1.2 too.
        let r = shape_time_of_impact(&p, &m1, &c, &m2, 0.0, t1, &ToiOptions::default()).expect("answered");
        assert_eq!(r.status, ToiStatus::Hit, "{v}");
        assert!((r.time * v - 1.2).abs() < 1e-9, "gap tracker at {v}: {}", r.time * v);
        let hit = d
            .cast_shapes_nonlinear(&m1, &a, &m2, &b, 0.0, t1, true)
            .expect("answered")
            .expect("a hit");
        assert!((hit.time_of_impact * v - 1.2).abs() < 1e-9, "dispatcher at {v}");
    }
}

/// Found by the fuzz with another seed (`FUZZ_SEED=777`, case 6968): a window from −1e300 s to
/// −1 s, two bodies 1e-4 in size meeting near its end. The tracker halved its way from the start
/// to t ≈ −1.1e287 and then recovered with the global distance at t + h, which rounded to 0 (the
/// window's end, −1, is lost against 1e287): a hit at 0, after the window. Every tracker's next
/// time is now kept within the window; the hit is at its end, where the pair touches.
#[test]
fn a_window_ending_far_from_its_start_keeps_every_answer_inside_it() {
    let p = RoundedPolygon::try_regular(10, 6.583887209729579e-5, 2.5898850691172458e-5).expect("valid");
    let b = Ellipse::new(0.00013066506841059132, 0.00013066506841059132);
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::new(-0.0, -9.960467120501367e-6),
        Vector::new(-7.045141471315296e-5, 7.145894484436469e-5),
        5e-324,
    );
    let start2 = Pose::from_parts(
        Vector::new(1.3427850226082439e-5, 5.86613868106411e-5),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(0.9505975648210587, 0.31042594890935427),
    );
    let m2 = NonlinearRigidMotion::new(
        start2,
        Vector::new(-5.6161949771065445e-6, 1e20),
        Vector::new(7.156175118024756e-5, 2.5148291494086983e-5),
        0.0,
    );
    let (t0, t1) = (-1e300, -1.0);
    let o = ToiOptions::default().with_stop_at_penetration(true);
    let r = within("time_of_impact", move || time_of_impact(&p, &m1, &b, &m2, t0, t1, &o)).expect("answered");
    assert!(
        (t0..=t1).contains(&r.time),
        "{:?} at {} outside [{t0}, {t1}]",
        r.status,
        r.time
    );
    assert_eq!(r.status, ToiStatus::Hit);
}

/// Found by the fuzz with another seed (`FUZZ_SEED=2004`, case 122492), in rapier's cast of a
/// polygon that does not turn (in closed form, as a disc's): a window from −1.8e308 s to
/// −1.38 s, where the start plus the entry's offset rounds past the window's end. The closed
/// forms' times are kept within the window.
#[test]
fn a_closed_form_cast_over_a_window_ending_far_from_its_start_stays_inside_it() {
    let p = RoundedPolygon::try_regular(10, 2.509739471376431e-6, 3.0752608652163396e-7).expect("valid");
    let q = RoundedPolygon::try_new(
        &[
            Vector::new(-6.07458065535825e-6, -2.528236234554779e-6),
            Vector::new(6.562311006503291e-6, -1.668740082707563e-6),
            Vector::new(5.7054280188391075e-6, 2.989501685379284e-6),
            Vector::new(5.638999177641803e-6, 3.062381809026463e-6),
            Vector::new(5.0240907127375235e-6, 3.63534475810723e-6),
            Vector::new(-6.9112637153172104e-6, 1.814885990066977e-7),
        ],
        1.9223336181371837e-6,
    )
    .expect("valid");
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::new(-5.581405653857503e-7, 3.133657443641483e-7),
        Vector::new(-5.3416986518452875e-6, -9.591119592255376e-6),
        0.0,
    );
    let start2 = Pose::from_parts(
        Vector::new(6.3298184099516535e-6, 9.614719329102188e-6),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.9952068144095766, 0.09779262013435641),
    );
    let m2 = NonlinearRigidMotion::new(
        start2,
        Vector::ZERO,
        Vector::new(-4.097794192889215e-6, 4.522391117438657e-6),
        0.0,
    );
    let (t0, t1) = (-f64::MAX, -1.379789359758342);
    for (g1, g2, a, b) in [(&p, &q, &m1, &m2), (&q, &p, &m2, &m1)] {
        let (g1, g2, a, b) = (g1.clone(), g2.clone(), *a, *b);
        let hit = within("cast_shapes_nonlinear", move || {
            SmoothDispatcher::default().cast_shapes_nonlinear(&a, &g1, &b, &g2, t0, t1, true)
        })
        .expect("answered");
        if let Some(h) = hit {
            assert!(
                (t0..=t1).contains(&h.time_of_impact),
                "a hit at {} outside [{t0}, {t1}]",
                h.time_of_impact
            );
        }
    }
}

/// Found by the fuzz with another seed (`FUZZ_SEED=3004`, case 157457): two parry balls of
/// radius −0 and 1e-300 (points) passing each other at about 100 m/s. The pair's rates, 1e302
/// sizes a second, sent rapier's policy to a time scale where they are about 1 — and parry's own
/// cast, which answers the pair, to a window of 1e302 s, where its conservative advancement
/// with absolute time tolerances never ended. parry's own pairs now keep the caller's time
/// scale: the call answers at once (parry itself, on the same input, answers no hit in 10 µs).
#[test]
fn parry_balls_of_no_size_passing_each_other_are_answered_at_once() {
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(38.78496442129538, 101.40148917307064),
        -6.083702193247845,
    );
    let start2 = Pose::from_parts(
        Vector::new(0.0, 47.28740043084232),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.8807951589750529, 0.4734975057232205),
    );
    let m2 = NonlinearRigidMotion::new(
        start2,
        Vector::ZERO,
        Vector::new(-11.563600781145531, -78.24517107232525),
        0.0,
    );
    for (r1, r2) in [(-0.0, 1e-300), (1e-300, -0.0)] {
        let r = within("cast_shapes_nonlinear", move || {
            SmoothDispatcher::default().cast_shapes_nonlinear(
                &m1,
                &Ball::new(r1),
                &m2,
                &Ball::new(r2),
                0.0,
                1.1502567991219912,
                false,
            )
        });
        if let Ok(Some(h)) = r {
            assert!(h.time_of_impact.is_finite() && (0.0..=1.1502567991219912).contains(&h.time_of_impact));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 7. constructors that allocate from a count
// ---------------------------------------------------------------------------------------------

/// Item 7: `RoundedPolygon::try_regular(usize::MAX, …)` panicked (capacity overflow) and
/// `try_regular(1 << 40, …)` aborted the process (17 TB): documented to return `ShapeError`.
/// The count is checked against `MAX_VERTICES` before anything is allocated.
#[test]
fn regular_polygon_of_too_many_sides_is_refused_before_it_allocates() {
    for sides in [usize::MAX, 1 << 40, MAX_VERTICES + 1] {
        let r = within("try_regular", move || {
            RoundedPolygon::try_regular(sides, 1.0, 0.1).map(|_| ())
        });
        assert_eq!(r, Err(ShapeError::TooManyVertices { count: sides }));
        assert!(r.unwrap_err().to_string().contains("vertices"));
    }
    // The limit itself is accepted.
    let big = within("try_regular at the limit", || {
        RoundedPolygon::try_regular(MAX_VERTICES, 1.0, 0.0).map(|p| p.vertices().len())
    });
    assert_eq!(big, Ok(MAX_VERTICES));
    let too_many = vec![Vector::ZERO; MAX_VERTICES + 1];
    assert_eq!(
        RoundedPolygon::try_new(&too_many, 0.0),
        Err(ShapeError::TooManyVertices {
            count: MAX_VERTICES + 1
        })
    );
}

// ---------------------------------------------------------------------------------------------
// 9. non-finite poses
// ---------------------------------------------------------------------------------------------

/// Item 9: an infinite pose made intersection, contact, closest points and manifolds answer
/// `Ok(false / None / Disjoint / empty)` (the bounding-circle rejection took the infinite
/// distance as apart); the documented answer, given for NaN, is `Err(Unsupported)`. Every pair
/// kind, every query, every non-finite number in the translation or the rotation.
#[test]
fn non_finite_pose_is_unsupported_in_every_dispatcher_query() {
    let shapes: Vec<SharedShape> = vec![
        SharedShape::new(Ellipse::new(0.5, 0.2)),
        SharedShape::new(RoundedPolygon::regular(5, 0.5, 0.1)),
        SharedShape::new(CapsuleEllipse::new(0.3, 0.5, 0.4)),
        SharedShape::new(CustomCurve::new(Ellipse::new(0.3, 0.6))),
        SharedShape::new(Cuboid::new(Vector::new(0.5, 0.2))),
        SharedShape::new(Ball::new(0.3)),
        SharedShape::new(HalfSpace::new(Vector::Y)),
        SharedShape::new(Compound::new(vec![(
            Pose::IDENTITY,
            SharedShape::new(Ellipse::new(0.2, 0.1)),
        )])),
    ];
    let d = SmoothDispatcher::default();
    let mut checked = 0;
    for x in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
        let poses = [
            Pose::new(Vector::new(x, 0.0), 0.0),
            Pose::new(Vector::new(0.0, x), 0.0),
            Pose::from_parts(
                Vector::new(1.0, 0.0),
                parry2d_f64::math::Rotation::from_cos_sin_unchecked(x, 0.0),
            ),
        ];
        for pose in poses {
            for (i, g1) in shapes.iter().enumerate() {
                for (j, g2) in shapes.iter().enumerate() {
                    if i >= 6 && j >= 6 {
                        continue; // two half-spaces or compounds without a shape of ours
                    }
                    let what = format!("shapes {i}, {j}, pose {pose:?}");
                    assert!(d.intersection_test(&pose, &**g1, &**g2).is_err(), "intersection {what}");
                    assert!(d.distance(&pose, &**g1, &**g2).is_err(), "distance {what}");
                    assert!(d.contact(&pose, &**g1, &**g2, 0.1).is_err(), "contact {what}");
                    assert!(d.closest_points(&pose, &**g1, &**g2, 0.1).is_err(), "closest {what}");
                    let mut m: Vec<ContactManifold<(), ()>> = Vec::new();
                    let r = d.contact_manifolds(&pose, &**g1, &**g2, 0.1, &mut m, &mut None);
                    assert!(r.is_err(), "manifolds {what}");
                    checked += 5;
                }
            }
        }
    }
    println!("non-finite poses: {checked} queries, each Err(Unsupported)");
}

/// Found by the adversarial fuzz with seed 20261127 (case 75845): under rapier's policies a pair
/// in contact at the start is answered at a nudge of the window past its start, with the pair's
/// contact there for witnesses; a spin of 1e160 rad/s over a window of 1e300 s reaches that
/// time only by overflowing, and the hit came out with zero witnesses and a NaN normal. Every
/// cast of a pair touching at the start, every pair kind and policy, spins and windows whose
/// product overflows: `Err(Unsupported)` or a hit whose every number is finite.
#[test]
fn start_contact_at_a_time_the_motions_overflow_to_is_unsupported_never_nan() {
    use smooth_ccd2d::CastPolicy;
    let shapes: Vec<SharedShape> = vec![
        SharedShape::new(RoundedPolygon::regular(12, 0.0052, 0.0013)),
        SharedShape::new(RoundedPolygon::regular(4, 0.006, 0.0)),
        SharedShape::new(Ellipse::new(0.0011, 0.0118)),
        SharedShape::new(Ellipse::new(0.005, 0.005)),
        SharedShape::new(CapsuleEllipse::new(0.003, 0.004, 0.006)),
        SharedShape::new(Ball::new(0.005)),
        SharedShape::new(Cuboid::new(Vector::new(0.004, 0.006))),
        SharedShape::new(parry2d_f64::shape::Segment::new(
            Vector::new(-0.01, 0.0),
            Vector::new(0.01, 0.0),
        )),
        SharedShape::new(Capsule::new_y(0.003, 0.002)),
    ];
    let pose2 = Pose::from_parts(
        Vector::new(-0.0012, -0.0021),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.003136167043825366, -0.9999950822160443),
    );
    let (mut casts, mut refused) = (0, 0);
    for policy in [CastPolicy::Rapier, CastPolicy::RapierConstantSpin, CastPolicy::Plain] {
        let d = SmoothDispatcher::default().with_cast_policy(policy);
        for g1 in &shapes {
            for g2 in &shapes {
                for (w1, w2, t1) in [(1e160, -19.9, 1e300), (0.0, 1e160, 1e200), (1e160, 0.0, 1e200)] {
                    let m1 = NonlinearRigidMotion::new(Pose::IDENTITY, Vector::ZERO, Vector::new(-0.011, 0.005), w1);
                    let m2 = NonlinearRigidMotion::new(pose2, Vector::ZERO, Vector::new(0.0034, 0.0007), w2);
                    for stop in [false, true] {
                        let r = d.cast_shapes_nonlinear(&m1, &**g1, &m2, &**g2, 0.0, t1, stop);
                        casts += 1;
                        match r {
                            Err(_) => refused += 1,
                            Ok(None) => {}
                            Ok(Some(h)) => assert!(
                                h.time_of_impact.is_finite()
                                    && h.witness1.is_finite()
                                    && h.witness2.is_finite()
                                    && h.normal1.is_finite()
                                    && h.normal2.is_finite(),
                                "{policy:?} {:?} against {:?}, spins {w1:e} and {w2:e} over [0, {t1:e}]: {h:?}",
                                g1.shape_type(),
                                g2.shape_type(),
                            ),
                        }
                    }
                }
            }
        }
    }
    println!("casts at overflowing times: {casts}, Err(Unsupported) {refused}, the rest finite");
    // The policies' start-contact answers are the ones refused; the pairs are in contact.
    assert!(refused > casts / 4, "{refused} of {casts} refused");
}

/// The promise the hostile fuzz with seed 99 (case 531) found stated too widely: a cast on a
/// time scale of 2^k answers as on the ordinary scale, with its time scaled, unless the
/// answer's own rate of distance is beyond f64's range — a spinning half-space's turn times the
/// lever arm to the far contact, at 2^1000 — where the answer is `Degenerate`
/// (`QueryError::Degenerate`; the fuzz had expected the ordinary answer). That case's
/// capsule-ellipse (17 596, 3 859, 9 693) and half-space (moving at 5e5 m/s and spinning at
/// 4.8 rad/s, the contact 5e6 m from its centre), its time scaled by 2^k for k = −1000 … 1000
/// (every 50, and every 1 from −1000 to −990, where the rates reach 1e307).
#[test]
fn halfspace_cast_answers_alike_on_every_time_scale() {
    let shape = CapsuleEllipse::new(17596.32492950854, 3858.834104952514, 9692.58743683483);
    let plane = HalfSpace::new(Vector::new(
        (-1.5003572930047504f64).cos(),
        (-1.5003572930047504f64).sin(),
    ));
    let hs_pose = Pose::from_parts(
        Vector::new(-84202.76467746461, -127987.46116208693),
        parry2d_f64::math::Rotation::from_cos_sin_unchecked(0.04961528762791126, 0.9987684032014628),
    );
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(1346403.6867640833, -461346.6492651799),
        55.19429736439399,
    );
    let m2 = NonlinearRigidMotion::new(
        hs_pose,
        Vector::ZERO,
        Vector::new(-185546.482384213, 493626.5746941382),
        -4.788139072837382,
    );
    let (mut checked, mut unrepresentable) = (0, 0);
    for (t0, t1, stop) in [
        (2.9579598316465, 3.0419384651048547, true),
        (2.0, 3.2, false),
        (0.0, 0.5, false),
    ] {
        let o = ToiOptions::default().with_stop_at_penetration(stop);
        let base = time_of_impact_halfspace(&shape, &m1, &plane, &m2, t0, t1, &o).unwrap();
        for k in (-20..=20).map(|i| 50 * i).chain(-1000..-990) {
            let s = 2f64.powi(k);
            let fast = |m: &NonlinearRigidMotion| {
                NonlinearRigidMotion::new(m.start, m.local_center, m.linvel / s, m.angvel / s)
            };
            let r = time_of_impact_halfspace(&shape, &fast(&m1), &plane, &fast(&m2), t0 * s, t1 * s, &o);
            checked += 1;
            match r {
                Err(e) => {
                    assert!(
                        e == smooth_ccd2d::QueryError::Degenerate && !(base.distance_rate / s).is_finite(),
                        "2^{k}: {e:?}, unscaled {base:?}"
                    );
                    unrepresentable += 1;
                }
                Ok(r) => {
                    assert_eq!(r.status, base.status, "2^{k}");
                    assert!(
                        (r.time / s - base.time).abs() <= 1e-12 * (t1 - t0),
                        "2^{k}: {} vs {}",
                        r.time / s,
                        base.time
                    );
                }
            }
        }
    }
    println!("half-space casts on 51 time scales: {checked}, {unrepresentable} Degenerate (a rate of distance beyond f64), the rest as on the ordinary scale");
}

/// Hostile seed 5105, case 1153: a rounded 100,000-gon (radius 169, corners 29) turning at
/// −52 rad/s against a `CapsuleEllipse` turning at 38 rad/s over a window of 9.3 s, 140 turns
/// of one relative to the other. Each exact distance of the gap tracker walked from the last
/// axis across the polygon's tiny normal cones one at a time, about 19,000 of them a call: 3.8 s
/// for a time of impact, past the fuzz's 2 s limit. The walk now jumps ahead where it is long
/// (O(log n) support searches): every query of the case well within the limit, its promises
/// kept.
#[test]
fn a_cast_of_a_many_sided_polygon_turning_many_times_answers_well_within_the_call_limit() {
    use reliability::hostile::{compare, hostile};
    let (case, expect) = hostile(5105, 1153);
    assert_eq!(case.class, "huge-polygon");
    let mut out = reliability::run_case(&case);
    out.violations.extend(compare(&case, &expect));
    assert!(out.violations.is_empty(), "{:?}", out.violations);
    println!(
        "hostile 5105/1153: slowest call {:?} ({})",
        out.slowest.0, out.slowest.1
    );
    assert!(
        out.slowest.0 < reliability::CALL_LIMIT / 4,
        "slowest call {:?} ({})",
        out.slowest.0,
        out.slowest.1
    );
}

/// Fuzz seed 5032, case 79067 (`crates/dev/tests/adversarial.rs`): a thin ellipse and a
/// compound of one ellipse, 0.1 m apart and moving side by side at 1e20 m/s, cast over half a
/// second. The pair goes to parry's composite cast, which saw positions of 1e19 m — rounded by
/// 1e3 m, ten thousand times the bodies — and its advancement, moved by that rounding at every
/// step, ran for ever (more than 20 s); with the compound first, on the time scale the
/// dispatcher takes for rates beyond 2^64 (a window of 5.7e20 s), parry's absolute time
/// tolerances did the same. Parry's casts now get the motions seen from the body that does not
/// turn (`input_guard::resolved_motions`) and the caller's time scale: the answer at once, the
/// same as for the same relative motion near the origin.
#[test]
fn a_composite_cast_of_bodies_side_by_side_at_1e20_m_per_s_answers_at_once() {
    // The pair's casts in both orders (the compound first: a window rescaled for the rates of
    // 1e20 m/s, which parry's composite helper must not get), both motions shifted by −shift and
    // moving by `common` besides their own.
    fn cast(shift: Vector, common: Vector) -> [Result<Option<ShapeCastHit>, Unsupported>; 2] {
        let ellipse = Ellipse::new(0.00043654616129277564, 0.06672093399598593);
        let part = Pose::new(
            Vector::new(0.033360466997992964, 0.0),
            (-0.9165356509417905f64).atan2(0.39995299792939215),
        );
        let compound = Compound::new(vec![(
            part,
            SharedShape::new(Ellipse::new(0.04003256039759156, 0.02001628019879578)),
        )]);
        let turned = (0.9869190977011687f64).atan2(0.1612162975406362);
        let m1 = NonlinearRigidMotion::new(
            Pose::translation(-shift.x, -shift.y),
            Vector::new(-0.009055778579886117, -0.008097205025047445),
            common + Vector::new(0.0, 0.5609752929646611),
            0.0,
        );
        let m2 = NonlinearRigidMotion::new(
            Pose::new(Vector::new(0.01346469952869244, -0.10048141844158512) - shift, turned),
            Vector::ZERO,
            common + Vector::new(0.0, 0.3623689006538127),
            -0.0,
        );
        let d = SmoothDispatcher::default();
        [
            d.cast_shapes_nonlinear(&m1, &ellipse, &m2, &compound, 0.0, 0.4831652517656168, false),
            d.cast_shapes_nonlinear(&m1, &compound, &m2, &ellipse, 0.0, 0.4831652517656168, false),
        ]
    }
    // On a thread of its own: a cast that runs for ever fails the test instead of stalling it.
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(cast(Vector::ZERO, Vector::new(1e20, 0.0)));
    });
    let limit = reliability::CALL_LIMIT / 4;
    let fast = rx
        .recv_timeout(limit)
        .unwrap_or_else(|_| panic!("the casts still run after {limit:?}"));
    // The same relative motion near the origin (the compound at rest there): overlapping at the
    // start and parting, no hit with `stop_at_penetration = false`.
    let slow = cast(
        Vector::new(0.01346469952869244, -0.10048141844158512),
        Vector::new(0.0, -0.3623689006538127),
    );
    for hit in fast.iter().chain(&slow) {
        assert_eq!(hit.as_ref().map(|h| h.is_none()), Ok(true), "{fast:?} {slow:?}");
    }
}

/// Hostile seed 5106, case 1659: a capsule-ellipse (1153, 248, 1626) turning at −1.8e302 rad/s
/// and moving at 8.3e306 m/s against a half-space turning at −6.0e302 rad/s and moving at
/// 5.3e306 m/s, over a window of 8.3e-304 s (3.4e-301 s after 0): the steps' bounds overflowed
/// and the cast answered `Degenerate`, where the same motion on a time scale 2^−1000 slower
/// answers `NoHit`. The half-space cast now asks such rates on a rescaled time, as
/// `time_of_impact` does: the same answer on both scales.
/// Adversarial fuzz seed 5014, case 44828: a `CapsuleEllipse` of r1 : r2 = 1 : 9.3e5 (the edge
/// of the supported axis ratios) touching a 1 : 7,900 ellipse's flank with the end of its arc
/// beside the segment, where its normal turns by about 1e-5 rad per unit in the last place of φ.
/// The stationary distance ended there on two adjacent floats of φ with distanceSide at 5e-8
/// and jittered between −3.4e-13 and +2.5e-16 over picoseconds of the motion (2e-8 of the size,
/// 1e-12 promised); Newton's steps over the normal angle (`query::polish`) now give the exact
/// contact query's distance and witnesses (an independent method: the minimum of the support
/// functions over the normal angle) at every time, and the status of its sign.
#[test]
fn a_needle_arc_that_phi_cannot_resolve_gets_the_exact_stationary_distance() {
    let a = CapsuleEllipse::new(1.1756974580030133e-11, 1.0970018038101628e-5, 8.246317336479094e-6);
    let b = Ellipse::new(2.197602988639123e-9, 1.733767065333242e-5);
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::ZERO,
        Vector::new(-4.8034450365496056e-8, 7.722378964231305e-6),
        -53.2243525344351,
    );
    let m2 = NonlinearRigidMotion::new(
        Pose::from_parts(
            Vector::new(6.4870460886455655e-6, 3.7645466842405977e-5),
            parry2d_f64::math::Rotation::from_cos_sin_unchecked(0.8219896066645191, -0.5695024903681363),
        ),
        Vector::ZERO,
        Vector::new(4.964741239889841e-6, -5.7094652291015695e-6),
        -32.796748176138856,
    );
    let size = a.bounding_radius().max(b.bounding_radius());
    let d = SmoothDispatcher::default();
    // The fuzz's hit time, and picoseconds around it: the pair moves by 1e-15 m a picosecond.
    let hit = 0.9523974931482061;
    let mut worst: f64 = 0.0;
    for k in -10..=10 {
        let t = hit + k as f64 * 1e-12;
        let pos12 = m1.position_at_time(t).inv_mul(&m2.position_at_time(t));
        let s = stationary_distance(&a, &b, &pos12, &DistanceOptions::default()).unwrap();
        let c = d.contact(&pos12, &a, &b, 1.0).unwrap().unwrap();
        let err = (s.distance - c.dist).abs();
        worst = worst.max(err / size);
        assert!(err <= 1e-12 * size, "t = {t}: {} against {}", s.distance, c.dist);
        assert!((s.point1 - c.point1).length() <= 1e-12 * size, "t = {t}: point1");
        assert!((s.point2 - c.point2).length() <= 1e-12 * size, "t = {t}: point2");
        let apart = smooth_ccd2d::DistanceStatus::Separated;
        assert_eq!(
            s.status == apart,
            s.distance > 0.0,
            "t = {t}: {:?} at {}",
            s.status,
            s.distance
        );
    }
    println!("needle arc: worst |stationary − exact contact| {worst:.1e} of the size over 21 times");
}

/// Adversarial fuzz seed 5042, case 29513 (`wild`): a parry `Ball` of radius 1e160 against a
/// rounded hexagon at a pose whose rotation is not unit ((1e20, −0.36)). The pair's manifold
/// came from the stationary distance, and its new core contacts (a user's curve's, a polygon's
/// the exact contact query does not read) put a point at (−∞, −∞) in body 2's frame; such a
/// point is now left out, and every query of the case keeps its promises.
#[test]
fn a_core_contact_that_leaves_f64_in_the_other_bodys_frame_is_left_out() {
    let case = reliability::generate(5042, 29513);
    let out = within("seed 5042, case 29513", move || reliability::run_case(&case));
    assert!(out.violations.is_empty(), "{:?}", out.violations);
}

#[test]
fn halfspace_cast_at_speeds_near_the_largest_float_answers_as_on_an_ordinary_time_scale() {
    let shape = CapsuleEllipse::new(1153.3140806495276, 247.99646258840284, 1625.8808178461309);
    let plane = HalfSpace::new(Vector::new(2.50617742176697f64.cos(), 2.50617742176697f64.sin()));
    let m1 = NonlinearRigidMotion::new(
        Pose::IDENTITY,
        Vector::new(-532.278763160718, 675.8979939503903),
        Vector::new(8.278734823079186e306, -2.2096967042384525e304),
        -1.8227849416608437e302,
    );
    let m2 = NonlinearRigidMotion::new(
        Pose::from_parts(
            Vector::new(159.61864580987213, -1662.173976309729),
            parry2d_f64::math::Rotation::from_cos_sin_unchecked(-0.8827046285351703, 0.46992822724602007),
        ),
        Vector::ZERO,
        Vector::new(4.122629139791279e306, 3.2764118478829426e306),
        -6.0386591952442085e302,
    );
    let (t0, t1) = (3.417310090086945e-301, 3.4256241776342636e-301);
    let o = ToiOptions::default().with_stop_at_penetration(true);
    let fast = time_of_impact_halfspace(&shape, &m1, &plane, &m2, t0, t1, &o).unwrap();
    let s = 2f64.powi(-1000);
    let slow =
        |m: &NonlinearRigidMotion| NonlinearRigidMotion::new(m.start, m.local_center, m.linvel * s, m.angvel * s);
    let base = time_of_impact_halfspace(&shape, &slow(&m1), &plane, &slow(&m2), t0 / s, t1 / s, &o).unwrap();
    assert_eq!(fast.status, base.status);
    assert_eq!(fast.status, smooth_ccd2d::ToiStatus::NoHit);
    assert!((fast.time / t1 - 1.0).abs() <= 1e-12, "{} vs {}", fast.time, t1);
}

// ---------------------------------------------------------------------------------------------
// The checks of a user's curve
// ---------------------------------------------------------------------------------------------

/// Each checkable part of the contract, broken alone, is refused at wrapping with a
/// `ShapeError` naming the method that breaks it (and `CustomCurve::new` panics with it); the
/// same curve unbroken, noisy in f32, or with a radius overstated, is accepted.
#[test]
fn custom_curve_refuses_each_broken_part_of_the_contract_naming_its_method() {
    let cases: [(Break, &str); 15] = [
        (Break::Radius(0.5), "bounding_radius"),
        (Break::Radius(1.0 - 1e-4), "bounding_radius"),
        (Break::Inward, "eval"),
        (Break::Clockwise, "eval"),
        (Break::NanEval, "eval"),
        (Break::LongNormal, "eval"),
        (Break::Unwrapped, "eval"),
        (Break::NoDerivative, "eval"),
        (Break::Breakpoints(&[1.0, 0.5]), "breakpoints"),
        (Break::Breakpoints(&[-4.0, 0.5]), "breakpoints"),
        (Break::NoSupportJet, "support_jet"),
        (Break::ZeroDdBound, "support_dd_bound"),
        (Break::SmallMaxRadius, "max_radius_of_curvature"),
        (Break::LargeMinRadius, "min_radius_of_curvature"),
        (Break::HugeRange(10.0), "phi_range_of_normal"),
    ];
    for (how, method) in cases {
        let r = within("try_new", move || CustomCurve::try_new(broken(how)));
        match r {
            Err(ShapeError::BrokenContract { method: m, reason, at }) => {
                assert_eq!(m, method, "{how:?}: {reason} at {at}");
                println!("{how:?}: refused, `{m}`: {reason} (at {at})");
            }
            other => panic!("{how:?}: {other:?}"),
        }
    }
    // `new` panics with the error's message, naming the method.
    let msg = std::panic::catch_unwind(|| CustomCurve::new(broken(Break::Inward)))
        .map(|_| ())
        .expect_err("new panics");
    let msg = msg.downcast_ref::<String>().cloned().unwrap_or_default();
    assert!(msg.contains("ConvexCurve::eval"), "{msg}");
    for how in [Break::None, Break::F32Eval, Break::Noise(1e-13), Break::Radius(3.0)] {
        assert!(CustomCurve::try_new(broken(how)).is_ok(), "{how:?}");
    }
}

/// Found by the hunt through composite casts (a mesh with a degenerate triangle): a flat
/// triangle — two vertices equal, or all three on a line — had no curve, so its casts went to
/// parry's conservative advancement; against a turning user curve (`EccentricEllipse` 0.114 ×
/// 0.046) over a window of 384 s one cast ran for more than 15 s. A flat triangle is now its hull,
/// the segment between its two farthest vertices: every query answers as for that `Segment`, to
/// the bit, each within the time limit (random flat triangles, both kinds, against the user
/// curve turning at up to 5 rad/s over windows of up to 400 s, and against the crate's ellipse).
#[test]
fn a_flat_triangle_answers_as_the_segment_it_is() {
    let mut rng = common::rng::Rng::new(0xF1A7);
    let d = SmoothDispatcher::default();
    let (mut casts, mut hits) = (0, 0);
    for case in 0..120 {
        let (p, q) = (
            Vector::new(rng.uniform(-3.0, 3.0), rng.uniform(-1.0, 1.0)),
            Vector::new(rng.uniform(-3.0, 3.0), rng.uniform(-1.0, 1.0)),
        );
        // Two vertices equal, or the third between the other two.
        let triangle = if case % 2 == 0 {
            Triangle::new(p, q, q)
        } else {
            Triangle::new(p, q, p + (q - p) * rng.uniform(0.1, 0.9))
        };
        let segment = parry2d_f64::shape::Segment::new(p, q);
        let s = rng.log_uniform(0.1, 1.0);
        let body: Box<dyn Shape> = if case % 3 == 0 {
            Box::new(Ellipse::new(0.5 * s, 0.2 * s))
        } else {
            Box::new(CustomCurve::new(common::curves::EccentricEllipse {
                a: 0.5 * s,
                b: 0.2 * s,
                center: Vector::new(0.05 * s, 0.0),
            }))
        };
        let start = Pose::new(Vector::new(rng.uniform(-4.0, 4.0), rng.uniform(1.5, 3.0)), rng.angle());
        let aim = Vector::new(rng.uniform(-3.0, 3.0), rng.uniform(-1.0, 1.0)) - start.translation;
        let window = rng.log_uniform(0.5, 400.0);
        let m1 = NonlinearRigidMotion::new(start, Vector::new(0.01, 0.0), aim / window, rng.uniform(-5.0, 5.0));
        let m2 = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
        let body: std::sync::Arc<dyn Shape> = body.into();
        for stop in [false, true] {
            let (b, t) = (body.clone(), triangle);
            let on_triangle = within("cast against a flat triangle", move || {
                SmoothDispatcher::default().cast_shapes_nonlinear(&m1, &*b, &m2, &t, 0.0, window, stop)
            });
            let on_segment = d.cast_shapes_nonlinear(&m1, &*body, &m2, &segment, 0.0, window, stop);
            assert_eq!(
                format!("{on_triangle:?}"),
                format!("{on_segment:?}"),
                "case {case}, stop {stop}"
            );
            casts += 1;
            hits += usize::from(matches!(on_triangle, Ok(Some(_))));
        }
        let pos12 = start.inv_mul(&Pose::IDENTITY);
        assert_eq!(
            format!("{:?}", d.distance(&pos12, &*body, &triangle)),
            format!("{:?}", d.distance(&pos12, &*body, &segment)),
            "case {case}"
        );
    }
    println!("{casts} casts against flat triangles, {hits} hits, each equal to the segment's");
    assert!(hits > 20, "{hits}");
}

// ---------------------------------------------------------------------------------------------
// The hostile fuzz
// ---------------------------------------------------------------------------------------------

/// Cases of the hostile batch (a quarter of each class; about 9 s at opt-level 3, the polygons
/// of 10⁵ vertices taking most of it).
const HOSTILE_CASES: u64 = 400;
/// A case (every query of it, and the comparison) running longer than this is a hang.
const CASE_LIMIT: Duration = Duration::from_secs(30);

/// The hostile batch of `reliability::hostile` — user curves breaking each part of the contract
/// (refused naming the method when the checks can see the lie, queried when they cannot),
/// polygons of 10⁵ vertices, poses 1e4 … 1e15 from the origin (the same answers as at the origin,
/// half-spaces included), time scaled by 2^−1000 … 2^1000 (the same answers in scaled time) —
/// every query of each case through `reliability::run_case` (no panic, no NaN, the documented
/// errors, each call within `reliability::CALL_LIMIT`), each case on its own thread under
/// [`CASE_LIMIT`]. Prints its counts (`HOSTILE_SEED`, `HOSTILE_CASES` explore others).
#[test]
fn hostile_fuzz_of_every_query_keeps_its_promises() {
    use reliability::hostile::{compare, hostile, Expect, HOSTILE_CLASSES};
    let env = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<u64>().ok());
    let (seed, n) = (
        env("HOSTILE_SEED").unwrap_or(0x0007_5EED),
        env("HOSTILE_CASES").unwrap_or(HOSTILE_CASES),
    );
    let start = Instant::now();
    let mut failures: Vec<(u64, Vec<String>)> = Vec::new();
    let mut per_class: BTreeMap<&str, (usize, Duration)> = BTreeMap::new();
    let mut refused: BTreeMap<&str, usize> = BTreeMap::new();
    let (mut far, mut scaled, mut slowest) = (0usize, 0usize, (Duration::ZERO, "", 0u64));
    for i in 0..n {
        let (case, expect) = hostile(seed, i);
        let t = Instant::now();
        let (c, e) = (case.clone(), expect.clone());
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                let mut out = reliability::run_case(&c);
                out.violations.extend(compare(&c, &e));
                out
            }));
            let _ = tx.send(run.map_err(|_| ()));
        });
        let out = match rx.recv_timeout(CASE_LIMIT) {
            Ok(Ok(out)) => out,
            Ok(Err(())) => {
                failures.push((i, vec!["PANIC".into()]));
                continue;
            }
            Err(_) => panic!("HANG: case {i} still running after {CASE_LIMIT:?}"),
        };
        let dt = t.elapsed();
        let e = per_class.entry(case.class).or_insert((0, Duration::ZERO));
        e.0 += 1;
        e.1 = e.1.max(dt);
        if out.slowest.0 > slowest.0 {
            slowest = (out.slowest.0, out.slowest.1, i);
        }
        match &expect {
            Expect::Refused(m) => *refused.entry(m).or_default() += 1,
            Expect::SameAs(_) => far += 1,
            Expect::Scaled(..) => scaled += 1,
            Expect::Nothing | Expect::Documented => {}
        }
        if !out.violations.is_empty() {
            failures.push((i, out.violations));
        }
    }
    println!(
        "hostile fuzz: {n} cases (seed {seed:#x}) in {:.1} s; slowest call {:.1} ms ({}, case {})",
        start.elapsed().as_secs_f64(),
        slowest.0.as_secs_f64() * 1e3,
        slowest.1,
        slowest.2
    );
    for class in HOSTILE_CLASSES {
        let (k, w) = per_class.get(class).copied().unwrap_or_default();
        println!(
            "  class {class:<15} {k:>5} cases, worst case {:>8.1} ms",
            w.as_secs_f64() * 1e3
        );
    }
    let refusals: Vec<String> = refused.iter().map(|(k, v)| format!("{k} {v}")).collect();
    println!("  lies refused at wrapping, by method: {}", refusals.join(", "));
    println!("  answers compared: far poses against the origin {far}, scaled time against unscaled {scaled}");
    println!("  cases with a broken promise: {}", failures.len());
    for (i, v) in failures.iter().take(15) {
        let (case, _) = hostile(seed, *i);
        println!("  FAIL {}\n      {}", reliability::describe(&case), v.join("\n      "));
    }
    assert!(
        failures.is_empty(),
        "{} of {n} hostile cases broke a promise",
        failures.len()
    );
}
