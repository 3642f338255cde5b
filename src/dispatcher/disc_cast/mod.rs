//! rapier's casts of a *disc* in closed form: "a disc is a disc" (issue 29, item 3).
//!
//! # Why a closed form
//!
//! A disc of radius ρ (an [`Ellipse`] with equal semi-axes) that turns about its own centre
//! covers, at every time, exactly the points its centre's translation puts it on: its rotation
//! moves none of them. Both of the paths a cast may follow ([`crate::MotionPath::ConstantSpin`],
//! parry's motion, and [`crate::MotionPath::Nlerp`], rapier's clamp) carry the rotation centre
//! along a straight line at a constant speed, so when the disc's centre *is* its rotation centre
//! (the motion's `local_center` at the shape's origin, as a disc collider on its body's centre
//! of mass has it) — or the disc does not turn at all — the centre moves on the segment
//!
//!   c(t) = c₀ + w·(t − t₀)
//!
//! in the frame of a target that does not turn (w the disc's velocity relative to the target's,
//! in that frame). Against a target K dilated by its own radius r_K (parry's `Ball`, `Segment`,
//! `Capsule`, `Cuboid`, `Triangle`, `ConvexPolygon`, their round versions, this crate's
//! `RoundedPolygon`, a disc), with K's core a convex polygon (a point for a ball, a segment for a
//! capsule), the signed distance of the pair is
//!
//!   D(t) = sd_K(c(t)) − ρ − r_K,
//!
//! sd_K the signed distance from a point to the core (the Euclidean distance outside; inside,
//! minus the distance to the boundary, max over edges of nᵢ·x − nᵢ·vᵢ). Every question a cast
//! asks of such a pair is the first time D comes down to a level L, i.e. the first time the
//! segment c(t) enters {sd_K ≤ R} with R = ρ + r_K + L, in closed form ([`first_entry`]):
//!
//! * R ≥ 0: {sd_K ≤ R} is K's core dilated by R, whose boundary is made of the edges moved out
//!   by R along their normals and arcs of the circles of radius R about the vertices. Each of
//!   those pieces lies in the set, so from a start outside the set the first piece the segment
//!   meets is where it enters: the first root of nᵢ·c(t) = nᵢ·vᵢ + R that falls on the edge's
//!   extent, and of |c(t) − vᵢ|² = R², the smaller root of a quadratic taken in its stable form
//!   t − t₀ = c/(−b + √(b² − ac)) (no cancellation: b < 0 when the centre comes closer).
//! * R < 0 (a level deeper than the disc): {sd_K ≤ R} is the intersection of the half-planes
//!   nᵢ·x ≤ nᵢ·vᵢ + R (the inner parallel set of a convex polygon), entered where the latest
//!   entering line is crossed, if before the earliest leaving one (Cyrus–Beck clipping); empty
//!   for a point or a segment.
//!
//! # The answers
//!
//! Those of the general path, rule by rule ([`crate::CastPolicy`], module docs of
//! `rapier_rule`), under the two rapier policies, for `cast_shapes_nonlinear` with the disc as
//! shape 1:
//!
//! * **apart at the start** (D(t₀) − δ above the tolerance): the first time D comes down to the
//!   target distance δ, with the witnesses of that time — the disc's point facing the target
//!   (in its frame, at the rotation the path has then), the target's nearest point, the
//!   normals along the line between them; no hit if D never gets there. The general path
//!   accepts a contact within the tolerance τ above δ (`ToiOptions::distance_tolerance`): a
//!   path that grazes the target between δ and δ + τ hits at its entry into the level δ + τ;
//! * **in contact at the start** (`stop_at_penetration = false`): rule 3 — the earlier of the
//!   core's contact (the disc of `CORE`·r about the rotation centre reaching the target, R =
//!   `CORE`·r + r_K, or a quarter of its radius deeper than it starts when it starts touching,
//!   never past half of it) and the translation deepening the contact to min(−A, d₀ − A) (R = ρ + r_K +
//!   level), at least `START_NUDGE` of the window after the start, with the exact contact of
//!   that time for its witnesses, as the general path reports them — in closed form too: the
//!   target's nearest point to the disc's centre and the normal there. The start's distance
//!   from the disc's centre to the core is read once and serves the translation's level
//!   search, and the core's when the core's centre is the disc's (the motion's `local_center`
//!   at the shape's origin).
//!
//! Everything else — the disc as the target, a disc not turning about its centre, a target that
//! turns or that is not a polygon or a disc, a contact at the start with
//! `stop_at_penetration = true`, a start within the tolerance of δ, non-finite input — is left
//! to the general path (`None`), which answers it as it always has: the statuses of degenerate
//! input are its own.
//!
//! Under [`CastPolicy::RapierConstantSpin`] (the moving-pairs pass) rule 3 measures the
//! deepening on the whole motions where both bodies move, rotation included; a disc turning
//! about its centre deepens a contact exactly as its translation does, so the same closed form
//! answers it.

