//! The hostile fuzz of issue 32 (`tests/hostile_input.rs`,
//! `hostile_fuzz_of_every_query_keeps_its_promises`), beside the batch of [`super::generate`]
//! (whose classes and digests it leaves alone): four classes, every query of each case through
//! [`super::run_case`] (per-call time limit, no panic, no NaN, the documented errors), and for
//! two of them a comparison that the answers are the ones of an equivalent ordinary case.
//!
//! * `broken-curve`: a user curve ([`Liar`]: an ellipse, a rounded polygon or a
//!   `CapsuleEllipse` with one lie) breaking one part of the [`ConvexCurve`] contract. A lie the
//!   checks of `CustomCurve::try_new` can see must be refused naming its method; one they cannot
//!   (a lie between the sampled directions, a bound a hair too small, a noisy `eval`) is
//!   accepted and every query must still end, without panic or NaN.
//! * `huge-polygon`: a rounded or sharp polygon of 10⁵ vertices against a random shape.
//! * `far-pose`: a random pair with both motions (and the half-space) moved 1e4 … 1e15 from the
//!   origin, the relative geometry exact in f64; every cast must answer as the same pair at the
//!   origin (same status, same time to 1e-9 of the window).
//! * `extreme-motion`: a random pair with its time scaled by 2^k, k in −1000 … 1000 (speeds and
//!   spins times 2^−k ≈ 1e301 … 1e-301, the window times 2^k): the same answer in scaled time
//!   wherever the scaled inputs are finite, a documented status where they are not.

use super::*;
use smooth_ccd2d::{shape_time_of_impact, CurvePoint, SupportJet};

/// The classes of [`hostile`].
pub const HOSTILE_CLASSES: [&str; 4] = ["broken-curve", "huge-polygon", "far-pose", "extreme-motion"];

/// The vertex count of the `huge-polygon` class.
pub const HUGE: usize = 100_000;

// ---------------------------------------------------------------------------------------------
// Curves that lie
// ---------------------------------------------------------------------------------------------

/// One part of the contract broken. The first group the checks of `CustomCurve::try_new` see
/// ([`Lie::refused_by`] names the method); the second they cannot.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Lie {
    /// `bounding_radius` times this factor (0.2, 0.5, 0, −1, NaN).
    Radius(f64),
    /// Normals pointing in.
    Inward,
    /// The boundary traversed clockwise.
    Clockwise,
    /// `eval` NaN on a band of φ.
    NanEval,
    /// Normals 1 % too long.
    LongNormal,
    /// `eval` does not wrap φ.
    Unwrapped,
    /// `d_point` = 0.
    NoDerivative,
    /// Breakpoints out of order.
    Breakpoints,
    /// `support_jet` absent although strictly convex.
    NoSupportJet,
    /// `support_dd_bound` and `support_dd_bound_near` 0.
    ZeroDdBound,
    /// `max_radius_of_curvature` a tenth of the true one.
    SmallMaxRadius,
    /// `min_radius_of_curvature` ten times the true one (plus the size).
    LargeMinRadius,
    /// `phi_range_of_normal` answers (p, p + 1e17).
    HugeRange,
    /// `support_point` answers the origin.
    SupportPointOrigin,
    /// A polygon that says it is strictly convex (with its support points as `support_jet`).
    FalselyStrict,
    // --- not seen by the checks ---
    /// `eval` computed in f32.
    F32Eval,
    /// `eval`'s point with a relative noise of 1e-13.
    Noise,
    /// `bounding_radius` 5e-7 too small (within the checks' tolerance).
    TightRadius,
    /// `phi_range_of_normal` answers (p, p + 1e17) for normals between the checks' directions.
    RangeBetweenSamples,
    /// `support_dd_bound_near` a tenth of the truth over arcs wider than the checks try.
    DdNearLowWide,
    /// `support_jet` 10 % of the size off for normals between the checks' directions.
    JetBetweenSamples,
    /// `max_radius_of_curvature` 0.05 % below the truth (within the checks' tolerance).
    MaxRadiusHair,
}

