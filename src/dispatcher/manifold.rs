//! Contact manifolds for rapier: [`SmoothDispatcher`] as parry's `PersistentQueryDispatcher`.
//!
//! rapier's narrow phase asks its dispatcher for *contact manifolds* (the persistent contact
//! points the solver works on), not for single contacts. This module builds them:
//!
//! * **Pairs of this crate's shapes with polygons, discs, ellipses and `CapsuleEllipse`s**
//!   (parry's boxes, polygons, triangles, segments, capsules and their round versions included,
//!   read in place by [`super::support_shape`]): the exact contact query
//!   ([`crate::query::contact`], docs/theory.md § 13) — the signed distance as the minimum of a
//!   support function over the merged breakpoints of both shapes, exact shallow or deep, with two
//!   points where a face faces a face (the incident face clipped to the reference face, feature
//!   ids that do not depend on which face is the reference) and one point elsewhere. Its search
//!   starts from the normal of the manifold rapier hands back ([`SmoothDispatcher::warm_start`]);
//!   the answer does not depend on it.
//! * **Other pairs the dispatcher answers itself** (see [`crate::dispatcher`]: a user's curve, a
//!   polygon of more than 16 vertices, and any pair whose exact contact failed): the manifold
//!   comes from the exact stationary distance ([`SmoothDispatcher::signed_distance`]). Such a pair has a
//!   strictly convex side, so the contact is a single point, added when the signed distance is
//!   at most the prediction distance. The one exception is a half-space against a curve with a
//!   flat piece (a [`crate::RoundedPolygon`] edge, the segment of a [`crate::CapsuleEllipse`])
//!   facing it within [`FLAT_FEATURE_MAX_ANGLE`]: the manifold then has two points, the ends of
//!   the flat piece (the end nearer the plane replaced by the support point once the support
//!   point has left the piece), each with its exact distance, so that a body can rest on a flat
//!   side. Pairs where neither side is strictly convex and the exact contact does not apply are
//!   parry's, which clips the shapes' polygonal features and returns up to two points; where
//!   parry's manifold comes back empty for shapes its distance puts within the prediction
//!   (nearly touching parallel faces, where GJK/EPA give up), it is computed on the shapes pushed
//!   10⁻⁸ of their size into each other and its distances measured at the true pose.
//! * **Composite shapes** (compound, polyline, trimesh, heightfield, voxels) on either side:
//!   parry's composite helpers, called with *this* dispatcher so that every sub-pair comes back
//!   here ([`PersistentQueryDispatcher::contact_manifold_convex_convex`]); a polyline, compound,
//!   heightfield or user's composite against one of the crate's shapes or a user's curve, the
//!   dispatcher's own version of parry's helpers with two manifolds a part, the part's points and
//!   its core contact (`super::part_cores`, [`SmoothDispatcher::part_manifolds`]). Normal constraints
//!   (an oriented polyline's or a fixed-edge compound's pseudo-normals) are applied to the smooth contact's
//!   normals, and a contact whose normal they moved is re-derived along the new one
//!   ([`super::constrained`]: none where its line misses the part).
//! * **Everything else** goes to parry's `DefaultQueryDispatcher`; so does a pair of ours whose
//!   stationary distance failed (parry then works through the shapes' polygonal feature maps).
//!   The commonest of parry's own pairs (box–box, disc–disc, a disc against another convex
//!   shape) skip parry's dispatch ([`super::parry_pairs`]): parry's answer to the bit.
//!
//! # Feature ids (warm starting)
//!
//! The exact contact query's ids are described in [`crate::query::contact`]. For the other
//! pairs: rapier transfers the previous step's impulses to a new contact with the same pair of
//! feature ids. The id of a contact on a curve is derived from the piece of the curve (between
//! breakpoints, see [`ConvexCurve::breakpoints`]) that holds the witness point: `face(k)` when
//! piece k is flat, `vertex(2k)` when it is curved (a smooth curve such as an ellipse has one
//! piece: every contact is `vertex(0)`, so a rolling contact keeps its impulse); the ends of a
//! flat piece are `vertex(2j + 1)` with j the index of the breakpoint. A half-space contributes
//! `face(0)`. The ids are therefore stable while a contact stays on the same piece, and the two
//! points of a two-point manifold have distinct ids.
//!
//! No contact caching: the manifold is recomputed at every call (parry's polygonal path reuses
//! contacts while the pose changes by less than its thresholds, which makes smooth bodies roll
//! over small facets).

