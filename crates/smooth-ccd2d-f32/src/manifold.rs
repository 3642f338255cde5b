//! Contact manifolds for rapier2d (f32): [`SmoothDispatcher`] as parry2d's
//! `PersistentQueryDispatcher`.
//!
//! A convex pair with one of this package's shapes is widened to f64 and handed to
//! `smooth-ccd2d`'s manifold (the exact contact query: one point on curved contacts, two where
//! faces face faces, stable feature ids; warm-started from the manifold's previous normal). The
//! f64 manifold is a stack value (parry's 2D manifolds hold their points in an `ArrayVec`): the
//! previous f32 manifold's normals and points are widened into it, the f64 dispatcher fills it,
//! and its normals, points, distances and feature ids round back into rapier's manifold, whose
//! per-contact data (rapier's impulses) is carried over by feature id, as parry does.
//!
//! Normal constraints (the pseudo-normals of a heightfield's segments, an oriented polyline's, a
//! compound's with internal edges fixed) are parry2d (f32) objects; each is handed to the f64
//! crate as an f64 constraint that rounds the normal, projects it with the f32 constraint and
//! widens it back (`Widened`), so a constrained pair takes exactly the f64 crate's constrained
//! route.

use crate::composite::{composite_manifolds, single_manifold};
use crate::convert::{packed32, pose64, v32, v64};
use crate::dispatcher::composite_pair;
use crate::guard::{inputs_ok, AllFinite};
use crate::shapes::own_f64;
use crate::widen::widen_pair;
use crate::SmoothDispatcher;
use parry2d::math::{Pose, Real};
use parry2d::query::details::NormalConstraints;
use parry2d::query::{
    ContactManifold, ContactManifoldsWorkspace, DefaultQueryDispatcher, PersistentQueryDispatcher, TrackedContact,
    Unsupported,
};
use parry2d::shape::Shape;
use parry2d_f64::query as q64;
use parry2d_f64::query::details::NormalConstraints as NormalConstraints64;
use parry2d_f64::query::PersistentQueryDispatcher as _;
use parry2d_f64::shape as s64;

/// The f64 manifold standing for `m`: its normals and its points' geometry and ids, widened.
fn widened<M, C>(m: &ContactManifold<M, C>) -> q64::ContactManifold<(), ()> {
    let mut w = q64::ContactManifold::<(), ()>::new();
    w.local_n1 = v64(m.local_n1);
    w.local_n2 = v64(m.local_n2);
    for p in &m.points {
        w.points.push(q64::TrackedContact::new(
            v64(p.local_p1),
            v64(p.local_p2),
            s64::PackedFeatureId(p.fid1.0),
            s64::PackedFeatureId(p.fid2.0),
            p.dist as f64,
        ));
    }
    w
}

/// Rounds the f64 manifold `w` into `m`, keeping each contact's data where its pair of feature
/// ids is kept; false (with `m` cleared) when a rounded value is not finite.
fn round_into<M, C: Default + Copy>(w: &q64::ContactManifold<(), ()>, m: &mut ContactManifold<M, C>) -> bool {
    let old = m.points.clone();
    m.clear();
    m.local_n1 = v32(w.local_n1);
    m.local_n2 = v32(w.local_n2);
    for p in &w.points {
        m.points.push(TrackedContact::new(
            v32(p.local_p1),
            v32(p.local_p2),
            packed32(p.fid1),
            packed32(p.fid2),
            p.dist as f32,
        ));
    }
    if !m.all_finite() {
        m.clear();
        return false;
    }
    m.match_contacts(&old);
    true
}

