//! A rapier world driven by `PhysicsPipeline::step`: the sets, the pipeline and one step. One
//! harness for the rapier tests (`tests/rapier_integration.rs`, `tests/threads.rs`) and the pile
//! benchmark (`benches/support/pile.rs`); each wraps it with what it records.
#![allow(dead_code)]

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

/// Bodies of [`mixed_pile`] besides its three shots (enough for rapier to split its narrow
/// phase, solver and CCD sweeps between workers: more than 64 pairs, 64 swept bodies).
pub const MIXED_PILE_BODIES: usize = 150;

/// A pile of ellipses, rounded polygons and capsule-ellipses on a box, with three fast CCD
/// ellipse shots into it (`tests/threads.rs`, `tests/golden.rs`). Returns the dynamic bodies.
pub fn mixed_pile(world: &mut World) -> Vec<RigidBodyHandle> {
    use smooth_ccd2d::{CapsuleEllipse, Ellipse, RoundedPolygon};
    let mut handles = Vec::new();
    world.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(0.0, -0.5)),
        ColliderBuilder::cuboid(20.0, 0.5),
    );
    for i in 0..MIXED_PILE_BODIES {
        let x = -9.0 + 0.9 * (i % 20) as f64;
        let y = 1.0 + 0.9 * (i / 20) as f64;
        let shape = match i % 4 {
            0 => SharedShape::new(Ellipse::new(0.4, 0.18)),
            1 => SharedShape::new(RoundedPolygon::regular(3 + i % 5, 0.3, 0.03)),
            2 => SharedShape::new(CapsuleEllipse::new(0.1, 0.15, 0.2)),
            _ => SharedShape::new(Ellipse::new(0.25, 0.25)),
        };
        let (h, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, y))
                .rotation(0.37 * i as f64)
                .angvel(2.0 - 0.1 * i as f64)
                .ccd_enabled(i % 2 == 0),
            ColliderBuilder::new(shape),
        );
        handles.push(h);
    }
    for k in 0..3 {
        let (shot, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(-15.0 - 3.0 * k as f64, 1.5 + 1.2 * k as f64))
                .linvel(Vector::new(250.0, 0.0))
                .angvel(120.0)
                .ccd_enabled(true),
            ColliderBuilder::new(SharedShape::new(Ellipse::new(0.3, 0.08))),
        );
        handles.push(shot);
    }
    handles
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
