//! The cases: each class's shapes, poses, motions and windows, drawn from `(seed, index)`
//! ([`generate`]), wild numbers mixed in for the `wild` class.

use super::*;

/// One input for every query.
#[derive(Clone, Debug)]
pub struct Case {
    pub seed: u64,
    pub index: u64,
    /// The scenario class that produced it.
    pub class: &'static str,
    /// Every number finite, sizes within 1e-6..1e6, axis ratios to 1:1e6: the answers must be
    /// `Ok` and pass the accuracy checks, not only be free of NaN.
    pub supported: bool,
    /// Shape size (the larger bounding radius, roughly).
    pub scale: f64,
    pub s1: ShapeSpec,
    pub s2: ShapeSpec,
    pub pos12: Pose,
    pub m1: NonlinearRigidMotion,
    pub m2: NonlinearRigidMotion,
    pub t0: f64,
    pub t1: f64,
    pub target: f64,
    pub stop: bool,
    pub prediction: f64,
    pub local_vel12: Vector,
    pub ray: Ray,
    pub max_toi: f64,
    pub solid: bool,
    pub point: Vector,
    pub dir: Vector,
    pub density: f64,
    pub rescale: Vector,
    /// For grazing passes: the smallest distance over the window (exact).
    pub min_gap: Option<f64>,
}

fn pose(x: f64, y: f64, a: f64) -> Pose {
    Pose::new(Vector::new(x, y), a)
}

/// A random shape of the crate at scale `s`, axis ratios down to `min_ratio`.
fn own_spec(rng: &mut Rng, s: f64, min_ratio: f64) -> ShapeSpec {
    let ratio = rng.log_uniform(min_ratio, 1.0);
    match rng.int(0, 6) {
        0 | 1 => {
            if rng.chance(0.5) {
                ShapeSpec::Ellipse(s, s * ratio)
            } else {
                ShapeSpec::Ellipse(s * ratio, s)
            }
        }
        2 => {
            let r = if rng.chance(0.3) {
                0.0
            } else {
                s * rng.uniform(0.0, 0.4)
            };
            ShapeSpec::Regular(rng.int(3, 12), s, r)
        }
        3 => {
            // A random convex polygon around the origin: sorted angles on an ellipse.
            let n = rng.int(3, 9);
            let mut angles: Vec<f64> = (0..n).map(|_| rng.angle()).collect();
            angles.sort_by(f64::total_cmp);
            let r2 = rng.log_uniform(ratio.max(1e-3), 1.0);
            let v = angles
                .iter()
                .map(|a| Vector::new(s * a.cos(), s * r2 * a.sin()))
                .collect::<Vec<_>>();
            let r = if rng.chance(0.3) {
                0.0
            } else {
                s * rng.uniform(0.0, 0.3)
            };
            ShapeSpec::Polygon(v, r)
        }
        4 => ShapeSpec::CapsuleEllipse(
            s * rng.uniform(0.1, 0.6),
            s * rng.uniform(0.05, 0.6),
            s * rng.uniform(0.1, 0.8),
        ),
        5 => ShapeSpec::Ball(s * rng.uniform(0.2, 1.0)),
        _ => {
            let inner = match rng.int(0, 2) {
                0 => ShapeSpec::Ellipse(s, s * ratio),
                1 => ShapeSpec::Regular(rng.int(3, 8), s, s * rng.uniform(0.0, 0.3)),
                _ => ShapeSpec::CapsuleEllipse(s * 0.4, s * 0.3, s * 0.5),
            };
            ShapeSpec::Custom(Box::new(inner))
        }
    }
}

/// A random parry shape at scale `s` (also a half-space or a compound).
fn parry_spec(rng: &mut Rng, s: f64) -> ShapeSpec {
    match rng.int(0, 7) {
        0 => ShapeSpec::Ball(s * rng.uniform(0.1, 1.0)),
        1 => ShapeSpec::Cuboid(s * rng.uniform(0.05, 1.0), s * rng.uniform(0.05, 1.0)),
        2 => ShapeSpec::Capsule(s * rng.uniform(0.05, 0.8), s * rng.uniform(0.05, 0.5)),
        3 => {
            let n = rng.int(3, 7);
            let v = (0..n)
                .map(|i| {
                    Vector::new(
                        (2.0 * PI * i as f64 / n as f64).cos(),
                        (2.0 * PI * i as f64 / n as f64).sin(),
                    ) * s
                })
                .collect();
            ShapeSpec::ParryPolygon(v, if rng.chance(0.5) { 0.0 } else { s * 0.1 })
        }
        4 => ShapeSpec::Triangle([
            Vector::new(-s, -0.5 * s),
            Vector::new(s, -0.3 * s),
            Vector::new(0.1 * s, s),
        ]),
        5 => ShapeSpec::Segment(Vector::new(-s, 0.2 * s), Vector::new(s, -0.1 * s)),
        6 => ShapeSpec::HalfSpace(rng.angle()),
        _ => ShapeSpec::Compound(
            Box::new(ShapeSpec::Ellipse(0.6 * s, 0.3 * s)),
            pose(0.5 * s, 0.1 * s, rng.angle()),
        ),
    }
}