/// An f32 normal constraint as an f64 one: the normal rounded, projected by the f32 constraint,
/// widened and renormalised in f64.
struct Widened(&'static dyn NormalConstraints);

impl NormalConstraints64 for Widened {
    fn project_local_normal_mut(&self, normal: &mut parry2d_f64::math::Vector) -> bool {
        let mut n = v32(*normal);
        if !self.0.project_local_normal_mut(&mut n) {
            return false;
        }
        let w = v64(n);
        let len = w.length();
        if !(len > 0.0 && len.is_finite()) {
            return false;
        }
        *normal = w / len;
        true
    }
}

/// `c` as an f64 constraint for the duration of `f`.
fn widened_constraint<R>(
    c: Option<&dyn NormalConstraints>,
    f: impl FnOnce(Option<&dyn NormalConstraints64>) -> R,
) -> R {
    match c {
        None => f(None),
        Some(c) => {
            // SAFETY: parry's `NormalConstraints` trait requires `'static` implementors, which a
            // wrapper of a borrowed f32 constraint is not; the borrow is extended to `'static`
            // only inside `Widened`, which lives on this stack frame and is lent to `f` for the
            // call (`f` receives a reference bounded by this frame, and cannot reach the inner
            // reference except through `Widened`'s method, since `Widened` is private and parry's
            // trait has no way to downcast or clone). The reference never outlives `c`'s borrow.
            let c: &'static dyn NormalConstraints = unsafe { core::mem::transmute::<&dyn NormalConstraints, _>(c) };
            let w = Widened(c);
            f(Some(&w))
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
        if composite_pair(g1, g2) {
            if !inputs_ok(pos12, g1, g2, prediction) {
                manifolds.iter_mut().for_each(|m| m.clear());
                return Err(Unsupported);
            }
            composite_manifolds(self, pos12, g1, g2, prediction, manifolds, workspace);
            return Ok(());
        }
        if own_f64(g1).is_none() && own_f64(g2).is_none() {
            return DefaultQueryDispatcher.contact_manifolds(pos12, g1, g2, prediction, manifolds, workspace);
        }
        let Some((a, b)) = widen_pair(g1, g2) else {
            let manifold = single_manifold(manifolds);
            return self.contact_manifold_convex_convex(pos12, g1, g2, None, None, prediction, manifold);
        };
        // The core's manifolds of the pair (its points, then each body's core contact: three
        // manifolds, always, for rapier's solver graph), rounded into three of ours.
        manifolds.truncate(3);
        while manifolds.len() < 3 {
            manifolds.push(ContactManifold::new());
        }
        let mut wide: Vec<q64::ContactManifold<(), ()>> = manifolds.iter().map(widened).collect();
        let answered = self.core.contact_manifolds(
            &pose64(pos12),
            a.get(),
            b.get(),
            prediction as f64,
            &mut wide,
            &mut None,
        );
        wide.resize_with(3, q64::ContactManifold::new);
        let rounded = manifolds.iter_mut().zip(&wide).all(|(m, w)| {
            (m.subshape1, m.subshape2, m.subshape_poses) = (0, 0, None);
            round_into(w, m)
        });
        if answered.is_err() || !rounded {
            manifolds.iter_mut().for_each(|m| m.clear());
            return Err(Unsupported);
        }
        Ok(())
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
        let Some((a, b)) = widen_pair(g1, g2) else {
            // parry2d's; with one of this package's shapes (against a shape the core does not
            // take), under the guards as in the dispatcher's route 3.
            let ours = own_f64(g1).is_some() || own_f64(g2).is_some();
            if ours && !inputs_ok(pos12, g1, g2, prediction) {
                manifold.clear();
                return Err(Unsupported);
            }
            DefaultQueryDispatcher.contact_manifold_convex_convex(
                pos12,
                g1,
                g2,
                normal_constraints1,
                normal_constraints2,
                prediction,
                manifold,
            )?;
            if ours && !manifold.all_finite() {
                manifold.clear();
                return Err(Unsupported);
            }
            return Ok(());
        };
        let mut wide = widened(manifold);
        let answered = widened_constraint(normal_constraints1, |nc1| {
            widened_constraint(normal_constraints2, |nc2| {
                self.core.contact_manifold_convex_convex(
                    &pose64(pos12),
                    a.get(),
                    b.get(),
                    nc1,
                    nc2,
                    prediction as f64,
                    &mut wide,
                )
            })
        });
        if answered.is_err() {
            manifold.clear();
            return Err(Unsupported);
        }
        if !round_into(&wide, manifold) {
            return Err(Unsupported);
        }
        Ok(())
    }
}

impl SmoothDispatcher {
    /// `smooth_ccd2d::SmoothDispatcher::part_manifolds` in f32: the manifolds of a part of a
    /// composite shape against a convex shape as the composite bookkeeping of
    /// `composite_helpers!` takes them (the part's points, then its core contact where it would
    /// otherwise take the second point's place), widened to f64, answered by the core and rounded
    /// back as `contact_manifold_convex_convex` does; parry2d's pairs as that method answers
    /// them, with no core contact. Not a public API.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn part_manifolds<M, C>(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        [nc1, nc2]: [Option<&dyn NormalConstraints>; 2],
        prediction: Real,
        manifold: &mut ContactManifold<M, C>,
        core: &mut ContactManifold<M, C>,
    ) -> Result<(), Unsupported>
    where
        M: Default + Clone + Send + Sync,
        C: Default + Copy + Send + Sync,
    {
        let Some((a, b)) = widen_pair(g1, g2) else {
            core.clear();
            return self.contact_manifold_convex_convex(pos12, g1, g2, nc1, nc2, prediction, manifold);
        };
        let (mut wide, mut wide_core) = (widened(manifold), widened(core));
        let answered = widened_constraint(nc1, |nc1| {
            widened_constraint(nc2, |nc2| {
                self.core.part_manifolds(
                    &pose64(pos12),
                    a.get(),
                    b.get(),
                    [nc1, nc2],
                    prediction as f64,
                    &mut wide,
                    &mut wide_core,
                )
            })
        });
        if answered.is_err() || !(round_into(&wide, manifold) && round_into(&wide_core, core)) {
            manifold.clear();
            core.clear();
            return Err(Unsupported);
        }
        Ok(())
    }
}