use super::apart::{beyond_prediction, circles, circles_apart, far_apart};
use super::composite::{composite_manifolds, is_composite_like};
use super::core_disc::{
    add_part_core, core_contact, core_disc_manifolds, core_manifold_of, core_of_shape, place_part_core, CoreContact,
};
use super::distance_manifold::manifold_from_distance;
use super::input_guard;
use super::parry_fallback::{pair_size, parry_within, pushed_together, TOUCH_PUSH};
use super::parry_pairs;
use super::route::{own_curve, route, RouteScratch};
use super::segment_side::from_centre_side;
use super::support_shape::{exact_contact_of, support_shape, SupportScratch};
use crate::numerics::math::{Pose, Real, Vector};
use crate::parry_shape::{face_id, vertex_id};
use crate::query::contact::{Contact, Feature};
use crate::SmoothDispatcher;
use parry2d_f64::query::details::NormalConstraints;
use parry2d_f64::query::{
    ContactManifold, ContactManifoldsWorkspace, DefaultQueryDispatcher, PersistentQueryDispatcher, TrackedContact,
    Unsupported,
};
use parry2d_f64::shape::{Shape, ShapeType};

/// Fills `manifold` from the exact contact of a pair of polygonal shapes, or of one with an
/// ellipse or a `CapsuleEllipse` ([`crate::query::contact`]): its one or two points within the
/// prediction, their ids kept from the previous points (rapier's warm start). False, with the
/// manifold left as it was, when a point is not finite in body 2's frame.
fn manifold_from_contact<M, C: Default + Copy>(
    pos12: &Pose,
    c: &Contact,
    core: Option<CoreContact>,
    prediction: Real,
    manifold: &mut ContactManifold<M, C>,
    own: Option<&mut ContactManifold<M, C>>,
) -> bool {
    let local2 = |p: Vector| pos12.inverse_transform_point(p);
    let n2 = pos12.inverse_transform_vector(-c.normal);
    if !(n2.is_finite() && c.points[..c.len].iter().all(|p| local2(p.point2).is_finite())) {
        return false;
    }
    let (old, n_old) = parry_pairs::previous_points(&manifold.points);
    manifold.clear();
    manifold.local_n1 = c.normal;
    manifold.local_n2 = n2;
    let fid = |f: Feature| match f {
        Feature::Face(k) => face_id(k),
        Feature::Vertex(k) => vertex_id(k),
    };
    // The deepest point within the prediction makes a contact; the second point of facing faces
    // (the other end of the clipped incident face) goes with it whatever its distance: rapier's
    // solver takes it as a speculative contact only when the bodies' velocities would close it
    // within the step (a face turning in), and a one-point contact would leave that unseen.
    let keep = c.len > 0 && c.points[0].dist <= prediction;
    for (k, p) in c.points[..c.len].iter().enumerate() {
        if p.dist <= prediction || (keep && k > 0) {
            manifold.points.push(TrackedContact::new(
                p.point1,
                local2(p.point2),
                fid(p.feature1),
                fid(p.feature2),
                p.dist,
            ));
        }
    }
    place_part_core(pos12, c.normal, core, prediction, manifold, own);
    manifold.match_contacts(&old[..n_old]);
    true
}

