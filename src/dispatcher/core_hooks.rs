//! [`CoreContactHooks`] and [`OneBounceHooks`]: rapier hooks that keep rapier's restitution
//! from adding energy (feature `rapier`).
//!
//! rapier's restitution is Box2D's: after the substeps, every contact row that pushed is given
//! the bounce of its own approach velocity. On one row that keeps the energy of the collision
//! (e = 1) or takes some (e < 1); on two rows with different lever arms on a spinning body it
//! adds energy ([`super::impact_row`] gives the algebra). Two places make such rows:
//!
//! * **the exact point and a core contact.** A pair of this crate's shapes gets three manifolds
//!   in rapier: its exact points, and the bodies' *core contacts* ([`super::core_disc`]:
//!   speculative points on each body's centre line that stop a centre a spin would drive into
//!   the other body; both bodies' share one manifold where both are along the contact normal). Two spinning ellipses with restitution 1 gained up to 40 % in one head-on
//!   collision. [`CoreContactHooks`] set the restitution of a manifold made only of core
//!   contacts to 0: the core rows still hold the centres (no body goes through anything more
//!   than before), and the bounce is the exact point's alone.
//! * **two points where flat sides meet** (a box on a box, a polygon's edge on a rounded
//!   polygon's): a spinning box hitting a box face on gained up to 34 % with `CoreContactHooks`.
//!   [`OneBounceHooks`] (opt-in) do what `CoreContactHooks` do and, at an impact — both points
//!   of a manifold approaching, both to be bounced (restitution positive, and the points new or
//!   the restitution at least 1, as rapier's `is_bouncy` reads them) — replace the two rows by
//!   one that carries their inelastic impulse ([`super::impact_row`]: the point of the face
//!   where the two points' impulses' resultant acts; anchors, gap and tangent velocity
//!   interpolated alike; the id of the row with the larger share). A contact whose points are
//!   not both bounced (resting: restitution below 1 and points that pushed in the last step, or
//!   one end moving apart) keeps its two points.
//!
//! With one bouncing row the restitution cannot add energy to a frictionless contact
//! ([`super::impact_row`]: E₁ ≤ E₀ − (1 − e²) u² / (2K) whatever the other, inelastic rows do,
//! once the substeps have reached the inelastic solution); with friction it is measured, not
//! proven (the moving-pairs head-on table, docs/rapier.md). The price of the merged row: for the
//! impact's step the other end of the face has no row of its own (the merged row stops it along
//! the normal in the inelastic phase; after the bounce it may close on the other body, a contact
//! of the next step). A part of a composite shape (its exact point and one core contact in one
//! manifold) is left as it is by both.
//!
//! Install either as rapier's `PhysicsHooks` and give the bouncing colliders
//! `ActiveHooks::MODIFY_SOLVER_CONTACTS`; with hooks of your own, call
//! [`CoreContactHooks::modify`] or [`CoreContactHooks::modify_one_bounce`] from your
//! `modify_solver_contacts`.

use super::core_disc::is_core_feature;
use super::impact_row::{impact_weights, ImpactSide};
use parry2d_f64::math::Vector;
use rapier2d_f64::dynamics::{RigidBodyHandle, RigidBodySet};
use rapier2d_f64::geometry::{ContactManifold, SolverContact, NEW_CONTACT_BIT};
use rapier2d_f64::pipeline::{ContactModificationContext, ModifiableContacts, ModifiableManifold, PhysicsHooks};

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

    /// [`OneBounceHooks`]' change to one manifold: [`Self::modify`], and the two points of an
    /// impact merged into one row (module docs) on a manifold without core contacts.
    pub fn modify_one_bounce(context: &mut ContactModificationContext) {
        let bodies = context.bodies;
        let handles = [context.rigid_body1, context.rigid_body2];
        if let ModifiableContacts::Rigid(m) = &mut context.contacts {
            if Self::is_core_manifold(m.manifold) {
                *m.restitution = 0.0;
            } else if !m.manifold.points.iter().any(|p| is_core_feature(p.fid1.0)) {
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

/// rapier hooks that keep restitution from adding energy to a frictionless contact (opt-in;
/// module docs): [`CoreContactHooks`], and one bouncing row per impact — the two points of a
/// flat side's impact merged into one row that carries their inelastic impulse.
///
/// ```
/// use rapier2d_f64::prelude::*;
/// use smooth_ccd2d::{OneBounceHooks, RoundedPolygon};
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

/// The state of the body of `handle` for [`impact_weights`] (a side without a body: nothing
/// moves, infinite mass).
fn side(bodies: &RigidBodySet, handle: Option<RigidBodyHandle>) -> ImpactSide {
    handle
        .and_then(|h| bodies.get(h))
        .map_or_else(ImpactSide::default, |rb| {
            let m = rb.mass_properties();
            ImpactSide {
                com: m.world_com,
                linvel: rb.linvel(),
                angvel: rb.angvel(),
                inv_mass: m.effective_inv_mass,
                inv_inertia: m.effective_world_inv_inertia,
            }
        })
}

/// Replaces the two solver contacts of `m` by one when both would be bounced and both approach
/// (module docs); leaves `m` otherwise. A manifold of equal dominance only (a dominated side
/// acts as a wall in rapier's solver, which the weights do not model).
fn merge_impact_rows(m: &mut ModifiableManifold, sides: [ImpactSide; 2]) {
    let e = *m.restitution;
    let rows = &mut *m.solver_contacts;
    if rows.len() != 2 || e <= 0.0 || m.manifold.data.relative_dominance != 0 {
        return;
    }
    // rapier's `is_bouncy`: a new point bounces when e > 0, an old one only when e ≥ 1.
    let bounced = |c: &SolverContact| c.contact_id[0] & NEW_CONTACT_BIT != 0 || e >= 1.0;
    if !rows.iter().all(bounced) {
        return;
    }
    let mid = |c: &SolverContact| (c.anchor1 + c.anchor2) * 0.5;
    let Some(w) = impact_weights(*m.normal, [mid(&rows[0]), mid(&rows[1])], sides) else {
        return;
    };
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