use super::cast::{is_window, toi_to_parry, NonlinearCast};
use super::rapier_rule::{core_level, in_contact};
use super::support_shape::{support_shape, SupportScratch};
use crate::numerics::math::{cross, sin_cos, Real, Vector};
use crate::numerics::motion::motion_is_finite;
use crate::query::contact::SupportShape;
use crate::query::path::OnPath;
use crate::query::toi::{TimeOfImpact, ToiCost, ToiOptions, ToiStatus};
use crate::{CastPolicy, Ellipse};
use parry2d_f64::math::Rotation;
use parry2d_f64::query::{NonlinearRigidMotion, ShapeCastHit, Unsupported};
use parry2d_f64::shape::ShapeType;

/// What [`Core::distance`] sees from a point: the signed distance to the core, the core's
/// nearest point and the outward unit normal there.
type Seen = (Real, Vector, Vector);

/// A target's core: a convex polygon given by its vertices (counter-clockwise) and the outward
/// unit normals of its edges vᵢ → vᵢ₊₁, a segment (two vertices, two opposite normals) or a
/// point (one vertex, no edge), dilated by `radius`.
#[derive(Copy, Clone)]
struct Core<'a> {
    vertices: &'a [Vector],
    normals: &'a [Vector],
    radius: Real,
}

/// The one vertex of a disc's core: its centre.
const CENTRE: [Vector; 1] = [Vector::ZERO];

impl<'a> Core<'a> {
    /// The core of `target` as the contact query reads it (`support_shape`, its vertices written
    /// to `scratch` where it has no stored ones): a polygon or a segment with its normals, a
    /// disc (parry's `Ball`, an `Ellipse` with equal semi-axes) as its centre; `None` for any
    /// other shape.
    fn of(target: &'a dyn parry2d_f64::shape::Shape, scratch: &'a mut SupportScratch) -> Option<Self> {
        match support_shape(target, scratch)? {
            SupportShape::Polygon {
                vertices,
                normals,
                radius,
            } if normals.len() == vertices.len() => Some(Core {
                vertices,
                normals,
                radius,
            }),
            SupportShape::Disc(radius) => Some(Core {
                vertices: &CENTRE,
                normals: &[],
                radius,
            }),
            SupportShape::Ellipse(a, b) if a == b => Some(Core {
                vertices: &CENTRE,
                normals: &[],
                radius: a,
            }),
            _ => None,
        }
    }
}

/// Which feature of a core is nearest a point ([`Core::nearest`]): an edge (its index, the
/// point's foot inside it or the point inside the polygon) or a vertex.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Nearest {
    Edge(usize),
    Vertex(usize),
}

