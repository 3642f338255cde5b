//! Separating-axis advancement: the time of impact of a turning body against one that does not
//! turn, by lower bounds along separating axes — the fast path of the dispatcher's casts for
//! rapier (a fast body against a target at rest), exact like the trackers, with them to fall
//! back on.
//!
//! # The method
//!
//! Let A be the body that does not turn (it may translate) and B the other, both convex, seen in
//! A's frame: B's rotation centre at x(u) and its rotation θ(u) at the clock time u (the path's
//! clock, `numerics::clock`: x(u) = x₀ + d·τ(u), θ(u) uniform). For any unit direction n the
//! separation along n,
//!
//!   S_n(u) = min over q ∈ B(u) of n·q − h_A(n)     (h_A the support function of A),
//!
//! is at most the signed distance D(u) (the separating-axis theorem: D is the largest of them),
//! and equals it for the contact normal n of the pair. So from a time u_k with the exact
//! contact (D, n), the first time S_n comes down to the target distance δ is no later than the
//! first time D does: the pair is certainly apart before it. There the exact contact gives a new
//! normal, and so on; S_n is tangent to D at u_k (the same value and, the normal being the
//! maximiser, the same derivative), so the times converge to the time of impact like Newton's
//! iteration, in two to four contacts on rapier's scenes. When S_n stays above δ over the rest
//! of the window, so does D: no impact.
//!
//! S_n is explicit. With w = R(θ)ᵀn, n in B's frame, c B's rotation centre in its frame:
//!
//! * B a polygon with vertices vᵢ dilated by r: S_n = min over i of fᵢ,
//!   fᵢ(u) = n·x(u) + w(u)·(vᵢ − c) − r − h_A(n);
//! * B an ellipse with semi-axes a, b (a disc when a = b): S_n = n·x(u) − k(w) − w·c − h_A(n),
//!   k(w) = √(a²w_x² + b²w_y²).
//!
//! Each piece is smooth with |f″| ≤ |n·d|·max|τ″| + θ′²·ρ, where ρ is |vᵢ − c| for a vertex,
//! max(a, b)²/min(a, b) + |c| for an ellipse (the largest radius of curvature bounds the second
//! derivative of k along a turning direction) and |c| for a disc (k = r in every direction).
//! From a time where every piece is above δ, the step to the first root of f + f′s − Ks²/2 is
//! safe for each piece (the parabola lies below it), and the smallest over the pieces is safe for S_n; near a crossing it is Newton's step to
//! second order, so the first crossing of S_n is found in a few steps.
//!
//! The first axis need not come from a contact: any separating axis bounds D from below. Where
//! the caller finds A's face normal of largest separation at the start apart by more than the
//! start-contact gap ([`face_separation`]: the exact distance when a vertex or an arc of B is
//! nearest a face of A, the usual start of a body flying at a wall), the advancement starts
//! from it ([`Start::Axis`]) and the first contact query waits for the first crossing, where
//! the certificate often makes it unneeded. The certificate's projections on a polygon or a
//! disc are exact (`project`), at every scale.
//!
//! At a contact on a face of B (B a polygon, A a polygon or a disc) the axis is that face's
//! normal turning with B instead of n fixed in A ([`FaceAxis`]): still a separating axis at
//! every time, and tangent to D without the kink that the fixed axis has where B's face turns
//! away from it (where an end of the face dips along n faster than the contact point closes, the
//! fixed axis's steps converge only linearly, halving the gap from contact to contact).
//!
//! What the method does not take goes to the trackers: two turning bodies, a turning body that
//! is not a polygon, a disc or an ellipse, pairs the exact contact query does not read, and
//! the rare query that runs out of [`ADVANCE_MAX_CONTACTS`] contacts or [`ADVANCE_MAX_STEPS`]
//! steps (a graze that keeps S_n near δ).

use crate::numerics::clock::Clock;
use crate::numerics::math::{perp, sin_cos, Pose, Real, Vector};
mod certificate;
mod face_axis;
mod project;
mod start;
mod support_run;
mod swept;
#[cfg(test)]
mod test_shapes;