fn motion(rng: &mut Rng, start: Pose, s: f64, window: f64) -> NonlinearRigidMotion {
    let speed = s * rng.uniform(0.0, 6.0) / window;
    let spin = if rng.chance(0.3) { 0.0 } else { rng.uniform(-60.0, 60.0) };
    let center = if rng.chance(0.7) {
        Vector::ZERO
    } else {
        Vector::new(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)) * s
    };
    NonlinearRigidMotion::new(start, center, rng.direction() * speed, spin)
}

/// Replaces a number by a [`WILD`] one with probability `p`.
fn wild(rng: &mut Rng, x: f64, p: f64) -> f64 {
    if rng.chance(p) {
        rng.pick(&WILD)
    } else {
        x
    }
}

fn wild_vec(rng: &mut Rng, v: Vector, p: f64) -> Vector {
    Vector::new(wild(rng, v.x, p), wild(rng, v.y, p))
}

fn wild_pose(rng: &mut Rng, q: Pose, p: f64) -> Pose {
    let t = wild_vec(rng, q.translation, p);
    if rng.chance(p) {
        // A rotation that is not a unit complex number, or a non-finite one.
        let re = rng.pick(&WILD);
        Pose::from_parts(t, Rotation::from_cos_sin_unchecked(re, q.rotation.im))
    } else {
        Pose::from_parts(t, q.rotation)
    }
}

fn wild_motion(rng: &mut Rng, m: &NonlinearRigidMotion, p: f64) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(
        wild_pose(rng, m.start, p),
        wild_vec(rng, m.local_center, p),
        wild_vec(rng, m.linvel, p),
        wild(rng, m.angvel, p),
    )
}

fn wild_spec(rng: &mut Rng, spec: &ShapeSpec, p: f64) -> ShapeSpec {
    match spec {
        ShapeSpec::Ellipse(a, b) => ShapeSpec::Ellipse(wild(rng, *a, p), wild(rng, *b, p)),
        ShapeSpec::Regular(n, c, r) => ShapeSpec::Regular(
            if rng.chance(p) { rng.int(0, 2) } else { *n },
            wild(rng, *c, p),
            wild(rng, *r, p),
        ),
        ShapeSpec::Polygon(v, r) => {
            let mut v = v.clone();
            if rng.chance(p) && !v.is_empty() {
                // Break it: a non-finite vertex, a repeated vertex, a reversed order or too few.
                match rng.int(0, 3) {
                    0 => {
                        let i = rng.int(0, v.len() - 1);
                        v[i] = wild_vec(rng, v[i], 1.0);
                    }
                    1 => {
                        let i = rng.int(0, v.len() - 1);
                        let x = v[i];
                        v.insert(i, x);
                    }
                    2 => v.reverse(),
                    _ => v.truncate(2),
                }
            }
            ShapeSpec::Polygon(v, wild(rng, *r, p))
        }
        ShapeSpec::CapsuleEllipse(a, b, c) => {
            ShapeSpec::CapsuleEllipse(wild(rng, *a, p), wild(rng, *b, p), wild(rng, *c, p))
        }
        ShapeSpec::Custom(inner) => ShapeSpec::Custom(Box::new(wild_spec(rng, inner, p))),
        ShapeSpec::Ball(r) => ShapeSpec::Ball(wild(rng, *r, p)),
        ShapeSpec::Cuboid(x, y) => ShapeSpec::Cuboid(wild(rng, *x, p), wild(rng, *y, p)),
        ShapeSpec::Capsule(h, r) => ShapeSpec::Capsule(wild(rng, *h, p), wild(rng, *r, p)),
        ShapeSpec::HalfSpace(a) => ShapeSpec::HalfSpace(wild(rng, *a, p)),
        ShapeSpec::Compound(inner, q) => ShapeSpec::Compound(Box::new(wild_spec(rng, inner, p)), wild_pose(rng, *q, p)),
        other => other.clone(),
    }
}

