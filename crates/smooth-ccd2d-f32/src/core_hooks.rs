//! [`CoreContactHooks`] and [`OneBounceHooks`] for rapier2d (feature `rapier`): the root
//! crate's `smooth_ccd2d::CoreContactHooks` and `smooth_ccd2d::OneBounceHooks` (their docs give
//! the why and the energy argument) with rapier2d's types. The merged row's weights are the root
//! crate's, computed in f64 from the f32 state.

use rapier2d::dynamics::{RigidBodyHandle, RigidBodySet};
use rapier2d::geometry::{ContactManifold, SolverContact, NEW_CONTACT_BIT};
use rapier2d::math::Vector;
use rapier2d::pipeline::{ContactModificationContext, ModifiableContacts, ModifiableManifold, PhysicsHooks};
use smooth_ccd2d::__ImpactSide as ImpactSide;

/// rapier2d hooks that take the bounce off the manifolds' core contacts: restitution 0 on a
/// manifold made only of core contacts, every other manifold as it is (see
/// `smooth_ccd2d::CoreContactHooks`). Give the bouncing colliders
/// `ActiveHooks::MODIFY_SOLVER_CONTACTS`; with hooks of your own, call
/// [`CoreContactHooks::modify`] from your `modify_solver_contacts`.
///
/// ```
/// use rapier2d::prelude::*;
/// use smooth_ccd2d_f32::{CoreContactHooks, Ellipse};
///
/// let collider = ColliderBuilder::new(SharedShape::new(Ellipse::new(0.5, 0.2)))
///     .restitution(1.0)
///     .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS)
///     .build();
/// let hooks = CoreContactHooks; // pipeline.step(…, &hooks, &events)
/// # let _ = (collider, hooks);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct CoreContactHooks;

impl CoreContactHooks {
    /// Whether every point of `manifold` is a core contact (and it has one).
    pub fn is_core_manifold(manifold: &ContactManifold) -> bool {
        !manifold.points.is_empty()
            && manifold
                .points
                .iter()
                .all(|p| smooth_ccd2d::__is_core_feature(p.fid1.0))
    }

    /// The hooks' change to one manifold: its restitution set to 0 when it holds only core
    /// contacts.
    pub fn modify(context: &mut ContactModificationContext) {
        if let ModifiableContacts::Rigid(m) = &mut context.contacts {
            if Self::is_core_manifold(m.manifold) {
                *m.restitution = 0.0;
            }
        }
    }

    /// [`OneBounceHooks`]' change to one manifold: [`Self::modify`], and the two points of an
    /// impact merged into one row on a manifold without core contacts (see
    /// `smooth_ccd2d::CoreContactHooks::modify_one_bounce`).
    pub fn modify_one_bounce(context: &mut ContactModificationContext) {
        let bodies = context.bodies;
        let handles = [context.rigid_body1, context.rigid_body2];
        if let ModifiableContacts::Rigid(m) = &mut context.contacts {
            if Self::is_core_manifold(m.manifold) {
                *m.restitution = 0.0;
            } else if !m
                .manifold
                .points
                .iter()
                .any(|p| smooth_ccd2d::__is_core_feature(p.fid1.0))
            {
                merge_impact_rows(m, handles.map(|h| side(bodies, h)));
            }
        }
    }
}

impl PhysicsHooks for CoreContactHooks {
    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        Self::modify(context);
    }
}

/// rapier2d hooks that keep restitution from adding energy to a frictionless contact (opt-in):
/// [`CoreContactHooks`], and one bouncing row per impact (see `smooth_ccd2d::OneBounceHooks`).
///
/// ```
/// use rapier2d::prelude::*;
/// use smooth_ccd2d_f32::{OneBounceHooks, RoundedPolygon};
///
/// let collider = ColliderBuilder::new(SharedShape::new(RoundedPolygon::regular(6, 0.4, 0.05)))
///     .restitution(1.0)
///     .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS)
///     .build();
/// let hooks = OneBounceHooks; // pipeline.step(…, &hooks, &events)
/// # let _ = (collider, hooks);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct OneBounceHooks;

impl PhysicsHooks for OneBounceHooks {
    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        CoreContactHooks::modify_one_bounce(context);
    }
}

/// The state of the body of `handle` in f64 (a side without a body: nothing moves).
fn side(bodies: &RigidBodySet, handle: Option<RigidBodyHandle>) -> ImpactSide {
    handle
        .and_then(|h| bodies.get(h))
        .map_or_else(ImpactSide::default, |rb| {
            let m = rb.mass_properties();
            ImpactSide {
                com: m.world_com.as_dvec2(),
                linvel: rb.linvel().as_dvec2(),
                angvel: f64::from(rb.angvel()),
                inv_mass: m.effective_inv_mass.as_dvec2(),
                inv_inertia: f64::from(m.effective_world_inv_inertia),
            }
        })
}

/// The root crate's merge (`smooth_ccd2d::CoreContactHooks::modify_one_bounce`) on rapier2d's
/// solver contacts: when both rows are bounced (rapier's `is_bouncy`) and both approach, one row
/// at the weights of `smooth_ccd2d::__impact_weights`.
fn merge_impact_rows(m: &mut ModifiableManifold, sides: [ImpactSide; 2]) {
    let e = *m.restitution;
    let rows = &mut *m.solver_contacts;
    if rows.len() != 2 || e <= 0.0 || m.manifold.data.relative_dominance != 0 {
        return;
    }
    let bounced = |c: &SolverContact| c.contact_id[0] & NEW_CONTACT_BIT != 0 || e >= 1.0;
    if !rows.iter().all(bounced) {
        return;
    }
    let mid = |c: &SolverContact| ((c.anchor1 + c.anchor2) * 0.5).as_dvec2();
    let normal = m.normal.as_dvec2();
    let Some(w) = smooth_ccd2d::__impact_weights(normal, [mid(&rows[0]), mid(&rows[1])], sides) else {
        return;
    };
    let w = w.map(|x| x as f32);
    let mix = |f: fn(&SolverContact) -> Vector| f(&rows[0]) * w[0] + f(&rows[1]) * w[1];
    let merged = SolverContact {
        anchor1: mix(|c| c.anchor1),
        anchor2: mix(|c| c.anchor2),
        dist: rows[0].dist * w[0] + rows[1].dist * w[1],
        tangent_velocity: mix(|c| c.tangent_velocity),
        contact_id: rows[usize::from(w[1] > w[0])].contact_id,
    };
    rows.truncate(1);
    rows[0] = merged;
}
