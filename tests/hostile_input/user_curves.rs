//! A user's curve that breaks its contract, one part at a time: the queries still end and
//! answer, and `CustomCurve::try_new` refuses what it can check, naming the method.

use super::*;

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
