//! `MovingPairs` for rapier2d (f32, as bevy_rapier2d builds it; feature `rapier`): the root
//! crate's moving-pairs pass (`smooth_ccd2d::MovingPairs`, same API and options), with rapier2d's
//! sets. The pass itself works in f64: poses widen exactly ([`crate::convert`]), the bodies'
//! paths and the event loop are f64; a cast hands the f32 dispatcher its motions rounded to f32
//! (the precision of the world's own poses) and its time rounds down, and a stopped body's pose
//! rounds to nearest.

/// The f32 boundary of the adapter.
mod boundary {
    use crate::convert::{v32, v64};
    use crate::{CastPolicy, SmoothDispatcher};
    use parry2d::math::{Pose, Real, Vector};
    use parry2d::query::{NonlinearRigidMotion, QueryDispatcher, ShapeCastStatus};
    use parry2d::shape::Shape;
    use smooth_ccd2d::__moving_pairs::{CastOutcome, NonlinearRigidMotion as Motion64, Pose as Pose64};

    /// An f32 pose widened (exactly; its rotation normalised in f64).
    pub(super) use crate::convert::pose64;

    pub(super) fn pose_back(p: &Pose64) -> Pose {
        Pose::from_parts(
            v32(p.translation),
            parry2d::math::Rot2 {
                re: p.rotation.re as f32,
                im: p.rotation.im as f32,
            },
        )
    }

    pub(super) fn vector64(v: Vector) -> parry2d_f64::math::Vector {
        v64(v)
    }

    pub(super) fn real64(x: Real) -> f64 {
        x as f64
    }

    /// The pass's dispatcher: rapier's rules on the constant-spin path.
    pub(super) fn dispatcher() -> SmoothDispatcher {
        SmoothDispatcher::default().with_cast_policy(CastPolicy::RapierConstantSpin)
    }

    fn motion32(m: &Motion64) -> NonlinearRigidMotion {
        NonlinearRigidMotion::new(pose_back(&m.start), v32(m.local_center), v32(m.linvel), m.angvel as f32)
    }

    /// The dispatcher's nonlinear cast on the motions rounded to f32 (`stop_at_penetration` for
    /// a sensor pair); its time widened back.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn cast(
        d: &SmoothDispatcher,
        g1: &dyn Shape,
        m1: &Motion64,
        g2: &dyn Shape,
        m2: &Motion64,
        t0: f64,
        t1: f64,
        sensor: bool,
    ) -> CastOutcome {
        let (m1, m2) = (motion32(m1), motion32(m2));
        match d.cast_shapes_nonlinear(&m1, g1, &m2, g2, t0 as f32, t1 as f32, sensor) {
            Ok(Some(hit)) => {
                let t = (hit.time_of_impact as f64).max(t0);
                match hit.status {
                    ShapeCastStatus::OutOfIterations | ShapeCastStatus::Failed => CastOutcome::Capped(t),
                    _ => CastOutcome::Hit(t),
                }
            }
            Ok(None) => CastOutcome::Miss,
            Err(_) => CastOutcome::Unsupported,
        }
    }

    /// Whether the shapes intersect at `pos12` (an unanswered test counts as an intersection:
    /// no event is invented).
    pub(super) fn intersects(d: &SmoothDispatcher, pos12: &Pose64, g1: &dyn Shape, g2: &dyn Shape) -> bool {
        d.intersection_test(&pose_back(pos12), g1, g2)
            .map_or(true, |i| i.intersecting)
    }
}

smooth_ccd2d::moving_pairs_rapier!(
    rapier2d,
    crate::SmoothDispatcher,
    boundary,
    r#"
```
use rapier2d::prelude::*;
use smooth_ccd2d_f32::{Ellipse, MovingPairs, SmoothDispatcher};

let mut bodies = RigidBodySet::new();
let mut colliders = ColliderSet::new();
let mut params = IntegrationParameters::default();
params.normalized_max_linear_velocity = f32::MAX; // rapier caps speeds at 400 m/s otherwise
// Two bullets shot at each other at 1000 m/s: 16.7 m a step, through each other in rapier.
for (x, v) in [(-3.0, 1000.0), (3.0, -1000.0)] {
    let rb = RigidBodyBuilder::dynamic().translation(Vector::new(x, 0.0)).linvel(Vector::new(v, 0.0)).ccd_enabled(true);
    let h = bodies.insert(rb);
    let shape = SharedShape::new(Ellipse::new(0.5, 0.2));
    colliders.insert_with_parent(ColliderBuilder::new(shape).restitution(1.0), h, &mut bodies);
}
let (mut pipeline, mut islands, mut broad_phase) = (PhysicsPipeline::new(), IslandManager::new(), BroadPhaseBvh::new());
let mut narrow_phase = NarrowPhase::with_query_dispatcher(SmoothDispatcher::default());
let (mut joints, mut multibody_joints, mut soft) = (ImpulseJointSet::new(), MultibodyJointSet::new(), SoftBodySet::new());
let mut ccd = CCDSolver::new();
let mut pass = MovingPairs::default();
for _ in 0..10 {
    pass.before_step(&bodies);
    pipeline.step(Vector::ZERO, &params, &mut islands, &mut broad_phase, &mut narrow_phase, &mut bodies,
        &mut colliders, &mut joints, &mut multibody_joints, &mut soft, &mut ccd, &(), &());
    pass.after_step(&params, &mut bodies, &mut colliders, &(), &());
}
let xs: Vec<f32> = bodies.iter().map(|(_, rb)| rb.translation().x).collect();
assert!(xs[0] < xs[1], "the bodies bounced: {xs:?}");
```
"#
);
