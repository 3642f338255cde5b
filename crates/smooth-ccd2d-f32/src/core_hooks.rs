//! [`CoreContactHooks`] for rapier2d (feature `rapier`): the root crate's
//! `smooth_ccd2d::CoreContactHooks` (its docs give the why) with rapier2d's types.

use rapier2d::geometry::ContactManifold;
use rapier2d::pipeline::{ContactModificationContext, ModifiableContacts, PhysicsHooks};

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
}

impl PhysicsHooks for CoreContactHooks {
    fn modify_solver_contacts(&self, context: &mut ContactModificationContext) {
        Self::modify(context);
    }
}