impl Core<'_> {
    /// The signed distance from `p` to the core (not its dilation), the core's point nearest to
    /// `p` and the unit normal from it towards `p` (outward: inside, the normal of the nearest
    /// edge). A point at a point core takes the x axis.
    fn distance(&self, p: Vector) -> Seen {
        self.nearest(p).0
    }

    /// [`Core::distance`] and the feature the nearest point lies on.
    fn nearest(&self, p: Vector) -> (Seen, Nearest) {
        let n = self.vertices.len();
        if n == 1 {
            let d = (p - self.vertices[0]).length();
            let normal = if d > 0.0 { (p - self.vertices[0]) / d } else { Vector::X };
            return ((d, self.vertices[0], normal), Nearest::Vertex(0));
        }
        if n >= 3 {
            // Inside a proper polygon the nearest boundary is the nearest edge line.
            let (mut best, mut at) = (Real::NEG_INFINITY, 0);
            for (i, (v, normal)) in self.vertices.iter().zip(self.normals).enumerate() {
                let s = normal.dot(p - *v);
                if s > best {
                    (best, at) = (s, i);
                }
            }
            if best <= 0.0 {
                let normal = self.normals[at];
                return ((best, p - normal * best, normal), Nearest::Edge(at));
            }
        }
        // Outside (or a segment core): the nearest point of the edges.
        let mut nearest = (Real::INFINITY, self.vertices[0], Nearest::Vertex(0));
        let edges = if n == 2 { 1 } else { n };
        // Each edge vᵢ → vᵢ₊₁ (no `%` in the loop: an integer division an edge).
        let next = self.vertices.iter().cycle().skip(1);
        for (i, (&a, &b)) in self.vertices.iter().zip(next).take(edges).enumerate() {
            // The foot of p on the edge, a + e·clamp((p − a)·e / |e|², 0, 1); the division only
            // where the foot falls within the edge (the same point at either end).
            let (e, along) = (b - a, (p - a).dot(b - a));
            let (q, at) = if along <= 0.0 {
                (a, Nearest::Vertex(i))
            } else if along >= e.length_squared() {
                (a + e, Nearest::Vertex(if i + 1 == n { 0 } else { i + 1 }))
            } else {
                (a + e * (along / e.length_squared()), Nearest::Edge(i))
            };
            let d2 = (p - q).length_squared();
            if d2 < nearest.0 {
                nearest = (d2, q, at);
            }
        }
        let d = nearest.0.sqrt();
        let normal = if d > 0.0 { (p - nearest.1) / d } else { Vector::X };
        ((d, nearest.1, normal), nearest.2)
    }
}

/// The signed distance from `p` to the convex polygon (or segment) with these vertices
/// (counter-clockwise) and outward edge normals, not dilated ([`Core::distance`]).
pub(crate) fn polygon_point_distance(vertices: &[Vector], normals: &[Vector], p: Vector) -> Real {
    Core {
        vertices,
        normals,
        radius: 0.0,
    }
    .distance(p)
    .0
}

/// Below this fraction of the distance from a vertex, a vertex circle's entry in
/// [`first_entry`] takes the path's distance to the vertex from a cross product rather than
/// from a difference of squares (see there).
const TANGENT_FORM: Real = 1e-3;

