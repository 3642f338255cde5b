//! The separation along a face normal of the turning body that turns with it: the axis of the
//! separating-axis advancement at a contact on a face of B ([`FaceAxis`]; the module docs of
//! `query::advance`).

use super::support_run::{support_run, Run};
use super::{Kinematics, Turning};
use crate::numerics::math::{perp, Real, Vector};
use crate::query::contact::{Contact, Feature, SupportShape};
use parry2d_f64::math::Rotation;

/// A separating axis along which `first_crossing` steps.
#[derive(Copy, Clone)]
pub(super) enum Axis<'a> {
    /// A direction `n` fixed in A's frame: the pieces of S_n − `level` (`pieces`).
    Fixed { n: Vector, level: Real },
    /// A face normal of B, turning with B ([`FaceAxis`]).
    Turning(FaceAxis<'a>),
}

/// A's centre as its one vertex (a disc).
const ORIGIN: [Vector; 1] = [Vector::ZERO];

/// The separation along a face normal of B that turns with B. At a contact on a face of B the
/// fixed axis n is a poor bound: as B turns, an end of the face dips along n at |θ′| times its
/// distance from the contact, the pieces' minimum has a kink there, and the steps converge only
/// linearly (halving the gap from contact to contact, dozens of contacts). With m the face's
/// outward normal in B's frame and m(u) = R(θ(u))·m in A's, every fixed m is a separating axis:
///
/// ```text
/// S(u) = min over A of m(u)·a − h_B(m(u)) = min over i of fᵢ(u),
/// fᵢ(u) = m(u)·(aᵢ − x(u)) − r_A − H,     H = max over B of m·(v − c) + r_B,
/// fᵢ′   = θ′·perp(m(u))·(aᵢ − x) − m(u)·d,
/// |fᵢ″| ≤ (θ′² + |θ″|)·|aᵢ − x| + 2|θ′|·|d|      (x″ = 0 in the path's time),
/// ```
///
/// ≤ D at every time, and equal to D with the same derivative where A's vertex faces B's face
/// (the contact's own configuration): the steps are Newton's on D itself. |aᵢ − x| is convex
/// along the step (x moves on a line), so its larger end value bounds it. A a polygon or a disc
/// (aᵢ its vertices, r_A its radius), B a polygon.
#[derive(Copy, Clone)]
pub(super) struct FaceAxis<'a> {
    /// A's vertices (a disc: its centre).
    vertices: &'a [Vector],
    /// A's edge normals (`support_run`'s order; none for a disc).
    normals: &'a [Vector],
    /// The unit face normal in B's frame.
    m: Vector,
    /// r_A + H + δ.
    offset: Real,
}

impl<'a> FaceAxis<'a> {
    /// The turning axis of contact `c` at clock time `u` when its point on B is on a face of B,
    /// A is a polygon or a disc and B a polygon (`None` otherwise: the fixed axis).
    pub(super) fn of(
        c: &Contact,
        sa: SupportShape<'a>,
        turning: Turning,
        k: &Kinematics,
        u: Real,
        target: Real,
    ) -> Option<Self> {
        if !matches!(c.points[0].feature2, Feature::Face(_)) {
            return None;
        }
        let Turning::Polygon {
            vertices: vb,
            radius: rb,
            centre,
            ..
        } = turning
        else {
            return None;
        };
        let (vertices, normals, ra) = match sa {
            SupportShape::Polygon {
                vertices,
                normals,
                radius,
            } => (vertices, normals, radius),
            SupportShape::Disc(r) => (&ORIGIN[..], &[][..], r),
            _ => return None,
        };
        let m = k.turn(u).0.inverse() * -c.normal;
        let h = vb
            .iter()
            .map(|v| m.dot(*v - centre))
            .fold(Real::NEG_INFINITY, Real::max)
            + rb;
        let offset = ra + h + target;
        (offset.is_finite() && m.is_finite()).then_some(FaceAxis {
            vertices,
            normals,
            m,
            offset,
        })
    }

    /// The axis in A's frame at clock time `u`, as a contact normal (from A towards B).
    pub(super) fn normal_at(&self, k: &Kinematics, u: Real) -> Vector {
        -(k.turn(u).0 * self.m)
    }

    /// Whether A is a polygon (not a disc): whether [`FaceAxis::run`] can leave a vertex out.
    pub(super) fn is_polygon(&self) -> bool {
        !self.normals.is_empty()
    }

    /// A's vertices that can be the minimum while B turns from the rotation `r0` to `r1`,
    /// counter-clockwise when `ccw`, through less than half a turn (`support_run`: min over A
    /// of m·a is A's support along −m, which turns with B); `None` (all of them) for a disc.
    pub(super) fn run(&self, r0: Rotation, r1: Rotation, ccw: bool) -> Option<Run> {
        self.is_polygon()
            .then(|| support_run(self.vertices, self.normals, -(r0 * self.m), -(r1 * self.m), ccw))
    }

    /// Calls `each(fᵢ, fᵢ′, ρᵢ)` for every piece at clock time `u` (type docs), ρᵢ such that
    /// `turn`·ρᵢ bounds |fᵢ″| up to `u_end`, `turn` = θ′² + |θ″| and `d1` = |θ′| bounded there —
    /// of A's vertices, those of `run` only where given ([`FaceAxis::run`]); answers no cap
    /// (infinite).
    pub(super) fn pieces(
        &self,
        k: &Kinematics,
        u: Real,
        u_end: Real,
        (d1, turn): (Real, Real),
        run: Option<Run>,
        mut each: impl FnMut(Real, Real, Real),
    ) -> Real {
        let (rotation, dtheta) = k.turn(u);
        let m = rotation * self.m;
        let pm = perp(m);
        let (x, x_end) = (k.x0 + k.d * u, k.x0 + k.d * u_end);
        // 2|θ′||d| as a share of `turn`.
        let cross = if turn > 0.0 {
            2.0 * d1 * k.d.length() / turn
        } else {
            0.0
        };
        let dm = m.dot(k.d);
        for a in run.unwrap_or(Run::all(self.vertices.len())).of(self.vertices) {
            let r = *a - x;
            let rho = r.length().max((*a - x_end).length()) + cross;
            each(m.dot(r) - self.offset, dtheta * pm.dot(r) - dm, rho);
        }
        Real::INFINITY
    }
}
