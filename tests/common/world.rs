//! A rapier world driven by `PhysicsPipeline::step`: the sets, the pipeline and one step, and a
//! hash of its bodies' state. The one harness of the rapier tests (`tests/rapier_integration.rs`,
//! `tests/golden.rs`, `crates/parallel-tests`), the rapier examples (through `examples/common`) and
//! the pile benchmarks (through `benches/support`); each wraps it with what it records. The scenes
//! built in it are in `scenes.rs`.
#![allow(dead_code)]

use rapier2d_f64::prelude::*;

/// The gravity of the scenes that have one: 9.81 m/s² down the y axis.
pub const GRAVITY: Vector = Vector::new(0.0, -9.81);

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
        self.step_with(gravity, &(), events);
    }

    /// One step under `gravity` with these hooks.
    pub fn step_with(&mut self, gravity: Vector, hooks: &dyn PhysicsHooks, events: &dyn EventHandler) {
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
            hooks,
            events,
        );
    }
}

/// FNV-1a over the bits of every body's pose and velocities (in the order of `handles`), and
/// those numbers.
pub fn state_hash(world: &World, handles: &[RigidBodyHandle]) -> (u64, Vec<[f64; 7]>) {
    let mut hash = 0xCBF2_9CE4_8422_2325u64;
    let mut words = Vec::new();
    for h in handles {
        let rb = &world.bodies[*h];
        let (t, r) = (rb.translation(), rb.rotation());
        let w = [t.x, t.y, r.re, r.im, rb.linvel().x, rb.linvel().y, rb.angvel()];
        for x in w {
            for b in x.to_bits().to_le_bytes() {
                hash ^= b as u64;
                hash = hash.wrapping_mul(0x100_0000_01B3);
            }
        }
        words.push(w);
    }
    (hash, words)
}