impl Lie {
    /// Every lie.
    pub const ALL: [Lie; 26] = [
        Lie::Radius(0.2),
        Lie::Radius(0.5),
        Lie::Radius(0.0),
        Lie::Radius(-1.0),
        Lie::Radius(f64::NAN),
        Lie::Inward,
        Lie::Clockwise,
        Lie::NanEval,
        Lie::LongNormal,
        Lie::Unwrapped,
        Lie::NoDerivative,
        Lie::Breakpoints,
        Lie::NoSupportJet,
        Lie::ZeroDdBound,
        Lie::SmallMaxRadius,
        Lie::LargeMinRadius,
        Lie::HugeRange,
        Lie::SupportPointOrigin,
        Lie::FalselyStrict,
        Lie::F32Eval,
        Lie::Noise,
        Lie::TightRadius,
        Lie::RangeBetweenSamples,
        Lie::DdNearLowWide,
        Lie::JetBetweenSamples,
        Lie::MaxRadiusHair,
    ];

    /// The method whose name the refusal must carry; `None` for a lie the checks cannot see.
    /// (`Radius(0)`, `Radius(−1)` and `Radius(NaN)` are `NotPositive` / `NotFinite` of
    /// `bounding_radius`.)
    pub fn refused_by(self) -> Option<&'static str> {
        Some(match self {
            Lie::Radius(_) => "bounding_radius",
            Lie::Inward | Lie::Clockwise | Lie::NanEval | Lie::LongNormal | Lie::Unwrapped | Lie::NoDerivative => {
                "eval"
            }
            Lie::Breakpoints => "breakpoints",
            Lie::NoSupportJet => "support_jet",
            Lie::ZeroDdBound => "support_dd_bound",
            Lie::SmallMaxRadius => "max_radius_of_curvature",
            Lie::LargeMinRadius => "min_radius_of_curvature",
            Lie::HugeRange => "phi_range_of_normal",
            Lie::SupportPointOrigin => "support_point",
            Lie::FalselyStrict => "is_strictly_convex",
            _ => return None,
        })
    }

    /// Whether the lie is about the strictly convex side's methods (told only by an ellipse).
    fn needs_strict(self) -> bool {
        matches!(
            self,
            Lie::NoSupportJet | Lie::ZeroDdBound | Lie::SmallMaxRadius | Lie::DdNearLowWide | Lie::JetBetweenSamples
        ) || self == Lie::MaxRadiusHair
    }
}

/// The base of a [`Liar`].
#[derive(Clone, Debug)]
pub enum Base {
    Ellipse(Ellipse),
    Polygon(RoundedPolygon),
    Capsule(CapsuleEllipse),
}

/// A curve of the crate telling one [`Lie`].
#[derive(Debug)]
pub struct Liar {
    pub base: Base,
    pub lie: Lie,
}

/// Whether the direction `n` lies between the checks' sampled directions: a band of 0.4 of
/// their spacing (2π/256) in the middle of one gap of the grid (angles 1.0 … 1.025).
fn between_samples(n: Vector) -> bool {
    let a = n.y.atan2(n.x);
    let step = std::f64::consts::TAU / 256.0;
    let k = ((a + PI) / step).floor();
    let f = (a + PI) / step - k;
    (1.0..1.03).contains(&a) && (0.3..0.7).contains(&f)
}

fn round32(v: Vector) -> Vector {
    Vector::new(v.x as f32 as f64, v.y as f32 as f64)
}

impl Liar {
    fn base(&self) -> &dyn ConvexCurve {
        match &self.base {
            Base::Ellipse(e) => e,
            Base::Polygon(p) => p,
            Base::Capsule(c) => c,
        }
    }
}

