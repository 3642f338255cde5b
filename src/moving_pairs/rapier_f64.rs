//! `MovingPairs` for rapier2d-f64 (feature `rapier`): the adapter's macro instantiated with
//! this crate's [`crate::SmoothDispatcher`] and the identity at the f64 boundary.

/// The f64 boundary of the adapter: poses and numbers are already f64; casts and intersection
/// tests are the dispatcher's.
mod boundary {
    use crate::moving_pairs::core::CastOutcome;
    use crate::{CastPolicy, SmoothDispatcher};
    use parry2d_f64::math::{Pose, Real, Vector};
    use parry2d_f64::query::{NonlinearRigidMotion, QueryDispatcher, ShapeCastStatus};
    use parry2d_f64::shape::Shape;

    pub(super) fn pose64(p: &Pose) -> Pose {
        *p
    }

    pub(super) fn pose_back(p: &Pose) -> Pose {
        *p
    }

    pub(super) fn vector64(v: Vector) -> Vector {
        v
    }

    pub(super) fn real64(x: Real) -> f64 {
        x
    }

    /// The pass's dispatcher: rapier's rules on the constant-spin path.
    pub(super) fn dispatcher() -> SmoothDispatcher {
        SmoothDispatcher::default().with_cast_policy(CastPolicy::RapierConstantSpin)
    }

    /// The dispatcher's nonlinear cast (`stop_at_penetration` for a sensor pair).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn cast(
        d: &SmoothDispatcher,
        g1: &dyn Shape,
        m1: &NonlinearRigidMotion,
        g2: &dyn Shape,
        m2: &NonlinearRigidMotion,
        t0: f64,
        t1: f64,
        sensor: bool,
    ) -> CastOutcome {
        match d.cast_shapes_nonlinear(m1, g1, m2, g2, t0, t1, sensor) {
            Ok(Some(hit)) => match hit.status {
                ShapeCastStatus::OutOfIterations | ShapeCastStatus::Failed => CastOutcome::Capped(hit.time_of_impact),
                _ => CastOutcome::Hit(hit.time_of_impact),
            },
            Ok(None) => CastOutcome::Miss,
            Err(_) => CastOutcome::Unsupported,
        }
    }

    /// Whether the shapes intersect at `pos12` (an unanswered test counts as an intersection:
    /// no event is invented).
    pub(super) fn intersects(d: &SmoothDispatcher, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> bool {
        d.intersection_test(pos12, g1, g2).map_or(true, |i| i.intersecting)
    }
}

crate::moving_pairs_rapier!(
    rapier2d_f64,
    crate::SmoothDispatcher,
    boundary,
    r#"
```
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{Ellipse, MovingPairs, SmoothDispatcher};

let mut bodies = RigidBodySet::new();
let mut colliders = ColliderSet::new();
let mut params = IntegrationParameters::default();
params.normalized_max_linear_velocity = f64::MAX; // rapier caps speeds at 400 m/s otherwise
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
let xs: Vec<f64> = bodies.iter().map(|(_, rb)| rb.translation().x).collect();
assert!(xs[0] < xs[1], "the bodies bounced: {xs:?}");
```
"#
);