pub(crate) use start::{face_separation, Start};
pub(crate) use swept::certified_miss;

use crate::query::contact::{contact, Contact, SupportShape};
use crate::query::path::OnPath;
use crate::query::toi::{TimeOfImpact, ToiCost, ToiStatus};
use certificate::{certificate, Parry, Witnesses};
use core::f64::consts::FRAC_PI_2;
use face_axis::{Axis, FaceAxis};
use parry2d_f64::math::Rotation;
use parry2d_f64::query::NonlinearRigidMotion;
use parry2d_f64::shape::Shape;
use support_run::{support_run, Run};

/// Exact contacts one advancement computes at most before it hands the query to the trackers.
pub(crate) const ADVANCE_MAX_CONTACTS: usize = 24;

/// Steps along one axis at most before the advancement hands the query to the trackers.
pub(crate) const ADVANCE_MAX_STEPS: usize = 256;

/// Within this angle of the boundary between a `CapsuleEllipse`'s two regions of normals, the
/// pieces of both are taken (module docs of [`pieces`]).
const CAPSULE_BOUNDARY_ANGLE: Real = 1e-6;

/// The fraction of the distance tolerance to which a crossing of a separation is found.
const CROSSING_FRACTION: Real = 1e-3;

/// The contact query's cosine between facing faces that asks for no second point.
const NO_SECOND_POINT: Real = 2.0;

/// The turning body's support seen along the axis: what [`pieces`] needs of it.
#[derive(Copy, Clone)]
enum Turning<'a> {
    /// Vertices, their edge normals (`support_run`'s order), radius, and the rotation centre c.
    Polygon {
        vertices: &'a [Vector],
        normals: &'a [Vector],
        radius: Real,
        centre: Vector,
    },
    /// Semi-axes and the rotation centre.
    Ellipse { a: Real, b: Real, centre: Vector },
    /// A `CapsuleEllipse` (r1, r2, r3) and the rotation centre.
    CapsuleEllipse { r: (Real, Real, Real), centre: Vector },
}

/// The kinematics of B in A's frame (module docs), in the path's own time τ: the rotation
/// centre moves uniformly, x(τ) = x₀ + d·τ, and the rotation is θ(τ) = θ₀ + ω·u(τ), with u the
/// clock time of τ on the nlerp path (`Clock::clock_of_path`; u = τ on parry's motion).
///
/// On the nlerp path the rotation is algebraic: with x = 2s − 1 at the fraction s of the window,
/// h = Δ/2 and k = tan h, u(τ) = t₀ + T/2 + (T/2h)·atan(x·k) and ω = 2h/T, so
///
/// ```text
/// θ(τ) = θ_mid + atan(y),   y = x·k,   R(θ(τ)) = R(θ_mid)·(1, y)/√(1 + y²),
/// θ′(τ) = ω·du/dτ = ω·(k/h)/(1 + y²),
/// ```
///
/// θ_mid = θ₀ + ω·(t₀ + T/2) the rotation at the middle of the window: the direction of the
/// chord point (1 − s)·q₀ + s·q₁ that parry's `Sweep` normalises, one square root and no
/// trigonometric function a time. Without a spin the rotation is B's start rotation in A's
/// frame, as it is.
struct Kinematics {
    x0: Vector,
    d: Vector,
    theta0: Real,
    omega: Real,
    clock: Option<Clock>,
    /// R(θ₀) without a spin, R(θ_mid) on the nlerp path's clock (unused on a turning motion
    /// without a clock).
    base: Rotation,
    /// B's rotation centre in its own frame.
    centre: Vector,
}