/// The first time in `[0, span]` after the start at which the point p₀ + w·s enters
/// {sd_K ≤ `grow`} (module docs), from a start outside it; `None` when it does not.
fn first_entry(core: &Core, p0: Vector, w: Vector, span: Real, grow: Real) -> Option<Real> {
    let n = core.vertices.len();
    if grow < 0.0 {
        return (n >= 3).then(|| clipped_entry(core, p0, w, span, grow)).flatten();
    }
    let mut first = Real::INFINITY;
    // The edges moved out by `grow`: crossed inwards within their extent.
    if n >= 2 {
        for i in 0..n {
            let (a, normal) = (core.vertices[i], core.normals[i]);
            let above = normal.dot(p0 - a) - grow;
            let rate = normal.dot(w);
            if above < 0.0 || rate >= 0.0 {
                continue;
            }
            let s = above / -rate;
            if s < first {
                let e = core.vertices[if i + 1 == n { 0 } else { i + 1 }] - a;
                let along = (p0 + w * s - a).dot(e);
                if (0.0..=e.length_squared()).contains(&along) {
                    first = s;
                }
            }
        }
    }
    // The circles of radius `grow` about the vertices.
    let a = w.length_squared();
    for v in core.vertices {
        let from = p0 - *v;
        let b = from.dot(w);
        if b >= 0.0 {
            continue;
        }
        let c = (from.length() - grow) * (from.length() + grow);
        // b² − ac = a·(grow² − d⊥²), d⊥ the distance from the vertex to the path's line. Its
        // difference of squares carries ε·b² of rounding: ε·|from|²/(2·grow) on d⊥, enough to
        // make a path that passes a sharp corner (grow 0, a Minkowski difference's vertex)
        // 1e-8·|from| away touch it. A circle smaller than `TANGENT_FORM` of the distance takes
        // d⊥ from the cross product instead (ε·|from| of rounding); larger ones keep the
        // difference of squares, within 5e-14·|from| there.
        let disc = if grow >= TANGENT_FORM * from.length() {
            b * b - a * c
        } else {
            let d_perp = cross(from, w).abs() / a.sqrt();
            a * ((grow - d_perp) * (grow + d_perp))
        };
        if disc < 0.0 {
            continue;
        }
        let s = (c / (-b + disc.sqrt())).max(0.0);
        first = first.min(s);
    }
    (first <= span).then_some(first)
}

/// [`first_entry`] for a level inside a proper polygon core (`grow` < 0): Cyrus–Beck clipping
/// of the segment by the half-planes nᵢ·x ≤ nᵢ·vᵢ + `grow`.
fn clipped_entry(core: &Core, p0: Vector, w: Vector, span: Real, grow: Real) -> Option<Real> {
    let (mut enter, mut leave) = (0.0, span);
    for (v, normal) in core.vertices.iter().zip(core.normals) {
        let above = normal.dot(p0 - *v) - grow;
        let rate = normal.dot(w);
        if rate < 0.0 {
            enter = Real::max(enter, above / -rate);
        } else if rate > 0.0 {
            leave = Real::min(leave, -above / rate);
        } else if above > 0.0 {
            return None;
        }
    }
    (enter <= leave).then_some(enter)
}

/// The time `s` after the start of `c`'s window, within the window: t₀ + s rounds past t₁
/// where |t₀| is far above |t₁| (fuzz seed 2004, case 122492: a window from −1.8e308 s to
/// −1.38 s).
pub(crate) fn at_offset(c: &NonlinearCast, s: Real) -> Real {
    (c.t0 + s).min(c.t1)
}

/// The disc of a cast's shape 1 and its rotation centre, if the cast is one this module answers
/// (module docs): ρ, and the motion's `local_center`.
fn moving_disc(c: &NonlinearCast) -> Option<Real> {
    if c.g1.shape_type() != ShapeType::Custom {
        return None;
    }
    let e = c.g1.as_shape::<Ellipse>()?;
    let turns_about_centre = c.m1.angvel == 0.0 || c.m1.local_center == Vector::ZERO;
    (e.half_x() == e.half_y() && turns_about_centre).then_some(e.half_x())
}