impl ConvexCurve for Liar {
    fn eval(&self, phi: f64) -> CurvePoint {
        let mut cp = self.base().eval(phi);
        match self.lie {
            Lie::Inward => {
                cp.normal = -cp.normal;
                cp.d_normal = -cp.d_normal;
                cp.dd_normal = -cp.dd_normal;
            }
            Lie::Clockwise => {
                cp = self.base().eval(-phi);
                cp.d_point = -cp.d_point;
                cp.d_normal = -cp.d_normal;
            }
            Lie::NanEval if (0.5..0.7).contains(&phi) => cp.point = Vector::new(f64::NAN, 0.0),
            Lie::LongNormal => cp.normal *= 1.01,
            Lie::Unwrapped if !(-PI..PI).contains(&phi) => {
                cp = self.base().eval(smooth_ccd2d::method::wrap_phi(phi) + 0.5)
            }
            Lie::NoDerivative => cp.d_point = Vector::ZERO,
            Lie::F32Eval => {
                cp.point = round32(cp.point);
                cp.d_point = round32(cp.d_point);
                cp.normal = round32(cp.normal);
                cp.d_normal = round32(cp.d_normal);
            }
            Lie::Noise => {
                let z = (phi.to_bits().wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 40) as f64 / (1u64 << 24) as f64;
                cp.point *= 1.0 + 1e-13 * (2.0 * z - 1.0);
            }
            _ => {}
        }
        cp
    }
    fn breakpoints(&self) -> &[f64] {
        match self.lie {
            Lie::Breakpoints => &[0.5, -0.5],
            _ => self.base().breakpoints(),
        }
    }
    fn bounding_radius(&self) -> f64 {
        let r = self.base().bounding_radius();
        match self.lie {
            Lie::Radius(f) => f * r,
            Lie::TightRadius => r * (1.0 - 5e-7),
            _ => r,
        }
    }
    fn phi_range_of_normal(&self, n: Vector) -> (f64, f64) {
        let (lo, hi) = self.base().phi_range_of_normal(n);
        match self.lie {
            Lie::HugeRange => (lo, lo + 1e17),
            Lie::RangeBetweenSamples if between_samples(n) => (lo, lo + 1e17),
            _ => (lo, hi),
        }
    }
    fn support_jet(&self, m: Vector) -> Option<SupportJet> {
        match (self.lie, &self.base) {
            (Lie::NoSupportJet, _) => None,
            (Lie::FalselyStrict, _) => Some(SupportJet {
                point: self.base().support_point(m),
                radius_of_curvature: 0.0,
                d_radius_of_curvature: 0.0,
            }),
            (Lie::JetBetweenSamples, _) if between_samples(m) => self.base().support_jet(m).map(|j| SupportJet {
                point: j.point + m * (0.1 * self.base().bounding_radius()),
                ..j
            }),
            _ => self.base().support_jet(m),
        }
    }
    fn is_strictly_convex(&self) -> bool {
        self.lie == Lie::FalselyStrict || self.base().is_strictly_convex()
    }
    fn max_radius_of_curvature(&self) -> f64 {
        let r = self.base().max_radius_of_curvature();
        match self.lie {
            Lie::FalselyStrict => self.base().bounding_radius(),
            Lie::SmallMaxRadius => 0.1 * r,
            Lie::MaxRadiusHair => r * (1.0 - 5e-4),
            _ => r,
        }
    }
    fn min_radius_of_curvature(&self) -> f64 {
        match self.lie {
            Lie::LargeMinRadius => {
                10.0 * self.base().max_radius_of_curvature().min(1e300) + self.base().bounding_radius()
            }
            _ => self.base().min_radius_of_curvature(),
        }
    }
    fn support_dd_bound(&self) -> f64 {
        match self.lie {
            Lie::ZeroDdBound => 0.0,
            Lie::FalselyStrict => 2.0 * self.base().bounding_radius(),
            _ => self.base().support_dd_bound(),
        }
    }
    fn support_dd_bound_near(&self, m: Vector, half_angle: f64) -> f64 {
        match self.lie {
            Lie::ZeroDdBound => 0.0,
            Lie::FalselyStrict => 2.0 * self.base().bounding_radius(),
            Lie::DdNearLowWide if half_angle > 0.05 => 0.1 * self.base().support_dd_bound_near(m, half_angle),
            _ => self.base().support_dd_bound_near(m, half_angle),
        }
    }
    fn support_point(&self, n: Vector) -> Vector {
        match self.lie {
            Lie::SupportPointOrigin => Vector::ZERO,
            _ => self.base().support_point(n),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Cases
// ---------------------------------------------------------------------------------------------

/// What the hostile fuzz checks beyond [`super::run_case`] for one case.
#[derive(Clone, Debug)]
pub enum Expect {
    /// Nothing more.
    Nothing,
    /// Shape 1 is a liar that must be refused naming this method.
    Refused(&'static str),
    /// The casts must answer as those of this case (far poses: the same case at the origin).
    SameAs(Box<Case>),
    /// The casts must answer as those of this case with times divided by `scale`.
    Scaled(Box<Case>, f64),
    /// No comparison: a documented status is enough (speeds whose squares overflow).
    Documented,
}

/// Case `index` of the hostile batch `seed`: the classes in turn.
pub fn hostile(seed: u64, index: u64) -> (Case, Expect) {
    let mut rng = Rng::mixed(seed.wrapping_mul(0x2545_F491_4F6C_DD1D) ^ index.wrapping_mul(0x7F4A_7C15));
    let class = HOSTILE_CLASSES[(index % HOSTILE_CLASSES.len() as u64) as usize];
    // An ordinary random case to start from (the `random` class: supported sizes and motions).
    let mut base = generate(seed ^ 0x32, index.wrapping_mul(CLASSES.len() as u64));
    (base.class, base.seed, base.index) = (class, seed, index);
    match class {
        "broken-curve" => broken_curve(&mut rng, base),
        "huge-polygon" => huge_polygon(&mut rng, base),
        "far-pose" => far_pose(&mut rng, base),
        _ => extreme_motion(&mut rng, base),
    }
}

fn broken_curve(rng: &mut Rng, mut c: Case) -> (Case, Expect) {
    let lie = rng.pick(&Lie::ALL);
    let s = c.scale;
    let base = if lie.needs_strict() || rng.chance(0.4) {
        Base::Ellipse(Ellipse::new(s, s * rng.log_uniform(1e-2, 1.0)))
    } else if rng.chance(0.5) {
        Base::Polygon(RoundedPolygon::regular(rng.int(3, 9), s, s * rng.uniform(0.0, 0.3)))
    } else {
        Base::Capsule(CapsuleEllipse::new(0.4 * s, 0.3 * s, 0.5 * s))
    };
    // A circle says it has h'' ≡ 0: its 0 is the truth. So does a polygon told strict.
    let lie = match (&base, lie) {
        (Base::Ellipse(e), Lie::ZeroDdBound) if e.half_x() == e.half_y() => Lie::SmallMaxRadius,
        (Base::Ellipse(_), Lie::FalselyStrict) => Lie::NoDerivative,
        _ => lie,
    };
    c.s1 = ShapeSpec::Liar(lie, base);
    c.supported = false;
    let expect = match lie.refused_by() {
        Some(m) => Expect::Refused(m),
        None => Expect::Nothing,
    };
    (c, expect)
}

fn huge_polygon(rng: &mut Rng, mut c: Case) -> (Case, Expect) {
    let s = c.scale;
    let r = if rng.chance(0.3) {
        0.0
    } else {
        s * rng.uniform(0.0, 0.2)
    };
    c.s1 = ShapeSpec::Regular(HUGE, s, r);
    (c, Expect::Nothing)
}

/// The far-pose offsets.
const OFFSETS: [f64; 6] = [1e4, 1e6, 1e8, 1e10, 1e12, 1e15];

fn far_pose(rng: &mut Rng, mut c: Case) -> (Case, Expect) {
    let o = rng.pick(&OFFSETS);
    if rng.chance(0.3) {
        c.s2 = ShapeSpec::HalfSpace(rng.angle());
    }
    // Positions on the grid of the offset's resolution, local centres 0: the far starts are
    // then exact, and so are their differences.
    let q = {
        // A power of two, at least an ulp of every far coordinate (|x + shift| < 4·o).
        let w = 4.0 * o;
        w.next_up() - w
    };
    let snap = |v: Vector| Vector::new((v.x / q).round() * q, (v.y / q).round() * q);
    let mut near = c.clone();
    // Sizes 0.5 … 4 (the offset's resolution, 0.44 at 1e15, stays below them).
    near.scale = rng.uniform(0.5, 4.0);
    let k = near.scale / c.scale;
    near.s1 = rescaled(&c.s1, k);
    near.s2 = rescaled(&c.s2, k);
    for m in [&mut near.m1, &mut near.m2] {
        m.start.translation = snap(m.start.translation * k);
        m.linvel *= k;
        m.local_center = Vector::ZERO;
    }
    near.pos12 = near.m1.start.inv_mul(&near.m2.start);
    near.supported = false;
    let mut far = near.clone();
    let shift = Vector::new(o, -0.7 * o);
    for m in [&mut far.m1, &mut far.m2] {
        m.start.translation += shift;
    }
    (far, Expect::SameAs(Box::new(near)))
}

fn extreme_motion(rng: &mut Rng, mut c: Case) -> (Case, Expect) {
    if rng.chance(0.2) {
        c.s2 = ShapeSpec::HalfSpace(rng.angle());
    }
    // Powers of two: the scaled inputs are the ordinary ones exactly (and so, the algorithms
    // scaling with time, are the answers).
    let k = rng.int(0, 40) as i32 * 50 - 1000;
    let scale = 2f64.powi(k);
    let mut fast = c.clone();
    fast.t0 *= scale;
    fast.t1 *= scale;
    for m in [&mut fast.m1, &mut fast.m2] {
        // start is the pose at time 0: unchanged.
        m.linvel /= scale;
        m.angvel /= scale;
    }
    fast.supported = false;
    let finite = fast.t0.is_finite() && fast.t1.is_finite() && fast.m1.linvel.is_finite() && fast.m2.linvel.is_finite();
    // Every scale whose inputs are finite: the queries rescale time themselves where the
    // rates leave 2^±64 (`query::time_scale`).
    let expect = if finite {
        Expect::Scaled(Box::new(c), scale)
    } else {
        Expect::Documented
    };
    (fast, expect)
}

/// The spec of a shape of the crate's (or parry's) scaled by `k`.
fn rescaled(spec: &ShapeSpec, k: f64) -> ShapeSpec {
    match spec {
        ShapeSpec::Ellipse(a, b) => ShapeSpec::Ellipse(a * k, b * k),
        ShapeSpec::Regular(n, c, r) => ShapeSpec::Regular(*n, c * k, r * k),
        ShapeSpec::Polygon(v, r) => ShapeSpec::Polygon(v.iter().map(|p| *p * k).collect(), r * k),
        ShapeSpec::CapsuleEllipse(a, b, c) => ShapeSpec::CapsuleEllipse(a * k, b * k, c * k),
        ShapeSpec::Custom(inner) => ShapeSpec::Custom(Box::new(rescaled(inner, k))),
        ShapeSpec::Ball(r) => ShapeSpec::Ball(r * k),
        other => other.clone(),
    }
}

// ---------------------------------------------------------------------------------------------
// The comparisons
// ---------------------------------------------------------------------------------------------

/// The casts of a case: (name, status, time, rate of distance) of the time of impact (curves),
/// the half-space cast, `shape_time_of_impact` and the dispatcher's nonlinear cast (no rate:
/// 0), for both orders.
fn casts(case: &Case) -> Vec<(String, String, f64, f64)> {
    let mut out = Vec::new();
    let (Ok(b1), Ok(b2)) = (build(&case.s1), build(&case.s2)) else {
        return out;
    };
    let opts = ToiOptions::default().with_stop_at_penetration(case.stop);
    let mut push = |name: &str, r: Result<TimeOfImpact, QueryError>| match r {
        Ok(r) => out.push((name.to_string(), format!("{:?}", r.status), r.time, r.distance_rate)),
        Err(e) => out.push((name.to_string(), format!("{e:?}"), f64::NAN, 0.0)),
    };
    if let (Some(c1), Some(c2)) = (&b1.curve, &b2.curve) {
        push(
            "time_of_impact",
            time_of_impact(&**c1, &case.m1, &**c2, &case.m2, case.t0, case.t1, &opts),
        );
    }
    if let (Some(c), Some(hs)) = (&b1.curve, &b2.halfspace) {
        push(
            "time_of_impact_halfspace",
            time_of_impact_halfspace(&**c, &case.m1, hs, &case.m2, case.t0, case.t1, &opts),
        );
    }
    push(
        "shape_time_of_impact",
        shape_time_of_impact(&*b1.shape, &case.m1, &*b2.shape, &case.m2, case.t0, case.t1, &opts),
    );
    let d = SmoothDispatcher::default();
    for (name, g1, m1, g2, m2) in [
        ("cast_shapes_nonlinear 12", &b1.shape, &case.m1, &b2.shape, &case.m2),
        ("cast_shapes_nonlinear 21", &b2.shape, &case.m2, &b1.shape, &case.m1),
    ] {
        match d.cast_shapes_nonlinear(m1, &**g1, m2, &**g2, case.t0, case.t1, case.stop) {
            Ok(Some(h)) => out.push((name.into(), format!("{:?}", h.status), h.time_of_impact, 0.0)),
            Ok(None) => out.push((name.into(), "None".into(), f64::NAN, 0.0)),
            Err(_) => out.push((name.into(), "Unsupported".into(), f64::NAN, 0.0)),
        }
    }
    out
}

/// The violations of `case` against what `expect` asks (beyond `run_case`'s).
pub fn compare(case: &Case, expect: &Expect) -> Vec<String> {
    let mut bad = Vec::new();
    match expect {
        Expect::Nothing | Expect::Documented => {}
        Expect::Refused(method) => match build(&case.s1) {
            Ok(_) => bad.push(format!("a curve lying ({:?}) was accepted", case.s1)),
            Err(e) if !e.contains(method) => bad.push(format!("refused for another reason than `{method}`: {e}")),
            Err(_) => {}
        },
        Expect::SameAs(reference) | Expect::Scaled(reference, _) => {
            let scale = if let Expect::Scaled(_, k) = expect { *k } else { 1.0 };
            let (got, want) = (casts(case), casts(reference));
            let window = (reference.t1 - reference.t0).abs().max(f64::MIN_POSITIVE);
            for ((name, s, t, _), (_, s_ref, t_ref, rate_ref)) in got.iter().zip(&want) {
                // A cap reached is documented; a contact found at the grazing tolerance by
                // one and not the other is the tolerance's (both within it).
                let capped = s.contains("OutOfIterations") || s_ref.contains("OutOfIterations");
                // An answer whose rate of distance on the fast time scale is beyond f64's range
                // (speeds near 1e308) cannot be given: `Degenerate` is its documented answer.
                let unrepresentable = s == "Degenerate" && !(rate_ref / scale).is_finite();
                if capped || unrepresentable {
                    continue;
                }
                // A miss's time is where the query stopped looking: only its status counts.
                let timed = !(s.contains("NoHit") || s == "None");
                let dt = (t / scale - t_ref).abs() / window;
                let off =
                    timed && ((t.is_finite() && t_ref.is_finite() && dt > 1e-9) || t.is_finite() != t_ref.is_finite());
                if s != s_ref || off {
                    bad.push(format!(
                        "{name}: {s} at {t:e} (÷ {scale:e} = {:e}) against {s_ref} at {t_ref:e}",
                        t / scale
                    ));
                }
            }
        }
    }
    bad
}