impl Kinematics {
    /// R(θ) and θ′ at path time `tau`.
    #[inline]
    fn turn(&self, tau: Real) -> (Rotation, Real) {
        match &self.clock {
            None if self.omega == 0.0 => (self.base, 0.0),
            None => {
                let (s, c) = sin_cos(self.theta0 + self.omega * tau);
                (Rotation::from_cos_sin_unchecked(c, s), self.omega)
            }
            Some(c) => {
                let (y, d1) = c.turn_of_path(tau);
                let inv = 1.0 / (1.0 + y * y).sqrt();
                (
                    self.base * Rotation::from_cos_sin_unchecked(inv, y * inv),
                    self.omega * d1,
                )
            }
        }
    }

    /// Whether B turns counter-clockwise from path time `ta` to `tb`, where it turns through
    /// less than half a turn: always on the nlerp path (its turn over the window is less than
    /// half a turn, in the sense of ω: θ′ = ω·(k/h)/(1 + y²), k/h > 0); on parry's motion where
    /// |ω|·(tb − ta) < π. `None` otherwise.
    fn short_turn(&self, ta: Real, tb: Real) -> Option<bool> {
        (self.clock.is_some() || self.omega.abs() * (tb - ta).abs() < core::f64::consts::PI)
            .then_some(self.omega >= 0.0)
    }

    /// Bounds of |θ′| and |θ″| for path times between `ta` and `tb`.
    fn turn_bounds(&self, ta: Real, tb: Real) -> (Real, Real) {
        let w = self.omega.abs();
        match &self.clock {
            None => (w, 0.0),
            Some(c) => {
                let (d1, d2) = c.clock_of_path_bounds(ta, tb);
                (w * d1, w * d2)
            }
        }
    }

    /// Whether the turning rate varies by more than a factor 4 over the window: on the nlerp
    /// path θ′ ∝ 1/(1 + x²k²), from (k/h)/(1 + k²) at the ends to k/h in the middle, so when
    /// 1 + k² > 4 (|Δ| > 2π/3).
    fn turn_varies(&self) -> bool {
        self.clock.as_ref().is_some_and(|c| c.rate_spread() > 4.0)
    }

    /// B's pose in A's frame at path time `tau`: T(x) R(θ) T(−c).
    fn pose(&self, tau: Real) -> Pose {
        let r = Pose::from_parts(Vector::ZERO, self.turn(tau).0);
        Pose::from_translation(self.x0 + self.d * tau) * r * Pose::from_translation(-self.centre)
    }
}

/// What an advancement found: an answer, or nothing the caller should take (the trackers then).
pub(crate) enum Advance {
    /// The time of impact (status `Hit` or `NoHit`), in the caller's order, on the path's time.
    Answer(TimeOfImpact),
    /// The method does not take this query, or ran out of contacts or steps.
    Declined,
}

/// A pair on its path as the advancement and the certified miss read it: which body turns
/// (B; A the other) and B's kinematics in A's frame, computed once a cast for both.
pub(crate) struct PairOnPath {
    /// Whether B is shape 1 (the caller's order is then reversed).
    b_first: bool,
    k: Kinematics,
}

impl PairOnPath {
    /// The pair moving on the path `on`; `None` when both bodies turn (the method declines).
    pub(crate) fn of(on: &OnPath) -> Option<PairOnPath> {
        let (w1, w2) = (on.m1.angvel, on.m2.angvel);
        if w1 != 0.0 && w2 != 0.0 {
            return None;
        }
        // A: the body that does not turn (shape 2 when neither does).
        let b_first = w1 != 0.0;
        let (ma, mb) = if b_first { (&on.m2, &on.m1) } else { (&on.m1, &on.m2) };
        Some(PairOnPath {
            b_first,
            k: kinematics(ma, mb, on.clock),
        })
    }

    /// The shapes `s1`, `s2` (the caller's order) as A, B.
    fn ordered<'a>(&self, s1: SupportShape<'a>, s2: SupportShape<'a>) -> (SupportShape<'a>, SupportShape<'a>) {
        if self.b_first {
            (s2, s1)
        } else {
            (s1, s2)
        }
    }
}