/// rapier's cast of `c` (a disc as shape 1, module docs) in closed form, under rapier's rules
/// (`start_contact`: solid bodies, `stop_at_penetration = false`); `None` where the general path
/// answers.
pub(crate) fn disc_cast(
    c: &NonlinearCast,
    opts: &ToiOptions,
    start_contact: bool,
) -> Option<Result<Option<ShapeCastHit>, Unsupported>> {
    let rho = moving_disc(c)?;
    // Start poses parry could not use (a rotation that is not unit, coordinates beyond its
    // range) are the general path's, which answers such input as it always has.
    let ok_motions = motion_is_finite(c.m1)
        && motion_is_finite(c.m2)
        && c.m2.angvel == 0.0
        && super::input_guard::pose_ok(&c.m1.start)
        && super::input_guard::pose_ok(&c.m2.start);
    let ok_options = opts.target_distance >= 0.0
        && opts.target_distance.is_finite()
        && opts.distance_tolerance >= 0.0
        && opts.distance_tolerance.is_finite();
    if !(ok_motions && ok_options && is_window(c.t0, c.t1)) {
        return None;
    }
    let mut scratch = SupportScratch::default();
    let core = Core::of(c.g2, &mut scratch)?;
    let p = DiscPair::new(c, core, rho);
    // The core seen from the disc's centre at the start: the start's distance, and the start
    // of both of rule 3's searches (read once).
    let seen0 = core.distance(p.p0);
    let d0 = seen0.0 - rho - core.radius;
    if !d0.is_finite() || !p.w.is_finite() {
        return None;
    }
    if in_contact(c, d0) {
        // The fast body is the disc unless it stays put and the target moves (the general
        // rule then).
        let still = |m: &NonlinearRigidMotion| m.linvel == Vector::ZERO && m.angvel == 0.0;
        let disc_is_fast = !still(c.m1) || still(c.m2);
        return (start_contact && disc_is_fast).then(|| start_contact_answer(c, &p, seen0, d0, opts));
    }
    let delta = opts.target_distance;
    let tol = opts.distance_tolerance * c.size();
    if d0 - delta <= tol {
        return None;
    }
    let span = c.t1 - c.t0;
    let grow = rho + core.radius + delta;
    let s = first_entry(&core, p.p0, p.w, span, grow).or_else(|| first_entry(&core, p.p0, p.w, span, grow + tol));
    Some(toi_to_parry(Ok(s.map(|s| p.hit(c, opts, at_offset(c, s))))))
}

/// A disc's centre and a target that does not turn, in the target's frame (module docs).
struct DiscPair<'a> {
    core: Core<'a>,
    rho: Real,
    /// The disc's centre at the start, and its velocity relative to the target.
    p0: Vector,
    w: Vector,
    /// The target's rotation.
    rotation2: Rotation,
}

impl<'a> DiscPair<'a> {
    fn new(c: &NonlinearCast, core: Core<'a>, rho: Real) -> Self {
        // The disc's centre (its shape's origin) and the target's origin, both translating.
        let (m1, m2) = (c.m1, c.m2);
        let inv = m2.start.rotation.inverse();
        let x0 = inv * (m1.start.translation - m2.start.translation);
        let w = inv * (m1.linvel - m2.linvel);
        DiscPair {
            core,
            rho,
            p0: x0 + w * c.t0,
            w,
            rotation2: m2.start.rotation,
        }
    }

    /// The pair's signed distance with the disc's centre at `p`, the target's witness and the
    /// target's outward normal there.
    fn distance(&self, p: Vector) -> Seen {
        let (sd, q, normal) = self.core.distance(p);
        (sd - self.rho - self.core.radius, q + normal * self.core.radius, normal)
    }

    /// The hit of a contact at the start reported at time `t`, with the pair's exact contact
    /// of that time for its witnesses, in each shape's frame as `rapier_rule::hit_at` gives
    /// them (the disc's at the rotation of its constant spin at `t`, parry's motion), in
    /// closed form ([`Self::hit_with`]). rapier reads only the time.
    fn start_contact_hit(&self, c: &NonlinearCast, t: Real) -> TimeOfImpact {
        let rotation1 = c.m1.position_at_time(t).rotation;
        TimeOfImpact {
            status: ToiStatus::PenetratingAtStart,
            distance_rate: 0.0,
            ..self.hit_with(c, t, rotation1)
        }
    }

    /// The hit at time `t` (apart at the start), with its witnesses and normals in each shape's
    /// frame: the disc's at the rotation its path has at `t`.
    fn hit(&self, c: &NonlinearCast, opts: &ToiOptions, t: Real) -> TimeOfImpact {
        self.hit_with(c, t, rotation_at(c, opts, t))
    }