/// The scenario classes of [`generate`].
pub const CLASSES: [&str; 9] = [
    "random",
    "parry-pair",
    "wild",
    "coincident",
    "concentric",
    "touching-at-t0",
    "grazing",
    "extreme-scale",
    "thin-ellipse",
];

/// A case being drawn: the shapes, poses, motions and window, before the numbers every case gets
/// ([`finish_case`]).
struct Draft {
    class: &'static str,
    supported: bool,
    /// The size.
    s: f64,
    s1: ShapeSpec,
    s2: ShapeSpec,
    pos12: Pose,
    m1: NonlinearRigidMotion,
    m2: NonlinearRigidMotion,
    t0: f64,
    t1: f64,
    target: f64,
    /// Probability that [`finish_case`] makes a number wild (0 but for the `wild` class).
    p: f64,
    min_gap: Option<f64>,
}

/// Case `index` of the batch `seed`: every class in turn.
pub fn generate(seed: u64, index: u64) -> Case {
    let mut rng = Rng::mixed(seed.wrapping_mul(0x2545_F491_4F6C_DD1D) ^ index.wrapping_mul(0x9E37_79B9));
    let class = CLASSES[(index % CLASSES.len() as u64) as usize];
    // Sizes 1e-6..1e6 (extreme-scale also goes beyond).
    let s = rng.log_uniform(1e-6, 1e6);
    let (s1, s2) = draw_shapes(&mut rng, class, s);
    let (window, t0, t1) = draw_window(&mut rng);
    let mut d = draw_motions(&mut rng, class, s, (s1, s2), window, (t0, t1));
    match class {
        "coincident" => make_coincident(&mut rng, &mut d),
        "concentric" => make_concentric(&mut d),
        "touching-at-t0" | "grazing" => make_discs_touch_or_graze(&mut rng, &mut d, window),
        "extreme-scale" => make_extreme_scale(&mut rng, &mut d, window),
        "wild" => make_wild(&mut rng, &mut d),
        _ => {}
    }
    finish_case(&mut rng, seed, index, d)
}

/// The two shapes of `class` at size `s` (ratios down to 1e-6 for thin ellipses; a parry shape on
/// either side for parry pairs).
fn draw_shapes(rng: &mut Rng, class: &str, s: f64) -> (ShapeSpec, ShapeSpec) {
    let mut min_ratio = 1e-3;
    if class == "thin-ellipse" {
        min_ratio = 1e-6;
    }
    let mut s1 = own_spec(rng, s, min_ratio);
    let mut s2 = if class == "parry-pair" {
        parry_spec(rng, s)
    } else {
        let s2 = s * rng.log_uniform(0.3, 3.0);
        own_spec(rng, s2, min_ratio)
    };
    if class == "thin-ellipse" {
        let ratio = rng.log_uniform(1e-6, 1e-3);
        s1 = if rng.chance(0.3) {
            // A thin capsule-ellipse: arcs of radius down to 1e-6 of the segment's half-length.
            ShapeSpec::CapsuleEllipse(s * rng.log_uniform(1e-6, 1e-3), s, s * rng.uniform(0.1, 1.0))
        } else {
            ShapeSpec::Ellipse(s, s * ratio)
        };
        if rng.chance(0.5) {
            s2 = ShapeSpec::Ellipse(s * ratio * rng.uniform(1.0, 10.0), s * rng.uniform(0.5, 2.0));
        }
    }
    if class == "parry-pair" && rng.chance(0.5) {
        std::mem::swap(&mut s1, &mut s2);
    }
    (s1, s2)
}

/// (window length, t0, t1): one time in ten an empty window, one in ten a reversed one.
fn draw_window(rng: &mut Rng) -> (f64, f64, f64) {
    let window = if rng.chance(0.5) {
        1.0
    } else {
        rng.log_uniform(1e-3, 10.0)
    };
    let t0 = if rng.chance(0.5) { 0.0 } else { rng.uniform(-5.0, 5.0) };
    let mut t1 = t0 + window;
    match rng.int(0, 9) {
        0 => t1 = t0,
        1 => t1 = t0 - window,
        _ => {}
    }
    (window, t0, t1)
}