/// The time of impact of the shapes `s1` and `s2` moving as `pair` says (the motions and clock
/// a tracker would run) over `[t0, t1]`, at target distance `target`, accepting D − δ ≤ `tol`;
/// the shapes must be apart at `t0` by more than `tol` (the caller's start-contact rules come
/// first), the advancement starting as `start` says. One body at most may turn. Module docs.
#[allow(clippy::too_many_arguments)]
pub(crate) fn advance_time_of_impact(
    s1: SupportShape,
    s2: SupportShape,
    g1: &dyn Shape,
    g2: &dyn Shape,
    pair: &PairOnPath,
    t0: Real,
    t1: Real,
    target: Real,
    tol: Real,
    start: Start,
) -> Advance {
    let (b_first, k) = (pair.b_first, &pair.k);
    let (sa, sb) = pair.ordered(s1, s2);
    let Some(turning) = turning_of(sb, k.centre) else {
        return Advance::Declined;
    };
    // The caller's contact at the start (shape 1 first), in A-then-B order.
    let start = match start {
        Start::Contact(first) => Start::Contact(first.map(|c| if b_first { swapped(c, &k.pose(t0)) } else { c })),
        axis => axis,
    };
    let (a, b) = if b_first { (g2, g1) } else { (g1, g2) };
    let b_polygonal = matches!(sb, SupportShape::Polygon { .. });
    let g = Parry {
        a,
        b,
        sa,
        sb,
        b_polygonal,
    };
    let Some(r) = advance(sa, sb, g, turning, k, t0, t1, target, tol, start) else {
        return Advance::Declined;
    };
    Advance::Answer(finish(r, k, b_first))
}

/// What [`advance`] found, in A-then-B order, on the clock.
struct Found {
    status: ToiStatus,
    time: Real,
    /// The distance, normal and witnesses at `time` (A's frame), for a hit.
    at: Option<Witnesses>,
    /// B's pose in A's frame at `time`, where the loop placed it.
    pose: Option<Pose>,
    rate: Real,
    contacts: usize,
}

/// B's kinematics in A's frame from the two motions (A's spin is 0).
fn kinematics(ma: &NonlinearRigidMotion, mb: &NonlinearRigidMotion, clock: Option<Clock>) -> Kinematics {
    // A's pose at t is T(v_A t)·P_A; B's is T(c_B + v_B t) R(ω t) R_B0 T(−c) (parry's motions).
    let inv = ma.start.rotation.inverse();
    let c_b = mb.start * mb.local_center;
    let start = inv * mb.start.rotation;
    let theta0 = start.angle();
    let base = match &clock {
        None => start,
        Some(c) => {
            let (s, co) = sin_cos(theta0 + mb.angvel * c.middle());
            Rotation::from_cos_sin_unchecked(co, s)
        }
    };
    Kinematics {
        x0: inv * (c_b - ma.start.translation),
        d: inv * (mb.linvel - ma.linvel),
        theta0,
        omega: mb.angvel,
        clock,
        base,
        centre: mb.local_center,
    }
}

/// The turning body as [`pieces`] reads it, about its rotation centre `c`.
fn turning_of(s: SupportShape, c: Vector) -> Option<Turning> {
    match s {
        SupportShape::Polygon {
            vertices,
            normals,
            radius,
        } => Some(Turning::Polygon {
            vertices,
            normals,
            radius,
            centre: c,
        }),
        SupportShape::Disc(r) => Some(Turning::Ellipse { a: r, b: r, centre: c }),
        SupportShape::Ellipse(a, b) => Some(Turning::Ellipse { a, b, centre: c }),
        SupportShape::CapsuleEllipse(r1, r2, r3) => Some(Turning::CapsuleEllipse {
            r: (r1, r2, r3),
            centre: c,
        }),
    }
}

