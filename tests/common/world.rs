//! A rapier world driven by `PhysicsPipeline::step`: the sets, the pipeline and one step. One
//! harness for the rapier tests (`tests/rapier_integration.rs`, `tests/threads.rs`) and the pile
//! benchmark (`benches/support/pile.rs`); each wraps it with what it records.

use rapier2d_f64::prelude::*;

/// Everything `PhysicsPipeline::step` takes, with default integration parameters.
pub struct World {
    pub params: IntegrationParameters,
    pub pipeline: PhysicsPipeline,
    pub islands: IslandManager,
    pub broad_phase: DefaultBroadPhase,
    pub narrow_phase: NarrowPhase,
    pub bodies: RigidBodySet,
    pub colliders: ColliderSet,
    pub impulse_joints: ImpulseJointSet,
    pub multibody_joints: MultibodyJointSet,
    pub soft_bodies: SoftBodySet,
    pub ccd: CCDSolver,
}

impl World {
    /// An empty world with this narrow phase (`NarrowPhase::with_query_dispatcher(SmoothDispatcher)`
    /// or parry's default `NarrowPhase::new()`).
    pub fn new(narrow_phase: NarrowPhase) -> Self {
        World {
            params: IntegrationParameters::default(),
            pipeline: PhysicsPipeline::new(),
            islands: IslandManager::new(),
            broad_phase: DefaultBroadPhase::new(),
            narrow_phase,
            bodies: RigidBodySet::new(),
            colliders: ColliderSet::new(),
            impulse_joints: ImpulseJointSet::new(),
            multibody_joints: MultibodyJointSet::new(),
            soft_bodies: SoftBodySet::new(),
            ccd: CCDSolver::new(),
        }
    }

    /// Inserts a body with one collider.
    pub fn insert(&mut self, body: RigidBodyBuilder, collider: ColliderBuilder) -> (RigidBodyHandle, ColliderHandle) {
        let h = self.bodies.insert(body);
        let c = self.colliders.insert_with_parent(collider, h, &mut self.bodies);
        (h, c)
    }

    /// One step under `gravity`, events to `events` (`&()` to drop them).
    pub fn step(&mut self, gravity: Vector, events: &dyn EventHandler) {
        self.pipeline.step(
            gravity,
            &self.params,
            &mut self.islands,
            &mut self.broad_phase,
            &mut self.narrow_phase,
            &mut self.bodies,
            &mut self.colliders,
            &mut self.impulse_joints,
            &mut self.multibody_joints,
            &mut self.soft_bodies,
            &mut self.ccd,
            &(),
            events,
        );
    }
}