    /// The hit at time `t`, the disc turned by `rotation1` then: the target's nearest point q
    /// to the disc's centre c (inside a polygon core, its nearest edge's foot) and the outward
    /// normal n there, the target's witness q + r_K·n and the disc's c − ρ·n, each normal and
    /// witness in its shape's frame, and the rate of the distance along n.
    fn hit_with(&self, c: &NonlinearCast, t: Real, rotation1: Rotation) -> TimeOfImpact {
        let (dist, point2, normal2) = self.distance(self.p0 + self.w * (t - c.t0));
        // The target's normal, from the target's frame to the disc's at `t`.
        let to_disc = rotation1.inverse() * self.rotation2;
        let normal1 = to_disc * -normal2;
        TimeOfImpact {
            status: ToiStatus::Hit,
            time: t,
            distance: dist,
            distance_rate: normal2.dot(self.w),
            point1: normal1 * self.rho,
            point2,
            normal1,
            normal2,
            cost: ToiCost::default(),
        }
    }
}

/// Shape 1's rotation at time `t` on the cast's path, as the advancement has it
/// (`query::advance`): parry's constant spin, or the nlerp path's rotation on its clock.
fn rotation_at(c: &NonlinearCast, opts: &ToiOptions, t: Real) -> Rotation {
    let turn = |angle: Real| {
        let (s, c) = sin_cos(angle);
        Rotation::from_cos_sin_unchecked(c, s)
    };
    let spin = |m: &NonlinearRigidMotion, t: Real| turn(m.angvel * t) * m.start.rotation;
    if c.m1.angvel == 0.0 {
        return c.m1.start.rotation;
    }
    let Ok(on) = OnPath::new(c.m1, c.m2, c.t0, c.t1, opts.path) else {
        return spin(c.m1, t);
    };
    match &on.clock {
        None => spin(&on.m1, t),
        Some(clock) => {
            // R(θ_mid)·(1, y)/√(1 + y²) (`Clock::turn_of_path`).
            let (y, _) = clock.turn_of_path(t);
            let inv = 1.0 / (1.0 + y * y).sqrt();
            let middle = turn(on.m1.angvel * clock.middle()) * on.m1.start.rotation;
            middle * Rotation::from_cos_sin_unchecked(inv, y * inv)
        }
    }
}

/// Rule 3 of `rapier_rule` for a disc pair in contact at the start (`d0`; `seen0` the core seen
/// from the disc's centre then): the earlier of the core's contact and the translation's
/// deepening to min(−A, d₀ − A), each a first entry (module docs), as
/// `rapier_rule::start_contact_answer` answers it.
fn start_contact_answer(
    c: &NonlinearCast,
    p: &DiscPair,
    seen0: Seen,
    d0: Real,
    opts: &ToiOptions,
) -> Result<Option<ShapeCastHit>, Unsupported> {
    // The disc's inradius about its rotation centre (`rapier_rule::inradius_about`, the core
    // of a disc being the disc itself): ρ less the centre's offset.
    let r = (p.rho - c.m1.local_center.length()).max(0.0);
    let size = c.size();
    let span = c.t1 - c.t0;
    let nudge = c.t0 + CastPolicy::START_NUDGE * span;
    let tol = opts.distance_tolerance * size;
    let travel = p.w.length() * span;
    // The translation: down to min(−A, d₀ − A), the disc's centre into the target grown by
    // ρ + r_K + level (the disc's spin moves none of its points).
    let allowance = CastPolicy::ALLOWANCE * r.max(CastPolicy::START_CONTACT_GAP * size);
    let level = (-allowance).min(d0 - allowance);
    let t_trans = if travel < d0 - level {
        None
    } else {
        level_entry(p, p.p0, seen0, level + p.rho, span, tol)
    };
    // The core: the disc of CORE·r about the rotation centre (the disc's centre, or any point
    // of a disc that does not turn), down to distance 0 — or, when it starts touching the
    // target, a quarter of its radius below its start, never below CORE_DEPTH_LIMIT of it
    // (`rapier_rule::core_level` on the core's closed-form distance).
    let t_core = if r <= 0.0 || travel < (1.0 - CastPolicy::CORE) * r + d0 {
        None
    } else {
        // The core's centre: the disc's own (seen at the start already) unless the disc, not
        // turning, has its rotation centre elsewhere.
        let (at, seen) = if c.m1.local_center == Vector::ZERO {
            (p.p0, seen0)
        } else {
            let centre = c.m2.start.rotation.inverse() * (c.m1.start * c.m1.local_center - c.m1.start.translation);
            let at = p.p0 + centre;
            (at, p.core.distance(at))
        };
        let core = CastPolicy::CORE * r;
        let start = seen.0 - core - p.core.radius;
        level_entry(p, at, seen, core + core_level(Some(start), core, tol), span, tol)
    };
    let earliest = match (t_trans, t_core) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    };
    toi_to_parry(Ok(earliest.map(|s| p.start_contact_hit(c, at_offset(c, s).max(nudge)))))
}