/// The outer loop (module docs): exact contacts at the times the separations along their normals
/// allow. `None`: out of contacts or steps, or a value the method cannot use.
#[allow(clippy::too_many_arguments)]
fn advance(
    sa: SupportShape,
    sb: SupportShape,
    g: Parry,
    turning: Turning,
    k: &Kinematics,
    t0: Real,
    t1: Real,
    target: Real,
    tol: Real,
    start: Start,
) -> Option<Found> {
    let mut u = t0;
    // Contacts within `fine` of the target are taken; within `tol`, where the separations make
    // no more progress (a graze between the two).
    let fine = CROSSING_FRACTION * tol;
    // B's pose at `u`, once placed (the certificate's, then the next contact's).
    let mut pose: Option<Pose> = None;
    let (mut first, mut axis0) = match start {
        Start::Contact(c) => (c, None),
        Start::Axis { n, support } => (None, Some((n, support))),
    };
    for contacts in 1..=ADVANCE_MAX_CONTACTS {
        let hit = |at: Witnesses, u: Real, pose: Option<Pose>| hit_found(turning, k, at, u, pose, contacts);
        let (axis, gap, c) = match axis0.take() {
            // The caller's separating axis at the start, along which the pair is apart by more
            // than the tolerance (no contact query): its first crossing, then the certificate
            // or a contact there, as from a contact's axis.
            Some((n, support)) => (
                Axis::Fixed {
                    n,
                    level: support + target,
                },
                Real::INFINITY,
                None,
            ),
            None => {
                let c = match first.take() {
                    Some(c) => c,
                    None => contact(sa, sb, pose.get_or_insert_with(|| k.pose(u)), NO_SECOND_POINT, None)?,
                };
                let gap = c.dist - target;
                if !gap.is_finite() || (u == t0 && gap <= tol) {
                    // In contact at the start: the caller's rules.
                    return None;
                }
                if gap <= fine {
                    return Some(hit(Witnesses::of(&c), u, pose));
                }
                // S_n = min over B of n·q − h_A(n), taken below the level δ to far below the
                // tolerance (Newton's steps: a step or two more than to the tolerance).
                // At a face of B the axis turns with B (module docs); otherwise it is fixed in A.
                let axis = match FaceAxis::of(&c, sa, turning, k, u, target) {
                    Some(face) => Axis::Turning(face),
                    None => Axis::Fixed {
                        n: c.normal,
                        level: support_value(sa, &c, c.normal)? + target,
                    },
                };
                (axis, gap, Some(c))
            }
        };
        match first_crossing(turning, k, axis, u, t1, fine)? {
            Some(next) if next > u => {
                u = next;
                let at = *pose.insert(k.pose(u));
                // A crossing whose witnesses show the distance within the tolerance is the time
                // of impact without another contact query.
                let n = match axis {
                    Axis::Fixed { n, .. } => n,
                    Axis::Turning(face) => face.normal_at(k, u),
                };
                if let Some(w) = certificate(g, &at, n, target + fine) {
                    return Some(hit(w, u, Some(at)));
                }
            }
            // (Only after a contact: the caller's axis starts apart by more than `tol`.)
            _ if gap <= tol => return Some(hit(Witnesses::of(c.as_ref()?), u, pose)),
            Some(_) => return None,
            None => return Some(no_hit(t1, contacts)),
        }
    }
    None
}

/// A hit at clock time `u` with witnesses `at` (B placed at `pose` when known), after
/// `contacts` iterations: the rate from the lowest piece along the normal.
fn hit_found(turning: Turning, k: &Kinematics, at: Witnesses, u: Real, pose: Option<Pose>, contacts: usize) -> Found {
    Found {
        status: ToiStatus::Hit,
        time: u,
        at: Some(at),
        pose,
        rate: lowest_piece(turning, k, at.normal, 0.0, u).1,
        contacts,
    }
}

/// No impact up to the window's end `t1`, after `contacts` iterations.
fn no_hit(t1: Real, contacts: usize) -> Found {
    Found {
        status: ToiStatus::NoHit,
        time: t1,
        at: None,
        pose: None,
        rate: 0.0,
        contacts,
    }
}