/// Where [`SmoothDispatcher::exact_manifold`] puts the core contacts of a pair.
enum Cores<'a, M, C> {
    /// A convex pair: each body's core in a manifold of its own (two manifolds).
    Both(&'a mut [ContactManifold<M, C>]),
    /// A part of a composite shape: the smaller body's core with the part's points, or beside
    /// them in a manifold of its own where one is given ([`place_part_core`]).
    Part(Option<&'a mut ContactManifold<M, C>>),
}

/// The dispatcher's guard around parry's manifolds: when `ok` is false (a bad pose or shape in,
/// a non-finite contact out), the manifolds are cleared and the pair is `Unsupported`.
#[inline]
pub(super) fn guarded<M, C: Default + Copy>(
    manifolds: &mut [ContactManifold<M, C>],
    ok: bool,
) -> Result<(), Unsupported> {
    if ok {
        Ok(())
    } else {
        refused(manifolds)
    }
}

/// [`guarded`]'s refusal, out of line: inlined, the clearing loop made parry's disc pairs
/// through the dispatcher about 10 % slower (`cargo bench --bench ratios -- parry-pairs`).
#[cold]
#[inline(never)]
fn refused<M, C: Default + Copy>(manifolds: &mut [ContactManifold<M, C>]) -> Result<(), Unsupported> {
    manifolds.iter_mut().for_each(|m| m.clear());
    Err(Unsupported)
}

impl SmoothDispatcher {
    /// The manifolds of a pair with a composite shape: parry's helpers with this dispatcher, for
    /// a finite pose (with a non-finite one parry's helpers would prune every part as apart:
    /// issue 32). Out of line: the convex pairs' path stays as short as it was.
    #[inline(never)]
    fn composite_pair_manifolds<M, C>(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
        manifolds: &mut Vec<ContactManifold<M, C>>,
        workspace: &mut Option<ContactManifoldsWorkspace>,
    ) -> Result<(), Unsupported>
    where
        M: Default + Clone + Send + Sync,
        C: Default + Copy + Send + Sync,
    {
        guarded(manifolds, pos12.is_finite())?;
        composite_manifolds(self, pos12, g1, g2, prediction, manifolds, workspace);
        Ok(())
    }

    /// The exact contact query's manifold of an unconstrained convex pair whose two shapes it
    /// reads ([`support_shape`]: one of this crate's, no half-space, no user's curve), each shape
    /// read once: bounding circles apart, no point; else the exact contact from the previous
    /// normal. False (the manifold unchanged) when the pair is not such a pair or its contact
    /// failed: the rest of `contact_manifold_convex_convex` answers it.
    fn exact_manifold<M, C: Default + Copy>(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
        manifold: &mut ContactManifold<M, C>,
        cores: Cores<M, C>,
    ) -> bool {
        // parry's own pairs (e.g. the parts of a compound) stay parry's.
        if g1.shape_type() != ShapeType::Custom && g2.shape_type() != ShapeType::Custom {
            return false;
        }
        let (mut st1, mut st2) = (SupportScratch::default(), SupportScratch::default());
        let (Some(s1), Some(s2)) = (support_shape(g1, &mut st1), support_shape(g2, &mut st2)) else {
            return false;
        };
        // A pair whose last manifold had no point (apart beyond the prediction, or new) is tried
        // along its last normal and its line of centres before the exact contact; one in contact
        // last time, which usually still is, goes straight to it.
        let b = circles(pos12, g1, g2);
        let was_apart = manifold.points.is_empty();
        if circles_apart(pos12, &b, prediction)
            || (was_apart && beyond_prediction(s1, s2, pos12, &b, manifold.local_n1, prediction))
        {
            manifold.clear();
            match cores {
                Cores::Both(m) => m.iter_mut().for_each(|m| m.clear()),
                Cores::Part(m) => m.into_iter().for_each(|m| m.clear()),
            }
            return true;
        }
        let hint = Some(manifold.local_n1).filter(|n| self.warm_start && n.is_finite() && *n != Vector::ZERO);
        let Some(c) = exact_contact_of(s1, s2, pos12, hint) else {
            return false;
        };
        // Each shape's core, once: the centres below and the core contacts read them.
        let k = [core_of_shape(g1, s1), core_of_shape(g2, s2)];
        // A wall of no thickness: the contact from the side the body's centre is on.
        let c = match k {
            [Some(k1), Some(k2)] => from_centre_side(c, pos12, g1, g2, k1.centre, k2.centre),
            _ => c,
        };
        match cores {
            // Each body's core, in a manifold of its own.
            Cores::Both(m) => {
                manifold_from_contact(pos12, &c, None, prediction, manifold, None)
                    && core_disc_manifolds(
                        pos12,
                        [g1, g2],
                        [Some(s1), Some(s2)],
                        k,
                        &c,
                        !manifold.points.is_empty(),
                        m,
                    )
            }
            // One core, with the exact points or beside them (a part of a composite shape).
            Cores::Part(own) => {
                manifold_from_contact(pos12, &c, core_contact(s1, s2, k, pos12, &c), prediction, manifold, own)
            }
        }
    }
}

impl<M, C> PersistentQueryDispatcher<M, C> for SmoothDispatcher
where
    M: Default + Clone + Send + Sync,
    C: Default + Copy + Send + Sync,
{
    fn contact_manifolds(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: Real,
        manifolds: &mut Vec<ContactManifold<M, C>>,
        workspace: &mut Option<ContactManifoldsWorkspace>,
    ) -> Result<(), Unsupported> {
        if prediction.is_nan() || prediction < 0.0 {
            // parry's contract (its composite helpers assert it): no negative or NaN prediction.
            return Err(Unsupported);
        }
        let (t1, t2) = (g1.shape_type(), g2.shape_type());
        if is_composite_like(g1, t1) || is_composite_like(g2, t2) {
            return self.composite_pair_manifolds(pos12, g1, g2, prediction, manifolds, workspace);
        }
        if t1 != ShapeType::Custom && t2 != ShapeType::Custom {
            // The commonest pairs (box–box, disc–disc, disc–convex): parry's answer without its dispatch.
            if let Some(answer) = parry_pairs::common_manifold(pos12, g1, t1, g2, t2, prediction, manifolds) {
                return answer;
            }
            // Two of parry's convex shapes: parry's manifold, behind the dispatcher's guards. What
            // parry's `contact_manifolds` does for two convex shapes (its first manifold, made if
            // missing, from its convex routine), without its dispatch on the types again.
            let guards = input_guard::pose_ok(pos12) && input_guard::shapes_ok_typed(g1, t1, g2, t2);
            guarded(manifolds, guards)?;
            if manifolds.is_empty() {
                manifolds.push(ContactManifold::new());
            }
            let manifold = &mut manifolds[0];
            DefaultQueryDispatcher.contact_manifold_convex_convex(pos12, g1, g2, None, None, prediction, manifold)?;
            let finite = manifolds.iter().all(input_guard::AllFinite::all_finite);
            return guarded(manifolds, finite);
        }
        // Three manifolds, always, for a stable count (rapier's solver graph keeps manifolds by
        // their place in the list): the pair's points, and each body's core contact.
        manifolds.truncate(3);
        while manifolds.len() < 3 {
            manifolds.push(ContactManifold::new());
        }
        for m in manifolds.iter_mut() {
            (m.subshape1, m.subshape2, m.subshape_poses) = (0, 0, None);
        }
        let (main, cores) = manifolds.split_at_mut(1);
        if self.exact_manifold(pos12, g1, g2, prediction, &mut main[0], Cores::Both(cores)) {
            return Ok(());
        }
        let answer = self.curve_manifold(pos12, g1, g2, None, None, prediction, &mut main[0]);
        match answer {
            // The bodies' core contacts, when the manifold has a point.
            Ok(()) => core_manifold_of(pos12, g1, g2, &main[0], cores),
            Err(_) => cores.iter_mut().for_each(|m| m.clear()),
        }
        answer
    }

    fn contact_manifold_convex_convex(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        normal_constraints1: Option<&dyn NormalConstraints>,
        normal_constraints2: Option<&dyn NormalConstraints>,
        prediction: Real,
        manifold: &mut ContactManifold<M, C>,
    ) -> Result<(), Unsupported> {
        let nc = [normal_constraints1, normal_constraints2];
        self.part_manifold(pos12, g1, g2, nc, prediction, manifold, None)
    }
}

impl SmoothDispatcher {
    /// The manifolds of a part of a composite shape against a convex shape (`g1`, `g2`, their
    /// normal constraints `nc`) as the dispatcher's own bookkeeping of a composite takes them,
    /// two a part: the part's points in `manifold`, and in `core` the smaller body's core
    /// contact where it would otherwise take the place of the second point (module docs of
    /// `core_disc`, `place_part_core`). `contact_manifold_convex_convex` with a manifold for the
    /// core. Not a public API: the composite helpers of both packages call it.
    #[doc(hidden)]
    #[allow(clippy::too_many_arguments)]
    pub fn part_manifolds<M, C>(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        nc: [Option<&dyn NormalConstraints>; 2],
        prediction: Real,
        manifold: &mut ContactManifold<M, C>,
        core: &mut ContactManifold<M, C>,
    ) -> Result<(), Unsupported>
    where
        M: Default + Clone + Send + Sync,
        C: Default + Copy + Send + Sync,
    {
        let answer = self.part_manifold(pos12, g1, g2, nc, prediction, manifold, Some(&mut *core));
        if answer.is_err() {
            core.clear();
        }
        answer
    }

    /// `contact_manifold_convex_convex` of a part, its core placed by `place_part_core` (`own`:
    /// the part's manifold for it, if any).
    #[allow(clippy::too_many_arguments)]
    fn part_manifold<M, C>(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        [nc1, nc2]: [Option<&dyn NormalConstraints>; 2],
        prediction: Real,
        manifold: &mut ContactManifold<M, C>,
        own: Option<&mut ContactManifold<M, C>>,
    ) -> Result<(), Unsupported>
    where
        M: Default + Clone + Send + Sync,
        C: Default + Copy + Send + Sync,
    {
        let unconstrained = nc1.is_none() && nc2.is_none();
        let own = match own {
            Some(m) if unconstrained => {
                // Reborrowed for the exact path; handed on below when it declines.
                if self.exact_manifold(pos12, g1, g2, prediction, manifold, Cores::Part(Some(&mut *m))) {
                    return Ok(());
                }
                Some(m)
            }
            None if unconstrained && self.exact_manifold(pos12, g1, g2, prediction, manifold, Cores::Part(None)) => {
                return Ok(());
            }
            own => own,
        };
        let (old, n_old) = parry_pairs::previous_points(&manifold.points);
        if let Err(e) = self.curve_manifold(pos12, g1, g2, nc1, nc2, prediction, manifold) {
            if let Some(m) = own {
                m.clear();
            }
            return Err(e);
        }
        // A part of a composite shape (parry's composite helpers call this method for each): the
        // smaller body's core contact with the points, as the exact path gives it, its impulse
        // kept from the previous points; parry's own pairs keep parry's manifold to the bit.
        if own_curve(g1).is_some() || own_curve(g2).is_some() {
            add_part_core(pos12, g1, g2, prediction, manifold, own);
            manifold.match_contacts(&old[..n_old]);
        } else if let Some(m) = own {
            m.clear();
        }
        Ok(())
    }
}

impl SmoothDispatcher {
    /// The manifold of a convex pair the exact contact query does not make (a user's curve, a
    /// polygon of more than 16 vertices, a curve on a half-space, two of parry's shapes): one
    /// point from the exact stationary distance where a side is strictly convex, parry's
    /// clipped manifold otherwise (module docs).
    #[allow(clippy::too_many_arguments)]
    fn curve_manifold<M: Default + Clone + Send + Sync, C: Default + Copy + Send + Sync>(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        normal_constraints1: Option<&dyn NormalConstraints>,
        normal_constraints2: Option<&dyn NormalConstraints>,
        prediction: Real,
        manifold: &mut ContactManifold<M, C>,
    ) -> Result<(), Unsupported> {
        let ours = own_curve(g1).is_some() || own_curve(g2).is_some();
        if ours && far_apart(pos12, g1, g2, prediction) {
            manifold.clear();
            return Ok(());
        }
        // Route once: parry shapes are converted to curves a single time per query.
        let mut scratch = RouteScratch::default();
        let routed = if ours { Some(route(g1, g2, &mut scratch)) } else { None };
        let sd = routed.as_ref().and_then(|r| self.routed_distance(r, pos12));
        match (sd, &routed) {
            (Some(Ok(sd)), Some(r)) => {
                manifold_from_distance(
                    pos12,
                    g1,
                    g2,
                    r.curves(),
                    &sd,
                    normal_constraints1,
                    normal_constraints2,
                    prediction,
                    manifold,
                );
                Ok(())
            }
            // Not ours, or our distance failed: parry (through the polygonal feature maps),
            // under the dispatcher's guards (no NaN pose or shape in, no NaN contact out).
            _ => {
                let guards = input_guard::pose_ok(pos12) && input_guard::shapes_ok(g1, g2);
                guarded(core::slice::from_mut(manifold), guards)?;
                DefaultQueryDispatcher.contact_manifold_convex_convex(
                    pos12,
                    g1,
                    g2,
                    normal_constraints1,
                    normal_constraints2,
                    prediction,
                    manifold,
                )?;
                if ours && manifold.points.is_empty() && parry_within(pos12, g1, g2, prediction) {
                    touching_manifold(
                        pos12,
                        g1,
                        g2,
                        normal_constraints1,
                        normal_constraints2,
                        prediction,
                        manifold,
                    )?;
                }
                let finite = input_guard::AllFinite::all_finite(manifold);
                guarded(core::slice::from_mut(manifold), finite)
            }
        }
    }
}

/// parry's manifold of shapes within the prediction of each other for which parry's own comes
/// back empty (GJK/EPA give up on shapes that touch or nearly touch, e.g. parallel faces 1e-10
/// apart, as rapier's CCD leaves them; see `parry_contact` in [`crate::dispatcher`]): computed
/// with the shapes pushed into each other by a tiny fraction of their size, then each point's
/// distance recomputed at the true pose.
#[allow(clippy::too_many_arguments)]
fn touching_manifold<M, C>(
    pos12: &Pose,
    g1: &dyn Shape,
    g2: &dyn Shape,
    normal_constraints1: Option<&dyn NormalConstraints>,
    normal_constraints2: Option<&dyn NormalConstraints>,
    prediction: Real,
    manifold: &mut ContactManifold<M, C>,
) -> Result<(), Unsupported>
where
    M: Default + Clone + Send + Sync,
    C: Default + Copy + Send + Sync,
{
    let size = pair_size(g1, g2);
    for push in TOUCH_PUSH {
        let deeper = pushed_together(pos12, push * size);
        DefaultQueryDispatcher.contact_manifold_convex_convex(
            &deeper,
            g1,
            g2,
            normal_constraints1,
            normal_constraints2,
            prediction + push * size,
            manifold,
        )?;
        if manifold.points.is_empty() {
            continue;
        }
        let n1 = manifold.local_n1;
        for p in &mut manifold.points {
            p.dist = (pos12.transform_point(p.local_p2) - p.local_p1).dot(n1);
        }
        manifold.points.retain(|p| p.dist <= prediction && p.dist.is_finite());
        return Ok(());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dispatcher::core_disc::CORE_FEATURE;
    use crate::{Ellipse, RoundedPolygon};
    use parry2d_f64::shape::{Compound, Cuboid, HalfSpace, PackedFeatureId, SharedShape};

    type Manifolds = Vec<ContactManifold<(), ()>>;

    fn manifolds(g1: &dyn Shape, g2: &dyn Shape, pos12: &Pose, prediction: f64) -> Manifolds {
        let mut m = Vec::new();
        let mut ws = None;
        PersistentQueryDispatcher::<(), ()>::contact_manifolds(
            &SmoothDispatcher::default(),
            pos12,
            g1,
            g2,
            prediction,
            &mut m,
            &mut ws,
        )
        .unwrap();
        m
    }

    #[test]
    fn ellipse_on_box_is_one_exact_point_and_each_core_in_a_manifold_of_its_own() {
        let e = Ellipse::new(0.5, 0.2);
        let b = Cuboid::new(Vector::new(2.0, 0.5));
        // Ellipse 0.19 above the box top (penetration 0.01).
        let pos12 = Pose::translation(0.1, 0.69);
        let m = manifolds(&b, &e, &pos12, 0.0);
        assert_eq!(m.len(), 3);
        assert_eq!(m[0].points.len(), 1);
        let p = &m[0].points[0];
        assert!((p.dist + 0.01).abs() < 1e-12, "{}", p.dist);
        assert!((m[0].local_n1 - Vector::Y).length() < 1e-12);
        assert!((m[0].local_n2 + Vector::Y).length() < 1e-12);
        assert!((p.local_p2 - Vector::new(0.0, -0.2)).length() < 1e-9);
        assert!(p.fid1.is_face());
        assert_eq!(p.fid2, PackedFeatureId::vertex(0));
        // The box's core (half its inradius 0.5 about its centre: a disc of 0.25 at the origin):
        // its line along the normal (x = 0) misses the ellipse's lowest point (x = 0.1), a curved
        // side: no core contact (it would push the ellipse at a point it does not have).
        assert!(m[1].points.is_empty());
        // The ellipse's core (half its inradius 0.2: a disc of 0.1 about its centre) 0.09 above
        // the box's face, the point of the face under its centre, in a manifold of its own.
        let k2 = &m[2].points;
        assert_eq!(k2.len(), 1);
        let k2 = &k2[0];
        assert!((m[2].local_n1 - Vector::Y).length() < 1e-12);
        assert!((k2.dist - 0.09).abs() < 1e-12, "{}", k2.dist);
        assert!((k2.local_p2 - Vector::new(0.0, -0.1)).length() < 1e-12);
        assert!((k2.local_p1 - Vector::new(0.1, 0.5)).length() < 1e-12);
        assert_eq!(k2.fid2, vertex_id(CORE_FEATURE - 1));
        // Swapped order gives the mirrored manifolds, each body's core in its own.
        let m2 = manifolds(&e, &b, &pos12.inverse(), 0.0);
        let q = &m2[0].points[0];
        assert!((q.dist - p.dist).abs() < 1e-12);
        assert!((q.local_p1 - p.local_p2).length() < 1e-9);
        assert_eq!(q.fid2, p.fid1);
        assert!((m2[1].points[0].dist - 0.09).abs() < 1e-12);
        assert!(m2[2].points.is_empty());
        // Apart beyond the prediction: no point, no core contact (three manifolds still, for a
        // stable count); within it, the exact point and the core contacts, whatever their gaps.
        let far = Pose::translation(0.0, 0.75);
        let apart = manifolds(&b, &e, &far, 0.01);
        assert_eq!(apart.len(), 3);
        assert!(apart.iter().all(|m| m.points.is_empty()));
        let near = manifolds(&b, &e, &far, 0.1);
        assert_eq!(near[0].points.len(), 1);
        assert!((near[0].points[0].dist - 0.05).abs() < 1e-12);
        // Over the box's centre both cores' lines meet the other body (its face, its lowest
        // point): both along the normal, in the first core manifold.
        assert_eq!((near[1].points.len(), near[2].points.len()), (2, 0));
    }

    #[test]
    fn a_core_whose_line_misses_a_polygon_meets_its_nearest_point_along_its_own_normal() {
        // A small square resting on a long box 1.5 from the box's centre: the box's core line
        // (x = 0) misses the square, so the box's core contact is its core disc (radius 0.25 at
        // the origin) against the square's nearest corner (1.3, 0.49), along their line; the
        // square's core (0.1 about its centre) is along the pair's normal, over the box's face.
        let b = Cuboid::new(Vector::new(2.0, 0.5));
        let sq = RoundedPolygon::regular(4, 0.2 * std::f64::consts::SQRT_2, 0.0);
        let pos12 = Pose::new(Vector::new(1.5, 0.69), std::f64::consts::FRAC_PI_4);
        let m = manifolds(&b, &sq, &pos12, 0.0);
        assert_eq!(m.len(), 3);
        let corner = Vector::new(1.3, 0.49);
        let (k1, n1) = (&m[1].points[0], m[1].local_n1);
        assert!((n1 - corner / corner.length()).length() < 1e-12, "{n1:?}");
        assert!((k1.dist - (corner.length() - 0.25)).abs() < 1e-12, "{}", k1.dist);
        assert!((k1.local_p1 - n1 * 0.25).length() < 1e-12);
        assert!((pos12 * k1.local_p2 - corner).length() < 1e-12);
        let k2 = &m[2].points[0];
        assert!((m[2].local_n1 - Vector::Y).length() < 1e-12);
        assert!((k2.dist - 0.09).abs() < 1e-12, "{}", k2.dist);
        assert!((k2.local_p1 - Vector::new(1.5, 0.5)).length() < 1e-12);
    }

    #[test]
    fn a_part_of_a_compound_carries_the_core_contact_of_the_smaller_body() {
        // A single manifold per part: the exact point and one core contact, the ellipse's (0.5
        // from its centre to its farthest point, the box 2.06).
        let e = Ellipse::new(0.5, 0.2);
        let b = Cuboid::new(Vector::new(2.0, 0.5));
        let pos12 = Pose::translation(0.1, 0.69);
        let mut m = ContactManifold::<(), ()>::new();
        SmoothDispatcher::default()
            .contact_manifold_convex_convex(&pos12, &b, &e, None, None, 0.0, &mut m)
            .unwrap();
        assert_eq!(m.points.len(), 2);
        let k = &m.points[1];
        assert!((k.dist - 0.09).abs() < 1e-12, "{}", k.dist);
        assert_eq!(k.fid2, vertex_id(CORE_FEATURE));
    }

    #[test]
    fn rounded_polygon_on_halfspace_has_two_points() {
        let hs = HalfSpace::new(Vector::Y);
        let sq = RoundedPolygon::regular(4, 0.5, 0.05);
        // The regular square's edges: rotate so an edge faces down.
        let verts = sq.vertices();
        let (a, b) = (verts[0], verts[1]);
        // Rotate the square so that its edge a→b is horizontal, at the bottom (ccw order).
        let ang = (b - a).y.atan2((b - a).x);
        let pos12 = Pose::new(Vector::new(0.0, 1.0), -ang);
        assert!(manifolds(&hs, &sq, &pos12, 0.0)[0].points.is_empty());
        // Lower it into contact, 10⁻³ deep.
        let mut pose = pos12;
        let gap = SmoothDispatcher::default()
            .signed_distance(&pose, &hs, &sq)
            .unwrap()
            .unwrap()
            .distance;
        pose.translation.y -= gap + 1e-3;
        let m = manifolds(&hs, &sq, &pose, 0.0);
        assert_eq!(m[0].points.len(), 2, "{:?}", m[0].points);
        for p in &m[0].points {
            assert!((p.dist + 1e-3).abs() < 1e-9, "{}", p.dist);
        }
        assert_ne!(m[0].points[0].fid2, m[0].points[1].fid2);
    }

    #[test]
    fn ellipse_inside_compound_gets_contacts() {
        let e = SharedShape::new(Ellipse::new(0.5, 0.2));
        let compound = Compound::new(vec![(Pose::translation(1.0, 0.0), e)]);
        let b = Cuboid::new(Vector::new(2.0, 0.5));
        let pos12 = Pose::translation(-1.0, 0.69);
        let m = manifolds(&b, &compound, &pos12, 0.0);
        let pts: Vec<_> = m.iter().flat_map(|m| m.points.iter()).collect();
        // The exact point and the ellipse's core contact.
        assert_eq!(pts.len(), 2);
        assert!((pts[0].dist + 0.01).abs() < 1e-12);
        assert_eq!(m.iter().find(|m| !m.points.is_empty()).unwrap().subshape2, 0);
    }

    #[test]
    fn contact_on_a_flat_face_faces_the_smooth_witness() {
        // The stationary distance may put the witness of a flat piece anywhere on it (e.g. the
        // box corner 20 units away); the manifold point must face the ellipse's witness.
        let e = Ellipse::new(0.5, 0.2);
        let b = Cuboid::new(Vector::new(20.0, 0.5));
        for i in 0..40 {
            let ang = -3.0 + 0.15 * i as f64;
            let pos12 = Pose::new(Vector::new(0.3, 0.9 - 0.01 * i as f64), ang);
            for flip in [false, true] {
                let m = if flip {
                    manifolds(&e, &b, &pos12.inverse(), 0.1)
                } else {
                    manifolds(&b, &e, &pos12, 0.1)
                };
                for p in &m[0].points {
                    let (pb, pe) = if flip {
                        (p.local_p2, p.local_p1)
                    } else {
                        (p.local_p1, p.local_p2)
                    };
                    let pe_in_b = pos12.transform_point(pe);
                    assert!((pb.x - pe_in_b.x).abs() < 1e-9, "{pb:?} {pe_in_b:?}");
                    assert!((pb.y - 0.5).abs() < 1e-12);
                    assert!((pe_in_b.y - 0.5 - p.dist).abs() < 1e-9);
                }
            }
        }
    }

    #[test]
    fn ellipse_on_halfspace_is_one_exact_point() {
        let hs = HalfSpace::new(Vector::Y);
        let e = Ellipse::new(0.5, 0.2);
        let pos12 = Pose::new(Vector::new(0.3, 0.19), 0.0);
        for (g1, g2, pose) in [(&hs as &dyn Shape, &e as &dyn Shape, pos12), (&e, &hs, pos12.inverse())] {
            let m = manifolds(g1, g2, &pose, 0.0);
            assert_eq!(m[0].points.len(), 1);
            let p = &m[0].points[0];
            assert!((p.dist + 0.01).abs() < 1e-12, "{}", p.dist);
            assert!((pose.transform_point(p.local_p2) - p.local_p1 - m[0].local_n1 * p.dist).length() < 1e-12);
        }
    }
}
