//! [`CoreContactHooks`]: rapier hooks that keep the bounce off the manifolds' core contacts
//! (feature `rapier`).
//!
//! A pair of this crate's shapes gets two manifolds in rapier: its exact points, and the
//! bodies' *core contacts* ([`super::core_disc`]: speculative points on each body's centre line
//! that stop a centre a spin would drive into the other body). rapier's restitution is Box2D's:
//! after the substeps, every point that pushed is given the bounce of its own approach velocity.
//! On one contact point that keeps the energy of the collision (e = 1) or takes some (e < 1); on
//! two rows of one contact with different lever arms — the exact point and a core contact of a
//! spinning body — it adds energy: two spinning ellipses with restitution 1 gained up to 40 % in
//! one head-on collision. The hooks set the restitution of a manifold made only of core contacts
//! to 0: the core rows still hold the centres (no body goes through anything more than before),
//! and the bounce is the exact point's alone. A manifold of parry's own pairs, and a part of a
//! composite shape (its exact point and one core contact in one manifold), keep the colliders'
//! restitution.
//!
//! Install them as rapier's `PhysicsHooks` and give the bouncing colliders
//! `ActiveHooks::MODIFY_SOLVER_CONTACTS`; with hooks of your own, call
//! [`CoreContactHooks::modify`] from your `modify_solver_contacts`.

use super::core_disc::is_core_feature;
use rapier2d_f64::geometry::ContactManifold;
use rapier2d_f64::pipeline::{ContactModificationContext, ModifiableContacts, PhysicsHooks};

/// rapier hooks that take the bounce off the core contacts (module docs): restitution 0 on a
/// manifold made only of core contacts, every other manifold as it is.
///
/// ```
/// use rapier2d_f64::prelude::*;
/// use smooth_ccd2d::{CoreContactHooks, Ellipse};
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
        !manifold.points.is_empty() && manifold.points.iter().all(|p| is_core_feature(p.fid1.0))
    }

    /// The hooks' change to one manifold: its restitution set to 0 when it holds only core
    /// contacts. For a `modify_solver_contacts` of your own.
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