/// The contact `c` of body 1 (at the origin) and body 2 (at `pos21`, body 2's pose in body
/// 1's frame) seen from body 2: body 2 first, in its frame.
fn swapped(c: Contact, pos21: &Pose) -> Contact {
    // `pos21` is B's pose in A's frame, A being body 2 of `c`: body 1's points go through it.
    let p = &c.points[0];
    let one = crate::query::contact::ContactPoint {
        point1: *pos21 * p.point2,
        point2: *pos21 * p.point1,
        feature1: p.feature2,
        feature2: p.feature1,
        dist: p.dist,
    };
    Contact {
        dist: c.dist,
        normal: pos21.rotation * -c.normal,
        points: [one; 2],
        len: 1,
    }
}

/// h_A(n), A's support function along `n` (its frame): closed form, or, for a
/// `CapsuleEllipse`, from the contact `c` whose normal is `n` (A's witness is its support point
/// along it).
fn support_value(sa: SupportShape, c: &Contact, n: Vector) -> Option<Real> {
    let h = match sa {
        SupportShape::Polygon { vertices, radius, .. } => {
            vertices.iter().map(|v| v.dot(n)).fold(Real::NEG_INFINITY, Real::max) + radius
        }
        SupportShape::Disc(r) => r,
        SupportShape::Ellipse(a, b) => ((a * n.x).powi(2) + (b * n.y).powi(2)).sqrt(),
        SupportShape::CapsuleEllipse(..) => c.points[0].point1.dot(n),
    };
    h.is_finite().then_some(h)
}

/// The lowest piece of S_n + h_A(n) − `h` at clock time `u`: its value and derivative.
fn lowest_piece(turning: Turning, k: &Kinematics, n: Vector, h: Real, u: Real) -> (Real, Real) {
    let mut lowest = (Real::INFINITY, 0.0);
    pieces(turning, k, n, h, u, u, None, |f, df, _| {
        if f < lowest.0 {
            lowest = (f, df);
        }
    });
    lowest
}

