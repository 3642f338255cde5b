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
//! Normal constraints (the pseudo-normals of a trimesh's or heightfield's triangles) are
//! parry2d (f32) objects: they are applied to the rounded manifold — the contact normal is
//! projected, the contact dropped when the constraint rejects it, and each point's distance
//! re-measured along a moved normal.

use crate::composite::{composite_manifolds, single_manifold};
use crate::convert::{packed32, pose64, v32, v64};
use crate::dispatcher::composite_pair;
use crate::shapes::own_f64;
use crate::widen::widen_pair;
use crate::SmoothDispatcher;
use parry2d::math::{Pose, Real, Vector};
use parry2d::query::details::{NormalConstraints, NormalConstraintsPair};
use parry2d::query::{
    ContactManifold, ContactManifoldsWorkspace, DefaultQueryDispatcher, PersistentQueryDispatcher, TrackedContact,
    Unsupported,
};
use parry2d::shape::Shape;
use parry2d_f64::query as q64;
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
    let finite = m.local_n1.is_finite()
        && m.local_n2.is_finite()
        && m.points
            .iter()
            .all(|p| p.local_p1.is_finite() && p.local_p2.is_finite() && p.dist.is_finite());
    if !finite {
        m.clear();
        return false;
    }
    m.match_contacts(&old);
    true
}

/// Applies normal constraints to a rounded manifold (see the module docs).
fn constrain<M, C: Default + Copy>(
    pos12: &Pose,
    constraints: (Option<&dyn NormalConstraints>, Option<&dyn NormalConstraints>),
    prediction: Real,
    m: &mut ContactManifold<M, C>,
) {
    if m.points.is_empty() {
        return;
    }
    let (mut n1, mut n2) = (m.local_n1, m.local_n2);
    if !constraints.project_local_normals(pos12, &mut n1, &mut n2) {
        m.clear();
        m.local_n1 = Vector::ZERO;
        return;
    }
    if n1 != m.local_n1 {
        for p in &mut m.points {
            p.dist = (pos12.transform_point(p.local_p2) - p.local_p1).dot(n1);
        }
        m.points.retain(|p| p.dist <= prediction && p.dist.is_finite());
    }
    m.local_n1 = n1;
    m.local_n2 = n2;
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
            composite_manifolds(self, pos12, g1, g2, prediction, manifolds, workspace);
            return Ok(());
        }
        if own_f64(g1).is_none() && own_f64(g2).is_none() {
            return DefaultQueryDispatcher.contact_manifolds(pos12, g1, g2, prediction, manifolds, workspace);
        }
        let manifold = single_manifold(manifolds);
        self.contact_manifold_convex_convex(pos12, g1, g2, None, None, prediction, manifold)
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
            return DefaultQueryDispatcher.contact_manifold_convex_convex(
                pos12,
                g1,
                g2,
                normal_constraints1,
                normal_constraints2,
                prediction,
                manifold,
            );
        };
        let mut wide = widened(manifold);
        let answered = self.core.contact_manifold_convex_convex(
            &pose64(pos12),
            a.get(),
            b.get(),
            None,
            None,
            prediction as f64,
            &mut wide,
        );
        if answered.is_err() {
            manifold.clear();
            return Err(Unsupported);
        }
        if !round_into(&wide, manifold) {
            return Err(Unsupported);
        }
        if normal_constraints1.is_some() || normal_constraints2.is_some() {
            constrain(pos12, (normal_constraints1, normal_constraints2), prediction, manifold);
        }
        Ok(())
    }
}