/// The random pose and motions of the shapes (shape 1 starting at the origin) and the target.
fn draw_motions(
    rng: &mut Rng,
    class: &'static str,
    s: f64,
    (s1, s2): (ShapeSpec, ShapeSpec),
    window: f64,
    (t0, t1): (f64, f64),
) -> Draft {
    let reach = 2.0 * s + s * rng.uniform(0.0, 2.0);
    let mut pos12 = pose(0.0, 0.0, rng.angle());
    pos12.translation = rng.direction() * (reach * rng.uniform(0.0, 1.5));
    let mut m1 = motion(rng, Pose::IDENTITY, s, window);
    let m2 = motion(rng, pos12, s, window);
    m1.start = pose(0.0, 0.0, 0.0);
    let target = if rng.chance(0.7) {
        0.0
    } else {
        s * rng.uniform(0.0, 0.05)
    };
    Draft {
        class,
        supported: true,
        s,
        s1,
        s2,
        pos12,
        m1,
        m2,
        t0,
        t1,
        target,
        p: 0.0,
        min_gap: None,
    }
}

/// `coincident`: shape 2 a copy of shape 1 at its pose (or 1e-13 of the size away), on the same
/// motion.
fn make_coincident(rng: &mut Rng, d: &mut Draft) {
    d.s2 = d.s1.clone();
    d.pos12 = if rng.chance(0.5) {
        Pose::IDENTITY
    } else {
        pose(1e-13 * d.s, 0.0, 0.0)
    };
    // Same motion: coincident over the whole window.
    d.m2 = NonlinearRigidMotion::new(d.m1.start * d.pos12, d.m1.local_center, d.m1.linvel, d.m1.angvel);
}

/// `concentric`: the same centre, moving together; the spins differ.
fn make_concentric(d: &mut Draft) {
    d.pos12.translation = Vector::ZERO;
    d.m2.start = d.pos12;
    d.m2.local_center = Vector::ZERO;
    d.m1.local_center = Vector::ZERO;
    // Same velocity: the centres stay together; the spins differ.
    d.m2.linvel = d.m1.linvel;
}

/// `touching-at-t0` and `grazing`: two discs (exact distance) or one of ours against a disc,
/// placed at an exact gap: touching at t0, or sliding past with the smallest gap inside the window.
fn make_discs_touch_or_graze(rng: &mut Rng, d: &mut Draft, window: f64) {
    let (s, t0) = (d.s, d.t0);
    let touching = d.class == "touching-at-t0";
    let r1 = s * rng.uniform(0.3, 1.0);
    let r2 = s * rng.uniform(0.3, 1.0);
    d.s1 = if rng.chance(0.5) {
        ShapeSpec::Ball(r1)
    } else {
        ShapeSpec::Ellipse(r1, r1)
    };
    d.s2 = ShapeSpec::Ball(r2);
    let gap = if touching {
        0.0
    } else {
        rng.pick(&[-1e-9, -1e-12, 0.0, 1e-12, 1e-9, 1e-6]) * s
    };
    let n = rng.direction();
    let tan = Vector::new(-n.y, n.x);
    let dist = r1 + r2 + gap;
    d.t1 = t0 + window;
    if touching {
        // Touching at t0, approaching, separating or sliding.
        d.pos12 = Pose::new(n * (r1 + r2), rng.angle());
        let v = (n * rng.uniform(-3.0, 3.0) + tan * rng.uniform(-3.0, 3.0)) * (s / window);
        let w = rng.uniform(-5.0, 5.0);
        d.m1 = NonlinearRigidMotion::new(Pose::new(Vector::ZERO, rng.angle()), Vector::ZERO, Vector::ZERO, 0.0);
        // `start` is the pose at time 0; the window starts at t0.
        d.m2 = NonlinearRigidMotion::new(Pose::new(n * (r1 + r2) - v * t0, -w * t0), Vector::ZERO, v, w);
        d.min_gap = Some(0.0);
    } else {
        // Sliding past along the tangent: the centre distance is smallest (= dist) at
        // tc, inside the window.
        let tc = t0 + window * rng.uniform(0.2, 0.8);
        let speed = s * rng.uniform(0.5, 4.0) / window;
        let start = n * dist - tan * (speed * (tc - t0));
        d.m1 = NonlinearRigidMotion::new(Pose::new(Vector::ZERO, rng.angle()), Vector::ZERO, Vector::ZERO, 0.0);
        d.m2 = NonlinearRigidMotion::new(
            Pose::new(start - tan * (speed * t0), 0.0),
            Vector::ZERO,
            tan * speed,
            0.0,
        );
        d.pos12 = Pose::new(n * dist, 0.0);
        d.min_gap = Some(gap);
    }
    d.target = 0.0;
}