/// Calls `each(f, f′, ρ)` for every piece of min over B of n·q − `h` at clock time `u` (module
/// docs: with `h` = h_A(n) + δ, the pieces of S_n − δ) — of a polygon B, the vertices of `run`
/// only where given (`support_run`: those that can be the minimum up to `u_end`); answers the
/// longest step over which these pieces bound S_n (infinite but for a `CapsuleEllipse`, whose
/// pieces change with the direction).
#[allow(clippy::too_many_arguments)]
fn pieces(
    turning: Turning,
    k: &Kinematics,
    n: Vector,
    h: Real,
    u: Real,
    u_end: Real,
    run: Option<Run>,
    mut each: impl FnMut(Real, Real, Real),
) -> Real {
    let (rotation, dtheta) = k.turn(u);
    let (s, c) = (rotation.im, rotation.re);
    // w = R(−θ) n and its perpendicular, in B's frame.
    let w = Vector::new(c * n.x + s * n.y, -s * n.x + c * n.y);
    let pw = perp(w);
    let base = n.dot(k.x0 + k.d * u) - h;
    let dbase = n.dot(k.d);
    match turning {
        Turning::Polygon {
            vertices,
            radius,
            centre,
            ..
        } => {
            for v in run.unwrap_or(Run::all(vertices.len())).of(vertices) {
                // f = n·x + w·(v − c) − r − h;  f′ = n·d τ′ − θ′ perp(w)·(v − c).
                let p = *v - centre;
                each(base + w.dot(p) - radius, dbase - dtheta * pw.dot(p), p.length());
            }
        }
        Turning::Ellipse { a, b, centre } => {
            let (wx, wy) = (a * w.x, b * w.y);
            let kk = (wx * wx + wy * wy).sqrt();
            // The support point of the centred ellipse along w: (a² w_x, b² w_y)/k.
            let sp = Vector::new(a * wx, b * wy) / kk;
            // A disc's k(w) = r is the same in every direction: only w·c turns (a disc about its
            // centre is a translation, |f″| = 0).
            let rho = if a == b {
                centre.length()
            } else {
                a.max(b) * a.max(b) / a.min(b) + centre.length()
            };
            each(base - kk - w.dot(centre), dbase + dtheta * pw.dot(sp + centre), rho);
        }
        Turning::CapsuleEllipse {
            r: (r1, r2, r3),
            centre,
        } => {
            // min over B of w·q = −h(q), q = −w: the half ellipse (r3, r1 + r2) for q_x < 0; the
            // two arcs (radius r1 about (0, ±r2)) and the segment x = r1 for q_x ≥ 0, where
            // −h(q) = min over the arcs' centres of −(0, ±r2)·q − r1 (the segment's normal is a
            // concave kink between them). h is C¹ across q_x = 0 (the boundary's normal is
            // continuous there), so each region's pieces bound S_n until q leaves the region:
            // the step is capped where it may (q turns at |θ′|); next to the boundary both
            // regions' pieces are taken, which agree there to first order.
            let dir = -w;
            let b = r1 + r2;
            let rho = (r3 * r3 / b).max(b * b / r3).max(r1).max(r3).max(b) + centre.length();
            let to_boundary = dir.x.abs().min(1.0).asin();
            let near = to_boundary < CAPSULE_BOUNDARY_ANGLE;
            if dir.x < 0.0 || near {
                let (x, y) = (r3 * dir.x, b * dir.y);
                let h = (x * x + y * y).sqrt();
                let sp = Vector::new(r3 * x, b * y) / h;
                // d/du of −h(−w) − w·c is −θ′ perp(w)·(s − c), s = ∇h(u) the support point.
                each(base - h - w.dot(centre), dbase - dtheta * pw.dot(sp - centre), rho);
            }
            if dir.x >= 0.0 || near {
                for arc in [Vector::new(0.0, r2), Vector::new(0.0, -r2)] {
                    // −arc·u − r1 = w·arc − r1: a vertex with radius r1.
                    let p = arc - centre;
                    each(base + w.dot(p) - r1, dbase - dtheta * pw.dot(p), rho);
                }
            }
            // q turns at |θ′|, at most its bound over the rest of the window.
            let angle = if near { FRAC_PI_2 } else { to_boundary };
            let fastest = k.turn_bounds(u, u_end).0;
            return if fastest > 0.0 { angle / fastest } else { Real::INFINITY };
        }
    }
    Real::INFINITY
}