/// Rule 3's core time (`rapier_rule::start_contact_answer`) in closed form: the first time in
/// `[t0, t1]` at which the disc of radius `radius` about the point moving by `centre` (a
/// translation: its pose's translation at t = 0 and its velocity) comes down to
/// `core_level` of its start's signed distance to `target`, which moves by `target_m` without
/// turning — the same first entry of a point into the target's core grown by the level as a
/// disc's own casts take ([`level_entry`]). `None` where the target is not a polygon, a segment
/// or a disc ([`Core::of`]; the caller's level search answers), `Some(None)` when the core does not get
/// there within the window.
pub(crate) fn core_entry(
    centre: &NonlinearRigidMotion,
    target: &dyn parry2d_f64::shape::Shape,
    target_m: &NonlinearRigidMotion,
    radius: Real,
    (t0, t1): (Real, Real),
    tol: Real,
) -> Option<Option<Real>> {
    // A target that turns, or a pose the contact query would refuse (a rotation that is not
    // unit), is the caller's level search's.
    if target_m.angvel != 0.0 || !super::input_guard::pose_ok(&target_m.start) {
        return None;
    }
    let mut scratch = SupportScratch::default();
    let core = Core::of(target, &mut scratch)?;
    let inv = target_m.start.rotation.inverse();
    let w = inv * (centre.linvel - target_m.linvel);
    let p0 = inv * (centre.start.translation - target_m.start.translation) + w * t0;
    let p = DiscPair {
        core,
        rho: 0.0,
        p0,
        w,
        rotation2: target_m.start.rotation,
    };
    let seen = core.distance(p0);
    let start = seen.0 - radius - core.radius;
    if !(start.is_finite() && w.is_finite()) {
        return None;
    }
    let reach = radius + core_level(Some(start), radius, tol);
    Some(level_entry(&p, p0, seen, reach, t1 - t0, tol).map(|s| (t0 + s).min(t1)))
}

/// The first time after the start (as an offset) at which the point `p0` (from which the core
/// is `seen`) moving with the pair's relative velocity comes within `reach` of the target's
/// boundary: sd_K(p) − r_K = `reach`, as `translation_level` finds it — at the start itself
/// when it is there within `tol` and coming closer, never when it is there and leaving.
fn level_entry(p: &DiscPair, p0: Vector, seen: Seen, reach: Real, span: Real, tol: Real) -> Option<Real> {
    let (sd, _, normal) = seen;
    if sd - p.core.radius - reach <= tol {
        return (normal.dot(p.w) < 0.0).then_some(0.0);
    }
    first_entry(&p.core, p0, p.w, span, reach + p.core.radius)
}

mod translating;
mod translating_ellipse;

pub(crate) use translating::translating_cast;

#[cfg(test)]
mod tests;