/// `extreme-scale`: sizes and positions beyond the supported range, in both directions: up to
/// the constructors' limits (1e±50), and beyond them (the constructors refuse, parry's shapes are
/// taken as they are).
fn make_extreme_scale(rng: &mut Rng, d: &mut Draft, window: f64) {
    let s = rng.pick(&[
        1e-12, 1e-9, 1e9, 1e12, 1e-45, 1e45, 1e-50, 1e50, 1e-60, 1e60, 1e-100, 1e100, 1e-200, 1e200, 1e-300, 1e300,
    ]);
    d.s = s;
    d.supported = false;
    let min_ratio = if rng.chance(0.3) { 1e-40 } else { 1e-3 };
    d.s1 = own_spec(rng, s, min_ratio);
    let s2_size = s * rng.uniform(0.5, 2.0);
    d.s2 = if rng.chance(0.3) {
        parry_spec(rng, s2_size)
    } else {
        own_spec(rng, s2_size, min_ratio)
    };
    d.pos12.translation = rng.direction() * (s * rng.uniform(0.0, 4.0));
    d.m1 = motion(rng, Pose::IDENTITY, s, window);
    d.m2 = motion(rng, d.pos12, s, window);
    d.target *= s;
}

/// `wild`: every number of the case a [`WILD`] one with probability 0.12 (the target 0.06).
fn make_wild(rng: &mut Rng, d: &mut Draft) {
    let p = 0.12;
    d.supported = false;
    if rng.chance(0.3) {
        d.s2 = parry_spec(rng, d.s);
    }
    d.s1 = wild_spec(rng, &d.s1, p);
    d.s2 = wild_spec(rng, &d.s2, p);
    d.pos12 = wild_pose(rng, d.pos12, p);
    d.m1 = wild_motion(rng, &d.m1, p);
    d.m2 = wild_motion(rng, &d.m2, p);
    d.t0 = wild(rng, d.t0, p);
    d.t1 = wild(rng, d.t1, p);
    d.target = wild(rng, d.target, p * 0.5);
    d.p = p;
}

/// The case: `d` with the numbers of the other queries (ray, point, direction, margins, density,
/// scaling), each made wild with probability `d.p`.
fn finish_case(rng: &mut Rng, seed: u64, index: u64, d: Draft) -> Case {
    let (s, p) = (d.s, d.p);
    let o = rng_vec(rng, 3.0 * s);
    let o = wild_vec(rng, o, p);
    let dir = rng_vec(rng, 1.0);
    let dir = wild_vec(rng, dir, p);
    let ray = Ray::new(o, dir);
    let stop = rng.chance(0.5);
    let prediction = s * rng.uniform(0.0, 0.5);
    let prediction = wild(rng, prediction, p);
    let v = rng.direction() * (s * rng.uniform(0.0, 5.0));
    let local_vel12 = wild_vec(rng, v, p);
    let max_toi = rng.pick(&[1.0, 10.0, f64::MAX]);
    let max_toi = wild(rng, max_toi, p);
    let solid = rng.chance(0.5);
    let point = rng_vec(rng, 2.0 * s);
    let point = wild_vec(rng, point, p);
    let dir = rng.direction();
    let dir = wild_vec(rng, dir, p);
    let density = rng.log_uniform(1e-3, 1e3);
    let density = wild(rng, density, p);
    let rescale = Vector::new(rng.log_uniform(0.1, 10.0), rng.log_uniform(0.1, 10.0));
    let rescale = wild_vec(rng, rescale, p);
    Case {
        seed,
        index,
        class: d.class,
        supported: d.supported,
        scale: s,
        s1: d.s1,
        s2: d.s2,
        pos12: d.pos12,
        m1: d.m1,
        m2: d.m2,
        t0: d.t0,
        t1: d.t1,
        target: d.target,
        stop,
        prediction,
        local_vel12,
        ray,
        max_toi,
        solid,
        point,
        dir,
        density,
        rescale,
        min_gap: d.min_gap,
    }
}

fn rng_vec(rng: &mut Rng, r: f64) -> Vector {
    Vector::new(rng.uniform(-r, r), rng.uniform(-r, r))
}