/// The first clock time in `[u, u1]` at which the separation along `axis` (S_n − level for a
/// fixed one) comes within `tol` of 0, by safe
/// steps from below each piece's parabola (module docs); `Some(None)`: none in the window;
/// `None`: out of steps or not finite.
fn first_crossing(
    turning: Turning,
    k: &Kinematics,
    axis: Axis,
    mut u: Real,
    u1: Real,
    tol: Real,
) -> Option<Option<Real>> {
    // |f″| ≤ ρ·(θ′² + |θ″|) for every piece (the translation is uniform in the path's time),
    // with the turn's bounds over the rest of the window. Where the turning rate varies much
    // (the nlerp path's peaks in mid-window at 2·tan(Δ/2)/Δ times its mean, 585× at Δ = 3.14),
    // over [u, u + H] instead: a step no longer than the horizon H is safe; H starts at the rest
    // of the window and follows the steps (twice the last), so that the steps away from the peak
    // are not held to the peak's rate.
    let adaptive = k.turn_varies();
    // The vertices that can be the separation's minimum up to `u1` (`support_run`).
    let run = axis_run(turning, k, axis, u, u1);
    let mut horizon = u1 - u;
    let (mut d1, mut d2) = k.turn_bounds(u, u1);
    for _ in 0..ADVANCE_MAX_STEPS {
        if adaptive {
            (d1, d2) = k.turn_bounds(u, (u + horizon).min(u1));
        }
        let turn = d1 * d1 + d2;
        let mut step = Real::INFINITY;
        let mut lowest = Real::INFINITY;
        let each = |f: Real, df: Real, rho: Real| {
            lowest = lowest.min(f);
            let kk = turn * rho;
            // The first root of f + f′s − K s²/2 (the step that is safe for this piece), in the
            // form without cancellation: 2f/(√(f′² + 2Kf) − f′) when the piece comes down.
            let f = f.max(0.0);
            // √(f′² + 2Kf) as a hypotenuse, scaled: f′² alone underflows at 1e-160 m/s.
            let (a, b) = (df.abs(), (2.0 * kk * f).sqrt());
            let (hi, lo) = if a > b { (a, b) } else { (b, a) };
            let root = if hi > 0.0 {
                hi * (1.0 + (lo / hi) * (lo / hi)).sqrt()
            } else {
                0.0
            };
            let s = if df < 0.0 {
                2.0 * f / (root + a)
            } else if kk > 0.0 {
                (df + root) / kk
            } else {
                Real::INFINITY
            };
            step = step.min(s);
        };
        let cap = match axis {
            Axis::Fixed { n, level } => pieces(turning, k, n, level, u, u1, run, each),
            Axis::Turning(face) => face.pieces(
                k,
                u,
                if adaptive { (u + horizon).min(u1) } else { u1 },
                (d1, turn),
                run,
                each,
            ),
        };
        let step = if adaptive {
            step.min(cap).min(horizon)
        } else {
            step.min(cap)
        };
        if !(lowest.is_finite() && step >= 0.0) {
            return None;
        }
        if lowest <= tol {
            return Some(Some(u));
        }
        let next = u + step;
        if next >= u1 {
            return Some(None);
        }
        if next <= u {
            // Below rounding: the crossing is here.
            return Some(Some(u));
        }
        u = next;
        horizon = 2.0 * step;
    }
    None
}

/// The vertices of the polygon whose pieces make the separation along `axis` that can be its
/// minimum between clock times `u` and `u1` (`support_run`); `None` (all of them) where the
/// pieces are not a polygon's vertices.
fn axis_run(turning: Turning, k: &Kinematics, axis: Axis, u: Real, u1: Real) -> Option<Run> {
    // B's rotations at both ends, only where the pieces are a polygon's vertices.
    let ends = || Some((k.short_turn(u, u1)?, k.turn(u).0, k.turn(u1).0));
    match axis {
        // min over B's vertices of w·(v − c), w = R(θ)ᵀn: B's support along −w, which turns
        // the other way from B.
        Axis::Fixed { n, .. } => match turning {
            Turning::Polygon { vertices, normals, .. } => {
                let (ccw, r0, r1) = ends()?;
                let (d0, d1) = (-(r0.inverse() * n), -(r1.inverse() * n));
                Some(support_run(vertices, normals, d0, d1, !ccw))
            }
            _ => None,
        },
        Axis::Turning(face) if face.is_polygon() => {
            let (ccw, r0, r1) = ends()?;
            face.run(r0, r1, ccw)
        }
        Axis::Turning(_) => None,
    }
}

/// The answer in the caller's order and on the path's time.
fn finish(r: Found, k: &Kinematics, b_first: bool) -> TimeOfImpact {
    let cost = ToiCost {
        evaluations: r.contacts,
        ..ToiCost::default()
    };
    let mut out = TimeOfImpact {
        status: r.status,
        time: r.time,
        distance: 0.0,
        distance_rate: 0.0,
        point1: Vector::ZERO,
        point2: Vector::ZERO,
        normal1: Vector::X,
        normal2: -Vector::X,
        cost,
    };
    if let Some(w) = r.at {
        // A's frame: A's witness is in its own frame; B's goes to B's.
        let pose = r.pose.unwrap_or_else(|| k.pose(r.time));
        out.distance = w.dist;
        out.distance_rate = r.rate;
        out.point1 = w.point_a;
        out.point2 = pose.inverse_transform_point(w.point_b);
        out.normal1 = w.normal;
        out.normal2 = pose.rotation.inverse() * -w.normal;
    }
    if b_first {
        out.swapped()
    } else {
        out
    }
}
